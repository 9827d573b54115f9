//! The modal interpreter: runs the blocks like a controller and emits segments.
//!
//! Order within one block (FANUC/GSK practice): modal G codes, F, S, T and M03/M04/M08
//! first; then the block's one motion (or G04/G28/G50); then M05/M09, M98/M99 and the
//! program end. A controller alarm stops the run; the segments made so far are kept.

use crate::arc::{self, ArcError};
use crate::cycles::{self, Cycle, Retained};
use crate::tnrc::{self, Nose, Side};
use crate::words::Words;
use crate::{Arc, Diagnostic, Feed, Machine, Motion, Pt, RapidPath, Segment, Span, Spindle};
use gcode::{Block, Program, Subprogram, Word};
use std::collections::BTreeMap;

/// Interpreter settings from the command line.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Skip blocks that start with `/`.
    pub block_delete: bool,
    /// Stop with an alarm when the program expands to more segments than this.
    pub max_segments: usize,
    /// Stop with an alarm after executing this many blocks (endless loops).
    pub max_blocks: usize,
    /// Nose radius and tip per tool offset number (`oo` of `Tttoo`) for G41/G42;
    /// `None` marks a grooving blade, for which compensation is ignored with a warning.
    pub noses: BTreeMap<u32, Option<Nose>>,
    /// The nose of an offset with no entry (the documented default insert: r 0.4, tip 3).
    pub default_nose: Nose,
    /// The tool table's radial grooving blades by tool number: width, and whether the
    /// blade extends toward +Z from its reference corner (G75.1 without I).
    pub blades: BTreeMap<u32, (f64, bool)>,
    /// The tool that cuts before the program's first T word (`--tool N`, else the tool
    /// table's first entry); `None` leaves it 0, "no tool yet".
    pub start_tool: Option<u32>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            block_delete: false,
            max_segments: 5_000_000,
            max_blocks: 20_000_000,
            noses: BTreeMap::new(),
            default_nose: Nose {
                radius: 0.4,
                tip: 3,
            },
            blades: BTreeMap::new(),
            start_tool: None,
        }
    }
}

/// What the interpreter made of a program.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Toolpath {
    /// The moves, in order.
    pub segments: Vec<Segment>,
    /// Controller alarms (at most one: an alarm stops the run).
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
    /// Shapes the program defines for itself (G75.1 grooves, G70–G73 finishing shapes).
    pub intended: Vec<crate::Intended>,
}

/// FANUC's subprogram nesting limit.
const MAX_NESTING: u32 = 4;

/// Expand a parsed program into segments.
pub fn expand(program: &Program, machine: &Machine, opts: &Options) -> Toolpath {
    let mut it = Interp::new(machine, opts);
    for note in &program.notes {
        it.warn(note.span, "W-ANNOTATION", note.message.clone(), "");
    }
    if let Some(main) = program.main() {
        it.out.title = main.number.map(|n| format!("O{n:04}")).unwrap_or_default();
        let mut result = it.run(program, 0, 0, 0);
        it.flush_compensation();
        if result.is_ok() && it.retained.g75_1.is_some() {
            let span = program
                .programs
                .iter()
                .flat_map(|p| p.blocks.last())
                .last()
                .map(|b| b.span)
                .unwrap_or_default();
            result = Err(g75_1_unfinished(span));
        }
        match result {
            Ok(Exit::End) => {}
            Ok(Exit::Return(_)) => unreachable!("M99 in the main program is an alarm"),
            Err(alarm) => it.out.alarms.push(alarm),
        }
    }
    it.out
}

enum Exit {
    End,
    Return(Option<u32>),
}

