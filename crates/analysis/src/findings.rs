//! What a run concludes, as plain data: the binary maps it onto the report, the renderer
//! draws it, nobody decides anything after it.

use crate::deviation::Deviation;
use crate::intent::Intent;
use crate::MoveFacts;
use expander::Span;

/// The one-word outcome of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Verdict {
    /// No alarm, crash or gouge.
    #[default]
    Clean,
    /// A controller alarm stopped or corrupted the run (or the analysis raised one: a
    /// threading tool on the wrong side).
    Alarm,
    /// A rapid ran into stock, a tool's body met stock, or a tool entered the chuck, its
    /// jaws or the tailstock (or cut inside the jaws).
    Crash,
    /// Part material removed: a gouge, or a thread cut deeper than expected by more than
    /// the tolerance.
    Gouge,
}

pub use crate::note::Note;

/// A crash, or a rapid scrape: a move whose tool met stock, or whose tool entered the
/// workholding.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Crash {
    /// The move (index into the toolpath's segments).
    pub segment: usize,
    /// Where the tool first met stock or the obstacle, `[z, r]`.
    pub at: [f64; 2],
    /// Overlap, mm² of the half section.
    pub area: f64,
    /// Thickness of the overlap normal to the move, mm.
    pub depth: f64,
    /// The tool's non-cutting body that met it ("holder", "boring bar", …); `None`: the
    /// cutting outline.
    pub body: Option<&'static str>,
    /// The workholding it entered ("chuck face", "chuck jaw", "tailstock centre",
    /// "gripped length"); `None`: it met stock.
    pub obstacle: Option<&'static str>,
    /// The tool (cutting outline and body, convex parts in `[z, r]`) where it met it, for
    /// the first crashes of a run ([`crate::MAX_TOOL_POSES`]); empty for the others.
    pub tool: Vec<Vec<[f64; 2]>>,
    /// A possible crash (spec/simulation.md, "Findings from assumed tools"): the tool's
    /// outline is a guess and its reference point alone meets nothing. No effect on the
    /// verdict.
    pub assumed: bool,
    /// Why it happened ([`crate::diagnose`]); `None` before the diagnosis.
    pub cause: Option<Cause>,
    /// How to fix it, checked by simulating the fix; `None` when no fix was found.
    pub remedy: Option<Remedy>,
}

/// Why a finding happened, from the geometry: which part of the tool met what, with the
/// measured numbers that show it.
#[derive(Debug, Clone, PartialEq)]
pub struct Cause {
    /// The kind of cause.
    pub kind: CauseKind,
    /// One sentence for a machinist.
    pub text: String,
    /// The measured numbers it rests on (`flank_deg`, `clearance_deg`, `nose_radius`, …).
    pub numbers: Vec<(&'static str, f64)>,
}

/// The kinds of cause (issue 33's contract; JSON `cause.kind`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CauseKind {
    /// A turning tool's trailing edge on a descending flank steeper than its clearance.
    TrailingEdge,
    /// The leading edge on a wall that leans back further than the holder allows.
    LeadingEdge,
    /// The nose: in an inside corner smaller than its radius.
    Nose,
    /// The nose radius left uncompensated (or compensated for another nose).
    Compensation,
    /// The tool's body (holder, bar) reached what the edge could not.
    Body,
    /// A rapid into uncut stock.
    Rapid,
    /// The chuck, its jaws or the tailstock.
    Workholding,
    /// Another tool or operation cut it.
    OtherTool,
    /// The program itself: the programmed point goes there, or no pass reaches it.
    Program,
}

impl CauseKind {
    /// The JSON word.
    pub fn word(self) -> &'static str {
        match self {
            Self::TrailingEdge => "trailing-edge",
            Self::LeadingEdge => "leading-edge",
            Self::Nose => "nose",
            Self::Compensation => "compensation",
            Self::Body => "body",
            Self::Rapid => "rapid",
            Self::Workholding => "workholding",
            Self::OtherTool => "other-tool",
            Self::Program => "program",
        }
    }
}

/// A fix latsim has checked: the program re-run with it (in memory, same blank) loses the
/// finding and gains none.
#[derive(Debug, Clone, PartialEq)]
pub struct Remedy {
    /// One sentence for a machinist.
    pub text: String,
    /// The tool to use instead (an ISO designation or a table entry), for a tool change.
    pub tool: Option<String>,
    /// The program line to change, for a program change.
    pub line: Option<u32>,
    /// The block(s) as they should read there, for a program change.
    pub edit: Option<String>,
    /// Whether the re-run confirmed it (only confirmed remedies are given).
    pub verified: bool,
    /// A tool change's tool as mounted, its cutting outline relative to the reference
    /// point (`[dz, dr]` rings), for the player to draw on the move; empty otherwise.
    pub ghost: Vec<Vec<[f64; 2]>>,
}

/// A thread, checked in the final section.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThreadCheck {
    /// Its first pass's block.
    pub span: Span,
    /// Cut in the bore (an ID thread) rather than the outside.
    pub inside: bool,
    /// Programmed lead, mm.
    pub lead_mm: f64,
    /// Number of starts (the pitch is the lead over it).
    pub starts: usize,
    /// Programmed final X (the deepest pass's end): minor diameter (OD), major (ID).
    pub x_mm: f64,
    /// The diameter that should be reached: `--target`'s surface over the thread, else
    /// `x_mm`; `None`: not measurable.
    pub expected_x_mm: Option<f64>,
    /// Radial depth of each pass, mm.
    pub pass_depths_mm: Vec<f64>,
    /// Minor (OD) / major (ID) diameter reached in the final section.
    pub achieved_x_mm: Option<f64>,
    /// Achieved depth minus the expected depth, radial mm (positive: too deep).
    pub depth_error_mm: Option<f64>,
    /// Pitch diameter as cut, mm.
    pub pitch_diameter_mm: Option<f64>,
    /// Included angle of the groove's flanks as cut, degrees.
    pub included_angle_deg: Option<f64>,
    /// Z where the deepest pass starts, mm.
    pub z_start_mm: f64,
    /// Z where the deepest pass ends, mm.
    pub z_end_mm: f64,
}

