//! Running a canned cycle from the interpreter: the cycle's words and state in, its moves,
//! warnings, intended shapes and G70 compensation out.

use super::flow::Flow;
use super::Interp;
use crate::cycles::{self, Cycle, Output};
use crate::words::Words;
use crate::{Diagnostic, Motion, Span};
use gcode::{Block, Subprogram, Word};

impl Interp<'_> {
    /// Run a canned cycle and emit its moves with this block's span.
    pub(super) fn cycle<'b>(
        &mut self,
        code: i32,
        g: Option<&'b Word>,
        sub: &'b Subprogram,
        b: &'b Block,
        index: usize,
        used: &mut Words<'b>,
    ) -> Result<Flow, Diagnostic> {
        let tool_blade = self.blade_for(self.tool);
        let feed_mm = self.feed * self.unit();
        let out = {
            let mut c = Cycle {
                code,
                g,
                words: used,
                start: self.pos,
                // G91 (system B/C): the end points are incremental from the start point.
                shift: if self.incremental {
                    self.pos
                } else {
                    self.shift
                },
                unit: self.unit(),
                machine: self.machine,
                retained: &mut self.retained,
                program: sub,
                index,
                tool_blade,
                thread_chamfer: self.thread_chamfer,
                feed_mm,
                drill_return: self.drill_return,
                turning_free: self.spindle_on && !self.c_axis,
                linuxcnc: cycles::g76_linuxcnc::Modes {
                    x_diameter: self.x_diameter,
                    compensating: self.comp.is_some(),
                    spindle_turning: self.spindle_on,
                    incremental: self.incremental,
                },
            };
            cycles::run(&mut c)?
        };
        if code == crate::linuxcnc::CYCLE_G76 {
            // modal in LinuxCNC: a block of axis words repeats it
            self.motion = super::MotionMode::Cycle(code);
        }
        let mut out = out;
        if let Some(angle) = out.tool_angle {
            if !self.out.thread_angles.iter().any(|&(t, _)| t == self.tool) {
                self.out.thread_angles.push((self.tool, angle));
            }
        }
        self.out.warnings.append(&mut out.warnings);
        self.out.dwell_s += out.dwell_s;
        self.record_intended(std::mem::take(&mut out.intended), b.span);
        // a Haas G84 starts the spindle itself ("it is not necessary to start the spindle
        // CW before this canned cycle", Haas's G84 page): no spindle-stopped warning, and
        // the spindle is as the program left it afterwards
        let haas_tap = code == crate::codes::G84 && self.machine.control == crate::Control::Haas;
        let spindle = self.spindle_on;
        self.spindle_on |= haas_tap;
        let flow = self.emit_cycle(out, b.span);
        self.spindle_on = spindle;
        flow
    }

    /// The shapes a cycle intends, for the analysis. G73 then G70 on one shape hand it over
    /// twice: it is kept once, as the later cycle's (the one that finishes it: its tool
    /// owns the contour).
    pub(super) fn record_intended(
        &mut self,
        intended: Vec<(crate::IntendedKind, Vec<crate::Pt>)>,
        span: Span,
    ) {
        for (kind, points) in intended {
            let after_move = self.out.segments.len();
            match self
                .out
                .intended
                .iter_mut()
                .find(|i| i.kind == kind && i.points == points)
            {
                Some(known) => known.after_move = after_move,
                None => self.out.intended.push(crate::Intended {
                    kind,
                    points,
                    span,
                    after_move,
                    began: after_move,
                }),
            }
        }
    }

    /// Emit a cycle's moves with the block's `span` (a move's own span wins): G70 runs its
    /// pass as one compensation section (start-up A → B, or the move of the block that
    /// wrote G41/G42 inside the shape; cancel back to A). Where the program goes next.
    pub(super) fn emit_cycle(&mut self, out: Output, span: Span) -> Result<Flow, Diagnostic> {
        let side = out.comp.and_then(|shape_side| shape_side.or(self.comp));
        let feed = self.feed;
        for (k, m) in out.moves.into_iter().enumerate() {
            if k == out.comp_from {
                if let Some(side) = side {
                    if let Some(nose) = self.nose_for_offset(span) {
                        self.section = Some((side, nose, vec![]));
                    }
                }
            }
            if let Some(f) = m.feed {
                self.feed = f;
            }
            if let Some(modes) = m.modes {
                self.apply_shape_modes(modes);
            }
            let at = m.span.unwrap_or(span);
            if m.to.dist(self.pos) >= 1e-12 {
                // a threading move's lead is the F in force (G92: F is the lead)
                let lead = if m.motion == Motion::Thread {
                    out.lead.unwrap_or(self.feed * self.unit())
                } else {
                    0.0
                };
                self.thread_phase = m.phase.unwrap_or(out.thread_phase);
                self.push_at(at, m.motion, m.to, m.arc, lead, m.hint)?;
            }
        }
        self.feed = feed;
        self.thread_phase = 0.0;
        self.flush_compensation();
        Ok(out.resume_at.map_or(Flow::Next, Flow::Jump))
    }
}
