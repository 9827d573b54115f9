//! G92 — threading cycle, straight or tapered (spec/cycles.md, "G92 / G32 / G76").
//!
//! `G92 X(U) Z(W) [R] F(lead);` the threading analogue of G90: rapid in X to the thread
//! start, cut the thread to the end point at one lead per revolution, rapid out in X, rapid
//! back in Z. Modal like G90: later blocks give only the words that change (a new X for
//! each depth). R is the radius difference thread start minus thread end (taper).
//! Q is the start angle of this block only (multi-start, spec/dialects.md §4.7): a modal
//! repeat without Q after a block with Q ≠ 0 threads at 0°, with a warning.

use super::{thread_start_angle, Cycle, Move, Output};
use crate::codes::G92;
use crate::{Diagnostic, Motion, Pt};

/// Expand one G92 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    let w = c.turn_words(G92)?;
    let has_q = c.words.has('Q');
    let start_angle = thread_start_angle(c.words)?;
    let mut warnings = vec![];
    if c.g.is_none() && !has_q && c.retained.g92_shifted {
        warnings.push(Diagnostic::new(
            c.words.span(),
            "LS-THREAD-Q-NOT-MODAL",
            "this G92 repeat has no Q: it threads at 0°, not at the start angle of the block before (Q is not modal)",
            "repeat the Q word on every pass of a shifted start",
        ));
    }
    c.retained.g92_shifted = start_angle != 0.0;
    let a = c.start;
    let (end, r) = (w.end, w.r);
    let mut thread = Move::feed(end);
    thread.motion = Motion::Thread;
    Ok(Output {
        moves: vec![
            Move::rapid(Pt::new(a.z, end.r + r)), // ① X rapid to the thread start
            thread,                               // ② thread to the end point, F = lead
            Move::rapid(Pt::new(end.z, a.r)),     // ③ X rapid out to the start X
            Move::rapid(a),                       // ④ Z rapid back to the start point
        ],
        warnings,
        thread_phase: start_angle / 360.0,
        ..Output::default()
    })
}
