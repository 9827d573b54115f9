// The move slider: replays the embedded toolpath over the stock on a canvas.
// Data: the JSON block #ls-data (see the render crate's html module for its fields).
(function () {
  'use strict';
  var byId = function (id) { return document.getElementById(id); };
  var data;
  try {
    data = JSON.parse(byId('ls-data').textContent);
  } catch (e) {
    return;
  }
  var slider = byId('ls-slider');
  var label = byId('ls-label');
  var canvas = byId('ls-canvas');
  var box = canvas.parentNode;
  var ctx = canvas.getContext('2d');
  if (!ctx) { return; }
  var n = data.moves | 0;
  var path = data.path || [];
  var snaps = data.snapshots || [];
  var st = data.style || {};
  var KIND = ['rapid', 'feed', 'thread'];
  var COL = [st.rapid || '#c9930a', st.feed || '#1a7f37', st.thread || '#00838f'];
  var HI = '#e0218a';
  var STOCK = '#dccfae';
  var win = data.window || [-10, 10, -20, 20];
  var zmin = win[0], zmax = win[1], rmin = win[2] / 2, rmax = win[3] / 2;
  if (!(zmax > zmin)) { zmax = zmin + 1; }
  if (!(rmax > rmin)) { rmax = rmin + 1; }

  var W = 0, H = 0, s = 1, ox = 0, oy = 0;
  var X = function (z) { return ox + (z - zmin) * s; };
  var Y = function (x) { return oy + (rmax - x / 2) * s; };
  var cache = {};

  function ringsPath(rings) {
    var p = new Path2D();
    for (var i = 0; i < rings.length; i++) {
      var r = rings[i];
      if (r.length < 6) { continue; }
      p.moveTo(X(r[0]), Y(r[1]));
      for (var j = 2; j + 1 < r.length; j += 2) { p.lineTo(X(r[j]), Y(r[j + 1])); }
      p.closePath();
    }
    return p;
  }

  function layout() {
    var dpr = window.devicePixelRatio || 1;
    W = Math.max(300, box.clientWidth || 1200);
    var aspect = (rmax - rmin) / (zmax - zmin);
    H = Math.round(Math.min(Math.max(W * aspect, 260), Math.max(360, (window.innerHeight || 900) * 0.8)));
    canvas.width = Math.round(W * dpr);
    canvas.height = Math.round(H * dpr);
    canvas.style.height = H + 'px';
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    var pad = 34;
    s = Math.min((W - 2 * pad) / (zmax - zmin), (H - 2 * pad) / (rmax - rmin));
    if (!(s > 0) || !isFinite(s)) { s = 1; }
    ox = (W - (zmax - zmin) * s) / 2;
    oy = (H - (rmax - rmin) * s) / 2;
    cache = {
      blank: ringsPath(data.blank || []),
      part: ringsPath(data.part || []),
      intended: ringsPath(data.intended || []),
      gouges: ringsPath(data.gouges || []),
      leftovers: ringsPath(data.leftovers || []),
      snaps: []
    };
  }

  function niceStep(min) {
    var p = Math.pow(10, Math.floor(Math.log(min) / Math.LN10));
    var m = [1, 2, 5, 10];
    for (var i = 0; i < m.length; i++) { if (m[i] * p >= min) { return m[i] * p; } }
    return 10 * p;
  }

  function grid() {
    var step = niceStep(70 / s);
    if (!isFinite(step) || step <= 0) { return; }
    ctx.save();
    ctx.strokeStyle = '#e9edf2';
    ctx.lineWidth = 1;
    ctx.fillStyle = '#5f6b7a';
    ctx.font = '12px system-ui, sans-serif';
    var z0 = Math.ceil((zmin - ox / s) / step) * step;
    var dec = step < 1 ? Math.min(4, Math.ceil(-Math.log(step) / Math.LN10)) : 0;
    ctx.textAlign = 'center';
    for (var z = z0, i = 0; X(z) <= W && i < 400; z += step, i++) {
      var x = Math.round(X(z)) + 0.5;
      ctx.beginPath(); ctx.moveTo(x, 0); ctx.lineTo(x, H); ctx.stroke();
      ctx.fillText(z.toFixed(dec), x, H - 6);
    }
    ctx.textAlign = 'left';
    var r0 = Math.ceil((rmax - (H - oy) / s) / step) * step;
    for (var r = r0, k = 0; Y(2 * r) >= 0 && k < 400; r += step, k++) {
      var y = Math.round(Y(2 * r)) + 0.5;
      ctx.beginPath(); ctx.moveTo(0, y); ctx.lineTo(W, y); ctx.stroke();
      ctx.fillText(r.toFixed(dec), 4, y - 3);
    }
    ctx.fillText('Z (mm) \u2192, X/2 (mm) \u2191', W - 170, 16);
    ctx.restore();
  }

  // Index of the last listed move with number <= k, or -1.
  function upTo(k) {
    var lo = 0, hi = path.length - 1, best = -1;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (path[mid][0] <= k) { best = mid; lo = mid + 1; } else { hi = mid - 1; }
    }
    return best;
  }

  function snapAt(k) {
    var best = -1;
    for (var i = 0; i < snaps.length; i++) { if (snaps[i].after <= k) { best = i; } }
    return best;
  }

  function trace(p, m) {
    if (m.length < 5) { return; }
    p.moveTo(X(m[3]), Y(m[4]));
    if (m.length < 7) { p.lineTo(X(m[3]) + 0.01, Y(m[4])); }
    for (var j = 5; j + 1 < m.length; j += 2) { p.lineTo(X(m[j]), Y(m[j + 1])); }
  }

  function marker(x, y) {
    ctx.save();
    ctx.strokeStyle = '#111';
    ctx.lineWidth = 2;
    ctx.fillStyle = 'rgba(255,255,255,0.7)';
    ctx.beginPath(); ctx.arc(x, y, 7, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    ctx.beginPath();
    ctx.moveTo(x - 12, y); ctx.lineTo(x + 12, y);
    ctx.moveTo(x, y - 12); ctx.lineTo(x, y + 12);
    ctx.lineWidth = 1.2; ctx.stroke();
    ctx.restore();
  }

  var k = n;

  function draw() {
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, W, H);
    grid();
    ctx.lineJoin = 'round';
    if (typeof lsTools !== 'undefined') { lsTools.under(ctx, data, X, Y); }
    // Blank outline (what will be removed shows as the light area).
    ctx.fillStyle = '#fbfaf6';
    ctx.fill(cache.blank, 'evenodd');
    ctx.strokeStyle = st.blank_edge || '#9b9283';
    ctx.lineWidth = 1.2;
    ctx.stroke(cache.blank);
    // The stock at the last snapshot at or before move k.
    var si = snapAt(k);
    if (si >= 0) {
      if (!cache.snaps[si]) { cache.snaps[si] = ringsPath(snaps[si].rings || []); }
      ctx.fillStyle = STOCK;
      ctx.fill(cache.snaps[si], 'evenodd');
      ctx.strokeStyle = '#8c7b5a';
      ctx.lineWidth = 1;
      ctx.stroke(cache.snaps[si]);
    }
    // The final part, faint; over a snapshot opaque, so that the stock still to be cut
    // (the snapshot less the final part) is what stays visible of it.
    ctx.save();
    if (si >= 0) {
      ctx.fillStyle = '#c8d4e3';
    } else {
      ctx.globalAlpha = 0.35;
      ctx.fillStyle = st.part || '#9db0c8';
    }
    ctx.fill(cache.part, 'evenodd');
    ctx.globalAlpha = 0.6;
    ctx.strokeStyle = st.part_edge || '#3f5570';
    ctx.stroke(cache.part);
    ctx.globalAlpha = 0.5;
    ctx.fillStyle = st.gouge || '#d62728';
    ctx.fill(cache.gouges, 'evenodd');
    ctx.fillStyle = st.leftover || '#ff8c2a';
    ctx.fill(cache.leftovers, 'evenodd');
    // Outlined 2 px wide, so a band thinner than a pixel still shows.
    ctx.globalAlpha = 0.9;
    ctx.lineWidth = 2;
    ctx.lineJoin = 'round';
    ctx.strokeStyle = st.gouge_edge || '#a31515';
    ctx.stroke(cache.gouges);
    ctx.strokeStyle = st.leftover_edge || '#d9650b';
    ctx.stroke(cache.leftovers);
    ctx.lineWidth = 1;
    ctx.globalAlpha = 0.55;
    ctx.setLineDash([7, 4]);
    ctx.strokeStyle = st.intended || '#1f6fe5';
    ctx.stroke(cache.intended);
    ctx.restore();
    // Axis centre line.
    var ya = Y(0);
    if (ya >= 0 && ya <= H) {
      ctx.save();
      ctx.strokeStyle = '#2b2f36';
      ctx.lineWidth = 1;
      ctx.setLineDash([16, 4, 3, 4]);
      ctx.beginPath(); ctx.moveTo(0, ya); ctx.lineTo(W, ya); ctx.stroke();
      ctx.restore();
    }
    // Toolpath before the current move.
    var cur = k > 0 ? upTo(k) : -1;
    var ps = [new Path2D(), new Path2D(), new Path2D()];
    for (var i = 0; i < cur; i++) { trace(ps[path[i][1]] || ps[1], path[i]); }
    ctx.save();
    ctx.globalAlpha = 0.9;
    for (var kind = 0; kind < 3; kind++) {
      ctx.setLineDash(kind === 0 ? [5, 4] : []);
      ctx.lineWidth = kind === 0 ? 1.1 : 1.4;
      ctx.strokeStyle = COL[kind];
      ctx.stroke(ps[kind]);
    }
    ctx.restore();
    // Crashes.
    var cr = data.crashes || [];
    ctx.save();
    ctx.strokeStyle = st.crash || '#7b3fe4';
    ctx.lineWidth = 2.5;
    for (var c = 0; c < cr.length; c++) {
      var cx = X(cr[c][1]), cy = Y(cr[c][2]);
      ctx.beginPath();
      ctx.moveTo(cx - 6, cy - 6); ctx.lineTo(cx + 6, cy + 6);
      ctx.moveTo(cx - 6, cy + 6); ctx.lineTo(cx + 6, cy - 6);
      ctx.stroke();
    }
    ctx.restore();
    // The current move, highlighted, and the tool's reference point after it.
    var text = 'move ' + k + ' / ' + n;
    if (cur >= 0) {
      var m = path[cur];
      var hp = new Path2D();
      trace(hp, m);
      ctx.save();
      ctx.strokeStyle = HI;
      ctx.lineWidth = 3.5;
      ctx.lineCap = 'round';
      ctx.setLineDash(m[1] === 0 ? [8, 5] : []);
      ctx.stroke(hp);
      ctx.restore();
      if (typeof lsTools !== 'undefined') { lsTools.over(ctx, data, m, X, Y); }
      if (m.length >= 5) { marker(X(m[m.length - 2]), Y(m[m.length - 1])); }
      var what = 'line ' + m[2] + ' (' + (KIND[m[1]] || 'feed') + ')';
      text += m[0] === k ? ' \u2014 ' + what : ' \u2014 nearest drawn: move ' + m[0] + ', ' + what;
    } else if (n > 0) {
      text += ' \u2014 start';
      if (path.length > 0 && path[0].length >= 5) { marker(X(path[0][3]), Y(path[0][4])); }
    } else {
      text = 'no moves';
    }
    if (si >= 0) { text += ' \u00b7 stock after move ' + snaps[si].after; }
    label.textContent = text;
  }

  function setK(v, fromSlider) {
    v = Math.max(0, Math.min(n, Math.round(Number(v) || 0)));
    k = v;
    if (!fromSlider) { slider.value = String(v); }
    draw();
  }

  function fromHash() {
    var m = /move=(\d+|end)/.exec(window.location.hash || '');
    if (!m) { return false; }
    setK(m[1] === 'end' ? n : parseInt(m[1], 10), false);
    return true;
  }

  function saveHash() {
    try { history.replaceState(null, '', '#move=' + k); } catch (e) { /* file: may refuse */ }
  }

  var timer = null;
  var playBtn = byId('ls-play');
  function stop() {
    if (timer !== null) { clearInterval(timer); timer = null; }
    playBtn.textContent = 'play';
  }
  function play() {
    if (timer !== null) { stop(); saveHash(); return; }
    if (k >= n) { setK(0, false); }
    var tick = Math.max(16, Math.min(250, 10000 / Math.max(1, n)));
    var step = Math.max(1, Math.round(n * tick / 10000));
    playBtn.textContent = 'pause';
    timer = setInterval(function () {
      if (k >= n) { stop(); saveHash(); return; }
      setK(k + step, false);
    }, tick);
  }

  slider.addEventListener('input', function () { stop(); setK(slider.value, true); });
  slider.addEventListener('change', saveHash);
  byId('ls-first').addEventListener('click', function () { stop(); setK(0, false); saveHash(); });
  byId('ls-prev').addEventListener('click', function () { stop(); setK(k - 1, false); saveHash(); });
  byId('ls-next').addEventListener('click', function () { stop(); setK(k + 1, false); saveHash(); });
  byId('ls-last').addEventListener('click', function () { stop(); setK(n, false); saveHash(); });
  playBtn.addEventListener('click', play);
  document.addEventListener('keydown', function (e) {
    var t = e.target;
    if (t === slider || e.altKey || e.ctrlKey || e.metaKey) { return; }
    if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'BUTTON')) { return; }
    var d = { ArrowLeft: -1, ArrowRight: 1 }[e.key];
    if (d) { e.preventDefault(); stop(); setK(k + d, false); saveHash(); }
  });
  window.addEventListener('hashchange', fromHash);
  var pending = null;
  window.addEventListener('resize', function () {
    if (pending !== null) { clearTimeout(pending); }
    pending = setTimeout(function () { pending = null; layout(); draw(); }, 100);
  });

  // Rows of the finding tables jump to the first move of their line.
  var firstOf = {};
  for (var j = 0; j < path.length; j++) {
    if (!(path[j][2] in firstOf)) { firstOf[path[j][2]] = path[j][0]; }
  }
  var rows = document.querySelectorAll('tr[data-line]');
  for (var i = 0; i < rows.length; i++) {
    (function (tr) {
      var line = parseInt(tr.getAttribute('data-line'), 10);
      if (!(line > 0) || !(line in firstOf)) { return; }
      var at = firstOf[line];
      tr.className += ' jump';
      tr.title = 'show move ' + at + ' (line ' + line + ')';
      tr.addEventListener('click', function () {
        stop();
        setK(at, false);
        saveHash();
        byId('ls-player').scrollIntoView();
      });
    })(rows[i]);
  }

  layout();
  if (fromHash()) {
    // A link to a move shows the player unless it is already in view.
    var top = byId('ls-player').getBoundingClientRect().top;
    if (top > (window.innerHeight || 900) * 0.5) { byId('ls-player').scrollIntoView(); }
  } else {
    setK(n, false);
  }
})();
