/* handmotion's 3D hand (hand_3d() in R/hand-3d.R): a solid hand per
 * recording -- bones as cylinders with spheres at the joints (capsules), the
 * palm as a surface -- played back at the recording's own rate, with an
 * orbit camera, play/pause, a time slider and a speed choice.
 *
 * The R side sends joint positions already posed (forward kinematics is done
 * once, in R), so this file only places meshes. Data (x):
 *   joints, parent (0-based, -1 for the root), colour (per joint), radius
 *   (per joint, mm), palm (0-based outline indices), rate, speed, autoplay,
 *   loop, background, layout ("side" or "overlay"), recordings: [{label, colour, n, pos (frame-major
 *   n x joints x 3), outside (n x joints 0/1 or null), markers (n x m x 3
 *   or null), offset [x, y, z], opacity}].
 *
 * For tests in a headless browser the container carries data-ready="1"
 * once drawn and data-frame (the first recording's frame on screen), and
 * any script error is written to document.body's data-js-error. */
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

  function buildHand(scene, x, rec) {
    var J = x.joints.length;
    var group = new THREE.Group();
    var opacity = rec.opacity === undefined ? 1 : rec.opacity;
    var material = function (colour) {
      return new THREE.MeshStandardMaterial({
        color: colour, roughness: 0.55, metalness: 0.05,
        transparent: opacity < 1, opacity: opacity
      });
    };
    var jointMat = [], spheres = [], bones = [];
    for (var j = 0; j < J; j++) {
      var colour = rec.colour ? rec.colour : x.colour[j];
      jointMat.push(material(colour));
      var s = new THREE.Mesh(new THREE.SphereGeometry(x.radius[j] * 1.08, 20, 14), jointMat[j]);
      group.add(s);
      spheres.push(s);
      if (x.parent[j] >= 0) {
        var c = new THREE.Mesh(new THREE.CylinderGeometry(1, 1, 1, 20, 1, true), material(colour));
        group.add(c);
        bones.push({ mesh: c, a: x.parent[j], b: j, r: x.radius[j] });
      }
    }
    // the palm: a fan of triangles from the centroid of its outline
    var P = x.palm.length, palm = null;
    if (P >= 3) {
      var geo = new THREE.BufferGeometry();
      geo.setAttribute("position", new THREE.BufferAttribute(new Float32Array((P + 1) * 3), 3));
      var idx = [];
      for (var k = 0; k < P; k++) idx.push(P, k, (k + 1) % P);
      geo.setIndex(idx);
      palm = new THREE.Mesh(geo, new THREE.MeshStandardMaterial({
        color: rec.colour || 0xd9c2a7, roughness: 0.7, side: THREE.DoubleSide,
        transparent: opacity < 1, opacity: opacity
      }));
      group.add(palm);
    }
    var markers = [];
    var M = rec.markers ? rec.markers.length / (rec.n * 3) : 0;
    for (var m = 0; m < M; m++) {
      var mk = new THREE.Mesh(new THREE.SphereGeometry(x.radius[0] * 0.7, 14, 10),
                              new THREE.MeshStandardMaterial({ color: MARKER_COLOUR, roughness: 0.3 }));
      group.add(mk);
      markers.push(mk);
    }
    group.position.set(rec.offset[0], rec.offset[1], rec.offset[2]);
    scene.add(group);
    var base = x.colour.map(function (c) { return new THREE.Color(rec.colour || c); });
    var pa = new THREE.Vector3(), pb = new THREE.Vector3(), dir = new THREE.Vector3();

    return function pose(f) {
      var o = f * J * 3, pos = rec.pos;
      for (var j = 0; j < J; j++) {
        spheres[j].position.set(pos[o + 3 * j], pos[o + 3 * j + 1], pos[o + 3 * j + 2]);
        var out = rec.outside && rec.outside[f * J + j] === 1;
        jointMat[j].color.set(out ? LIMIT_COLOUR : base[j]);
      }
      for (var b = 0; b < bones.length; b++) {
        var bone = bones[b];
        pa.copy(spheres[bone.a].position);
        pb.copy(spheres[bone.b].position);
        dir.subVectors(pb, pa);
        var len = dir.length();
        bone.mesh.position.addVectors(pa, pb).multiplyScalar(0.5);
        if (len > 1e-9) bone.mesh.quaternion.setFromUnitVectors(UP, dir.divideScalar(len));
        bone.mesh.scale.set(bone.r, Math.max(len, 1e-6), bone.r);
      }
      if (palm) {
        var arr = palm.geometry.attributes.position.array, cx = 0, cy = 0, cz = 0;
        for (var k = 0; k < P; k++) {
          var q = o + 3 * x.palm[k];
          arr[3 * k] = pos[q]; arr[3 * k + 1] = pos[q + 1]; arr[3 * k + 2] = pos[q + 2];
          cx += pos[q]; cy += pos[q + 1]; cz += pos[q + 2];
        }
        arr[3 * P] = cx / P; arr[3 * P + 1] = cy / P; arr[3 * P + 2] = cz / P;
        palm.geometry.attributes.position.needsUpdate = true;
        palm.geometry.computeVertexNormals();
        palm.geometry.computeBoundingSphere();
      }
      for (var m = 0; m < markers.length; m++) {
        var r = (f * markers.length + m) * 3;
        markers[m].position.set(rec.markers[r], rec.markers[r + 1], rec.markers[r + 2]);
      }
    };
  }

  function bounds(x) {
    var box = new THREE.Box3();
    var v = new THREE.Vector3();
    x.recordings.forEach(function (rec) {
      for (var i = 0; i < rec.pos.length; i += 3) {
        v.set(rec.pos[i] + rec.offset[0], rec.pos[i + 1] + rec.offset[1], rec.pos[i + 2] + rec.offset[2]);
        box.expandByPoint(v);
      }
    });
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
    div.style.cssText = "position:absolute;left:8px;top:6px;font:12px sans-serif;color:#222;" +
      "background:rgba(255,255,255,0.7);padding:2px 6px;border-radius:3px";
    var esc = function (t) { return t.replace(/&/g, "&amp;").replace(/</g, "&lt;"); };
    if (x.layout === "side" && x.recordings.length > 1) {
      // which hand is which: they stand in this order, left to right, in the first view
      div.innerHTML = "<div>left to right (as first shown):</div>" + x.recordings.map(function (r, i) {
        return "<div>" + (i + 1) + ". " + esc(r.label) + "</div>";
      }).join("");
    } else {
      div.innerHTML = x.recordings.map(function (r) {
        var sw = r.colour ? '<span style="display:inline-block;width:10px;height:10px;margin-right:4px;background:' +
          r.colour + '"></span>' : "";
        return "<div>" + sw + esc(r.label) + "</div>";
      }).join("");
    }
    el.appendChild(div);
  }

  HTMLWidgets.widget({
    name: "hand3d",
    type: "output",
    factory: function (el, width, height) {
      var renderer = null, scene, camera, controls, ui, poses = [], x = null;
      var playing = false, t = 0, duration = 0, last = null;

      function size() {
        var w = el.clientWidth || width || 600, h = el.clientHeight || height || 400;
        return [w, h];
      }

      function show(time) {
        t = Math.max(0, Math.min(time, duration));
        for (var i = 0; i < poses.length; i++) poses[i](frameTime(x.recordings[i], x.rate, t));
        var f0 = frameTime(x.recordings[0], x.rate, t);
        el.setAttribute("data-frame", f0);
        ui.slider.value = duration > 0 ? Math.round(1000 * t / duration) : 0;
        ui.label.textContent = t.toFixed(2) + " / " + duration.toFixed(2) + " s";
        renderer.render(scene, camera);
      }

      function setPlaying(p) {
        playing = p;
        ui.play.textContent = playing ? "pause" : "play";
        last = null;
      }

      // Driven by a timer rather than requestAnimationFrame: it keeps
      // playing where no frames are requested (headless browsers, the tests)
      // and costs the same at 60 updates a second.
      function tick() {
        var now = performance.now();
        if (!renderer || !el.isConnected) return;
        setTimeout(tick, 1000 / 60);
        if (playing) {
          if (last !== null) {
            var next = t + (now - last) / 1000 * Number(ui.speed.value);
            if (next > duration) next = x.loop ? 0 : duration;
            if (next >= duration && !x.loop) setPlaying(false);
            show(next);
          }
          last = now;
        }
        controls.update();
        renderer.render(scene, camera);
      }

      return {
        renderValue: function (data) {
          x = data;
          el.innerHTML = "";
          el.style.position = "relative";
          var wh = size();
          renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
          renderer.setPixelRatio(window.devicePixelRatio || 1);
          renderer.setSize(wh[0], wh[1]);
          renderer.setClearColor(new THREE.Color(x.background), 1);
          el.appendChild(renderer.domElement);
          scene = new THREE.Scene();
          scene.add(new THREE.HemisphereLight(0xffffff, 0x8d7c6a, 0.75));
          var key = new THREE.DirectionalLight(0xffffff, 0.65);
          scene.add(key);
          poses = x.recordings.map(function (rec) { return buildHand(scene, x, rec); });

          // frame the hands, seen from the palm and turned towards the thumb
          var box = bounds(x), centre = box.getCenter(new THREE.Vector3());
          var radius = box.getSize(new THREE.Vector3()).length() / 2;
          camera = new THREE.PerspectiveCamera(35, wh[0] / wh[1], radius / 50, radius * 50);
          camera.up.set(0, -1, 0); // fingers (skeleton -y) point up on screen
          // (R/hand-3d.R sets side-by-side hands across this line of sight, at one depth)
          var view = new THREE.Vector3(0.55, -0.25, -1).normalize();
          var dist = radius / Math.sin(THREE.MathUtils.degToRad(35 / 2)) *
            Math.max(1, wh[1] / wh[0]) * 0.75;
          camera.position.copy(centre).addScaledVector(view, dist);
          key.position.copy(camera.position).add(new THREE.Vector3(0, -radius, 0));
          controls = new THREE.OrbitControls(camera, renderer.domElement);
          controls.target.copy(centre);
          controls.update();

          duration = Math.max.apply(null, x.recordings.map(function (r) { return (r.n - 1) / x.rate; }));
          ui = controlBar(el);
          legend(el, x);
          ui.speed.value = String(x.speed);
          if (ui.speed.value === "") ui.speed.value = "1";
          ui.play.onclick = function () {
            if (!playing && t >= duration) show(0);
            setPlaying(!playing);
          };
          ui.slider.oninput = function () { setPlaying(false); show(duration * ui.slider.value / 1000); };
          setPlaying(!!x.autoplay);
          show(0);
          el.setAttribute("data-ready", "1");
          setTimeout(tick, 0);
        },
        resize: function (w, h) {
          if (!renderer) return;
          renderer.setSize(w, h);
          camera.aspect = w / h;
          camera.updateProjectionMatrix();
          renderer.render(scene, camera);
        }
      };
    }
  });
})();
