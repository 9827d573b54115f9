//! The words of `LinuxCNC`'s G76 block to [`Params`], with `LinuxCNC`'s checks
//! (`interp_check.cc`, `convert_threading_cycle`) as alarms at their word and its quiet
//! corrections (R below 1, negative E) as warnings (docs/linuxcnc-g76.md, "Words").

use super::{Modes, Params};
use crate::cycles::Cycle;
use crate::{Diagnostic, Span};
use gcode::Word;

/// The most passes one G76 may cut (rough and full depth): a tiny J with a large R is an
/// alarm, never a hang.
pub(crate) const MAX_PASSES: f64 = 10_000.0;

/// The block's words as `LinuxCNC` reads them, or the alarm `LinuxCNC` (or latsim's limits)
/// gives; `warnings` gets what `LinuxCNC` corrects without a word.
pub(super) fn params(
    c: &mut Cycle,
    modes: Modes,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Params, Diagnostic> {
    let at = c.span();
    let unit = c.unit;
    // LinuxCNC's order: the words first (a modal repeat without P says so), then the modes
    let pitch = pitch(c, at)?;
    let (i, j, k) = depths(c, at, modes.x_diameter)?;
    refuse_modes(c, modes)?;
    let end_z = c.z_target()?.unwrap_or(c.start.z);
    let end_x = c.x_target()?;
    let degression = degression(c, warnings);
    let compound = compound_angle(c)?;
    let spring = whole(c, 'H', "the number of spring passes")?.unwrap_or(0);
    let taper = match c.words.take('E') {
        Some(e) if e.value < 0.0 => {
            warnings.push(Diagnostic::new(
                e.span,
                "LS-G76-E",
                format!(
                    "E{} is negative: LinuxCNC cuts without a taper (E0)",
                    e.value
                ),
                "E is the length of the taper along the drive line, 0 or more",
            ));
            0.0
        }
        Some(e) => e.value * unit,
        None => 0.0,
    };
    let ends = whole(c, 'L', "the taper ends (0 none, 1 entry, 2 exit, 3 both)")?.unwrap_or(0);
    let p = Params {
        pitch,
        end_z,
        end_x,
        i,
        j,
        k,
        degression,
        compound,
        spring,
        taper,
        entry_taper: ends & 1 != 0,
        exit_taper: ends & 2 != 0,
    };
    check_pass_count(&p, at)?;
    if p.taper > 0.0 && (ends & 3) != 0 && 2.0 * p.taper > (p.end_z - c.start.z).abs() {
        warnings.push(Diagnostic::new(
            at,
            "LS-G76-E",
            format!(
                "E {:.4} mm is more than half the drive line ({:.4} mm): LinuxCNC's reference calls it an error, its interpreter cuts it",
                p.taper,
                (p.end_z - c.start.z).abs()
            ),
            "make E at most half the thread length",
        ));
    }
    Ok(p)
}

/// `LinuxCNC` refuses G76 under cutter compensation and with the spindle stopped.
fn refuse_modes(c: &Cycle, modes: Modes) -> Result<(), Diagnostic> {
    if modes.compensating {
        return Err(c.alarm(
            "LS-G76-COMP",
            "Cannot use G76 threading cycle with cutter radius compensation on (LinuxCNC)",
            "write G40 before the G76",
        ));
    }
    if !modes.spindle_turning {
        return Err(c.alarm(
            "LS-G76-SPINDLE",
            "G76 with the spindle stopped: LinuxCNC stops with \"Chosen spindle (0) not turning in G76\"",
            "start the spindle with M3 or M4 before the G76",
        ));
    }
    Ok(())
}

/// P: the thread pitch, distance per revolution (required, positive).
fn pitch(c: &mut Cycle, at: Span) -> Result<f64, Diagnostic> {
    match c.words.take('P') {
        None => Err(Diagnostic::new(
            at,
            "LS-G76-WORDS",
            "P word missing with G76 (LinuxCNC: P is the thread pitch)",
            "write G76 P<pitch> Z<end> I<peak offset> J<first cut> K<full depth>; G76 is modal in LinuxCNC, so a block of axis words after it repeats it: start such a block with G0 or G1",
        )),
        Some(p) if p.value <= 0.0 => Err(Diagnostic::new(
            p.span,
            "LS-VALUE",
            format!("G76 P{} is no thread pitch: P must be positive", p.value),
            "P is the distance the tool travels along Z per spindle revolution",
        )),
        Some(p) => Ok(p.value * c.unit),
    }
}

/// I, J, K as radii in mm (halved under G7: `LinuxCNC` halves them in
/// `convert_threading_cycle` when `lathe_diameter_mode`), with `LinuxCNC`'s checks: I not 0,
/// J > 0, K > J.
fn depths(c: &mut Cycle, at: Span, x_diameter: bool) -> Result<(f64, f64, f64), Diagnostic> {
    let (Some(i), Some(j), Some(k)) = (c.words.take('I'), c.words.take('J'), c.words.take('K'))
    else {
        return Err(Diagnostic::new(
            at,
            "LS-G76-WORDS",
            "I J or K words missing with G76 (LinuxCNC)",
            "write I (thread peak offset from the drive line, negative outside), J (first cut depth) and K (full thread depth)",
        ));
    };
    let scale = c.unit / if x_diameter { 2.0 } else { 1.0 };
    let refuse = |w: &Word, message: &str, help: &str| {
        Err(Diagnostic::new(
            w.span,
            "LS-VALUE",
            message.to_string(),
            help.to_string(),
        ))
    };
    if i.value == 0.0 {
        return refuse(
            i,
            "In G76, I must not be 0 (LinuxCNC)",
            "I is the thread peak's offset from the drive line: negative for an outside thread, positive for a bore",
        );
    }
    if j.value <= 0.0 {
        return refuse(
            j,
            "In G76, J must be greater than 0 (LinuxCNC)",
            "J is the depth of the first cut beyond the thread peak",
        );
    }
    if k.value <= j.value {
        return refuse(
            k,
            "In G76, K must be greater than J (LinuxCNC)",
            "K is the full thread depth beyond the peak; J the first cut",
        );
    }
    Ok((i.value * scale, j.value * scale, k.value * scale))
}

/// R: the depth degression; absent or below 1 `LinuxCNC` cuts with 1 (a warning says so:
/// its reference calls R below 1 an error, its interpreter does not).
fn degression(c: &mut Cycle, warnings: &mut Vec<Diagnostic>) -> f64 {
    match c.words.take('R') {
        None => 1.0,
        Some(r) if r.value >= 1.0 => r.value,
        Some(r) => {
            warnings.push(Diagnostic::new(
                r.span,
                "LS-G76-R",
                format!(
                    "R{} is below 1: LinuxCNC cuts with R1 (constant depth per pass)",
                    r.value
                ),
                "R is the depth degression, 1 or more (R1 constant depth, R2 constant area)",
            ));
            1.0
        }
    }
}

/// Q: the compound slide angle in degrees; absent (and, as `LinuxCNC` reads it, Q-1) is 0.
/// A right angle or more is no infeed: an alarm.
fn compound_angle(c: &mut Cycle) -> Result<f64, Diagnostic> {
    match c.words.take('Q') {
        None => Ok(0.0),
        Some(q) if q.value == -1.0 => Ok(0.0),
        Some(q) if q.value.abs() >= 90.0 => Err(Diagnostic::new(
            q.span,
            "LS-VALUE",
            format!(
                "G76 Q{}: the compound slide angle must be less than 90°",
                q.value
            ),
            "Q is the angle of the infeed from the X axis, typically 29.5 for a 60° thread",
        )),
        Some(q) => Ok(q.value),
    }
}

/// A whole, non-negative word (`LinuxCNC` reads H and L as integers and refuses negative
/// ones); `None` when absent.
fn whole(c: &mut Cycle, letter: char, what: &str) -> Result<Option<u32>, Diagnostic> {
    let Some(w) = c.words.take(letter) else {
        return Ok(None);
    };
    let n = w.value.round();
    if (w.value - n).abs() > 1e-4 || !(0.0..=MAX_PASSES).contains(&n) {
        return Err(Diagnostic::new(
            w.span,
            "LS-VALUE",
            format!(
                "G76 {letter}{} must be a whole number from 0 to {MAX_PASSES}",
                w.value
            ),
            format!("{letter} is {what}"),
        ));
    }
    Ok(Some(n as u32))
}

/// The passes the words ask for: J·n^(1/R) reaches K after (K/J)^R passes.
fn check_pass_count(p: &Params, at: Span) -> Result<(), Diagnostic> {
    let rough = (p.k / p.j).powf(p.degression).ceil();
    let total = rough + f64::from(p.spring) + 1.0;
    if total > MAX_PASSES {
        return Err(Diagnostic::new(
            at,
            "LS-G76-PASSES",
            format!(
                "this G76 cuts about {total:.0} passes (J·n^(1/R) reaches K after (K/J)^R passes): more than {MAX_PASSES}"
            ),
            "raise J or lower R (LinuxCNC warns that high degression values make many passes)",
        ));
    }
    Ok(())
}
