//! G70 — finishing cycle (spec/cycles.md).
//!
//! `G70 P(ns) Q(nf);` runs the finishing shape with its own F (an F inside ns..nf holds
//! from its block on; before the first one, the F in force at G70), then rapids back to
//! the start point. Moves carry the span of their shape block.
//!
//! S, T and G96–G99 inside the shape are put in force from their block on.
//! G41/G42 in the shape (or in force at G70) compensate the pass: the move A → B is the
//! start-up, the rapid back to A the cancel (spec/tnrc.md). The program continues
//! after nf when the shape follows the G70 block in the program's flow, else after the
//! G70 block (FANUC; a shape kept after M30 is not in the flow).

use super::{contour, passes};
use super::{Cycle, Move, Output};
use crate::Diagnostic;

/// Expand one G70 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let mut shape = contour::read(c)?;
    // ① the shape A → B → C as written, each element with its own motion and F
    let mut moves = passes::finishing(&shape);
    // ② rapid back to the start point A
    moves.push(Move::rapid(shape.start));
    let mut out = Output {
        moves,
        resume_at: shape.resume_at(c.index, &c.program.blocks),
        warnings: std::mem::take(&mut shape.notes),
        comp: Some(shape.comp),
        comp_from: if shape.comp.is_some() {
            shape.comp_from
        } else {
            0
        },
        ..Output::default()
    };
    out.intended.push((
        crate::IntendedKind::FinishingContour,
        intended(shape, c.machine.control).intended_path(0.001),
    ));
    Ok(out)
}

/// The shape the pass finishes to: on a Haas, without the return its last G00 moves make
/// to the start level (docs/field-rules.md §3), as G71/G72 read it. The pass runs the
/// return as written; kept in the intended shape, its run back along the bar's diameter
/// closed the part against the roughed stock and left a band W wide out of it, a
/// leftover through the part's core (field run: 18 of 33 Haas programs end their shapes
/// so). The ns block tells G71's shape (X given) from G72's (Z alone).
fn intended(shape: contour::FinishingShape, control: crate::Control) -> contour::FinishingShape {
    if control != crate::Control::Haas {
        return shape;
    }
    let g72 = shape.ns_moves == (false, true);
    super::shape_return::trim(shape, g72).0
}
