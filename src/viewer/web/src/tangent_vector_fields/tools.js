// Mouse and keyboard: placing constraints, grabbing and dragging their handles, deleting.
// A press on a handle, or on the surface with a placing tool, belongs to the tool; any other
// press goes on to the orbit controls.
import * as THREE from 'three';
import { pickables, baseOf } from './handles.js';

const CLICK_PIXELS = 4; // a press that moves less than this is a click

export class Tools {
  constructor(editor, container) {
    this.editor = editor;
    this.viewer = editor.viewer;
    this.tool = 'select';
    this.vortexSign = 1; // +1: counter-clockwise
    this.strength = 1;
    this.singularityIndex = 1; // k: the index of a new singularity is k / n
    this.drag = null;
    // Capture on the container: before the orbit controls' own listener on the canvas.
    container.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    window.addEventListener('pointermove', (e) => this.move(e));
    window.addEventListener('pointerup', (e) => this.up(e));
    window.addEventListener('keydown', (e) => this.key(e));
    this.onToolChange = () => {};
  }

  setTool(tool) {
    this.tool = tool;
    this.onToolChange(tool);
  }

  // The signed value a new source, sink or vortex gets.
  value(type) {
    if (type === 'source') return this.strength;
    if (type === 'sink') return -this.strength;
    return this.vortexSign * this.strength;
  }

  down(e) {
    if (e.button !== 0 || !this.editor.mesh) return;
    const { clientX: x, clientY: y } = e;
    const hit = this.viewer.pick(x, y);
    const grabbed = this.viewer.pickObjects(x, y, pickables(this.editor.handles));
    // Handles behind the surface are out of reach (the margin covers those that sink into it).
    const reachable = grabbed && (!hit || grabbed.distance <= hit.distance + 0.01 * this.viewer.diagonal);
    if (reachable) {
      const { handle, role } = grabbed.object.userData;
      this.editor.select(handle);
      this.drag = { kind: role === 'tip' ? 'tip' : 'move', handle, x, y };
      return this.take(e);
    }
    if (this.tool === 'select' || !hit) {
      this.drag = { kind: 'orbit', x, y }; // the controls get the press; a click deselects
      return;
    }
    const point = hit.point.toArray();
    switch (this.tool) {
      case 'vector':
      case 'direction':
        this.drag = { kind: 'place', type: this.tool, face: hit.face, anchor: hit.point, handle: null, x, y };
        return this.take(e);
      case 'source':
      case 'sink':
      case 'vortex': {
        const type = this.tool === 'vortex' ? 'curl' : 'divergence';
        const { handle } = this.editor.add({ type, face: hit.face, point, value: this.value(this.tool) });
        this.editor.select(handle);
        this.drag = { kind: 'move', handle, x, y };
        return this.take(e);
      }
      case 'singularity': {
        if (this.editor.n === 1) {
          this.editor.line.error('singularities are constraints of n-direction fields: choose a line or cross field under Field');
          return this.take(e);
        }
        const { handle } = this.editor.add(this.singularityConstraint(hit, this.singularityIndex));
        this.editor.select(handle);
        this.drag = { kind: 'move', handle, x, y };
        return this.take(e);
      }
      case 'boundary': {
        const edge = this.nearestBoundaryEdge(hit.point);
        if (edge === null) {
          this.editor.line.error('no boundary edge near the click (boundary alignment needs a mesh with boundary)');
          return this.take(e);
        }
        const { handle } = this.editor.add({ type: 'boundary_alignment', edge });
        this.editor.select(handle);
        this.drag = { kind: 'move', handle, x, y };
        return this.take(e);
      }
    }
  }

  // The cursor tells what a press would do: grab a handle, place a constraint, or orbit.
  hover(e) {
    const canvas = this.viewer.canvas;
    if (e.target !== canvas) return;
    const overHandle = this.viewer.pickObjects(e.clientX, e.clientY, pickables(this.editor.handles)) !== null;
    canvas.style.cursor = overHandle ? 'grab' : this.tool === 'select' ? 'default' : 'crosshair';
  }

  take(e) {
    e.preventDefault();
    e.stopPropagation();
  }

  moved(e) {
    return Math.hypot(e.clientX - this.drag.x, e.clientY - this.drag.y) >= CLICK_PIXELS;
  }

  move(e) {
    const d = this.drag;
    if (!d) return this.hover(e);
    if (d.kind === 'orbit') return;
    if (!d.dragged && !this.moved(e)) return;
    d.dragged = true;
    if (d.kind === 'place') {
      const v = this.inPlane(e, d.anchor, this.viewer.faceNormal(d.face));
      if (!v) return;
      const constraint = this.vectorConstraint(d.type, d.face, v);
      if (!d.handle) {
        d.handle = this.editor.add(constraint, d.anchor).handle;
        this.editor.select(d.handle);
      } else this.editor.change(d.handle, constraint);
    } else if (d.kind === 'tip') {
      const c = d.handle.constraint;
      const { base, normal } = baseOf(d.handle, this.viewer);
      const v = this.inPlane(e, base, normal);
      if (v) this.editor.change(d.handle, this.vectorConstraint(c.type, c.face, v));
    } else if (d.kind === 'move') {
      this.moveHandle(d.handle, e);
    }
  }

  up(e) {
    const d = this.drag;
    if (!d) return;
    this.drag = null;
    const click = !d.dragged && Math.hypot(e.clientX - d.x, e.clientY - d.y) < CLICK_PIXELS;
    if (d.kind === 'orbit' && click) this.editor.select(null);
    if (d.kind === 'place' && !d.handle) {
      // A click without a drag: the field's own vector there, or a default one.
      const v = this.defaultVector(d.face);
      const { handle } = this.editor.add(this.vectorConstraint(d.type, d.face, v), d.anchor);
      this.editor.select(handle);
    }
  }

