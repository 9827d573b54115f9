// The final part as a solid: its section revolved about the Z axis over three quarters of
// a turn, the quarter toward the viewer cut away so that the bore shows; gouges red and
// leftovers orange on it, the blank a ghost. WebGL 1, no library. Drag to turn it, the
// wheel zooms, a double click resets. Data: the `solid` field of #ls-data (html/solid.rs):
// rings [z, x, z, x, ...] (x a diameter), already thinned to a bounded count.
(function () {
  'use strict';
  var canvas = document.getElementById('ls-solid');
  var note = document.getElementById('ls-solid-note');
  if (!canvas) { return; }
  function fail(msg) {
    canvas.style.display = 'none';
    if (note) { note.textContent = msg; }
  }
  // The view is set up and drawn after the page has loaded (in a software renderer a
  // detailed part takes a second or two, which must not hold the page), or at once when
  // the page is printed before that.
  var started = false;
  function begin() {
    if (!started) { started = true; start(); }
  }
  if (document.readyState === 'complete') {
    window.setTimeout(begin, 0);
  } else {
    window.addEventListener('load', function () { window.setTimeout(begin, 0); });
  }
  window.addEventListener('beforeprint', begin);

  function start() {
    var began = performance.now();
    var data, style;
    try {
      var all = JSON.parse(document.getElementById('ls-data').textContent);
      data = all.solid || {};
      style = all.style || {};
    } catch (e) {
      return;
    }
    // '#d62728' as [r, g, b, 1] in 0..1, or `fallback`.
    function rgb(hex, fallback) {
      var m = /^#([0-9a-f]{6})$/i.exec(hex || '');
      if (!m) { return fallback; }
      var v = parseInt(m[1], 16);
      return [(v >> 16 & 255) / 255, (v >> 8 & 255) / 255, (v & 255) / 255, 1];
    }
    var part = data.part || [];
    if (!part.length) { fail('No final part to show in 3D.'); return; }
    // A graphics card draws 150 000 quads smoothed; a software renderer (no card, or a
    // headless browser: SwiftShader) draws 40 000, unsmoothed, so that the page opens quickly.
    var opts = { stencil: true, antialias: true, preserveDrawingBuffer: true, alpha: false,
      failIfMajorPerformanceCaveat: true };
    var gl = canvas.getContext('webgl', opts), QUADS = 150000;
    if (!gl) {
      opts.antialias = false;
      opts.failIfMajorPerformanceCaveat = false;
      gl = canvas.getContext('webgl', opts) || canvas.getContext('experimental-webgl', opts);
      QUADS = 40000;
    }
    if (!gl) { fail('The 3D view needs WebGL, which this browser does not offer.'); return; }
    var wide = !!gl.getExtension('OES_element_index_uint');

    // The material spans the angles from START to START + SWEEP about the axis: the removed
    // quarter is the one up and toward the viewer (y > 0, z > 0).
    var START = Math.PI / 2, SWEEP = 1.5 * Math.PI;
    var COLOURS = {
      part: [0.62, 0.68, 0.76, 1], cut: [0.80, 0.76, 0.66, 1],
      gouge: rgb(style.gouge, [0.84, 0.15, 0.16, 1]), leftover: rgb(style.leftover, [1.0, 0.55, 0.16, 1]),
      blank: [0.55, 0.52, 0.46, 0.2], edge: [0.16, 0.19, 0.24, 1], blankEdge: [0.42, 0.39, 0.33, 0.7]
    };

    function edgeCount(rings) {
      var n = 0;
      for (var i = 0; i < rings.length; i++) { n += rings[i].length >> 1; }
      return n;
    }
    var allEdges = edgeCount(part) + edgeCount(data.gouges || []) + edgeCount(data.leftovers || []) +
      edgeCount(data.blank || []);
    // About QUADS quads in all, 12 to 72 steps over the three quarters.
    var STEPS = Math.max(12, Math.min(72, Math.round(QUADS / Math.max(1, allEdges))));
    var COS = [], SIN = [];
    for (var s = 0; s <= STEPS; s++) {
      var a = START + SWEEP * s / STEPS;
      COS.push(Math.cos(a)); SIN.push(Math.sin(a));
    }

    // Buffers of positions, normals and triangle indices; split into chunks below 65 536
    // vertices when 32-bit indices are not offered.
    function Builder() { this.chunks = []; this.open(); }
    Builder.prototype.open = function () {
      this.p = []; this.n = []; this.i = []; this.v = 0;
      this.chunks.push({ p: this.p, n: this.n, i: this.i });
    };
    Builder.prototype.room = function (verts) {
      if (!wide && this.v + verts > 65535) { this.open(); }
    };
    Builder.prototype.vert = function (x, y, z, nx, ny, nz) {
      this.p.push(x, y, z); this.n.push(nx, ny, nz);
      return this.v++;
    };

    // The surface the edges of `rings` sweep: a band of quads per edge, flat along the
    // section, round about the axis. Edges on the axis sweep nothing.
    function revolve(b, rings) {
      for (var k = 0; k < rings.length; k++) {
        var r = rings[k], m = r.length >> 1;
        for (var i = 0; i < m; i++) {
          var j = (i + 1) % m;
          var z1 = r[2 * i], r1 = Math.max(0, r[2 * i + 1] / 2);
          var z2 = r[2 * j], r2 = Math.max(0, r[2 * j + 1] / 2);
          var dz = z2 - z1, dr = r2 - r1, len = Math.sqrt(dz * dz + dr * dr);
          if (!(len > 0) || (r1 === 0 && r2 === 0)) { continue; }
          var nz = dr / len, nr = -dz / len;
          b.room(2 * (STEPS + 1));
          var first = b.v;
          for (var s = 0; s <= STEPS; s++) {
            var c = COS[s], sn = SIN[s];
            b.vert(z1, r1 * c, r1 * sn, nz, nr * c, nr * sn);
            b.vert(z2, r2 * c, r2 * sn, nz, nr * c, nr * sn);
          }
          for (s = 0; s < STEPS; s++) {
            var q = first + 2 * s;
            b.i.push(q, q + 1, q + 3, q, q + 3, q + 2);
          }
        }
      }
    }

    // The section laid in the plane at angle `a` (a cut face), drawn through the stencil
    // buffer without a triangulation: `parity` holds, for each edge, the trapezoid between
    // it and a base line below the section, so that a point is covered by as many
    // trapezoids as edges lie above it, odd inside the rings (holes and all), even outside;
    // `cover`, the section's box, is then coloured where the count is odd. The trapezoids'
    // sides on a column z = const are cut at every vertex of that column, so that
    // neighbours share them exactly: sides merely collinear are snapped to pixels apart and
    // left dots along the seams. The base line lies below the box, where the same holds of
    // the trapezoids' bottoms. Each pixel is drawn about as often as edges cross its column
    // (a fan from one point drew a detailed section hundreds of times over, seconds in a
    // software renderer). (nx, ny, nz): the face's normal, x along the axis.
    function cutFace(rings, a, nx, ny, nz) {
      var c = Math.cos(a), sn = Math.sin(a);
      var columns = new Map(), zmin = Infinity, zmax = -Infinity, rmin = Infinity, rmax = 0;
      var k, i, r, m, z, x;
      for (k = 0; k < rings.length; k++) {
        r = rings[k];
        for (i = 0; i + 1 < r.length; i += 2) {
          z = r[i]; x = Math.max(0, r[i + 1] / 2);
          if (!columns.has(z)) { columns.set(z, []); }
          columns.get(z).push(x);
          zmin = Math.min(zmin, z); zmax = Math.max(zmax, z);
          rmin = Math.min(rmin, x); rmax = Math.max(rmax, x);
        }
      }
      columns.forEach(function (hs) { hs.sort(function (p, q) { return p - q; }); });
      var base = rmin - 1 - 0.05 * rmax;
      var parity = new Builder(), cover = new Builder();
      function at(bld, zz, xx) { return bld.vert(zz, xx * c, xx * sn, nx, ny, nz); }
      for (k = 0; k < rings.length; k++) {
        r = rings[k]; m = r.length >> 1;
        for (i = 0; i < m; i++) {
          var j = (i + 1) % m;
          var z1 = r[2 * i], x1 = Math.max(0, r[2 * i + 1] / 2);
          var z2 = r[2 * j], x2 = Math.max(0, r[2 * j + 1] / 2);
          if (z1 === z2) { continue; }
          // the outline: up column z1 to the edge, along it, down column z2
          var pts = [[z1, base]];
          columns.get(z1).forEach(function (h) { if (h < x1) { pts.push([z1, h]); } });
          pts.push([z1, x1], [z2, x2]);
          var down = columns.get(z2).filter(function (h) { return h < x2; });
          for (var d = down.length - 1; d >= 0; d--) { pts.push([z2, down[d]]); }
          pts.push([z2, base]);
          parity.room(pts.length + 1);
          var centre = at(parity, (z1 + z2) / 2, (2 * base + x1 + x2) / 4);
          for (var e = 0; e < pts.length; e++) { at(parity, pts[e][0], pts[e][1]); }
          for (e = 0; e < pts.length; e++) {
            parity.i.push(centre, centre + 1 + e, centre + 1 + (e + 1) % pts.length);
          }
        }
      }
      if (zmax > zmin) {
        var q = at(cover, zmin, rmin);
        at(cover, zmax, rmin); at(cover, zmax, rmax); at(cover, zmin, rmax);
        cover.i.push(q, q + 1, q + 2, q, q + 2, q + 3);
      }
      return { parity: upload(parity), cover: upload(cover) };
    }

    // The outline of the section in both cut planes, and a circle about the axis at each
    // corner of the section (where its direction turns by more than 25°): lines. A section
    // of more than MAX_CORNERS corners (a sawtooth) gets no circles: they would be a smear.
    var MAX_CORNERS = 300;
    function corners(r) {
      var m = r.length >> 1, out = [];
      for (var i = 0; i < m; i++) {
        var p = (i + m - 1) % m, n = (i + 1) % m;
        var ax = r[2 * i] - r[2 * p], ay = (r[2 * i + 1] - r[2 * p + 1]) / 2;
        var bx = r[2 * n] - r[2 * i], by = (r[2 * n + 1] - r[2 * i + 1]) / 2;
        var la = Math.sqrt(ax * ax + ay * ay), lb = Math.sqrt(bx * bx + by * by);
        if (la > 0 && lb > 0 && r[2 * i + 1] > 0 && (ax * bx + ay * by) / (la * lb) < 0.906) {
          out.push(i);
        }
      }
      return out;
    }
    function outlines(b, rings) {
      var ends = [START, START + SWEEP], found = [], count = 0;
      for (var k = 0; k < rings.length; k++) {
        var r = rings[k], m = r.length >> 1;
        for (var e = 0; e < 2; e++) {
          b.room(m);
          var c = Math.cos(ends[e]), sn = Math.sin(ends[e]), first = b.v;
          for (var i = 0; i < m; i++) {
            var x = Math.max(0, r[2 * i + 1] / 2);
            b.vert(r[2 * i], x * c, x * sn, 0, 0, 1);
          }
          for (i = 0; i < m; i++) { b.i.push(first + i, first + (i + 1) % m); }
        }
        found.push(corners(r));
        count += found[k].length;
      }
      if (count > MAX_CORNERS) { return; }
      for (k = 0; k < rings.length; k++) {
        for (var j = 0; j < found[k].length; j++) {
          var z = rings[k][2 * found[k][j]], rad = rings[k][2 * found[k][j] + 1] / 2;
          b.room(STEPS + 1);
          first = b.v;
          for (var s = 0; s <= STEPS; s++) { b.vert(z, rad * COS[s], rad * SIN[s], 0, 0, 1); }
          for (s = 0; s < STEPS; s++) { b.i.push(first + s, first + s + 1); }
        }
      }
    }

    // Upload a builder's chunks: [{pos, nrm, idx, count, type}].
    function upload(b) {
      var out = [];
      for (var c = 0; c < b.chunks.length; c++) {
        var ch = b.chunks[c];
        if (!ch.i.length) { continue; }
        var big = wide && ch.p.length / 3 > 65535;
        var pos = gl.createBuffer(), nrm = gl.createBuffer(), idx = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, pos);
        gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(ch.p), gl.STATIC_DRAW);
        gl.bindBuffer(gl.ARRAY_BUFFER, nrm);
        gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(ch.n), gl.STATIC_DRAW);
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, idx);
        gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, big ? new Uint32Array(ch.i) : new Uint16Array(ch.i), gl.STATIC_DRAW);
        out.push({ pos: pos, nrm: nrm, idx: idx, count: ch.i.length, type: big ? gl.UNSIGNED_INT : gl.UNSIGNED_SHORT });
      }
      return out;
    }

    function build(kind, rings) {
      var b = new Builder();
      if (kind === 'surface') { revolve(b, rings); }
      if (kind === 'faces') {
        // one per cut plane (their counts must not mix where one hides the other), normals
        // toward the removed quarter: -d/da at the start, +d/da at the end
        return [
          cutFace(rings, START, 0, Math.sin(START), -Math.cos(START)),
          cutFace(rings, START + SWEEP, 0, -Math.sin(START + SWEEP), Math.cos(START + SWEEP))
        ];
      }
      if (kind === 'lines') { outlines(b, rings); }
      return upload(b);
    }

    var VS = 'attribute vec3 p; attribute vec3 n; uniform mat4 mvp; uniform mat4 mv; varying vec3 vn;' +
      'void main() { gl_Position = mvp * vec4(p, 1.0); vn = (mv * vec4(n, 0.0)).xyz; }';
    var FS = 'precision mediump float; varying vec3 vn; uniform vec4 col; uniform float lit;' +
      'void main() {' +
      '  if (lit < 0.5) { gl_FragColor = col; return; }' +
      // a key light from the upper left, a fill from the right, both two-sided
      '  vec3 N = normalize(vn); vec3 L = normalize(vec3(-0.35, 0.6, 0.72));' +
      '  vec3 F = normalize(vec3(0.75, 0.05, 0.65));' +
      '  float d = 0.55 * abs(dot(N, L)) + 0.3 * abs(dot(N, F));' +
      '  float h = pow(abs(dot(N, normalize(L + vec3(0.0, 0.0, 1.0)))), 48.0);' +
      '  gl_FragColor = vec4(col.rgb * (0.32 + d) + 0.2 * h, col.a);' +
      '}';
    function shader(type, src) {
      var s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      return s;
    }
    var prog = gl.createProgram();
    gl.attachShader(prog, shader(gl.VERTEX_SHADER, VS));
    gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, FS));
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) { fail('The 3D view could not start (WebGL shader).'); return; }
    gl.useProgram(prog);
    var loc = {
      p: gl.getAttribLocation(prog, 'p'), n: gl.getAttribLocation(prog, 'n'),
      mvp: gl.getUniformLocation(prog, 'mvp'), mv: gl.getUniformLocation(prog, 'mv'),
      col: gl.getUniformLocation(prog, 'col'), lit: gl.getUniformLocation(prog, 'lit')
    };

    var layers = {
      part: build('surface', part), partFaces: build('faces', part), partLines: build('lines', part),
      gouge: build('surface', data.gouges || []), gougeFaces: build('faces', data.gouges || []),
      left: build('surface', data.leftovers || []), leftFaces: build('faces', data.leftovers || []),
      blank: build('surface', data.blank || []), blankLines: build('lines', data.blank || [])
    };

    // The view: the part's box centred, turned by yaw (about the screen's vertical) and
    // pitch (about its horizontal), seen in perspective from `dist`.
    var zmin = Infinity, zmax = -Infinity, rmax = 0;
    [part, data.blank || []].forEach(function (rings) {
      rings.forEach(function (r) {
        for (var i = 0; i + 1 < r.length; i += 2) {
          zmin = Math.min(zmin, r[i]); zmax = Math.max(zmax, r[i]);
          rmax = Math.max(rmax, r[i + 1] / 2);
        }
      });
    });
    var zc = (zmin + zmax) / 2, radius = Math.max(1e-3, Math.sqrt(Math.pow((zmax - zmin) / 2, 2) + rmax * rmax));
    var FOV = 30 * Math.PI / 180;
    var HOME = { yaw: -0.55, pitch: 0.42, zoom: 1 };
    var view = { yaw: HOME.yaw, pitch: HOME.pitch, zoom: HOME.zoom };

    function mul(a, b) {
      var o = new Float32Array(16);
      for (var c = 0; c < 4; c++) {
        for (var r = 0; r < 4; r++) {
          var s = 0;
          for (var k = 0; k < 4; k++) { s += a[k * 4 + r] * b[c * 4 + k]; }
          o[c * 4 + r] = s;
        }
      }
      return o;
    }
    function matrices(aspect) {
      var cy = Math.cos(view.yaw), sy = Math.sin(view.yaw), cp = Math.cos(view.pitch), sp = Math.sin(view.pitch);
      var dist = radius / Math.sin(FOV / 2) * 1.05 / view.zoom / Math.min(1, aspect);
      var ry = [cy, 0, -sy, 0, 0, 1, 0, 0, sy, 0, cy, 0, 0, 0, 0, 1];
      var rx = [1, 0, 0, 0, 0, cp, sp, 0, 0, -sp, cp, 0, 0, 0, 0, 1];
      var centre = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -zc, 0, 0, 1];
      var back = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -dist, 1];
      var mv = mul(back, mul(rx, mul(ry, centre)));
      var near = Math.max(dist - 2 * radius, dist * 0.01), far = dist + 2 * radius;
      var f = 1 / Math.tan(FOV / 2);
      var proj = [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1,
        0, 0, 2 * far * near / (near - far), 0];
      return { mv: mv, mvp: mul(proj, mv) };
    }

    function draw(list, mode, colour, lit) {
      gl.uniform4fv(loc.col, colour);
      gl.uniform1f(loc.lit, lit ? 1 : 0);
      for (var i = 0; i < list.length; i++) {
        var c = list[i];
        gl.bindBuffer(gl.ARRAY_BUFFER, c.pos);
        gl.vertexAttribPointer(loc.p, 3, gl.FLOAT, false, 0, 0);
        gl.bindBuffer(gl.ARRAY_BUFFER, c.nrm);
        gl.vertexAttribPointer(loc.n, 3, gl.FLOAT, false, 0, 0);
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, c.idx);
        gl.drawElements(mode, c.count, c.type, 0);
      }
    }
    // The two cut faces of a layer: each plane's trapezoids invert the stencil (parity:
    // inside the rings), then its box is coloured where the parity is odd and the face is
    // in front. The parity is counted without the depth test (a trapezoid's depth at a
    // seam is a rounding away from its neighbour's).
    function face(planes, colour) {
      gl.enable(gl.STENCIL_TEST);
      for (var i = 0; i < planes.length; i++) {
        gl.clear(gl.STENCIL_BUFFER_BIT);
        gl.colorMask(false, false, false, false);
        gl.depthMask(false);
        gl.disable(gl.DEPTH_TEST);
        gl.stencilFunc(gl.ALWAYS, 0, 1);
        gl.stencilOp(gl.KEEP, gl.KEEP, gl.INVERT);
        draw(planes[i].parity, gl.TRIANGLES, colour, false);
        gl.enable(gl.DEPTH_TEST);
        gl.colorMask(true, true, true, true);
        gl.depthMask(true);
        gl.stencilFunc(gl.EQUAL, 1, 1);
        gl.stencilOp(gl.KEEP, gl.KEEP, gl.KEEP);
        draw(planes[i].cover, gl.TRIANGLES, colour, true);
      }
      gl.disable(gl.STENCIL_TEST);
    }

    var W = 0, H = 0;
    function resize() {
      var dpr = window.devicePixelRatio || 1;
      W = Math.max(200, canvas.clientWidth || 900);
      H = Math.max(200, canvas.clientHeight || 480);
      canvas.width = Math.round(W * dpr);
      canvas.height = Math.round(H * dpr);
    }

    function render() {
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.clearColor(1, 1, 1, 1);
      gl.clearStencil(0);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT | gl.STENCIL_BUFFER_BIT);
      gl.enable(gl.DEPTH_TEST);
      gl.depthFunc(gl.LEQUAL);
      gl.disable(gl.BLEND);
      var m = matrices(W / H);
      gl.uniformMatrix4fv(loc.mvp, false, m.mvp);
      gl.uniformMatrix4fv(loc.mv, false, m.mv);
      gl.enableVertexAttribArray(loc.p);
      gl.enableVertexAttribArray(loc.n);
      // surfaces pushed back so that the findings (less so) and the lines (not at all) lying
      // on them win
      gl.enable(gl.POLYGON_OFFSET_FILL);
      gl.polygonOffset(2, 2);
      draw(layers.part, gl.TRIANGLES, COLOURS.part, true);
      face(layers.partFaces, COLOURS.cut);
      gl.polygonOffset(1, 1);
      draw(layers.gouge, gl.TRIANGLES, COLOURS.gouge, true);
      face(layers.gougeFaces, COLOURS.gouge);
      draw(layers.left, gl.TRIANGLES, COLOURS.leftover, true);
      face(layers.leftFaces, COLOURS.leftover);
      gl.disable(gl.POLYGON_OFFSET_FILL);
      draw(layers.partLines, gl.LINES, COLOURS.edge, false);
      // the blank last, see-through, not hiding what lies behind it
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      gl.depthMask(false);
      draw(layers.blank, gl.TRIANGLES, COLOURS.blank, true);
      draw(layers.blankLines, gl.LINES, COLOURS.blankEdge, false);
      gl.depthMask(true);
    }

    var queued = false;
    function later() {
      if (queued) { return; }
      queued = true;
      window.requestAnimationFrame(function () { queued = false; render(); });
    }

    var drag = null;
    canvas.addEventListener('pointerdown', function (e) {
      drag = { x: e.clientX, y: e.clientY };
      if (canvas.setPointerCapture) { canvas.setPointerCapture(e.pointerId); }
    });
    canvas.addEventListener('pointermove', function (e) {
      if (!drag) { return; }
      view.yaw += (e.clientX - drag.x) * 0.01;
      view.pitch = Math.max(-1.55, Math.min(1.55, view.pitch + (e.clientY - drag.y) * 0.01));
      drag = { x: e.clientX, y: e.clientY };
      later();
    });
    var stopDrag = function () { drag = null; };
    canvas.addEventListener('pointerup', stopDrag);
    canvas.addEventListener('pointercancel', stopDrag);
    canvas.addEventListener('wheel', function (e) {
      e.preventDefault();
      view.zoom = Math.max(0.3, Math.min(40, view.zoom * Math.exp(-e.deltaY * 0.0015)));
      later();
    }, { passive: false });
    canvas.addEventListener('dblclick', function () {
      view.yaw = HOME.yaw; view.pitch = HOME.pitch; view.zoom = HOME.zoom;
      later();
    });
    window.addEventListener('resize', function () { resize(); later(); });
    canvas.addEventListener('webglcontextlost', function (e) {
      e.preventDefault();
      fail('The 3D view lost its WebGL context; reload the page to see it again.');
    });

    resize();
    render();
    // when the view was drawn first and how long it took to set up, for html-check.sh
    canvas.setAttribute('data-drawn', String(Math.round(performance.now())));
    canvas.setAttribute('data-took', String(Math.round(performance.now() - began)));
  }
})();
