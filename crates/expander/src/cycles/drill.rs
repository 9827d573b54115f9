//! Drilling cycles on the spindle axis (spec/dialects.md §6.2): FANUC G83 (drill / peck),
//! G84 (tap), G85 (bore); Haas G81 (drill), G82 (drill with dwell), G83 (peck), G84 (tap).
//!
//! ```text
//! FANUC:  G83 X(U)0 Z(W) R Q P F K ;   G84 / G85 X(U)0 Z(W) R P F K ;
//! Haas:   G81 / G82 / G83 / G84 X0 Z R [Q] [P] F ;
//! ```
//! From the initial point I (the Z where the cycle is first read, X0):
//! 1. rapid to the R point;
//! 2. G81/G82/G83 without Q: feed to Z. G83 with Q, **peck** (`g83_full_retract = true`):
//!    feed Q, rapid back to R, rapid down to δ short of the depth reached, feed on Q … (the
//!    last feed lands on Z). **High-speed peck** (the default): feed Q, rapid back δ, feed
//!    on. δ = `drill_clearance`. G84/G85: feed to Z;
//! 3. dwell P at the bottom;
//! 4. G84/G85: feed back to R (the tap reverses; the bore is fed out);
//! 5. rapid to the return level: the initial level, or the R point (`drill_return`, set by
//!    G98/G99 in systems B/C).
//!
//! Words (**Interpretations** where §6.2 says so):
//! - X must be 0 (on the axis), absent when the tool is already on it; C/H (C axis) are
//!   alarms: an off-axis hole is not axisymmetric.
//! - Z absolute bottom; W the distance from the R point to the bottom (FANUC [S28]).
//! - FANUC R: signed distance from the initial level to the R point (system A); Haas R: the
//!   R plane's absolute Z.
//! - FANUC Q: peck depth in least input increments, no decimal point; Haas Q in mm.
//! - P: dwell; FANUC milliseconds (no decimal point); Haas `P1.5` seconds, `P1500` ms.
//! - K: repeats; the hole is drilled K times (K > 1 with an incremental W is an alarm: a
//!   second hole would be off the axis of the first one's depth).
//! - The cycle is modal until G80 or a group-01 code; a later block with X/Z/U/W/R/Q
//!   repeats it with the retained words (`Retained::drill`).
//! - G84 sweeps the drill outline of the tool table (the tap's major diameter); the thread
//!   form is not drawn (a note says so).

use super::{Cycle, Move, Output, MAX_MOVES};
use crate::codes::{G81, G82, G83, G84, G85};
use crate::linuxcnc::DRILL_CHIP_BREAK;
use crate::{Control, Diagnostic, DrillReturn, Pt};

/// The words a drilling cycle retains between its blocks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DrillWords {
    /// The cycle in force (tenths).
    pub(crate) code: i32,
    /// The initial level: the Z where the cycle was first read, G54 frame.
    pub(crate) initial: f64,
    /// The R point, G54 frame Z.
    pub(crate) r: f64,
    /// The hole bottom, G54 frame Z.
    pub(crate) bottom: f64,
    /// Peck depth, mm (0: one feed).
    pub(crate) q: f64,
    /// Dwell at the bottom, s.
    pub(crate) dwell: f64,
    /// How far short of the depth reached the tool comes back down after a peck (or backs
    /// off, high-speed), mm: the profile's `drill_clearance`, `LinuxCNC`'s D.
    pub(crate) clearance: f64,
}

/// Whether a G code (tenths) is a drilling cycle of the spindle axis.
pub(crate) fn is_drill(t: i32) -> bool {
    matches!(t, G81 | G82 | G83 | G84 | G85 | DRILL_CHIP_BREAK)
}