impl ThreadCheck {
    /// Whether this thread is cut deeper than `tol` past its expected depth: a gouge (the
    /// verdict's rule, and the CI reports' too).
    pub fn too_deep(&self, tol: f64) -> bool {
        self.depth_error_mm.is_some_and(|e| e > tol)
    }
}

/// A G75.1 groove the program defines, and how far the final part strays from it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GrooveCheck {
    /// The block that defines it.
    pub span: Span,
    /// Its outline as a closed ring in `[z, r]`, corners in order.
    pub ring: Vec<[f64; 2]>,
    /// Largest distance between the ring and the final part's boundary, mm; `None`: not
    /// measured.
    pub deviation_mm: Option<f64>,
}

/// Everything a run concludes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Findings {
    /// The outcome: the worst of alarms, crashes and gouges.
    pub verdict: Verdict,
    /// Crashes in program order: the removal's over `rapid_cut_tol` and its bodies', and the
    /// workholding's (spec/simulation.md, "Rapids that cut").
    pub crashes: Vec<Crash>,
    /// Rapids that cut no deeper than `rapid_cut_tol`: warnings, not crashes.
    pub scrapes: Vec<Crash>,
    /// The intended part the run was judged against.
    pub intents: Vec<Intent>,
    /// Gouges and leftovers against the intents; `None` without intents.
    pub deviation: Option<Deviation>,
    /// The threads, checked in the final section.
    pub threads: Vec<ThreadCheck>,
    /// The G75.1 grooves.
    pub grooves: Vec<GrooveCheck>,
    /// Alarms the analysis raises (a threading tool working on the wrong side).
    pub alarms: Vec<Note>,
    /// Warnings about moves (rapid scrapes), in program order.
    pub warnings: Vec<Note>,
    /// Warnings about the part (cuts of a later operation, thread depths), after them.
    pub part_warnings: Vec<Note>,
    /// What the moves alone tell (times, rear-post tools, the tools drawn in the player).
    pub facts: MoveFacts,
}

impl Findings {
    /// Worst finding first: alarm (the toolpath's `toolpath_alarms` or the analysis's own),
    /// crash, gouge (a thread too deep by more than `tol` is one), else clean.
    pub(crate) fn judge(&self, toolpath_alarms: usize, tol: f64) -> Verdict {
        let gouged = self
            .deviation
            .as_ref()
            .is_some_and(|d| d.gouges.iter().any(|g| !g.assumed));
        let too_deep = self.threads.iter().any(|t| t.too_deep(tol));
        if toolpath_alarms > 0 || !self.alarms.is_empty() {
            Verdict::Alarm
        } else if self.crashes.iter().any(|c| !c.assumed) {
            Verdict::Crash
        } else if gouged || too_deep {
            Verdict::Gouge
        } else {
            Verdict::Clean
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deviation::Finding;

    fn gouge() -> Finding {
        Finding {
            shape: stock::Shape::default(),
            area: 1.0,
            depth: 0.2,
            at: [0.0, 0.0],
            nearest: [0.0, 0.0],
            made_by: None,
            assumed: false,
            cause: None,
            remedy: None,
        }
    }

    /// Worst first: an alarm (the toolpath's or the analysis's) over a crash over a gouge
    /// (or a thread cut deeper than the tolerance) over clean; a thread too shallow, or
    /// too deep within the tolerance, is no gouge.
    #[test]
    fn the_verdict_is_the_worst_finding() {
        let mut f = Findings::default();
        assert_eq!(f.judge(0, 0.01), Verdict::Clean);
        f.threads.push(ThreadCheck {
            depth_error_mm: Some(-0.5),
            ..ThreadCheck::default()
        });
        f.threads.push(ThreadCheck {
            depth_error_mm: Some(0.01),
            ..ThreadCheck::default()
        });
        assert_eq!(f.judge(0, 0.01), Verdict::Clean);
        f.threads[1].depth_error_mm = Some(0.011);
        assert_eq!(f.judge(0, 0.01), Verdict::Gouge);
        f.threads.clear();
        f.deviation = Some(Deviation {
            gouges: vec![gouge()],
            ..Deviation::default()
        });
        assert_eq!(f.judge(0, 0.01), Verdict::Gouge);
        // possible findings (an assumed tool's) do not count
        f.crashes.push(Crash {
            assumed: true,
            ..Crash::default()
        });
        assert_eq!(f.judge(0, 0.01), Verdict::Gouge);
        if let Some(d) = &mut f.deviation {
            d.gouges[0].assumed = true;
        }
        assert_eq!(f.judge(0, 0.01), Verdict::Clean);
        f.crashes.push(Crash::default());
        assert_eq!(f.judge(0, 0.01), Verdict::Crash);
        assert_eq!(f.judge(1, 0.01), Verdict::Alarm);
        f.alarms.push(Note {
            span: Span::default(),
            code: "LS-THREAD-SIDE",
            message: String::new(),
        });
        assert_eq!(f.judge(0, 0.01), Verdict::Alarm);
    }
}
