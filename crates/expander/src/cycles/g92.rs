//! G92 — threading cycle, straight or tapered (spec/cycles.md, "G92 / G32 / G76").
//!
//! `G92 X(U) Z(W) [R] F(lead);` the threading analogue of G90: rapid in X to the thread
//! start, cut the thread to the end point at one lead per revolution, rapid out in X, rapid
//! back in Z. Modal like G90: later blocks give only the words that change (a new X for
//! each depth). R is the radius difference thread start minus thread end (taper).
//! Q is the start angle of this block only (multi-start, spec/dialects.md §4.7): a modal
//! repeat without Q after a block with Q ≠ 0 threads at 0°, with a warning.
//!
//! With a pull-out chamfer each pass ends like G76's: on a Haas under M23 (the power-on
//! state; spec/dialects.md §3.5: M23/M24 switch it for G76 and G92) the thread runs to
//! Setting 95 leads before the end point (on the taper), then out at Setting 96° to the end
//! Z, away from the axis on an OD thread (toward it in a bore), still threading; on other
//! controls the profile's `g92_chamfer_leads` at 45° (§4.7, default none).

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
    let thread = |to: Pt| Move {
        motion: Motion::Thread,
        ..Move::feed(to)
    };
    let mut moves = vec![Move::rapid(Pt::new(a.z, end.r + r))]; // ① X rapid to the thread start
    match pull_out(c, a, end, r) {
        // ② thread to γ before the end, on the taper, then the pull-out to the end Z
        Some((corner, out)) => moves.extend([thread(corner), thread(out)]),
        // ② thread to the end point, F = lead
        None => moves.push(thread(end)),
    }
    moves.push(Move::rapid(Pt::new(end.z, a.r))); // ③ X rapid out to the start X
    moves.push(Move::rapid(a)); // ④ Z rapid back to the start point
    Ok(Output {
        moves,
        warnings,
        thread_phase: start_angle / 360.0,
        ..Output::default()
    })
}

/// The pull-out: on a Haas under M23, γ = Setting 95 leads at Setting 96°; elsewhere the
/// profile's `g92_chamfer_leads` at 45° (spec/dialects.md §4.7). Where the thread leaves
/// the taper, γ before the end Z, and where the chamfer ends, at the end Z moved γ·tan θ
/// away from the thread's depth toward the start X. `None`: no chamfer, or a thread too
/// short for it (then it threads to the end).
fn pull_out(c: &Cycle, a: Pt, end: Pt, taper: f64) -> Option<(Pt, Pt)> {
    let (leads, theta) = if c.machine.control == crate::Control::Haas {
        let h = c.machine.haas;
        (
            if c.thread_chamfer { h.setting95 } else { 0.0 },
            h.setting96,
        )
    } else {
        (c.machine.g92_chamfer_leads, 45.0)
    };
    let gamma = leads * c.feed_mm;
    let travel = (a.z - end.z).abs();
    if !(gamma > 0.0 && gamma < travel && theta > 0.0 && theta < 90.0) {
        return None;
    }
    let toward_start = (a.z - end.z).signum();
    // on the thread line from its start (at end.r + R) to the end point
    let corner_r = end.r + taper * gamma / travel;
    let outward = if a.r > end.r { 1.0 } else { -1.0 };
    let pull_out = gamma * theta.to_radians().tan();
    Some((
        Pt::new(end.z + toward_start * gamma, corner_r),
        Pt::new(end.z, end.r + outward * pull_out),
    ))
}
