// End-to-end test of the viewer's curve session (stroke fitting, Chapter 6): `tvf serve` on a
// small mesh, the page opened with kind=curve in headless Chromium, a zig-zag drawn with the
// mouse, the tolerance slider dragged with the mouse, and the fit checked through the page's
// hook (window.tvfCurve) and its readout.
//
//   node e2e_curve.mjs --tvf build/tvf --mesh sphere.off --node-modules build/viewer/node_modules
//                      --artifacts build/test-artifacts [--chromium /usr/bin/chromium]
import path from 'node:path';

import { check, openViewer, options, runTest } from './e2e_support.mjs';

// The zig-zag's corners, as fractions of the canvas: 4 interior corners.
const ZIGZAG = [[0.12, 0.3], [0.28, 0.72], [0.44, 0.3], [0.6, 0.72], [0.76, 0.3], [0.9, 0.65]];

async function drawStroke(page, box, corners) {
  const at = ([u, v]) => ({ x: box.x + u * box.width, y: box.y + v * box.height });
  const start = at(corners[0]);
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  for (const corner of corners.slice(1)) {
    const p = at(corner);
    await page.mouse.move(p.x, p.y, { steps: 25 });
  }
  await page.mouse.up();
}

// The slider's thumb dragged with the mouse to `fraction` of its track.
async function dragSlider(page, fraction) {
  const slider = await page.locator('#curve-tolerance').boundingBox();
  const value = Number(await page.locator('#curve-tolerance').inputValue());
  const x = (f) => slider.x + 8 + f * (slider.width - 16); // the thumb's centre stays inside the track
  const y = slider.y + slider.height / 2;
  await page.mouse.move(x(value / 1000), y);
  await page.mouse.down();
  await page.mouse.move(x(fraction), y, { steps: 12 });
  await page.mouse.up();
}

