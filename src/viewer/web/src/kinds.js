// The session kinds this page knows.  The server's answer to `hello` names the kind of the
// session (`info.kind`), and the page mounts that kind's interface (connection.js).  A system
// adds its kind in main.js, the way tangent_vector_fields/index.js does for fields.
//
// A kind is { binaryAnswers, mount(context) }: binaryAnswers lists its message types whose
// answer ends with a binary message; mount gets { connection, viewer, latency, line } and
// returns the session's page side, which has onText(message) (true for an unasked message,
// one that answers no request), onBinary(header, arrays, bytes, arrivedAt), and may have
// sent(message, sentAt) and onMesh(arrays).
const KINDS = new Map();

export function registerKind(name, kind) {
  KINDS.set(name, kind);
}

export function kindNamed(name) {
  return KINDS.get(name);
}

export function kindNames() {
  return [...KINDS.keys()];
}
