//! Canned cycles. Each cycle is a function from its block's words and the retained cycle
//! state to plain moves; the interpreter stamps them with the block's span and the feed in
//! force, so a cycle file reads like the manual's numbered motion steps.

use crate::codes::*;
use crate::words::Words;
use crate::{Arc, Diagnostic, IntendedKind, Machine, Motion, Pt, Span, ToolHint};
use gcode::{Subprogram, Word};

pub(crate) mod contour;
pub(crate) mod drill;
mod g70;
pub(crate) mod g71_g72;
mod g73;
mod g74_g75;
pub(crate) mod g75_1;
mod g76;
pub(crate) mod g76_linuxcnc;
mod g90;
mod g92;
mod g94;
pub(crate) mod linuxcnc_g7x;
mod passes;
mod shape_return;

/// One move of a cycle, from the previous move's end (or the cycle's start) to `to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Move {
    /// Rapid or feed (or thread).
    pub(crate) motion: Motion,
    /// End point, G54 frame (z, r).
    pub(crate) to: Pt,
    /// Arc data for G02/G03 moves (finishing shapes).
    pub(crate) arc: Option<Arc>,
    /// Feed override (G70 runs the shape with its own F); `None`: the F in force.
    pub(crate) feed: Option<f64>,
    /// Span override (a shape block's own line); `None`: the cycle block.
    pub(crate) span: Option<Span>,
    /// What cuts this move beyond the tool number (grooving defaults, G75.1 I).
    pub(crate) hint: ToolHint,
    /// S, T and G96–G99 to put in force before this move (G70 runs its shape's own).
    pub(crate) modes: Option<contour::ShapeModes>,
    /// Start shift of this thread move as a fraction of the lead (a GSK G92 with L starts
    /// cuts each start in turn); `None`: the cycle's [`Output::thread_phase`].
    pub(crate) phase: Option<f64>,
}

impl Move {
    /// A rapid to `to`.
    pub(crate) fn rapid(to: Pt) -> Self {
        Self::straight(Motion::Rapid, to)
    }
    /// A straight feed to `to`.
    pub(crate) fn feed(to: Pt) -> Self {
        Self::straight(Motion::Feed, to)
    }
    /// A straight move to `to`, nothing overridden.
    fn straight(motion: Motion, to: Pt) -> Self {
        Self {
            motion,
            to,
            arc: None,
            feed: None,
            span: None,
            hint: ToolHint::Table,
            modes: None,
            phase: None,
        }
    }
}

/// Words of the cycles that stay in force from block to block (spec/language.md,
/// "Modal state that must be tracked").
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Retained {
    /// G90/G92/G94: end point (G54 frame), R (taper) of the last cycle block.
    pub(crate) turn: Option<TurnWords>,
    /// G74/G75 R(e): peck retract, mm.
    pub(crate) peck_retract: Option<f64>,
    /// G75.1 geometry block, waiting for its process block.
    pub(crate) g75_1: Option<g75_1::Geometry>,
    /// G71 U(Δd) R(e).
    pub(crate) g71: Option<(f64, f64)>,
    /// G72 W(Δd) R(e).
    pub(crate) g72: Option<(f64, f64)>,
    /// G73 U(Δi) W(Δk) R(d), GSK data parameters NO.053–055.
    pub(crate) g73: Option<(f64, f64, u32)>,
    /// G76 first block: m r a, Δdmin, d.
    pub(crate) g76: Option<g76::FirstBlock>,
    /// The last G92 block had a start angle Q ≠ 0 (a modal repeat without Q is warned).
    pub(crate) g92_shifted: bool,
    /// GSK G92 J K L of the last G92 block (spec/dialects.md §4.6), which its modal repeats
    /// keep.
    pub(crate) g92_gsk: g92::GskWords,
    /// The drilling cycle in force (modal until G80 or a group-01 code) and its words.
    pub(crate) drill: Option<drill::DrillWords>,
}

/// The most moves one G74/G75/G75.1 block may expand to; more is an alarm (a P1 Q1 typo
/// over a long groove would otherwise make billions of moves).
pub(crate) const MAX_MOVES: usize = 1_000_000;

/// The retained words of G90/G92/G94.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct TurnWords {
    /// Which cycle set them (tenths: 900, 920, 940).
    pub(crate) code: i32,
    /// Cut end point, G54 frame.
    pub(crate) end: Pt,
    /// Taper R, mm (radius for G90/G92, Z for G94).
    pub(crate) r: f64,
}

