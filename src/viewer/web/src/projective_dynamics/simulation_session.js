// The simulation as the page sees it: frames of surface positions drawn as they come, the
// mouse grabbing, dragging and poking the surface, and the panel's buttons and stiffness
// slider.  Requests go through the connection's queue; drags and the slider are keyed, so a
// fast mouse sends only its latest target and never piles up requests.
import * as THREE from 'three';

const $ = (id) => document.getElementById(id);
const STEPS = 1000; // of the stiffness slider, log scale between the server's min and max
const AVERAGE = 0.1; // weight of a new sample in the moving averages

const ms = (x) => (Number.isFinite(x) ? `${x.toFixed(1)} ms` : '–');
const average = (old, x) => (!Number.isFinite(x) ? old : Number.isFinite(old) ? old + AVERAGE * (x - old) : x);

export class SimulationSession {
  constructor(connection, viewer, line) {
    Object.assign(this, { connection, viewer, line });
    this.queue = connection.queue;
    this.info = null;
    this.state = null;
    this.frame = null; // { header, positions } of the last frame
    this.frames = 0;
    this.log = []; // answers to the page's requests: { type, request, ... }
    this.averages = { simulation: NaN, interval: NaN, arrival: NaN };
    this.late = 0;
    this.lastArrival = NaN;
    this.drag = null;
    this.bindPanel();
    this.bindMouse();
  }

  send(message, key) {
    return this.queue.push({ key, build: () => message });
  }

  bindPanel() {
    $('sim-play').addEventListener('click', () => this.send({ type: this.state?.playing ? 'pause' : 'play' }));
    $('sim-reset').addEventListener('click', () => this.send({ type: 'reset' }));
    $('sim-drop').addEventListener('click', () => this.send({ type: 'drop' }));
    // Another body or simulator: a new hello builds it (the server keeps the old one if refused).
    const rebuild = () => {
      this.line.status('building the body…');
      this.send({ type: 'hello', kind: 'simulation', mode: $('sim-mode').value, simulator: $('sim-simulator').value })
        .catch(() => this.showBody());
    };
    $('sim-mode').addEventListener('change', rebuild);
    $('sim-simulator').addEventListener('change', rebuild);
    const slider = $('sim-stiffness');
    slider.addEventListener('input', () => {
      const value = this.sliderToStiffness(Number(slider.value));
      this.showStiffness(value);
      this.send({ type: 'stiffness', value }, 'stiffness');
    });
  }

  sliderToStiffness(v) {
    const { min, max } = this.info.stiffness;
    return min * (max / min) ** (v / STEPS);
  }

  stiffnessToSlider(k) {
    const { min, max } = this.info.stiffness;
    return Math.round((STEPS * Math.log(k / min)) / Math.log(max / min));
  }

  showStiffness(k) {
    $('sim-stiffness-value').textContent = `×${(k / this.info.stiffness.default).toPrecision(2)}`;
  }

  // Left button on the body: grab (drag) or poke; elsewhere the orbit controls have it.  The
  // capture phase sees the press before the controls do.
  bindMouse() {
    const view = this.viewer.canvas.parentElement;
    view.addEventListener('pointerdown', (e) => {
      if (e.button !== 0 || !this.info) return;
      const hit = this.viewer.pick(e.clientX, e.clientY);
      if (!hit) return;
      e.stopPropagation();
      e.preventDefault();
      const vertex = this.nearestCorner(hit);
      if (e.shiftKey || $('sim-poke').checked) {
        const direction = this.viewer.rayAt(e.clientX, e.clientY).direction.clone();
        const velocity = direction.multiplyScalar(1.5 * this.info.diagonal).toArray();
        this.send({ type: 'poke', vertex, velocity });
        return;
      }
      const start = this.viewer.vertexPosition(vertex);
      const normal = this.viewer.camera.getWorldDirection(new THREE.Vector3());
      this.drag = { vertex, start, point: hit.point.clone(), normal };
      this.send({ type: 'grab', vertex, target: start.toArray() });
      const move = (m) => {
        const p = this.viewer.rayOnPlane(m.clientX, m.clientY, this.drag.point, this.drag.normal);
        if (!p) return;
        const target = this.drag.start.clone().add(p.sub(this.drag.point)).toArray();
        this.lastTarget = target;
        this.send({ type: 'move', target }, 'move');
      };
      const up = () => {
        window.removeEventListener('pointermove', move);
        window.removeEventListener('pointerup', up);
        this.drag = null;
        this.send({ type: 'release' });
      };
      window.addEventListener('pointermove', move);
      window.addEventListener('pointerup', up);
    }, { capture: true });
  }

  // The corner of the picked face nearest to the picked point.
  nearestCorner(hit) {
    const t = this.viewer.mesh.triangles;
    let best = t[3 * hit.face], distance = Infinity;
    for (let k = 0; k < 3; ++k) {
      const v = t[3 * hit.face + k];
      const d = this.viewer.vertexPosition(v).distanceTo(hit.point);
      if (d < distance) [best, distance] = [v, d];
    }
    return best;
  }