/// Whose rules a drilling block is read by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Rules {
    /// FANUC: R from the initial level, Q in least increments, P milliseconds, K repeats.
    Fanuc,
    /// Haas: R the plane's Z, Q in mm, `P1.5` seconds (`P1500` milliseconds).
    Haas,
    /// `LinuxCNC` in G17 (docs/linuxcnc.md): R the plane's Z, Q in program units, P
    /// seconds, D the peck clearance; G83 retracts to R after each peck, G73 backs off by
    /// the clearance (`interp_cycles.cc` `convert_cycle_g83`, `convert_cycle_g73`).
    LinuxCnc,
}

impl Rules {
    fn of(control: Control) -> Self {
        match control {
            Control::Haas => Self::Haas,
            Control::LinuxCnc => Self::LinuxCnc,
            _ => Self::Fanuc,
        }
    }

    /// R is the R plane's Z (else its distance from the initial level).
    fn r_is_plane(self) -> bool {
        self != Self::Fanuc
    }
}

/// Expand one drilling block (the first of the cycle, or a modal repeat).
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let rules = Rules::of(c.machine.control);
    check_code(c, rules)?;
    check_on_axis(c)?;
    if rules == Rules::LinuxCnc && c.linuxcnc.incremental {
        return Err(c.alarm(
            "LS-NOT-IMPLEMENTED",
            "a LinuxCNC drilling cycle in G91 (R from the start, Z from R, L repeats) is not run by latsim",
            "drill in G90: Z the hole's bottom and R the R plane's Z",
        ));
    }
    let hole = read(c, rules)?;
    c.retained.drill = Some(hole.words);
    let mut out = Output {
        moves: moves(c, &hole),
        // 3. the dwell at the bottom, each time (summed as the times are drilled)
        dwell_s: (0..hole.times).fold(0.0, |sum, _| sum + hole.words.dwell),
        ..Output::default()
    };
    out.warnings.extend(hole.off_axis);
    if c.code == G84 && c.g.is_some() {
        out.warnings.push(c.alarm(
            "LS-TAP",
            "G84 taps with the drill outline of the tool table (the tap's major diameter); the thread form is not drawn",
            "",
        ));
    }
    Ok(out)
}

/// The drilling codes of this control; the other control's are alarms naming it.
fn check_code(c: &Cycle, rules: Rules) -> Result<(), Diagnostic> {
    let name = crate::codes::g_name(c.code);
    let accepted = match rules {
        Rules::Haas => matches!(c.code, G81 | G82 | G83 | G84),
        Rules::LinuxCnc => crate::linuxcnc::is_drilling(c.code),
        Rules::Fanuc => matches!(c.code, G83 | G84 | G85),
    };
    if accepted {
        return Ok(());
    }
    let (message, help) = match rules {
        Rules::Haas => (
            format!("{name} is not a Haas lathe drilling cycle on the spindle axis"),
            "Haas drills on the axis with G81 (drill), G82 (dwell), G83 (peck), G84 (tap)",
        ),
        Rules::LinuxCnc => (
            format!("{name} is not a LinuxCNC drilling cycle latsim runs"),
            "latsim runs LinuxCNC's G73, G81, G82, G83 and G85 in G17 (docs/linuxcnc.md)",
        ),
        Rules::Fanuc => (
            format!("{name} is the Haas drilling code; this control is {}", c.machine.control.key()),
            "FANUC lathes drill on the axis with G83 (drill/peck), G84 (tap), G85 (bore); or run with --control haas",
        ),
    };
    Err(c.alarm("LS-DRILL-CODE", message, help))
}

/// C and H (the C axis) are alarms: an off-axis hole is not axisymmetric.
fn check_on_axis(c: &Cycle) -> Result<(), Diagnostic> {
    for letter in ['C', 'H'] {
        if let Some(w) = c.words.block.get(letter) {
            return Err(Diagnostic::new(
                w.span,
                "LS-OFF-AXIS",
                format!("{letter} indexes the C axis: an off-axis hole is not axisymmetric"),
                "latsim simulates holes on the spindle axis only (X0, no C)",
            ));
        }
    }
    Ok(())
}

