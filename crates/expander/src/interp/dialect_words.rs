//! The checks of a block that depend on the control's reading of it (spec/dialects.md §2,
//! §6.1): words of axes a turned section does not have, the plane, and the `G92` that
//! means a threading cycle in system A and a coordinate setting in B/C.

use super::modal::{GWords, MotionMode};
use super::{alarm, Interp};
use crate::codes::*;
use crate::words::Words;
use crate::{Diagnostic, GCodeSystem};
use gcode::Block;

/// Why an axis word cannot be simulated.
fn axis_reason(letter: char) -> Option<&'static str> {
    Some(match letter {
        'C' => {
            "the C axis (spindle angle) turns the part for milling; a turned section has no angle"
        }
        'H' => "H is the incremental C axis (spindle angle); a turned section has no angle",
        'Y' => {
            "the Y axis moves off the spindle centre line; not representable in a turned section"
        }
        'B' => "the B axis (sub-spindle or tool tilt) is outside a single 2D section",
        'V' => "V is the incremental Y axis; not representable in a turned section",
        _ => return None,
    })
}

impl Interp<'_> {
    /// The control-dependent checks of a block, after its G codes are read and before
    /// anything moves (so an alarm leaves no half-made move behind).
    pub(super) fn dialect_checks(
        &mut self,
        b: &Block,
        g: &GWords,
        used: &mut Words,
    ) -> Result<(), Diagnostic> {
        let motion = g.motion.map_or(self.motion, |(m, _)| m);
        let axis = ['X', 'Z', 'U', 'W'].iter().any(|&l| b.has(l));
        let own_words = matches!(g.one_shot, Some((G75_1 | G10, _)));
        if !own_words {
            self.axis_words(b, motion, used)?;
        }
        // G17 / G19: accepted until an arc or a cycle needs the plane (dialects.md §6.1).
        if let Some((plane, set)) = self.plane {
            let arc =
                matches!(motion, MotionMode::Cw | MotionMode::Ccw) && axis && g.one_shot.is_none();
            let cycle = g
                .one_shot
                .is_some_and(|(t, _)| crate::cycles::is_cycle(t) && !self.drills_along_z(t))
                || (matches!(motion, MotionMode::Cycle(_))
                    && (axis || b.has('R'))
                    && g.one_shot.is_none());
            if arc || cycle {
                return Err(alarm(
                    b.span,
                    "LS-NOT-SIMULATED",
                    format!(
                        "plane not simulated: G{} (set at line {}) is in force, and this {} needs the ZX plane",
                        plane / 10,
                        set.line,
                        if arc { "arc" } else { "cycle" }
                    ),
                    "a lathe section is the ZX plane: write G18 before the arc or cycle (G17/G19 are live-tooling planes)",
                ));
            }
        }
        let system = self.machine.control.system();
        // System A: G92 is the threading cycle, so `G92 S2500` is a thread without an end
        // point, never a spindle clamp or a new S (dialects.md §2.3, T2).
        if let Some((MotionMode::Cycle(G92), w)) = g.motion {
            if system == GCodeSystem::A && !axis && b.has('S') {
                return Err(alarm(
                    w.span,
                    "LS-DIALECT",
                    "G92 is the threading cycle in system A: this block has S but no thread end point X/Z",
                    "for the spindle clamp write G50 S…; if the program is written for system B or C run with --control fanuc-b (or fanuc-c)",
                ));
            }
        }
        // System B/C: G92 sets coordinates; an F is the system-A thread lead.
        if let Some((G50, w)) = g.one_shot {
            if system != GCodeSystem::A && w.code_tenths() == Some(G92) {
                if let Some(f) = b.get('F') {
                    return Err(alarm(
                        f.span,
                        "LS-DIALECT",
                        "G92 sets coordinates (or the spindle clamp) in system B/C: F has no meaning here",
                        "the threading cycle is G78 in system B (G21 in C); if the program is written for system A run with --control fanuc-a",
                    ));
                }
            }
        }
        // Finishing shapes are read as absolute positions.
        if self.incremental {
            if let Some((t @ (G70 | G71 | G72 | G73), w)) = g.one_shot {
                if b.has('P') {
                    return Err(alarm(
                        w.span,
                        "LS-NOT-SIMULATED",
                        format!("{} under G91: incremental finishing shapes are not simulated", crate::cycles::name(t)),
                        "write G90 (absolute) before the cycle; the shape blocks then give absolute positions",
                    ));
                }
            }
        }
        Ok(())
    }

    /// C, H, Y, B and V words: a clear alarm at the word, except `C0`/`H0` on a positioning
    /// block (spindle orientation), which is ignored with a warning.
    fn axis_words(
        &mut self,
        b: &Block,
        motion: MotionMode,
        used: &mut Words,
    ) -> Result<(), Diagnostic> {
        for (i, w) in b.words.iter().enumerate() {
            let Some(reason) = axis_reason(w.letter) else {
                continue;
            };
            // LinuxCNC: H is G43's tool number (an unused H is still an alarm)
            if w.letter == 'H' && self.machine.control == crate::Control::LinuxCnc {
                continue;
            }
            // system A's plain chamfer on a G01 (profile g01_cr = "plain"), not the C axis
            if w.letter == 'C'
                && motion == MotionMode::Line
                && self.machine.g01_cr == crate::G01Cr::Plain
            {
                continue;
            }
            if matches!(w.letter, 'C' | 'H') && w.value == 0.0 && motion == MotionMode::Rapid {
                used.mark(i);
                self.warn(
                    w.span,
                    "W-C0",
                    format!(
                        "{}0 on a positioning block ignored (spindle orientation)",
                        w.letter
                    ),
                    "a turned section has no spindle angle",
                );
                continue;
            }
            // Y0 keeps the tool on the spindle's centre line (a Y away from it is the
            // alarm below, so the tool was never off it): a drilling position written with
            // both axes, `G0 X0 Y0 Z5` (field run 8, F)
            if w.letter == 'Y' && w.value == 0.0 {
                used.mark(i);
                self.note_once(
                    w.span,
                    "W-Y0",
                    "Y0 ignored: the tool stays on the spindle centre line",
                    "a turned section has no Y axis; Y0 is where it is",
                );
                continue;
            }
            return Err(alarm(
                w.span,
                "LS-NOT-SIMULATED",
                format!("{}{} is not simulated: {reason}", w.letter, w.value),
                "latsim simulates one turned 2D section (X and Z); remove the word or simulate this part of the program elsewhere",
            ));
        }
        Ok(())
    }
}
