//! The modal interpreter: runs the blocks like a controller and emits segments.
//!
//! Order within one block (FANUC/GSK practice): modal G codes, F, S, T and M03/M04/M08
//! first; then the block's one motion (or G04/G28/G50); then M05/M09, M98/M99 and the
//! program end. A controller alarm stops the run; the segments made so far are kept.
//!
//! This file is the dispatcher: [`Interp::block`] runs the phases of one block in that
//! order. The phases live apart: `modal` (G, F, S, T, M words and the modes they set),
//! `motion` (end points, feeds, the moves of G00–G03/G32, G04, G28, G50), `cycle` (canned
//! cycles), `flow` (the block loop, subprogram calls and returns); tool nose compensation
//! state and buffering are in `crate::tnrc`.

mod cycle;
mod flow;
mod modal;
mod motion;

use crate::cycles::Retained;
use crate::tnrc::{Compensation, Nose, NoseTable};
use crate::words::Words;
use crate::{Diagnostic, Machine, Pt, Segment, Span};
use gcode::{Program, Subprogram};
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
        it.comp.flush(&mut it.out);
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
    /// G40/G41/G42, the offset in force and the section being compensated.
    comp: Compensation,
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
            comp: Compensation::default(),
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

    /// Millimetres per length unit: 25.4 under G20.
    fn unit(&self) -> f64 {
        if self.inch {
            25.4
        } else {
            1.0
        }
    }

    /// Where the tool table's noses come from (for G41/G42).
    fn noses(&self) -> NoseTable<'m> {
        NoseTable {
            noses: &self.opts.noses,
            default: self.opts.default_nose,
        }
    }

    /// The grooving blade of a tool number in the tool table: width and whether it extends
    /// toward +Z from its reference corner (G75.1 without I).
    fn blade_for(&self, tool: u32) -> Option<(f64, bool)> {
        self.opts.blades.get(&tool).copied()
    }

    /// Run one block: its words in the controller's order (see the module doc).
    fn block(&mut self, sub: &Subprogram, index: usize) -> Result<Flow, Diagnostic> {
        let b = &sub.blocks[index];
        let mut used = Words::new(b);
        self.check_block(b, &used)?;
        let g = self.g_words(b, &mut used)?;
        self.feed_and_speed(&mut used, &g)?;
        let deferred_offset = self.t_word(&mut used, &g)?;
        let after = self.m_words_before(b, &mut used)?;
        self.compensation_mode(b, &g);
        let mut flow = self.action(sub, index, &mut used, &g)?;
        if let Some(offset) = deferred_offset {
            self.comp.offset = offset;
        }
        if let Some(f) = self.m_words_after(&after, &mut used)? {
            flow = f;
        }
        used.check_all_used()?;
        Ok(flow)
    }
}
