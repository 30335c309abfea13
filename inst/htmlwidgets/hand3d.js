/* handmotion's 3D hand (hand_3d() in R/hand-3d.R): a solid hand per
 * recording played back at the recording's own rate, with an orbit camera,
 * play/pause, a time slider and a speed choice.
 *
 * The hand's solid shape is not decided here: R sends its description
 * (hand_geometry_json() in R/hand-geometry.R, the shape every picture of the
 * package draws), and joint positions already posed (forward kinematics is
 * done once, in R), so this file only places meshes. Data (x):
 *   joints, parent (0-based, -1 for the root), geometry: {from, to (0-based
 *   ends of each segment: joints, then extra points), r_from, r_to (radius
 *   at each end, mm), fill (#rrggbb), draw (false: inside the palm), skin,
 *   points: {n, weights (row-major n x joints: affine combinations of the
 *   joints)}, palm: {n, weights (n x joints), thickness, normal (4 outline
 *   indices a, b, c, d: normal = (b - a) x (d - c)), colour}},
 *   marker_radius, camera: {towards, up} (the first view: the direction
 *   towards the viewer and the screen's up, in skeleton axes), rate, speed, autoplay, loop, background, layout ("side"
 *   or "overlay"), recordings: [{label, colour, n, pos (frame-major n x
 *   joints x 3), outside (n x joints 0/1 or null), markers (n x m x 3 or
 *   null), offset [x, y, z], opacity}].
 *
 * For tests in a headless browser the container carries data-ready="1"
 * once drawn, data-frame (the first recording's frame on screen) and
 * data-meshes (the number of segment meshes drawn) and data-renders (the
 * number of frames rendered so far: it stops growing when the widget rests),
 * and any script error is written to document.body's data-js-error. */
