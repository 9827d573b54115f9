//! The modal words of a block: G codes (classified by group, modal groups set), F, S, T,
//! the M codes that act before the motion, and the compensation mode.

use super::{alarm, g75_1_unfinished, Interp, MotionMode};
use crate::codes::{self, *};
use crate::cycles;
use crate::tnrc::Side;
use crate::words::Words;
use crate::{Diagnostic, Spindle};
use gcode::{Block, Word};

/// The G words of one block that act beyond setting a modal group.
#[derive(Clone, Copy, Default)]
pub(super) struct GWords<'b> {
    /// The block's motion code (group 01 or a modal cycle).
    pub(super) motion: Option<(MotionMode, &'b Word)>,
    /// G04, G28, G50 or a one-shot cycle.
    pub(super) one_shot: Option<(i32, &'b Word)>,
    /// G40, G41 or G42.
    pub(super) comp: Option<(i32, &'b Word)>,
}

/// An M code that acts after the block's motion.
pub(super) type After<'b> = Vec<(u32, &'b Word)>;

fn g_name(w: &Word) -> String {
    codes::name(w.code_tenths().unwrap_or(0))
}

impl Interp<'_> {
    /// Checks before anything runs: lengths in their domain, a pending G75.1 process block.
    pub(super) fn check_block(&self, b: &Block, used: &Words) -> Result<(), Diagnostic> {
        let inch_here = b
            .words
            .iter()
            .rev()
            .find_map(|w| match (w.letter, w.code_tenths()) {
                ('G', Some(G20)) => Some(true),
                ('G', Some(G21)) => Some(false),
                _ => None,
            });
        used.check_domain(if inch_here.unwrap_or(self.inch) {
            25.4
        } else {
            1.0
        })?;
        let is_g75_1 = b
            .words
            .iter()
            .any(|w| w.letter == 'G' && w.code_tenths() == Some(G75_1));
        if self.retained.g75_1.is_some() && !is_g75_1 {
            return Err(g75_1_unfinished(b.span));
        }
        Ok(())
    }

    /// Classify the G words, check their groups and set the modal ones (units, work
    /// offsets, spindle and feed modes).
    pub(super) fn g_words<'b>(
        &mut self,
        b: &'b Block,
        used: &mut Words,
    ) -> Result<GWords<'b>, Diagnostic> {
        let mut g = GWords::default();
        for (i, w) in b.words.iter().enumerate() {
            if w.letter != 'G' {
                continue;
            }
            used.mark(i);
            let Some(t) = w.code_tenths() else {
                return Err(alarm(
                    w.span,
                    "PS010",
                    format!("G{} is not a G code", w.value),
                    "G codes are G00 … G99 (and G75.1)",
                ));
            };
            let mut set_motion = |m: MotionMode| {
                if let Some((_, first)) = g.motion {
                    return Err(alarm(
                        w.span,
                        "PS010",
                        format!(
                            "{} and {} are both motion codes (group 01)",
                            g_name(first),
                            g_name(w)
                        ),
                        "keep one motion code per block",
                    ));
                }
                g.motion = Some((m, w));
                Ok(())
            };
            match t {
                G00 => set_motion(MotionMode::Rapid)?,
                G01 => set_motion(MotionMode::Line)?,
                G02 => set_motion(MotionMode::Cw)?,
                G03 => set_motion(MotionMode::Ccw)?,
                G32 => set_motion(MotionMode::Thread)?,
                t if cycles::is_modal(t) => set_motion(MotionMode::Cycle(t))?,
                t if t == G04 || t == G28 || t == G50 || cycles::is_cycle(t) => {
                    if let Some((_, first)) = g.one_shot {
                        return Err(alarm(
                            w.span,
                            "PS010",
                            format!("{} and {} in one block", g_name(first), g_name(w)),
                            "put each of them in a block of its own",
                        ));
                    }
                    g.one_shot = Some((t, w));
                }
                G20 => self.inch = true,
                G21 => self.inch = false,
                G40 | G41 | G42 => {
                    if let Some((_, first)) = g.comp {
                        return Err(alarm(
                            w.span,
                            "PS010",
                            format!("{} and {} in one block", g_name(first), g_name(w)),
                            "keep one of G40/G41/G42 per block",
                        ));
                    }
                    g.comp = Some((t, w));
                }
                t if codes::is_work_offset(t) => {
                    self.shift = self.machine.work_offsets[((t - G54) / 10) as usize];
                }
                G96 => self.css = true,
                G97 => self.css = false,
                G98 => self.per_rev = false,
                G99 => self.per_rev = true,
                _ => {
                    return Err(alarm(
                        w.span,
                        "PS010",
                        format!("{} is not a G code this lathe knows", g_name(w)),
                        "see spec/language.md for the supported codes",
                    ))
                }
            }
        }
        if let (Some((_, m)), Some((_, o))) = (g.motion, g.one_shot) {
            return Err(alarm(
                o.span,
                "PS010",
                format!("{} cannot share a block with {}", g_name(o), g_name(m)),
                "split the block in two",
            ));
        }
        Ok(g)
    }

    /// F and S (with G50 S the spindle clamp).
    pub(super) fn feed_and_speed(
        &mut self,
        used: &mut Words,
        g: &GWords,
    ) -> Result<(), Diagnostic> {
        if let Some(f) = used.take('F') {
            if f.value < 0.0 {
                return Err(alarm(
                    f.span,
                    "PS011",
                    "negative feed",
                    "F must be positive",
                ));
            }
            self.feed = f.value;
        }
        if let Some(s) = used.take('S') {
            if s.value < 0.0 {
                return Err(alarm(
                    s.span,
                    "LS-VALUE",
                    "negative spindle speed",
                    "S must be positive",
                ));
            }
            if g.one_shot.map(|(t, _)| t) == Some(G50) {
                self.s_clamp = s.value;
            } else {
                self.s_value = self.surface_or_rpm(s.value);
            }
        }
        Ok(())
    }

    /// S as the spindle takes it: under G96 in inch a surface speed in ft/min is m/min × 0.3048.
    fn surface_or_rpm(&self, s: f64) -> f64 {
        if self.css && self.inch {
            s * 0.3048
        } else {
            s
        }
    }

    /// The T word `Tttoo`: tool and offset. Returns the offset to put in force after the
    /// block's move when the block also cancels compensation (G40).
    pub(super) fn t_word(
        &mut self,
        used: &mut Words,
        g: &GWords,
    ) -> Result<Option<u32>, Diagnostic> {
        let Some(t) = used.take('T') else {
            return Ok(None);
        };
        if t.has_point || t.value < 0.0 || t.value > 9999.0 {
            return Err(alarm(
                t.span,
                "LS-T-WORD",
                "T must be four digits Tttoo",
                "write e.g. T0101: tool 01 with offset 01",
            ));
        }
        let v = t.value as u32;
        let (tool, offset) = (v / 100, v % 100);
        // A T word suspends compensation; offset 00 cancels it (spec/tnrc.md). In a G40
        // block the block's own move is the cancel move, made with the offset in force:
        // the new offset takes effect after it (a `G00 G40 X… Z… T0` return must not turn
        // the last compensated move into the cancel move).
        let mut deferred = None;
        if matches!(g.comp, Some((G40, _))) {
            deferred = Some(offset);
        } else {
            self.comp.flush(&mut self.out);
            self.comp.offset = offset;
        }
        if tool == 0 && offset != 0 {
            self.warn(
                t.span,
                "LS-T-WORD",
                format!("T{v} read as tool 00 with offset {offset:02}"),
                format!("write T{offset:02}{offset:02} for tool {offset} with offset {offset}"),
            );
        }
        if tool != 0 {
            self.use_tool(tool);
        }
        Ok(deferred)
    }

    /// Put a tool in force, noting its first use.
    fn use_tool(&mut self, tool: u32) {
        self.tool = tool;
        if !self.out.tools.contains(&tool) {
            self.out.tools.push(tool);
        }
    }

    /// The M codes that act before the motion (spindle on, coolant, stops); the others
    /// come back to act after it.
    pub(super) fn m_words_before<'b>(
        &mut self,
        b: &'b Block,
        used: &mut Words,
    ) -> Result<super::modal::After<'b>, Diagnostic> {
        let mut after = vec![];
        for (i, w) in b.words.iter().enumerate() {
            if w.letter != 'M' {
                continue;
            }
            used.mark(i);
            if w.has_point || w.value < 0.0 || w.value.fract() != 0.0 {
                return Err(alarm(
                    w.span,
                    "PS010",
                    format!("M{} is not an M code", w.value),
                    "M codes are whole numbers",
                ));
            }
            match w.value as u32 {
                3 | 4 => {
                    self.spindle_on = true;
                    self.spindle_warned = false;
                }
                8 | 0 | 1 => {}
                m @ (2 | 30 | 5 | 9 | 98 | 99) => after.push((m, w)),
                m => {
                    return Err(alarm(
                        w.span,
                        "LS-UNKNOWN-M",
                        format!("M{m:02} is not an M code this lathe knows"),
                        "supported: M00 M01 M02 M03 M04 M05 M08 M09 M30 M98 M99",
                    ))
                }
            }
        }
        Ok(after)
    }

    /// G40/G41/G42 (spec/tnrc.md), and the suspension of compensation by G28, G50,
    /// G54–G59 and the cycles (resumed at the next move).
    pub(super) fn compensation_mode(&mut self, b: &Block, g: &GWords) {
        if let Some((t, _)) = g.comp {
            let side = match t {
                G41 => Some(Side::Left),
                G42 => Some(Side::Right),
                _ => None,
            };
            if side.is_some() && self.comp.side.is_some() && side != self.comp.side {
                // G41 in G42 mode (or the reverse) cancels and re-establishes.
                self.comp.flush(&mut self.out);
            }
            self.comp.side = side;
        }
        let modal_cycle = g
            .motion
            .map_or(matches!(self.motion, MotionMode::Cycle(_)), |(m, _)| {
                matches!(m, MotionMode::Cycle(_))
            });
        let suspends = matches!(g.one_shot, Some((G28 | G50, _)))
            || g.one_shot.is_some_and(|(t, _)| cycles::is_cycle(t))
            || b.words
                .iter()
                .any(|w| w.letter == 'G' && w.code_tenths().is_some_and(codes::is_work_offset))
            || (modal_cycle && ['X', 'Z', 'U', 'W', 'R'].iter().any(|&l| b.has(l)));
        if suspends {
            self.comp.flush(&mut self.out);
        }
    }

    /// Put a G70 shape's S, T and G96–G99 in force (the T word changes the tool that cuts;
    /// it does not suspend the compensation of the G70 pass).
    pub(super) fn apply_shape_modes(&mut self, m: cycles::contour::ShapeModes) {
        if let Some(css) = m.css {
            self.css = css;
        }
        if let Some(per_rev) = m.per_rev {
            self.per_rev = per_rev;
        }
        if let Some(s) = m.s {
            self.s_value = self.surface_or_rpm(s);
        }
        if let Some(t) = m.tool {
            if t / 100 != 0 {
                self.use_tool(t / 100);
            }
        }
    }

    /// The spindle speed in force.
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
}
