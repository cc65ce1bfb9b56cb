// The editor's server under load: many sessions at once against one `tvf serve`, each editing as
// fast as its answers come (a value edit, then the next as soon as its field arrives).  Per round:
// sessions held, edits answered per second (all sessions together) and the latency of an edit, and
// the server's resident memory before, at the end of the round, and after its sessions closed:
// what a dropped session held must come back.  Rounds alternate exact answers off and on.
//
//   node bench/bench_server_load.mjs --tvf build/tvf --mesh M.off --basis M.tvfb [--size 300]
//        [--sessions 1,4,16] [--seconds 8] [--constraints 10]
//
// A WebSocket client of its own (RFC 6455, the little the protocol needs), so that it runs on any
// node without packages.
import { spawn } from 'node:child_process';
import crypto from 'node:crypto';
import fs from 'node:fs';
import net from 'node:net';

function options(argv) {
  const o = { size: '300', sessions: '1,4,16', seconds: '8', constraints: '10' };
  for (let i = 2; i < argv.length; i += 2) {
    if (!argv[i].startsWith('--') || i + 1 >= argv.length) throw new Error(`bad argument ${argv[i]}`);
    o[argv[i].slice(2)] = argv[i + 1];
  }
  for (const required of ['tvf', 'mesh', 'basis']) if (!o[required]) throw new Error(`missing --${required}`);
  return o;
}

// One WebSocket connection: send(text), next(predicate) -> the next message it accepts.
class Socket {
  // address: { port, token } from the address tvf serve printed.
  static open(address) {
    return new Promise((resolve, reject) => {
      const s = new Socket(net.connect(address.port, '127.0.0.1'));
      const key = crypto.randomBytes(16).toString('base64');
      s.socket.on('error', reject);
      s.socket.once('connect', () => s.socket.write(`GET /ws?token=${address.token} HTTP/1.1\r\n` +
        `Host: 127.0.0.1:${address.port}\r\nUpgrade: websocket\r\n` +
        `Connection: Upgrade\r\nSec-WebSocket-Key: ${key}\r\nSec-WebSocket-Version: 13\r\n\r\n`));
      s.onUpgrade = (status) => (status.includes(' 101 ') ? resolve(s) : reject(new Error(status)));
    });
  }
  constructor(socket) {
    this.socket = socket;
    this.buffer = Buffer.alloc(0);
    this.upgraded = false;
    this.messages = [];
    this.waiters = [];
    this.fragments = [];
    socket.on('data', (chunk) => this.receive(chunk));
  }
  receive(chunk) {
    this.buffer = Buffer.concat([this.buffer, chunk]);
    if (!this.upgraded) {
      const end = this.buffer.indexOf('\r\n\r\n');
      if (end < 0) return;
      const status = this.buffer.subarray(0, this.buffer.indexOf('\r\n')).toString();
      this.buffer = this.buffer.subarray(end + 4);
      this.upgraded = true;
      this.onUpgrade(status);
    }
    for (;;) {
      if (this.buffer.length < 2) return;
      const opcode = this.buffer[0] & 0x0f, fin = this.buffer[0] & 0x80;
      let length = this.buffer[1] & 0x7f, offset = 2;
      if (length === 126) {
        if (this.buffer.length < 4) return;
        length = this.buffer.readUInt16BE(2);
        offset = 4;
      } else if (length === 127) {
        if (this.buffer.length < 10) return;
        length = Number(this.buffer.readBigUInt64BE(2));
        offset = 10;
      }
      if (this.buffer.length < offset + length) return;
      const payload = this.buffer.subarray(offset, offset + length);
      this.buffer = this.buffer.subarray(offset + length);
      if (opcode === 0x8) return; // close
      if (opcode === 0x9 || opcode === 0xa) continue; // ping, pong
      if (opcode !== 0) this.opcode = opcode;
      this.fragments.push(payload);
      if (!fin) continue;
      const data = Buffer.concat(this.fragments);
      this.fragments = [];
      this.deliver(this.opcode === 0x1 ? JSON.parse(data.toString()) : Socket.header(data));
    }
  }
  // The JSON header of a binary message (the arrays after it are not needed here).
  static header(data) {
    const n = data.readUInt32LE(0);
    return JSON.parse(data.subarray(4, 4 + n).toString());
  }
  deliver(message) {
    const i = this.waiters.findIndex((w) => w.accept(message));
    if (i >= 0) this.waiters.splice(i, 1)[0].resolve(message);
    else this.messages.push(message);
  }
  next(accept) {
    const i = this.messages.findIndex(accept);
    if (i >= 0) return Promise.resolve(this.messages.splice(i, 1)[0]);
    return new Promise((resolve) => this.waiters.push({ accept, resolve }));
  }
  send(object) {
    const payload = Buffer.from(JSON.stringify(object));
    const mask = crypto.randomBytes(4);
    const head = payload.length < 126 ? Buffer.from([0x81, 0x80 | payload.length])
      : Buffer.from([0x81, 0x80 | 126, payload.length >> 8, payload.length & 0xff]);
    const masked = Buffer.from(payload.map((b, i) => b ^ mask[i & 3]));
    this.socket.write(Buffer.concat([head, mask, masked]));
  }
  close() {
    this.socket.destroy();
  }
}

