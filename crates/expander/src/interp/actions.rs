//! The one-shot G codes that do not move along a path of their own: G04 dwell, G27/G28
//! reference return and G50 coordinate setting.

use super::{alarm, Interp};
use crate::words::Words;
use crate::{Diagnostic, Pt};
use gcode::{Block, Word};

impl Interp<'_> {
    /// G04 P (ms) or X/U (s); Haas `P1.5` (with a point) is seconds (spec/dialects.md §3.1).
    pub(super) fn dwell(&mut self, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        let p = used.take('P');
        if self.machine.control == crate::Control::LinuxCnc {
            // LinuxCNC: `G4 P` is seconds, with or without a decimal point (G-code reference, G4)
            return match p {
                Some(p) => {
                    self.out.dwell_s += p.value.max(0.0);
                    Ok(())
                }
                None => Err(alarm(
                    g.span,
                    "LS-VALUE",
                    "G4 without a time",
                    "write G4 P<seconds>",
                )),
            };
        }
        let x = used.take('X').or_else(|| used.take('U'));
        let haas = self.machine.control == crate::Control::Haas;
        let seconds = match (p, x) {
            (Some(p), None) if p.has_point => {
                // Haas: `G04 P1.5` is 1.5 s (dialects.md §3.1). **Interpretation** on the
                // other controls, where P takes no decimal point: the author meant seconds
                // too (a FANUC alarms or reads milliseconds), warned.
                if !haas {
                    self.warn(
                        p.span,
                        "W-G04-P",
                        format!("G04 P{} with a decimal point read as {} s (Haas style)", p.value, p.value),
                        "on a FANUC, P is milliseconds without a decimal point: write G04 X… for seconds",
                    );
                }
                p.value
            }
            (Some(p), None) => p.value / 1000.0,
            (None, Some(x)) => x.value,
            (None, None) => {
                return Err(alarm(
                    g.span,
                    "LS-VALUE",
                    "G04 without a time",
                    "write G04 P<ms> or G04 X<seconds>",
                ))
            }
            (Some(p), Some(_)) => {
                return Err(alarm(
                    p.span,
                    "LS-VALUE",
                    "G04 with both P and X/U",
                    "give the dwell once",
                ))
            }
        };
        if seconds < 0.0 {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "negative dwell",
                "give a positive time",
            ));
        }
        self.out.dwell_s += seconds;
        Ok(())
    }

    /// G28: rapid to the intermediate point, then the named axes to the reference point.
    /// A bare `G28` returns both axes. **Interpretation:** straight from where the tool is
    /// (the intermediate point is the current position), as `G28 U0 W0`.
    pub(super) fn g28(&mut self, b: &Block, used: &mut Words, _g: &Word) -> Result<(), Diagnostic> {
        let x_given = b.has('X') || b.has('U');
        let z_given = b.has('Z') || b.has('W');
        let bare = !x_given && !z_given;
        if bare {
            self.note_once(
                b.span,
                "W-G28-BARE",
                "G28 without axes: both axes return to the reference point straight from here",
                "write G28 U0 W0 for the same move in the usual form",
            );
        }
        let mid = self.target(used)?.unwrap_or(self.pos);
        self.rapid(b, mid)?;
        let home = self.machine.home;
        let to = Pt::new(
            if z_given || bare { home.z } else { mid.z },
            if x_given || bare { home.r } else { mid.r },
        );
        self.rapid(b, to)
    }

    /// G27 X(U) Z(W): reference position return check. The check needs the real machine;
    /// the move is a rapid to the point (dialects.md §6.1).
    pub(super) fn g27(&mut self, b: &Block, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        let Some(to) = self.target(used)? else {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "G27 without an axis",
                "write G27 X… Z… (the reference position to check)",
            ));
        };
        self.rapid(b, to)
    }

    /// G50 (B/C: G92): the current position gets the given work coordinates; G50 S is
    /// handled with S. On a Haas the meaning of `G50 X Z` depends on Setting 33; latsim
    /// reads it as FANUC does (dialects.md §3.6), warned once.
    pub(super) fn g50(&mut self, used: &mut Words) -> Result<(), Diagnostic> {
        let u = self.unit();
        if self.machine.control == crate::Control::Haas
            && ['X', 'Z', 'U', 'W'].iter().any(|&l| used.has(l))
        {
            self.note_once(
                used.span(),
                "W-HAAS-G50",
                "G50 X/Z read as a FANUC coordinate setting: on a Haas its meaning depends on Setting 33",
                "check Setting 33 (FANUC / YASNAC / HAAS coordinate style) on the machine",
            );
        }
        let (x, z, du, dw) = (
            used.take('X'),
            used.take('Z'),
            used.take('U'),
            used.take('W'),
        );
        if x.is_none() && z.is_none() && du.is_none() && dw.is_none() {
            return Ok(());
        }
        // Where the tool reads it is, in the present frame.
        let mut reads = self.pos - self.shift;
        if let Some(x) = x {
            reads.r = x.value * u / 2.0;
        }
        if let Some(z) = z {
            reads.z = z.value * u;
        }
        if let Some(du) = du {
            reads.r += du.value * u / 2.0;
        }
        if let Some(dw) = dw {
            reads.z += dw.value * u;
        }
        let span = used.span();
        if self.out.segments.is_empty() && self.section.is_none() && self.shift == Pt::default() {
            // Before the first move the setting states the program's own frame, the one the
            // stock is given in (spec/dialects.md §2.3): the tool is where it says.
            self.note_once(
                span,
                "W-G50-START",
                format!(
                    "G50 before the first move: the tool starts at X{} Z{} of the program's frame (not at the machine profile's home)",
                    fmt_mm(2.0 * reads.r),
                    fmt_mm(reads.z)
                ),
                "the stock is given in this frame (Z0 at the face the program means)",
            );
            self.pos = reads;
            return Ok(());
        }
        let shift = self.pos - reads;
        let moved = shift - self.shift;
        self.shift = shift;
        self.warn(
            span,
            "W-G50-SHIFT",
            format!(
                "coordinate setting moves the work origin by ΔX{} ΔZ{}: later positions are read in the new frame, the section stays in the first",
                fmt_mm(2.0 * moved.r),
                fmt_mm(moved.z)
            ),
            "",
        );
        Ok(())
    }
}

/// A length for a message: at most three decimals, no trailing zeros.
fn fmt_mm(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}
