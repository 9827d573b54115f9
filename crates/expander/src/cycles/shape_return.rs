//! The return at the end of a Haas G71/G72 finishing shape (issue 31, docs/field-rules.md).
//!
//! Haas's own lathe tutorials end the shape by leaving the part and going back to the
//! start: `… Z-2.0 / G00 X1.6 / N20 G00 G40 Z0.1` (start point X1.6 Z0.1). A Haas runs it;
//! read as profile, the shape would end where it began and not travel in Z (PS064). The
//! trailing G00 moves that lie wholly at or outside the start level (X at or beyond the
//! start X for G71, Z at or beyond the start Z for G72) are the return: the roughing cycle
//! ends its final pass where the shape last reaches the start level and rapids back to the
//! start point itself. FANUC and GSK alarm on such a shape (their manuals require the shape
//! to be monotonic from B to C), so the rule is Haas's only.

use super::contour::FinishingShape;
use crate::{Diagnostic, Pt};

/// Tolerance for "at the start level", mm.
const EPS: f64 = 1e-6;

/// The shape without its trailing return moves, and the warning that says which blocks
/// were read as the return (`None` when the shape has none).
pub(super) fn trim(mut shape: FinishingShape, g72: bool) -> (FinishingShape, Option<Diagnostic>) {
    let a = shape.start;
    let b = shape.b();
    // depth into the material from the start level, positive inside
    let depth = |p: Pt| {
        if g72 {
            (p.z - a.z) * (b.z - a.z).signum()
        } else {
            (p.r - a.r) * (b.r - a.r).signum()
        }
    };
    let mut keep = shape.elements.len();
    while keep > 2 {
        let e = &shape.elements[keep - 1];
        if !(e.rapid && e.arc.is_none() && depth(e.from) <= EPS && depth(e.to) <= EPS) {
            break;
        }
        keep -= 1;
    }
    if keep == shape.elements.len() {
        return (shape, None);
    }
    let first = shape.elements[keep].span;
    shape.elements.truncate(keep);
    let axis = if g72 { "Z" } else { "X" };
    let warning = Diagnostic::new(
        first,
        "LS-SHAPE-RETURN",
        format!(
            "the shape's last G00 moves, from line {} on, stay at or beyond the start {axis}: read as the return to the start point, not as part of the finishing shape (Haas)",
            first.line
        ),
        "end the shape where it leaves the part (FANUC and GSK alarm on a shape that turns back)",
    );
    (shape, Some(warning))
}
