//! What the feeds that cut features (a blade's, a drill's) swept of the part that is gone:
//! judged apart from the rest. Part material gone in one piece may be a real gouge beside a
//! groove a later blade cut into it: judged as one region, the groove's depth was the
//! gouge's and its LS-LATER-CUT note was lost (field run 8, B: a skim 0.4 too deep read
//! 1.9 mm at the groove's bottom), and a part-off slot joined an OD no contour states to the
//! bore contour it reaches (field run 8, A: a certain 3 mm gouge on a plain bush).

use expander::{Motion, Segment};
use geom::flat::pts;
use geom::Rect;
use stock::{boolean, float_sweep, move_path, BoolOp, Mounts, Shape, Tool, ToolTable};

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

/// The union of the sweeps of the feature-cutting feeds (not thread passes: a thread's
/// band is left out of every zone already) that reach the box of `gone`.
pub(super) fn sweeps(
    gone: &[Shape],
    segments: &[Segment],
    tools: &ToolTable,
    mounts: &mut Mounts,
    chord_tol: f64,
) -> Vec<Shape> {
    let features = |s: &Segment| s.motion == Motion::Feed && cuts_features(s, tools);
    feed_sweeps(gone, segments, mounts, chord_tol, &features)
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
        if !super::blame::may_sweep_over(&bx, seg, outline) {
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
