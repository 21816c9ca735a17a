// The replay's controls: the time slider with its markers, play/pause, step, speed, cameras,
// layers, the #t= address and the drawing loop (window.CosimReplay from viewer.js).
(function () {
  'use strict';
  var R = window.CosimReplay, D = R.D, T = R.T, $ = function (id) { return document.getElementById(id); };
  var body = document.body, slider = $('time');
  slider.max = D.duration;

  $('run-title').textContent = D.title;
  $('run-status').textContent = D.status;
  // The error legend: the run's scale (one per kind of reference, as in the video), shown while
  // a flown path is coloured by error.
  var tops = [];
  D.vehicles.forEach(function (v) { if (tops.indexOf(v.error_scale) < 0) tops.push(v.error_scale); });
  $('error-max').textContent = tops.map(function (x) { return +x.toPrecision(3) + ' m'; }).join(' / ');
  $('colour-bar').style.background = 'linear-gradient(to right, ' + R.style.error_stops.join(', ') + ')';
  function legend() {
    var byError = R.layers.error.objects[0].visible;
    $('legend').hidden = !byError;
    $('team-legend').hidden = byError || D.vehicles.length < 2;
  }
  var swatches = $('team-swatches');
  R.style.vehicles.slice(0, 32).forEach(function (c) {
    var s = document.createElement('span');
    s.style.background = c;
    swatches.appendChild(s);
  });

  function clock() {
    $('clock').textContent = T.t.toFixed(2) + ' / ' + D.duration.toFixed(2) + ' s';
    slider.value = T.t;
  }
  function seek(t) {
    T.t = Math.min(Math.max(t, 0), D.duration);
    clock();
    R.info();
  }
  function setPlaying(on) {
    T.playing = on && D.duration > 0;
    if (T.playing && T.t >= D.duration) seek(0);
    $('play').innerHTML = T.playing ? '&#10074;&#10074;' : '&#9654;';
  }

  // Markers on the timeline: closest approach, closest pair, worst error, collisions.
  D.moments.forEach(function (m) {
    var mark = document.createElement('div');
    mark.className = 'mark ' + m.kind;
    mark.style.left = (D.duration > 0 ? 100 * m.t / D.duration : 0) + '%';
    mark.title = m.label + ' at ' + m.t.toFixed(2) + ' s';
    mark.addEventListener('click', function () {
      setPlaying(false);
      seek(m.t);
      if (m.vehicle >= 0) { T.selected = T.follow = m.vehicle; $('follow-vehicle').value = m.vehicle; R.highlightVehicle(m.vehicle); R.info(); }
    });
    $('marks').appendChild(mark);
  });

  slider.addEventListener('input', function () { setPlaying(false); seek(parseFloat(slider.value)); });
  $('play').addEventListener('click', function () { setPlaying(!T.playing); });
  var frame = 1 / D.rate;
  $('step-back').addEventListener('click', function () { setPlaying(false); seek(Math.round(T.t / frame - 1) * frame); });
  $('step-forward').addEventListener('click', function () { setPlaying(false); seek(Math.round(T.t / frame + 1) * frame); });
  $('speed').addEventListener('change', function () { T.speed = parseFloat(this.value); });
  document.addEventListener('keydown', function (e) {
    if (e.target.tagName === 'SELECT') return;
    if (e.key === ' ') { setPlaying(!T.playing); e.preventDefault(); }
    if (e.key === ',') $('step-back').click();
    if (e.key === '.') $('step-forward').click();
  });

  // Cameras and the vehicle to follow.
  document.querySelectorAll('#cameras button').forEach(function (b) {
    b.addEventListener('click', function () { R.setCamera(b.dataset.camera); });
  });
  var pick = $('follow-vehicle');
  D.vehicles.forEach(function (v, i) {
    var opt = document.createElement('option');
    opt.value = i;
    opt.textContent = v.name;
    pick.appendChild(opt);
  });
  pick.addEventListener('change', function () {
    T.follow = T.selected = parseInt(pick.value, 10);
    R.highlightVehicle(T.selected);
    R.info();
    R.setCamera('follow');
  });
  // Vehicles smaller than a few pixels in the overview start enlarged (the choice says so).
  var span = Math.max(D.bounds.max[0] - D.bounds.min[0], D.bounds.max[1] - D.bounds.min[1]);
  var smallest = Math.min.apply(null, D.vehicles.map(function (v) { return v.radius || 1; }).concat([1e9]));
  var scaleBox = $('vehicle-scale');
  if (smallest * 80 < span) scaleBox.value = smallest * 800 < span ? '10' : '3';
  T.scale = parseFloat(scaleBox.value);
  scaleBox.addEventListener('change', function () { T.scale = parseFloat(this.value); });

  // Layer switches.
  Object.keys(R.layers).forEach(function (name) {
    var l = R.layers[name], label = document.createElement('label'), box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = l.on;
    box.addEventListener('change', function () { l.objects.forEach(function (x) { x.visible = box.checked; }); legend(); });
    label.appendChild(box);
    label.appendChild(document.createTextNode(' ' + l.label));
    $('layers').appendChild(label);
  });

  // viewer.html#t=12.5: paused at 12.5 s; also &camera=orbit|follow|top|side and &vehicle=NAME.
  function fromAddress() {
    var arg = function (key) {
      var m = new RegExp('(?:^|[#&])' + key + '=([^&]*)').exec(window.location.hash);
      if (!m) return null;
      // A malformed escape (#vehicle=%ZZ) throws URIError: such a part is ignored, not fatal.
      try { return decodeURIComponent(m[1]); } catch (e) { return null; }
    };
    var named = D.vehicles.map(function (v) { return v.name; }).indexOf(arg('vehicle'));
    if (named >= 0) { T.follow = T.selected = named; pick.value = named; R.highlightVehicle(named); }
    var t = parseFloat(arg('t'));
    if (isFinite(t)) { setPlaying(false); seek(t); }
    var cam = arg('camera');
    if (['orbit', 'follow', 'top', 'side'].indexOf(cam) >= 0) R.setCamera(cam);
    R.info();
    return isFinite(t);
  }
  window.addEventListener('hashchange', fromAddress);

  var last = null, drawn = false;
  function draw(now) {
    if (T.playing && last !== null) {
      var t = T.t + (now - last) / 1000 * T.speed;
      if (t >= D.duration) { t = D.duration; setPlaying(false); }
      seek(t);
    }
    last = now;
    R.place(T.t);
    R.follow(T.t);
    R.renderer.render(R.scene, R.camera);
    if (!drawn) {
      drawn = true;
      var fetched = window.performance && performance.getEntriesByType ? performance.getEntriesByType('resource').length : 0;
      body.setAttribute('data-t', T.t.toFixed(3));
      body.setAttribute('data-resources', String(fetched));
      if (D.vehicles.length) body.setAttribute('data-vehicle0', R.screenOf(0).join(' '));
      if (body.getAttribute('data-viewer') === 'loading') body.setAttribute('data-viewer', 'ready');
    }
    window.requestAnimationFrame(draw);
  }

  legend();
  R.resize();
  R.setCamera('orbit');
  if (!fromAddress()) seek(0);
  setPlaying(false);
  R.place(T.t);
  draw(performance.now());
})();