async function main() {
  const o = options(process.argv);
  // A small basis: the curve session does not use it.
  const { address, browser, page, problems } = await openViewer(o, 'curve', { eigenfields: 20 });
  try {
    await page.goto(`${address}&kind=curve`);
    await page.waitForFunction(() => window.tvfCurve !== undefined);
    await page.evaluate(() => window.tvfCurve.ready);
    const info = await page.evaluate(() => window.tvfCurve.info());
    check(info.kind === 'curve' && (await page.locator('#kind-menu').inputValue()) === 'curve',
      'kind=curve opens the curve session, and the Session menu says so');
    check((await page.locator('#curve-readout').textContent()) === 'no stroke yet', 'no stroke, no fit yet');

    // --- A zig-zag drawn with the mouse, fitted at the starting tolerance ---
    const box = await page.locator('#curve-canvas').boundingBox();
    await drawStroke(page, box, ZIGZAG);
    await page.evaluate(() => window.tvfCurve.idle());
    const stroke = await page.evaluate(() => window.tvfCurve.stroke());
    let fit = await page.evaluate(() => window.tvfCurve.lastFit());
    check(stroke.length > 50 && fit?.header.points === stroke.length,
      `the server fitted the stroke the mouse drew (${stroke.length} points)`);
    const tight = fit.header;
    check(tight.knots >= 4 && tight.within_bound && tight.max_error <= tight.tolerance,
      `at ${tight.tolerance.toFixed(2)} px: ${tight.knots} knots, max error ${tight.max_error.toFixed(3)} px`);
    check(fit.knots.length === 2 * tight.knots && fit.curve.length > 2 * 256, 'the knots and the curve arrive');
    // Every corner of the zig-zag has a knot near it (the cubic bends there).
    const corners = ZIGZAG.slice(1, -1).map(([u, v]) => [u * box.width, v * box.height]);
    const nearest = (p) => Math.min(...Array.from({ length: fit.knots.length / 2 },
      (_, i) => Math.hypot(fit.knots[2 * i] - p[0], fit.knots[2 * i + 1] - p[1])));
    const far = corners.map(nearest);
    check(far.every((d) => d < 25), `a knot within 25 px of every corner (${far.map((d) => d.toFixed(1)).join(', ')} px)`);
    let readout = await page.locator('#curve-readout').textContent();
    check(readout.startsWith(`${tight.knots} knots, max error`) && readout.endsWith('ms'), `the readout: "${readout}"`);
    await page.screenshot({ path: path.join(o.artifacts, 'curve_tight.png') });

    // --- The slider dragged to a large tolerance: fewer knots, re-fitted without the points ---
    await dragSlider(page, 0.85);
    await page.evaluate(() => window.tvfCurve.idle());
    fit = await page.evaluate(() => window.tvfCurve.lastFit());
    const loose = fit.header;
    const settings = await page.evaluate(() => window.tvfCurve.settings());
    check(Math.abs(loose.tolerance - settings.tolerance) < 1e-9 * settings.tolerance && loose.tolerance > 10 * tight.tolerance,
      `the last fit is at the slider's tolerance (${loose.tolerance.toFixed(1)} px)`);
    check(loose.knots < tight.knots && loose.within_bound,
      `a larger tolerance drops the knots: ${tight.knots} -> ${loose.knots}`);
    const log = await page.evaluate(() => window.tvfCurve.log());
    const fits = log.filter((e) => e.type === 'fit');
    check(fits.length >= 1 && log.filter((e) => e.type === 'stroke').length === 1,
      `the drag re-fitted ${fits.length} times, the stroke sent once`);
    readout = await page.locator('#curve-readout').textContent();
    check(readout.startsWith(`${loose.knots} knots`), `the readout follows: "${readout}"`);

    // A burst of slider moves faster than the fits: one fit in flight, the latest waiting, so
    // far fewer fits than moves, and the last one at the slider's last value.
    const burst = await page.evaluate(async () => {
      const slider = document.getElementById('curve-tolerance');
      const before = window.tvfCurve.log().length;
      for (let v = 300; v < 500; v += 5) {
        slider.value = String(v);
        slider.dispatchEvent(new Event('input'));
      }
      await window.tvfCurve.idle();
      const log = window.tvfCurve.log();
      return { moves: 40, fits: log.length - before, last: log[log.length - 1].tolerance,
        wanted: window.tvfCurve.sliderToTolerance(495) };
    });
    check(burst.fits <= 2 && Math.abs(burst.last - burst.wanted) < 1e-9 * burst.wanted,
      `${burst.moves} slider moves at once: ${burst.fits} fits, the last at the last value (${burst.last.toFixed(2)} px)`);

    // Closed: the end joins the start, re-fitted without the points.
    await page.check('#curve-closed');
    await page.evaluate(() => window.tvfCurve.idle());
    fit = await page.evaluate(() => window.tvfCurve.lastFit());
    const [x0, y0] = fit.curve, [x1, y1] = fit.curve.slice(-2);
    check(fit.header.closed && fit.header.within_bound && Math.hypot(x1 - x0, y1 - y0) < 1e-3,
      `closed: ${fit.header.knots} knots, the curve ends where it starts`);
    await page.uncheck('#curve-closed');
    await dragSlider(page, 0.85);

    // Degree 1 and the control polygon, through the panel.
    await page.selectOption('#curve-degree', '1');
    await page.check('#curve-polygon');
    await page.evaluate(() => window.tvfCurve.idle());
    fit = await page.evaluate(() => window.tvfCurve.lastFit());
    check(fit.header.degree === 1 && fit.control.length === 2 * (fit.header.knots + 2),
      `degree 1: ${fit.header.knots} knots, ${fit.header.knots + 2} control points`);
    await page.screenshot({ path: path.join(o.artifacts, 'curve_loose.png') });

    const status = await page.locator('#status').getAttribute('class');
    check(problems.length === 0, `no errors in the page${problems.length ? ': ' + problems.join('; ') : ''}`);
    check(!status.includes('error'), 'the status line shows no error');

    // A setting the fit refuses (the exact DP takes no max-error bound): the reason on the
    // status line, the panel back at the settings the server kept, the fit unchanged.
    const before = await page.evaluate(() => window.tvfCurve.lastFit().header.request);
    await page.selectOption('#curve-algorithm', 'dp');
    await page.evaluate(() => window.tvfCurve.idle());
    const refusal = await page.locator('#status').textContent();
    check((await page.locator('#status').getAttribute('class')).includes('error') && refusal.includes('max error bound'),
      `a refused setting is explained: "${refusal}"`);
    check((await page.locator('#curve-algorithm').inputValue()) === 'greedy' &&
      (await page.evaluate(() => window.tvfCurve.lastFit().header.request)) === before,
    'the panel shows the kept algorithm again, the fit is unchanged');
    console.log(`screenshots: ${path.join(o.artifacts, 'curve_tight.png')}, curve_loose.png`);
  } finally {
    await browser.close().catch(() => {});
  }
}

runTest('curve', main);