enum Flow {
    Next,
    End,
    Call {
        number: u32,
        times: u32,
        span: Span,
    },
    Return {
        seq: Option<u32>,
        span: Span,
    },
    /// Continue at this block index (G70–G73 skip their finishing shape).
    Jump(usize),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum MotionMode {
    Rapid,
    Line,
    Cw,
    Ccw,
    Thread,
    /// A modal canned cycle (G90/G92/G94), by code in tenths.
    Cycle(i32),
}

struct Interp<'m> {
    machine: &'m Machine,
    opts: &'m Options,
    out: Toolpath,
    /// Current position of the reference point, G54 frame.
    pos: Pt,
    /// Origin of the current work coordinate system in the G54 frame.
    shift: Pt,
    motion: MotionMode,
    per_rev: bool,
    inch: bool,
    css: bool,
    s_value: f64,
    s_clamp: f64,
    spindle_on: bool,
    spindle_warned: bool,
    feed: f64,
    tool: u32,
    retained: Retained,
    /// G41/G42 mode in force (group 07); `None` is G40.
    comp: Option<Side>,
    /// Tool offset number `oo` in force.
    offset: u32,
    /// The compensation section being collected (start-up first), with its side and nose.
    section: Option<(Side, Nose, Vec<Segment>)>,
    /// Offsets already warned about (blade, no entry).
    comp_warned: Vec<u32>,
}

/// A G75.1 geometry block not followed by its process block.
fn g75_1_unfinished(span: Span) -> Diagnostic {
    alarm(
        span,
        "LS-G75.1-BLOCKS",
        "the G75.1 geometry block is not followed by its process block",
        "write the process block (G75.1 R… ) right after the geometry block (G75.1 X Z P Q H D …)",
    )
}

fn alarm(
    span: Span,
    code: &'static str,
    message: impl Into<String>,
    help: impl Into<String>,
) -> Diagnostic {
    Diagnostic::new(span, code, message, help)
}

