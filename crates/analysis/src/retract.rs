//! Retract scrapes (spec/simulation.md, "Retract scrapes"): a rapid that leaves the end of
//! the same tool's feed straight along the side of its leading edge, within the edge's own
//! lean (κr − 90°) plus 1°, and removes only the wedge that edge left on the shoulder it
//! just cut. The edge runs almost along itself and re-touches a surface it made a moment
//! before: a warning with the fix, never a crash, whatever its depth (a 95° holder leaves
//! 0.44 mm on a 5 mm shoulder).

use crate::findings::{Crash, Note};
use expander::{Motion, Segment, ToolHint};
use stock::{Tool, ToolTable};

/// Slack on the edge's lean, degrees (the spec's "plus 1°").
const LEAN_SLACK_DEG: f64 = 1.0;

/// The lean of the leading edge of the turning tool that cuts `seg`, and its direction
/// from the cutting corner in the programmed frame (mirrored for a rear post); `None` for
/// other tools, holders of 90° or less, and tips without a leading edge along Z (0, 5–9).
fn leading_edge(seg: &Segment, tools: &ToolTable, rear: bool) -> Option<(f64, [f64; 2])> {
    if seg.hint != ToolHint::Table {
        return None;
    }
    let tool = tools.tool_or_default(seg.tool).clone();
    let Tool::Turning {
        tip,
        entering_angle,
        ..
    } = tool
    else {
        return None;
    };
    let lean = entering_angle - 90.0;
    if lean <= 0.0 {
        return None;
    }
    // tip 3 leaves the corner at 180° − κr from +Z; 2, 4, 1 mirror it in r, z, both
    let a = (180.0 - entering_angle).to_radians();
    let (z, r) = (a.cos(), a.sin());
    let (z, r) = match tip {
        3 => (z, r),
        2 => (z, -r),
        4 => (-z, r),
        1 => (-z, -r),
        _ => return None,
    };
    Some((lean, [z, if rear { -r } else { r }]))
}

/// Whether the rapid crash `c` (its cutting outline, no workholding) is a retract scrape.
pub(crate) fn is_retract(c: &Crash, segments: &[Segment], tools: &ToolTable, rear: &[u32]) -> bool {
    if c.body.is_some() || c.obstacle.is_some() || c.segment == 0 {
        return false;
    }
    let (prev, seg) = (&segments[c.segment - 1], &segments[c.segment]);
    let after_its_feed = seg.motion == Motion::Rapid
        && prev.motion == Motion::Feed
        && (prev.tool, prev.hint) == (seg.tool, seg.hint)
        && prev.to == seg.from;
    if !after_its_feed {
        return false;
    }
    let Some((lean, edge)) = leading_edge(seg, tools, rear.contains(&seg.tool)) else {
        return false;
    };
    let d = seg.to - seg.from;
    let len = d.len();
    if seg.arc.is_some() || len == 0.0 {
        return false;
    }
    let limit = (lean + LEAN_SLACK_DEG).to_radians();
    let along = ((d.z * edge[0] + d.r * edge[1]) / len)
        .clamp(-1.0, 1.0)
        .acos();
    // only a wedge: a thin triangle from the corner, its width across the move at most
    // tan(lean + 1°) of its length (width² / (2 · area) = the tangent of its angle)
    let wedge = c.area > 0.0 && c.depth * c.depth / (2.0 * c.area) <= limit.tan();
    along <= limit && wedge
}

/// The warning of a retract scrape, with its fix.
pub(crate) fn note(c: &Crash, segments: &[Segment], tools: &ToolTable) -> Note {
    let seg = &segments[c.segment];
    let kr = match *tools.tool_or_default(seg.tool) {
        Tool::Turning { entering_angle, .. } => entering_angle,
        _ => 90.0,
    };
    Note {
        span: seg.span,
        code: "LS-RETRACT-SCRAPE",
        message: format!(
            "retract scrapes {:.3} mm deep ({:.4} mm² of stock) at Z{:.3} X{:.3}: the leading edge of the {kr}° holder re-touches the {}° wedge it left on the shoulder it just cut (not a crash); retract at 45°, or feed out along the shoulder, as G71 does",
            c.depth,
            c.area,
            c.at[0],
            2.0 * c.at[1],
            kr - 90.0
        ),
    }
}
