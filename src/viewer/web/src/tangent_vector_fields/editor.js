// The field session as the page sees it: the constraints and their handles, the last field,
// and the actions the tools and the panel call.  The connection (../connection.js) hands it
// the session's messages.
import { Handle, drawHandle } from './handles.js';
import { latencyEntry } from '../latency.js';

export class Editor {
  // connection: the Connection; viewer: its Viewer; latency: its LatencyPanel; line: its
  // StatusLine; ui: callbacks the panel provides (info, field, selection, constraints, ...).
  constructor(connection, viewer, latency, line, ui) {
    this.viewer = viewer;
    this.latency = latency;
    this.line = line;
    this.ui = ui;
    this.handles = new Set();
    this.selected = null;
    this.info = null;
    this.field = null;
    this.n = 1; // the design's n: 1 for vector fields
    this.display = { lines: 'fur', strokes: 4000, length: 0.03, separation: 0.02, colour: 'magnitude' };
    this.sentTimes = new Map(); // request -> when it left: the exact fields that follow edits
    this.queue = connection.queue;
    this.mesh = connection.mesh;
  }

  sent(message, sentAt) {
    this.sentTimes.set(message.request, sentAt);
    if (this.sentTimes.size > 200) this.sentTimes.delete(this.sentTimes.keys().next().value);
  }

  onMesh(arrays) {
    this.mesh = arrays;
  }

  // True for a message that answers no request.
  onText(message) {
    const entry = this.queue.inflight;
    switch (message.type) {
      case 'info':
        this.info = message;
        this.n = message.n ?? 1;
        this.display = { ...this.display, ...message.display };
        this.display.colour = message.display?.scalar && message.display.scalar !== 'none'
          ? message.display.scalar : 'magnitude';
        this.ui.info(message);
        break;
      case 'added':
        if (entry?.handle) entry.handle.id = message.id;
        break;
      case 'loaded':
        if (entry?.handles) entry.handles.forEach((h, i) => { h.id = message.ids[i]; });
        break;
      case 'refinement_failed': // unasked, like the exact fields: not an answer to a request
        this.line.error(message.message);
        return true;
    }
    return false;
  }

  onBinary(header, arrays, bytes, arrivedAt) {
    if (header.type === 'preview') return this.onPreview(arrays);
    if (header.type !== 'field') return;
    if (header.refined) return this.onExact(header, arrays, arrivedAt);
    const entry = this.queue.matches(header.request);
    this.field = { header, arrays };
    this.showField();
    if (entry?.onDone) entry.onDone(header, entry.message);
    this.syncHandles(header.ids || []);
    // The frame that shows the field, finished on the GPU: the end of draw_ms.
    const updatedAt = performance.now();
    this.viewer.renderNow();
    this.viewer.finish();
    const drawnAt = performance.now();
    if (entry) {
      this.latency.add(latencyEntry(entry.message, header, bytes,
        { sentAt: entry.sentAt, arrivedAt, updatedAt, drawnAt }));
      // An edit answered exactly at once (the worker was quicker than the reduced field):
      // its exact field is this frame.
      if (header.answer?.exact && header.answer?.pending === 0) {
        this.latency.exact(header.request, { exact_ms: drawnAt - entry.sentAt, exact_server_ms: header.timings?.server_ms,
          exact_transfer_ms: arrivedAt - entry.sentAt - (header.timings?.server_ms ?? 0) });
      }
    }
    this.ui.field(header);
    this.queue.onFieldDrawn(entry, header);
  }

  // The exact field that follows an edit's reduced one (exact answers on): it replaces the
  // field whole, in one frame; the latency log gets the time from the edit to this frame.
  onExact(header, arrays, arrivedAt) {
    this.field = { header, arrays };
    this.showField();
    this.syncHandles(header.ids || []);
    this.viewer.renderNow();
    this.viewer.finish();
    const drawnAt = performance.now();
    const sentAt = this.sentTimes.get(header.request);
    if (sentAt !== undefined) {
      this.latency.exact(header.request, { exact_ms: drawnAt - sentAt, exact_server_ms: header.timings?.server_ms,
        exact_transfer_ms: arrivedAt - sentAt - (header.timings?.server_ms ?? 0) });
    }
    this.ui.field(header);
  }

  // The strokes of the reduced answer, sent before its field: drawn at once over the last
  // field's colours; the field that follows replaces them.
  onPreview(arrays) {
    if (!this.mesh || this.display.lines !== 'fur') return;
    this.viewer.setLines(arrays.lines, this.display.colour === 'magnitude', true);
    this.viewer.renderNow();
  }

  // Colours and lines of the last field, as the display asks.
  showField() {
    if (!this.field || !this.mesh) return;
    const { header, arrays } = this.field;
    const colour = this.display.colour;
    if (colour === 'magnitude') this.viewer.colourByMagnitude(arrays.vectors, header.magnitude_max);
    else if (colour === 'energy' && arrays.scalar && header.scalar_on === 'faces') {
      this.viewer.colourByFaceEnergy(arrays.scalar, header.scalar_range || [0, 0]);
    } else if ((colour === 'divergence' || colour === 'curl') && arrays.scalar) {
      this.viewer.colourByScalar(arrays.scalar, header.scalar_range || [0, 0]);
    } else this.viewer.colourUniform();
    this.viewer.setSingularities(arrays.singular_vertices, arrays.singular_indices, header.n || 1);
    this.viewer.setLines(arrays.lines, colour === 'magnitude', this.display.lines === 'fur');
  }