/// One hole as the block gives it: its retained words, how many times it is drilled, and
/// the number of pecks of each.
struct Hole {
    words: DrillWords,
    times: u32,
    pecks: usize,
    /// Its radius: 0 on the axis, else an offset drill's ([`hole_radius`]).
    radius: f64,
    /// The warning of a drill off the axis.
    off_axis: Option<Diagnostic>,
}

/// Read the block's words, the retained ones of the same cycle filling what it omits, and
/// check the levels: initial, R point, bottom in that order along Z.
fn read(c: &mut Cycle, rules: Rules) -> Result<Hole, Diagnostic> {
    let name = crate::codes::g_name(c.code);
    let prev = c
        .retained
        .drill
        .filter(|d| d.code == c.code || c.g.is_none());
    let (radius, off_axis) = hole_radius(c, &name)?;
    let initial = prev.map_or(c.start.z, |p| p.initial);
    let r = r_point(c, rules.r_is_plane(), &name, initial, prev)?;
    let w_word = c.words.block.get('W');
    let bottom = bottom(c, &name, r, prev)?;
    let q = peck(c, rules, &name, prev)?;
    let dwell = dwell(c, rules, &name, prev)?;
    let times = repeats(c, rules)?;
    let clearance = clearance(c, rules, prev)?;
    if times > 1 {
        if let Some(w) = w_word {
            return Err(Diagnostic::new(
                w.span,
                "LS-DRILL-K",
                "K repeats with an incremental W would drill each repeat deeper along the axis",
                "repeat a hole on the axis with an absolute Z (the same hole), or write each hole",
            ));
        }
    }
    let dir = (bottom - r).signum();
    if (bottom - r).abs() < 1e-9 || (r - initial) * dir < -1e-9 {
        return Err(c.alarm(
            "LS-DRILL-LEVELS",
            format!(
                "{name}: the R point Z{r:.3} must lie between the initial level Z{initial:.3} and the bottom Z{bottom:.3}"
            ),
            "the tool goes from the initial level to R by rapid, then feeds from R to the bottom",
        ));
    }
    let pecks = if q > 0.0 {
        ((bottom - r).abs() / q - 1e-9).ceil().max(1.0)
    } else {
        1.0
    };
    if pecks * 3.0 * f64::from(times) > MAX_MOVES as f64 {
        return Err(c.alarm(
            "LS-CYCLE-TOO-LONG",
            format!("{name} would make {pecks:.0} pecks"),
            "Q is in least input increments: Q8000 is 8 mm at IS-B",
        ));
    }
    let words = DrillWords {
        code: c.code,
        initial,
        r,
        bottom,
        q,
        dwell,
        clearance,
    };
    Ok(Hole {
        words,
        times,
        pecks: pecks as usize,
        radius,
        off_axis,
    })
}

/// X: the hole's radius. On the axis; off it only a drill (not a tap nor a boring bar)
/// with the spindle turning and its C axis free: an offset indexable drill cuts a round
/// hole about the axis, as G01 at that X does (**Interpretation**, docs/field-rules.md
/// §19), warned. Else a hole off the axis is a hole in one place: an alarm.
fn hole_radius(c: &mut Cycle, name: &str) -> Result<(f64, Option<Diagnostic>), Diagnostic> {
    let x_word = c.words.block.get('X').or_else(|| c.words.block.get('U'));
    let x = c.x_target()?.unwrap_or(c.start.r);
    if x.abs() <= 1e-6 {
        return Ok((0.0, None));
    }
    let span = x_word.map_or(c.span(), |w| w.span);
    // the X as the program writes it (a diameter, in its units)
    let written = 2.0 * x / c.unit;
    if c.turning_free && matches!(c.code, G81 | G82 | G83 | DRILL_CHIP_BREAK) {
        let warning = Diagnostic::new(
            span,
            "W-OFF-AXIS-DRILL",
            format!(
                "{name} at X{written:.4} with the spindle turning: an offset drill, its hole {:.3} mm larger in diameter than the drill",
                2.0 * x.abs()
            ),
            "the hole is drawn round about the axis; with the C axis engaged (M154) it would be an alarm",
        );
        return Ok((x, Some(warning)));
    }
    Err(Diagnostic::new(
        span,
        "LS-OFF-AXIS",
        format!("{name} at X{written:.4}: a hole off the spindle axis is not axisymmetric"),
        "drill on the axis: position at X0 before the cycle (or give X0); an offset drill needs the spindle turning (M03/M04)",
    ))
}

