//! The modal interpreter: runs the blocks like a controller and emits segments.
//!
//! Order within one block (FANUC/GSK practice): modal G codes, F, S, T and M03/M04/M08
//! first; then the block's one motion (or G04/G28/G50); then M05/M09, M98/M99 and the
//! program end. A controller alarm stops the run; the segments made so far are kept.
//!
//! This file is the dispatcher; the words live in `modal` (G/M/F/S/T), `flow` (program
//! flow), `motion` (moves), `actions` (G04/G28/G50), `cycle` (canned cycles), and the
//! compensation buffer in `crate::tnrc`.

mod actions;
mod ahead;
mod corner;
mod cycle;
mod dialect_words;
mod flow;
mod frame;
mod g10;
mod linuxcnc;
mod linuxcnc_g7x;
mod loop_guard;
mod macros;
mod modal;
mod modal_call;
mod motion;
mod reach;
mod rigid_tap;
mod tool_facts;

use crate::codes::{self, *};
use crate::cycles::{self, g75_1, Retained};
use crate::tnrc::{Nose, Side};
use crate::words::Words;
use crate::{Diagnostic, Machine, Pt, Segment, Span};
use flow::{Exit, Flow};
use gcode::{Block, Program, Subprogram, Word};
use modal::GWords;
pub(crate) use modal::MotionMode;

/// Interpreter settings from the command line.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Skip blocks that start with `/`.
    pub block_delete: bool,
    /// The move budget: stop with an alarm when the program expands to more segments than
    /// this (`--max-moves`).
    pub max_segments: usize,
    /// Stop with an alarm after executing this many blocks (endless loops).
    pub max_blocks: usize,
    /// The tool table's facts: noses by offset (G41/G42), blades by tool (G75.1).
    pub tools: toolfacts::ToolFacts,
    /// The tool that cuts before the program's first T word (`--tool N`, else the tool
    /// table's first entry); `None` leaves it 0, "no tool yet".
    pub start_tool: Option<u32>,
    /// Where `M98 P`/`G65 P` find programs the file does not hold (`--lib`).
    pub library: Option<crate::LibraryRef>,
    /// Custom macro B with these rules (`--macro`); `None`: off. The program must have
    /// been read with macro B on too.
    pub macros: Option<macro_b::Options>,
    /// Custom macro B: common variables set before the run (`--vars`).
    pub vars: Vec<(u32, f64)>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            block_delete: false,
            max_segments: 10_000_000,
            max_blocks: macro_b::DEFAULT_MAX_BLOCKS as usize,
            tools: toolfacts::ToolFacts::default(),
            start_tool: None,
            library: None,
            macros: None,
            vars: vec![],
        }
    }
}

/// What the interpreter made of a program.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Toolpath {
    /// The moves, in order.
    pub segments: Vec<Segment>,
    /// The feeds the segments' [`Segment::feed`] ids stand for.
    pub feeds: crate::Feeds,
    /// Controller alarms. An alarm stops the run, except tool nose radius interference
    /// (PS041), reported at every block where the offset path would run backwards while
    /// the path goes on as the control would cut it (spec/tnrc.md).
    pub alarms: Vec<Diagnostic>,
    /// Warnings: the run went on.
    pub warnings: Vec<Diagnostic>,
    /// Total dwell time (G04), s.
    pub dwell_s: f64,
    /// Tool numbers used, in order of first use.
    pub tools: Vec<u32>,
    /// Main program number, e.g. `O0002`.
    pub title: String,
    /// Blocks executed.
    pub blocks: usize,
    /// Tailstock changes: from segment `k` on, the centre is advanced (`true`) or retracted,
    /// as M21/M22 (Haas) or M10/M11 (GSK980TD) say. Before the first, it is where the
    /// machine profile puts it (advanced, when it has a `[tailstock]`). A change inside a
    /// G41/G42 section takes effect where the section's moves end.
    pub tailstock: Vec<(usize, bool)>,
    /// Shapes the program defines for itself (G75.1 grooves, G70–G73 finishing shapes).
    pub intended: Vec<crate::Intended>,
    /// Custom macro B: the variables the run read or set, with their final values
    /// (`None`: vacant), in number order.
    pub variables: Vec<(String, Option<f64>)>,
    /// Custom macro B: the source lines executed more than once, with how many times.
    pub line_counts: Vec<(u32, u64)>,
    /// The tool offsets the T words called, `(tool, offset)` in order of first use
    /// (`T0101` → `(1, 1)`; offset 00, a cancel, left out): the setup sheet's offsets.
    pub tool_offsets: Vec<(u32, u32)>,
    /// The included angle the program's first G76 of each tool states for it (P's last two
    /// digits, Haas A), `(tool, degrees)`: a tool with no entry that threads is taken to be
    /// of that angle (docs/field-rules.md §17).
    pub thread_angles: Vec<(u32, f64)>,
    /// The moves that start a G41/G42 compensation (its start-up move), in order: a hand
    /// contour's and a G70's alike.
    pub comp_starts: Vec<usize>,
}

