//! The block's action: its one motion (G00, G01, G02/G03, G32), or G04, G28, G50, or a
//! cycle; end points, feeds, and the segments they make.

use super::modal::GWords;
use super::{alarm, Flow, Interp, MotionMode};
use crate::codes::*;
use crate::words::Words;
use crate::{arc, Arc, Diagnostic, Feed, Motion, Pt, RapidPath, Segment, Span, ToolHint};
use gcode::{Block, Subprogram, Word};

/// Axis words that make a block move.
const AXES: [char; 4] = ['X', 'Z', 'U', 'W'];

impl Interp<'_> {
    /// Run the block's one action.
    pub(super) fn action<'b>(
        &mut self,
        sub: &'b Subprogram,
        index: usize,
        used: &mut Words<'b>,
        g: &GWords<'b>,
    ) -> Result<Flow, Diagnostic> {
        let b = &sub.blocks[index];
        match g.one_shot {
            Some((G04, w)) => self.dwell(used, w)?,
            Some((G28, w)) => self.g28(b, used, w)?,
            Some((G50, _)) => self.g50(used)?,
            Some((t, w)) => return self.cycle(t, Some(w), sub, index, used),
            None => {
                if let Some((m, _)) = g.motion {
                    self.motion = m;
                }
                if let MotionMode::Cycle(t) = self.motion {
                    if ['X', 'Z', 'U', 'W', 'R'].iter().any(|&l| b.has(l)) {
                        return self.cycle(t, g.motion.map(|(_, w)| w), sub, index, used);
                    }
                } else {
                    let noses = self.noses();
                    let moves = AXES.iter().any(|&l| b.has(l));
                    let on_arc = matches!(self.motion, MotionMode::Cw | MotionMode::Ccw);
                    self.comp
                        .start(moves, on_arc, b.span, &noses, &mut self.out)?;
                    self.motion_block(b, used)?;
                    if self.comp.is_open() && (self.comp.side.is_none() || self.comp.offset == 0) {
                        // This block was the cancel block.
                        self.comp.flush(&mut self.out);
                    }
                }
            }
        }
        Ok(Flow::Next)
    }

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

    fn feed_for(&mut self, span: Span, motion: Motion) -> Result<Feed, Diagnostic> {
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
        // a thread's F is its lead: per revolution whatever G98/G99 says
        Ok(if self.per_rev || motion == Motion::Thread {
            Feed::PerRev {
                feed: f,
                spindle: self.spindle(),
            }
        } else {
            Feed::PerMinute(f)
        })
    }

    fn push(
        &mut self,
        b: &Block,
        motion: Motion,
        to: Pt,
        arc: Option<Arc>,
        lead: f64,
    ) -> Result<(), Diagnostic> {
        self.push_at(b.span, motion, to, arc, lead, ToolHint::Table)
    }

    /// Emit one move from the current position (into the compensation section when one is
    /// open).
    pub(super) fn push_at(
        &mut self,
        span: Span,
        motion: Motion,
        to: Pt,
        arc: Option<Arc>,
        lead: f64,
        hint: ToolHint,
    ) -> Result<(), Diagnostic> {
        if self.out.segments.len() + self.comp.buffered() >= self.opts.max_segments {
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
        if let Some(seg) = self.comp.buffer(seg) {
            self.out.segments.push(seg);
        }
        self.pos = to;
        Ok(())
    }

    fn rapid(&mut self, b: &Block, to: Pt) -> Result<(), Diagnostic> {
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

    fn motion_block(&mut self, b: &Block, used: &mut Words) -> Result<(), Diagnostic> {
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
                let center = arc::centre_from_words(
                    self.pos,
                    to,
                    ccw,
                    r_word,
                    i_word,
                    k_word,
                    self.unit(),
                    b.span,
                )?;
                self.push(b, Motion::Feed, to, Some(Arc { center, ccw }), 0.0)
            }
        }
    }

    fn dwell(&mut self, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        let p = used.take('P');
        let x = used.take('X').or_else(|| used.take('U'));
        let seconds = match (p, x) {
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
    fn g28(&mut self, b: &Block, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
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
    fn g50(&mut self, used: &mut Words) -> Result<(), Diagnostic> {
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