fn g_name(w: &Word) -> String {
    let t = w.code_tenths().unwrap_or(0);
    if t % 10 == 0 {
        format!("G{:02}", t / 10)
    } else {
        format!("G{}.{}", t / 10, t % 10)
    }
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
            inch: false,
            css: false,
            s_value: 0.0,
            s_clamp: 0.0,
            spindle_on: false,
            spindle_warned: false,
            feed: machine.power_on_feed,
            tool: opts.start_tool.unwrap_or(0),
            retained: Retained::default(),
            comp: None,
            offset: 0,
            section: None,
            comp_warned: vec![],
        }
    }

    fn warn(
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

    /// Run one O program from block `start`; `depth` 0 is the main program.
    fn run(
        &mut self,
        program: &Program,
        index: usize,
        start: usize,
        depth: u32,
    ) -> Result<Exit, Diagnostic> {
        let blocks = &program.programs[index].blocks;
        let mut i = start;
        'blocks: while i < blocks.len() {
            let b = &blocks[i];
            if b.block_delete && self.opts.block_delete {
                i += 1;
                continue;
            }
            self.out.blocks += 1;
            if self.out.blocks > self.opts.max_blocks {
                return Err(alarm(
                    b.span,
                    "LS-LOOP",
                    format!(
                        "more than {} blocks executed: the program does not end",
                        self.opts.max_blocks
                    ),
                    "check M98 repeat counts and M99 jumps for an endless loop",
                ));
            }
            match self.block(&program.programs[index], i)? {
                Flow::Next => i += 1,
                Flow::Jump(j) => i = j,
                Flow::End => return Ok(Exit::End),
                Flow::Return { seq, span } => {
                    if depth == 0 {
                        return Err(alarm(
                            span,
                            "LS-M99-MAIN",
                            "M99 in the main program would repeat it endlessly",
                            "end the main program with M30 (or M02); M99 belongs at the end of a subprogram",
                        ));
                    }
                    return Ok(Exit::Return(seq));
                }
                Flow::Call {
                    number,
                    times,
                    span,
                } => {
                    let Some(sub) = program
                        .programs
                        .iter()
                        .position(|p| p.number == Some(number))
                    else {
                        return Err(alarm(
                            span,
                            "PS078",
                            format!("subprogram O{number:04} not found in this file"),
                            "add the subprogram after M30 in the same file, starting with its O number",
                        ));
                    };
                    if depth + 1 > MAX_NESTING {
                        return Err(alarm(
                            span,
                            "PS077",
                            format!("subprogram calls nested deeper than {MAX_NESTING} levels (a subprogram calling itself?)"),
                            "remove the recursive M98 call or flatten the nesting",
                        ));
                    }
                    for _ in 0..times {
                        match self.run(program, sub, 0, depth + 1)? {
                            Exit::End => return Ok(Exit::End),
                            Exit::Return(None) => {}
                            Exit::Return(Some(seq)) => {
                                let Some(target) = blocks.iter().position(|x| x.seq == Some(seq))
                                else {
                                    return Err(alarm(
                                        span,
                                        "PS078",
                                        format!("M99 P{seq} returns to N{seq}, which the calling program does not have"),
                                        "give the block to return to that sequence number",
                                    ));
                                };
                                i = target;
                                continue 'blocks;
                            }
                        }
                    }
                    i += 1;
                }
            }
        }
        let span = blocks.last().map(|b| b.span).unwrap_or_default();
        if depth == 0 {
            self.warn(
                span,
                "LS-NO-END",
                "the program ends without M30 or M02",
                "end the main program with M30",
            );
            Ok(Exit::End)
        } else {
            self.warn(
                span,
                "LS-NO-M99",
                "the subprogram ends without M99; returning",
                "end the subprogram with M99",
            );
            Ok(Exit::Return(None))
        }
    }

    fn unit(&self) -> f64 {
        if self.inch {
            25.4
        } else {
            1.0
        }
    }

    fn block(&mut self, sub: &Subprogram, index: usize) -> Result<Flow, Diagnostic> {
        let b = &sub.blocks[index];
        let mut used = Words::new(b);
        let inch_here = b
            .words
            .iter()
            .rev()
            .find_map(|w| match (w.letter, w.code_tenths()) {
                ('G', Some(200)) => Some(true),
                ('G', Some(210)) => Some(false),
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
            .any(|w| w.letter == 'G' && w.code_tenths() == Some(751));
        if self.retained.g75_1.is_some() && !is_g75_1 {
            return Err(g75_1_unfinished(b.span));
        }
        // -- G codes: classify, check groups.
        let mut motion: Option<(MotionMode, &Word)> = None;
        let mut one_shot: Option<(i32, &Word)> = None;
        let mut comp_word: Option<(i32, &Word)> = None;
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
                if let Some((_, first)) = motion {
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
                motion = Some((m, w));
                Ok(())
            };
            match t {
                0 => set_motion(MotionMode::Rapid)?,
                10 => set_motion(MotionMode::Line)?,
                20 => set_motion(MotionMode::Cw)?,
                30 => set_motion(MotionMode::Ccw)?,
                320 => set_motion(MotionMode::Thread)?,
                t if cycles::is_modal(t) => set_motion(MotionMode::Cycle(t))?,
                t if t == 40 || t == 280 || t == 500 || cycles::is_cycle(t) => {
                    if let Some((_, first)) = one_shot {
                        return Err(alarm(
                            w.span,
                            "PS010",
                            format!("{} and {} in one block", g_name(first), g_name(w)),
                            "put each of them in a block of its own",
                        ));
                    }
                    one_shot = Some((t, w));
                }
                200 => self.inch = true,
                210 => self.inch = false,
                400 | 410 | 420 => {
                    if let Some((_, first)) = comp_word {
                        return Err(alarm(
                            w.span,
                            "PS010",
                            format!("{} and {} in one block", g_name(first), g_name(w)),
                            "keep one of G40/G41/G42 per block",
                        ));
                    }
                    comp_word = Some((t, w));
                }
                540 | 550 | 560 | 570 | 580 | 590 => {
                    self.shift = self.machine.work_offsets[((t - 540) / 10) as usize];
                }
                960 => self.css = true,
                970 => self.css = false,
                980 => self.per_rev = false,
                990 => self.per_rev = true,
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
        if let (Some((_, m)), Some((_, o))) = (motion, one_shot) {
            return Err(alarm(
                o.span,
                "PS010",
                format!("{} cannot share a block with {}", g_name(o), g_name(m)),
                "split the block in two",
            ));
        }
        // -- F, S, T.
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
            if one_shot.map(|(t, _)| t) == Some(500) {
                self.s_clamp = s.value;
            } else {
                self.s_value = if self.css && self.inch {
                    s.value * 0.3048
                } else {
                    s.value
                };
            }
        }
        let mut deferred_offset = None;
        if let Some(t) = used.take('T') {
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
            if matches!(comp_word, Some((400, _))) {
                deferred_offset = Some(offset);
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
            if tool != 0 {
                self.tool = tool;
                if !self.out.tools.contains(&tool) {
                    self.out.tools.push(tool);
                }
            }
        }
        // -- M codes, part 1 (before motion).
        let mut after: Vec<(u32, &Word)> = vec![];
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
        // -- tool nose radius compensation mode (spec/tnrc.md).
        if let Some((t, _)) = comp_word {
            let side = match t {
                410 => Some(Side::Left),
                420 => Some(Side::Right),
                _ => None,
            };
            if side.is_some() && self.comp.is_some() && side != self.comp {
                // G41 in G42 mode (or the reverse) cancels and re-establishes.
                self.flush_compensation();
            }
            self.comp = side;
        }
        let modal_cycle = motion.map_or(matches!(self.motion, MotionMode::Cycle(_)), |(m, _)| {
            matches!(m, MotionMode::Cycle(_))
        });
        let suspends = matches!(one_shot, Some((280 | 500, _)))
            || one_shot.is_some_and(|(t, _)| cycles::is_cycle(t))
            || b.words.iter().any(|w| {
                w.letter == 'G'
                    && matches!(w.code_tenths(), Some(540 | 550 | 560 | 570 | 580 | 590))
            })
            || (modal_cycle && ['X', 'Z', 'U', 'W', 'R'].iter().any(|&l| b.has(l)));
        if suspends {
            // Suspended by G28, G50, G54–G59 and the cycles; resumed at the next move.
            self.flush_compensation();
        }
        // -- the block's action.
        let mut flow = Flow::Next;
        match one_shot {
            Some((40, w)) => self.dwell(&mut used, w)?,
            Some((280, w)) => self.g28(b, &mut used, w)?,
            Some((500, _)) => self.g50(&mut used)?,
            Some((t, w)) => flow = self.cycle(t, Some(w), sub, index, &mut used)?,
            None => {
                if let Some((m, _)) = motion {
                    self.motion = m;
                }
                if let MotionMode::Cycle(t) = self.motion {
                    if ['X', 'Z', 'U', 'W', 'R'].iter().any(|&l| b.has(l)) {
                        let g = motion.map(|(_, w)| w);
                        flow = self.cycle(t, g, sub, index, &mut used)?;
                    }
                } else {
                    self.start_compensation(b)?;
                    self.motion_block(b, &mut used)?;
                    if self.section.is_some() && (self.comp.is_none() || self.offset == 0) {
                        // This block was the cancel block.
                        self.flush_compensation();
                    }
                }
            }
        }
        if let Some(offset) = deferred_offset {
            self.offset = offset;
        }
        // -- M codes, part 2 (after motion).
        for (m, w) in after {
            match m {
                5 => self.spindle_on = false,
                9 => {}
                2 | 30 => flow = Flow::End,
                98 => {
                    let p = used.take('P').ok_or_else(|| {
                        alarm(
                            w.span,
                            "PS078",
                            "M98 without P",
                            "write M98 P<program number>, e.g. M98 P1234",
                        )
                    })?;
                    if p.has_point || p.value < 1.0 || p.value > 99_999_999.0 {
                        return Err(alarm(p.span, "PS078", "M98 P needs a program number", "P is [repeat count (4 digits)] + program number (4 digits), e.g. P30010"));
                    }
                    let v = p.value as u32;
                    let (mut times, number) = if v > 9999 {
                        (v / 10000, v % 10000)
                    } else {
                        (1, v)
                    };
                    if let Some(l) = used.take('L') {
                        if l.has_point || l.value < 1.0 || l.value > 9999.0 {
                            return Err(alarm(
                                l.span,
                                "LS-VALUE",
                                "L must be a repeat count 1 … 9999",
                                "write e.g. L3",
                            ));
                        }
                        times = l.value as u32;
                    }
                    flow = Flow::Call {
                        number,
                        times: times.max(1),
                        span: w.span,
                    };
                }
                99 => {
                    let seq = match used.take('P') {
                        Some(p) if p.has_point || p.value < 0.0 => {
                            return Err(alarm(
                                p.span,
                                "LS-VALUE",
                                "M99 P needs a sequence number",
                                "write e.g. M99 P20 to return to N20",
                            ));
                        }
                        Some(p) => Some(p.value as u32),
                        None => None,
                    };
                    flow = Flow::Return { seq, span: w.span };
                }
                _ => {}
            }
        }
        used.check_all_used()?;
        Ok(flow)
    }

    /// The target of X/U Z/W in the G54 frame; `None` when no axis word is given.
    fn target(&self, used: &mut Words) -> Result<Option<Pt>, Diagnostic> {
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

    fn spindle(&self) -> Spindle {
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

    fn push(
        &mut self,
        b: &Block,
        motion: Motion,
        to: Pt,
        arc: Option<Arc>,
        lead: f64,
    ) -> Result<(), Diagnostic> {
        self.push_at(b.span, motion, to, arc, lead, crate::ToolHint::Table)
    }

    fn push_at(
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

    /// Begin a compensation section if G41/G42 is in force, an offset is active, no section
    /// is open and this block moves: this block is the start-up block.
    fn start_compensation(&mut self, b: &Block) -> Result<(), Diagnostic> {
        let Some(side) = self.comp else { return Ok(()) };
        if self.section.is_some()
            || self.offset == 0
            || !['X', 'Z', 'U', 'W'].iter().any(|&l| b.has(l))
        {
            return Ok(());
        }
        if matches!(self.motion, MotionMode::Cw | MotionMode::Ccw) {
            return Err(alarm(
                b.span,
                "PS034",
                "tool nose radius compensation cannot start on an arc",
                "start G41/G42 in a G00 or G01 block with a move",
            ));
        }
        if let Some(nose) = self.nose_for_offset(b.span) {
            self.section = Some((side, nose, vec![]));
        }
        Ok(())
    }

    /// The nose of the offset in force: from the tool table, or the default with a warning;
    /// `None` for offset 00 or a grooving blade (compensation ignored, with a warning).
    fn nose_for_offset(&mut self, span: Span) -> Option<Nose> {
        let offset = self.offset;
        if offset == 0 {
            return None;
        }
        Some(match self.opts.noses.get(&offset) {
            Some(Some(n)) => *n,
            Some(None) => {
                if !self.comp_warned.contains(&offset) {
                    self.comp_warned.push(offset);
                    self.warn(span, "LS-TNRC-BLADE", format!("G41/G42 ignored: offset {offset:02} is a grooving blade"), "compensation applies to pointed inserts; program the blade's corner directly");
                }
                return None;
            }
            None => {
                let n = self.opts.default_nose;
                if !self.comp_warned.contains(&offset) {
                    self.comp_warned.push(offset);
                    self.warn(
                        span,
                        "LS-TNRC-DEFAULT",
                        format!("offset {offset:02} has no tool table entry: compensating with the default nose r{} tip {}", n.radius, n.tip),
                        "give the tool in the tool table (--tools) with its nose_radius and tip",
                    );
                }
                n
            }
        })
    }

    /// Compensate and emit the collected section; its last move is the cancel move.
    fn flush_compensation(&mut self) {
        let Some((side, nose, section)) = self.section.take() else {
            return;
        };
        if section.len() >= 3 {
            // The programmed contour between start-up and cancel is an intended shape,
            // unless a G70 already handed it over as its finishing shape.
            let body = &section[1..section.len() - 1];
            let mut points = vec![body[0].from];
            for seg in body {
                points.extend(seg.polyline(0.001).into_iter().skip(1));
            }
            let known = self.out.intended.iter().any(|i| {
                i.kind == crate::IntendedKind::FinishingContour
                    && i.points.get(1..) == Some(&points[..])
            });
            if !known {
                self.out.intended.push(crate::Intended {
                    kind: crate::IntendedKind::Compensated {
                        part_on_left: side == Side::Right,
                    },
                    points,
                    span: section[0].span,
                });
            }
        }
        let c = tnrc::compensate(&section, side, nose);
        self.out.segments.extend(c.segments);
        self.out.alarms.extend(c.alarms);
    }

    /// Put a G70 shape's S, T and G96–G99 in force (the T word changes the tool that cuts;
    /// it does not suspend the compensation of the G70 pass).
    fn apply_shape_modes(&mut self, m: cycles::contour::ShapeModes) {
        if let Some(css) = m.css {
            self.css = css;
        }
        if let Some(per_rev) = m.per_rev {
            self.per_rev = per_rev;
        }
        if let Some(s) = m.s {
            self.s_value = if self.css && self.inch { s * 0.3048 } else { s };
        }
        if let Some(t) = m.tool {
            if t / 100 != 0 {
                self.tool = t / 100;
                if !self.out.tools.contains(&self.tool) {
                    self.out.tools.push(self.tool);
                }
            }
        }
    }

    /// Run a canned cycle and emit its moves with this block's span.
    fn cycle<'b>(
        &mut self,
        code: i32,
        g: Option<&'b Word>,
        sub: &'b Subprogram,
        index: usize,
        used: &mut Words<'b>,
    ) -> Result<Flow, Diagnostic> {
        let b = &sub.blocks[index];
        let out = {
            let mut c = Cycle {
                code,
                g,
                words: used,
                start: self.pos,
                shift: self.shift,
                unit: self.unit(),
                machine: self.machine,
                retained: &mut self.retained,
                program: sub,
                index,
                tool_blade: self.opts.blades.get(&self.tool).copied(),
            };
            cycles::run(&mut c)?
        };
        self.out.warnings.extend(out.warnings);
        for (kind, points) in out.intended {
            // G73 then G70 on one shape hand it over twice: keep it once.
            if !self
                .out
                .intended
                .iter()
                .any(|i| i.kind == kind && i.points == points)
            {
                self.out.intended.push(crate::Intended {
                    kind,
                    points,
                    span: b.span,
                });
            }
        }
        // G70 runs its pass as one compensation section (start-up A → B, cancel back to A).
        let side = out.comp.and_then(|shape_side| shape_side.or(self.comp));
        if let Some(side) = side {
            if let Some(nose) = self.nose_for_offset(b.span) {
                self.section = Some((side, nose, vec![]));
            }
        }
        let feed = self.feed;
        for m in out.moves {
            if let Some(f) = m.feed {
                self.feed = f;
            }
            if let Some(modes) = m.modes {
                self.apply_shape_modes(modes);
            }
            let span = m.span.unwrap_or(b.span);
            if m.to.dist(self.pos) >= 1e-12 {
                // a threading move's lead is the F in force (G92: F is the lead)
                let lead = if m.motion == Motion::Thread {
                    self.feed * self.unit()
                } else {
                    0.0
                };
                self.push_at(span, m.motion, m.to, m.arc, lead, m.hint)?;
            }
        }
        self.feed = feed;
        self.flush_compensation();
        Ok(out.resume_at.map_or(Flow::Next, Flow::Jump))
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

fn arc_alarm(span: Span, e: ArcError) -> Diagnostic {
    match e {
        ArcError::RadiusTooSmall { r, half_chord } => alarm(
            span,
            "PS020",
            format!("arc radius R{r} is too small to reach the end point (at least {half_chord:.3} needed)"),
            "check the end point and the radius: R must be at least half the distance between start and end",
        ),
        ArcError::FullCircleWithR => alarm(span, "PS020", "arc with R whose end point equals its start", "a full circle needs I/K, not R"),
        ArcError::NonPositiveRadius => alarm(span, "PS020", "arc radius must be positive", "arcs over 180° are not possible with R on this lathe; use I/K or split the arc"),
        ArcError::EndNotOnCircle { r_start, r_end } => alarm(
            span,
            "PS020",
            format!("arc end point is not on the circle: radius {r_start:.4} at the start, {r_end:.4} at the end"),
            "correct I/K (I is a radius value) or the end point",
        ),
    }
}
