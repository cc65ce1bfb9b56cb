// The viewer page of `tvf serve`: the 3D view, the status line and the latency panel every
// session kind shares, and the connection, which mounts the kind the server's `hello` answer
// names (kinds.js).  The address tvf serve prints carries the token the WebSocket needs;
// `&kind=curve` (or the Session menu) asks for another kind than the server's first.
import { Viewer } from './viewer.js';
import { LatencyPanel } from './latency.js';
import { StatusLine } from './status.js';
import { Connection } from './connection.js';
import { registerKind, kindNames } from './kinds.js';
import { fieldKind } from './tangent_vector_fields/index.js';
import { curveKind } from './spline_approximation/index.js';
import { simulationKind } from './projective_dynamics/index.js';

registerKind('vector_field', fieldKind);
registerKind('n_field', fieldKind);
registerKind('curve', curveKind);
registerKind('simulation', simulationKind);

const viewer = new Viewer(document.getElementById('canvas'));
const latency = new LatencyPanel(document.getElementById('latency'));
latency.show();
const connection = new Connection(viewer, latency, new StatusLine());
const parameters = new URLSearchParams(location.search);
const token = encodeURIComponent(parameters.get('token') ?? '');

// The Session menu opens the page again with another kind (the server's first without one).
const LABELS = { vector_field: 'vector fields', n_field: 'n-direction fields', curve: 'stroke fitting',
  simulation: 'simulation' };
const menu = document.getElementById('kind-menu');
for (const name of kindNames()) menu.add(new Option(LABELS[name] ?? name, name));
menu.value = parameters.get('kind') ?? kindNames()[0];
menu.addEventListener('change', () => {
  parameters.set('kind', menu.value);
  location.search = parameters.toString();
});
connection.open(`${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws?token=${token}`,
  parameters.get('kind'));
