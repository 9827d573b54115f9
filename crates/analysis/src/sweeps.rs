//! The sweeps of moves near a region: which feeds cut features (a blade's, a drill's, a
//! threading tool's), whether a move's sweep may reach a box, and the union of the sweeps
//! of the moves a rule takes: the deviation's split of what feature cuts swept of gone
//! part material, and its gouges' makers.

use expander::{Motion, Segment};
use geom::flat::pts;
use geom::Rect;
use stock::{boolean, float_sweep, move_path, BoolOp, Mounts, Outline, Shape, Tool, ToolTable};

/// Whether `seg` is a feed of a tool that cuts features: a blade (or a grooving cycle's
/// move), a drill, a threading tool (its own grooves, holes and reliefs).
pub(crate) fn cuts_features(seg: &Segment, tools: &ToolTable) -> bool {
    seg.motion != Motion::Rapid
        && (tools.blade_cuts(seg)
            || matches!(
                tools.tool_or_default(seg.tool),
                Tool::Drill { .. } | Tool::Threading { .. }
            ))
}

/// Whether the sweep of `seg` may reach the box `bb` (false only when it surely does not).
pub(crate) fn may_sweep_over(bb: &Rect, seg: &Segment, outline: &Outline) -> bool {
    let Some((lo, hi)) = outline.bbox() else {
        return false;
    };
    let (sz0, sz1) = (seg.from.z.min(seg.to.z), seg.from.z.max(seg.to.z));
    let (sr0, sr1) = (seg.from.r.min(seg.to.r), seg.from.r.max(seg.to.r));
    // arcs may bulge beyond their end points by up to their radius
    let bulge = seg.arc.map_or(0.0, |a| a.center.dist(seg.from));
    // (a sweep reaching below the axis is folded: only its Z range is known beforehand)
    let folded = sr0 + lo[1] - bulge < 0.0;
    !(sz1 + hi[0] + bulge < bb.min.z
        || sz0 + lo[0] - bulge > bb.max.z
        || (!folded && (sr1 + hi[1] + bulge < bb.min.r || sr0 + lo[1] - bulge > bb.max.r)))
}

/// The union of the sweeps of the moves `which` takes that reach the box of `region`.
pub(crate) fn feed_sweeps(
    region: &[Shape],
    segments: &[Segment],
    mounts: &mut Mounts,
    chord_tol: f64,
    which: &dyn Fn(&Segment) -> bool,
) -> Vec<Shape> {
    let Some(bx) = region
        .iter()
        .map(|s| Rect::of(pts(&s.outer)))
        .reduce(|a, b| a.union(&b))
    else {
        return vec![];
    };
    let mut parts: Vec<Shape> = vec![];
    for seg in segments.iter().filter(|s| which(s)) {
        let mounted = mounts.of(seg);
        let outline = &mounted.edge;
        if !may_sweep_over(&bx, seg, outline) {
            continue;
        }
        parts.extend(
            float_sweep(outline, &move_path(seg, chord_tol))
                .into_iter()
                .map(|outer| Shape {
                    outer,
                    holes: vec![],
                }),
        );
    }
    if parts.is_empty() {
        return parts;
    }
    boolean(&parts, &[], BoolOp::Union)
}
