// Constraint handles: one Handle per constraint of the session, drawn as arrows (vectors),
// double-headed arrows (directions), spheres (sources, sinks), spheres with a turning ring
// (vortices) and a thick edge (boundary alignment).
import * as THREE from 'three';

const SPHERE = new THREE.SphereGeometry(1, 20, 14);
const CYLINDER = new THREE.CylinderGeometry(1, 1, 1, 12);
const CONE = new THREE.ConeGeometry(1, 1, 16);
const RING = new THREE.TorusGeometry(1, 0.07, 8, 40);
const UP = new THREE.Vector3(0, 1, 0);

export const COLOURS = {
  vector: 0xe91e63,
  direction: 0xff9800,
  source: 0xe53935,
  sink: 0x1e88e5,
  vortex_ccw: 0x8e24aa,
  vortex_cw: 0x00897b,
  boundary_alignment: 0x00bcd4,
  singularity_positive: 0xc62828,
  singularity_negative: 0x1565c0,
};

// What the page knows of one constraint: the constraint as last sent (`constraint`), as
// last accepted by the server (`confirmed`), its server id (null until `added`), and where
// the user put it (`anchor`: vectors and directions only have a face in the file format).
export class Handle {
  constructor(constraint, anchor = null, n = 1) {
    this.id = null;
    this.n = n; // the field's n: vectors of n-fields are drawn n-fold
    this.constraint = constraint;
    this.confirmed = null;
    this.anchor = anchor;
    this.removed = false;
    this.group = new THREE.Group();
  }

  colourName() {
    const c = this.constraint;
    if (c.type === 'divergence') return c.value >= 0 ? 'source' : 'sink';
    if (c.type === 'curl') return c.value >= 0 ? 'vortex_ccw' : 'vortex_cw';
    if (c.type === 'singularity') return c.index >= 0 ? 'singularity_positive' : 'singularity_negative';
    return c.type;
  }

  describe() {
    const c = this.constraint;
    const id = this.id === null ? 'new' : `#${this.id}`;
    const names = { source: 'source', sink: 'sink', vortex_ccw: 'vortex (counter-clockwise)',
      vortex_cw: 'vortex (clockwise)', vector: 'vector', direction: 'direction',
      boundary_alignment: 'boundary alignment' };
    if (c.type === 'singularity') {
      return `singularity ${c.index > 0 ? '+' : ''}${c.index}/${this.n} ${id} at vertex ${c.vertex}`;
    }
    const where = c.face !== undefined ? `face ${c.face}` : c.vertex !== undefined ? `vertex ${c.vertex}` : `edge ${c.edge}`;
    return `${names[this.colourName()]} ${id} at ${where}`;
  }
}

// Where a constraint sits on the mesh: {point, normal, face (or undefined)}.
function placeOf(handle, viewer) {
  const c = handle.constraint;
  const mesh = viewer.mesh;
  if (c.type === 'boundary_alignment' || (c.edge !== undefined && c.face === undefined)) {
    const [i, j] = [mesh.edges[2 * c.edge], mesh.edges[2 * c.edge + 1]];
    const point = viewer.vertexPosition(i).add(viewer.vertexPosition(j)).multiplyScalar(0.5);
    return { point, normal: viewer.vertexNormal(i).add(viewer.vertexNormal(j)).normalize() };
  }
  if (c.vertex !== undefined && (c.face === undefined || c.type === 'singularity')) {
    return { point: viewer.vertexPosition(c.vertex), normal: viewer.vertexNormal(c.vertex) };
  }
  const normal = viewer.faceNormal(c.face);
  let point;
  if (c.point) point = new THREE.Vector3().fromArray(c.point);
  else if (c.vertices && c.barycentric) {
    point = new THREE.Vector3();
    for (let k = 0; k < 3; ++k) point.addScaledVector(viewer.vertexPosition(c.vertices[k]), c.barycentric[k]);
  } else if (handle.anchor) point = handle.anchor.clone();
  else point = viewer.faceCentroid(c.face);
  return { point, normal, face: c.face };
}

// The point a handle is drawn from: its place, lifted off the surface so that the handle is
// not half buried in it.  {base, normal, face}
export function baseOf(handle, viewer) {
  const place = placeOf(handle, viewer);
  return { ...place, base: place.point.clone().addScaledVector(place.normal, 0.004 * viewer.diagonal) };
}

function part(geometry, material, handle, role) {
  const m = new THREE.Mesh(geometry, material);
  m.userData = { handle, role };
  return m;
}

// A cylinder or cone of unit size stretched from a to b.
function stretch(object, a, b, radius) {
  const d = new THREE.Vector3().subVectors(b, a);
  const length = d.length();
  object.position.copy(a).addScaledVector(d, 0.5);
  if (length > 0) object.quaternion.setFromUnitVectors(UP, d.clone().divideScalar(length));
  object.scale.set(radius, Math.max(length, 1e-9), radius);
}

