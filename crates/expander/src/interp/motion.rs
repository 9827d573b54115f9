//! The block's motion: end points in the work frame, feeds, rapids, lines, threads and
//! arcs, and emitting the segments (through the compensation buffer when one is open).

use super::modal::MotionMode;
use super::{alarm, arc_alarm, Interp};
use crate::arc;
use crate::words::Words;
use crate::{Arc, Diagnostic, Feed, Motion, Pt, RapidPath, Segment, Span, Spindle};
use gcode::Block;

impl Interp<'_> {
    /// The target of X/U Z/W in the G54 frame; `None` when no axis word is given.
    pub(super) fn target(&self, used: &mut Words) -> Result<Option<Pt>, Diagnostic> {
        let u = self.unit();
        let mut p = self.pos;
        let mut any = false;
        for (abs, inc, radius_div) in [('X', 'U', 2.0), ('Z', 'W', 1.0)] {
            let a = used.take(abs);
            let i = used.take(inc);
            if let (Some(a), Some(i)) = (a, i) {
                return Err(alarm(
                    i.span,
                    "LS-AXIS-TWICE",
                    format!("{abs} and {inc} both given (first at {})", a.span),
                    format!("give the end point either absolute ({abs}) or incremental ({inc})"),
                ));
            }
            let axis = if abs == 'X' { &mut p.r } else { &mut p.z };
            let shift = if abs == 'X' {
                self.shift.r
            } else {
                self.shift.z
            };
            if let Some(a) = a {
                *axis = a.value * u / radius_div + shift;
                any = true;
            }
            if let Some(i) = i {
                *axis += i.value * u / radius_div;
                any = true;
            }
        }
        Ok(any.then_some(p))
    }

    pub(super) fn feed_for(&mut self, span: Span, motion: Motion) -> Result<Feed, Diagnostic> {
        if motion == Motion::Rapid {
            return Ok(Feed::Rapid);
        }
        if !self.spindle_on && !self.spindle_warned {
            self.spindle_warned = true;
            self.warn(
                span,
                "LS-SPINDLE-STOPPED",
                "cutting with the spindle stopped (no M03/M04 in force)",
                "start the spindle with M03 or M04 before cutting; a real tool would break",
            );
        }
        if self.feed <= 0.0 {
            return Err(alarm(
                span,
                "PS011",
                "cutting move with no feed rate (F is 0 or was never given)",
                "give F in this block or before it",
            ));
        }
        let f = self.feed * self.unit();
        if motion == Motion::Thread {
            return Ok(Feed::PerRev {
                feed: f,
                spindle: self.spindle(),
            });
        }
        Ok(if self.per_rev {
            Feed::PerRev {
                feed: f,
                spindle: self.spindle(),
            }
        } else {
            Feed::PerMinute(f)
        })
    }

    pub(super) fn spindle(&self) -> Spindle {
        if self.css {
            Spindle::Css {
                vc: self.s_value,
                max_rpm: if self.s_clamp > 0.0 {
                    self.s_clamp
                } else {
                    self.machine.max_rpm
                },
            }
        } else {
            Spindle::Rpm(self.s_value)
        }
    }

    pub(super) fn push(
        &mut self,
        b: &Block,
        motion: Motion,
        to: Pt,
        arc: Option<Arc>,
        lead: f64,
    ) -> Result<(), Diagnostic> {
        self.push_at(b.span, motion, to, arc, lead, crate::ToolHint::Table)
    }

    pub(super) fn push_at(
        &mut self,
        span: Span,
        motion: Motion,
        to: Pt,
        arc: Option<Arc>,
        lead: f64,
        hint: crate::ToolHint,
    ) -> Result<(), Diagnostic> {
        let buffered = self.section.as_ref().map_or(0, |s| s.2.len());
        if self.out.segments.len() + buffered >= self.opts.max_segments {
            return Err(alarm(
                span,
                "LS-TOO-LONG",
                format!(
                    "the program expands to more than {} moves",
                    self.opts.max_segments
                ),
                "split the program, or check for a repeat count that is far too large",
            ));
        }
        let feed = self.feed_for(span, motion)?;
        let seg = Segment {
            motion,
            from: self.pos,
            to,
            arc,
            tool: self.tool,
            hint,
            lead,
            feed,
            span,
        };
        match &mut self.section {
            Some((_, _, buf)) => buf.push(seg),
            None => self.out.segments.push(seg),
        }
        self.pos = to;
        Ok(())
    }

    pub(super) fn rapid(&mut self, b: &Block, to: Pt) -> Result<(), Diagnostic> {
        if to.dist(self.pos) < 1e-12 {
            return Ok(());
        }
        if self.machine.rapid_path == RapidPath::PerAxis {
            // Both axes start together at their own rates; the shorter one arrives first.
            let (dz, dr) = (to.z - self.pos.z, to.r - self.pos.r);
            let (tz, tr) = (
                dz.abs() / self.machine.rapid_z,
                dr.abs() / self.machine.rapid_x,
            );
            let t = tz.min(tr);
            if t > 0.0 && (tz - tr).abs() > 1e-12 {
                let knee = Pt::new(
                    self.pos.z + dz.signum() * self.machine.rapid_z * t,
                    self.pos.r + dr.signum() * self.machine.rapid_x * t,
                );
                self.push(b, Motion::Rapid, knee, None, 0.0)?;
            }
        }
        self.push(b, Motion::Rapid, to, None, 0.0)
    }

    pub(super) fn motion_block(&mut self, b: &Block, used: &mut Words) -> Result<(), Diagnostic> {
        let is_arc = matches!(self.motion, MotionMode::Cw | MotionMode::Ccw);
        let r_word = if is_arc { used.take('R') } else { None };
        let i_word = if is_arc { used.take('I') } else { None };
        let k_word = if is_arc { used.take('K') } else { None };
        let Some(to) = self.target(used)? else {
            if let Some(w) = r_word.or(i_word).or(k_word) {
                return Err(alarm(
                    w.span,
                    "LS-ARC",
                    "arc data without an end point",
                    "give the arc's end point with X/U and Z/W",
                ));
            }
            return Ok(());
        };
        match self.motion {
            MotionMode::Rapid => self.rapid(b, to),
            MotionMode::Line | MotionMode::Thread if to.dist(self.pos) < 1e-12 => Ok(()),
            MotionMode::Line => self.push(b, Motion::Feed, to, None, 0.0),
            MotionMode::Thread => {
                let lead = self.feed * self.unit();
                self.push(b, Motion::Thread, to, None, lead)
            }
            MotionMode::Cycle(_) => Ok(()),
            MotionMode::Cw | MotionMode::Ccw => {
                let ccw = self.motion == MotionMode::Ccw;
                let u = self.unit();
                let from = self.pos;
                let centre = match (r_word, i_word, k_word) {
                    (Some(r), None, None) => arc::centre_from_radius(from, to, r.value * u, ccw)
                        .map_err(|e| arc_alarm(r.span, e))?,
                    (None, None, None) => {
                        return Err(alarm(
                            b.span,
                            "LS-ARC",
                            "G02/G03 without R or I/K",
                            "give the radius R, or the centre offset I (radius) and K",
                        ));
                    }
                    (Some(r), _, _) => {
                        return Err(alarm(
                            r.span,
                            "LS-ARC",
                            "arc given both R and I/K",
                            "give either R or I/K, not both",
                        ));
                    }
                    (None, i, k) => {
                        let c = Pt::new(
                            from.z + k.map_or(0.0, |k| k.value * u),
                            from.r + i.map_or(0.0, |i| i.value * u),
                        );
                        let span = i.or(k).map(|w| w.span).unwrap_or(b.span);
                        arc::check_centre(from, to, c).map_err(|e| arc_alarm(span, e))?;
                        c
                    }
                };
                self.push(
                    b,
                    Motion::Feed,
                    to,
                    Some(Arc {
                        center: centre,
                        ccw,
                    }),
                    0.0,
                )
            }
        }
    }
}
