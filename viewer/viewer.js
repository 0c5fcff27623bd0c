// simswift's replay viewer (docs/viewer.md). Reads the recording from the
// server's JSON API (app/view/ViewerSite.hpp) and draws it with three.js r111
// (Debian's libjs-three, global THREE). Frames: the recording's "world" is
// the field (x to the opponent goal, y left, z up, metres); the 3D view keeps
// it (camera up = +z). Times are ns since the run's start (MCAP log times).
// window.simswiftView exposes the page's state for the browser test.
(function () {
  'use strict';

  const NS = 1e9;
  const TF_BLOCK_NS = 2 * NS;      // /tf is loaded in blocks of this much run time
  const PLOT_BEFORE_NS = 4 * NS;   // the plots' window: this much before the cursor ...
  const PLOT_AFTER_NS = 1 * NS;    // ... and this much after
  const PLOT_POINTS = 400;         // messages per plot window (the server thins evenly)
  const EVENT_COLOURS = { fall: '#ff5050', push: '#ffb040', penalty: '#ffe040', goal: '#50ff80',
                          game_state: '#80b0ff', verdict: '#ff40ff', watchdog: '#ff8080' };

  const S = {
    info: null, meta: {}, robots: [], topics: new Set(), t0: 0, t1: 0, tick: 1e7,
    t: 0, playing: false, speed: 1, robot: 0, follow: 'none', joint: null, camera: 'top',
    events: [], tfBlocks: new Map(), tfT: null, series: null, seriesKey: '', belief: null, beliefKey: '',
    image: null, imageKey: '', pending: 0, errors: [], ready: false, webgl: false,
  };

  const $ = (id) => document.getElementById(id);

  function fail(message) {
    S.errors.push(String(message));
    $('notice').textContent = S.errors[S.errors.length - 1];
  }
  window.addEventListener('error', (e) => fail(e.message));
  window.addEventListener('unhandledrejection', (e) => fail(e.reason && e.reason.message ? e.reason.message : e.reason));

  async function getJson(url) {
    S.pending++;
    S.generation = (S.generation || 0) + 1;  // a change to draw (frame())
    try {
      const r = await fetch(url);
      if (!r.ok) throw new Error(url + ': ' + r.status + ' ' + (await r.text()));
      return await r.json();
    } finally {
      S.pending--;
      S.dirty = true;
    }
  }
  const topicUrl = (path, topic, params) =>
    path + '?topic=' + encodeURIComponent(topic) + Object.keys(params).map((k) => '&' + k + '=' + Math.round(params[k])).join('');

  // The last element of a time-sorted list of {t} at or before t (else the first), or null.
  function atOrBefore(list, t) {
    if (!list || !list.length) return null;
    let lo = 0, hi = list.length - 1;
    if (list[0].t > t) return list[0];
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (list[mid].t <= t) lo = mid; else hi = mid - 1;
    }
    return list[lo];
  }

  // ---------------------------------------------------------------- 3D scene
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x30343a);
  const camera = new THREE.PerspectiveCamera(45, 1, 0.05, 200);
  camera.up.set(0, 0, 1);
  camera.position.set(-6.5, -6.5, 5.5);
  let renderer = null, controls = null;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    $('scene').appendChild(renderer.domElement);
    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.set(0, 0, 0);
    controls.update();
    controls.addEventListener('change', () => { S.dirty = true; });
    S.webgl = true;
  } catch (e) {
    $('notice').textContent = 'No WebGL in this browser: the 3D view is off (timeline, plots and images still work).';
  }
  scene.add(new THREE.HemisphereLight(0xffffff, 0x404040, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 0.6);
  sun.position.set(3, -4, 10);
  scene.add(sun);

  const frames = new Map();  // frame id -> THREE.Group posed from /tf ("world" is the scene)
  function frameGroup(id) {
    if (id === 'world' || id === '') return scene;
    let g = frames.get(id);
    if (!g) {
      g = new THREE.Group();
      g.name = id;
      frames.set(id, g);
      scene.add(g);
    }
    return g;
  }

  const colour = (c) => new THREE.Color(c ? c.r : 0.7, c ? c.g : 0.7, c ? c.b : 0.7);
  function material(c) {
    const a = c && c.a !== undefined ? c.a : 1;
    return new THREE.MeshLambertMaterial({ color: colour(c), transparent: a < 1, opacity: a });
  }
  function place(obj, pose) {
    if (!pose) return obj;
    const p = pose.position || {}, o = pose.orientation || {};
    obj.position.set(p.x || 0, p.y || 0, p.z || 0);
    obj.quaternion.set(o.x || 0, o.y || 0, o.z || 0, o.w === undefined ? 1 : o.w);
    return obj;
  }
  const unitBox = new THREE.BoxBufferGeometry(1, 1, 1);
  const unitSphere = new THREE.SphereBufferGeometry(0.5, 20, 14);

  // A foxglove.SceneUpdate entity's primitives, in its frame.
  function addEntity(e) {
    const g = frameGroup(e.frame_id);
    for (const c of e.cubes || []) {
      const m = place(new THREE.Mesh(unitBox, material(c.color)), c.pose);
      m.scale.set(c.size.x, c.size.y, c.size.z);
      g.add(m);
    }
    for (const s of e.spheres || []) {
      const m = place(new THREE.Mesh(unitSphere, material(s.color)), s.pose);
      m.scale.set(s.size.x, s.size.y, s.size.z);
      g.add(m);
    }
    for (const c of e.cylinders || []) {
      // foxglove's cylinder: axis z, size = diameters x, y and height z; three's: axis y.
      const top = c.top_scale === undefined ? 1 : c.top_scale, bottom = c.bottom_scale === undefined ? 1 : c.bottom_scale;
      const geo = new THREE.CylinderBufferGeometry(0.5 * top, 0.5 * bottom, 1, 20);
      geo.rotateX(Math.PI / 2);
      const m = place(new THREE.Mesh(geo, material(c.color)), c.pose);
      m.scale.set(c.size.x, c.size.y, c.size.z);
      g.add(m);
    }
    for (const l of e.lines || []) addLines(g, l);
  }
  // A LinePrimitive (0 strip, 1 loop, 2 list): segments drawn as flat bands of
  // its thickness (m) when it has one (WebGL draws lines 1 px wide).
  function addLines(g, l) {
    const pts = (l.points || []).map((p) => new THREE.Vector3(p.x, p.y, p.z));
    const segs = [];
    if (l.type === 2) for (let i = 0; i + 1 < pts.length; i += 2) segs.push([pts[i], pts[i + 1]]);
    else for (let i = 0; i + 1 < pts.length; ++i) segs.push([pts[i], pts[i + 1]]);
    if (l.type === 1 && pts.length > 2) segs.push([pts[pts.length - 1], pts[0]]);
    const holder = place(new THREE.Group(), l.pose);
    const mat = material(l.color);
    for (const [a, b] of segs) {
      const d = new THREE.Vector3().subVectors(b, a);
      if (l.thickness > 0 && !l.scale_invariant) {
        const m = new THREE.Mesh(unitBox, mat);
        m.scale.set(d.length() + l.thickness, l.thickness, 0.002);
        m.position.addVectors(a, b).multiplyScalar(0.5);
        m.rotation.z = Math.atan2(d.y, d.x);
        holder.add(m);
      } else {
        const geo = new THREE.BufferGeometry().setFromPoints([a, b]);
        holder.add(new THREE.Line(geo, new THREE.LineBasicMaterial({ color: colour(l.color) })));
      }
    }
    g.add(holder);
  }

  // Without a /scene: a plain field (SPL 2017, 9 x 6 m) and a box per frame.
  function fallbackField() {
    const carpet = new THREE.Mesh(unitBox, material({ r: 0.1, g: 0.45, b: 0.15 }));
    carpet.scale.set(10.4, 7.4, 0.01);
    carpet.position.z = -0.005;
    scene.add(carpet);
    const p = (x, y) => ({ x, y, z: 0.002 });
    addLines(scene, { type: 1, thickness: 0.05, color: { r: 1, g: 1, b: 1 }, points: [p(-4.5, -3), p(4.5, -3), p(4.5, 3), p(-4.5, 3)] });
    addLines(scene, { type: 2, thickness: 0.05, color: { r: 1, g: 1, b: 1 }, points: [p(0, -3), p(0, 3)] });
  }
  function fallbackShape(id) {
    const g = frameGroup(id);
    if (g.children.length) return;
    const ball = id === 'ball';
    const m = new THREE.Mesh(ball ? unitSphere : unitBox, material(ball ? { r: 1, g: 0.5, b: 0 } : { r: 0.75, g: 0.75, b: 0.8 }));
    m.scale.setScalar(ball ? 0.1 : 0.05);
    g.add(m);
  }

  // What the selected robot believed: its ball estimate and its pose.
  const beliefBall = new THREE.Mesh(new THREE.TorusBufferGeometry(0.08, 0.012, 8, 24), material({ r: 1, g: 0.6, b: 0.1, a: 0.9 }));
  const beliefPose = new THREE.Group();
  {
    const mat = material({ r: 0.3, g: 0.8, b: 1, a: 0.85 });
    const shaft = new THREE.Mesh(unitBox, mat);
    shaft.scale.set(0.3, 0.03, 0.01);
    shaft.position.x = 0.15;
    const head = new THREE.Mesh(new THREE.ConeBufferGeometry(0.06, 0.12, 12), mat);
    head.rotation.z = -Math.PI / 2;
    head.position.x = 0.34;
    const disc = new THREE.Mesh(new THREE.CylinderBufferGeometry(0.12, 0.12, 0.01, 24), mat);
    disc.rotation.x = Math.PI / 2;
    beliefPose.add(shaft, head, disc);
  }
  beliefBall.visible = beliefPose.visible = false;
  beliefBall.position.z = 0.02;
  beliefPose.position.z = 0.015;
  scene.add(beliefBall, beliefPose);

  function resize() {
    if (!renderer) return;
    const el = $('scene');
    renderer.setSize(el.clientWidth, el.clientHeight, false);
    camera.aspect = el.clientWidth / Math.max(1, el.clientHeight);
    camera.updateProjectionMatrix();
  }
  window.addEventListener('resize', () => { resize(); S.dirty = true; });

  // ---------------------------------------------------------------- data
  function tfBlock(b) {
    if (S.tfBlocks.has(b)) return S.tfBlocks.get(b);
    const entry = { list: null };
    S.tfBlocks.set(b, entry);
    const from = S.t0 + b * TF_BLOCK_NS;
    getJson(topicUrl('/api/messages', '/tf', { from, to: from + TF_BLOCK_NS - 1, max: 200000 }))
      .then((r) => { entry.list = r.messages; })
      .catch((e) => { S.tfBlocks.delete(b); fail(e.message); });
    return entry;
  }
  // The /tf message in force at t: the last at or before t (from t's block or the one before).
  function tfAt(t) {
    if (!S.topics.has('/tf')) return { msg: null, loading: false };
    const b = Math.max(0, Math.floor((t - S.t0) / TF_BLOCK_NS));
    const here = tfBlock(b);
    if (!here.list) return { msg: null, loading: true };
    if (S.playing) tfBlock(b + 1);  // ahead of the cursor
    if (here.list.length && here.list[0].t <= t) return { msg: atOrBefore(here.list, t), loading: false };
    if (b === 0) return { msg: here.list[0] || null, loading: false };
    const before = tfBlock(b - 1);
    if (!before.list) return { msg: null, loading: true };
    return { msg: before.list.length ? before.list[before.list.length - 1] : here.list[0] || null, loading: false };
  }
  function applyTf(msg) {
    for (const tr of msg.data.transforms || []) {
      if (!S.hasScene) fallbackShape(tr.child_frame_id);
      const g = frameGroup(tr.child_frame_id);
      const p = tr.translation, q = tr.rotation;
      g.position.set(p.x, p.y, p.z);
      g.quaternion.set(q.x, q.y, q.z, q.w);
    }
    S.tfT = msg.t;
  }

  const robotTopic = (suffix) => '/' + robotId(S.robot) + '/' + suffix;
  function robotId(i) {
    const r = S.robots[i];
    return r && r.id ? r.id : 'robot' + i;
  }

  // The selected robot's joints and sensors around the cursor (reloaded when the cursor leaves the middle of the window).
  function wantSeries() {
    const w = S.series;
    const key = S.robot;
    if (w && w.key === key && (w.loading || (S.t >= w.from + 0.25 * PLOT_BEFORE_NS && S.t <= w.to - 0.5 * PLOT_AFTER_NS) ||
        (S.t >= w.from && S.t <= w.to && (w.from <= S.t0 || w.to >= S.t1)))) return;
    const from = Math.max(S.t0, S.t - PLOT_BEFORE_NS), to = Math.min(S.t1, S.t + PLOT_AFTER_NS);
    const entry = { key, from, to, loading: true, joints: null, sensors: null };
    S.series = entry;
    const load = (suffix, field) => {
      const topic = robotTopic(suffix);
      if (!S.topics.has(topic)) return Promise.resolve();
      return getJson(topicUrl('/api/messages', topic, { from, to, max: PLOT_POINTS })).then((r) => { entry[field] = r.messages; });
    };
    Promise.all([load('joints', 'joints'), load('sensors', 'sensors')])
      .then(() => { entry.loading = false; fillJointNames(); })
      .catch((e) => fail(e.message));
  }
  function fillJointNames() {
    const j = S.series && S.series.joints && S.series.joints.length ? S.series.joints[0].data.name || [] : [];
    const sel = $('joint');
    if (sel.options.length === j.length && [...sel.options].every((o, i) => o.value === j[i])) return;
    sel.innerHTML = '';
    for (const n of j) sel.add(new Option(n, n));
    if (!j.includes(S.joint)) S.joint = j.length ? (j.includes(S.wantJoint) ? S.wantJoint : j[0]) : null;
    sel.value = S.joint || '';
  }

  // The latest message of `topic` at the cursor (belief, camera image), fetched once per cursor position.
  function latest(slot, topic) {
    const key = topic + '@' + S.t;
    if (!S.topics.has(topic)) { S[slot] = null; S[slot + 'Key'] = key; return; }
    if (S[slot + 'Key'] === key || S[slot + 'Loading']) return;
    // While playing, at most one fetch per 100 ms of run time (camera images are large).
    if (S.playing && S[slot + 'At'] !== undefined && Math.abs(S.t - S[slot + 'At']) < 0.1 * NS) return;
    S[slot + 'At'] = S.t;
    S[slot + 'Loading'] = true;
    getJson(topicUrl('/api/at', topic, { t: S.t }))
      .then((m) => { S[slot] = m.data ? m : null; S[slot + 'Key'] = key; })
      .catch((e) => fail(e.message))
      // Drawn again once it is done: the cursor may have moved while it loaded.
      .finally(() => { S[slot + 'Loading'] = false; S.dirty = true; });
  }

  // ---------------------------------------------------------------- drawing
  function plot(canvas, series, title) {
    const c = canvas.getContext('2d');
    const w = canvas.width, h = canvas.height;
    c.clearRect(0, 0, w, h);
    const from = Math.max(S.t0, S.t - PLOT_BEFORE_NS), to = from + PLOT_BEFORE_NS + PLOT_AFTER_NS;
    let lo = Infinity, hi = -Infinity;
    for (const s of series) for (const p of s.points) if (isFinite(p[1])) { lo = Math.min(lo, p[1]); hi = Math.max(hi, p[1]); }
    if (!isFinite(lo)) { lo = -1; hi = 1; }
    if (hi - lo < 1e-6) { lo -= 0.5; hi += 0.5; }
    const pad = 0.08 * (hi - lo);
    lo -= pad; hi += pad;
    const X = (t) => ((t - from) / (to - from)) * w, Y = (v) => h - 14 - ((v - lo) / (hi - lo)) * (h - 20);
    c.strokeStyle = '#555';
    c.beginPath(); c.moveTo(X(S.t), 0); c.lineTo(X(S.t), h); c.stroke();
    for (const s of series) {
      c.strokeStyle = s.colour;
      c.setLineDash(s.dash ? [4, 3] : []);
      c.beginPath();
      s.points.forEach((p, i) => (i ? c.lineTo(X(p[0]), Y(p[1])) : c.moveTo(X(p[0]), Y(p[1]))));
      c.stroke();
    }
    c.setLineDash([]);
    c.fillStyle = '#bbb';
    c.fillText(title + '   [' + lo.toFixed(2) + ', ' + hi.toFixed(2) + ']', 4, h - 3);
    let x = w - 4;
    c.textAlign = 'right';
    for (const s of series.slice().reverse()) { c.fillStyle = s.colour; c.fillText(s.name, x, 11); x -= c.measureText(s.name).width + 8; }
    c.textAlign = 'left';
  }
  const pts = (list, f) => (list || []).map((m) => [m.t, f(m.data)]);
  const sum = (a) => (a || []).reduce((x, y) => x + y, 0);

  // Values at the cursor (what the plots' cursor line crosses), for the panel and the test.
  function plotValues() {
    const out = {};
    const j = S.series && atOrBefore(S.series.joints, S.t);
    if (j && S.joint) {
      const i = (j.data.name || []).indexOf(S.joint);
      out.joint = { t_ns: j.t, name: S.joint, position: j.data.position[i], command: j.data.command ? j.data.command[i] : null };
    }
    const s = S.series && atOrBefore(S.series.sensors, S.t);
    if (s) out.sensors = { t_ns: s.t, fsr_left: sum(s.data.fsr_left), fsr_right: sum(s.data.fsr_right),
                           accelerometer: s.data.accelerometer, gyroscope: s.data.gyroscope, angle: s.data.angle };
    return out;
  }

  function drawPlots() {
    const w = S.series || {};
    const i = (d) => (d.name || []).indexOf(S.joint);
    plot($('plot-joint'), [
      { name: 'position', colour: '#6cf', points: pts(w.joints, (d) => d.position[i(d)]) },
      { name: 'command', colour: '#fc6', dash: true, points: pts(w.joints, (d) => (d.command || [])[i(d)]) },
    ], (S.joint || 'joint') + ' (rad)');
    plot($('plot-fsr'), [
      { name: 'left', colour: '#6f6', points: pts(w.sensors, (d) => sum(d.fsr_left)) },
      { name: 'right', colour: '#f66', points: pts(w.sensors, (d) => sum(d.fsr_right)) },
    ], 'FSR total per foot');
    const v = (f, k) => (d) => (d[f] || {})[k];
    plot($('plot-accel'), [
      { name: 'x', colour: '#f66', points: pts(w.sensors, v('accelerometer', 'x')) },
      { name: 'y', colour: '#6f6', points: pts(w.sensors, v('accelerometer', 'y')) },
      { name: 'z', colour: '#69f', points: pts(w.sensors, v('accelerometer', 'z')) },
    ], 'accelerometer (m/s²)');
    plot($('plot-gyro'), [
      { name: 'gyro x', colour: '#f66', points: pts(w.sensors, v('gyroscope', 'x')) },
      { name: 'gyro y', colour: '#6f6', points: pts(w.sensors, v('gyroscope', 'y')) },
      { name: 'gyro z', colour: '#69f', points: pts(w.sensors, v('gyroscope', 'z')) },
      { name: 'angle x', colour: '#fa6', dash: true, points: pts(w.sensors, v('angle', 'x')) },
      { name: 'angle y', colour: '#c8f', dash: true, points: pts(w.sensors, v('angle', 'y')) },
    ], 'gyroscope (rad/s), angle (rad)');
  }

  function drawBelief() {
    const b = S.belief && S.belief.data;
    beliefBall.visible = !!(b && b.ball);
    if (b && b.ball) beliefBall.position.set(b.ball.x, b.ball.y, 0.02);
    beliefPose.visible = !!(b && b.pose);
    if (b && b.pose) { beliefPose.position.set(b.pose.x, b.pose.y, 0.015); beliefPose.rotation.z = b.pose.theta; }
    const f = (x) => (typeof x === 'number' ? x.toFixed(2) : '?');
    $('belief').textContent = !S.topics.has(robotTopic('belief')) ? 'No beliefs recorded for this robot.' :
      !b ? '' : 'Believed: pose (' + f(b.pose && b.pose.x) + ', ' + f(b.pose && b.pose.y) + ') m, ' + f(b.pose && b.pose.theta) +
      ' rad; ball ' + (b.ball ? '(' + f(b.ball.x) + ', ' + f(b.ball.y) + ') m' : 'not seen') + (b.behaviour ? '; ' + b.behaviour : '');
  }

  function drawImage() {
    const img = $('camera-image');
    const m = S.image;
    const src = m && m.data && m.data.data ? 'data:image/' + (m.data.format === 'jpeg' ? 'jpeg' : 'png') + ';base64,' + m.data.data : '';
    if (img.dataset.t !== String(m ? m.t : '')) {
      img.dataset.t = m ? m.t : '';
      if (src) img.src = src; else img.removeAttribute('src');
    }
    $('camera').style.display = S.topics.has(robotTopic('camera/top')) || S.topics.has(robotTopic('camera/bottom')) ? '' : 'none';
  }

  const fmt = (t) => ((t - S.t0) / NS).toFixed(3);
  function drawTimeline() {
    const c = $('timeline');
    const w = (c.width = c.clientWidth), h = c.height;
    const g = c.getContext('2d');
    g.clearRect(0, 0, w, h);
    g.fillStyle = '#333';
    g.fillRect(0, h / 2 - 3, w, 6);
    const X = (t) => ((t - S.t0) / Math.max(1, S.t1 - S.t0)) * (w - 8) + 4;
    for (const e of S.events) {
      g.fillStyle = EVENT_COLOURS[e.data.name] || '#ccc';
      g.fillRect(X(e.t) - 1.5, 4, 3, h - 8);
    }
    g.fillStyle = '#fff';
    g.fillRect(X(S.t) - 1, 0, 2, h);
    $('time').textContent = 't = ' + fmt(S.t) + ' s / ' + fmt(S.t1) + ' s';
  }

  // ---------------------------------------------------------------- the loop
  let lastFrame = null, urlT = null;
  // Draws only when something changed (the cursor, data arriving, the
  // controls): a still page costs nothing, which matters on a CPU renderer.
  let drawnKey = '';
  function frame(now) {
    if (S.ready && S.playing && lastFrame !== null) {
      // At most 100 ms of wall clock per frame: a browser that draws seldom
      // (a hidden tab, a loaded machine) plays slower rather than leaping.
      // Whole ns: the cursor names a time to the server (/api/at?t=), which takes integers.
      S.t = Math.min(S.t1, Math.round(S.t + Math.min(now - lastFrame, 100) * 1e6 * S.speed));
      if (S.t >= S.t1) setPlaying(false);
    }
    lastFrame = now;
    const key = [S.ready, S.t, S.robot, S.joint, S.camera, S.follow, S.pending, S.generation].join();
    if (key !== drawnKey || S.dirty) {
      drawnKey = key;
      S.dirty = false;
      if (S.ready) update();
      if (renderer) renderer.render(scene, camera);
    }
    requestAnimationFrame(frame);
  }

  function update() {
    const tf = tfAt(S.t);
    if (tf.msg && tf.msg.t !== S.tfT) applyTf(tf.msg);
    wantSeries();
    latest('belief', robotTopic('belief'));
    latest('image', robotTopic('camera/' + S.camera));
    drawBelief();
    drawImage();
    drawPlots();
    drawTimeline();
    follow();
    if (controls) controls.update();
    if (!S.playing && urlT !== S.t) writeUrl();
  }

  // Keeps the followed body at the view's centre; on starting to follow,
  // the camera comes close (2 m behind and to the right, 1.1 m up).
  let followed = null;
  function follow() {
    if (S.follow === 'none' || !controls) { followed = null; return; }
    const id = S.follow === 'ball' ? 'ball' : robotId(S.robot) + '/' + robotRoot(S.robot);
    const g = frames.get(id);
    if (!g) return;
    if (followed !== id) {
      followed = id;
      controls.target.copy(g.position);
      camera.position.set(g.position.x - 1.4, g.position.y - 1.4, g.position.z + 1.1);
    }
    const d = new THREE.Vector3().subVectors(g.position, controls.target);
    controls.target.add(d);
    camera.position.add(d);
  }
  function robotRoot(i) {
    const links = (S.robots[i] && S.robots[i].links) || [];
    return links.includes('torso') ? 'torso' : links[0] || 'torso';
  }

  function writeUrl() {
    urlT = S.t;
    const q = new URLSearchParams(location.search);
    q.set('t', fmt(S.t));
    q.set('robot', S.robot);
    if (S.follow !== 'none') q.set('follow', S.follow); else q.delete('follow');
    history.replaceState(null, '', '?' + q.toString());
  }

  // ---------------------------------------------------------------- controls
  function seek(t) {
    S.t = Math.max(S.t0, Math.min(S.t1, Math.round(t)));
  }
  function setPlaying(on) {
    S.playing = on;
    S.dirty = true;  // paused: what playing fetched only now and then (belief, image) is fetched for the cursor
    if (on && S.t >= S.t1) S.t = S.t0;
    $('play').innerHTML = on ? '&#x2016;' : '&#x25B6;';
  }
  function jumpEvent(dir) {
    const tol = S.tick / 2;
    const list = dir > 0 ? S.events.filter((e) => e.t > S.t + tol) : S.events.filter((e) => e.t < S.t - tol).reverse();
    if (list.length) { setPlaying(false); seek(list[0].t); }
  }
  function selectRobot(i) {
    S.robot = Math.max(0, Math.min(S.robots.length - 1, i | 0));
    $('robot').value = String(S.robot);
    S.series = null;
  }

  function wire() {
    $('play').onclick = () => setPlaying(!S.playing);
    $('step').onclick = () => { setPlaying(false); seek(S.t + S.tick); };
    $('step-back').onclick = () => { setPlaying(false); seek(S.t - S.tick); };
    $('next-event').onclick = () => jumpEvent(1);
    $('prev-event').onclick = () => jumpEvent(-1);
    $('speed').onchange = (e) => { S.speed = Number(e.target.value); };
    $('robot').onchange = (e) => selectRobot(Number(e.target.value));
    $('follow').onchange = (e) => { S.follow = e.target.value; urlT = null; };
    $('joint').onchange = (e) => { S.joint = e.target.value; };
    $('camera-name').onchange = (e) => { S.camera = e.target.value; };
    const timeline = $('timeline');
    timeline.onclick = (e) => {
      const r = timeline.getBoundingClientRect();
      seek(S.t0 + ((e.clientX - r.left - 4) / (r.width - 8)) * (S.t1 - S.t0));
    };
    timeline.onmousemove = (e) => {
      const r = timeline.getBoundingClientRect();
      const t = S.t0 + ((e.clientX - r.left - 4) / (r.width - 8)) * (S.t1 - S.t0);
      const near = S.events.filter((ev) => Math.abs(ev.t - t) < (S.t1 - S.t0) * 0.005);
      timeline.title = near.map((ev) => fmt(ev.t) + ' s ' + ev.data.name + ': ' + ev.data.message).join('\n');
    };
    window.addEventListener('keydown', (e) => {
      if (e.target.tagName === 'SELECT') return;
      if (e.key === ' ') { setPlaying(!S.playing); e.preventDefault(); }
      if (e.key === 'ArrowRight') { setPlaying(false); seek(S.t + S.tick); }
      if (e.key === 'ArrowLeft') { setPlaying(false); seek(S.t - S.tick); }
    });
  }

  // ---------------------------------------------------------------- start
  async function start() {
    wire();
    resize();
    S.info = await getJson('/api/info');
    S.meta = (S.info.metadata && S.info.metadata.simswift) || {};
    for (const c of S.info.channels) S.topics.add(c.topic);
    S.t0 = 0;  // log times are ns since the run's start
    S.t1 = Math.max(S.info.end_ns, 1);
    S.tick = Number(S.meta.tick_ns) > 0 ? Number(S.meta.tick_ns) : 1e7;
    try { S.robots = JSON.parse(S.meta.robots || '[]'); } catch (e) { S.robots = []; }
    if (!S.robots.length)
      for (const t of S.topics) { const m = /^\/robot(\d+)\//.exec(t); if (m && !S.robots[+m[1]]) S.robots[+m[1]] = { id: 'robot' + m[1] }; }
    S.robots = Array.from(S.robots, (r, i) => r || { id: 'robot' + i });
    const sel = $('robot');
    S.robots.forEach((r, i) => sel.add(new Option(r.id + (r.team ? ' (team ' + r.team + ', player ' + r.player + ')' : ''), i)));
    $('title').textContent = [S.meta.scenario ? S.meta.scenario.split('/').pop() : '', S.meta.seed !== undefined ? 'seed ' + S.meta.seed : '', (S.meta.simswift_version || S.meta.version) ? 'simswift ' + (S.meta.simswift_version || S.meta.version) : '',
                              S.meta.commit ? 'commit ' + S.meta.commit : ''].filter(Boolean).join(' · ') || S.info.file;
    document.title = 'simswift view: ' + (S.meta.scenario || S.info.file);

    S.hasScene = false;
    if (S.topics.has('/scene')) {
      const sc = await getJson(topicUrl('/api/at', '/scene', { t: S.t0 }));
      const entities = (sc.data && sc.data.entities) || [];
      for (const e of entities) addEntity(e);
      S.hasScene = true;
      S.hasField = entities.some((e) => e.frame_id === 'world');
    }
    if (!S.hasField) fallbackField();
    if (S.topics.has('/events')) S.events = (await getJson(topicUrl('/api/messages', '/events', { max: 200000 }))).messages;
    const list = $('events');
    for (const e of S.events) {
      const li = document.createElement('li');
      li.textContent = fmt(e.t) + ' s  ' + e.data.name + ': ' + e.data.message;
      li.style.color = EVENT_COLOURS[e.data.name] || '';
      li.onclick = () => { setPlaying(false); seek(e.t); };
      list.appendChild(li);
    }

    const q = new URLSearchParams(location.search);
    if (q.has('robot')) selectRobot(Number(q.get('robot')));
    if (q.has('follow')) { S.follow = q.get('follow'); $('follow').value = S.follow; }
    if (q.has('joint')) S.wantJoint = q.get('joint');
    if (q.has('t') && isFinite(Number(q.get('t')))) seek(S.t0 + Number(q.get('t')) * NS);
    S.ready = true;
  }

  // For the browser test (tests/view/) and the tools that film the viewer:
  // the page's state, and the cursor and selection as the controls set them.
  window.simswiftView = {
    state() {
      const drawn = {};
      for (const [id, g] of frames)
        drawn[id] = { x: g.position.x, y: g.position.y, z: g.position.z, qx: g.quaternion.x, qy: g.quaternion.y, qz: g.quaternion.z, qw: g.quaternion.w };
      const b = S.belief && S.belief.data;
      return {
        ready: S.ready, webgl: S.webgl, t_ns: S.t, t_s: (S.t - S.t0) / NS, end_s: (S.t1 - S.t0) / NS, tick_ns: S.tick,
        playing: S.playing, speed: S.speed, robot: S.robot, follow: S.follow, time_text: $('time').textContent,
        tf_t_ns: S.tfT, frames: drawn, plots: plotValues(), belief: b || null, belief_t_ns: S.belief ? S.belief.t : null,
        image_t_ns: S.image ? S.image.t : null, events: S.events.map((e) => ({ t_ns: e.t, name: e.data.name, message: e.data.message })),
        errors: S.errors.slice(), pending: S.pending,
      };
    },
    // true once everything at the cursor is loaded and drawn.
    settled() {
      if (!S.ready || S.pending) return false;
      const tf = tfAt(S.t);
      return !tf.loading && (!tf.msg || S.tfT === tf.msg.t) && S.series && !S.series.loading &&
             (!S.topics.has(robotTopic('belief')) || S.beliefKey === robotTopic('belief') + '@' + S.t);
    },
    seek(seconds) { setPlaying(false); seek(S.t0 + seconds * NS); },
    select(i) { selectRobot(i); },
    play(on) { setPlaying(on !== false); },
  };

  start().catch((e) => fail('cannot load the recording: ' + e.message));
  requestAnimationFrame(frame);
})();
