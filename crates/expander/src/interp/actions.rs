//! The one-shot G codes that do not move along a path of their own: G04 dwell, G28
//! reference return and G50 coordinate setting.

use super::{alarm, Interp};
use crate::words::Words;
use crate::{Diagnostic, Pt};
use gcode::{Block, Word};

impl Interp<'_> {
    /// G04 P (ms) or X/U (s); Haas `P1.5` (with a point) is seconds (spec/dialects.md §3.1).
    pub(super) fn dwell(&mut self, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        let p = used.take('P');
        let x = used.take('X').or_else(|| used.take('U'));
        let haas = self.machine.control == crate::Control::Haas;
        let seconds = match (p, x) {
            (Some(p), None) if haas && p.has_point => p.value,
            (Some(p), None) => {
                if p.has_point {
                    return Err(alarm(
                        p.span,
                        "LS-VALUE",
                        "G04 P is in milliseconds and takes no decimal point",
                        "write G04 P1500 for 1.5 s, or G04 X1.5",
                    ));
                }
                p.value / 1000.0
            }
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
    pub(super) fn g28(&mut self, b: &Block, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        let x_given = b.has('X') || b.has('U');
        let z_given = b.has('Z') || b.has('W');
        let Some(mid) = self.target(used)? else {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "G28 without an axis",
                "write e.g. G28 U0 W0 to return both axes through the current position",
            ));
        };
        self.rapid(b, mid)?;
        let home = self.machine.home;
        let to = Pt::new(
            if z_given { home.z } else { mid.z },
            if x_given { home.r } else { mid.r },
        );
        self.rapid(b, to)
    }

    /// G50: the current position gets the given work coordinates; G50 S is handled with S.
    pub(super) fn g50(&mut self, used: &mut Words) -> Result<(), Diagnostic> {
        let u = self.unit();
        if let Some(x) = used.take('X') {
            self.shift.r = self.pos.r - x.value * u / 2.0;
        }
        if let Some(z) = used.take('Z') {
            self.shift.z = self.pos.z - z.value * u;
        }
        if let Some(du) = used.take('U') {
            self.shift.r -= du.value * u / 2.0;
        }
        if let Some(dw) = used.take('W') {
            self.shift.z -= dw.value * u;
        }
        Ok(())
    }
}
