//! G74 face grooving / peck drilling and G75 radial grooving (seed 002, spec/cycles.md).
//!
//! ```text
//! G75 R(e);                                   retract block: e is retained
//! G75 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F;          cycle block
//! ```
//! G74 is G75 with the axes swapped. Both are written here once, in the cycle's own axes:
//! the **infeed** axis (G75: X, G74: Z) along which the tool pecks, and the **shift** axis
//! (G75: Z, G74: X) along which it moves between plunges. Δi and Δk are unsigned, in least
//! input increments (`Machine::pq_mm`), Δi a radius.
//!
//! Choices where the seed is silent (what a FANUC 0i-TF user expects):
//! - With no `G7x R(e)` block yet, e = 0: each peck feeds straight on (no chip break).
//! - The escape Δd is a feed along the shift axis, back toward the side already cut; it is
//!   skipped on the first plunge, where the side behind the tool is still uncut material.
//! - A block with any of X U Z W P Q is the cycle block; one with only R is the retract block.
//! - A cycle with no infeed travel (G75 without X/U or with U0; G74 without Z/W) cuts nothing
//!   and is an alarm rather than a silent no-op.
//!
//! Haas one block (spec/dialects.md §3.4): `G7x X(U) Z(W) I K D F`, the same motion with
//! I ≙ P(Δi) and K ≙ Q(Δk) in mm (calculator type, not increments), D ≙ R(Δd) the escape,
//! and the chip-break retract e from the profile (`haas.peck_retract`, Haas has no
//! `G7x R(e)` block). P/Q under `haas` and I/K under the other controls are alarms naming
//! the form.

use super::{Cycle, Move, Output, MAX_MOVES};
use crate::{Diagnostic, Pt, ToolHint};

