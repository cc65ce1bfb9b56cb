// The curve session's side of the page (Chapter 6, kind "curve"): a stroke drawn with the
// mouse on a 2D canvas over the view, fitted by the server with the fewest knots within a
// tolerance.  window.tvfCurve is the hook tests drive it with.
import { CurveSession } from './curve_session.js';
import { CurvePanel, sliderToTolerance } from './panel.js';
import { StrokeView } from './stroke_view.js';
import panelHtml from './panel.html';

function installHook({ connection, session, view }) {
  const copy = (a) => (a ? Array.from(a) : []);
  window.tvfCurve = {
    ready: connection.ready,
    info: () => session.info,
    settings: () => ({ ...session.settings }),
    // The page's stroke, and the last fit: its header and arrays as plain arrays.
    stroke: () => session.stroke.map((p) => [...p]),
    lastFit: () => session.fit && {
      header: session.fit.header,
      curve: copy(session.fit.arrays.curve),
      knots: copy(session.fit.arrays.knot_points),
      control: copy(session.fit.arrays.control_polygon),
    },
    log: () => session.log.slice(),
    sliderToTolerance,
    // Resolves when no request waits or is in flight.
    idle: () => session.queue.whenIdle(),
    request: (message) => session.queue.push({ build: () => message }),
    polygon: (show) => view.setPolygon(show),
  };
}

export const curveKind = {
  binaryAnswers: ['stroke', 'fit', 'clear'],
  mount({ connection, viewer, line }) {
    document.getElementById('kind-title').textContent = 'Stroke fitting';
    document.title = 'tvf stroke fitting';
    document.getElementById('kind-panel').innerHTML = panelHtml;
    document.getElementById('help').textContent = 'Left-drag: draw a stroke (a new one replaces it) · ' +
      'the slider: the tolerance, re-fitted as it moves';
    // The 3D view and what belongs to it (latency of field edits, the mesh) are not used here.
    viewer.canvas.style.visibility = 'hidden';
    for (const id of ['latency', 'mesh-info']) document.getElementById(id).closest('section').hidden = true;
    const panel = new CurvePanel();
    let session = null;
    const view = new StrokeView(document.getElementById('view'), (points) => session.setStroke(points));
    session = new CurveSession(connection, line, view, panel);
    panel.bind(session, view);
    installHook({ connection, session, view });
    return session;
  },
};
