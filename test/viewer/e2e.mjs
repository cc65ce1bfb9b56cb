// End-to-end test of the viewer with its field sessions: `tvf serve` on a small mesh, the
// bundled page in headless Chromium opened at the address the server printed (with its token),
// constraints placed and dragged with the mouse as a user would, and the server's field
// checked through the page's hook (window.tvfEditor).
//
//   node e2e.mjs --tvf build/tvf --mesh sphere.off --node-modules build/viewer/node_modules
//                --artifacts build/test-artifacts [--chromium /usr/bin/chromium] [--eigenfields 60]
import path from 'node:path';

import { check, openViewer, options, runTest } from './e2e_support.mjs';

const norm = (v) => Math.hypot(...v);
const sub = (a, b) => a.map((x, i) => x - b[i]);
const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);

// The index k (the field turns by 2 pi k / n around v) of an n-field given by one 3D vector per
// face, from the geometry alone: around the one-ring, counter-clockwise, each face's vector is
// carried into the next face by the rotation about their common edge, the turn to the next
// face's vector is taken modulo 2 pi / n, and the angle defect is added.
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => a.map((x) => x / norm(a));
function turned(u, k, angle) {
  const kxu = cross(k, u);
  const c = Math.cos(angle), s = Math.sin(angle), d = dot(k, u) * (1 - c);
  return u.map((x, i) => x * c + kxu[i] * s + k[i] * d);
}
function indexFromVectors(mesh, vectors, v, n) {
  const point = (i) => mesh.positions.slice(3 * i, 3 * i + 3);
  const vector = (f) => vectors.slice(3 * f, 3 * f + 3);
  const normal = (f) => {
    const a = point(mesh.triangles[3 * f]);
    return unit(cross(sub(point(mesh.triangles[3 * f + 1]), a), sub(point(mesh.triangles[3 * f + 2]), a)));
  };
  const byFirst = new Map(); // p -> [face, q] for the ring's faces (v, p, q)
  for (let f = 0; 3 * f < mesh.triangles.length; ++f) {
    for (let k = 0; k < 3; ++k) {
      if (mesh.triangles[3 * f + k] === v) byFirst.set(mesh.triangles[3 * f + (k + 1) % 3], [f, mesh.triangles[3 * f + (k + 2) % 3]]);
    }
  }
  const x = point(v);
  let defect = 2 * Math.PI, turns = 0;
  for (const [p, [f, q]] of byFirst) {
    const a = unit(sub(point(p), x)), b = unit(sub(point(q), x));
    defect -= Math.acos(Math.max(-1, Math.min(1, dot(a, b))));
    const h = byFirst.get(q)[0];
    const nf = normal(f), nh = normal(h);
    const carried = turned(vector(f), b, Math.atan2(dot(cross(nf, nh), b), dot(nf, nh)));
    const next = vector(h);
    const turn = n * Math.atan2(dot(cross(carried, next), nh), dot(carried, next));
    turns += (turn - 2 * Math.PI * Math.round(turn / (2 * Math.PI))) / n;
  }
  return (n * (turns + defect)) / (2 * Math.PI);
}

// The page's mesh and last field as plain arrays, and the server's singular vertices.
async function fieldState(page) {
  return page.evaluate(() => {
    const m = window.tvfEditor.mesh();
    const f = window.tvfEditor.lastField();
    return {
      mesh: { positions: Array.from(m.positions), triangles: Array.from(m.triangles) },
      vectors: Array.from(f.vectors),
      n: f.header.n,
      singular: Array.from(f.singular_vertices || []).map((v, i) => [v, f.singular_indices[i]]),
    };
  });
}

// The field at face f must equal the constraint's vector projected onto the face's plane, to
// float32 precision (the field is sent as float32; the solve itself is exact).
async function checkFieldMatches(page, constraint, what) {
  const { field, normal } = await page.evaluate((f) => ({
    field: window.tvfEditor.faceVector(f),
    normal: window.tvfEditor.faceNormal(f),
  }), constraint.face);
  const v = constraint.vector;
  const expected = sub(v, normal.map((n) => n * dot(v, normal)));
  const error = norm(sub(field, expected)) / norm(expected);
  console.log(`  field ${field.map((x) => x.toFixed(5))} vs constraint ${expected.map((x) => x.toFixed(5))}: ` +
    `relative error ${error.toExponential(2)}`);
  check(norm(expected) > 0 && error < 1e-4, what);
}

