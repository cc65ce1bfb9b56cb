// The 3D view: the mesh coloured per face or per vertex, the field's lines, the constraint
// handles, the camera, picking, and a render loop that draws only when something changed.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { VIRIDIS, COOL_WARM, colourAt } from './colormap.js';

const GREY = [0.55, 0.55, 0.55];
const MARKER = new THREE.SphereGeometry(1, 14, 10);

// Whether WebGL runs on a software rasterizer (headless browsers, machines without a GPU).
function softwareRendering() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|software/i.test(name);
}

export class Viewer {
  constructor(canvas) {
    this.canvas = canvas;
    this.software = softwareRendering();
    // Multisampling costs software rasterizers about 40% of a frame; GPUs hardly notice it.
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: !this.software });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xeef0f3);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
    this.scene.add(this.camera); // the camera carries a light, so the view is always lit from the front
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x505060, 1.4));
    const light = new THREE.DirectionalLight(0xffffff, 1.8);
    light.position.set(0.4, 0.8, 1);
    this.camera.add(light);

    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.requestRender());

    this.handles = new THREE.Group();
    this.scene.add(this.handles);
    this.raycaster = new THREE.Raycaster();

    this.lineMaterial = new THREE.LineBasicMaterial({ vertexColors: true });
    this.lines = new THREE.LineSegments(new THREE.BufferGeometry(), this.lineMaterial);
    this.lines.frustumCulled = false;
    this.scene.add(this.lines);

    // Singular vertices of n-fields: one marker each, coloured by the sign of the index.
    this.singular = new THREE.Group();
    this.scene.add(this.singular);

    this.dirty = true;
    this.holdUntil = 0;
    this.frames = 0;
    this.fps = 0;
    this.frameWindowStart = performance.now();
    new ResizeObserver(() => this.resize()).observe(canvas.parentElement);
    this.resize();
    const loop = () => {
      requestAnimationFrame(loop);
      if (this.dirty && performance.now() >= this.holdUntil) this.renderNow();
      this.updateFps();
    };
    requestAnimationFrame(loop);
  }

  resize() {
    const box = this.canvas.parentElement.getBoundingClientRect();
    const w = Math.max(1, Math.floor(box.width));
    const h = Math.max(1, Math.floor(box.height));
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  requestRender() {
    this.dirty = true;
  }

  // No frame before time t unless renderNow() is called: while a field is on its way, a
  // frame that only moves a handle would delay the field's own frame (a frame may cost tens
  // of milliseconds with software rendering).
  holdFrames(t) {
    this.holdUntil = t;
  }

  // Renders at once; the caller may then call finish() to wait for the GPU.
  renderNow() {
    this.dirty = false;
    this.renderer.render(this.scene, this.camera);
    ++this.frames;
  }

  // Reading one pixel waits until the GPU has drawn the frame, so timings include its work.
  finish() {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  }

  updateFps() {
    const now = performance.now();
    if (now - this.frameWindowStart < 1000) return;
    this.fps = (1000 * this.frames) / (now - this.frameWindowStart);
    this.frames = 0;
    this.frameWindowStart = now;
  }

  // mesh: the arrays of the `mesh` message.  Builds a triangle soup (3 corners per face) so
  // that faces can carry their own colour while normals stay smooth.
  setMesh(mesh) {
    const { positions, triangles } = mesh;
    const nf = triangles.length / 3;
    const nv = positions.length / 3;
    const faceNormals = new Float32Array(3 * nf);
    const centroids = new Float32Array(3 * nf);
    const vertexNormals = new Float32Array(3 * nv);
    const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
    for (let f = 0; f < nf; ++f) {
      const [i, j, k] = [triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]];
      a.fromArray(positions, 3 * i);
      b.fromArray(positions, 3 * j);
      c.fromArray(positions, 3 * k);
      centroids[3 * f] = (a.x + b.x + c.x) / 3;
      centroids[3 * f + 1] = (a.y + b.y + c.y) / 3;
      centroids[3 * f + 2] = (a.z + b.z + c.z) / 3;
      c.sub(a);
      b.sub(a);
      b.cross(c); // twice the area times the unit normal: area-weighted vertex normals
      for (const v of [i, j, k]) {
        vertexNormals[3 * v] += b.x;
        vertexNormals[3 * v + 1] += b.y;
        vertexNormals[3 * v + 2] += b.z;
      }
      b.normalize().toArray(faceNormals, 3 * f);
    }
    const soupPositions = new Float32Array(9 * nf);
    const soupNormals = new Float32Array(9 * nf);
    for (let v = 0; v < nv; ++v) a.fromArray(vertexNormals, 3 * v).normalize().toArray(vertexNormals, 3 * v);
    for (let corner = 0; corner < 3 * nf; ++corner) {
      const v = triangles[corner];
      const n = a.fromArray(vertexNormals, 3 * v);
      for (let d = 0; d < 3; ++d) {
        soupPositions[3 * corner + d] = positions[3 * v + d];
        soupNormals[3 * corner + d] = n.getComponent(d);
      }
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(soupPositions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(soupNormals, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(9 * nf), 3));
    geometry.computeBoundingSphere();
    geometry.computeBoundingBox();
    // Pushed back in depth so that lines and handles lying on the surface stay visible.
    // Lambert: half the cost of the physically based material in software rendering.
    const material = new THREE.MeshLambertMaterial({
      vertexColors: true, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    });
    if (this.surface) {
      this.scene.remove(this.surface);
      this.surface.geometry.dispose();
    }
    this.surface = new THREE.Mesh(geometry, material);
    this.scene.add(this.surface);
    this.mesh = mesh;
    this.vertexNormals = vertexNormals;
    this.faceNormals = faceNormals;
    this.centroids = centroids;
    this.colourUniform();
    this.fitCamera(geometry.boundingSphere);
  }

  // New vertex positions (3 floats per vertex) for the mesh of setMesh, moved in place: the
  // triangle soup and its smooth normals follow (a simulation's frames).
  updatePositions(positions) {
    const { triangles } = this.mesh;
    const nv = positions.length / 3;
    const normals = this.vertexNormals;
    normals.fill(0);
    const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
    for (let corner = 0; corner < triangles.length; corner += 3) {
      const [i, j, k] = [triangles[corner], triangles[corner + 1], triangles[corner + 2]];
      a.fromArray(positions, 3 * i);
      b.fromArray(positions, 3 * j).sub(a);
      c.fromArray(positions, 3 * k).sub(a);
      b.cross(c);
      for (const v of [i, j, k]) {
        normals[3 * v] += b.x;
        normals[3 * v + 1] += b.y;
        normals[3 * v + 2] += b.z;
      }
    }
    for (let v = 0; v < nv; ++v) a.fromArray(normals, 3 * v).normalize().toArray(normals, 3 * v);
    const geometry = this.surface.geometry;
    const soup = geometry.getAttribute('position');
    const soupNormals = geometry.getAttribute('normal');
    for (let corner = 0; corner < triangles.length; ++corner) {
      const v = triangles[corner];
      for (let d = 0; d < 3; ++d) {
        soup.array[3 * corner + d] = positions[3 * v + d];
        soupNormals.array[3 * corner + d] = normals[3 * v + d];
      }
    }
    soup.needsUpdate = true;
    soupNormals.needsUpdate = true;
    geometry.computeBoundingSphere(); // picking tests the sphere first
    geometry.computeBoundingBox();
    this.mesh = { ...this.mesh, positions: Float32Array.from(positions) };
    this.requestRender();
  }

  // The whole mesh in view, seen from the front and a little from above and the right.
  fitCamera(sphere) {
    const { center, radius } = sphere;
    this.diagonal = this.surface.geometry.boundingBox.getSize(new THREE.Vector3()).length();
    const distance = (1.3 * radius) / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2));
    this.camera.near = radius * 0.01;
    this.camera.far = distance + 10 * radius;
    this.camera.position.copy(center).add(new THREE.Vector3(0.25, 0.3, 1).normalize().multiplyScalar(distance));
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.requestRender();
  }

  colours() {
    return this.surface.geometry.getAttribute('color');
  }

  colourUniform() {
    const attribute = this.colours();
    const out = attribute.array;
    for (let i = 0; i < out.length; i += 3) out.set(GREY, i);
    attribute.needsUpdate = true;
    this.requestRender();
  }

  // One colour per face: |vector| / max on viridis.
  colourByMagnitude(vectors, max) {
    const attribute = this.colours();
    const out = attribute.array;
    const scale = max > 0 ? 1 / max : 0;
    const nf = vectors.length / 3;
    for (let f = 0; f < nf; ++f) {
      const x = vectors[3 * f], y = vectors[3 * f + 1], z = vectors[3 * f + 2];
      colourAt(VIRIDIS, Math.sqrt(x * x + y * y + z * z) * scale, out, 9 * f);
      out.copyWithin(9 * f + 3, 9 * f, 9 * f + 3);
      out.copyWithin(9 * f + 6, 9 * f, 9 * f + 3);
    }
    attribute.needsUpdate = true;
    this.requestRender();
  }

  // One value per vertex on a diverging map centred at 0, symmetric so that 0 stays white.
  colourByScalar(scalar, range) {
    const attribute = this.colours();
    const out = attribute.array;
    const extent = Math.max(Math.abs(range[0]), Math.abs(range[1]));
    const scale = extent > 0 ? 0.5 / extent : 0;
    const triangles = this.mesh.triangles;
    for (let corner = 0; corner < triangles.length; ++corner) {
      colourAt(COOL_WARM, 0.5 + scalar[triangles[corner]] * scale, out, 3 * corner);
    }
    attribute.needsUpdate = true;
    this.requestRender();
  }

  // One value per face, >= 0 (the smoothness energy density of an n-field): log scale over
  // four decades below the largest, since it peaks at singularities.
  colourByFaceEnergy(scalar, range) {
    const attribute = this.colours();
    const out = attribute.array;
    const max = range[1] > 0 ? range[1] : 1;
    const nf = scalar.length;
    for (let f = 0; f < nf; ++f) {
      const t = scalar[f] > 0 ? 1 + Math.log10(scalar[f] / max) / 4 : 0;
      colourAt(VIRIDIS, Math.max(0, t), out, 9 * f);
      out.copyWithin(9 * f + 3, 9 * f, 9 * f + 3);
      out.copyWithin(9 * f + 6, 9 * f, 9 * f + 3);
    }
    attribute.needsUpdate = true;
    this.requestRender();
  }

  // Markers of the singular vertices (n-fields): red for positive indices k / n, blue for
  // negative ones, larger for |k| > 1.  vertices, indices: the field message's arrays.
  setSingularities(vertices, indices, n) {
    for (const child of this.singular.children) child.material.dispose();
    this.singular.clear();
    this.singularInfo = [];
    if (!vertices || vertices.length === 0 || !this.mesh) {
      this.requestRender();
      return;
    }
    const geometry = MARKER;
    const lift = 0.003 * this.diagonal;
    for (const sign of [1, -1]) {
      const chosen = [];
      for (let i = 0; i < vertices.length; ++i) if (Math.sign(indices[i]) === sign) chosen.push(i);
      if (chosen.length === 0) continue;
      const material = new THREE.MeshLambertMaterial({ color: sign > 0 ? 0xd32f2f : 0x1565c0,
        emissive: sign > 0 ? 0x5a1010 : 0x0a2a5a });
      const markers = new THREE.InstancedMesh(geometry, material, chosen.length);
      const m = new THREE.Matrix4();
      chosen.forEach((i, j) => {
        const v = vertices[i];
        const p = this.vertexPosition(v).addScaledVector(this.vertexNormal(v), lift);
        const size = 0.006 * this.diagonal * (1 + 0.35 * (Math.abs(indices[i]) - 1));
        m.makeScale(size, size, size).setPosition(p);
        markers.setMatrixAt(j, m);
      });
      markers.instanceMatrix.needsUpdate = true;
      markers.frustumCulled = false;
      this.singular.add(markers);
    }
    this.singularInfo = Array.from(vertices, (v, i) => ({ vertex: v, index: indices[i], n }));
    this.requestRender();
  }

  // lines: 6 floats per segment; light: white lines (on dark colours) rather than black.
  // Fur strokes fade in from their tail to their head, which shows the field's direction;
  // a stroke is a run of segments where each starts at the end of the previous one.
  setLines(lines, light, fade) {
    const geometry = new THREE.BufferGeometry();
    if (lines && lines.length > 0) {
      geometry.setAttribute('position', new THREE.BufferAttribute(lines, 3));
      const head = light ? 1 : 0.02;
      const tail = light ? 0.3 : 0.65;
      const colours = new Float32Array(lines.length);
      if (fade) fadeStrokes(lines, colours, tail, head);
      else colours.fill(light ? 0.9 : 0.08);
      geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    }
    this.lines.geometry.dispose();
    this.lines.geometry = geometry;
    this.requestRender();
  }

  // The ray under client coordinates.
  rayAt(clientX, clientY) {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1,
      -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    return this.raycaster.ray;
  }

  // The surface point under client coordinates: {face, point} or null.
  pick(clientX, clientY) {
    if (!this.surface) return null;
    this.rayAt(clientX, clientY);
    const hit = this.raycaster.intersectObject(this.surface, false)[0];
    return hit ? { face: hit.faceIndex, point: hit.point.clone(), distance: hit.distance } : null;
  }

  // The nearest of objects under client coordinates: the intersection or null.
  pickObjects(clientX, clientY, objects) {
    this.rayAt(clientX, clientY);
    return this.raycaster.intersectObjects(objects, false)[0] || null;
  }

  // Where the ray under client coordinates meets the plane through point with normal.
  rayOnPlane(clientX, clientY, point, normal) {
    const plane = new THREE.Plane().setFromNormalAndCoplanarPoint(normal, point);
    return this.rayAt(clientX, clientY).intersectPlane(plane, new THREE.Vector3());
  }

  // CSS pixels relative to the canvas of a 3D point.
  project(point) {
    const p = point.clone().project(this.camera);
    const rect = this.canvas.getBoundingClientRect();
    return { x: (p.x + 1) * 0.5 * rect.width, y: (1 - p.y) * 0.5 * rect.height, depth: p.z };
  }

  faceNormal(f) {
    return new THREE.Vector3().fromArray(this.faceNormals, 3 * f);
  }

  faceCentroid(f) {
    return new THREE.Vector3().fromArray(this.centroids, 3 * f);
  }

  vertexNormal(v) {
    return new THREE.Vector3().fromArray(this.vertexNormals, 3 * v);
  }

  vertexPosition(v) {
    return new THREE.Vector3().fromArray(this.mesh.positions, 3 * v);
  }
}

// Grey levels from tail to head along each stroke, by arc length.
function fadeStrokes(lines, colours, tail, head) {
  const segments = lines.length / 6;
  const length = (i) => Math.hypot(lines[6 * i + 3] - lines[6 * i], lines[6 * i + 4] - lines[6 * i + 1],
    lines[6 * i + 5] - lines[6 * i + 2]);
  const joined = (i) => lines[6 * i] === lines[6 * i - 3] && lines[6 * i + 1] === lines[6 * i - 2] &&
    lines[6 * i + 2] === lines[6 * i - 1];
  let first = 0;
  while (first < segments) {
    let last = first + 1;
    let total = length(first);
    while (last < segments && joined(last)) total += length(last++);
    let along = 0;
    for (let i = first; i < last; ++i) {
      const a = total > 0 ? along / total : 0;
      along += length(i);
      const b = total > 0 ? along / total : 1;
      colours.fill(tail + (head - tail) * a, 6 * i, 6 * i + 3);
      colours.fill(tail + (head - tail) * b, 6 * i + 3, 6 * i + 6);
    }
    first = last;
  }
}
