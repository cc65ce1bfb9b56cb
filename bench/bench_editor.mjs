// The editor's edit loop, end to end: `tvf serve` on a mesh with a saved basis, the page in
// headless Chromium, and constraint edits driven through the page's own request path
// (window.tvfEditor.request, the path a mouse drag takes).  For each display setting it
// prints where the time from a constraint change to the new field on the page goes:
// solve, reconstruction (field + 3D vectors), lines and scalar (tracing fur or streamlines,
// divergence/curl), transfer (socket + decoding on arrival), draw (buffers + render + GPU
// finish).  Then the full-resolution solution: its time and the reduced solution's distance
// to it, for several basis sizes (error against run time).
//
//   node bench/bench_editor.mjs --tvf build/tvf --mesh M.off --basis M.tvfb --constraints C.json
//        --node-modules build/viewer/node_modules [--size 1000] [--sizes 250,500,1000]
//        [--edits 30] [--full yes] [--chromium /usr/bin/chromium] [--web-root DIR] [--n N]
//
// With --n N the session designs n-direction fields: the basis of n-fields is loaded from
// M.n<N>.tvfn beside --basis (computed and saved there if missing), --constraints is an n-field
// constraint file, the displays are n-fold glyphs, hatching and the energy density, and one more
// row places and removes a singularity (an edit with new rows).
//
// The meshes and constraint sets of the design benchmark: `bench_design --write-meshes DIR`.
import { createRequire } from 'node:module';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

function options(argv) {
  const o = { chromium: '/usr/bin/chromium', size: '1000', sizes: '', edits: '30', full: 'yes' };
  for (let i = 2; i < argv.length; i += 2) {
    if (!argv[i].startsWith('--') || i + 1 >= argv.length) throw new Error(`bad argument ${argv[i]}`);
    o[argv[i].slice(2).replace(/-(.)/g, (_, c) => c.toUpperCase())] = argv[i + 1];
  }
  for (const required of ['tvf', 'mesh', 'basis', 'constraints', 'nodeModules'])
    if (!o[required]) throw new Error(`missing --${required}`);
  return o;
}

const median = (values) => {
  const s = values.filter(Number.isFinite).sort((a, b) => a - b);
  if (!s.length) return NaN;
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
};
const quantile = (values, q) => {
  const s = values.filter(Number.isFinite).sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.floor(q * s.length))] : NaN;
};
const f = (x, digits = 1) => (Number.isFinite(x) ? x.toFixed(digits) : '-');

