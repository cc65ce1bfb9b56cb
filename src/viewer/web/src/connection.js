// The WebSocket to the server (doc/viewer/protocol.md), shared by every session kind: it sends
// `hello`, mounts the kind the answer names, shows the server's progress and errors, hands the
// mesh to the 3D view and every other message to the kind.
import { decodeBinary, RequestQueue } from './protocol.js';
import { kindNamed, kindNames } from './kinds.js';

// How long the render loop waits for an answer before drawing without it.
const HOLD_FRAMES_MS = 40;

export class Connection {
  // viewer: the Viewer; latency: the LatencyPanel; line: the StatusLine.
  constructor(viewer, latency, line) {
    Object.assign(this, { viewer, latency, line });
    this.session = null; // the kind's page side, once the server said which kind
    this.opened = false;
    this.mesh = null;
    this.queue = new RequestQueue((message) => {
      const sentAt = performance.now();
      this.session?.sent?.(message, sentAt);
      this.socket.send(JSON.stringify(message));
      this.viewer.holdFrames(sentAt + HOLD_FRAMES_MS);
      return sentAt;
    });
    this.ready = new Promise((resolve, reject) => {
      this.resolveReady = resolve;
      this.rejectReady = reject;
    });
    this.ready.catch(() => {});
  }

  // kind: the session kind to ask for (null: the server's first).
  open(url, kind) {
    this.socket = new WebSocket(url);
    this.socket.binaryType = 'arraybuffer';
    this.socket.onopen = () => {
      this.opened = true;
      this.line.status('connected; waiting for the server');
      this.queue.push({ build: () => (kind ? { type: 'hello', kind } : { type: 'hello' }) })
        .then(() => this.resolveReady(), this.rejectReady);
    };
    this.socket.onmessage = (event) => {
      const arrivedAt = performance.now();
      try {
        if (typeof event.data === 'string') this.onText(JSON.parse(event.data));
        else this.onBinary(event.data, arrivedAt);
      } catch (e) {
        this.line.error(`bad message from the server: ${e.message}`);
        console.error(e);
      }
    };
    this.socket.onclose = () => {
      // A refused upgrade (a missing or wrong token: 403) closes before it opened.
      this.line.error(!this.opened
        ? 'the server refused the connection: open the address tvf serve printed, with its ?token=...'
        : 'the connection to the server is closed; reload the page once the server runs again');
      this.queue.failAll('connection closed');
      this.rejectReady(new Error('connection closed'));
    };
  }

  mount(name) {
    const kind = kindNamed(name);
    if (!kind) throw new Error(`the server's session kind ${name} is not one this page shows (${kindNames().join(', ')})`);
    for (const type of kind.binaryAnswers) this.queue.binaryAnswers.add(type);
    this.session = kind.mount({ connection: this, viewer: this.viewer, latency: this.latency, line: this.line });
    if (this.mesh) this.session.onMesh?.(this.mesh);
  }

  onText(message) {
    switch (message.type) {
      case 'status':
      case 'progress':
        this.line.progress(message.stage, message.fraction);
        break;
      case 'error':
        this.line.error(message.message);
        break;
      case 'info':
        if (!this.session) this.mount(message.kind ?? kindNames()[0]);
        break;
    }
    if (this.session?.onText(message)) return; // unasked: answers no request
    const answered = this.queue.matches(message.request);
    if (message.type === 'error' && answered?.onError) answered.onError(message);
    this.queue.onText(message);
  }

  onBinary(buffer, arrivedAt) {
    const { header, arrays } = decodeBinary(buffer);
    if (header.type === 'mesh') {
      this.mesh = arrays;
      this.viewer.setMesh(arrays);
      this.session?.onMesh?.(arrays);
      return;
    }
    this.session?.onBinary(header, arrays, buffer.byteLength, arrivedAt);
  }
}
