// The messages of the viewer's WebSocket (doc/viewer/protocol.md): binary messages, and the
// queue that keeps at most one request in flight.

// Binary messages: uint32 header length, JSON header, padding to 4 bytes, then the arrays the
// header lists.  The arrays are views on the message buffer, not copies.
export function decodeBinary(buffer) {
  const view = new DataView(buffer);
  if (buffer.byteLength < 4) throw new Error('binary message shorter than its length field');
  const n = view.getUint32(0, true);
  if (4 + n > buffer.byteLength) throw new Error('binary message shorter than its header');
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, n)));
  let offset = 4 + n;
  offset += (4 - (offset % 4)) % 4;
  const arrays = {};
  for (const a of header.arrays || []) {
    const Type = a.type === 'float32' ? Float32Array : a.type === 'uint32' ? Uint32Array : null;
    if (!Type) throw new Error(`array ${a.name} has unknown type ${a.type}`);
    if (offset + 4 * a.length > buffer.byteLength) throw new Error(`array ${a.name} runs past the message`);
    arrays[a.name] = new Type(buffer, offset, a.length);
    offset += 4 * a.length;
  }
  return { header, arrays };
}

// Requests are sent one at a time: the next leaves when the answer of the previous one has
// arrived (its field, or an error).  An edit that arrives while an equal-keyed one waits is
// merged into it, and its message is built only when it is sent, so a drag always sends its
// latest state and never piles up requests behind a slow solve.
export class RequestQueue {
  // send(message) -> the time it left; onField/onText are called by the session.
  constructor(send) {
    this.send = send;
    this.waiting = [];
    this.inflight = null;
    this.nextRequest = 1;
    this.idleWaiters = [];
    // Message types whose answer ends with a binary message (the kind's picture): `hello`'s
    // for every kind, and those the kind adds.
    this.binaryAnswers = new Set(['hello']);
  }

  // entry: {build() -> message or null (nothing to send), key?}.  Returns a Promise of the
  // answer: the field header for field answers (`answer` holds an `added`/`loaded` message),
  // the text answer otherwise.
  push(entry) {
    const promise = new Promise((resolve, reject) => {
      const waiter = { resolve, reject };
      if (entry.key !== undefined) {
        const same = this.waiting.find((e) => e.key === entry.key);
        if (same) {
          same.build = entry.build;
          same.waiters.push(waiter);
          return;
        }
      }
      this.waiting.push({ ...entry, waiters: [waiter] });
      this.pump();
    });
    // Errors reach the user through the status line; a caller that does not wait for the
    // answer must not turn them into unhandled rejections.
    promise.catch(() => {});
    return promise;
  }

  busy() {
    return this.inflight !== null || this.waiting.length > 0;
  }

  // A Promise resolved once nothing waits and nothing is in flight.
  whenIdle() {
    if (!this.busy()) return Promise.resolve();
    return new Promise((resolve) => this.idleWaiters.push(resolve));
  }

  pump() {
    while (!this.inflight && this.waiting.length > 0) {
      const entry = this.waiting.shift();
      const message = entry.build();
      if (!message) {
        entry.waiters.forEach((w) => w.resolve(null));
        continue;
      }
      entry.message = { ...message, request: this.nextRequest++ };
      entry.expectsField = this.binaryAnswers.has(message.type);
      this.inflight = entry;
      entry.sentAt = this.send(entry.message);
    }
    if (!this.busy()) this.idleWaiters.splice(0).forEach((resolve) => resolve());
  }

  // The entry a message answers, if it answers the one in flight.
  matches(request) {
    const e = this.inflight;
    return e && (request === undefined || request === e.message.request) ? e : null;
  }

  // A text message.  Returns the entry it belongs to (or null).
  onText(message) {
    const e = this.matches(message.request);
    if (!e || message.type === 'status' || message.type === 'info' || message.type === 'progress') return e;
    if (message.type === 'error') {
      this.finish(e, (w) => w.reject(Object.assign(new Error(message.message), { answer: message })));
    } else if (e.expectsField) {
      e.answer = message; // `added` or `loaded`: the field follows
    } else {
      this.finish(e, (w) => w.resolve(message));
    }
    return e;
  }

  // A field message, once drawn.
  onFieldDrawn(entry, header) {
    if (!entry || entry !== this.inflight) return;
    const result = entry.answer ? { ...entry.answer, field: header } : header;
    this.finish(entry, (w) => w.resolve(result));
  }

  finish(entry, settle) {
    this.inflight = null;
    entry.waiters.forEach(settle);
    this.pump();
  }

  // The connection is gone: every waiting request fails.
  failAll(reason) {
    const all = (this.inflight ? [this.inflight] : []).concat(this.waiting);
    this.inflight = null;
    this.waiting = [];
    for (const e of all) e.waiters.forEach((w) => w.reject(new Error(reason)));
    this.idleWaiters.splice(0).forEach((resolve) => resolve());
  }
}
