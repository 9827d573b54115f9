//! The modal words of a block: its G codes (classified by group), F, S, T and the M codes
//! that act before the motion (spindle start, coolant). What they set stays in force.

use super::{alarm, Interp};
use crate::codes::{self, *};
use crate::words::{whole_in, Words};
use crate::{cycles, Diagnostic};
use gcode::{Block, Word};

/// The motion mode in force (group 01).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum MotionMode {
    Rapid,
    Line,
    Cw,
    Ccw,
    Thread,
    /// A modal canned cycle (G90/G92/G94), by code in tenths.
    Cycle(i32),
}

/// A block's G codes that act beyond setting a mode: its motion code, its one-shot code
/// (G04, G28, G50 or a cycle) and its G40/G41/G42.
#[derive(Default)]
pub(super) struct GWords<'b> {
    pub(super) motion: Option<(MotionMode, &'b Word)>,
    pub(super) one_shot: Option<(i32, &'b Word)>,
    pub(super) comp: Option<(i32, &'b Word)>,
}

fn g_name(w: &Word) -> String {
    codes::g_name(w.code_tenths().unwrap_or(0))
}

/// Whether the block has a G code with these tenths.
pub(super) fn has_g(b: &Block, pred: impl Fn(i32) -> bool) -> bool {
    b.words
        .iter()
        .any(|w| w.letter == 'G' && w.code_tenths().is_some_and(&pred))
}

impl Interp<'_> {
    /// Read the block's G codes: set the plain modes (G20/G21, G54–G59, G96–G99), check
    /// the groups, and hand back the codes that act later in the block.
    pub(super) fn g_codes<'b>(
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
                G18 => {}
                G80 => self.retained.drill = None,
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
                t if codes::work_offset(t).is_some() => {
                    self.shift = self.machine.work_offsets[codes::work_offset(t).unwrap()];
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

    /// F, S and T: the feed, the spindle speed (or the G50 S clamp) and the tool/offset.
    pub(super) fn feed_speed_tool(
        &mut self,
        used: &mut Words,
        one_shot: Option<i32>,
        cancels: bool,
    ) -> Result<Option<u32>, Diagnostic> {
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
            if one_shot == Some(G50) {
                self.s_clamp = s.value;
            } else {
                self.s_value = self.speed(s.value);
            }
        }
        let mut deferred = None;
        if let Some(t) = used.take('T') {
            if !whole_in(t, 0.0, 9999.0) {
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
            if cancels {
                deferred = Some(offset);
            } else {
                self.flush_compensation();
                self.offset = offset;
            }
            if tool == 0 && offset != 0 {
                self.warn(
                    t.span,
                    "LS-T-WORD",
                    format!("T{v} read as tool 00 with offset {offset:02}"),
                    format!("write T{offset:02}{offset:02} for tool {offset} with offset {offset}"),
                );
            }
            self.select_tool(tool);
        }
        Ok(deferred)
    }

    /// The S value in force for a programmed S: under G96 in inch, feet/min become m/min.
    fn speed(&self, s: f64) -> f64 {
        if self.css && self.inch {
            s * 0.3048
        } else {
            s
        }
    }

    /// Tool `tool` cuts from now on (tool 00 keeps the tool in force).
    fn select_tool(&mut self, tool: u32) {
        if tool != 0 {
            self.tool = tool;
            if !self.out.tools.contains(&tool) {
                self.out.tools.push(tool);
            }
        }
    }

    /// The M codes that act before the motion (M03/M04, M08, M00/M01); the ones that act
    /// after it (M02/M30, M05/M09, M98/M99) are handed back in order.
    pub(super) fn m_codes_before<'b>(
        &mut self,
        b: &'b Block,
        used: &mut Words,
    ) -> Result<Vec<(u32, &'b Word)>, Diagnostic> {
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
                23 | 24 if self.machine.control == crate::Control::Haas => {
                    self.thread_chamfer = w.value as u32 == 23;
                }
                m @ (2 | 30 | 5 | 9 | 98 | 99) => after.push((m, w)),
                97 if self.machine.control == crate::Control::Haas => after.push((97, w)),
                97 => {
                    return Err(alarm(
                        w.span,
                        "LS-UNKNOWN-M",
                        format!(
                            "M97 (local subprogram call) is the Haas form: run with --control haas (this control is {})",
                            self.machine.control.key()
                        ),
                        "call a subprogram with M98 P<program number> under this control",
                    ))
                }
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
            self.s_value = self.speed(s);
        }
        if let Some(t) = m.tool {
            self.select_tool(t / 100);
        }
    }
}
