// The drawing surface of the curve session: a 2D canvas over the view.  The left button draws
// a stroke (pointer events, in CSS pixels of the canvas); the fit is drawn over it.
const MIN_STEP_PX = 1; // closer pointer samples add nothing but zero-length pieces

export class StrokeView {
  // container: the element the canvas fills; onStroke(points): a stroke was drawn.
  constructor(container, onStroke) {
    this.canvas = document.createElement('canvas');
    this.canvas.id = 'curve-canvas';
    // Right above the 3D view's canvas: the help line and the waiting text stay on top.
    container.insertBefore(this.canvas, container.querySelector('#canvas')?.nextSibling ?? null);
    this.context = this.canvas.getContext('2d');
    this.onStroke = onStroke;
    this.drawing = null; // the points of the stroke being drawn
    this.stroke = [];
    this.fit = null; // { header, arrays } of the last answer
    this.showPolygon = false;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.canvas.addEventListener('pointerdown', (e) => this.down(e));
    this.canvas.addEventListener('pointermove', (e) => this.move(e));
    this.canvas.addEventListener('pointerup', (e) => this.up(e));
    this.canvas.addEventListener('pointercancel', (e) => this.up(e));
  }

  resize() {
    const box = this.canvas.getBoundingClientRect();
    const ratio = Math.min(window.devicePixelRatio || 1, 2);
    this.canvas.width = Math.max(1, Math.round(box.width * ratio));
    this.canvas.height = Math.max(1, Math.round(box.height * ratio));
    this.context.setTransform(ratio, 0, 0, ratio, 0, 0);
    this.draw();
  }

  point(e) {
    const box = this.canvas.getBoundingClientRect();
    return [e.clientX - box.left, e.clientY - box.top];
  }

  add(p) {
    const last = this.drawing[this.drawing.length - 1];
    if (Math.hypot(p[0] - last[0], p[1] - last[1]) >= MIN_STEP_PX) this.drawing.push(p);
  }

  down(e) {
    if (e.button !== 0) return;
    this.canvas.setPointerCapture(e.pointerId);
    this.drawing = [this.point(e)];
    this.fit = null;
    this.draw();
  }

  move(e) {
    if (!this.drawing) return;
    for (const c of e.getCoalescedEvents?.() ?? [e]) this.add(this.point(c));
    this.draw();
  }

  up(e) {
    if (!this.drawing) return;
    if (e.type === 'pointerup') this.add(this.point(e));
    const points = this.drawing;
    this.drawing = null;
    if (points.length >= 2) {
      this.stroke = points;
      this.onStroke(points);
    }
    this.draw();
  }

  setStroke(points) {
    this.stroke = points;
    this.draw();
  }

  setFit(fit) {
    this.fit = fit;
    this.draw();
  }

  setPolygon(show) {
    this.showPolygon = show;
    this.draw();
  }

  draw() {
    const c = this.context;
    const box = this.canvas.getBoundingClientRect();
    c.clearRect(0, 0, box.width, box.height);
    const stroke = this.drawing ?? this.stroke;
    polyline(c, stroke, false, { colour: '#9aa3b2', width: 4 });
    if (!this.fit || this.drawing) return;
    const { header, arrays } = this.fit;
    const d = header.dimension;
    const points = (array) => Array.from({ length: array.length / d }, (_, i) => [array[d * i], array[d * i + 1]]);
    if (this.showPolygon && arrays.control_polygon) {
      const control = points(arrays.control_polygon);
      c.setLineDash([5, 4]);
      polyline(c, control, header.closed, { colour: '#e08a1e', width: 1.2 });
      c.setLineDash([]);
      for (const [x, y] of control) c.strokeRect(x - 3, y - 3, 6, 6);
    }
    const curve = arrays.curve ? points(arrays.curve) : [];
    polyline(c, curve, false, { colour: '#1d4ed8', width: 2.2 });
    if (arrays.knot_points) {
      c.fillStyle = '#d32f2f';
      for (const [x, y] of points(arrays.knot_points)) {
        c.beginPath();
        c.arc(x, y, 4.5, 0, 2 * Math.PI);
        c.fill();
      }
    }
    if (!header.closed && curve.length >= 2) { // the ends: the clamped spline's end knots
      c.fillStyle = '#1d2330';
      for (const [x, y] of [curve[0], curve[curve.length - 1]]) c.fillRect(x - 3, y - 3, 6, 6);
    }
  }
}

function polyline(c, points, closed, { colour, width }) {
  if (points.length < 2) return;
  c.strokeStyle = colour;
  c.lineWidth = width;
  c.lineJoin = 'round';
  c.lineCap = 'round';
  c.beginPath();
  c.moveTo(points[0][0], points[0][1]);
  for (let i = 1; i < points.length; ++i) c.lineTo(points[i][0], points[i][1]);
  if (closed) c.closePath();
  c.stroke();
}