  // The selects show the body the server holds (after a refusal: the one it kept).
  showBody() {
    if (!this.info) return;
    $('sim-mode').value = this.info.body.mode;
    $('sim-simulator').value = this.info.body.fallback ? 'reduced' : this.info.body.simulator;
  }

  onText(message) {
    if (message.type === 'info') {
      this.info = message;
      this.averages = { simulation: NaN, interval: NaN, arrival: NaN }; // a new body: its own times
      this.late = 0;
      this.showBody();
      $('sim-mode').disabled = !message.mesh.closed;
      const b = message.body;
      $('sim-body').textContent = `${message.mesh.name}: a ${b.mode} of ${b.vertices} vertices, ${b.elements} ` +
        `${b.mode === 'solid' ? 'tetrahedra' : 'triangles'}; ` +
        (b.simulator === 'reduced' ? `hyper-reduced PD, k = ${b.dimension}, l = ${b.projection_columns}, ` +
          `s = ${b.sampled_elements}` : 'full PD') + `; set up in ${ms(b.setup_ms)}` +
        (b.fallback ? ` (${b.fallback})` : '');
      $('sim-stiffness').value = String(this.stiffnessToSlider(message.stiffness.value));
      this.showStiffness(message.stiffness.value);
      $('mesh-info').textContent = `${message.mesh.vertices} vertices, ${message.mesh.faces} faces` +
        (message.mesh.closed ? ', closed' : ', open');
      return false;
    }
    if (message.type === 'state') {
      this.state = message;
      $('sim-play').textContent = message.playing ? 'Pause' : 'Play';
      this.log.push({ type: 'state', request: message.request, stiffness: message.stiffness,
        playing: message.playing, grabbed: message.grabbed });
      if (this.log.length > 1000) this.log.splice(0, this.log.length - 1000);
    }
    if (message.type === 'error' && message.blown_up) {
      this.state = { ...this.state, playing: false };
      $('sim-play').textContent = 'Play';
    }
    return message.request === undefined; // frames' errors come unasked
  }

  onMesh() {
    // Gravity is along -z: z up, seen from the side and a little above, the floor in view.
    const v = this.viewer;
    const geometry = v.surface.geometry;
    const { center, radius } = geometry.boundingSphere;
    const floor = this.info?.floor ?? geometry.boundingBox.min.z;
    const target = new THREE.Vector3(center.x, center.y, (center.z + floor) / 2);
    const distance = (2.4 * radius) / Math.sin(THREE.MathUtils.degToRad(v.camera.fov / 2));
    v.camera.up.set(0, 0, 1);
    v.camera.position.copy(target).add(new THREE.Vector3(0.35, -1, 0.5).normalize().multiplyScalar(distance));
    v.camera.far = distance + 20 * radius;
    v.camera.updateProjectionMatrix();
    v.controls.target.copy(target);
    v.controls.update();
    if (this.floor) v.scene.remove(this.floor);
    const size = 6 * radius;
    this.floor = new THREE.Group();
    const plane = new THREE.Mesh(new THREE.PlaneGeometry(size, size),
      new THREE.MeshLambertMaterial({ color: 0xd5d9e0, side: THREE.DoubleSide }));
    const grid = new THREE.GridHelper(size, 12, 0x9aa1ad, 0xb4bac4);
    grid.rotation.x = Math.PI / 2; // the helper lies in xz; the floor is the plane z = floor
    grid.position.z = 1e-4 * radius;
    this.floor.add(plane, grid);
    this.floor.position.set(center.x, center.y, floor);
    v.scene.add(this.floor);
    v.requestRender();
  }

  onBinary(header, arrays, bytes, arrivedAt) {
    if (header.type !== 'frame') return;
    this.viewer.updatePositions(arrays.positions);
    this.viewer.holdFrames(0); // frames are the picture: draw each at once
    this.frame = { header, positions: arrays.positions };
    ++this.frames;
    const t = header.timings;
    this.averages.simulation = average(this.averages.simulation, t.simulation_ms ?? NaN);
    this.averages.interval = average(this.averages.interval, t.interval_ms ?? NaN);
    if (t.interval_ms !== null) this.averages.arrival = average(this.averages.arrival, arrivedAt - this.lastArrival);
    this.lastArrival = arrivedAt;
    if (header.late) ++this.late;
    $('sim-readout').textContent = `frame time ${ms(this.averages.interval)} · simulation ${ms(this.averages.simulation)}` +
      ' per frame';
    $('sim-details').textContent = `step ${header.step}, t = ${header.time.toFixed(2)} s; on this page every ` +
      `${ms(this.averages.arrival)}, ${this.viewer.fps.toFixed(0)} fps drawn; ${this.late} late frames` +
      (header.grabbed !== null ? `; holding vertex ${header.grabbed}` : '');
    if (header.request !== undefined) {
      this.queue.onFieldDrawn(this.queue.matches(header.request), header);
      this.line.status('drag the body with the mouse; Shift-click pokes it');
      this.line.shown?.();
    }
  }
}
