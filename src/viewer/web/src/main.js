// The viewer page of `tvf serve`: the 3D view, the status line and the latency panel every
// session kind shares, and the connection, which mounts the kind the server's `hello` answer
// names (kinds.js).  The address tvf serve prints carries the token the WebSocket needs.
import { Viewer } from './viewer.js';
import { LatencyPanel } from './latency.js';
import { StatusLine } from './status.js';
import { Connection } from './connection.js';
import { registerKind } from './kinds.js';
import { fieldKind } from './tangent_vector_fields/index.js';

registerKind('vector_field', fieldKind);
registerKind('n_field', fieldKind);

const viewer = new Viewer(document.getElementById('canvas'));
const latency = new LatencyPanel(document.getElementById('latency'));
latency.show();
const connection = new Connection(viewer, latency, new StatusLine());
const parameters = new URLSearchParams(location.search);
const token = encodeURIComponent(parameters.get('token') ?? '');
connection.open(`${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws?token=${token}`,
  parameters.get('kind'));