/// Everything a cycle may read.
pub(crate) struct Cycle<'a, 'b> {
    /// The cycle code in tenths (900 = G90, 751 = G75.1).
    pub(crate) code: i32,
    /// The G word (for alarm positions); `None` when a modal cycle continues.
    pub(crate) g: Option<&'b Word>,
    /// The block's words; a cycle takes the ones it reads.
    pub(crate) words: &'a mut Words<'b>,
    /// Position when the block is read, G54 frame: the cycle's start point A.
    pub(crate) start: Pt,
    /// Origin of the work frame (absolute X/Z words are relative to it).
    pub(crate) shift: Pt,
    /// 1.0, or 25.4 under G20.
    pub(crate) unit: f64,
    /// The machine profile (P/Q units).
    pub(crate) machine: &'a Machine,
    /// Retained cycle words.
    pub(crate) retained: &'a mut Retained,
    /// The O program the block is in (finishing shapes are found here by N).
    pub(crate) program: &'b Subprogram,
    /// Index of the cycle block in `program.blocks`.
    pub(crate) index: usize,
    /// The active tool when the tool table says it is a radial grooving blade: its width
    /// and whether it extends toward +Z from its reference corner (G75.1 without I).
    pub(crate) tool_blade: Option<(f64, bool)>,
    /// The thread pull-out chamfer is on (Haas M23, the power-on state; M24 turns it off).
    pub(crate) thread_chamfer: bool,
    /// The F in force (this block's included) in mm: G92's lead.
    pub(crate) feed_mm: f64,
    /// Where a drilling cycle returns (G98/G99 in systems B/C; the profile elsewhere).
    pub(crate) drill_return: crate::DrillReturn,
    /// The spindle turns (M03/M04 in force) and its C axis is not engaged: a drill off
    /// the axis cuts a round hole about it (an offset indexable drill), not a hole in
    /// one place.
    pub(crate) turning_free: bool,
    /// The modes a `LinuxCNC` G76 reads (G7, compensation, spindle).
    pub(crate) linuxcnc: g76_linuxcnc::Modes,
}

/// What a cycle made.
#[derive(Debug, Default)]
pub(crate) struct Output {
    /// The moves, in order.
    pub(crate) moves: Vec<Move>,
    /// Continue at this block index instead of the next (G70–G73 skip their shape).
    pub(crate) resume_at: Option<usize>,
    /// Warnings; the run goes on.
    pub(crate) warnings: Vec<Diagnostic>,
    /// Shapes the cycle defines (G75.1 groove, G70–G73 finishing shape), for the analysis.
    pub(crate) intended: Vec<(IntendedKind, Vec<Pt>)>,
    /// G70: run the moves as one compensation section, on the shape's side (`Some(None)`:
    /// the side in force at G70, if any); `None`: never compensated (the other cycles).
    pub(crate) comp: Option<Option<crate::tnrc::Side>>,
    /// The lead of the cycle's thread moves, mm (G76 reads F or E itself); `None`: the F in
    /// force.
    pub(crate) lead: Option<f64>,
    /// Start shift of the cycle's thread moves as a fraction of the lead (multi-start Q:
    /// q / 360), 0 without Q.
    pub(crate) thread_phase: f64,
    /// Dwell the cycle makes (drilling P), s.
    pub(crate) dwell_s: f64,
    /// G70: the move that starts the compensation (the block that wrote G41/G42; 0: the
    /// first move).
    pub(crate) comp_from: usize,
    /// G76: the tool's included angle, where a word of the program states it (P's a, A);
    /// a of 0 (straight infeed) says nothing of the insert.
    pub(crate) tool_angle: Option<f64>,
}

impl Cycle<'_, '_> {
    /// The end point and R of a G90/G92/G94 block, filling what the block omits from the
    /// retained words of the same cycle (or, for a new cycle, the start point and R0).
    pub(crate) fn turn_words(&mut self, code: i32) -> Result<TurnWords, Diagnostic> {
        let prev = self
            .retained
            .turn
            .filter(|t| t.code == code && self.g.is_none());
        let x = self.x_target()?;
        let z = self.z_target()?;
        let r = self.taper(code)?;
        let end = Pt::new(
            z.or(prev.map(|p| p.end.z)).unwrap_or(self.start.z),
            x.or(prev.map(|p| p.end.r)).unwrap_or(self.start.r),
        );
        let words = TurnWords {
            code,
            end,
            r: r.or(prev.map(|p| p.r)).unwrap_or(0.0),
        };
        self.retained.turn = Some(words);
        Ok(words)
    }

    /// The taper word of G90/G92/G94 in mm: `R` (FANUC 0i and later, GSK); on Haas `I`
    /// (G90/G92, radius) and `K` (G94), and `R` there is an alarm naming them
    /// (spec/dialects.md §3.5). Same sign convention: start minus end.
    fn taper(&mut self, code: i32) -> Result<Option<f64>, Diagnostic> {
        if self.machine.control != crate::Control::Haas {
            return Ok(self.words.mm('R', self.unit));
        }
        let word = if code == G94 { 'K' } else { 'I' };
        if let Some(r) = self.words.take('R') {
            return Err(Diagnostic::new(
                r.span,
                "LS-DIALECT",
                format!("R is not a Haas taper word: {} takes {word}", name(code)),
                format!(
                    "write {word}{} (Haas: I is the radius taper of G90/G92, K the Z taper of G94)",
                    r.value
                ),
            ));
        }
        Ok(self.words.mm(word, self.unit))
    }

    /// Where alarms about the cycle as a whole point: its G word, or the block.
    pub(crate) fn span(&self) -> Span {
        self.g.map_or(self.words.span(), |g| g.span)
    }

