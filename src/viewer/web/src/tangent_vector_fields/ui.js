// The field session's part of the side panel (panel.html): controls that call the editor's
// actions, and what the session reports.
import { cssGradient } from '../colormap.js';

const $ = (id) => document.getElementById(id);

function number(x, digits = 3) {
  if (!Number.isFinite(x)) return '–';
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e4 || a < 1e-3 ? x.toExponential(digits - 1) : x.toPrecision(digits);
}

// The tools and colours of each kind of field: 'vector' (n = 1) and 'n' (n > 1).
const N_TOOLS = {
  select: ['vector', 'n'], vector: ['vector', 'n'], direction: ['vector', 'n'], source: ['vector'], sink: ['vector'],
  vortex: ['vector'], boundary: ['vector'], singularity: ['n'],
};
const N_COLOURS = { magnitude: ['vector', 'n'], divergence: ['vector'], curl: ['vector'], energy: ['n'], none: ['vector', 'n'] };

// Failures are already shown by the status line; a promise nobody awaits must not throw.
const quiet = (promise) => promise.catch(() => {});

export class Panel {
  // line: the page's StatusLine.
  constructor(line) {
    this.line = line;
  }

  // Binds the controls to the editor and the tools (both exist by now).
  bind(editor, tools) {
    this.editor = editor;
    this.tools = tools;

    for (const button of $('tools').querySelectorAll('button')) {
      button.addEventListener('click', () => tools.setTool(button.dataset.tool));
    }
    tools.onToolChange = (tool) => {
      for (const button of $('tools').querySelectorAll('button')) {
        button.classList.toggle('active', button.dataset.tool === tool);
      }
      $('vortex-row').style.display = tool === 'vortex' ? '' : 'none';
      $('singularity-row').style.display = tool === 'singularity' ? '' : 'none';
    };
    $('n').addEventListener('change', () => {
      const n = Number($('n').value);
      this.showN(n);
      if (!N_TOOLS[tools.tool]?.includes(n === 1 ? 'vector' : 'n')) tools.setTool('select');
      quiet(editor.setN(n));
    });
    $('singularity-index').addEventListener('change', () => {
      tools.singularityIndex = Number($('singularity-index').value);
      this.showN(editor.n);
      const h = editor.selected;
      if (h && h.constraint.type === 'singularity') {
        quiet(editor.change(h, { ...h.constraint, index: tools.singularityIndex }));
      }
    });
    tools.setTool('select');
    for (const radio of document.querySelectorAll('input[name="vortex-sign"]')) {
      radio.addEventListener('change', () => {
        tools.vortexSign = Number(radio.value);
        const h = editor.selected;
        if (h && h.constraint.type === 'curl') {
          quiet(editor.change(h, { ...h.constraint, value: tools.vortexSign * Math.abs(h.constraint.value) }));
        }
      });
    }

    // Strength: a log slider; it also sets the value of the selected source, sink or vortex.
    const strength = $('strength');
    const showStrength = () => {
      tools.strength = Math.pow(10, Number(strength.value));
      $('strength-value').textContent = number(tools.strength);
    };
    strength.value = '0'; // 1: divergence and curl are dimensionless when vectors are lengths
    showStrength();
    strength.addEventListener('input', () => {
      showStrength();
      const h = editor.selected;
      if (h && (h.constraint.type === 'divergence' || h.constraint.type === 'curl')) {
        const sign = h.constraint.value < 0 ? -1 : 1;
        quiet(editor.change(h, { ...h.constraint, value: sign * tools.strength }));
      }
    });

    $('delete').addEventListener('click', () => editor.selected && quiet(editor.remove(editor.selected)));
    $('clear').addEventListener('click', () => quiet(editor.clear()));

    // omega: the slider's leftmost notch is 0; the number field takes any value.
    const slider = $('omega-slider');
    const input = $('omega');
    slider.addEventListener('input', () => {
      const x = Number(slider.value);
      const omega = x <= Number(slider.min) ? 0 : Number(Math.pow(10, x).toPrecision(3));
      input.value = String(omega);
      quiet(editor.setOmega(omega));
    });
    input.addEventListener('change', () => {
      const omega = Number(input.value);
      if (!(omega >= 0)) return this.line.error('ω must be a number >= 0');
      this.showOmega(omega);
      quiet(editor.setOmega(omega));
    });

    $('basis-size').addEventListener('change', () => {
      const size = Math.round(Number($('basis-size').value));
      quiet(editor.setBasisSize(size));
    });
    for (const radio of document.querySelectorAll('input[name="solver"]')) {
      radio.addEventListener('change', () => quiet(editor.setSolver(radio.value)));
    }

    $('colour').addEventListener('change', () => quiet(editor.setDisplay({ colour: $('colour').value })));
    $('lines').addEventListener('change', () => {
      this.showLineControls($('lines').value);
      quiet(editor.setDisplay({ lines: $('lines').value }));
    });
    for (const name of ['strokes', 'length', 'separation']) {
      $(name).addEventListener('change', () => {
        const x = Number($(name).value);
        if (Number.isFinite(x)) quiet(editor.setDisplay({ [name]: name === 'strokes' ? Math.round(x) : x }));
      });
    }

    $('save').addEventListener('click', () => this.save());
    $('load').addEventListener('change', () => this.load($('load').files[0]));

    setInterval(() => {
      const fps = editor.viewer.fps;
      $('fps').textContent = fps > 0 ? `render loop: ${fps.toFixed(0)} frames/s` : 'render loop: idle (draws on change)';
    }, 500);
  }

