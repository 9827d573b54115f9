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
use crate::codes::G74;
use crate::{Diagnostic, Pt, ToolHint};

/// Expand one G74/G75 block: the retract block stores e; the cycle block runs.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let axes = Axes::of(c.code == G74);
    let haas = c.machine.control == crate::Control::Haas;
    reject_other_form(c, &axes, haas)?;
    let is_cycle_block = ['X', 'U', 'Z', 'W', 'P', 'Q', 'I', 'K']
        .iter()
        .any(|&l| c.words.has(l));
    if !is_cycle_block && !haas {
        retract_block(c, axes.name)?;
        return Ok(Output::default());
    }
    let words = read(c, haas)?;
    let mut warnings = vec![];
    let params = plan(c, &axes, &words, haas, &mut warnings)?;
    Ok(Output {
        moves: moves(&axes, &params),
        warnings,
        ..Output::default()
    })
}

/// The cycle's own axes: the **infeed** axis (G75: X, G74: Z) along which the tool pecks,
/// the **shift** axis (G75: Z, G74: X) along which it moves between plunges, and the names
/// the messages give them.
struct Axes {
    g74: bool,
    name: &'static str,
    in_axis: &'static str,
    shift_axis: &'static str,
}

impl Axes {
    fn of(g74: bool) -> Self {
        Self {
            g74,
            name: if g74 { "G74" } else { "G75" },
            in_axis: if g74 { "Z" } else { "X" },
            shift_axis: if g74 { "X" } else { "Z" },
        }
    }

    /// (infeed, shift) coordinates of a point.
    fn split(&self, p: Pt) -> (f64, f64) {
        if self.g74 {
            (p.z, p.r)
        } else {
            (p.r, p.z)
        }
    }

    /// The point of (infeed, shift) coordinates.
    fn join(&self, d: f64, s: f64) -> Pt {
        if self.g74 {
            Pt::new(d, s)
        } else {
            Pt::new(s, d)
        }
    }

    /// G75: infeed Δi (P) along X, shift Δk (Q) along Z; G74: infeed Δk (Q), shift Δi (P).
    /// The pair (p, q) in the order (infeed, shift).
    fn order<T>(&self, p: T, q: T) -> (T, T) {
        if self.g74 {
            (q, p)
        } else {
            (p, q)
        }
    }
}

/// The words of the other control's form are alarms naming the form.
fn reject_other_form(c: &Cycle, axes: &Axes, haas: bool) -> Result<(), Diagnostic> {
    let name = axes.name;
    let foreign = if haas {
        ['P', 'Q', 'R']
    } else {
        ['I', 'K', 'D']
    };
    let Some(w) = foreign.iter().find_map(|&l| c.words.block.get(l)) else {
        return Ok(());
    };
    Err(Diagnostic::new(
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
    ))
}

/// The retract block `G7x R(e);`: e is retained for the following cycle blocks.
fn retract_block(c: &mut Cycle, name: &str) -> Result<(), Diagnostic> {
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
    Ok(())
}

/// The cycle block's words as written, in mm.
struct Words {
    /// The end point.
    end: Pt,
    /// Δi and Δk, as given.
    p: Option<f64>,
    q: Option<f64>,
    /// The escape Δd at the bottom.
    escape: f64,
    /// The chip-break retract e.
    e: f64,
    /// The letters of Δi and Δk in this form.
    p_word: char,
    q_word: char,
}

/// Read the cycle block's words: FANUC `P Q R` in increments with the retained R(e), or
/// Haas `I K D` in mm with the profile's retract.
fn read(c: &mut Cycle, haas: bool) -> Result<Words, Diagnostic> {
    let x = c.x_target()?;
    let z = c.z_target()?;
    let pq = c.machine.pq_mm_under(c.unit);
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
    Ok(Words {
        end: Pt::new(z.unwrap_or(c.start.z), x.unwrap_or(c.start.r)),
        p,
        q,
        escape,
        e,
        p_word,
        q_word,
    })
}

/// The cycle checked and counted, in its own axes.
struct Params {
    /// Start A and end, (infeed, shift).
    d0: f64,
    s0: f64,
    d1: f64,
    s1: f64,
    /// The start point A.
    a: Pt,
    in_step: f64,
    shift_step: f64,
    escape: f64,
    e: f64,
    pecks: usize,
    plunges: usize,
    /// The moves the cycle makes, about.
    estimate: usize,
}

const TINY: f64 = 1e-9;