    /// An alarm at the cycle's G word.
    pub(crate) fn alarm(
        &self,
        code: &'static str,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::new(self.span(), code, message, help)
    }

    /// Absolute X (diameter) or incremental U as a radius in the G54 frame; `None` if absent.
    pub(crate) fn x_target(&mut self) -> Result<Option<f64>, Diagnostic> {
        self.axis('X', 'U', 2.0, self.start.r, self.shift.r)
    }

    /// Absolute Z or incremental W in the G54 frame; `None` if absent.
    pub(crate) fn z_target(&mut self) -> Result<Option<f64>, Diagnostic> {
        self.axis('Z', 'W', 1.0, self.start.z, self.shift.z)
    }

    fn axis(
        &mut self,
        abs: char,
        inc: char,
        div: f64,
        from: f64,
        shift: f64,
    ) -> Result<Option<f64>, Diagnostic> {
        let a = self.words.take(abs);
        let i = self.words.take(inc);
        match (a, i) {
            (Some(a), Some(i)) => Err(Diagnostic::new(
                i.span,
                "LS-AXIS-TWICE",
                format!("{abs} and {inc} both given (first at {})", a.span),
                format!("give the end point either absolute ({abs}) or incremental ({inc})"),
            )),
            (Some(a), None) => Ok(Some(a.value * self.unit / div + shift)),
            (None, Some(i)) => Ok(Some(from + i.value * self.unit / div)),
            (None, None) => Ok(None),
        }
    }
}

/// The thread start angle `Q` of G32/G92 in degrees (spec/dialects.md §4.7): 0.001° units,
/// no decimal point, `Q0`–`Q360000`; 0 without Q (not modal on FANUC).
pub(crate) fn thread_start_angle(words: &mut Words) -> Result<f64, Diagnostic> {
    let Some(w) = words.take('Q') else {
        return Ok(0.0);
    };
    if w.has_point || w.value.fract() != 0.0 || !(0.0..=360_000.0).contains(&w.value) {
        return Err(Diagnostic::new(
            w.span,
            "LS-THREAD-Q",
            format!(
                "Q{} is not a thread start angle: Q is 0–360000 in 0.001° without a decimal point",
                w.value
            ),
            "write the start angle in thousandths of a degree, e.g. Q180000 for the second start of a two-start thread",
        ));
    }
    Ok(w.value / 1000.0)
}

/// Run the cycle `c.code`.
pub(crate) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    match c.code {
        G90 => g90::run(c),
        G92 => g92::run(c),
        G94 => g94::run(c),
        G74 | G75 => g74_g75::run(c),
        G75_1 => g75_1::run(c),
        G70 => g70::run(c),
        G71 | G72 => g71_g72::run(c),
        G73 => g73::run(c),
        G76 => g76::run(c),
        crate::linuxcnc::CYCLE_G76 => g76_linuxcnc::run(c),
        t if drill::is_drill(t) => drill::run(c),
        _ => Err(not_implemented(c)),
    }
}

/// The alarm for a cycle latsim recognises but cannot run yet.
pub(crate) fn not_implemented(c: &Cycle) -> Diagnostic {
    c.alarm(
        "LS-NOT-IMPLEMENTED",
        format!("{} is not implemented yet in this version of latsim", name(c.code)),
        "the cycle is recognised but cannot be simulated yet; remove it or wait for the release that adds it",
    )
}

/// A cycle's name for messages.
pub(crate) fn name(tenths: i32) -> &'static str {
    match tenths {
        G70 => "G70 (finishing cycle)",
        G71 => "G71 (stock removal in turning)",
        G72 => "G72 (stock removal in facing)",
        G73 => "G73 (pattern repeating cycle)",
        G74 => "G74 (face grooving / peck drilling cycle)",
        G75 => "G75 (radial grooving cycle)",
        G75_1 => "G75.1 (radial trapezoid groove cycle)",
        G76 => "G76 (multiple threading cycle)",
        crate::linuxcnc::CYCLE_G76 => "G76 (LinuxCNC threading cycle)",
        G90 => "G90 (axial turning cycle)",
        G92 => "G92 (threading cycle)",
        G94 => "G94 (face turning cycle)",
        G81 => "G81 (drilling cycle)",
        G82 => "G82 (drilling cycle with dwell)",
        G83 => "G83 (peck drilling cycle)",
        G84 => "G84 (tapping cycle)",
        G85 => "G85 (boring cycle)",
        _ => "this cycle",
    }
}

/// Whether a G code (tenths) is a canned cycle.
pub(crate) fn is_cycle(tenths: i32) -> bool {
    matches!(
        tenths,
        G70 | G71 | G72 | G73 | G74 | G75 | G75_1 | G76 | G90 | G92 | G94
    ) || drill::is_drill(tenths)
        || tenths == crate::linuxcnc::CYCLE_G76
}

/// Whether a cycle is modal (group 01): later blocks with only coordinates repeat it.
pub(crate) fn is_modal(tenths: i32) -> bool {
    matches!(tenths, G90 | G92 | G94)
}