async function main() {
  const o = options(process.argv, { eigenfields: '60' });
  console.log(`node ${process.version}`); // the page's packages must run on Debian 12's node 18
  const { address, browser, page, problems } =
    await openViewer(o, 'editor', { eigenfields: o.eigenfields, watchdogSeconds: 150 });
  try {
    // Without the token the page loads, but its WebSocket is refused, and the page says why.
    check(/\/\?token=[0-9a-f]{32}$/.test(address), 'the printed address carries a token of 128 bits');
    const bare = await browser.newPage();
    await bare.goto(address.replace(/\?token=.*/, ''));
    await bare.waitForFunction(() => document.getElementById('status').classList.contains('error'));
    const refusal = await bare.locator('#status').textContent();
    check(refusal.includes('token') && !(await bare.evaluate(() => window.tvfEditor !== undefined)),
      `without the token no session: "${refusal}"`);
    await bare.close();

    await page.goto(address);
    await page.waitForFunction(() => window.tvfEditor !== undefined);
    await page.evaluate(() => window.tvfEditor.ready);
    const info = await page.evaluate(() => window.tvfEditor.info());
    check(info.mesh.faces > 0 && info.basis.available > 0,
      `the page got the mesh (${info.mesh.faces} faces) and the basis (${info.basis.available} eigenfields)`);

    // --- A vector constraint, placed by pressing on the surface and dragging ---
    await page.click('button[data-tool="vector"]');
    const canvas = await page.locator('#canvas').boundingBox();
    const centre = { x: canvas.width / 2, y: canvas.height / 2 };
    const under = await page.evaluate(({ x, y }) => window.tvfEditor.faceAt(x, y), centre);
    check(under !== null, `the surface is under the centre of the view (face ${under?.face})`);
    const start = { x: canvas.x + centre.x, y: canvas.y + centre.y };
    await page.mouse.move(start.x, start.y);
    await page.mouse.down();
    await page.mouse.move(start.x + 70, start.y - 40, { steps: 8 });
    await page.mouse.up();
    await page.evaluate(() => window.tvfEditor.idle());

    let constraints = await page.evaluate(() => window.tvfEditor.constraints());
    check(constraints.length === 1 && constraints[0].constraint.type === 'vector',
      'one vector constraint after the drag');
    const placed = constraints[0];
    check(placed.constraint.face === under.face, `it sits on the face that was pressed (${under.face})`);
    await checkFieldMatches(page, placed.constraint, 'the field at that face is the constraint\'s vector');

    // --- Its tip dragged to a new direction ---
    const handle = await page.evaluate((id) => window.tvfEditor.handleScreen(id), placed.id);
    const tip = { x: canvas.x + handle.tip.x, y: canvas.y + handle.tip.y };
    await page.mouse.move(tip.x, tip.y);
    await page.mouse.down();
    await page.mouse.move(tip.x - 90, tip.y + 60, { steps: 10 });
    await page.mouse.up();
    await page.evaluate(() => window.tvfEditor.idle());
    constraints = await page.evaluate(() => window.tvfEditor.constraints());
    check(constraints.length === 1 && constraints[0].id === placed.id, 'still one constraint, the same one');
    const moved = constraints[0].constraint;
    const turn = Math.acos(dot(moved.vector, placed.constraint.vector) /
      (norm(moved.vector) * norm(placed.constraint.vector))) * 180 / Math.PI;
    check(moved.face === placed.constraint.face && turn > 20,
      `dragging the tip turned the vector by ${turn.toFixed(0)} degrees`);
    await checkFieldMatches(page, moved, 'the field at that face follows the new vector');

    // --- Exact answers: the reduced field at once, the exact one replaces it unasked ---
    await page.check('input[name="solver"][value="full"]');
    await page.waitForFunction(() => window.tvfEditor.lastField()?.header.answer?.exact === true, null, { timeout: 60000 });
    const exact = await page.evaluate(() => window.tvfEditor.lastField().header);
    check(exact.report.residual < 1e-9, `the exact field meets the constraints to ${exact.report.residual.toExponential(1)} ` +
      '(solver precision, < 1e-9)');
    await checkFieldMatches(page, moved, 'the exact field on the page is the constraint\'s vector (float32)');
    const badge = await page.locator('#answer-badge').textContent();
    check(badge.startsWith('exact') && exact.difference > 0,
      `the badge says which answer is on screen and how far the reduced one was: "${badge}"`);
    // A move: reduced at once, then exact again.
    const handleNow = await page.evaluate((id) => window.tvfEditor.handleScreen(id), placed.id);
    await page.mouse.move(canvas.x + handleNow.anchor.x, canvas.y + handleNow.anchor.y);
    await page.mouse.down();
    await page.mouse.move(canvas.x + handleNow.anchor.x + 40, canvas.y + handleNow.anchor.y + 30, { steps: 5 });
    await page.mouse.up();
    await page.evaluate(() => window.tvfEditor.idle());
    await page.waitForFunction(() => window.tvfEditor.lastField()?.header.answer?.exact === true, null, { timeout: 60000 });
    const afterMove = (await page.evaluate(() => window.tvfEditor.constraints()))[0].constraint;
    await checkFieldMatches(page, afterMove, `after moving it to face ${afterMove.face}, the exact field follows`);
    const exactLog = (await page.evaluate(() => window.tvfEditor.latencyLog())).filter((e) => e.exact_ms !== undefined);
    check(exactLog.length > 0 && exactLog.every((e) => e.exact_ms >= e.total_ms - 1e-6),
      `${exactLog.length} edits with the time to their exact field (${exactLog.map((e) => e.exact_ms.toFixed(1)).join(', ')} ms)`);
    await page.check('input[name="solver"][value="reduced"]');
    await page.evaluate(() => window.tvfEditor.idle());
    constraints = await page.evaluate(() => window.tvfEditor.constraints());
    const current = constraints[0].constraint;

    // --- A source by a click, selected and removed with the Delete key ---
    await page.click('button[data-tool="source"]');
    const other = { x: canvas.x + centre.x - 0.12 * canvas.height, y: canvas.y + centre.y + 0.1 * canvas.height };
    await page.mouse.click(other.x, other.y);
    await page.evaluate(() => window.tvfEditor.idle());
    constraints = await page.evaluate(() => window.tvfEditor.constraints());
    const source = constraints.find((c) => c.constraint.type === 'divergence');
    check(constraints.length === 2 && source && source.constraint.value > 0, 'a click with the source tool adds a source');
    await page.keyboard.press('Delete');
    await page.evaluate(() => window.tvfEditor.idle());
    constraints = await page.evaluate(() => window.tvfEditor.constraints());
    check(constraints.length === 1 && constraints[0].id === placed.id && constraints[0].constraint.face === current.face,
      'Delete removes the selected source');

    // --- Display: divergence colours and streamlines, through the panel ---
    await page.selectOption('#colour', 'divergence');
    await page.selectOption('#lines', 'streamlines');
    await page.evaluate(() => window.tvfEditor.idle());
    const field = await page.evaluate(() => {
      const f = window.tvfEditor.lastField();
      return { scalar: f.scalar?.length ?? 0, lines: f.lines?.length ?? 0 };
    });
    check(field.scalar === info.mesh.vertices && field.lines > 0, 'divergence per vertex and streamlines arrive');
    await page.screenshot({ path: path.join(o.artifacts, 'editor.png') });

    // --- A cross field: n chosen in the page, a singularity placed with the mouse ---
    await page.selectOption('#n', '4');
    await page.evaluate(() => window.tvfEditor.idle());
    check((await page.evaluate(() => window.tvfEditor.info().n)) === 4 &&
      (await page.evaluate(() => window.tvfEditor.constraints())).length === 0,
    'choosing a cross field gives n = 4 and drops the vector-field constraints');
    await page.click('button[data-tool="singularity"]');
    const spot = { x: canvas.x + centre.x + 0.08 * canvas.height, y: canvas.y + centre.y - 0.05 * canvas.height };
    await page.mouse.click(spot.x, spot.y);
    await page.evaluate(() => window.tvfEditor.idle());
    constraints = await page.evaluate(() => window.tvfEditor.constraints());
    const placedSingularity = constraints[0]?.constraint;
    check(constraints.length === 1 && placedSingularity.type === 'singularity' && placedSingularity.index === 1,
      `a click with the singularity tool places index +1/4 at vertex ${placedSingularity?.vertex}`);
    let state = await fieldState(page);
    let measured = indexFromVectors(state.mesh, state.vectors, placedSingularity.vertex, 4);
    console.log(`  index measured from the page's vectors at vertex ${placedSingularity.vertex}: ${measured.toFixed(6)} / 4`);
    check(state.n === 4 && Math.abs(measured - 1) < 1e-3, 'the field turns by exactly +1/4 around that vertex');
    check(state.singular.some(([v, k]) => v === placedSingularity.vertex && k === 1),
      'the page marks that vertex as a +1/4 singularity');
    const sum = state.singular.reduce((total, [, k]) => total + k, 0);
    check(sum === 8, `the singular vertices' indices sum to ${sum}/4 = 2 = the sphere's Euler characteristic`);

    // Dragged to another vertex: the index goes with it.
    const from = await page.evaluate((v) => window.tvfEditor.projectVertex(v), placedSingularity.vertex);
    await page.mouse.move(canvas.x + from.x, canvas.y + from.y);
    await page.mouse.down();
    await page.mouse.move(canvas.x + from.x - 0.15 * canvas.height, canvas.y + from.y + 0.1 * canvas.height, { steps: 8 });
    await page.mouse.up();
    await page.evaluate(() => window.tvfEditor.idle());
    constraints = await page.evaluate(() => window.tvfEditor.constraints());
    const movedSingularity = constraints[0]?.constraint;
    check(constraints.length === 1 && movedSingularity.vertex !== placedSingularity.vertex,
      `dragging moves the singularity to vertex ${movedSingularity?.vertex}`);
    state = await fieldState(page);
    measured = indexFromVectors(state.mesh, state.vectors, movedSingularity.vertex, 4);
    check(Math.abs(measured - 1) < 1e-3, `the field turns by +1/4 around the new vertex (measured ${measured.toFixed(6)})`);

    // Glyphs and hatching of the cross field, coloured by its smoothness energy.
    await page.selectOption('#colour', 'energy');
    await page.selectOption('#lines', 'streamlines');
    await page.evaluate(() => window.tvfEditor.idle());
    const hatching = await page.evaluate(() => {
      const f = window.tvfEditor.lastField();
      return { scalar: f.scalar?.length ?? 0, lines: f.lines?.length ?? 0, on: f.header.scalar_on };
    });
    check(hatching.scalar === info.mesh.faces && hatching.on === 'faces' && hatching.lines > 0,
      'energy density per face and the hatching of the cross field arrive');
    await page.screenshot({ path: path.join(o.artifacts, 'editor_cross_field.png') });
    await page.keyboard.press('Delete');
    await page.evaluate(() => window.tvfEditor.idle());
    check((await page.evaluate(() => window.tvfEditor.constraints())).length === 0, 'Delete removes the singularity');

    // --- The latency log ---
    const log = await page.evaluate(() => window.tvfEditor.latencyLog());
    const edits = log.filter((e) => e.type === 'add' || e.type === 'change');
    const sane = (e) => [e.solve_ms, e.server_ms, e.draw_ms, e.total_ms].every((x) => Number.isFinite(x) && x >= 0) &&
      e.transfer_ms > -1 && e.total_ms + 1e-6 >= e.server_ms + e.draw_ms && e.bytes > 0;
    check(edits.length >= 3 && edits.every(sane), `${edits.length} edits in the latency log, all with sane timings`);
    const median = (key) => {
      const s = edits.map((e) => e[key]).sort((a, b) => a - b);
      return s[s.length >> 1];
    };
    console.log('  median ms: ' + ['solve_ms', 'reconstruct_ms', 'lines_ms', 'server_ms', 'transfer_ms', 'draw_ms',
      'total_ms'].map((k) => `${k.replace('_ms', '')} ${median(k).toFixed(2)}`).join(', ') +
      `; message ${median('bytes')} bytes`);

    const status = await page.locator('#status').getAttribute('class');
    console.log(`screenshots: ${path.join(o.artifacts, 'editor.png')}, editor_cross_field.png`);
    check(problems.length === 0, `no errors in the page${problems.length ? ': ' + problems.join('; ') : ''}`);
    check(!status.includes('error'), 'the status line shows no error');
  } finally {
    await browser.close().catch(() => {});
  }
}

runTest('editor', main);
