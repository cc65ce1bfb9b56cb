// window.tvfEditor, the hook tests and benchmarks drive the field session with.  Its requests
// take the same paths as the panel's and the mouse's, so a benchmark measures what a user
// gets.  Field answers resolve once the field is drawn.
import * as THREE from 'three';
import { baseOf } from './handles.js';

function request(editor, message) {
  const handle = message.id !== undefined ? editor.handleById(message.id) : null;
  switch (message.type) {
    case 'add':
      return editor.add(message.constraint).promise;
    case 'change':
      if (handle) return editor.change(handle, message.constraint);
      break;
    case 'remove':
      if (handle) return editor.remove(handle);
      break;
    case 'clear':
      return editor.clear();
    case 'set_n':
      return editor.setN(message.n);
    case 'load':
      return editor.load(message.file);
    case 'set_display': {
      const changes = { ...message };
      delete changes.type;
      if (changes.scalar !== undefined) {
        changes.colour = changes.scalar === 'none' ? 'magnitude' : changes.scalar;
        delete changes.scalar;
      }
      return editor.setDisplay(changes);
    }
  }
  // Anything else (and ids the page does not know) goes to the server as it is.
  return editor.queue.push({ build: () => message });
}

export function installHook({ connection, viewer, editor, tools }) {
  const canvasPoint = (point) => {
    const p = viewer.project(point);
    return { x: p.x, y: p.y };
  };
  window.tvfEditor = {
    ready: connection.ready,
    info: () => editor.info,
    constraints: () => editor.constraints(),
    lastField: () => editor.field && { header: editor.field.header, ...editor.field.arrays },
    faceVector: (f) => Array.from(editor.field.arrays.vectors.subarray(3 * f, 3 * f + 3)),
    latencyLog: () => editor.latency.log.slice(),
    request: (message) => request(editor, message),
    // Resolves when no request waits or is in flight (after a drag, say).
    idle: () => editor.queue.whenIdle(),
    mesh: () => editor.mesh,
    faceNormal: (f) => viewer.faceNormal(f).toArray(),
    // Screen position (CSS pixels, relative to the canvas) of face f's centroid, and whether
    // the surface there is f itself (not hidden behind another part of the mesh).
    projectFace(f) {
      const p = canvasPoint(viewer.faceCentroid(f));
      const rect = viewer.canvas.getBoundingClientRect();
      const hit = viewer.pick(rect.left + p.x, rect.top + p.y);
      return { ...p, visible: hit !== null && hit.face === f };
    },
    // The face under a canvas point (CSS pixels), or null.
    faceAt(x, y) {
      const rect = viewer.canvas.getBoundingClientRect();
      const hit = viewer.pick(rect.left + x, rect.top + y);
      return hit && { face: hit.face, point: hit.point.toArray() };
    },
    // Screen positions of a constraint's handle: its anchor and, for vectors and directions,
    // the tip of the arrow.
    handleScreen(id) {
      const handle = editor.handleById(id);
      if (!handle) return null;
      const { base } = baseOf(handle, viewer);
      const v = handle.constraint.vector || handle.constraint.direction;
      return { anchor: canvasPoint(base), tip: v ? canvasPoint(new THREE.Vector3().fromArray(v).add(base)) : null };
    },
    setTool: (tool) => tools.setTool(tool),
    // Screen position (CSS pixels, relative to the canvas) of vertex v, and whether it is in view.
    projectVertex(v) {
      const p = canvasPoint(viewer.vertexPosition(v));
      const rect = viewer.canvas.getBoundingClientRect();
      const hit = viewer.pick(rect.left + p.x, rect.top + p.y);
      return { ...p, visible: hit !== null && hit.point.distanceTo(viewer.vertexPosition(v)) < 0.02 * viewer.diagonal };
    },
    // Mean time (ms) of n frames of the current scene, each finished on the GPU.
    renderTime(n = 10) {
      const start = performance.now();
      for (let i = 0; i < n; ++i) {
        viewer.renderNow();
        viewer.finish();
      }
      return (performance.now() - start) / n;
    },
    fps: () => viewer.fps,
  };
}
