//! `LinuxCNC`'s `G33.1` rigid tapping on the lathe's axis (docs/linuxcnc.md).

use super::{alarm, Interp, MotionMode};
use crate::linuxcnc as lc;
use crate::words::Words;
use crate::Diagnostic;
use gcode::{Block, Span};

impl Interp<'_> {
    /// `G33.1 Z K [I]`: `LinuxCNC`'s rigid tapping, a move synchronised with the spindle at the
    /// lead K to Z, then the spindle reverses and the tap comes back to where it started
    /// along the same line ([G] "G33.1 Rigid Tapping"; I, the retract's speed factor, changes
    /// only the time). On a lathe the hole is on the axis: the tap must stand at X0. It is
    /// swept as the tool table's outline (a drill's: the tap's major diameter); the thread
    /// form is not drawn (a warning says so), and both moves are feeds at K per revolution.
    pub(super) fn rigid_tap(
        &mut self,
        b: &Block,
        at: Span,
        used: &mut Words,
    ) -> Result<(), Diagnostic> {
        if !self.spindle_on {
            return Err(alarm(
                at,
                "LS-VALUE",
                "Spindle not turning in G33.1 (LinuxCNC stops here)",
                "start the spindle with M3 or M4 before the tap",
            ));
        }
        if let Some(f) = used.take('F') {
            return Err(alarm(
                f.span,
                "LS-VALUE",
                "F word used with G33.1 (LinuxCNC stops here: the lead K sets the feed)",
                "leave F out of the G33.1 block",
            ));
        }
        let Some(k) = used.take('K') else {
            return Err(alarm(
                at,
                "LS-VALUE",
                "G33.1 without K (the tap's lead, distance per revolution)",
                "write e.g. G33.1 Z-20 K1.5 (each G33.1 block, a repeat too, needs K)",
            ));
        };
        if k.value <= 0.0 {
            return Err(alarm(
                k.span,
                "LS-VALUE",
                "G33.1 K must be a positive lead",
                "write the tap's pitch, e.g. K1.5",
            ));
        }
        used.take('I');
        let start = self.pos;
        let to = self.target(used)?.unwrap_or(start);
        if start.r.abs() > 1e-6 || to.r.abs() > 1e-6 {
            return Err(alarm(
                at,
                "LS-OFF-AXIS",
                format!(
                    "G33.1 from X{:.3} to X{:.3}: a tapped hole off the spindle axis is not axisymmetric",
                    2.0 * start.r,
                    2.0 * to.r
                ),
                "tap on the axis: stand at X0 and give only Z",
            ));
        }
        self.note_once(
            at,
            "LS-TAP",
            "G33.1 taps with the drill outline of the tool table (the tap's major diameter); the thread form is not drawn",
            "",
        );
        let per_rev = crate::Feed::PerRev {
            feed: k.value * self.unit(),
            spindle: self.spindle(),
        };
        let feed = self.feed_id(at, per_rev)?;
        for point in [to, start] {
            // (built as a rapid, which needs no F, then made the synchronised feed it is)
            let mut seg = self.segment(
                b.span,
                crate::Motion::Rapid,
                point,
                None,
                0.0,
                crate::ToolHint::Table,
            )?;
            seg.motion = crate::Motion::Feed;
            seg.feed = feed;
            self.emit(seg);
        }
        // modal in LinuxCNC: a later block of axis words (and K) taps again
        self.motion = MotionMode::Cycle(lc::RIGID_TAP);
        Ok(())
    }
}