/// Expand a parsed program into segments.
pub fn expand(program: &Program, machine: &Machine, opts: &Options) -> Toolpath {
    let mut it = Interp::new(machine, opts);
    for note in &program.notes {
        it.warn(note.span, "W-ANNOTATION", note.message.clone(), "");
    }
    if let Some(main) = program.main() {
        if let Some(first) = program
            .programs
            .first()
            .filter(|_| program.main_index() > 0)
        {
            let name = |n: Option<u32>| n.map_or_else(String::new, |n| format!("O{n:04}"));
            it.warn(
                main.span,
                "LS-MAIN-PROGRAM",
                format!(
                    "{} comes first in the file but is a subprogram (another program of the file calls it): {}, the first program none calls, runs as the main program",
                    name(first.number),
                    name(main.number)
                ),
                "list the main program first if another reading was meant",
            );
        }
        it.warn_assumed_units(program, main);
        it.out.title = main.number.map(|n| format!("O{n:04}")).unwrap_or_default();
        if let Some(b) = reach::unreachable_tail(main) {
            it.warn(
                b.span,
                "LS-UNREACHABLE",
                "the blocks after M30/M02 are not in an O program and nothing calls them (M97, GOTO): unreachable",
                "start them with an O number to make a subprogram, call them with M97 P<N>, or delete them",
            );
        }
        let mut result = it
            .prepare_macros(program)
            .and_then(|()| it.run(program, program.main_index(), 0, 0));
        if let (Ok(_), Some(p)) = (&result, it.corner.take()) {
            result = Err(it.corner_without_line(&p, "the program ends"));
        }
        it.flush_compensation();
        if result.is_ok() && it.retained.g75_1.is_some() {
            let span = program
                .programs
                .iter()
                .flat_map(|p| p.blocks.last())
                .last()
                .map(|b| b.span)
                .unwrap_or_default();
            result = Err(it.g75_1_unfinished(span));
        }
        match result {
            Ok(Exit::End) => {}
            Ok(Exit::Return(_)) => unreachable!("M99 in the main program ends it"),
            Err(alarm) => it.out.alarms.push(alarm),
        }
        it.finish_macros(program);
        it.name_units_assumed();
        name_mixed_systems(&mut it.out.alarms, program);
    }
    it.out
}

/// An LS-DIALECT alarm suggests the control whose code it is (`--control fanuc-b`); when
/// the program also writes a code that control does not read, no control reads it, and the
/// help says so instead of sending the user back and forth (field run 10, B5: `G91` under
/// fanuc-a, `G50 S` under fanuc-b).
fn name_mixed_systems(alarms: &mut [crate::Diagnostic], program: &Program) {
    for alarm in alarms.iter_mut().filter(|a| a.code == "LS-DIALECT") {
        let Some(other) = crate::Control::ALL
            .into_iter()
            .find(|c| alarm.help.contains(&format!("--control {}?", c.key())))
        else {
            continue;
        };
        let foreign = program
            .programs
            .iter()
            .flat_map(|p| p.blocks.iter())
            .find_map(|b| {
                b.words.iter().filter(|w| w.letter == 'G').find_map(|w| {
                    let t = w.code_tenths()?;
                    crate::dialect::canonical(other, t)
                        .err()
                        .map(|f| (b.span.line, f))
                })
            });
        if let Some((line, f)) = foreign {
            alarm.help = format!(
                "the program mixes G-code systems: under --control {} line {line} stops too ({}); no control reads both: write the program for one",
                other.key(),
                f.message
            );
        }
    }
}