/// The R point, G54 frame Z: Haas R the plane's Z, FANUC R from the initial level.
fn r_point(
    c: &mut Cycle,
    r_is_plane: bool,
    name: &str,
    initial: f64,
    prev: Option<DrillWords>,
) -> Result<f64, Diagnostic> {
    Ok(match c.words.take('R') {
        Some(w) if r_is_plane => w.value * c.unit + c.shift.z,
        Some(w) => initial + w.value * c.unit,
        None => match prev {
            Some(p) => p.r,
            None if r_is_plane => {
                return Err(c.alarm(
                    "LS-DRILL-R",
                    format!("{name} without R (the R plane)"),
                    "give the R plane's Z, e.g. R2.",
                ))
            }
            None => initial,
        },
    })
}

/// The hole bottom, G54 frame Z: Z absolute, W from the R point.
fn bottom(c: &mut Cycle, name: &str, r: f64, prev: Option<DrillWords>) -> Result<f64, Diagnostic> {
    Ok(match (c.words.take('Z'), c.words.take('W')) {
        (Some(z), None) => z.value * c.unit + c.shift.z,
        (None, Some(w)) => r + w.value * c.unit,
        (Some(_), Some(w)) => {
            return Err(Diagnostic::new(
                w.span,
                "LS-AXIS-TWICE",
                "Z and W both given",
                "give the hole bottom either absolute (Z) or from the R point (W)",
            ))
        }
        (None, None) => match prev {
            Some(p) => p.bottom,
            None => {
                return Err(c.alarm(
                    "LS-DRILL-Z",
                    format!("{name} without the hole bottom Z"),
                    "give the depth of the hole as Z (absolute) or W (from the R point)",
                ))
            }
        },
    })
}

/// The peck depth Q of G83 (and `LinuxCNC`'s G73), mm (0: one feed): Haas in mm,
/// `LinuxCNC` in program units, FANUC in increments. `LinuxCNC` pecks need Q.
fn peck(
    c: &mut Cycle,
    rules: Rules,
    name: &str,
    prev: Option<DrillWords>,
) -> Result<f64, Diagnostic> {
    if !matches!(c.code, G83 | DRILL_CHIP_BREAK) {
        return Ok(0.0);
    }
    let q = match rules {
        Rules::Haas | Rules::LinuxCnc => c.words.mm('Q', c.unit),
        Rules::Fanuc => c
            .words
            .increments('Q', c.machine.increment_mm_under(c.unit))?,
    };
    if q.is_none() && rules == Rules::LinuxCnc && prev.is_none_or(|p| p.q <= 0.0) {
        return Err(c.alarm(
            "LS-DRILL-Q",
            format!("{name} without Q (LinuxCNC's peck depth)"),
            "give the depth of each peck, e.g. Q2; G81 drills in one feed",
        ));
    }
    match q {
        Some(q) if q <= 0.0 => Err(c.alarm(
            "LS-DRILL-Q",
            format!("{name}: the peck depth Q must be positive"),
            "give the depth of each peck, or leave Q out to drill in one feed",
        )),
        Some(q) => Ok(q),
        None => Ok(prev.map_or(0.0, |p| p.q)),
    }
}

