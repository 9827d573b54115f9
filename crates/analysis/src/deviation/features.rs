//! What the feeds that cut features (a blade's, a drill's) swept of the part that is gone:
//! judged apart from the rest. Part material gone in one piece may be a real gouge beside a
//! groove a later blade cut into it: judged as one region, the groove's depth was the
//! gouge's and its LS-LATER-CUT note was lost (field run 8, B: a skim 0.4 too deep read
//! 1.9 mm at the groove's bottom), and a part-off slot joined an OD no contour states to the
//! bore contour it reaches (field run 8, A: a certain 3 mm gouge on a plain bush).

use crate::sweeps::{cuts_features, feed_sweeps};
use expander::{Motion, Segment};
use stock::{Mounts, Shape, ToolTable};

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
