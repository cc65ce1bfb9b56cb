// The curve session as the page sees it: the stroke, the fit settings and the last fit.  Every
// change goes through one keyed request, built when it leaves, so that at most one fit is in
// flight and one waits: a slider dragged fast sends only its latest tolerance.  The stroke
// itself is sent once; later changes send the settings only (the server keeps the stroke).

export class CurveSession {
  // connection: the Connection; line: its StatusLine; view: the StrokeView; ui: the panel.
  constructor(connection, line, view, ui) {
    Object.assign(this, { line, view, ui });
    this.queue = connection.queue;
    this.info = null;
    this.fit = null; // { header, arrays } of the last answer
    this.settings = { degree: 3, error: 'max', tolerance: 2, algorithm: 'greedy', closed: false };
    this.stroke = [];
    this.version = 0; // of the page's stroke
    this.serverVersion = 0; // of the stroke the server holds
    this.sendingVersion = 0;
    this.log = []; // answers: { type, request, knots, tolerance, fit_ms, server_ms, total_ms }
  }

  onText(message) {
    if (message.type === 'info') {
      this.info = message;
      this.ui.info(message);
    }
    return false;
  }

  onBinary(header, arrays, bytes, arrivedAt) {
    if (header.type !== 'curve') return;
    const entry = this.queue.matches(header.request);
    if (entry?.message.type === 'stroke') this.serverVersion = this.sendingVersion;
    if (entry?.message.type === 'clear') this.serverVersion = 0;
    this.fit = header.points > 0 ? { header, arrays } : null;
    this.view.setFit(this.fit);
    const total = entry ? arrivedAt - entry.sentAt : NaN;
    if (entry && entry.message.type !== 'hello') {
      this.log.push({ type: entry.message.type, request: header.request, knots: header.knots,
        tolerance: header.tolerance, fit_ms: header.timings?.fit_ms, server_ms: header.timings?.server_ms, total_ms: total });
      if (this.log.length > 1000) this.log.splice(0, this.log.length - 1000);
    }
    this.ui.fit(header, total);
    this.line.status(this.fit ? 'move the slider: the knots follow the tolerance; a new stroke replaces this one'
      : 'draw a stroke with the mouse');
    this.line.shown();
    this.queue.onFieldDrawn(entry, header);
  }

  // The message that brings the server to the page's state (null: nothing to fit).
  build() {
    if (this.stroke.length === 0) return null;
    const settings = { ...this.settings };
    if (this.version !== this.serverVersion) {
      this.sendingVersion = this.version;
      return { type: 'stroke', points: this.stroke, ...settings };
    }
    return { type: 'fit', ...settings };
  }

  request() {
    return this.queue.push({
      key: 'fit',
      build: () => this.build(),
      // A refused setting leaves the session as it was: the panel shows the last fit's again.
      onError: () => {
        if (this.fit) {
          const h = this.fit.header;
          Object.assign(this.settings, { degree: h.degree, error: h.error, algorithm: h.algorithm, closed: h.closed,
            tolerance: h.tolerance });
          this.ui.settings(this.settings);
        }
      },
    });
  }

  // points: [[x, y], ...] in CSS pixels, as drawn.
  setStroke(points) {
    const last = points[points.length - 1];
    // A closed curve must not repeat its start: the closing piece is implied.
    if (points.length > 2 && last[0] === points[0][0] && last[1] === points[0][1]) points = points.slice(0, -1);
    this.stroke = points;
    ++this.version;
    this.view.setStroke(points);
    return this.request();
  }

  // changes: some of degree, error, tolerance, algorithm, closed.
  setSettings(changes) {
    Object.assign(this.settings, changes);
    return this.request();
  }

  clear() {
    this.stroke = [];
    ++this.version;
    this.view.setStroke([]);
    return this.queue.push({ key: 'fit', build: () => ({ type: 'clear' }) });
  }
}
