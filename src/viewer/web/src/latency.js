// Where the time of an edit goes: the server's own timings from the field header, and what
// the page measures around them (the network and the drawing).

export const COLUMNS = ['solve_ms', 'reconstruct_ms', 'lines_ms', 'scalar_ms', 'server_ms', 'transfer_ms',
  'draw_ms', 'total_ms', 'exact_ms', 'bytes'];

// message: the request as sent; times (performance.now()): sentAt when it left, arrivedAt
// when its field arrived, updatedAt when the field was decoded and in the buffers, drawnAt
// when the frame showing it was finished on the GPU.
export function latencyEntry(message, header, bytes, { sentAt, arrivedAt, updatedAt, drawnAt }) {
  const t = header.timings || {};
  const server = t.server_ms ?? 0;
  return {
    request: message.request,
    type: message.type,
    solve_ms: t.solve_ms ?? 0,
    reconstruct_ms: t.reconstruct_ms ?? 0,
    lines_ms: t.lines_ms ?? 0,
    scalar_ms: t.scalar_ms ?? 0,
    full_ms: t.full_ms,
    server_ms: server,
    transfer_ms: arrivedAt - sentAt - server,
    draw_ms: drawnAt - arrivedAt,
    update_ms: updatedAt - arrivedAt, // of draw_ms: decoding and buffers
    render_ms: drawnAt - updatedAt, // of draw_ms: the frame, CPU and GPU
    total_ms: drawnAt - sentAt,
    bytes,
  };
}

export function median(values) {
  if (values.length === 0) return NaN;
  const s = [...values].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

function format(column, x) {
  if (!Number.isFinite(x)) return '–';
  if (column === 'bytes') return x >= 1e6 ? `${(x / 1e6).toFixed(2)} MB` : x >= 1e3 ? `${(x / 1e3).toFixed(1)} kB` : `${x} B`;
  return x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2);
}

// The panel: a table of the last edit and the median of the last 20.
export class LatencyPanel {
  constructor(table) {
    this.table = table;
    this.log = [];
  }

  add(entry) {
    this.log.push(entry);
    if (this.log.length > 1000) this.log.splice(0, this.log.length - 1000);
    this.show();
  }

  // The exact field of request `request` is on screen (exact answers on): `times.exact_ms`
  // from sending the edit to the frame that shows it.
  exact(request, times) {
    const entry = [...this.log].reverse().find((e) => e.request === request);
    if (!entry) return;
    Object.assign(entry, times);
    this.show();
  }

  show() {
    // Edits only: the first field and display changes are not what the panel is about.
    const edits = this.log.filter((e) => ['add', 'change', 'remove', 'clear', 'load'].includes(e.type));
    const last = edits[edits.length - 1];
    const recent = edits.slice(-20);
    const rows = COLUMNS.map((c) => {
      const label = c === 'bytes' ? 'message' : c === 'exact_ms' ? 'exact field' : c.replace('_ms', '');
      return `<tr><th>${label}</th><td>${last ? format(c, last[c]) : '–'}</td>` +
        `<td>${format(c, median(recent.map((e) => e[c])))}</td></tr>`;
    });
    this.table.innerHTML = `<tr><th></th><th>last${last ? ` (${last.type})` : ''}</th>` +
      `<th>median of ${recent.length}</th></tr>${rows.join('')}`;
  }
}