/// The dwell P at the bottom, s: FANUC milliseconds without a point; Haas `P1.5` seconds;
/// `LinuxCNC` seconds.
fn dwell(
    c: &mut Cycle,
    rules: Rules,
    name: &str,
    prev: Option<DrillWords>,
) -> Result<f64, Diagnostic> {
    match c.words.take('P') {
        Some(p) if p.value < 0.0 => Err(Diagnostic::new(
            p.span,
            "LS-VALUE",
            "a negative dwell",
            "give the dwell at the bottom (FANUC milliseconds, Haas and LinuxCNC seconds)",
        )),
        Some(p) if rules == Rules::LinuxCnc => Ok(p.value),
        Some(p) if rules == Rules::Haas && p.has_point => Ok(p.value),
        Some(p) if p.has_point => Err(Diagnostic::new(
            p.span,
            "LS-VALUE",
            format!("{name} P is the dwell in milliseconds and takes no decimal point"),
            "write e.g. P500 for 0.5 s",
        )),
        Some(p) => Ok(p.value / 1000.0),
        None => Ok(prev.map_or(0.0, |p| p.dwell)),
    }
}

/// The peck clearance, mm: `LinuxCNC`'s D (sticky), else the profile's `drill_clearance`
/// (1 mm, `LinuxCNC`'s metric default too).
fn clearance(c: &mut Cycle, rules: Rules, prev: Option<DrillWords>) -> Result<f64, Diagnostic> {
    let d = if rules == Rules::LinuxCnc {
        c.words.take('D')
    } else {
        None
    };
    match d {
        Some(d) if d.value < 0.0 => Err(Diagnostic::new(
            d.span,
            "LS-VALUE",
            "a negative peck clearance D",
            "give how far short of the depth reached the drill comes back, e.g. D0.5",
        )),
        Some(d) => Ok(d.value * c.unit),
        None => Ok(prev.map_or(c.machine.drill_clearance, |p| p.clearance)),
    }
}

/// K: how many times the hole is drilled (FANUC; 1 on Haas). `LinuxCNC`'s L repeats a
/// hole only in G91 (moved along X), so in G90 it is read and changes nothing.
fn repeats(c: &mut Cycle, rules: Rules) -> Result<u32, Diagnostic> {
    if rules == Rules::LinuxCnc {
        c.words.take('L');
    }
    let k_word = if rules == Rules::Fanuc {
        c.words.take('K')
    } else {
        None
    };
    match k_word {
        None => Ok(1),
        Some(k) if !k.has_point && (1.0..=9999.0).contains(&k.value) => Ok(k.value as u32),
        Some(k) => Err(Diagnostic::new(
            k.span,
            "LS-VALUE",
            "K must be a repeat count 1 … 9999",
            "write e.g. K2",
        )),
    }
}

/// Steps 1–5 of the module doc for each time the hole is drilled.
fn moves(c: &Cycle, hole: &Hole) -> Vec<Move> {
    let w = &hole.words;
    let ret = match c.drill_return {
        DrillReturn::Initial => w.initial,
        DrillReturn::RPoint => w.r,
    };
    let at = |z: f64| Pt::new(z, hole.radius);
    let dir = (w.bottom - w.r).signum();
    let delta = w.clearance;
    let full_retract = match c.code {
        DRILL_CHIP_BREAK => false,
        _ if c.machine.control == Control::LinuxCnc => true,
        _ => c.machine.g83_full_retract,
    };
    let mut moves = vec![];
    for _ in 0..hole.times {
        moves.push(Move::rapid(at(w.r))); // 1. to the R point
        if w.q > 0.0 {
            let n = hole.pecks;
            for i in 1..=n {
                let depth = if i == n {
                    w.bottom
                } else {
                    w.r + dir * w.q * i as f64
                };
                moves.push(Move::feed(at(depth))); // 2. one peck
                if i < n {
                    if full_retract {
                        moves.push(Move::rapid(at(w.r)));
                        moves.push(Move::rapid(at(depth - dir * delta)));
                    } else {
                        moves.push(Move::rapid(at(depth - dir * delta)));
                    }
                }
            }
        } else {
            moves.push(Move::feed(at(w.bottom))); // 2. one feed
        }
        if matches!(c.code, G84 | G85) {
            moves.push(Move::feed(at(w.r))); // 4. tap reversed / bore fed out
        }
        moves.push(Move::rapid(at(ret))); // 5.
    }
    moves
}
