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
    err: channel('err', nV), quat: channel('quat', nV), vel: channel('vel', nV), thrust: channel('thrust', nV),
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
  var frameTimes = [];
  for (var k = 0; k < nF; k++) frameTimes.push(Math.min(k / rate, D.duration));
  // The colours and the error scale are the run's visual language (render/overlay_palette.h),
  // the same as its video's and figures'.
  var style = D.style, colour = function (hex) { return new THREE.Color(hex); };
  var stops = style.error_stops.map(colour);
  function errorOf(v, k) { return ch.err[v * nF + k] / 1000; }  // m
  function errorColour(v, k) {
    var x = Math.min(Math.max(errorOf(v, k) / D.vehicles[v].error_scale, 0), 1) * (stops.length - 1);
    var j = Math.min(Math.floor(x), stops.length - 2);
    return stops[j].clone().lerp(stops[j + 1], x - j);
  }
  var vColour = D.vehicles.map(function (_, i) { return colour(style.vehicles[i]); });
  var team = nV > 1;

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
  var pathColour = team ? vColour : [colour(style.planned)];
  var wide = [];  // the wide lines, whose width in pixels needs the canvas size
  function wideLayer(name, label, line, on) { wide.push(line); layer(name, label, line, on); return line; }
  // The planned path below the flown one: a 5 px band for one vehicle (the flown path, 3 px,
  // shows inside it), 3 px per member of a team.
  wideLayer('planned', 'planned path', S.polylines(planned, pathColour, team ? 3 : 5), !team || D.team_plans);
  wideLayer('reference', 'reference (dashed)', S.polylines(R, R.map(function () { return colour(style.reference); }), 2, true),
    !team || D.team_plans);
  // The flown paths: a team's in each member's colour (error on demand), one vehicle's by error.
  var own = team ? vColour : [colour(style.flown)];
  var flown = wideLayer('flown', team ? 'flown paths (one colour each)' : 'flown path (plain)',
    S.flownPaths(P, nF, function (v) { return own[v]; }, 3), team && !D.team_error);
  var flownError = wideLayer('error', team ? 'flown paths coloured by error' : 'flown path coloured by error',
    S.flownPaths(P, nF, errorColour, 3), !team || D.team_error);
  flownError.renderOrder = 1;
  // The picked vehicle: its flown path drawn wider over the others, and a ring under its dot.
  var highlight = null, ring = S.dots(1, nV > 30 ? 20 : 24, [new THREE.Color(0x111111)]);
  ring.renderOrder = 1;
  ring.visible = false;
  scene.add(ring);
  function highlightVehicle(v) {
    if (highlight) { scene.remove(highlight); highlight.geometry.dispose(); highlight = null; }
    ring.visible = v >= 0;
    if (v < 0) return;
    highlight = S.flownPaths([P[v]], nF, function () { return vColour[v] || own[0]; }, 7);
    highlight.renderOrder = 2;
    highlight.material.resolution.copy(wide[0].material.resolution);
    scene.add(highlight);
  }
  var vehicleMeshes = S.vehicleMeshes(D);
  layer('vehicles', 'vehicles', vehicleMeshes, true);
  var markers = S.dots(nV, nV > 30 ? 7 : 10, team ? vColour : [colour(style.flown)]);
  layer('markers', 'vehicle dots', markers, true);
  // Goals as open squares, starts as small dots: where one member's start is another's goal,
  // the dot shows inside the square.
  var goals = S.dots(nV, nV > 30 ? 9 : 14, team ? vColour : [colour(style.goal)], 'square');
  D.vehicles.forEach(function (x, i) { goals.geometry.attributes.position.setXYZ(i, x.goal[0], x.goal[1], x.goal[2]); });
  layer('goals', 'goals (squares)', goals, nV <= 50);
  var starts = S.dots(nV, nV > 30 ? 5 : 8, team ? vColour : [colour(style.start)]);
  D.vehicles.forEach(function (x, i) { starts.geometry.attributes.position.setXYZ(i, P[i][0], P[i][1], P[i][2]); });
  layer('starts', 'starts (dots)', starts, nV <= 50);
  var estimate = ch.est ? S.dots(nV, 6, D.vehicles.map(function () { return colour(style.estimate); })) : null;
  if (estimate) layer('estimate', 'estimate (sky blue)', estimate, false);
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
    // A path reaches the frame at or before t (the vehicle's dot sits at its end).
    var shown = Math.min(Math.floor(t * rate + 1e-6), nF - 1);
    flown.showUpTo(shown);
    flownError.showUpTo(shown);
    if (highlight) highlight.showUpTo(shown);
    if (T.selected >= 0) {
      sample(P, T.selected, t, tmpP);
      ring.geometry.attributes.position.setXYZ(0, tmpP.x, tmpP.y, tmpP.z + Math.max(D.vehicles[T.selected].radius * T.scale, 0.05));
      ring.geometry.attributes.position.needsUpdate = true;
    }
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
    wide.concat(highlight ? [highlight] : []).forEach(function (l) { l.material.resolution.set(w, h); });
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
      ['speed', fmt(speed, 2) + ' m/s'], ['tracking error', fmt(errorOf(v, k)) + ' m']];
    if (ch.est) {
      var e = sample(E, v, T.t, new THREE.Vector3());
      rows.push(['estimate', fmt(e.x, 2) + ', ' + fmt(e.y, 2) + ', ' + fmt(e.z, 2) + ' m'], ['estimate - truth', fmt(e.distanceTo(p)) + ' m']);
    }
    if (ch.thrust && x.max_thrust > 0) {
      var th = [];
      for (var r = 0; r < 4; r++) th.push(fmt(ch.thrust[(v * nF + k) * 4 + r] / 65535 * x.max_thrust, 2));
      rows.push(['rotor thrusts', th.join(' ') + ' N'], ['rotor limit', fmt(x.max_thrust, 2) + ' N']);
    }
    // As of the time shown: a vehicle that arrives later has not reached its goal yet.
    var arrived = x.arrival_time >= 0 && T.t >= x.arrival_time - 1e-9;
    rows.push(['reached goal', arrived ? 'yes, at ' + fmt(x.arrival_time, 2) + ' s'
      : x.arrival_time >= 0 ? 'not yet (at ' + fmt(x.arrival_time, 2) + ' s)' : 'no']);
    box.innerHTML = '<b></b><table>' + rows.map(function (r) { return '<tr><td></td><td class="v"></td></tr>'; }).join('') + '</table>';
    box.querySelector('b').textContent = x.name + ' (' + x.model + (x.controller ? ', ' + x.controller + ' controller' : '') + ')';
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
    highlightVehicle(best);
    info();
  });

  // Where vehicle v is drawn now, in CSS pixels from the page's top left (for checks and tests).
  function screenOf(v) {
    var p = sample(P, v, T.t, new THREE.Vector3()).project(camera), rect = renderer.domElement.getBoundingClientRect();
    return [Math.round((p.x + 1) / 2 * rect.width + rect.left), Math.round((1 - p.y) / 2 * rect.height + rect.top)];
  }

  window.CosimReplay = { screenOf: screenOf, D: D, T: T, layers: layers, setCamera: setCamera, place: place, follow: follow, info: info,
    frameOf: frameOf, renderer: renderer, scene: scene, camera: camera, controls: controls, resize: resize,
    highlightVehicle: highlightVehicle, style: style };
})();
