// The replay's 3D objects, built from the run's data (render/viewer_data.h): the floor and its
// grid, the static shapes merged into one mesh, one instanced mesh per vehicle model, the paths
// as merged sets of wide lines. Classic script: defines window.CosimScene for viewer.js.
(function () {
  'use strict';

  // Unit solids with their axis along z (three.js builds cylinders along y).
  var toZ = new THREE.Matrix4().makeRotationX(Math.PI / 2);
  var unit = {
    box: new THREE.BoxBufferGeometry(1, 1, 1).toNonIndexed(),
    cylinder: new THREE.CylinderBufferGeometry(0.5, 0.5, 1, 28).applyMatrix(toZ).toNonIndexed(),
    sphere: new THREE.SphereBufferGeometry(0.5, 24, 14).toNonIndexed()
  };

  // Collects transformed copies of unit solids, with a colour per vertex, into one geometry.
  function Merger() {
    this.pos = [];
    this.nrm = [];
    this.col = [];
  }
  Merger.prototype.add = function (geometry, matrix, colour) {
    var p = geometry.attributes.position, n = geometry.attributes.normal;
    var normalMatrix = new THREE.Matrix3().getNormalMatrix(matrix);
    var v = new THREE.Vector3();
    for (var i = 0; i < p.count; i++) {
      v.fromBufferAttribute(p, i).applyMatrix4(matrix);
      this.pos.push(v.x, v.y, v.z);
      v.fromBufferAttribute(n, i).applyMatrix3(normalMatrix).normalize();
      this.nrm.push(v.x, v.y, v.z);
      this.col.push(colour.r, colour.g, colour.b);
    }
  };
  Merger.prototype.geometry = function () {
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(this.pos, 3));
    g.setAttribute('normal', new THREE.Float32BufferAttribute(this.nrm, 3));
    g.setAttribute('color', new THREE.Float32BufferAttribute(this.col, 3));
    return g;
  };

  // One shape ([kind, x, y, z, qx, qy, qz, qw, sx, sy, sz, r, g, b, a]) into the merger, placed by
  // `frame` (a Matrix4) and coloured `override` or its own colour.
  function addShape(merger, s, frame, override) {
    var colour = override || new THREE.Color(s[11], s[12], s[13]);
    var q = new THREE.Quaternion(s[4], s[5], s[6], s[7]);
    var at = new THREE.Vector3(s[1], s[2], s[3]);
    var place = function (offset, scale, solid) {
      var m = new THREE.Matrix4().compose(at.clone().add(offset.applyQuaternion(q)), q, scale);
      merger.add(solid, frame.clone().multiply(m), colour);
    };
    var d = new THREE.Vector3(s[8], s[9], s[10]);
    if (s[0] === 'box') place(new THREE.Vector3(), d, unit.box);
    else if (s[0] === 'cylinder') place(new THREE.Vector3(), d, unit.cylinder);
    else if (s[0] === 'capsule') {  // a cylinder with a half sphere on each end
      place(new THREE.Vector3(), d, unit.cylinder);
      var cap = new THREE.Vector3(d.x, d.x, d.x);
      place(new THREE.Vector3(0, 0, d.z / 2), cap, unit.sphere);
      place(new THREE.Vector3(0, 0, -d.z / 2), cap.clone(), unit.sphere);
    } else place(new THREE.Vector3(), d, unit.sphere);  // sphere, ellipsoid
  }

  function shapesGeometry(shapes, override) {
    var merger = new Merger();
    var identity = new THREE.Matrix4();
    shapes.forEach(function (s) { addShape(merger, s, identity, override); });
    return merger.geometry();
  }

  // The floor: a light plane over the bounds, a 1 m grid (5 m lines darker; coarser in big
  // worlds) and the bounds' outline.
  function floor(bounds) {
    var lo = bounds.min, hi = bounds.max, group = new THREE.Group();
    var w = hi[0] - lo[0], h = hi[1] - lo[1];
    var plane = new THREE.Mesh(new THREE.PlaneBufferGeometry(w, h),
      new THREE.MeshLambertMaterial({ color: 0xf3f1ec }));
    plane.position.set(lo[0] + w / 2, lo[1] + h / 2, lo[2] - 0.002);
    group.add(plane);
    var cell = Math.max(w, h) > 200 ? 10 : 1;
    var fine = [], bold = [];
    for (var x = Math.ceil(lo[0] / cell) * cell; x <= hi[0] + 1e-9; x += cell)
      (Math.round(x / cell) % 5 === 0 ? bold : fine).push(x, lo[1], lo[2], x, hi[1], lo[2]);
    for (var y = Math.ceil(lo[1] / cell) * cell; y <= hi[1] + 1e-9; y += cell)
      (Math.round(y / cell) % 5 === 0 ? bold : fine).push(lo[0], y, lo[2], hi[0], y, lo[2]);
    [[fine, 0xd3d0c8], [bold, 0xaaa69c]].forEach(function (set) {
      var g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute(set[0], 3));
      group.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: set[1] })));
    });
    var box = new THREE.Box3(new THREE.Vector3().fromArray(lo), new THREE.Vector3().fromArray(hi));
    var outline = new THREE.Box3Helper(box, 0x8d96a3);
    outline.material.transparent = true;
    outline.material.opacity = 0.5;
    group.add(outline);
    return group;
  }

  function obstacles(shapes) {
    var mesh = new THREE.Mesh(shapesGeometry(shapes),
      new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors }));
    return mesh;
  }

  // One instanced mesh per model: instance i is the i-th vehicle of that model.
  function vehicleMeshes(data) {
    var byModel = {};
    data.vehicles.forEach(function (v, i) {
      (byModel[v.model] = byModel[v.model] || []).push(i);
    });
    var meshes = [];
    Object.keys(byModel).forEach(function (model) {
      var shapes = data.models[model] || [['sphere', 0, 0, 0, 0, 0, 0, 1, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 1]];
      var geometry = shapesGeometry(shapes);
      var material = new THREE.MeshPhongMaterial({ vertexColors: THREE.VertexColors, shininess: 40 });
      var mesh = new THREE.InstancedMesh(geometry, material, byModel[model].length);
      mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
      mesh.frustumCulled = false;
      mesh.userData.vehicles = byModel[model];
      meshes.push(mesh);
    });
    return meshes;
  }

  // Lines `px` pixels wide whatever the distance (WebGL draws its own lines 1 px wide): three.js's
  // LineSegments2, one instance per segment. pos: x y z x y z per segment; col: r g b r g b.
  function wideSegments(pos, col, px, dashed) {
    var g = new THREE.LineSegmentsGeometry();
    g.setPositions(pos.length ? pos : [0, 0, 0, 0, 0, 0]);
    g.setColors(col.length ? col : [0, 0, 0, 0, 0, 0]);
    var material = new THREE.LineMaterial({ linewidth: px, vertexColors: THREE.VertexColors, dashed: !!dashed,
      dashSize: 0.25, gapSize: 0.18 });
    if (dashed) material.defines.USE_DASH = '';
    var line = new THREE.LineSegments2(g, material);
    if (dashed) line.computeLineDistances();
    line.frustumCulled = false;
    if (!pos.length) g.maxInstancedCount = 0;
    return line;
  }

  // Wide segments through each list of points (Float32Array x, y, z, ...), merged into one set.
  function polylines(lists, colours, px, dashed) {
    var pos = [], col = [];
    lists.forEach(function (pts, i) {
      var c = colours[i];
      for (var k = 0; k + 5 < pts.length; k += 3) {
        pos.push(pts[k], pts[k + 1], pts[k + 2], pts[k + 3], pts[k + 4], pts[k + 5]);
        col.push(c.r, c.g, c.b, c.r, c.g, c.b);
      }
    });
    return wideSegments(pos, col, px, dashed);
  }

  // The flown paths as one set of wide segments, frame by frame (all vehicles' segments of
  // frame 1, then of frame 2, ...), so that drawing the first k * vehicles of them shows each
  // path up to frame k: the path grows behind each vehicle. colour(v, k): the colour of vehicle
  // v at frame k. showUpTo(k) sets how far.
  function flownPaths(positions, frames, colour, px) {
    var pos = [], col = [], nV = positions.length;
    for (var k = 0; k + 1 < frames; k++)
      for (var v = 0; v < nV; v++) {
        var pts = positions[v], a = colour(v, k), b = colour(v, k + 1);
        pos.push(pts[3 * k], pts[3 * k + 1], pts[3 * k + 2], pts[3 * k + 3], pts[3 * k + 4], pts[3 * k + 5]);
        col.push(a.r, a.g, a.b, b.r, b.g, b.b);
      }
    var line = wideSegments(pos, col, px, false);
    line.showUpTo = function (k) { line.geometry.maxInstancedCount = pos.length ? Math.max(0, k) * nV : 0; };
    return line;
  }

  // A round dot (or, shape 'square', a hollow square) of `px` pixels whatever the distance, one
  // per point: vehicles too small to see, starts, goals.
  function dots(count, px, colours, shape) {
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(new Float32Array(3 * count), 3));
    var col = [];
    for (var i = 0; i < count; i++) col.push(colours[i].r, colours[i].g, colours[i].b);
    g.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
    var canvas = document.createElement('canvas');
    canvas.width = canvas.height = 64;
    var ctx = canvas.getContext('2d');
    if (shape === 'square') {  // the figures' goal: an open square, a start shows inside it
      ctx.lineWidth = 12;
      ctx.strokeStyle = '#ffffff';
      ctx.strokeRect(10, 10, 44, 44);
    } else {
      ctx.beginPath();
      ctx.arc(32, 32, 26, 0, 2 * Math.PI);
      ctx.fillStyle = '#ffffff';
      ctx.fill();
      ctx.lineWidth = 8;
      ctx.strokeStyle = 'rgba(20, 20, 30, 0.9)';
      ctx.stroke();
    }
    var material = new THREE.PointsMaterial({ size: px, sizeAttenuation: false,
      vertexColors: THREE.VertexColors, map: new THREE.CanvasTexture(canvas),
      transparent: true, alphaTest: 0.3, depthTest: false });
    var points = new THREE.Points(g, material);
    points.frustumCulled = false;
    points.renderOrder = 2;
    return points;
  }

  window.CosimScene = {
    floor: floor, obstacles: obstacles, shapesGeometry: shapesGeometry,
    vehicleMeshes: vehicleMeshes, wideSegments: wideSegments, polylines: polylines,
    flownPaths: flownPaths, dots: dots
  };
})();