(function () {
  "use strict";

  window.addEventListener("error", function (e) {
    if (!document.body) return;
    var where = e.filename ? " @ " + e.filename + ":" + e.lineno : "";
    var seen = document.body.getAttribute("data-js-error");
    document.body.setAttribute("data-js-error", (seen ? seen + " | " : "") + String(e.message || e) + where);
  });

  var UP = new THREE.Vector3(0, 1, 0);
  var LIMIT_COLOUR = 0xe31a1c;
  var MARKER_COLOUR = 0x202020;

  function frameTime(rec, rate, t) {
    // the frame on screen at time t (s): recordings that have ended hold their last pose
    var f = Math.floor(t * rate + 1e-9);
    return f < 0 ? 0 : (f >= rec.n ? rec.n - 1 : f);
  }

  // affine combinations (row-major rows x J weights) of frame f's joints, into out (rows x 3)
  function combine(weights, rows, J, pos, o, out) {
    for (var v = 0; v < rows; v++) {
      var px = 0, py = 0, pz = 0;
      for (var j = 0; j < J; j++) {
        var w = weights[v * J + j];
        if (w === 0) continue;
        px += w * pos[o + 3 * j]; py += w * pos[o + 3 * j + 1]; pz += w * pos[o + 3 * j + 2];
      }
      out[3 * v] = px; out[3 * v + 1] = py; out[3 * v + 2] = pz;
    }
  }

  function buildHand(scene, x, rec) {
    var J = x.joints.length, geo = x.geometry;
    var K = geo.points ? geo.points.n : 0;
    var group = new THREE.Group();
    var opacity = rec.opacity === undefined ? 1 : rec.opacity;
    var material = function (colour) {
      return new THREE.MeshStandardMaterial({
        color: colour, roughness: 0.62, metalness: 0.0,
        transparent: opacity < 1, opacity: opacity
      });
    };
    // segments: a truncated cone (unit height, scaled to the bone's length)
    // capped by a sphere at each end, sized by the description's radii
    var segs = [], spheres = [];
    for (var s = 0; s < geo.from.length; s++) {
      if (!geo.draw[s]) continue;
      var colour = rec.colour || geo.fill[s];
      var r0 = geo.r_from[s], r1 = geo.r_to[s];
      var cone = new THREE.Mesh(new THREE.CylinderGeometry(r1, r0, 1, 24, 1, true), material(colour));
      group.add(cone);
      segs.push({ mesh: cone, a: geo.from[s], b: geo.to[s] });
      [[geo.from[s], r0], [geo.to[s], r1]].forEach(function (end) {
        var mat = material(colour);
        var ball = new THREE.Mesh(new THREE.SphereGeometry(end[1], 24, 16), mat);
        group.add(ball);
        spheres.push({ mesh: ball, at: end[0], mat: mat, base: new THREE.Color(colour) });
      });
    }
    // the palm: a slab along its normal; top and bottom fans from the centre
    // (vertices 0..P and P+1..2P+1) and its sides, four vertices each of
    // their own so that their edges stay sharp
    var palm = null, P = geo.palm ? geo.palm.n : 0, palmPts = new Float64Array(3 * Math.max(P, 1));
    if (P >= 3) {
      var g = new THREE.BufferGeometry();
      g.setAttribute("position", new THREE.BufferAttribute(new Float32Array((6 * P + 2) * 3), 3));
      var idx = [], S0 = 2 * P + 2;
      for (var k = 0; k < P; k++) {
        var k2 = (k + 1) % P, q0 = S0 + 4 * k;
        idx.push(P, k, k2);                              // top
        idx.push(2 * P + 1, P + 1 + k2, P + 1 + k);      // bottom
        idx.push(q0, q0 + 2, q0 + 1, q0, q0 + 3, q0 + 2); // side k: top k, top k2, bottom k2, bottom k
      }
      g.setIndex(idx);
      palm = new THREE.Mesh(g, new THREE.MeshStandardMaterial({
        color: rec.colour || geo.palm.colour, roughness: 0.62, side: THREE.DoubleSide,
        transparent: opacity < 1, opacity: opacity
      }));
      group.add(palm);
    }
    var markers = [];
    var M = rec.markers ? rec.markers.length / (rec.n * 3) : 0;
    for (var m = 0; m < M; m++) {
      // markers sit on the bones' axes, inside the solid fingers: drawn over them
      var mk = new THREE.Mesh(new THREE.SphereGeometry(x.marker_radius, 14, 10),
                              new THREE.MeshBasicMaterial({ color: MARKER_COLOUR, depthTest: false,
                                                            transparent: true, opacity: 0.85 }));
      mk.renderOrder = 10;
      group.add(mk);
      markers.push(mk);
    }
    group.position.set(rec.offset[0], rec.offset[1], rec.offset[2]);
    scene.add(group);
    var pts = new Float64Array(3 * (J + K)), extra = new Float64Array(3 * Math.max(K, 1));
    var pa = new THREE.Vector3(), pb = new THREE.Vector3(), dir = new THREE.Vector3();
    var ab = new THREE.Vector3(), cd = new THREE.Vector3(), nrm = new THREE.Vector3();

    function pose(f) {
      var o = f * J * 3, pos = rec.pos;
      for (var i = 0; i < 3 * J; i++) pts[i] = pos[o + i];
      if (K > 0) {
        combine(geo.points.weights, K, J, pos, o, extra);
        for (var e = 0; e < 3 * K; e++) pts[3 * J + e] = extra[e];
      }
      for (var b = 0; b < segs.length; b++) {
        var seg = segs[b];
        pa.set(pts[3 * seg.a], pts[3 * seg.a + 1], pts[3 * seg.a + 2]);
        pb.set(pts[3 * seg.b], pts[3 * seg.b + 1], pts[3 * seg.b + 2]);
        dir.subVectors(pb, pa);
        var len = dir.length();
        seg.mesh.position.addVectors(pa, pb).multiplyScalar(0.5);
        if (len > 1e-9) seg.mesh.quaternion.setFromUnitVectors(UP, dir.divideScalar(len));
        seg.mesh.scale.set(1, Math.max(len, 1e-6), 1);
      }
      for (var q = 0; q < spheres.length; q++) {
        var sp = spheres[q], at = sp.at;
        sp.mesh.position.set(pts[3 * at], pts[3 * at + 1], pts[3 * at + 2]);
        var out = at < J && rec.outside && rec.outside[f * J + at] === 1;
        sp.mat.color.copy(out ? new THREE.Color(LIMIT_COLOUR) : sp.base);
      }
      if (palm) {
        combine(geo.palm.weights, P, J, pos, o, palmPts);
        var nv = geo.palm.normal;
        ab.set(palmPts[3 * nv[1]] - palmPts[3 * nv[0]], palmPts[3 * nv[1] + 1] - palmPts[3 * nv[0] + 1],
               palmPts[3 * nv[1] + 2] - palmPts[3 * nv[0] + 2]);
        cd.set(palmPts[3 * nv[3]] - palmPts[3 * nv[2]], palmPts[3 * nv[3] + 1] - palmPts[3 * nv[2] + 1],
               palmPts[3 * nv[3] + 2] - palmPts[3 * nv[2] + 2]);
        nrm.crossVectors(ab, cd).normalize().multiplyScalar(geo.palm.thickness / 2);
        var arr = palm.geometry.attributes.position.array, cx = 0, cy = 0, cz = 0;
        for (var v = 0; v < P; v++) {
          var X = palmPts[3 * v], Y = palmPts[3 * v + 1], Z = palmPts[3 * v + 2];
          arr[3 * v] = X + nrm.x; arr[3 * v + 1] = Y + nrm.y; arr[3 * v + 2] = Z + nrm.z;
          var w = 3 * (P + 1 + v);
          arr[w] = X - nrm.x; arr[w + 1] = Y - nrm.y; arr[w + 2] = Z - nrm.z;
          cx += X; cy += Y; cz += Z;
        }
        cx /= P; cy /= P; cz /= P;
        arr[3 * P] = cx + nrm.x; arr[3 * P + 1] = cy + nrm.y; arr[3 * P + 2] = cz + nrm.z;
        var c2 = 3 * (2 * P + 1);
        arr[c2] = cx - nrm.x; arr[c2 + 1] = cy - nrm.y; arr[c2 + 2] = cz - nrm.z;
        for (var u = 0; u < P; u++) {
          var u2 = (u + 1) % P, corner = [u, u2, P + 1 + u2, P + 1 + u];
          for (var cc = 0; cc < 4; cc++) {
            var to = 3 * (2 * P + 2 + 4 * u + cc), from = 3 * corner[cc];
            arr[to] = arr[from]; arr[to + 1] = arr[from + 1]; arr[to + 2] = arr[from + 2];
          }
        }
        palm.geometry.attributes.position.needsUpdate = true;
        palm.geometry.computeVertexNormals();
        palm.geometry.computeBoundingSphere();
      }
      for (var mm = 0; mm < markers.length; mm++) {
        var r = (f * markers.length + mm) * 3;
        markers[mm].position.set(rec.markers[r], rec.markers[r + 1], rec.markers[r + 2]);
      }
    }
    return { pose: pose, group: group, segments: segs.length };
  }

  // the box around a hand over its whole recording: joints and extra points (the forearm)
  function handBox(x, rec) {
    var box = new THREE.Box3(), v = new THREE.Vector3(), J = x.joints.length;
    var K = x.geometry.points ? x.geometry.points.n : 0, extra = new Float64Array(3 * Math.max(K, 1));
    var add = function (a, i) {
      box.expandByPoint(v.set(a[i] + rec.offset[0], a[i + 1] + rec.offset[1], a[i + 2] + rec.offset[2]));
    };
    for (var i = 0; i < rec.pos.length; i += 3) add(rec.pos, i);
    for (var f = 0; f < rec.n && K > 0; f++) {
      combine(x.geometry.points.weights, K, J, rec.pos, f * J * 3, extra);
      for (var e = 0; e < 3 * K; e += 3) add(extra, e);
    }
    return box;
  }

  function bounds(x) {
    var box = new THREE.Box3();
    x.recordings.forEach(function (rec) { box.union(handBox(x, rec)); });
    return box;
  }

  function controlBar(el) {
    var bar = document.createElement("div");
    bar.className = "hand3d-bar";
    bar.style.cssText = "position:absolute;left:0;right:0;bottom:0;display:flex;gap:8px;align-items:center;" +
      "padding:4px 8px;font:12px sans-serif;background:rgba(255,255,255,0.85)";
    var play = document.createElement("button");
    play.className = "hand3d-play";
    var slider = document.createElement("input");
    slider.type = "range"; slider.min = 0; slider.max = 1000; slider.value = 0;
    slider.style.flex = "1";
    slider.setAttribute("aria-label", "time");
    var speed = document.createElement("select");
    speed.setAttribute("aria-label", "playback speed");
    [0.1, 0.25, 0.5, 1, 2].forEach(function (s) {
      var o = document.createElement("option");
      o.value = s; o.textContent = s + "x";
      speed.appendChild(o);
    });
    var label = document.createElement("span");
    label.style.cssText = "min-width:92px;text-align:right;font-variant-numeric:tabular-nums";
    bar.appendChild(play); bar.appendChild(slider); bar.appendChild(speed); bar.appendChild(label);
    el.appendChild(bar);
    return { bar: bar, play: play, slider: slider, speed: speed, label: label };
  }

  function legend(el, x) {
    var div = document.createElement("div");
    div.className = "hand3d-legend";
    div.style.cssText = "position:absolute;left:8px;top:6px;font:13px sans-serif;color:#222;" +
      "background:rgba(255,255,255,0.7);padding:2px 6px;border-radius:3px";
    var esc = function (t) { return t.replace(/&/g, "&amp;").replace(/</g, "&lt;"); };
    if (x.layout === "side" && x.recordings.length > 1) {
      // each hand is named underneath (handLabels); this says what the view is
      div.innerHTML = "<div>" + x.recordings.length + " hands, one camera: drag to turn them together</div>";
    } else {
      // every entry has its swatch: a hand in its own colour shows that
      // colour, a hand in the description's colours (skin, or one colour per
      // finger) those colours
      var own = [];
      x.geometry.fill.forEach(function (f, s) { if (x.geometry.draw[s] && own.indexOf(f) < 0) own.push(f); });
      var ownSwatch = own.length === 1 ? own[0] : "linear-gradient(90deg," + own.join(",") + ")";
      div.innerHTML = x.recordings.map(function (r) {
        var sw = '<span style="display:inline-block;width:10px;height:10px;margin-right:4px;border:1px solid #888;' +
          'vertical-align:-1px;background:' + (r.colour || ownSwatch) + (r.opacity < 1 ? ";opacity:" + r.opacity : "") +
          '"></span>';
        return "<div>" + sw + esc(r.label) + "</div>";
      }).join("");
    }
    el.appendChild(div);
  }

  // Side by side: a label under each hand, kept there as the camera turns
  // (the corners of the hand's box over the whole recording, projected).
  function handLabels(el, x) {
    if (!(x.layout === "side" && x.recordings.length > 1)) return null;
    return x.recordings.map(function (rec) {
      var div = document.createElement("div");
      div.className = "hand3d-label";
      div.style.cssText = "position:absolute;font:13px sans-serif;color:#222;" +
        "text-align:center;white-space:pre-line;overflow-wrap:break-word;box-sizing:border-box;" +
        "background:rgba(255,255,255,0.6);padding:0 4px;border-radius:3px";
      // on two lines ("recorded: id" / "(type)"), as in the videos: side by side, one line each runs into the next
      div.textContent = rec.label.replace(" (", "\n(");
      el.appendChild(div);
      return { div: div, box: handBox(x, rec) };
    });
  }

  // Each label has the slot between the midpoints to its neighbours' hands
  // (the widget's edge beyond the first and the last), wraps to the slot's
  // width between words, and is centred under its hand as far as its slot
  // allows: labels of hands side by side never run into each other, none
  // runs off the widget's edges or under the control bar, and a label near
  // an edge takes the room there is beside its hand instead of shrinking to
  // a word cut in pieces (a centred label could only be twice as wide as
  // its hand's distance to the edge).
  function placeLabels(labels, camera, w, h) {
    if (!labels) return;
    // (the camera's matrices as they will be drawn: render() updates them,
    // but the labels are placed before it, and a widget at rest draws only
    // once, so without this its labels stood where the camera was before
    // it was placed, a hand's width to the side)
    camera.updateMatrixWorld();
    var v = new THREE.Vector3();
    labels.forEach(function (l) {
      var lo = -Infinity, xs = 0;
      for (var c = 0; c < 8; c++) {
        v.set(c & 1 ? l.box.max.x : l.box.min.x, c & 2 ? l.box.max.y : l.box.min.y, c & 4 ? l.box.max.z : l.box.min.z);
        v.project(camera);
        var sy = (1 - v.y) / 2 * h;
        if (sy > lo) lo = sy;
        xs += (v.x + 1) / 2 * w / 8;
      }
      l.x = xs; l.y = lo;
    });
    var order = labels.slice().sort(function (a, b) { return a.x - b.x; });
    var gap = 4;
    order.forEach(function (l, i) {
      var a = i > 0 ? (order[i - 1].x + l.x) / 2 : 0;
      var b = i < order.length - 1 ? (l.x + order[i + 1].x) / 2 : w;
      l.div.style.maxWidth = Math.max(40, Math.floor(b - a - 2 * gap)) + "px";
      var width = l.div.offsetWidth;
      var left = Math.min(Math.max(l.x - width / 2, a + gap), b - gap - width);
      l.div.style.left = Math.round(Math.max(0, left)) + "px";
    });
    var bar = 34;  // the control bar's height and a little
    labels.forEach(function (l) {
      l.div.style.top = Math.round(Math.max(0, Math.min(l.y + 4, h - bar - l.div.offsetHeight))) + "px";
    });
  }

  HTMLWidgets.widget({
    name: "hand3d",
    type: "output",
    factory: function (el, width, height) {
      var renderer = null, scene, camera, controls, ui, poses = [], x = null, labels = null, halfHeight = 1;
      var playing = false, t = 0, duration = 0, last = 0;
      // drawn on demand: a frame is rendered when the pose shown changes
      // (playing, the slider), the camera moves (OrbitControls' "change")
      // or the size changes; at rest nothing runs at all. `renders` counts
      // the frames rendered (data-renders, for the tests).
      var timer = null, drawPending = false, renders = 0;
      var visible = true, seen = false, observer = null;

      function size() {
        var w = el.clientWidth || width || 600, h = el.clientHeight || height || 400;
        return [w, h];
      }

      function draw() {
        if (!renderer) return;
        var wh = size();
        placeLabels(labels, camera, wh[0], wh[1]);
        renderer.render(scene, camera);
        renders++;
        el.setAttribute("data-renders", renders);
      }

      // one render for a burst of camera events (a drag sends one per pointer move)
      function requestDraw() {
        if (drawPending) return;
        drawPending = true;
        window.requestAnimationFrame(function () { drawPending = false; draw(); });
      }

      function show(time) {
        t = Math.max(0, Math.min(time, duration));
        for (var i = 0; i < poses.length; i++) poses[i].pose(frameTime(x.recordings[i], x.rate, t));
        var f0 = frameTime(x.recordings[0], x.rate, t);
        el.setAttribute("data-frame", f0);
        ui.slider.value = duration > 0 ? Math.round(1000 * t / duration) : 0;
        ui.label.textContent = t.toFixed(2) + " / " + duration.toFixed(2) + " s";
        draw();
      }

      function speed() { return Number(ui.speed.value) || 1; }

      // Playback runs only while it is wanted (playing), the widget is on
      // screen (IntersectionObserver) and the page is not hidden; paused,
      // finished, scrolled away or in a background tab, no timer is left.
      function running() { return playing && visible && !document.hidden && !!renderer && el.isConnected; }

      // Playback steps on a timer, at the time the next recorded frame is
      // due (at most 60 a second), rather than on requestAnimationFrame:
      // headless chromium under virtual time (the tests, the site's browser
      // checks, screenshots) runs only a few animation frames a second, so
      // playback there would not reach its end; a timer follows the page's
      // clock. (It used to redraw every 1/60 s at rest as well, which kept
      // a browser busy and made a 5 s virtual-time screenshot take 80 s.)
      function schedule() {
        if (timer !== null || !running()) return;
        var next = (Math.floor(t * x.rate + 1e-9) + 1) / x.rate;
        timer = setTimeout(tick, Math.max(1000 / 60, (next - t) / speed() * 1000));
      }

      function stop() {
        if (timer !== null) clearTimeout(timer);
        timer = null;
      }

      function tick() {
        timer = null;
        if (!running()) return;
        var now = performance.now();
        var next = t + (now - last) / 1000 * speed();
        last = now;
        if (next >= duration) {
          if (x.loop) next = 0;
          else { next = duration; setPlaying(false); }
        }
        show(next);
        schedule();
      }

      // start or stop the timer after a change of `playing`, `visible` or the page's visibility
      function reconcile() {
        if (!running()) return stop();
        if (timer === null) { last = performance.now(); schedule(); }
      }

      function setPlaying(p) {
        playing = p;
        ui.play.textContent = playing ? "pause" : "play";
        stop();
        reconcile();
      }

      function watchVisibility() {
        if (observer || !window.IntersectionObserver) return;
        observer = new IntersectionObserver(function (entries) {
          var v = entries[entries.length - 1].isIntersecting;
          // a widget that autoplays below the fold starts from the beginning when it is first seen
          if (!v && !seen && renderer) show(0);
          seen = seen || v;
          visible = v;
          reconcile();
        });
        observer.observe(el);
        document.addEventListener("visibilitychange", reconcile);
      }

      // an orthographic camera: hands side by side are seen from exactly the
      // same direction (and as in the still pictures, which are projections)
      function frustum(w, h) {
        var a = w / h;
        camera.left = -halfHeight * a; camera.right = halfHeight * a;
        camera.top = halfHeight; camera.bottom = -halfHeight;
        camera.updateProjectionMatrix();
      }

      return {
        renderValue: function (data) {
          x = data;
          stop();
          el.innerHTML = "";
          el.style.position = "relative";
          var wh = size();
          renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
          renderer.setPixelRatio(window.devicePixelRatio || 1);
          renderer.setSize(wh[0], wh[1]);
          renderer.setClearColor(new THREE.Color(x.background), 1);
          el.appendChild(renderer.domElement);
          scene = new THREE.Scene();
          scene.add(new THREE.HemisphereLight(0xffffff, 0x8d7c6a, 0.7));
          poses = x.recordings.map(function (rec) { return buildHand(scene, x, rec); });
          el.setAttribute("data-meshes", poses.map(function (p) { return p.segments; }).join(","));

          // frame the hands, seen from the palm and turned towards the thumb
          var box = bounds(x), centre = box.getCenter(new THREE.Vector3());
          var radius = box.getSize(new THREE.Vector3()).length() / 2;
          halfHeight = radius * 1.05 * Math.max(1, (wh[1] / wh[0]) * 0.9);
          camera = new THREE.OrthographicCamera(-1, 1, 1, -1, radius / 50, radius * 50);
          frustum(wh[0], wh[1]);
          // the first view is the still pictures' (R sends its screen up and
          // the direction towards the viewer; side-by-side hands stand across it)
          camera.up.set(x.camera.up[0], x.camera.up[1], x.camera.up[2]);
          var view = new THREE.Vector3(x.camera.towards[0], x.camera.towards[1], x.camera.towards[2]).normalize();
          camera.position.copy(centre).addScaledVector(view, radius * 4);
          // the light turns with the camera: from its upper left, as in the still pictures
          var key = new THREE.DirectionalLight(0xffffff, 0.6);
          key.position.set(-0.25, 0.35, 0.9);
          camera.add(key);
          scene.add(camera);
          controls = new THREE.OrbitControls(camera, renderer.domElement);
          controls.target.copy(centre);
          controls.update();
          controls.addEventListener("change", requestDraw);

          duration = Math.max.apply(null, x.recordings.map(function (r) { return (r.n - 1) / x.rate; }));
          ui = controlBar(el);
          legend(el, x);
          labels = handLabels(el, x);
          ui.speed.value = String(x.speed);
          if (ui.speed.value === "") ui.speed.value = "1";
          ui.play.onclick = function () {
            if (!playing && t >= duration) show(0);
            setPlaying(!playing);
          };
          ui.slider.oninput = function () { setPlaying(false); show(duration * ui.slider.value / 1000); };
          ui.speed.onchange = function () { stop(); reconcile(); };
          show(0);
          setPlaying(!!x.autoplay);
          el.setAttribute("data-ready", "1");
          watchVisibility();
        },
        resize: function (w, h) {
          if (!renderer) return;
          renderer.setSize(w, h);
          frustum(w, h);
          draw();
        }
      };
    }
  });
})();