/// The interpreter's state between blocks.
pub(crate) struct Interp<'m> {
    machine: &'m Machine,
    opts: &'m Options,
    pub(crate) out: Toolpath,
    /// Current position of the reference point, G54 frame.
    pos: Pt,
    /// Origin of the current work coordinate system in the G54 frame.
    shift: Pt,
    pub(crate) motion: MotionMode,
    per_rev: bool,
    inch: bool,
    css: bool,
    s_value: f64,
    s_clamp: f64,
    spindle_on: bool,
    spindle_warned: bool,
    /// The units a Haas program that states none was read in (W-HAAS-UNITS), named in its
    /// alarm: an inch program read in mm alarms for a reason its alarm would not say.
    units_assumed: Option<&'static str>,
    /// A feed per minute too slow for any cut (a feed per revolution under G98) was warned.
    slow_feed_warned: bool,
    feed: f64,
    tool: u32,
    retained: Retained,
    /// G41/G42 mode in force (group 07); `None` is G40.
    pub(crate) comp: Option<Side>,
    /// Tool offset number `oo` in force.
    pub(crate) offset: u32,
    /// The compensation section being collected (start-up first), with its side and nose.
    pub(crate) section: Option<(Side, Nose, Vec<Segment>)>,
    /// Offsets already warned about (blade, no entry).
    pub(crate) comp_warned: Vec<u32>,
    /// Nose radius and tip per offset: the tool table's, as G10 changes them.
    pub(crate) noses: std::collections::BTreeMap<u32, Result<Nose, &'static str>>,
    /// System B/C G91: X and Z are incremental.
    incremental: bool,
    /// System B/C: U/W outside a cycle already warned about.
    uw_warned: bool,
    /// G17/G19 in force (a live-tooling plane) and where it was set; G18 clears it.
    plane: Option<(i32, Span)>,
    /// Inside `G10 L50 … G11`: parameter blocks, skipped.
    param_mode: bool,
    /// The chuck is open (Haas M11, FANUC builders' M69, GSK M13); warned once per opening.
    chuck_open: bool,
    /// A tailstock change met inside a G41/G42 section (recorded when it is emitted).
    pub(crate) tailstock_pending: Option<bool>,
    chuck_warned: bool,
    /// M codes the control's table does not know, already warned about.
    m_warned: Vec<u32>,
    /// Interpretations already shown once (by warning code).
    noted: Vec<&'static str>,
    /// Work offsets and shifts (G54–G59, G54.1/G154, G10, G52).
    frames: frame::Frames,
    /// The C axis is engaged (Haas M154 until M155): the spindle is indexed, not turning.
    pub(crate) c_axis: bool,
    /// Haas M23 (on, the power-on state, **Interpretation**) / M24 (off): the thread
    /// pull-out chamfer of G76 (spec/dialects.md §3.5).
    pub(crate) thread_chamfer: bool,
    /// Start shift of the thread moves being pushed, a fraction of the lead (the Q of the
    /// G32/G92/G76 block; 0 otherwise).
    thread_phase: f64,
    /// A G01 line with `,C`/`,R` waiting for the next line (spec/dialects.md §6.5).
    corner: Option<corner::PendingCorner>,
    /// The parts counters `#3901`, `#3902`: 0 at the start, as the program sets them
    /// (spec/dialects.md §5.7; the +1 of M30 comes when the run is over).
    parts: [f64; 2],
    /// Return level of the drilling cycles (the profile's; G98/G99 in systems B/C set it).
    pub(crate) drill_return: crate::DrillReturn,
    /// Custom macro B's variables and program structure, when it is on.
    macros: Option<Box<macros::Macros>>,
    /// The last block was a motion block with an axis word: what triggers a `G66` modal call.
    moved: bool,
    /// The used-word flags of the block being run (one buffer for all blocks).
    used_buffer: Vec<bool>,
    /// `LinuxCNC`: G7 (X is a diameter) in force, else G8 (a radius).
    x_diameter: bool,
    /// `LinuxCNC`: G90.1 (arc centres absolute) in force.
    arc_absolute: bool,
    /// `LinuxCNC`: the tool a T word prepared for the next M6.
    pending_tool: Option<u32>,
    /// `LinuxCNC` G7x: the profile O-sub running, its moves captured.
    g7x_capture: Option<linuxcnc_g7x::Capture>,
    /// `LinuxCNC` G71.1/G72.1 run so far: (G72, profile Q), which a G7x.2 continues.
    g7x_roughed: Vec<(bool, u32)>,
}

