// The replay: decodes the run's data, plays it back on a time slider, moves the cameras, answers
// clicks on vehicles. Marks <body data-viewer="ready" data-t="..." data-resources="N"
// data-vehicle0="x y"> once a frame is drawn (N: resources the page fetched, which must be 0;
// x y: where the first vehicle is on screen), or data-viewer="error: ..." so that a headless
// browser can check the page.
(function () {
  'use strict';
  var body = document.body;
  window.addEventListener('error', function (e) { body.setAttribute('data-viewer', 'error: ' + e.message); });
  var D = JSON.parse(document.getElementById('run-data').textContent);
  THREE.Object3D.DefaultUp.set(0, 0, 1);  // the run's z is up
  var $ = function (id) { return document.getElementById(id); };
  var nV = D.vehicles.length, nF = D.frames, rate = D.rate;

  // ---- the log: 16-bit channels, [vehicle][frame][component] ----
  var raw = atob(D.tracks), bytes = new Uint8Array(raw.length);
  for (var i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
  function channel(name, count) {
    var l = D.layout[name];
    if (!l) return null;
    var Type = l.type === 'i16' ? Int16Array : Uint16Array;
    return new Type(bytes.buffer, l.offset, count * nF * l.components);
  }
  var ch = { pos: channel('pos', nV), ref: channel('ref', nV), est: channel('est', nV),
    quat: channel('quat', nV), vel: channel('vel', nV), thrust: channel('thrust', nV),
    moving: channel('moving', D.moving.length) };
  var o = D.quant.origin, step = D.quant.step;
  function positions(c) {  // Float32Array per vehicle, x y z per frame
    var out = [];
    for (var v = 0; v < nV; v++) {
      var a = new Float32Array(3 * nF);
      for (var k = 0; k < 3 * nF; k++) a[k] = o[k % 3] + c[v * 3 * nF + k] * step;
      out.push(a);
    }
    return out;
  }
  var P = positions(ch.pos), R = positions(ch.ref), E = ch.est ? positions(ch.est) : P;
  var err = [], worst = 0.05;
  for (var v = 0; v < nV; v++) {
    err.push(new Float32Array(nF));
    for (var k = 0; k < nF; k++) {
      var dx = P[v][3 * k] - R[v][3 * k], dy = P[v][3 * k + 1] - R[v][3 * k + 1], dz = P[v][3 * k + 2] - R[v][3 * k + 2];
      err[v][k] = Math.sqrt(dx * dx + dy * dy + dz * dz);
      worst = Math.max(worst, err[v][k]);
    }
  }
  var frameTimes = [];
  for (k = 0; k < nF; k++) frameTimes.push(Math.min(k / rate, D.duration));
  var stops = ['#1a9850', '#a6d96a', '#fee08b', '#f46d43', '#a50026'].map(function (c) { return new THREE.Color(c); });
  function errorColour(e) {
    var x = Math.min(Math.max(e / worst, 0), 1) * (stops.length - 1), j = Math.min(Math.floor(x), stops.length - 2);
    return stops[j].clone().lerp(stops[j + 1], x - j);
  }
  // Vehicle colours: none of the error scale's greens, yellows or reds.
  var palette = ['#1f77b4', '#9467bd', '#17becf', '#e377c2', '#8c564b', '#393b79', '#7f7f7f', '#ce6dbd']
    .map(function (c) { return new THREE.Color(c); });
  var vColour = D.vehicles.map(function (_, i) { return palette[i % palette.length]; });

  // ---- the scene ----
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xdfe5ec);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8478, 0.75));
  var sun = new THREE.DirectionalLight(0xffffff, 0.55);
  sun.position.set(0.4, -0.6, 1);
  scene.add(sun);
  var lo = new THREE.Vector3().fromArray(D.bounds.min), hi = new THREE.Vector3().fromArray(D.bounds.max);
  var centre = lo.clone().add(hi).multiplyScalar(0.5), span = hi.clone().sub(lo).length();
  var S = window.CosimScene, layers = {};
  function layer(name, label, object, on) {
    layers[name] = { label: label, objects: [].concat(object), on: on };
    layers[name].objects.forEach(function (x) { x.visible = on; scene.add(x); });
  }
  layer('floor', 'floor and grid', S.floor(D.bounds), true);
  layer('obstacles', 'obstacles', S.obstacles(D.obstacles), true);
  var planned = D.vehicles.map(function (x) { return new Float32Array(x.planned); });
  var pathColour = nV === 1 ? [new THREE.Color('#2f6bd8')] : vColour;
  layer('planned', 'planned path', new THREE.LineSegments(S.polylines(planned, pathColour),
    new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors })), nV === 1 || D.team_plans);
  var refLine = new THREE.LineSegments(S.polylines(R, R.map(function () { return new THREE.Color(0x555a66); })),
    new THREE.LineDashedMaterial({ color: 0x555a66, dashSize: 0.25, gapSize: 0.18 }));
  refLine.computeLineDistances();
  layer('reference', 'reference', refLine, nV === 1 || D.team_plans);
  var flown = S.flownPaths(P, err, frameTimes, errorColour);
  layer('flown', 'flown path (error colour)', flown, true);
  var vehicleMeshes = S.vehicleMeshes(D);
  layer('vehicles', 'vehicles', vehicleMeshes, true);
  var markers = S.dots(nV, nV > 30 ? 7 : 10, vColour);
  layer('markers', 'vehicle dots', markers, true);
  var goals = S.dots(nV, 6, D.vehicles.map(function () { return new THREE.Color(0x222222); }));
  D.vehicles.forEach(function (x, i) { goals.geometry.attributes.position.setXYZ(i, x.goal[0], x.goal[1], x.goal[2]); });
  layer('goals', 'goals', goals, nV <= 50);
  var estimate = ch.est ? S.dots(nV, 6, D.vehicles.map(function () { return new THREE.Color(0xff8c00); })) : null;
  if (estimate) layer('estimate', 'estimate (orange)', estimate, false);
  var moving = D.moving.map(function (m) {
    return new THREE.Mesh(S.shapesGeometry(m.shapes), new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors }));
  });
  if (moving.length) layer('moving', 'moving obstacles', moving, true);

  // ---- state at time t ----
  var T = { t: 0, playing: false, speed: 1, scale: 1, camera: 'orbit', follow: 0, selected: -1 };
  function sample(arr, v, t, out) {  // interpolated x y z of vehicle v
    var f = Math.min(Math.max(t * rate, 0), nF - 1), k0 = Math.floor(f), k1 = Math.min(k0 + 1, nF - 1), w = f - k0;
    var a = arr[v];
    return out.set(a[3 * k0] + w * (a[3 * k1] - a[3 * k0]), a[3 * k0 + 1] + w * (a[3 * k1 + 1] - a[3 * k0 + 1]),
      a[3 * k0 + 2] + w * (a[3 * k1 + 2] - a[3 * k0 + 2]));
  }
  function frameOf(t) { return Math.min(Math.max(Math.round(t * rate), 0), nF - 1); }
  function attitude(v, t, out) {
    var f = Math.min(Math.max(t * rate, 0), nF - 1), k0 = Math.floor(f), k1 = Math.min(k0 + 1, nF - 1);
    var b = (v * nF + k0) * 4, c = (v * nF + k1) * 4, q = ch.quat;
    var qa = new THREE.Quaternion(q[b], q[b + 1], q[b + 2], q[b + 3]).normalize();
    var qb = new THREE.Quaternion(q[c], q[c + 1], q[c + 2], q[c + 3]).normalize();
    return THREE.Quaternion.slerp(qa, qb, out, f - k0);
  }
  var tmpP = new THREE.Vector3(), tmpQ = new THREE.Quaternion(), tmpM = new THREE.Matrix4();
  function place(t) {
    var scale = new THREE.Vector3(T.scale, T.scale, T.scale);
    vehicleMeshes.forEach(function (mesh) {
      mesh.userData.vehicles.forEach(function (v, i) {
        mesh.setMatrixAt(i, tmpM.compose(sample(P, v, t, tmpP), attitude(v, t, tmpQ), scale));
      });
      mesh.instanceMatrix.needsUpdate = true;
    });
    var mp = markers.geometry.attributes.position;
    for (var v = 0; v < nV; v++) {
      sample(P, v, t, tmpP);
      mp.setXYZ(v, tmpP.x, tmpP.y, tmpP.z + Math.max(D.vehicles[v].radius * T.scale, 0.05));
      if (estimate) { sample(E, v, t, tmpP); estimate.geometry.attributes.position.setXYZ(v, tmpP.x, tmpP.y, tmpP.z); }
    }
    mp.needsUpdate = true;
    if (estimate) estimate.geometry.attributes.position.needsUpdate = true;
    var k = frameOf(t);
    moving.forEach(function (m, j) {
      var b = (j * nF + k) * 2;
      m.position.set(o[0] + ch.moving[b] * step, o[1] + ch.moving[b + 1] * step, 0);
    });
    flown.material.uniforms.now.value = t;
  }

  // ---- cameras ----
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  $('view').appendChild(renderer.domElement);
  var camera = new THREE.PerspectiveCamera(45, 1, Math.max(span / 5000, 0.01), span * 20);
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;
  function setCamera(kind) {
    T.camera = kind;
    // Far enough that the world's bounding sphere (its height counted half: the floor matters
    // most) fills the view, looking at a point low in the world.
    var ext = hi.clone().sub(lo), half = Math.tan(camera.fov * Math.PI / 360);
    var radius = 0.5 * Math.sqrt(ext.x * ext.x + ext.y * ext.y + 0.25 * ext.z * ext.z);
    var aim = new THREE.Vector3(centre.x, centre.y, lo.z + 0.2 * ext.z);
    if (kind === 'orbit') camera.position.copy(aim).addScaledVector(new THREE.Vector3(-0.35, -0.85, 0.8).normalize(), 0.95 * radius / half);
    if (kind === 'top') camera.position.set(centre.x, centre.y - 1e-3 * radius, hi.z + 0.55 * Math.max(ext.x / camera.aspect, ext.y) / half);
    if (kind === 'side') camera.position.set(centre.x, lo.y - 0.55 * Math.max(ext.x / camera.aspect, ext.z) / half, centre.z);
    controls.target.copy(kind === 'orbit' ? aim : centre);
    if (kind === 'follow') {
      var p = sample(P, T.follow, T.t, new THREE.Vector3()), r = Math.max(D.vehicles[T.follow].radius * T.scale, 0.2);
      controls.target.copy(p);
      camera.position.copy(p).add(new THREE.Vector3(-6 * r, -6 * r, 3.5 * r));
      lastFollow = p.clone();
    }
    controls.update();
    document.querySelectorAll('#cameras button').forEach(function (b) { b.classList.toggle('on', b.dataset.camera === kind); });
  }
  var lastFollow = null;
  function follow(t) {  // the camera keeps its offset from the vehicle as it moves
    if (T.camera !== 'follow') { lastFollow = null; return; }
    var p = sample(P, T.follow, t, new THREE.Vector3());
    if (lastFollow) { var d = p.clone().sub(lastFollow); camera.position.add(d); controls.target.add(d); }
    lastFollow = p;
    controls.update();
  }
  function resize() {
    var w = window.innerWidth, h = window.innerHeight;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }
  window.addEventListener('resize', resize);

  // ---- the state of a clicked vehicle ----
  function fmt(x, d) { return x.toFixed(d === undefined ? 3 : d); }
  function info() {
    var v = T.selected, box = $('info');
    if (v < 0) { box.hidden = true; return; }
    var k = frameOf(T.t), x = D.vehicles[v], p = sample(P, v, T.t, new THREE.Vector3());
    var vel = ch.vel, b = (v * nF + k) * 3, speed = Math.hypot(vel[b], vel[b + 1], vel[b + 2]) / 100;
    var rows = [['time', fmt(T.t, 2) + ' s'], ['position', fmt(p.x, 2) + ', ' + fmt(p.y, 2) + ', ' + fmt(p.z, 2) + ' m'],
      ['speed', fmt(speed, 2) + ' m/s'], ['error to reference', fmt(err[v][k]) + ' m']];
    if (ch.est) {
      var e = sample(E, v, T.t, new THREE.Vector3());
      rows.push(['estimate', fmt(e.x, 2) + ', ' + fmt(e.y, 2) + ', ' + fmt(e.z, 2) + ' m'], ['estimate - truth', fmt(e.distanceTo(p)) + ' m']);
    }
    if (ch.thrust && x.max_thrust > 0) {
      var th = [];
      for (var r = 0; r < 4; r++) th.push(fmt(ch.thrust[(v * nF + k) * 4 + r] / 65535 * x.max_thrust, 2));
      rows.push(['rotor thrusts', th.join(' ') + ' N'], ['rotor limit', fmt(x.max_thrust, 2) + ' N']);
    }
    rows.push(['reached goal', x.reached_goal ? 'yes' : 'no']);
    box.innerHTML = '<b></b><table>' + rows.map(function (r) { return '<tr><td></td><td class="v"></td></tr>'; }).join('') + '</table>';
    box.querySelector('b').textContent = x.name + ' (' + x.model + ')';
    box.querySelectorAll('tr').forEach(function (tr, i) { tr.cells[0].textContent = rows[i][0]; tr.cells[1].textContent = rows[i][1]; });
    box.hidden = false;
  }
  renderer.domElement.addEventListener('click', function (ev) {  // the nearest vehicle on screen
    var best = -1, bestD = 24, rect = renderer.domElement.getBoundingClientRect(), p = new THREE.Vector3();
    for (var v = 0; v < nV; v++) {
      sample(P, v, T.t, p).project(camera);
      if (p.z > 1) continue;
      var d = Math.hypot((p.x + 1) / 2 * rect.width - (ev.clientX - rect.left), (1 - p.y) / 2 * rect.height - (ev.clientY - rect.top));
      if (d < bestD) { bestD = d; best = v; }
    }
    T.selected = best;
    if (best >= 0) { T.follow = best; $('follow-vehicle').value = best; }
    info();
  });

  // Where vehicle v is drawn now, in CSS pixels from the page's top left (for checks and tests).
  function screenOf(v) {
    var p = sample(P, v, T.t, new THREE.Vector3()).project(camera), rect = renderer.domElement.getBoundingClientRect();
    return [Math.round((p.x + 1) / 2 * rect.width + rect.left), Math.round((1 - p.y) / 2 * rect.height + rect.top)];
  }

  window.CosimReplay = { screenOf: screenOf, D: D, T: T, layers: layers, setCamera: setCamera, place: place, follow: follow, info: info,
    frameOf: frameOf, renderer: renderer, scene: scene, camera: camera, controls: controls, resize: resize, worst: worst };
})();