/// Expand one G74/G75 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let g74 = c.code == 740;
    let name = if g74 { "G74" } else { "G75" };
    let haas = c.machine.control == crate::Control::Haas;
    let foreign = if haas {
        ['P', 'Q', 'R']
    } else {
        ['I', 'K', 'D']
    };
    if let Some(w) = foreign.iter().find_map(|&l| c.words.block.get(l)) {
        return Err(Diagnostic::new(
            w.span,
            "LS-ONE-BLOCK-FORM",
            if haas {
                format!("{} is not a Haas {name} word", w.letter)
            } else {
                format!(
                    "{name} with {} is the Haas one-block form: run with --control haas (this control is {})",
                    w.letter,
                    c.machine.control.key()
                )
            },
            if haas {
                format!("Haas writes {name} X(U) Z(W) I K D F with I, K, D in mm; the retract is haas.peck_retract")
            } else {
                format!("write {name} R(e); {name} X(U) Z(W) P(Δi) Q(Δk) R(Δd) F")
            },
        ));
    }
    let is_cycle_block = ['X', 'U', 'Z', 'W', 'P', 'Q', 'I', 'K']
        .iter()
        .any(|&l| c.words.has(l));
    if !is_cycle_block && !haas {
        // The retract block `G7x R(e);`: e is retained for the following cycle blocks.
        let Some(e) = c.words.mm('R', c.unit) else {
            return Err(c.alarm(
                "LS-G75-FORMAT",
                format!("{name} without R(e) or the cycle words"),
                format!("write {name} R(e); then {name} X(U) Z(W) P(Δi) Q(Δk) F;"),
            ));
        };
        if e < 0.0 {
            return Err(c.alarm(
                "LS-G75-E",
                format!("{name} retract R(e) = {e} is negative"),
                "e is an unsigned retract distance, e.g. R0.3",
            ));
        }
        c.retained.peck_retract = Some(e);
        return Ok(Output::default());
    }

    // -- the cycle block's words.
    let x = c.x_target()?;
    let z = c.z_target()?;
    let pq = c.machine.pq_mm();
    let (p, q, escape, e) = if haas {
        (
            c.words.mm('I', c.unit),
            c.words.mm('K', c.unit),
            c.words.mm('D', c.unit).unwrap_or(0.0),
            c.machine.haas.peck_retract,
        )
    } else {
        (
            c.words.increments('P', pq)?,
            c.words.increments('Q', pq)?,
            c.words.mm('R', c.unit).unwrap_or(0.0),
            c.retained.peck_retract.unwrap_or(0.0),
        )
    };
    let (p_word, q_word) = if haas { ('I', 'K') } else { ('P', 'Q') };
    let a = c.start;
    let end = Pt::new(z.unwrap_or(a.z), x.unwrap_or(a.r));

    // Axes of the cycle: (infeed, shift) coordinates of a point, and back.
    let split = |p: Pt| if g74 { (p.z, p.r) } else { (p.r, p.z) };
    let join = |d: f64, s: f64| if g74 { Pt::new(d, s) } else { Pt::new(s, d) };
    let (d0, s0) = split(a);
    let (d1, s1) = split(end);
    // G75: infeed Δi (P) along X, shift Δk (Q) along Z; G74: infeed Δk (Q), shift Δi (P).
    let (in_step, shift_step) = if g74 { (q, p) } else { (p, q) };
    let (in_word, shift_word) = if g74 {
        (q_word, p_word)
    } else {
        (p_word, q_word)
    };
    let (in_axis, shift_axis) = if g74 { ("Z", "X") } else { ("X", "Z") };
    let in_travel = (d1 - d0).abs();
    let shift_travel = (s1 - s0).abs();
    let tiny = 1e-9;

    // -- alarms of seed 002 §6.
    if in_travel <= tiny {
        return Err(c.alarm(
            "LS-G75-NO-DEPTH",
            format!("{name} has no {in_axis} travel: the end {in_axis} equals the start"),
            format!("give the bottom of the cut with {in_axis} (or its incremental word); the start is the tool position when {name} is read"),
        ));
    }
    // ② / ③ a step negative.
    for (step, word) in [(in_step, in_word), (shift_step, shift_word)] {
        if step.is_some_and(|v| v < 0.0) {
            return Err(c.alarm(
                "LS-G75-STEP",
                format!("{name}: {word} is negative"),
                format!("{word} is unsigned; the direction comes from the start and end points"),
            ));
        }
    }
    // ① X(U) or Z(W) given while the step it needs is missing or 0.
    let Some(in_step) = in_step.filter(|&v| v > 0.0) else {
        return Err(c.alarm(
            "LS-G75-STEP",
            format!("{name}: the {in_axis} step {in_word} is missing or 0"),
            format!("give {in_word} as the depth of each peck in least input increments, e.g. {in_word}1500 for 1.5 mm"),
        ));
    };
    let shift_step = if shift_travel <= tiny {
        0.0 // no shift travel: the step is not needed
    } else {
        let Some(v) = shift_step.filter(|&v| v > 0.0) else {
            return Err(c.alarm(
                "LS-G75-STEP",
                format!("{name}: {shift_axis} travels {shift_travel:.4} mm but the shift {shift_word} is missing or 0"),
                format!("give {shift_word} as the {shift_axis} shift between plunges in least input increments, e.g. {shift_word}2000 for 2 mm"),
            ));
        };
        v
    };
    // ② / ③ a step larger than its travel.
    for (step, word, axis, travel) in [
        (in_step, in_word, in_axis, in_travel),
        (shift_step, shift_word, shift_axis, shift_travel),
    ] {
        if travel > tiny && step > travel + tiny {
            return Err(c.alarm(
                "LS-G75-STEP",
                format!("{name}: {word} = {step} mm is larger than the {axis} travel {travel:.4} mm"),
                format!("make {word} at most the {axis} travel (a radius for X), or check the end point"),
            ));
        }
    }
    // ④ the retract larger than the peck: an error in R(e) the program wrote; on a Haas
    // the retract is the machine's setting, and a peck smaller than it runs (issue 31:
    // `G75 X0 I0.005` in inch): each retract then stops at the start of the infeed.
    let mut warnings = vec![];
    if e > in_step + tiny && haas {
        warnings.push(c.alarm(
            "LS-G75-E",
            format!("{name}: the retract haas.peck_retract = {e} mm is larger than the peck {in_word} = {in_step} mm: each peck retracts further than it cut"),
            "set haas.peck_retract in the machine profile to this machine's setting",
        ));
    } else if e > in_step + tiny {
        return Err(c.alarm(
            "LS-G75-E",
            format!(
                "{name}: the retract e = {e} mm is larger than the peck {in_word} = {in_step} mm"
            ),
            format!("make R(e) in the {name} R block smaller than {in_word}, or the pecks larger"),
        ));
    }
    if escape < 0.0 {
        return Err(c.alarm(
            "LS-G75-ESCAPE",
            format!("{name}: the escape R(Δd) = {escape} is negative"),
            "Δd is unsigned: the escape goes back toward the side already cut",
        ));
    }

    // -- step counts, bounded before anything is built.
    let pecks = (in_travel / in_step - tiny).ceil().max(1.0);
    let plunges = if shift_travel > tiny {
        (shift_travel / shift_step - tiny).ceil() + 1.0
    } else {
        1.0
    };
    let estimate = plunges * (2.0 * pecks + 3.0) + 1.0;
    if estimate > MAX_MOVES as f64 {
        return Err(c.alarm(
            "LS-CYCLE-TOO-LONG",
            format!(
                "{name} would make about {estimate:.0} moves ({plunges:.0} plunges of {pecks:.0} pecks), more than {MAX_MOVES}"
            ),
            format!("check {in_word} and {shift_word}: they are in least input increments ({pq} mm), so {in_word}1 is {pq} mm"),
        ));
    }
    let (pecks, plunges) = (pecks as usize, plunges as usize);
    let (dir_d, dir_s) = ((d1 - d0).signum(), (s1 - s0).signum());

    let mut moves = Vec::with_capacity(estimate as usize);
    let mut push = |m: Move| {
        moves.push(Move {
            hint: ToolHint::Grooving,
            ..m
        })
    };
    for n in 0..plunges {
        // ⑤ the plunge positions: Δk apart, the last exactly at the end point.
        let s = if n + 1 == plunges {
            s1
        } else {
            s0 + dir_s * shift_step * n as f64
        };
        if n > 0 {
            push(Move::rapid(join(d0, s)));
        }
        // ①–③ pecks: feed Δi, rapid back e, feed Δi + e, …; the last feed stops at the bottom.
        for k in 1..=pecks {
            let bottom = if k == pecks {
                d1
            } else {
                d0 + dir_d * in_step * k as f64
            };
            push(Move::feed(join(bottom, s)));
            if k < pecks && e > 0.0 {
                // never back past the start of the infeed (a retract larger than the cut)
                let back = e.min((bottom - d0).abs());
                push(Move::rapid(join(bottom - dir_d * back, s)));
            }
        }
        // Escape Δd at the bottom, back toward the side already cut.
        let s_out = if escape > 0.0 && n > 0 {
            let s_out = s - dir_s * escape;
            push(Move::feed(join(d1, s_out)));
            s_out
        } else {
            s
        };
        // ④ rapid back to the start of the infeed axis.
        push(Move::rapid(join(d0, s_out)));
    }
    // ⑥ back to the start point A along the shift axis.
    push(Move::rapid(a));
    Ok(Output {
        moves,
        warnings,
        ..Output::default()
    })
}