async function main() {
  const o = options(process.argv);
  const require = createRequire(path.join(path.resolve(o.nodeModules), 'noop.js'));
  const { chromium } = require('playwright-core');

  const started = Date.now();
  const args = ['serve', o.mesh, '--basis', o.basis, '-d', o.size, '--port', '0'];
  if (o.webRoot) args.push('--web-root', o.webRoot);
  const server = spawn(o.tvf, args,
    { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/listening on (http:\/\/\S+)/);
      if (m) resolve(m[1]);
    });
    server.on('exit', (code) => reject(new Error(`tvf serve exited (${code})`)));
  });
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'tvf-bench-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: o.chromium,
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = context.pages()[0] || await context.newPage();
    page.setDefaultTimeout(30 * 60 * 1000); // loading a 5 GB basis takes a while
    await page.goto(url);
    await page.waitForFunction(() => window.tvfEditor !== undefined);
    await page.evaluate(() => window.tvfEditor.ready);
    const info = await page.evaluate(() => window.tvfEditor.info());
    console.log(`# Editor edit loop: ${info.mesh.name}, ${info.mesh.faces} faces, basis ${info.basis.size} of ` +
      `${info.basis.available} eigenfields (page ready ${((Date.now() - started) / 1000).toFixed(0)} s after start)`);
    console.log(`Chromium ${context.browser() ? context.browser().version() : ''} headless, software GL ` +
      `(--disable-gpu); server and browser on this machine (loopback).\n`);

    const n = Number(o.n || 1);
    if (n > 1) {
      const t0 = Date.now();
      await page.evaluate((n) => window.tvfEditor.request({ type: 'set_n', n }), n);
      const nInfo = await page.evaluate(() => window.tvfEditor.info());
      console.log(`n = ${n}: basis of ${nInfo.basis.available} n-fields ready ${((Date.now() - t0) / 1000).toFixed(0)} s ` +
        `after asking; the session uses ${nInfo.basis.size}.\n`);
    }
    const file = JSON.parse(fs.readFileSync(o.constraints, 'utf8'));
    await page.evaluate((file) => window.tvfEditor.request({ type: 'load', file }), file);
    const constraints = await page.evaluate(() => window.tvfEditor.constraints());
    const vector = constraints.find((c) => c.constraint.type === 'vector');
    console.log(`${constraints.length} constraints (${o.constraints}); edits change the value of vector constraint ` +
      `${vector.id} (face ${vector.constraint.face}): the fast path of a drag of its tip; the last row moves it ` +
      `to other faces (a drag of its anchor: new rows, one new pull-back).  Medians of ${o.edits} edits ` +
      `(p90 of the total in brackets), milliseconds.\n`);

    const displays = n === 1 ? [
      ['vectors only (no lines, magnitude colours)', { lines: 'none', scalar: 'none' }],
      ['fur, 4000 strokes', { lines: 'fur', strokes: 4000, scalar: 'none' }],
      ['fur, 20000 strokes', { lines: 'fur', strokes: 20000, scalar: 'none' }],
      ['streamlines, separation 0.03 diagonal', { lines: 'streamlines', separation: 0.03, scalar: 'none' }],
      ['fur 4000 + divergence colours', { lines: 'fur', strokes: 4000, scalar: 'divergence' }],
    ] : [
      ['vectors and singular vertices only (no lines)', { lines: 'none', scalar: 'none' }],
      [`${n}-fold glyphs (fur), 4000 seeds`, { lines: 'fur', strokes: 4000, scalar: 'none' }],
      ['hatching (every family), separation 0.03 diagonal', { lines: 'streamlines', separation: 0.03, scalar: 'none' }],
      ['glyphs 4000 + energy density colours', { lines: 'fur', strokes: 4000, scalar: 'energy' }],
    ];
    console.log('| display | solve | reconstruct | lines | scalar | server | transfer | draw | total (p90) | message |');
    console.log('|---|---|---|---|---|---|---|---|---|---|');
    // A unit vector along the first edge of face f (tangent to it), from the mesh the page holds.
    const tangentIn = (f) => page.evaluate((f) => {
      const { positions: p, triangles: t } = window.tvfEditor.mesh();
      const e = [0, 1, 2].map((k) => p[3 * t[3 * f + 1] + k] - p[3 * t[3 * f] + k]);
      const n = Math.hypot(...e);
      return e.map((x) => x / n);
    }, f);
    const faces = info.mesh.faces;
    displays.push([`${n === 1 ? 'fur' : 'glyphs'} 4000, moving the constraint to another face (new rows)`,
      { lines: 'fur', strokes: 4000, scalar: 'none' }, 'move']);
    if (n > 1) {
      displays.push(['glyphs 4000, placing a singularity +1/n (add, new rows)',
        { lines: 'fur', strokes: 4000, scalar: 'none' }, 'singularity']);
    }
    for (const [label, display, kind] of displays) {
      await page.evaluate((d) => window.tvfEditor.request({ type: 'set_display', ...d }), display);
      const before = await page.evaluate(() => window.tvfEditor.latencyLog().length);
      for (let k = 0; k < Number(o.edits); ++k) {
        let constraint;
        if (kind === 'singularity') {
          // A click with the singularity tool: anchored in a face of the vertex by the field's
          // vector there; then removed (not timed) so that every add meets the same set.
          const face = (vector.constraint.face + 7919 * (k + 1)) % faces;
          await page.evaluate(async (face) => {
            const t = window.tvfEditor.mesh().triangles;
            const v = window.tvfEditor.faceVector(face);
            const c = { type: 'singularity', vertex: t[3 * face], index: 1, face, vector: v };
            try {
              await window.tvfEditor.request({ type: 'add', constraint: c });
            } catch (e) {
              return; // a boundary vertex, or a zero field there: refused, not counted
            }
            const id = window.tvfEditor.constraints().find((x) => x.constraint.type === 'singularity')?.id;
            await window.tvfEditor.request({ type: 'remove', id });
          }, face);
          continue;
        }
        if (kind === 'move') {
          // A drag of the anchor over the surface: each edit puts the constraint in another face.
          const face = (vector.constraint.face + 7919 * (k + 1)) % faces;
          constraint = { type: 'vector', face, vector: await tangentIn(face) };
        } else {
          // Scale and flip the vector: a new value in the same face each time.
          const s = 0.5 + (k % 7) * 0.25, sign = k % 2 ? -1 : 1;
          constraint = { type: 'vector', face: vector.constraint.face,
            vector: vector.constraint.vector.map((x) => sign * s * x) };
        }
        await page.evaluate(([id, c]) => window.tvfEditor.request({ type: 'change', id, constraint: c }),
          [vector.id, constraint]);
      }
      const log = (await page.evaluate(() => window.tvfEditor.latencyLog())).slice(before)
        .filter((e) => e.type === (kind === 'singularity' ? 'add' : 'change'));
      const col = (c) => median(log.map((e) => e[c]));
      console.log(`| ${label} | ${f(col('solve_ms'), 3)} | ${f(col('reconstruct_ms'))} | ${f(col('lines_ms'))} | ` +
        `${f(col('scalar_ms'))} | ${f(col('server_ms'))} | ${f(col('transfer_ms'))} | ${f(col('draw_ms'))} | ` +
        `${f(col('total_ms'))} (${f(quantile(log.map((e) => e.total_ms), 0.9))}) | ` +
        `${(col('bytes') / 1e6).toFixed(2)} MB |`);
    }

    if (o.full === 'yes') {
      // Exact answers: every edit is answered at once (reduced while a pull-back is pending),
      // the exact field follows when the worker has pulled the constraint back.  Per basis size:
      // the times to the first and to the exact field, and how far the reduced answer was.
      const current = await page.evaluate(() => window.tvfEditor.info());
      await page.evaluate(() => window.tvfEditor.request({ type: 'set_display', lines: 'none', scalar: 'none' }));
      const exactNow = () => page.evaluate(() => window.tvfEditor.lastField()?.header.answer?.exact === true);
      const waitExact = () => page.waitForFunction(() => window.tvfEditor.lastField()?.header.answer?.exact === true,
        null, { timeout: 30 * 60 * 1000 });
      const t0 = Date.now();
      await page.evaluate(() => window.tvfEditor.request({ type: 'set_solver', solver: 'full' }));
      await waitExact();
      const fullSeconds = (Date.now() - t0) / 1000;
      console.log(`\nExact answers switched on with ${constraints.length} constraints: the exact field on the page ` +
        `${fullSeconds.toFixed(2)} s later (the full solver made and factored on the server's worker thread, ` +
        `${constraints.length} pull-backs).`);
      const sizes = (o.sizes || `${Math.round(o.size / 4)},${Math.round(o.size / 2)},${o.size}`).split(',').map(Number)
        .filter((d) => d >= 1 && d <= current.basis.available);
      console.log('\n| basis size d | value edit: exact at once (total) | move: reduced answer (total) | ' +
        'move: exact answer on the page | move: server time to exact | reduced vs exact, rel. L2 (MX) | largest angle |');
      console.log('|---|---|---|---|---|---|---|');
      const log = () => page.evaluate(() => window.tvfEditor.latencyLog());
      const change = (c) => page.evaluate(([id, c]) => window.tvfEditor.request({ type: 'change', id, constraint: c }),
        [vector.id, c]);
      const rows = [];
      for (const d of sizes) {
        await page.evaluate((d) => window.tvfEditor.request({ type: 'set_basis_size', size: d }), d);
        await waitExact();
        const moveFirst = [], moveExact = [], moveServer = [], differences = [], angles = [];
        for (let k = 0; k < 4; ++k) {
          const face = (vector.constraint.face + 104729 * (k + 1)) % faces;
          await change({ type: 'vector', face, vector: await tangentIn(face) });
          await waitExact();
          const header = await page.evaluate(() => window.tvfEditor.lastField().header);
          const e = (await log()).filter((x) => x.type === 'change').at(-1);
          moveFirst.push(e.total_ms);
          moveExact.push(e.exact_ms ?? e.total_ms);
          moveServer.push(e.exact_server_ms ?? e.server_ms);
          if (header.difference !== undefined) differences.push(header.difference), angles.push(header.largest_angle_deg);
        }
        const valueEdits = [];
        for (let k = 0; k < 6; ++k) { // the first puts the constraint back: the table's set again
          await change({ type: 'vector', face: vector.constraint.face,
            vector: vector.constraint.vector.map((x) => (k % 2 ? -1 : 1) * x) });
          await waitExact();
          const e = (await log()).filter((x) => x.type === 'change').at(-1);
          if (k > 0 && (await exactNow())) valueEdits.push(e.total_ms);
        }
        // A constraint added (a click with the vector tool) and removed again.
        const addFirst = [], addExact = [], addServer = [];
        for (let k = 0; k < 3; ++k) {
          const face = (vector.constraint.face + 7919 * (k + 1)) % faces;
          const c = { type: 'vector', face, vector: await tangentIn(face) };
          await page.evaluate((c) => window.tvfEditor.request({ type: 'add', constraint: c }), c);
          await waitExact();
          const e = (await log()).filter((x) => x.type === 'add').at(-1);
          addFirst.push(e.total_ms);
          addExact.push(e.exact_ms ?? e.total_ms);
          addServer.push(e.exact_server_ms ?? e.server_ms);
          const id = await page.evaluate((face) => window.tvfEditor.constraints()
            .find((x) => x.constraint.type === 'vector' && x.constraint.face === face)?.id, face);
          await page.evaluate((id) => window.tvfEditor.request({ type: 'remove', id }), id);
          await waitExact();
        }
        rows.push(`| ${d} | ${f(median(addFirst))} ms | ${f(median(addExact))} ms | ${f(median(addServer))} ms |`);
        console.log(`| ${d} | ${f(median(valueEdits))} ms | ${f(median(moveFirst))} ms | ${f(median(moveExact))} ms | ` +
          `${f(median(moveServer))} ms | ${f(median(differences), 4)} | ${f(median(angles))} deg |`);
      }
      console.log('\n| basis size d | add: reduced answer on the page | add: exact answer on the page | add: server time to exact |');
      console.log('|---|---|---|---|');
      for (const r of rows) console.log(r);
    }
  } finally {
    await context.close();
    server.kill('SIGTERM');
    fs.rmSync(profile, { recursive: true, force: true });
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