  // Handles whose constraint the server no longer has go away; the others are confirmed.
  syncHandles(ids) {
    const present = new Set(ids);
    for (const h of [...this.handles]) {
      if (h.id !== null && !present.has(h.id)) this.dispose(h);
    }
    this.ui.constraints();
    if (this.selected) this.ui.selection(this.selected); // its id may just have arrived
  }

  dispose(handle) {
    handle.removed = true;
    this.viewer.handles.remove(handle.group);
    this.handles.delete(handle);
    if (this.selected === handle) this.select(null);
    this.viewer.requestRender();
  }

  select(handle) {
    const previous = this.selected;
    this.selected = handle;
    if (previous && !previous.removed) drawHandle(previous, this.viewer, false);
    if (handle) drawHandle(handle, this.viewer, true);
    this.ui.selection(handle);
  }

  redraw(handle) {
    if (!handle.removed) drawHandle(handle, this.viewer, handle === this.selected);
  }

  newHandle(constraint, anchor) {
    const handle = new Handle(constraint, anchor, this.n);
    this.handles.add(handle);
    this.viewer.handles.add(handle.group);
    this.redraw(handle);
    return handle;
  }

  // --- Actions: each returns the Promise of its answer (see RequestQueue.push). ---

  add(constraint, anchor = null) {
    const handle = this.newHandle(constraint, anchor);
    const promise = this.queue.push({
      build: () => ({ type: 'add', constraint: handle.constraint }),
      handle,
      onDone: (header, message) => { handle.confirmed = message.constraint; },
      onError: () => this.dispose(handle),
    });
    return { handle, promise };
  }

  // A new constraint for an existing handle; merged with a change still waiting to be sent.
  change(handle, constraint) {
    handle.constraint = constraint;
    this.redraw(handle);
    if (handle === this.selected) this.ui.selection(handle);
    return this.queue.push({
      key: handle,
      build: () => (handle.removed || handle.id === null ? null
        : { type: 'change', id: handle.id, constraint: handle.constraint }),
      onDone: (header, message) => { handle.confirmed = message.constraint; },
      onError: () => {
        if (handle.confirmed) handle.constraint = handle.confirmed;
        this.redraw(handle);
        if (handle === this.selected) this.ui.selection(handle);
      },
    });
  }

  remove(handle) {
    handle.group.visible = false;
    if (this.selected === handle) this.select(null);
    this.viewer.requestRender();
    return this.queue.push({
      build: () => (handle.removed || handle.id === null ? null : { type: 'remove', id: handle.id }),
      onError: () => { handle.group.visible = true; this.viewer.requestRender(); },
    });
  }

  clear() {
    this.select(null);
    return this.queue.push({ build: () => ({ type: 'clear' }) });
  }

  // file: a constraint file object.  Its constraints get handles at once; the server's
  // `loaded` gives them their ids.
  load(file) {
    const handles = (file.constraints || []).map((c) => this.newHandle(c));
    return this.queue.push({
      build: () => ({ type: 'load', file }),
      handles,
      onDone: () => handles.forEach((h) => { h.confirmed = h.constraint; }),
      onError: () => handles.forEach((h) => this.dispose(h)),
    });
  }

  save() {
    return this.queue.push({ build: () => ({ type: 'save' }) });
  }

  // A refused setting leaves the session as it was: the panel shows the last field's again.
  restoreSettings() {
    if (this.field) this.ui.settings(this.field.header);
  }

  setOmega(omega) {
    return this.queue.push({ key: 'omega', build: () => ({ type: 'set_omega', omega }),
      onError: () => this.restoreSettings() });
  }

  setBasisSize(size) {
    return this.queue.push({ key: 'basis', build: () => ({ type: 'set_basis_size', size }),
      onError: () => this.restoreSettings() });
  }

  setSolver(solver) {
    return this.queue.push({ key: 'solver', build: () => ({ type: 'set_solver', solver }),
      onError: () => this.restoreSettings() });
  }

  // changes: some of lines, strokes, length, separation, colour.  The server computes what
  // the display needs, so the colour decides whether it computes a scalar.
  setDisplay(changes) {
    Object.assign(this.display, changes);
    this.ui.displaySettings(this.display);
    this.showField();
    return this.queue.push({
      key: 'display',
      build: () => {
        const d = this.display;
        const scalar = ['divergence', 'curl', 'energy'].includes(d.colour) ? d.colour : 'none';
        return { type: 'set_display', lines: d.lines, strokes: d.strokes, length: d.length,
          separation: d.separation, scalar };
      },
    });
  }

  // Another kind of field: n = 1 vector fields, n > 1 n-direction fields.  The constraints of
  // the old kind do not carry over: their handles go at once.
  setN(n) {
    this.select(null);
    for (const h of [...this.handles]) this.dispose(h);
    return this.queue.push({ key: 'n', build: () => ({ type: 'set_n', n }),
      onError: () => this.ui.showN(this.n) });
  }

  ping() {
    return this.queue.push({ build: () => ({ type: 'ping' }) });
  }

  // The constraints the server holds, as it accepted them.
  constraints() {
    const ids = new Set(this.field?.header.ids || []);
    return [...this.handles]
      .filter((h) => h.id !== null && ids.has(h.id) && h.confirmed)
      .map((h) => ({ id: h.id, constraint: h.confirmed }));
  }

  handleById(id) {
    for (const h of this.handles) if (h.id === id) return h;
    return null;
  }
}