  // The controls of the kind of field the session designs.
  showN(n) {
    const kind = n === 1 ? 'vector' : 'n';
    $('n').value = String(n);
    for (const button of $('tools').querySelectorAll('button')) {
      button.style.display = N_TOOLS[button.dataset.tool]?.includes(kind) ? '' : 'none';
    }
    for (const option of $('colour').options) option.hidden = !N_COLOURS[option.value]?.includes(kind);
    $('strength-row').style.display = n === 1 ? '' : 'none';
    const k = Number($('singularity-index').value);
    $('singularity-fraction').textContent = n > 1 ? `index ${k > 0 ? '+' : ''}${k}/${n}` : '';
    if (n === 1) $('singularities').textContent = '';
  }

  info(info) {
    const m = info.mesh;
    this.showN(info.n ?? 1);
    $('mesh-name').textContent = m.name;
    $('mesh-info').innerHTML = `${m.vertices} vertices, ${m.faces} faces, ${m.edges} edges<br>` +
      `genus ${m.genus}, ${m.boundary_loops} boundary loop${m.boundary_loops === 1 ? '' : 's'}, ` +
      `${m.components} component${m.components === 1 ? '' : 's'}<br>` +
      `area ${number(m.area)}, diagonal ${number(m.diagonal)}, mean edge ${number(m.mean_edge_length)}<br>` +
      ((info.n ?? 1) === 1 ? `basis: ${info.basis.available} eigenfields (${info.basis.harmonic} harmonic)`
        : `basis of ${info.n}-fields: ${info.basis.available} elements (${info.basis.harmonic} parallel), order ${info.order}`);
    $('basis-size').max = String(info.basis.available);
    $('basis-size').value = String(info.basis.size);
    $('basis-available').textContent = `of ${info.basis.available}`;
    $('strokes').max = String(info.limits?.max_strokes ?? 200000);
    this.showOmega(info.omega);
    this.showSolver(info.solver);
    this.displaySettings(this.editor.display);
    this.line.progressDone();
    this.line.status('basis ready; loading the mesh');
  }

  // The settings a field was solved with, back in their controls.
  settings(header) {
    $('basis-size').value = String(header.basis_size);
    this.showOmega(header.omega);
    this.showSolver(header.solver);
  }

  showOmega(omega) {
    $('omega').value = String(omega);
    const slider = $('omega-slider');
    slider.value = String(omega > 0 ? Math.log10(omega) : Number(slider.min));
  }

  showSolver(solver) {
    for (const radio of document.querySelectorAll('input[name="solver"]')) radio.checked = radio.value === solver;
  }

  // The display's settings in their controls (they may come from the hook, not the panel).
  displaySettings(d) {
    $('colour').value = d.colour;
    $('lines').value = d.lines;
    $('strokes').value = String(d.strokes);
    $('length').value = String(d.length);
    $('separation').value = String(d.separation);
    this.showLineControls(d.lines);
  }

  showLineControls(lines) {
    $('strokes-row').style.display = lines === 'fur' ? '' : 'none';
    $('length-row').style.display = lines === 'fur' ? '' : 'none';
    $('separation-row').style.display = lines === 'streamlines' ? '' : 'none';
  }

  // After each field: what it was solved with, and the legend of its colours.
  field(header) {
    this.line.shown();
    // Controls the user is working on keep what the user typed or dragged.
    const active = document.activeElement;
    if (active !== $('basis-size')) $('basis-size').value = String(header.basis_size);
    if (active !== $('omega') && active !== $('omega-slider')) this.showOmega(header.omega);
    this.showSolver(header.solver);
    const report = header.report || {};
    const lines = [`${header.solver} solver, ${header.basis_size} eigenfields, ω = ${number(header.omega)}`,
      `constraint residual ${number(report.residual)}, max |v| ${number(header.magnitude_max)}`];
    if (!(header.answer && header.answer.exact)) {
      lines.push(report.error_bound === null || report.error_bound === undefined
        ? 'error bound: none known'
        : `error bound: ${number(report.error_bound)} of the exact field (energy norm, guaranteed)`);
    }
    if (header.difference !== undefined) {
      lines.push(`reduced vs exact: ${number(header.difference)} (rel. L2), largest angle ${number(header.largest_angle_deg)}°`);
    }
    if (report.undetermined_harmonic) lines.push(`harmonic part undetermined: ${report.undetermined_harmonic}`);
    for (const w of report.warnings || []) lines.push(`warning: ${w}`);
    $('field-info').innerHTML = lines.map((l) => `<div>${l.replace(/</g, '&lt;')}</div>`).join('');
    this.legend(header);
    this.singularities(header);
    this.answerBadge(header);
    this.line.status(`ready · ${(header.ids || []).length} constraint${(header.ids || []).length === 1 ? '' : 's'}`);
  }