/// A controller alarm.
pub(crate) fn alarm(
    span: Span,
    code: &'static str,
    message: impl Into<String>,
    help: impl Into<String>,
) -> Diagnostic {
    Diagnostic::new(span, code, message, help)
}

impl<'m> Interp<'m> {
    fn new(machine: &'m Machine, opts: &'m Options) -> Self {
        Self {
            machine,
            opts,
            out: Toolpath::default(),
            pos: machine.home,
            shift: Pt::default(),
            motion: MotionMode::Rapid,
            per_rev: machine.feed_mode == crate::FeedMode::G99,
            inch: machine.power_on_units == crate::machine::Units::Inch,
            css: false,
            s_value: 0.0,
            s_clamp: 0.0,
            spindle_on: false,
            spindle_warned: false,
            units_assumed: None,
            slow_feed_warned: false,
            feed: machine.power_on_feed,
            tool: opts.start_tool.unwrap_or(0),
            retained: Retained::default(),
            comp: None,
            offset: 0,
            section: None,
            comp_warned: vec![],
            noses: opts
                .tools
                .noses
                .iter()
                .map(|(&k, n)| (k, n.map(tool_facts::nose)))
                .collect(),
            incremental: machine.power_on_incremental
                && machine.control.system() != crate::GCodeSystem::A,
            uw_warned: false,
            plane: None,
            param_mode: false,
            chuck_open: false,
            tailstock_pending: None,
            chuck_warned: false,
            m_warned: vec![],
            noted: vec![],
            frames: frame::Frames::new(machine),
            thread_chamfer: true,
            c_axis: false,
            thread_phase: 0.0,
            corner: None,
            parts: [0.0; 2],
            drill_return: machine.drill_return,
            macros: None,
            moved: false,
            used_buffer: Vec::new(),
            x_diameter: machine.x_mode == crate::XMode::Diameter,
            arc_absolute: false,
            pending_tool: None,
            g7x_capture: None,
            g7x_roughed: Vec::new(),
        }
    }

    pub(crate) fn warn(
        &mut self,
        span: Span,
        code: &'static str,
        message: impl Into<String>,
        help: impl Into<String>,
    ) {
        self.out
            .warnings
            .push(Diagnostic::new(span, code, message, help));
    }

    /// A cycle's alarm in the program's own codes: the cycles name themselves by their
    /// system-A code (`G90`), a system-B program wrote `G77`.
    fn in_written_terms(&self, mut e: Diagnostic, canonical: i32) -> Diagnostic {
        if let Some(w) = crate::dialect::written(self.machine.control, canonical) {
            e.message = e
                .message
                .replacen(&codes::g_name(canonical), &codes::g_name(w), 1);
        }
        e
    }

    /// A warning shown once per run: an Interpretation that affects the run.
    pub(crate) fn note_once(
        &mut self,
        span: Span,
        code: &'static str,
        message: impl Into<String>,
        help: impl Into<String>,
    ) {
        if !self.noted.contains(&code) {
            self.noted.push(code);
            self.warn(span, code, message, help);
        }
    }

    fn unit(&self) -> f64 {
        if self.inch {
            25.4
        } else {
            1.0
        }
    }

