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
//!
//! GSK 980TD (spec/dialects.md §4.6, only under `gsk980`): `J` and `K` give the run-out, the
//! pull-out's travel in X (radius) and in Z, unsigned (its direction follows the start
//! point; K omitted or 0 is J); `L` the number of starts, 1–99. **Interpretation:** J, K and L
//! stay in force for the cycle's modal repeats (like X, Z, R and F; GSK calls them modal)
//! and a new G92 block starts without them; a block with L cuts every start at its depth
//! in turn, the n-th shifted n/L of the lead (after Q's shift), as one pass each (in X,
//! thread, out X, back Z).

use super::{thread_start_angle, Cycle, Move, Output};
use crate::codes::G92;
use crate::{Diagnostic, Motion, Pt};

/// GSK's G92 J K L (spec/dialects.md §4.6).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct GskWords {
    /// The run-out (J in X as a radius, K in Z), mm; `None`: none given.
    runout: Option<(f64, f64)>,
    /// Number of starts (L), at least 1 once read; 0: not given (one start).
    starts: u32,
}

/// Expand one G92 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    let w = c.turn_words(G92)?;
    let has_q = c.words.has('Q');
    let start_angle = thread_start_angle(c.words)?;
    let gsk = gsk_words(c)?;
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
    let out = match gsk.runout {
        Some((j, k)) => runout(c, a, end, r, j, k)?,
        None => pull_out(c, a, end, r),
    };
    let starts = gsk.starts.max(1);
    let mut moves = Vec::with_capacity(5 * starts as usize);
    for n in 0..starts {
        let phase = start_angle / 360.0 + f64::from(n) / f64::from(starts);
        let thread = |to: Pt| Move {
            motion: Motion::Thread,
            phase: Some(phase),
            ..Move::feed(to)
        };
        moves.push(Move::rapid(Pt::new(a.z, end.r + r))); // ① X rapid to the thread start
        match out {
            // ② thread to γ before the end, on the taper, then the pull-out to the end Z
            Some((corner, out)) => moves.extend([thread(corner), thread(out)]),
            // ② thread to the end point, F = lead
            None => moves.push(thread(end)),
        }
        moves.push(Move::rapid(Pt::new(end.z, a.r))); // ③ X rapid out to the start X
        moves.push(Move::rapid(a)); // ④ Z rapid back to the start point
    }
    Ok(Output {
        moves,
        warnings,
        thread_phase: start_angle / 360.0,
        ..Output::default()
    })
}

/// The GSK words of this block (J K L under `gsk980`, else left for the unused-word
/// alarm), or those of the block this one repeats.
fn gsk_words(c: &mut Cycle) -> Result<GskWords, Diagnostic> {
    if c.machine.control != crate::Control::Gsk980 {
        return Ok(GskWords::default());
    }
    let mut words = if c.g.is_none() {
        c.retained.g92_gsk
    } else {
        GskWords::default()
    };
    let unsigned = |c: &mut Cycle, letter: char| -> Result<Option<f64>, Diagnostic> {
        let Some(word) = c.words.take(letter) else {
            return Ok(None);
        };
        let v = word.value * c.unit;
        if !(v >= 0.0 && v.is_finite()) {
            return Err(Diagnostic::new(
                word.span,
                "LS-G92-RUNOUT",
                format!(
                    "{letter}{} is not a thread run-out: J and K are amounts without a sign",
                    word.value
                ),
                "write the run-out as a positive amount; its direction follows the start point",
            ));
        }
        Ok(Some(v))
    };
    let j = unsigned(c, 'J')?;
    let k = unsigned(c, 'K')?;
    if j.is_some() || k.is_some() {
        let j = j.or(words.runout.map(|r| r.0)).unwrap_or(0.0);
        let k = k.or(words.runout.map(|r| r.1)).unwrap_or(0.0);
        // J 0: no run-out; K omitted or 0: K = J
        words.runout = (j > 0.0).then_some((j, if k > 0.0 { k } else { j }));
    }
    if let Some(l) = c.words.take('L') {
        if !crate::words::whole_in(l, 1.0, 99.0) {
            return Err(Diagnostic::new(
                l.span,
                "LS-G92-STARTS",
                format!("L{} is not a number of starts: L is a whole number 1–99", l.value),
                "write the number of starts without a decimal point, e.g. L2 for a two-start thread",
            ));
        }
        words.starts = l.value as u32;
    }
    c.retained.g92_gsk = words;
    Ok(words)
}

/// GSK's run-out: the thread runs to `k` before the end Z (on the taper), then out to the
/// end Z moved `j` away from the thread's depth toward the start X, still threading.
fn runout(
    c: &Cycle,
    a: Pt,
    end: Pt,
    taper: f64,
    j: f64,
    k: f64,
) -> Result<Option<(Pt, Pt)>, Diagnostic> {
    let travel = (a.z - end.z).abs();
    if k >= travel {
        return Err(c.alarm(
            "LS-G92-RUNOUT",
            format!("the run-out K{k:.3} is not shorter than the thread's Z travel {travel:.3}"),
            "give a smaller K (or J), or start the cycle further from the end point",
        ));
    }
    Ok(Some(chamfer(a, end, taper, k, j)))
}

/// The pull-out: on a Haas under M23, γ = Setting 95 leads at Setting 96°; elsewhere the
/// profile's `g92_chamfer_leads` at 45° (spec/dialects.md §4.7). `None`: no chamfer, or a
/// thread too short for it (then it threads to the end).
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
    Some(chamfer(
        a,
        end,
        taper,
        gamma,
        gamma * theta.to_radians().tan(),
    ))
}

/// Where the thread leaves the taper, `along` before the end Z, and where the pull-out
/// ends: at the end Z moved `out` away from the thread's depth toward the start X.
fn chamfer(a: Pt, end: Pt, taper: f64, along: f64, out: f64) -> (Pt, Pt) {
    let travel = (a.z - end.z).abs();
    let toward_start = (a.z - end.z).signum();
    // on the thread line from its start (at end.r + R) to the end point
    let corner_r = end.r + taper * along / travel;
    let outward = if a.r > end.r { 1.0 } else { -1.0 };
    (
        Pt::new(end.z + toward_start * along, corner_r),
        Pt::new(end.z, end.r + outward * out),
    )
}