  // Which answer is on screen: the exact spline, or the reduced one in d basis elements (with
  // exact answers on, the exact one follows); once both are known, how far apart they are.
  answerBadge(header) {
    const badge = $('answer-badge');
    const answer = header.answer || { exact: false, pending: 0 };
    badge.hidden = false;
    badge.classList.toggle('exact', answer.exact);
    let text = answer.exact ? 'exact' : `reduced (d = ${header.basis_size})`;
    if (!answer.exact && header.solver === 'full') {
      text += answer.pending > 0 ? ` · exact on its way (${answer.pending} pending)` : ' · exact on its way';
    }
    if (header.difference !== undefined) {
      text += ` · reduced vs exact: ${number(100 * header.difference)}%, largest angle ${number(header.largest_angle_deg)}°`;
    }
    badge.textContent = text;
  }

  // n-fields: how many singular vertices of each index, and their sum (Poincare-Hopf).
  singularities(header) {
    const n = header.n || 1;
    if (n === 1) return;
    const indices = this.editor.field?.arrays.singular_indices || [];
    const count = new Map();
    let sum = 0;
    for (const k of indices) {
      count.set(k, (count.get(k) || 0) + 1);
      sum += k;
    }
    const parts = [...count.keys()].sort((a, b) => b - a)
      .map((k) => `<span class="${k > 0 ? 'positive' : 'negative'}">${k > 0 ? '+' : ''}${k}/${n}</span> × ${count.get(k)}`);
    $('singularities').innerHTML = `${indices.length} singular vertices${parts.length ? ': ' + parts.join(', ') : ''}` +
      `; indices sum to ${sum}/${n}`;
  }

  legend(header) {
    const colour = this.editor.display.colour;
    const legend = $('legend');
    if (colour === 'none' || (colour !== 'magnitude' && !header.scalar_range)) {
      legend.hidden = true;
      return;
    }
    legend.hidden = false;
    $('legend-name').textContent = colour === 'magnitude' ? '|v|' : colour === 'energy' ? 'energy density' : colour;
    $('legend-bar').style.background = cssGradient(colour === 'magnitude' || colour === 'energy' ? 'magnitude' : 'signed');
    if (colour === 'energy') {
      $('legend-min').textContent = number(1e-4 * header.scalar_range[1]);
      $('legend-max').textContent = `${number(header.scalar_range[1])} (log)`;
    } else if (colour === 'magnitude') {
      $('legend-min').textContent = '0';
      $('legend-max').textContent = number(header.magnitude_max);
    } else {
      const extent = Math.max(Math.abs(header.scalar_range[0]), Math.abs(header.scalar_range[1]));
      $('legend-min').textContent = number(-extent);
      $('legend-max').textContent = number(extent);
    }
  }

  selection(handle) {
    $('delete').disabled = !handle;
    if (!handle) {
      $('selection').textContent = 'No constraint selected';
      return;
    }
    const c = handle.constraint;
    let detail = '';
    const v = c.vector || c.direction;
    if (v) detail = `(${v.map((x) => number(x)).join(', ')}), length ${number(Math.hypot(...v))}`;
    if (c.value !== undefined) detail = `value ${number(c.value)}`;
    if (c.type === 'singularity') detail = '';
    $('selection').textContent = `${handle.describe()} ${detail}`;
  }

  constraints() {
    const n = this.editor.constraints().length;
    $('constraint-count').textContent = `${n} constraint${n === 1 ? '' : 's'}`;
  }

  // The session's constraint file, downloaded as constraints.json (ids are the session's
  // own, not part of the file format).
  async save() {
    try {
      const answer = await this.editor.save();
      const file = { ...answer.file };
      delete file.ids;
      const blob = new Blob([JSON.stringify(file, null, 2) + '\n'], { type: 'application/json' });
      const link = document.createElement('a');
      link.href = URL.createObjectURL(blob);
      link.download = 'constraints.json';
      link.click();
      setTimeout(() => URL.revokeObjectURL(link.href), 1000);
    } catch (e) {
      this.line.error(`save failed: ${e.message}`);
    }
  }

  async load(file) {
    if (!file) return;
    let parsed;
    try {
      parsed = JSON.parse(await file.text());
    } catch (e) {
      return this.line.error(`${file.name} is not JSON: ${e.message}`);
    } finally {
      $('load').value = ''; // loading the same file again still fires a change
    }
    quiet(this.editor.load(parsed));
  }
}
