// End-to-end test of the viewer's simulation session (Projective Dynamics in real time,
// Chapter 3): `tvf serve` on CGAL's sphere, the page opened with kind=simulation in headless
// Chromium.  Frames must arrive while the sphere falls, a mouse drag must grab a vertex and
// pull it towards the pointer, the stiffness slider dragged with the mouse must be
// acknowledged by the server, and the readout must show frame and simulation times.
//
//   node e2e_simulation.mjs --tvf build/tvf --mesh sphere.off --node-modules build/viewer/node_modules
//                           --artifacts build/test-artifacts [--chromium /usr/bin/chromium]
import path from 'node:path';

import { check, openViewer, options, runTest, sleep } from './e2e_support.mjs';

const args = options(process.argv);
const lowestZ = (positions) => Math.min(...positions.filter((_, i) => i % 3 === 2));

async function run() {
  const { address, browser, page, problems } = await openViewer(args, 'simulation', { watchdogSeconds: 60 });
  try {
    await page.goto(`${address}&kind=simulation`);
    await page.waitForFunction(() => window.tvfSimulation !== undefined);
    await page.evaluate(() => window.tvfSimulation.ready);
    const sim = (expression, arg) => page.evaluate(expression, arg);
    const info = await sim(() => window.tvfSimulation.info());
    check(info.kind === 'simulation' && info.body.simulator === 'reduced' && info.body.mode === 'shell',
      `kind=simulation: the sphere as a hyper-reduced shell (k = ${info.body.dimension})`);
    check((await page.locator('#kind-menu').inputValue()) === 'simulation', 'the Session menu says simulation');

    // --- Frames arrive and the sphere falls ---
    const first = { positions: await sim(() => window.tvfSimulation.startPositions()) };
    const framesBefore = await sim(() => window.tvfSimulation.frames());
    await sleep(1000);
    const later = await sim(() => window.tvfSimulation.lastFrame());
    const framesAfter = await sim(() => window.tvfSimulation.frames());
    check(framesAfter >= framesBefore + 10, `frames arrive while it plays (${framesAfter - framesBefore} in 1 s)`);
    check(later.positions.length === first.positions.length && later.positions.every(Number.isFinite),
      'each frame holds the positions of every vertex, finite');
    check(lowestZ(later.positions) < lowestZ(first.positions) - 0.05 * info.diagonal,
      `it falls: lowest vertex from ${lowestZ(first.positions).toFixed(3)} to ${lowestZ(later.positions).toFixed(3)}`);
    check(Math.abs(lowestZ(later.positions) - info.floor) < 0.05 * info.diagonal, 'and lies on the floor');

    // --- A mouse drag from the middle of the body grabs a vertex and pulls it towards the pointer ---
    const start = await sim(() => {
      const h = window.tvfSimulation;
      const n = h.lastFrame().positions.length / 3;
      const points = Array.from({ length: n }, (_, v) => h.screenPoint(v));
      return { x: points.reduce((s, p) => s + p.x, 0) / n, y: points.reduce((s, p) => s + p.y, 0) / n };
    });
    const aimed = await sim(([x, y]) => window.tvfSimulation.vertexAt(x, y), [start.x, start.y]);
    check(aimed !== null, `the middle of the body is on its surface (vertex ${aimed})`);
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    await page.mouse.move(start.x + 60, start.y - 120, { steps: 10 });
    const pointer = { x: start.x + 60, y: start.y - 120 };
    await sleep(1200);
    const held = await sim(() => window.tvfSimulation.lastFrame());
    const grabbed = held.header.grabbed;
    // (The body still moves a little: the grabbed vertex may be a neighbour of the aimed one.)
    check(grabbed !== null, `the press on the body grabbed vertex ${grabbed} (aimed at ${aimed})`);
    const now = await sim((v) => window.tvfSimulation.screenPoint(v), grabbed);
    const before = Math.hypot(start.x - pointer.x, start.y - pointer.y);
    const after = Math.hypot(now.x - pointer.x, now.y - pointer.y);
    check(after < 0.35 * before, `the grabbed vertex followed the pointer (${before.toFixed(0)} px away, now ` +
      `${after.toFixed(0)} px)`);
    await page.mouse.up();
    await sim(() => window.tvfSimulation.idle());
    check((await sim(() => window.tvfSimulation.state())).grabbed === null, 'releasing the button lets it go');

    // --- The stiffness slider dragged with the mouse: the server acknowledges the value ---
    const slider = await page.locator('#sim-stiffness').boundingBox();
    const x = (f) => slider.x + 8 + f * (slider.width - 16);
    const y = slider.y + slider.height / 2;
    await page.mouse.move(x(0.5), y);
    await page.mouse.down();
    await page.mouse.move(x(0.25), y, { steps: 8 });
    await page.mouse.up();
    await sim(() => window.tvfSimulation.idle());
    const state = await sim(() => window.tvfSimulation.state());
    const shown = await page.locator('#sim-stiffness').inputValue();
    const expected = info.stiffness.min * (info.stiffness.max / info.stiffness.min) ** (Number(shown) / 1000);
    check(Math.abs(state.stiffness / expected - 1) < 1e-9 && state.stiffness < info.stiffness.default / 10,
      `the server took the slider's stiffness (${state.stiffness.toPrecision(3)}, default ${info.stiffness.default.toPrecision(3)})`);

    // --- Shift-click pokes; the readout shows the times per frame ---
    const spot = await sim(() => window.tvfSimulation.screenPoint(0));
    await page.keyboard.down('Shift');
    await page.mouse.click(spot.x, spot.y);
    await page.keyboard.up('Shift');
    await sim(() => window.tvfSimulation.idle());
    check((await sim(() => window.tvfSimulation.log())).length >= 3, 'grab, release, stiffness and poke were answered');
    await sleep(500);
    const readout = await page.locator('#sim-readout').textContent();
    check(/frame time \d+\.\d ms · simulation \d+\.\d ms per frame/.test(readout), `the readout: "${readout}"`);
    // --- The Body menu: the solid the sphere bounds (Mesh_3), simulated and falling again ---
    await page.selectOption('#sim-mode', 'solid');
    await sim(() => window.tvfSimulation.idle());
    const solid = await sim(() => window.tvfSimulation.info());
    const solidFrames = await sim(() => window.tvfSimulation.frames());
    await sleep(1000);
    const landed = await sim(() => window.tvfSimulation.lastFrame());
    check(solid.body.mode === 'solid' && solid.body.elements > 100 &&
      (await sim(() => window.tvfSimulation.frames())) > solidFrames + 10 &&
      Math.abs(lowestZ(landed.positions) - solid.floor) < 0.05 * solid.diagonal,
    `the Body menu made a solid of ${solid.body.elements} tetrahedra, which fell onto the floor`);
    const status = await page.locator('#status').getAttribute('class');
    check(problems.length === 0 && !status.includes('error'),
      `no errors in the page${problems.length ? ': ' + problems.join('; ') : ''}`);
    await page.screenshot({ path: path.join(args.artifacts, 'simulation.png') });
    console.log(`screenshot: ${path.join(args.artifacts, 'simulation.png')}`);
  } finally {
    await browser.close().catch(() => {});
  }
}

runTest('simulation', run);
