//! The block's motion: end points in the work frame, feeds, rapids, lines, threads and
//! arcs, and emitting the segments (through the compensation buffer when one is open).

use super::modal::MotionMode;
use super::{alarm, Interp};
use crate::arc::ArcWords;
use crate::words::Words;
use crate::{Arc, Diagnostic, Feed, Motion, Pt, RapidPath, Segment, Span, Spindle};
use gcode::Block;

/// A feed per minute (G98) slower than this, mm/min, cuts nothing a lathe cuts: a feed per
/// revolution written under the wrong mode (a GSK's power-on G98 with `F0.15` ran a
/// 67-hour cycle time with no word; field run 5).
const SLOWEST_MM_PER_MIN: f64 = 1.0;

impl Interp<'_> {
    /// The target of X/U Z/W in the G54 frame; `None` when no axis word is given. In
    /// system B/C, X and Z follow G90/G91, and U/W are incremental axes as the profile's
    /// `uw_incremental` allows (warned once: it depends on the builder, dialects.md §2.2).
    pub(super) fn target(&mut self, used: &mut Words) -> Result<Option<Pt>, Diagnostic> {
        let u = self.unit();
        let mut p = self.pos;
        let mut any = false;
        let system_b = self.machine.control.system() != crate::GCodeSystem::A;
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
            if let (Some(i), true) = (i, system_b) {
                self.uw_outside_cycle(i)?;
            }
            let axis = if abs == 'X' { &mut p.r } else { &mut p.z };
            let shift = if abs == 'X' {
                self.shift.r
            } else {
                self.shift.z
            };
            if let Some(a) = a {
                if self.incremental {
                    *axis += a.value * u / radius_div;
                } else {
                    *axis = a.value * u / radius_div + shift;
                }
                any = true;
            }
            if let Some(i) = i {
                *axis += i.value * u / radius_div;
                any = true;
            }
        }
        Ok(any.then_some(p))
    }

    /// System B/C: U or W outside a cycle.
    fn uw_outside_cycle(&mut self, w: &gcode::Word) -> Result<(), Diagnostic> {
        if self.machine.control == crate::Control::LinuxCnc {
            return Err(alarm(
                w.span,
                "LS-DIALECT",
                format!("{} is an axis of its own in LinuxCNC, not an incremental X/Z (a lathe has X and Z)", w.letter),
                "write G91 X…/Z… for an incremental move (G90 back to absolute)",
            ));
        }
        if !self.machine.uw_incremental {
            return Err(alarm(
                w.span,
                "LS-DIALECT",
                format!("{} is not an axis on this machine in system B/C (uw_incremental = false)", w.letter),
                "write G91 X…/Z… for an incremental move, or set uw_incremental = true in the machine profile",
            ));
        }
        if !self.uw_warned {
            self.uw_warned = true;
            self.warn(
                w.span,
                "W-UW-SYSTEM-B",
                "U/W as incremental axes depend on the machine in system B/C: read as incremental X/Z",
                "if this machine rejects U/W, set uw_incremental = false in the machine profile",
            );
        }
        Ok(())
    }

    /// The feed of a cutting move, warning once of a feed per minute slower than any cut.
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
        if self.chuck_open && !self.chuck_warned {
            self.chuck_warned = true;
            self.warn(
                span,
                "LS-CHUCK-OPEN",
                "cutting with the chuck unclamped",
                "clamp the chuck (Haas M10, GSK M12, FANUC builders M68) before cutting",
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
        if !self.per_rev
            && motion == Motion::Feed
            && f < SLOWEST_MM_PER_MIN
            && !self.slow_feed_warned
        {
            self.slow_feed_warned = true;
            self.warn(
                span,
                "W-FEED-PER-MINUTE",
                format!(
                    "F{} is {f:.3} mm/min under G98 (feed per minute): slower than any cut, it reads as a feed per revolution",
                    self.feed
                ),
                "write G99 (feed per revolution) before the cut, or F in mm/min under G98; the cycle time follows the feed as written",
            );
        }
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
        if let Some(p) = &self.corner {
            let what = match (motion, arc) {
                (Motion::Rapid, _) => "a rapid comes",
                (Motion::Thread, _) => "a thread move comes",
                (Motion::Feed, Some(_)) => "an arc comes",
                (Motion::Feed, None) => "a cycle's move comes",
            };
            return Err(self.corner_without_line(p, &format!("{what} (line {})", span.line)));
        }
        let seg = self.segment(span, motion, to, arc, lead, hint)?;
        self.emit(seg);
        Ok(())
    }

    /// The segment from the present position to `to`, with the feed, tool and thread
    /// phase in force (not emitted).
    pub(super) fn segment(
        &mut self,
        span: Span,
        motion: Motion,
        to: Pt,
        arc: Option<Arc>,
        lead: f64,
        hint: crate::ToolHint,
    ) -> Result<Segment, Diagnostic> {
        let buffered = self.section.as_ref().map_or(0, |s| s.2.len());
        if self.out.segments.len() + buffered >= self.opts.max_segments {
            return Err(alarm(
                span,
                "LS-TOO-LONG",
                format!(
                    "the program expands to more than {} moves (the move budget)",
                    self.opts.max_segments
                ),
                "check for a loop or a repeat count that is far too large, or raise --max-moves if the program really makes this many moves",
            ));
        }
        if motion != Motion::Rapid {
            self.cut_in_work_system()?;
        }
        let feed = self.feed_for(span, motion)?;
        let feed = self.feed_id(span, feed)?;
        Ok(Segment {
            motion,
            from: self.pos,
            to,
            arc,
            tool: self.tool,
            hint,
            lead,
            thread_phase: if motion == Motion::Thread {
                self.thread_phase
            } else {
                0.0
            },
            feed,
            span,
        })
    }

    /// The toolpath's number of `feed` (moves hold the number, not the feed).
    pub(super) fn feed_id(&mut self, span: Span, feed: Feed) -> Result<crate::FeedId, Diagnostic> {
        self.out.feeds.id(feed).ok_or_else(|| {
            alarm(
                span,
                "LS-TOO-LONG",
                "the program uses more than 2^32 different feeds",
                "split the program",
            )
        })
    }

    /// Emit a segment: into the compensation section when one is open, else the toolpath.
    pub(super) fn emit(&mut self, seg: Segment) {
        self.pos = seg.to;
        match &mut self.section {
            Some((_, _, buf)) => buf.push(seg),
            None => self.out.segments.push(seg),
        }
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
        let arc_words = if is_arc {
            ArcWords {
                r: used.take('R'),
                i: used.take('I'),
                k: used.take('K'),
            }
        } else {
            ArcWords::default()
        };
        let (corner, angle) = if self.motion == MotionMode::Line {
            let axes = (
                used.has('X') || used.has('U'),
                used.has('Z') || used.has('W'),
            );
            (self.corner_word(used)?, used.take('a').map(|w| (w, axes)))
        } else {
            (None, None)
        };
        let mut target = self.target(used)?;
        if let Some((w, given)) = angle {
            // the coordinate not written, from the angle (an alarm without either)
            let to = target.unwrap_or(self.pos);
            target = Some(crate::corner::line_at_angle(self.pos, to, w, given)?);
        }
        let Some(to) = target else {
            if let Some(ask) = corner {
                return Err(crate::corner::standing_still(ask.word));
            }
            return arc_words.without_end_point().map_or(Ok(()), Err);
        };
        match self.motion {
            MotionMode::Rapid => self.rapid(b, to),
            MotionMode::Line if to.dist(self.pos) < 1e-12 => match corner {
                Some(ask) => Err(crate::corner::standing_still(ask.word)),
                None => Ok(()),
            },
            MotionMode::Thread if to.dist(self.pos) < 1e-12 => Ok(()),
            MotionMode::Line => self.feed_line(b.span, to, corner),
            MotionMode::Thread => {
                if self.machine.control == crate::Control::LinuxCnc {
                    // G33 K: the lead is K and the feed per revolution; F stays the feed
                    let lead = self.thread_lead(b, used)?;
                    let per_rev = lead / self.unit();
                    let feed = std::mem::replace(&mut self.feed, per_rev);
                    let pushed = self.push(b, Motion::Thread, to, None, lead);
                    self.feed = feed;
                    return pushed;
                }
                let lead = self.feed * self.unit();
                self.thread_phase = crate::cycles::thread_start_angle(used)? / 360.0;
                let pushed = self.push(b, Motion::Thread, to, None, lead);
                self.thread_phase = 0.0;
                pushed
            }
            MotionMode::Cycle(_) => Ok(()),
            MotionMode::Cw | MotionMode::Ccw => {
                let ccw = self.motion == MotionMode::Ccw;
                let centre = arc_words.centre(self.pos, to, ccw, self.unit(), b.span)?;
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