    /// Haas: a program that states neither G20 nor G21 runs in the profile's power-on units;
    /// US machines are usually inch, so say which was assumed (dialects.md §3.1).
    fn warn_assumed_units(&mut self, program: &Program, main: &Subprogram) {
        if self.machine.control != crate::Control::Haas {
            return;
        }
        let states = program
            .programs
            .iter()
            .flat_map(|p| p.blocks.iter())
            .any(|b| self.has_g(&b, |t| t == G20 || t == G21));
        if !states {
            let unit = if self.inch { "inch" } else { "mm" };
            self.units_assumed = Some(unit);
            self.warn(
                main.blocks.first().map_or(main.span, |b| b.span),
                "W-HAAS-UNITS",
                format!("no G20/G21: assumed {unit} (the profile's power_on_units)"),
                "state G20 (inch) or G21 (mm) at the top: a Haas runs in its Setting 9 units",
            );
        }
    }

    /// Adds to every alarm's help the units a program that states none was read in.
    fn name_units_assumed(&mut self) {
        let Some(unit) = self.units_assumed else {
            return;
        };
        let (other, code) = if unit == "mm" {
            ("inch", "G20")
        } else {
            ("mm", "G21")
        };
        for alarm in &mut self.out.alarms {
            alarm.help = format!(
                "{}; the program states no units and was read in {unit} (W-HAAS-UNITS): if it is written in {other}, state {code} at the top or set the profile's power_on_units",
                alarm.help
            );
        }
    }

    /// The alarm for a G75.1 geometry block whose process block does not follow.
    fn g75_1_unfinished(&self, span: Span) -> Diagnostic {
        g75_1::pairing::alarm(
            span,
            self.retained.g75_1.as_ref(),
            g75_1::pairing::Break::Interrupted,
        )
    }

    /// Execute one block: its modal words, its one action, then its flow words. A `LinuxCNC`
    /// block runs as `LinuxCNC` means it (`linuxcnc_block`: radius X, absolute arc centres).
    fn block(&mut self, sub: &Subprogram, b: &Block, index: usize) -> Result<Flow, Diagnostic> {
        if self.machine.control == crate::Control::LinuxCnc {
            let meant = self.linuxcnc_block(b);
            let b = meant.as_ref().unwrap_or(b);
            if linuxcnc_g7x::g7x_code(b).is_some() {
                return Ok(Flow::G7x(Box::new(b.clone())));
            }
            if let Some(profile) = self.g7x_hook(b) {
                return self.capture_block(sub, &profile, index);
            }
            return self.run_block(sub, b, index);
        }
        self.run_block(sub, b, index)
    }

    /// [`Interp::block`] as the interpreter reads it.
    fn run_block(&mut self, sub: &Subprogram, b: &Block, index: usize) -> Result<Flow, Diagnostic> {
        self.moved = false;
        if self.param_mode {
            // G10 L50 … G11: parameter data, not a program.
            self.param_mode = !self.has_g(b, |t| t == G11);
            return Ok(Flow::Next);
        }
        let mut used = Words::new(b, std::mem::take(&mut self.used_buffer));
        let inch = self.has_g(b, |t| t == G20) || (self.inch && !self.has_g(b, |t| t == G21));
        used.check_domain(if inch { 25.4 } else { 1.0 })?;
        if self.retained.g75_1.is_some() && !self.has_g(b, |t| t == G75_1) {
            return Err(self.g75_1_unfinished(b.span));
        }
        let g = self.g_codes(b, &mut used)?;
        self.dialect_checks(b, &g, &mut used)?;
        let cancels = matches!(g.comp, Some((G40, _)));
        let deferred_offset =
            self.feed_speed_tool(&mut used, g.one_shot.map(|(t, _)| t), cancels)?;
        let after = self.m_codes_before(b, &mut used)?;
        self.set_compensation_mode(g.comp);
        if self.suspends_compensation(b, &g) {
            // Suspended by G28, G50, G54–G59 and the cycles; resumed at the next move.
            self.flush_compensation();
        }
        let flow = match g.one_shot {
            Some((t, w)) => self.one_shot(t, w, &g, (sub, b, index), &mut used)?,
            None => self.modal_block(&g, (sub, b, index), &mut used)?,
        };
        if let Some(offset) = deferred_offset {
            self.offset = offset;
        }
        let flow = self.m_codes_after(&after, &mut used, sub.call_text(index), flow)?;
        used.check_all_used()?;
        self.used_buffer = used.into_buffer();
        Ok(flow)
    }