  key(e) {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    const selected = this.editor.selected;
    if ((e.key === 'Delete' || e.key === 'Backspace') && selected) {
      this.editor.remove(selected);
      e.preventDefault();
    } else if (e.key === 'Escape') this.editor.select(null);
    else {
      const tool = { s: 'select', v: 'vector', d: 'direction', o: 'source', i: 'sink', c: 'vortex', b: 'boundary',
        x: 'singularity' }[e.key];
      if (tool && !e.ctrlKey && !e.metaKey && !e.altKey) this.setTool(tool);
    }
  }

  // The drag from point to the ray under the mouse, in the plane through point with normal.
  inPlane(e, point, normal) {
    const p = this.viewer.rayOnPlane(e.clientX, e.clientY, point, normal);
    if (!p) return null;
    const v = p.sub(point);
    return v.addScaledVector(normal, -v.dot(normal)); // exactly in the plane despite rounding
  }

  vectorConstraint(type, face, v) {
    const c = { type, face };
    c[type === 'vector' ? 'vector' : 'direction'] = v.toArray();
    return c;
  }

  defaultVector(face) {
    const normal = this.viewer.faceNormal(face);
    const field = this.editor.field;
    const v = new THREE.Vector3();
    if (field) v.fromArray(field.arrays.vectors, 3 * face);
    const length = v.length();
    if (length > 0 && length >= 1e-6 * field.header.magnitude_max) return v;
    // No field there yet: along the screen's horizontal, a tenth of the diagonal long.
    v.set(1, 0, 0).applyQuaternion(this.viewer.camera.quaternion);
    v.addScaledVector(normal, -v.dot(normal));
    if (v.length() < 1e-6) v.set(0, 1, 0).applyQuaternion(this.viewer.camera.quaternion);
    v.addScaledVector(normal, -v.dot(normal));
    return v.setLength(0.1 * this.viewer.diagonal);
  }

  // The vertex of face `face` nearest to `point`.
  nearestVertex(face, point) {
    const triangles = this.editor.mesh.triangles;
    let best = triangles[3 * face];
    for (let k = 1; k < 3; ++k) {
      const v = triangles[3 * face + k];
      if (this.viewer.vertexPosition(v).distanceTo(point) < this.viewer.vertexPosition(best).distanceTo(point)) best = v;
    }
    return best;
  }

  // A singularity of index k / n at the vertex nearest to the hit, anchored in the hit face by
  // the field's vector there (so the field keeps its strength and orientation around it).
  singularityConstraint(hit, index, vector = null) {
    const v = vector ? new THREE.Vector3().fromArray(vector) : this.defaultVector(hit.face);
    const normal = this.viewer.faceNormal(hit.face);
    const length = v.length();
    v.addScaledVector(normal, -v.dot(normal));
    if (v.length() > 0) v.setLength(length);
    else v.copy(this.defaultVector(hit.face));
    return { type: 'singularity', vertex: this.nearestVertex(hit.face, hit.point), index, face: hit.face,
      vector: v.toArray() };
  }

  // Moves a handle to the surface point under the mouse.
  moveHandle(handle, e) {
    const hit = this.viewer.pick(e.clientX, e.clientY);
    if (!hit) return;
    const c = handle.constraint;
    let next;
    if (c.type === 'vector' || c.type === 'direction') {
      // Same length, turned into the new face's plane.
      const key = c.type === 'vector' ? 'vector' : 'direction';
      const v = new THREE.Vector3().fromArray(c[key]);
      const normal = this.viewer.faceNormal(hit.face);
      const length = v.length();
      v.addScaledVector(normal, -v.dot(normal));
      if (v.length() > 0) v.setLength(length);
      handle.anchor = hit.point;
      next = { ...c, face: hit.face, [key]: v.toArray() };
      if (hit.face === c.face) {
        this.editor.redraw(handle); // the file format has no point for vectors: nothing to send
        return;
      }
    } else if (c.type === 'divergence' || c.type === 'curl') {
      next = { type: c.type, face: hit.face, point: hit.point.toArray(), value: c.value };
      if (c.weight !== undefined) next.weight = c.weight;
    } else if (c.type === 'singularity') {
      next = this.singularityConstraint(hit, c.index, c.vector);
      if (next.vertex === c.vertex) return; // still the same vertex: nothing to send
    } else if (c.type === 'boundary_alignment') {
      const edge = this.nearestBoundaryEdge(hit.point);
      if (edge === null || edge === c.edge) return;
      next = { ...c, edge };
    }
    if (next) this.editor.change(handle, next);
  }

  // The boundary edge nearest to point, if it is within a few edge lengths; else null.
  nearestBoundaryEdge(point) {
    const mesh = this.editor.mesh;
    const reach = Math.max(3 * (this.editor.info?.mesh.mean_edge_length || 0), 0.02 * this.viewer.diagonal);
    let best = null;
    let bestDistance = reach;
    const segment = new THREE.Line3();
    const closest = new THREE.Vector3();
    for (const edge of mesh.boundary_edges) {
      segment.start.fromArray(mesh.positions, 3 * mesh.edges[2 * edge]);
      segment.end.fromArray(mesh.positions, 3 * mesh.edges[2 * edge + 1]);
      const distance = segment.closestPointToPoint(point, true, closest).distanceTo(point);
      if (distance < bestDistance) {
        bestDistance = distance;
        best = edge;
      }
    }
    return best;
  }
}
