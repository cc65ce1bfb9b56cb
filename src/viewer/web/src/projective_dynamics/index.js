// The simulation session's side of the page (Chapter 3, kind "simulation"): the served
// surface falls onto a floor in real time; drag it with the mouse, poke it, change its
// stiffness while it moves.  window.tvfSimulation is the hook tests drive it with.
import { SimulationSession } from './simulation_session.js';
import panelHtml from './panel.html';

function installHook({ connection, session, viewer }) {
  window.tvfSimulation = {
    ready: connection.ready,
    info: () => session.info,
    state: () => session.state && { ...session.state },
    frames: () => session.frames,
    // The surface as the mesh message brought it: where the body started.
    startPositions: () => Array.from(connection.mesh.positions),
    lastFrame: () => session.frame && { header: session.frame.header, positions: Array.from(session.frame.positions) },
    // Where vertex v is drawn, in client pixels (tests aim the mouse with it).
    screenPoint: (v) => {
      const p = viewer.project(viewer.vertexPosition(v));
      const rect = viewer.canvas.getBoundingClientRect();
      return { x: rect.left + p.x, y: rect.top + p.y };
    },
    // The vertex a press at client (x, y) would grab (null: not on the body).
    vertexAt: (x, y) => {
      const hit = viewer.pick(x, y);
      return hit ? session.nearestCorner(hit) : null;
    },
    log: () => session.log.slice(),
    camera: () => viewer.camera.position.toArray(),
    // The last target a drag sent.
    dragTarget: () => session.lastTarget ?? null,
    request: (message) => connection.queue.push({ build: () => message }),
    idle: () => connection.queue.whenIdle(),
  };
}

export const simulationKind = {
  binaryAnswers: [],
  mount({ connection, viewer, line }) {
    document.getElementById('kind-title').textContent = 'Simulation';
    document.title = 'tvf simulation';
    document.getElementById('kind-panel').innerHTML = panelHtml;
    document.getElementById('help').textContent = 'Left-drag on the body: grab and drag it · ' +
      'Shift-click (or "click pokes"): poke · left-drag elsewhere: orbit · wheel: zoom';
    document.getElementById('latency').closest('section').hidden = true;
    const session = new SimulationSession(connection, viewer, line);
    installHook({ connection, session, viewer });
    return session;
  },
};