    /// Whether the block suspends tool nose radius compensation: G28, G50, G50.3, G52,
    /// G53, G27, a cycle, a work offset, or a block repeating the modal cycle.
    fn suspends_compensation(&self, b: &Block, g: &GWords) -> bool {
        let modal_cycle = g
            .motion
            .map_or(matches!(self.motion, MotionMode::Cycle(_)), |(m, _)| {
                matches!(m, MotionMode::Cycle(_))
            });
        matches!(g.one_shot, Some((G28 | G50 | G50_3 | G52 | G53 | G27, _)))
            || g.one_shot.is_some_and(|(t, _)| cycles::is_cycle(t))
            || self.has_g(b, |t| {
                codes::work_offset(t).is_some() || t == G54_1 || t == G154
            })
            || (modal_cycle && ['X', 'Z', 'U', 'W', 'R'].iter().any(|&l| b.has(l)))
    }

    /// The block's one-shot code `t` (its word `w`): G04, G28, G50, G50.3, G52, G53, G27,
    /// G10, or a cycle.
    fn one_shot<'b>(
        &mut self,
        t: i32,
        w: &'b Word,
        g: &GWords,
        (sub, b, index): (&'b Subprogram, &'b Block, usize),
        used: &mut Words<'b>,
    ) -> Result<Flow, Diagnostic> {
        if let (G28 | G53, Some((m, _))) = (t, g.motion) {
            // G00 (G53: or G01) beside G28/G53 sets the mode for the blocks after it too
            self.motion = m;
            self.retained.drill = None;
        }
        match t {
            G04 => self.dwell(used, w)?,
            G28 => self.g28(b, used, w)?,
            G50 => self.g50(used)?,
            G50_3 => self.preset(w, used)?,
            G52 => self.g52(b, used)?,
            G53 => self.g53(b, used, w)?,
            G27 => self.g27(b, used, w)?,
            G10 => self.g10(used, w)?,
            crate::linuxcnc::RIGID_TAP => self.rigid_tap(b, w.span, used)?,
            t => {
                return self
                    .cycle(t, Some(w), sub, b, index, used)
                    .map_err(|e| self.in_written_terms(e, t))
            }
        }
        Ok(Flow::Next)
    }

    /// A block without a one-shot code: its motion, or the drilling or modal cycle in
    /// force repeated with its words.
    fn modal_block<'b>(
        &mut self,
        g: &GWords<'b>,
        (sub, b, index): (&'b Subprogram, &'b Block, usize),
        used: &mut Words<'b>,
    ) -> Result<Flow, Diagnostic> {
        if let Some((m, _)) = g.motion {
            self.motion = m;
            // a group-01 code ends a drilling cycle
            self.retained.drill = None;
        }
        let drill = self.retained.drill.map(|d| d.code);
        if let Some(t) = drill.filter(|_| ['X', 'Z', 'U', 'W', 'R', 'Q'].iter().any(|&l| b.has(l)))
        {
            // the drilling cycle in force repeats with the block's words
            return self.cycle(t, None, sub, b, index, used);
        }
        if let MotionMode::Cycle(t) = self.motion {
            if t == crate::linuxcnc::RIGID_TAP && ['X', 'Z'].iter().any(|&l| b.has(l)) {
                self.rigid_tap(b, b.span, used)?;
                return Ok(Flow::Next);
            }
            if ['X', 'Z', 'U', 'W', 'R'].iter().any(|&l| b.has(l)) {
                let w = g.motion.map(|(_, w)| w);
                return self
                    .cycle(t, w, sub, b, index, used)
                    .map_err(|e| self.in_written_terms(e, t));
            }
            return Ok(Flow::Next);
        }
        self.start_compensation(b)?;
        self.motion_block(b, used)?;
        self.moved = ['X', 'Z', 'U', 'W'].iter().any(|&l| b.has(l));
        if self.section.is_some() && (self.comp.is_none() || self.offset == 0) {
            // This block was the cancel block.
            self.flush_compensation();
        }
        Ok(Flow::Next)
    }
}
