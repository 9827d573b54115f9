//! The modal words of a block: its G codes (classified by group), F, S, T and the M codes
//! that act before the motion (spindle start, coolant). What they set stays in force.

use super::{alarm, Interp};
use crate::codes::{self, *};
use crate::words::{whole_in, Words};
use crate::{cycles, dialect, Diagnostic};
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

impl<'b> GWords<'b> {
    /// The block's motion code (group 01): one per block.
    fn set_motion(&mut self, m: MotionMode, w: &'b Word) -> Result<(), Diagnostic> {
        if let Some((_, first)) = self.motion {
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
        self.motion = Some((m, w));
        Ok(())
    }

    /// The block's one-shot code: one per block.
    fn set_one_shot(&mut self, t: i32, w: &'b Word) -> Result<(), Diagnostic> {
        if let Some((_, first)) = self.one_shot {
            return Err(alarm(
                w.span,
                "PS010",
                format!("{} and {} in one block", g_name(first), g_name(w)),
                "put each of them in a block of its own",
            ));
        }
        self.one_shot = Some((t, w));
        Ok(())
    }

    /// The block's G40/G41/G42: one per block.
    fn set_comp(&mut self, t: i32, w: &'b Word) -> Result<(), Diagnostic> {
        if let Some((_, first)) = self.comp {
            return Err(alarm(
                w.span,
                "PS010",
                format!("{} and {} in one block", g_name(first), g_name(w)),
                "keep one of G40/G41/G42 per block",
            ));
        }
        self.comp = Some((t, w));
        Ok(())
    }

    /// A one-shot code shares no block with a motion code, but G53 moves at the block's
    /// G00/G01 (spec/dialects.md §6.4; `G53 G00 X0`, the Haas and FANUC way home), and G28
    /// goes home at rapid with a G00 beside it (`G28 G00 U0 W0`, Haas class programs:
    /// docs/field-rules.md §10); either way the code sets the motion mode for the blocks
    /// after.
    fn check_motion_with_one_shot(&self) -> Result<(), Diagnostic> {
        let (Some((m, m_word)), Some((o_code, o))) = (self.motion, self.one_shot) else {
            return Ok(());
        };
        if o_code == G53 && matches!(m, MotionMode::Rapid | MotionMode::Line) {
            return Ok(());
        }
        if o_code == G28 && m == MotionMode::Rapid {
            return Ok(());
        }
        Err(alarm(
            o.span,
            "PS010",
            format!("{} cannot share a block with {}", g_name(o), g_name(m_word)),
            "split the block in two",
        ))
    }
}

fn g_name(w: &Word) -> String {
    codes::g_name(w.code_tenths().unwrap_or(0))
}

/// The one-shot codes: they act once, after the block's modes, instead of a motion.
fn is_one_shot(t: i32) -> bool {
    matches!(
        t,
        G04 | G10 | G27 | G28 | G50 | G50_3 | G52 | G53 | crate::linuxcnc::RIGID_TAP
    ) || cycles::is_cycle(t)
}

impl Interp<'_> {
    /// Read the block's G codes in the control's system (translated to their canonical
    /// meaning by `crate::dialect`): set the plain modes (G20/G21, G54–G59, G96–G99,
    /// G90/G91 of B/C, G17–G19), check the groups, and hand back the codes that act later.
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
            let t = self.canonical(w)?;
            if let Some(reason) = self.linuxcnc_unsupported(t) {
                return Err(alarm(
                    w.span,
                    "LS-NOT-IMPLEMENTED",
                    format!("{} (LinuxCNC): {reason}", g_name(w)),
                    "docs/linuxcnc.md lists the LinuxCNC codes latsim runs",
                ));
            }
            if let Some(reason) = codes::not_simulated(t) {
                return Err(alarm(
                    w.span,
                    "LS-NOT-SIMULATED",
                    format!("{} is not simulated: {reason}", g_name(w)),
                    "latsim simulates one turned 2D section; run this part of the program on a mill-turn simulator (live tools, C axis, a second spindle)",
                ));
            }
            if let Some(letters) = codes::no_effect(t) {
                for &l in letters {
                    used.take(l);
                }
                continue;
            }
            match t {
                G00 => g.set_motion(MotionMode::Rapid, w)?,
                G01 => g.set_motion(MotionMode::Line, w)?,
                G02 => g.set_motion(MotionMode::Cw, w)?,
                G03 => g.set_motion(MotionMode::Ccw, w)?,
                G32 => g.set_motion(MotionMode::Thread, w)?,
                t if cycles::is_modal(t) => g.set_motion(MotionMode::Cycle(t), w)?,
                t if is_one_shot(t) => g.set_one_shot(t, w)?,
                G40 | G41 | G42 => g.set_comp(t, w)?,
                crate::linuxcnc::DYNAMIC_LEFT | crate::linuxcnc::DYNAMIC_RIGHT => {
                    self.dynamic_nose(w, used)?;
                    let side = if t == crate::linuxcnc::DYNAMIC_LEFT {
                        G41
                    } else {
                        G42
                    };
                    g.set_comp(side, w)?
                }
                t => self.set_mode(t, w, b, used)?,
            }
        }
        g.check_motion_with_one_shot()?;
        Ok(g)
    }

    /// A G code that sets a mode of the interpreter at once (units, work offset, spindle
    /// and feed modes, B/C absolute/incremental and drill return, plane, drill cancel);
    /// any other is an alarm.
    fn set_mode(
        &mut self,
        t: i32,
        w: &Word,
        b: &Block,
        used: &mut Words,
    ) -> Result<(), Diagnostic> {
        if self.machine.control == crate::Control::LinuxCnc
            && self.linuxcnc_mode(t, (w, b), used)?
        {
            return Ok(());
        }
        match t {
            G20 => self.inch = true,
            G21 => self.inch = false,
            G54 if b.has('P') => self.select_extra_offset(w, used)?,
            G54_1 | G154 => self.select_extra_offset(w, used)?,
            t if codes::work_offset(t).is_some() => {
                self.select_work_offset(w, codes::work_offset(t).unwrap_or(0));
            }
            G96 => self.css = true,
            G97 => self.css = false,
            G98 => self.per_rev = false,
            G99 => self.per_rev = true,
            dialect::ABSOLUTE => self.incremental = false,
            dialect::INCREMENTAL => self.incremental = true,
            dialect::DRILL_RETURN_INITIAL => self.drill_return = crate::DrillReturn::Initial,
            dialect::DRILL_RETURN_R => self.drill_return = crate::DrillReturn::RPoint,
            G18 => self.plane = None,
            G17 | G19 => self.plane = Some((t, w.span)),
            G80 => self.retained.drill = None,
            650 if b.has('H') => return Err(super::macros::macro_a(b)),
            G11 => {
                return Err(alarm(
                    w.span,
                    "PS010",
                    "G11 ends parameter input, but no G10 L50 started it",
                    "remove the G11, or start the parameter blocks with G10 L50",
                ))
            }
            _ => {
                return Err(alarm(
                    w.span,
                    "PS010",
                    format!("{} is not a G code this lathe knows", g_name(w)),
                    unknown_code_help(t),
                ))
            }
        }
        Ok(())
    }

    /// The canonical meaning of a G word under the control (`crate::dialect`), or the alarm
    /// naming the control whose code it is.
    pub(super) fn canonical(&self, w: &Word) -> Result<i32, Diagnostic> {
        let Some(t) = w.code_tenths() else {
            return Err(alarm(
                w.span,
                "PS010",
                format!("G{} is not a G code", w.value),
                "G codes are G00 … G99 (and G75.1)",
            ));
        };
        dialect::canonical(self.machine.control, t)
            .map_err(|f| alarm(w.span, "LS-DIALECT", f.message, f.help))
    }

    /// Why the `LinuxCNC` code `t` (canonical) does not run, under `--control linuxcnc`.
    fn linuxcnc_unsupported(&self, t: i32) -> Option<String> {
        if self.machine.control != crate::Control::LinuxCnc {
            return None;
        }
        if crate::linuxcnc::is_drilling(t) && !self.drills_along_z(t) {
            return Some(
                "LinuxCNC drills along the plane's normal: in G18 (the lathe's plane) that is Y, no hole in the turned section; write G17 before the cycle to drill along Z, as LinuxCNC's lathe drill macro does".into(),
            );
        }
        // (its G70, G71, G72 and G76 run: `linuxcnc_g7x`, `cycles/g76_linuxcnc`)
        crate::linuxcnc::unsupported(t).map(str::to_string)
    }

    /// Whether `t` is a `LinuxCNC` drilling cycle under G17: it drills along Z, the lathe's
    /// axis (its normal), so the XY plane is no live-tooling plane for it.
    pub(super) fn drills_along_z(&self, t: i32) -> bool {
        self.machine.control == crate::Control::LinuxCnc
            && crate::linuxcnc::is_drilling(t)
            && matches!(self.plane, Some((170, _)))
    }

    /// Whether the block has a G code whose canonical meaning satisfies `pred`.
    pub(super) fn has_g(&self, b: &Block, pred: impl Fn(i32) -> bool) -> bool {
        b.words.iter().any(|w| {
            w.letter == 'G'
                && w.code_tenths()
                    .and_then(|t| dialect::canonical(self.machine.control, t).ok())
                    .is_some_and(&pred)
        })
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
        if self.machine.control == crate::Control::LinuxCnc {
            if let Some(t) = used.take('T') {
                self.prepare_tool(t)?;
            }
            return Ok(None);
        }
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
            let (tool, offset) = self.tool_and_offset(v, t);
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
            self.select_tool(tool);
            let called = (self.tool, offset);
            if offset != 0 && !self.out.tool_offsets.contains(&called) {
                self.out.tool_offsets.push(called);
            }
        }
        Ok(deferred)
    }

    /// Tool and offset of `T<v>`: `Tttoo`. A one- or two-digit T is ambiguous across
    /// controls (spec/dialects.md §3.7), so the profile's `short_t` decides. **Interpretation**
    /// of the defaults: on the seeds' GSK `"offset"` (`T1` = `T0001`, as before); on FANUC
    /// and Haas the spec's `"tool"` (`T1` = `T0101`). Warned either way.
    fn tool_and_offset(&mut self, v: u32, t: &Word) -> (u32, u32) {
        let (tool, offset) = (v / 100, v % 100);
        if tool != 0 || offset == 0 {
            return (tool, offset);
        }
        if self.machine.short_t == crate::ShortT::Offset {
            self.warn(
                t.span,
                "LS-T-WORD",
                format!("T{v} read as tool 00 with offset {offset:02}"),
                format!("write T{offset:02}{offset:02} for tool {offset} with offset {offset}"),
            );
            (0, offset)
        } else {
            self.warn(
                t.span,
                "LS-T-WORD",
                format!("T{v} read as tool {offset} with offset {offset} (short T: `short_t = \"tool\"`)"),
                format!("write T{offset:02}{offset:02}; on some FANUC parameter settings T{v} is an offset number only"),
            );
            (offset, offset)
        }
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
    pub(super) fn select_tool(&mut self, tool: u32) {
        if tool != 0 {
            self.tool = tool;
            if !self.out.tools.contains(&tool) {
                self.out.tools.push(tool);
            }
        }
    }

    /// The M codes of the block, in order (up to three, FANUC's parameter maximum): the
    /// ones that act before the motion (M03/M04, M08, M00/M01 and the machine functions of
    /// the control's table, `crate::mcodes`) act here; the ones that act after it
    /// (M02/M30, M05/M09, M98/M99) are handed back in order. An M code neither the table
    /// nor the profile's `accept_m` knows is accepted as a machine function, warned once.
    pub(super) fn m_codes_before<'b>(
        &mut self,
        b: &'b Block,
        used: &mut Words,
    ) -> Result<Vec<(u32, &'b Word)>, Diagnostic> {
        let mut after = vec![];
        let mut seen: Vec<&Word> = vec![];
        for (i, w) in b.words.iter().enumerate() {
            if w.letter != 'M' {
                continue;
            }
            used.mark(i);
            if w.has_point || w.value < 0.0 || w.value.fract() != 0.0 || w.value > 9999.0 {
                return Err(alarm(
                    w.span,
                    "PS010",
                    format!("M{} is not an M code", w.value),
                    "M codes are whole numbers",
                ));
            }
            seen.push(w);
            let flow = |m: f64| matches!(m as u32, 2 | 30 | 98 | 99);
            if seen.len() > 1 && seen.iter().any(|w| flow(w.value)) {
                let other = seen[0];
                return Err(alarm(
                    w.span,
                    "PS010",
                    format!(
                        "M{:02} cannot share a block with M{:02}",
                        w.value as u32, other.value as u32
                    ),
                    "M00 M01 M02 M30 M98 M99 stand alone; put the other M code in a block of its own",
                ));
            }
            if seen.len() > 3 {
                return Err(alarm(
                    w.span,
                    "PS010",
                    "more than three M codes in one block",
                    "a FANUC block holds at most three M codes; split the block",
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
                6 if self.machine.control == crate::Control::LinuxCnc => self.change_tool(w)?,
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
                m @ (133 | 134 | 143 | 144) if self.machine.control == crate::Control::Haas => {
                    // P is the live tool's or the sub-spindle's speed (rpm, Haas lathe
                    // manual, M133/M134, M143/M144): nothing of the main spindle's section
                    used.take('P');
                    self.machine_function(m, w)
                }
                m => self.machine_function(m, w),
            }
        }
        Ok(after)
    }

    /// A machine function: its effect on what the simulation warns about, and the one
    /// warning for a code the control's table does not know.
    fn machine_function(&mut self, m: u32, w: &Word) {
        use crate::mcodes::Effect;
        let known = crate::mcodes::machine_function(self.machine.control, m);
        match known.map(|k| k.1) {
            Some(Effect::SpindleStops) => self.spindle_on = false,
            Some(Effect::ChuckOpens) => {
                self.chuck_open = true;
                self.chuck_warned = false;
            }
            Some(Effect::ChuckCloses) => self.chuck_open = false,
            Some(Effect::ThreadChamfer(on)) => self.thread_chamfer = on,
            Some(Effect::CAxis(on)) => self.c_axis = on,
            Some(Effect::Tailstock(engaged)) => {
                // inside a G41/G42 section the moves are emitted when it ends
                if self.section.is_some() {
                    self.tailstock_pending = Some(engaged);
                } else {
                    self.out.tailstock.push((self.out.segments.len(), engaged));
                }
            }
            Some(Effect::None) | None => {}
        }
        let accepted = known.is_some()
            || self.machine.accept_m.contains(&m)
            || self.machine.m_names.contains_key(&m);
        if !accepted && !self.m_warned.contains(&m) {
            self.m_warned.push(m);
            self.warn(
                w.span,
                "W-M-UNKNOWN",
                format!(
                    "M{m:02} is not in the {} M-code table: accepted as a machine function that does not move the tool",
                    self.machine.control.key()
                ),
                format!("if M{m:02} moves the tool, latsim cannot show it; list it in the machine profile's accept_m to silence this"),
            );
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
            self.s_value = self.speed(s);
        }
        if let Some(t) = m.tool {
            self.select_tool(t / 100);
        }
    }
}

/// What to do about a G code no supported control knows; G07 is `LinuxCNC`'s diameter mode
/// (issue 31: generated `LinuxCNC` lathe programs start `G18 G7 G90`).
fn unknown_code_help(t: i32) -> &'static str {
    if t == G07 {
        "G7 selects diameter mode in LinuxCNC (rs274ngc): run LinuxCNC programs with --control linuxcnc (under FANUC, GSK and Haas X is a diameter by default; --x-mode radius for radii)"
    } else {
        "see spec/language.md and spec/dialects.md §6.1 for the supported codes"
    }
}
