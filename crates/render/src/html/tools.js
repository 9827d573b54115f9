// The tool (insert and holder outline) at the current move, the tool where a crash at
// the current line happened, and the chuck, jaws and tailstock, for the move slider.
// Data: the fields `fixture`, `tools`, `tool_runs`, `crash_tools`, `remedy_tools` of #ls-data (see the
// render crate's html/tools.rs). The player calls lsTools.under before the stock and
// lsTools.over after the toolpath.
var lsTools = (function () {
  'use strict';
  function rings(ctx, rs, X, Y, dz, dx, flip) {
    var p = new Path2D();
    for (var i = 0; i < rs.length; i++) {
      var r = rs[i];
      if (r.length < 6) { continue; }
      for (var j = 0; j + 1 < r.length; j += 2) {
        var x = flip ? -(dx + r[j + 1]) : dx + r[j + 1];
        if (j === 0) { p.moveTo(X(dz + r[j]), Y(x)); } else { p.lineTo(X(dz + r[j]), Y(x)); }
      }
      p.closePath();
    }
    return p;
  }
  // Index into data.tools of the tool of move k (1-based), or -1.
  function toolOf(data, k) {
    var runs = data.tool_runs || [], best = -1;
    var lo = 0, hi = runs.length - 1;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (runs[mid][0] <= k) { best = runs[mid][1]; lo = mid + 1; } else { hi = mid - 1; }
    }
    return best;
  }
  return {
    under: function (ctx, data, X, Y) {
      var f = data.fixture || [];
      if (!f.length) { return; }
      var p = rings(ctx, f, X, Y, 0, 0, false);
      var m = rings(ctx, f, X, Y, 0, 0, true);
      ctx.save();
      ctx.fillStyle = '#eff0f2';
      ctx.fill(m, 'evenodd');
      ctx.fillStyle = '#e4e6ea';
      ctx.fill(p, 'evenodd');
      ctx.strokeStyle = '#9aa1ab';
      ctx.lineWidth = 1;
      ctx.stroke(p);
      ctx.stroke(m);
      ctx.restore();
    },
    // m: the current move's path entry [move, kind, line, z, x, …]; its end is where the
    // tool's reference point is.
    over: function (ctx, data, m, X, Y) {
      if (!m || m.length < 5) { return; }
      var t = (data.tools || [])[toolOf(data, m[0])];
      var z = m[m.length - 2], x = m[m.length - 1];
      ctx.save();
      ctx.lineJoin = 'round';
      if (t) {
        // a tool below the axis is drawn folded into the upper half, like the section
        var flip = x < 0;
        ctx.fillStyle = 'rgba(110,118,130,0.18)';
        ctx.strokeStyle = '#4a5261';
        ctx.lineWidth = 1.3;
        var b = rings(ctx, t.body || [], X, Y, z, x, flip);
        ctx.fill(b, 'nonzero');
        ctx.stroke(b);
        var e = rings(ctx, t.edge || [], X, Y, z, x, flip);
        ctx.fillStyle = 'rgba(224,33,138,0.25)';
        ctx.strokeStyle = '#e0218a';
        ctx.fill(e, 'nonzero');
        ctx.stroke(e);
      }
      // a gouge's checked remedy: its tool dashed where the tool that gouged stands
      var rt = data.remedy_tools || [];
      ctx.strokeStyle = '#1a7f37';
      ctx.lineWidth = 1.6;
      ctx.setLineDash([5, 3]);
      for (var g = 0; g < rt.length; g++) {
        if (rt[g][0] === m[2]) { ctx.stroke(rings(ctx, rt[g][1], X, Y, z, x, x < 0)); }
      }
      ctx.setLineDash([]);
      var ct = data.crash_tools || [];
      ctx.strokeStyle = (data.style && data.style.crash) || '#7b3fe4';
      ctx.lineWidth = 2.2;
      for (var i = 0; i < ct.length; i++) {
        if (ct[i][0] === m[2]) { ctx.stroke(rings(ctx, ct[i][1], X, Y, 0, 0, false)); }
      }
      ctx.restore();
    }
  };
})();