const residentMegabytes = (pid) => {
  const line = fs.readFileSync(`/proc/${pid}/status`, 'utf8').split('\n').find((l) => l.startsWith('VmRSS:'));
  return Number(line.split(/\s+/)[1]) / 1024;
};
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const median = (v) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length ? s[s.length >> 1] : NaN;
};

// A session: hello, a constraint set, the mode, then value edits for the round's seconds.
async function session(address, o, exact, faces, latencies) {
  const ws = await Socket.open(address);
  let request = 1;
  // Sends `message` and waits for its answer: by default its field (the immediate one, not an
  // exact field that follows unasked).
  const ask = async (message, type = 'field') => {
    const r = (message.request = request++);
    ws.send(message);
    const reply = await ws.next((m) => m.request === r && ((m.type === type && !m.refined) || m.type === 'error'));
    if (reply.type === 'error') throw new Error(reply.message);
    return reply;
  };
  ws.send({ type: 'hello' });
  await ws.next((m) => m.type === 'field');
  // Vectors in faces spread over the mesh: any 3D vector is projected onto its face.
  const constraints = [];
  for (let k = 0; k < Number(o.constraints); ++k) {
    const face = (7919 * (k + 1) + Math.floor(Math.random() * faces)) % faces;
    const added = await ask({ type: 'add', constraint: { type: 'vector', face, vector: [1, 0.5, 0.25] } }, 'added');
    constraints.push({ id: added.id, face });
    await ws.next((m) => m.type === 'field' && m.request === added.request);
  }
  if (exact) await ask({ type: 'set_solver', solver: 'full' });
  // Each session edits for the round's seconds from the end of its own set-up (with exact
  // answers, the set-up of 16 sessions at once takes longer than a round).
  let edits = 0;
  const editing = Date.now();
  const until = editing + 1000 * Number(o.seconds);
  for (let k = 0; Date.now() < until; ++k) {
    const c = constraints[k % constraints.length];
    const start = performance.now();
    await ask({ type: 'change', id: c.id,
      constraint: { type: 'vector', face: c.face, vector: k % 2 ? [1, 0.5, 0.25] : [-0.5, 1, 0.2] } });
    latencies.push(performance.now() - start);
    ++edits;
    ws.messages.length = 0; // exact fields that came unasked
  }
  return { ws, edits, seconds: (Date.now() - editing) / 1000 };
}

async function main() {
  const o = options(process.argv);
  const server = spawn(o.tvf, ['serve', o.mesh, '--basis', o.basis, '-d', o.size, '--port', '0'],
    { stdio: ['ignore', 'pipe', 'inherit'] });
  const address = await new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/http:\/\/127\.0\.0\.1:(\d+)\/\?token=([0-9a-f]+)/);
      if (m) resolve({ port: Number(m[1]), token: m[2] });
    });
    server.on('exit', (code) => reject(new Error(`tvf serve exited with ${code}`)));
  });
  try {
    // One session first: the basis is loaded (or computed) before anything is measured.
    const first = await Socket.open(address);
    first.send({ type: 'hello' });
    const info = await first.next((m) => m.type === 'info');
    await first.next((m) => m.type === 'field');
    first.close();
    await sleep(500);
    const faces = info.mesh.faces;
    console.log(`tvf serve ${o.mesh}: ${faces} faces, basis ${info.basis.size} of ${info.basis.available}; ` +
      `${o.constraints} vector constraints per session, value edits for ${o.seconds} s per round`);
    const idle = residentMegabytes(server.pid);
    console.log(`resident memory with the basis loaded and no session: ${idle.toFixed(0)} MB\n`);
    console.log('| sessions | exact answers | edits answered per second | edit latency, median (90%) | ' +
      'memory at the end of the round | memory after its sessions closed |');
    console.log('|---|---|---|---|---|---|');
    // Every configuration twice: memory that grows from the first round to the second
    // would be a leak, memory that stays is what the allocator keeps.
    for (const exact of [false, true]) {
      for (const n of [...o.sessions.split(',').map(Number), ...o.sessions.split(',').map(Number)]) {
        const latencies = [];
        const results = await Promise.all(Array.from({ length: n }, () => session(address, o, exact, faces, latencies)));
        // Edits per second of each session while it edited, summed.
        const rate = results.reduce((s, r) => s + r.edits / r.seconds, 0);
        const during = residentMegabytes(server.pid);
        for (const r of results) r.ws.close();
        await sleep(1500);
        const after = residentMegabytes(server.pid);
        const sorted = [...latencies].sort((a, b) => a - b);
        console.log(`| ${n} | ${exact ? 'yes' : 'no'} | ${rate.toFixed(0)} | ${median(latencies).toFixed(1)} ms ` +
          `(${sorted[Math.floor(0.9 * sorted.length)]?.toFixed(1)} ms) | ${during.toFixed(0)} MB | ${after.toFixed(0)} MB |`);
      }
    }
  } finally {
    server.kill('SIGTERM');
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