/// Check the words against the travels (seed 002 §6) and count the steps, bounded before
/// anything is built; a Haas peck under the retract setting is a warning.
fn plan(
    c: &Cycle,
    axes: &Axes,
    w: &Words,
    haas: bool,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Params, Diagnostic> {
    let (d0, s0) = axes.split(c.start);
    let (d1, s1) = axes.split(w.end);
    let (in_step, shift_step) = steps(c, axes, w, (d1 - d0).abs(), (s1 - s0).abs())?;
    let (in_word, _) = axes.order(w.p_word, w.q_word);
    check_retract(c, axes.name, in_word, in_step, w.e, haas, warnings)?;
    if w.escape < 0.0 {
        return Err(c.alarm(
            "LS-G75-ESCAPE",
            format!("{}: the escape R(Δd) = {} is negative", axes.name, w.escape),
            "Δd is unsigned: the escape goes back toward the side already cut",
        ));
    }
    let (pecks, plunges, estimate) = count(
        c,
        axes,
        w,
        (d1 - d0).abs(),
        (s1 - s0).abs(),
        (in_step, shift_step),
    )?;
    Ok(Params {
        d0,
        s0,
        d1,
        s1,
        a: c.start,
        in_step,
        shift_step,
        escape: w.escape,
        e: w.e,
        pecks,
        plunges,
        estimate,
    })
}

/// The infeed and shift steps, checked against the travels: ① a travel given while its
/// step is missing or 0, ②/③ a step negative or larger than its travel.
fn steps(
    c: &Cycle,
    axes: &Axes,
    w: &Words,
    in_travel: f64,
    shift_travel: f64,
) -> Result<(f64, f64), Diagnostic> {
    let name = axes.name;
    let (in_axis, shift_axis) = (axes.in_axis, axes.shift_axis);
    let (in_step, shift_step) = axes.order(w.p, w.q);
    let (in_word, shift_word) = axes.order(w.p_word, w.q_word);
    if in_travel <= TINY {
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
    let shift_step = if shift_travel <= TINY {
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
        if travel > TINY && step > travel + TINY {
            return Err(c.alarm(
                "LS-G75-STEP",
                format!("{name}: {word} = {step} mm is larger than the {axis} travel {travel:.4} mm"),
                format!("make {word} at most the {axis} travel (a radius for X), or check the end point"),
            ));
        }
    }
    Ok((in_step, shift_step))
}

/// ④ the retract larger than the peck: an error in R(e) the program wrote; on a Haas the
/// retract is the machine's setting, and a peck smaller than it runs (issue 31:
/// `G75 X0 I0.005` in inch): each retract then stops at the start of the infeed.
fn check_retract(
    c: &Cycle,
    name: &str,
    in_word: char,
    in_step: f64,
    e: f64,
    haas: bool,
    warnings: &mut Vec<Diagnostic>,
) -> Result<(), Diagnostic> {
    if e > in_step + TINY && haas {
        warnings.push(c.alarm(
            "LS-G75-E",
            format!("{name}: the retract haas.peck_retract = {e} mm is larger than the peck {in_word} = {in_step} mm: each peck retracts further than it cut"),
            "set haas.peck_retract in the machine profile to this machine's setting",
        ));
    } else if e > in_step + TINY {
        return Err(c.alarm(
            "LS-G75-E",
            format!(
                "{name}: the retract e = {e} mm is larger than the peck {in_word} = {in_step} mm"
            ),
            format!("make R(e) in the {name} R block smaller than {in_word}, or the pecks larger"),
        ));
    }
    Ok(())
}

/// The pecks per plunge, the plunges and the moves about, bounded before anything is built.
fn count(
    c: &Cycle,
    axes: &Axes,
    w: &Words,
    in_travel: f64,
    shift_travel: f64,
    (in_step, shift_step): (f64, f64),
) -> Result<(usize, usize, usize), Diagnostic> {
    let pecks = (in_travel / in_step - TINY).ceil().max(1.0);
    let plunges = if shift_travel > TINY {
        (shift_travel / shift_step - TINY).ceil() + 1.0
    } else {
        1.0
    };
    let estimate = plunges * (2.0 * pecks + 3.0) + 1.0;
    if estimate > MAX_MOVES as f64 {
        let (in_word, shift_word) = axes.order(w.p_word, w.q_word);
        let pq = c.machine.pq_mm_under(c.unit);
        return Err(c.alarm(
            "LS-CYCLE-TOO-LONG",
            format!(
                "{} would make about {estimate:.0} moves ({plunges:.0} plunges of {pecks:.0} pecks), more than {MAX_MOVES}",
                axes.name
            ),
            format!("check {in_word} and {shift_word}: they are in least input increments ({pq} mm), so {in_word}1 is {pq} mm"),
        ));
    }
    Ok((pecks as usize, plunges as usize, estimate as usize))
}

/// The motion of the cycle (seed 002): plunges Δk apart, each pecking Δi down to the
/// bottom, escaping Δd, and back; then back to A.
fn moves(axes: &Axes, p: &Params) -> Vec<Move> {
    let (dir_d, dir_s) = ((p.d1 - p.d0).signum(), (p.s1 - p.s0).signum());
    let mut moves = Vec::with_capacity(p.estimate);
    let hint = if axes.g74 {
        ToolHint::FaceGrooving
    } else {
        ToolHint::Grooving
    };
    let mut push = |m: Move| moves.push(Move { hint, ..m });
    for n in 0..p.plunges {
        // ⑤ the plunge positions: Δk apart, the last exactly at the end point.
        let s = if n + 1 == p.plunges {
            p.s1
        } else {
            p.s0 + dir_s * p.shift_step * n as f64
        };
        if n > 0 {
            push(Move::rapid(axes.join(p.d0, s)));
        }
        // ①–③ pecks: feed Δi, rapid back e, feed Δi + e, …; the last feed stops at the bottom.
        for k in 1..=p.pecks {
            let bottom = if k == p.pecks {
                p.d1
            } else {
                p.d0 + dir_d * p.in_step * k as f64
            };
            push(Move::feed(axes.join(bottom, s)));
            if k < p.pecks && p.e > 0.0 {
                // never back past the start of the infeed (a retract larger than the cut)
                let back = p.e.min((bottom - p.d0).abs());
                push(Move::rapid(axes.join(bottom - dir_d * back, s)));
            }
        }
        // Escape Δd at the bottom, back toward the side already cut.
        let s_out = if p.escape > 0.0 && n > 0 {
            let s_out = s - dir_s * p.escape;
            push(Move::feed(axes.join(p.d1, s_out)));
            s_out
        } else {
            s
        };
        // ④ rapid back to the start of the infeed axis.
        push(Move::rapid(axes.join(p.d0, s_out)));
    }
    // ⑥ back to the start point A along the shift axis.
    push(Move::rapid(p.a));
    moves
}