// Rebuilds the handle's drawing from its constraint; sizes are fractions of the mesh's diagonal.
export function drawHandle(handle, viewer, selected) {
  const group = handle.group;
  const old = new Set(group.children.map((child) => child.material));
  old.forEach((m) => m.dispose()); // geometries are shared; materials are the handle's own
  group.clear();
  const size = viewer.diagonal;
  const c = handle.constraint;
  // Partly self-lit, so that handles stand out on dark colour maps; brighter when selected.
  const colour = new THREE.Color(COLOURS[handle.colourName()]);
  const material = new THREE.MeshLambertMaterial({
    color: colour, emissive: selected ? new THREE.Color(0x888888) : colour.clone().multiplyScalar(0.45),
  });
  const place = baseOf(handle, viewer);
  const base = place.base;
  const grow = selected ? 1.35 : 1;

  if (c.type === 'vector' || c.type === 'direction') {
    const v = new THREE.Vector3().fromArray(c.type === 'vector' ? c.vector : c.direction);
    const tip = base.clone().add(v);
    const length = v.length();
    const headLength = Math.min(0.035 * size, 0.45 * length);
    const shaftRadius = 0.0025 * size * grow;
    const arrowhead = (from, to) => {
      const direction = new THREE.Vector3().subVectors(to, from).normalize();
      const head = part(CONE, material, handle, 'tip');
      stretch(head, to.clone().addScaledVector(direction, -headLength), to, 0.011 * size * grow);
      return head;
    };
    const start = c.type === 'direction' ? base.clone().sub(v) : base;
    if (length > 0) {
      const shaft = part(CYLINDER, material, handle, 'anchor');
      stretch(shaft, start, tip, shaftRadius);
      group.add(shaft, arrowhead(start, tip));
      if (c.type === 'direction') group.add(arrowhead(tip, start));
      // An n-field's other n - 1 vectors, turned by 2 pi j / n in the face's plane: thin, not grabbable.
      for (let j = 1; j < handle.n; ++j) {
        const w = v.clone().applyAxisAngle(place.normal, (2 * Math.PI * j) / handle.n);
        const other = new THREE.Mesh(CYLINDER, material);
        stretch(other, base, base.clone().add(w), 0.5 * shaftRadius);
        group.add(other);
      }
    }
    const anchor = part(SPHERE, material, handle, 'anchor');
    anchor.position.copy(base);
    anchor.scale.setScalar(0.007 * size * grow);
    // The tip is a larger, translucent target than the arrowhead, to grab it easily.
    const grip = part(SPHERE, new THREE.MeshBasicMaterial({ color: COLOURS[handle.colourName()],
      transparent: true, opacity: 0.35, depthWrite: false }), handle, 'tip');
    grip.position.copy(tip);
    grip.scale.setScalar(0.012 * size * grow);
    group.add(anchor, grip);
  } else if (c.type === 'divergence' || c.type === 'curl') {
    const ball = part(SPHERE, material, handle, 'anchor');
    ball.position.copy(base);
    ball.scale.setScalar(0.011 * size * grow);
    group.add(ball);
    if (c.type === 'curl') {
      // A ring in the tangent plane with an arrowhead turning with the sign of the curl
      // (positive: counter-clockwise seen from the side the normal points to).
      const radius = 0.028 * size;
      const ring = part(RING, material, handle, 'anchor');
      ring.position.copy(base);
      ring.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), place.normal);
      ring.scale.setScalar(radius);
      const u = new THREE.Vector3(1, 0, 0).applyQuaternion(ring.quaternion);
      const turn = new THREE.Vector3().crossVectors(place.normal, u).multiplyScalar(c.value >= 0 ? 1 : -1);
      const at = base.clone().addScaledVector(u, radius);
      const head = part(CONE, material, handle, 'anchor');
      stretch(head, at.clone().addScaledVector(turn, -0.3 * radius), at.clone().addScaledVector(turn, 0.3 * radius),
        0.22 * radius);
      group.add(ring, head);
    }
  } else if (c.type === 'singularity') {
    // A ball at the vertex in a ring: the ring's colour tells the sign of the index.
    const ball = part(SPHERE, material, handle, 'anchor');
    ball.position.copy(base);
    ball.scale.setScalar(0.012 * size * grow);
    const ring = part(RING, material, handle, 'anchor');
    ring.position.copy(base);
    ring.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), place.normal);
    ring.scale.setScalar(0.024 * size * (1 + 0.3 * (Math.abs(c.index) - 1)));
    group.add(ball, ring);
  } else if (c.type === 'boundary_alignment') {
    const mesh = viewer.mesh;
    const a = viewer.vertexPosition(mesh.edges[2 * c.edge]).addScaledVector(place.normal, 0.002 * size);
    const b = viewer.vertexPosition(mesh.edges[2 * c.edge + 1]).addScaledVector(place.normal, 0.002 * size);
    const bar = part(CYLINDER, material, handle, 'anchor');
    stretch(bar, a, b, 0.005 * size * grow);
    group.add(bar);
  }
  viewer.requestRender();
}

// The meshes of all handles that can be grabbed.
export function pickables(handles) {
  const out = [];
  for (const h of handles) if (!h.removed && h.group.visible) for (const child of h.group.children) out.push(child);
  return out;
}
