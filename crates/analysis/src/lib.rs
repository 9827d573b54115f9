//! The fourth stage: what a run concludes. From the toolpath (`expander`) and what the
//! removal did to the blank (`stock`), it reads the intended part, compares the final part
//! with it (gouges, leftovers and the moves that made them), checks the workholding, the
//! threads and the grooves, splits rapid cuts into crashes and scrapes, and gives the
//! verdict. [`Findings`] is plain data; the binary maps it onto the report.
//!
//! ```text
//! &str ─gcode─▶ Program ─expander─▶ Toolpath ─stock─▶ Simulation ─analysis─▶ Findings ─▶ Report
//! ```

mod assumed;
mod crashes;
mod deviation;
pub mod diagnose;
pub mod diff;
mod findings;
mod fixture;
mod intent;
mod measure;
mod note;
mod pose;
mod retract;
mod sweeps;
mod threads;

pub use crashes::MAX_TOOL_POSES;
pub use deviation::{deviation, Deviation, Finding};
pub use findings::{
    Cause, CauseKind, Crash, Findings, GrooveCheck, Note, Remedy, ThreadCheck, Verdict,
};
pub use fixture::{Fixture, FixtureCrash, Obstacle, GRIPPED_LENGTH, TAILSTOCK_CENTRE};
pub use intent::program::{stock_marks, thread_marks};
pub use intent::{Comp, Intent, Owner, Stages};
pub use measure::{
    deepest_radius, groove_deviation, least_gap, surface_radius_at, thread_starts, threads,
    Reference, Surface, Thread, ThreadForm, ThreadPasses,
};
pub use pose::{tool_at_crash, tool_outlines};

use expander::{IntendedKind, Machine, Motion, Segment, Toolpath};
use stock::{Blank, Shape, SimOptions, Simulation, ToolTable};

/// Most findings of one kind a report lists, and most notes of later cuts.
pub const MAX_LISTED: usize = 1_000;

/// What the part is judged against.
#[derive(Debug, Clone, PartialEq)]
pub enum Intents {
    /// The shapes the program defines for itself (its finishing shapes, grooves and
    /// compensated contours).
    Program,
    /// A drawing of the whole part (`--target`).
    Target(Vec<Shape>),
}

/// What the run was given besides the program.
#[derive(Debug, Clone, Copy)]
pub struct Settings<'a> {
    /// The blank.
    pub blank: &'a Blank,
    /// The tool table.
    pub tools: &'a ToolTable,
    /// The machine profile: rapid rates and `rapid_cut_tol`.
    pub machine: &'a Machine,
    /// The chuck and tailstock, when given.
    pub fixture: Option<&'a Fixture>,
    /// Deviation tolerance (`--tol`), mm: shallower differences are no findings.
    pub tol: f64,
}

/// Chord tolerance of the moves' arcs in every check, mm: the removal's
/// (`stock::SimOptions::chord_tol`), so a check sees the sweep the removal cut.
pub(crate) const CHORD_TOL: f64 = 0.001;

/// What the moves alone tell, worked out beside the removal (each is a pass over the moves).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MoveFacts {
    /// Cycle time and time per tool.
    pub times: expander::timing::Times,
    /// Rapid moves among the moves.
    pub rapid_segments: usize,
    /// The tools on a rear post ([`stock::rear_tools`]).
    pub rear: Vec<u32>,
    /// Each distinct tool as mounted (cutting outline's parts, body's parts), for the
    /// player to draw.
    #[allow(clippy::type_complexity)]
    pub outlines: Vec<(Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>)>,
    /// (first move of a run of moves with one tool, index into `outlines`).
    pub runs: Vec<(usize, usize)>,
}

/// The moves' facts and the checks that need no stock: worked out while the removal runs.
struct Beside {
    facts: MoveFacts,
    fixture_crashes: Vec<FixtureCrash>,
    thread_passes: ThreadPasses,
}

impl Beside {
    fn of(toolpath: &Toolpath, s: &Settings, thread_passes: ThreadPasses) -> Self {
        let segments = &toolpath.segments;
        let rear = stock::rear_tools(segments);
        let (outlines, runs) = tool_outlines(s.tools, segments, &rear);
        Self {
            facts: MoveFacts {
                times: expander::timing::times(toolpath, s.machine),
                rapid_segments: segments
                    .iter()
                    .filter(|m| m.motion == Motion::Rapid)
                    .count(),
                rear,
                outlines,
                runs,
            },
            fixture_crashes: s
                .fixture
                .map(|f| f.check(s.tools, segments, CHORD_TOL, &toolpath.tailstock))
                .unwrap_or_default(),
            thread_passes,
        }
    }
}

/// What the run concludes from `sim`, the removal of `toolpath`'s moves from the blank.
pub fn run(toolpath: &Toolpath, sim: &Simulation, intents: &Intents, s: &Settings) -> Findings {
    let passes = ThreadPasses::of(&toolpath.segments, s.tools);
    conclude(toolpath, sim, intents, s, Beside::of(toolpath, s, passes))
}

/// The whole pipeline after expansion: the removal (`stock::simulate` with `opts`, its
/// snapshots taken where [`stock_marks`] wants them as well), with the checks that need no
/// stock worked out beside it on a second thread, then [`run`]'s conclusions.
pub fn pipeline(
    toolpath: &Toolpath,
    intents: &Intents,
    s: &Settings,
    opts: &SimOptions,
    progress: &mut dyn FnMut(usize),
) -> (Simulation, Findings) {
    let mut opts = opts.clone();
    // the threads' passes, found once: for their snapshots and for their checks beside
    let passes = ThreadPasses::of(&toolpath.segments, s.tools);
    opts.snapshot_after.extend(stock_marks(toolpath));
    opts.snapshot_exact
        .extend(intent::program::marks_of_threads(
            &passes,
            &toolpath.segments,
        ));
    opts.snapshot_after.sort_unstable();
    opts.snapshot_after.dedup();
    let (sim, beside) = std::thread::scope(|scope| {
        let side = scope.spawn(|| Beside::of(toolpath, s, passes));
        let sim = stock::simulate(s.blank, s.tools, &toolpath.segments, &opts, progress);
        // a panic there is a bug: the caller's guard reports it
        let beside = side.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        (sim, beside)
    });
    let findings = conclude(toolpath, &sim, intents, s, beside);
    (sim, findings)
}

fn conclude(
    toolpath: &Toolpath,
    sim: &Simulation,
    intents: &Intents,
    s: &Settings,
    beside: Beside,
) -> Findings {
    let segments = &toolpath.segments;
    let stocks = Stocks {
        s,
        sim,
        moves: segments.len(),
    };
    let intents_read = intent::program::read(
        intents,
        toolpath,
        s.tools,
        (&|k| stocks.at(k), &|k| stocks.kept_at(k)),
    );
    let deviation = (!intents_read.is_empty()).then(|| {
        deviation::deviation(
            &s.blank.shapes,
            &sim.final_shapes,
            &intents_read,
            s.tol,
            segments,
            s.tools,
            CHORD_TOL,
        )
    });
    let (crashes, scrapes, warnings) = crash_findings(sim, segments, s, &beside);
    let mut part_warnings = part_notes(deviation.as_ref(), segments, s.tools);
    part_warnings.extend(intent::program::comp_side_notes(toolpath, s.tools));
    let checked = check_threads(
        toolpath,
        sim,
        &stocks,
        intents,
        &intents_read,
        &beside,
        s.tol,
    );
    part_warnings.extend(checked.warnings);
    let mut findings = Findings {
        verdict: Verdict::Clean,
        crashes,
        scrapes,
        intents: intents_read,
        deviation,
        threads: checked.threads,
        grooves: grooves(toolpath, &sim.final_shapes),
        alarms: checked.alarms,
        warnings,
        part_warnings,
        facts: beside.facts,
    };
    findings.verdict = findings.judge(toolpath.alarms.len(), s.tol);
    findings
}

/// The crashes (workholding ones merged in move order, each with its tool placed, possible
/// ones marked), the scrapes, and their warnings.
fn crash_findings(
    sim: &Simulation,
    segments: &[Segment],
    s: &Settings,
    beside: &Beside,
) -> (Vec<Crash>, Vec<Crash>, Vec<Note>) {
    let cut_tol = s.machine.rapid_cut_tol;
    let rear = &beside.facts.rear;
    let (removal, scrapes) = crashes::split(sim, cut_tol, segments, s.tools, rear);
    let mut crashes = crashes::crashes(removal, &beside.fixture_crashes);
    crashes::place_tools(&mut crashes, segments, s.tools, rear, CHORD_TOL);
    let mut warnings = crashes::scrape_notes(&scrapes, segments, s.tools, rear, cut_tol);
    warnings.extend(crashes::mark_assumed(
        &mut crashes,
        segments,
        s,
        rear,
        CHORD_TOL,
    ));
    (crashes, scrapes, warnings)
}

/// The part's warnings from the deviation: later operations' own cuts, possible gouges.
fn part_notes(deviation: Option<&Deviation>, segments: &[Segment], tools: &ToolTable) -> Vec<Note> {
    let mut notes = deviation
        .map(|d| deviation::later_cut_notes(d, segments))
        .unwrap_or_default();
    notes.extend(
        deviation
            .iter()
            .flat_map(|d| &d.gouges)
            .filter(|g| g.assumed)
            .filter_map(|g| {
                let seg = &segments[g.made_by?];
                Some(assumed::note("gouge", g.depth, seg, tools))
            }),
    );
    notes
}

/// The threads checked against the final part (and `--target`), each against the stock it
/// cut into where the run kept it (short programs).
fn check_threads(
    toolpath: &Toolpath,
    sim: &Simulation,
    stocks: &Stocks,
    intents: &Intents,
    intents_read: &[Intent],
    beside: &Beside,
    tol: f64,
) -> threads::Checked {
    let kept = |marks: Vec<usize>| -> Vec<(usize, Vec<Shape>)> {
        marks
            .into_iter()
            .filter_map(|k| stocks.kept_at(k).map(|st| (k, st)))
            .collect()
    };
    let thread_stock = kept(beside.thread_passes.starts());
    let thread_done = kept(beside.thread_passes.ends(&toolpath.segments));
    let target = match intents {
        Intents::Target(_) => intents_read.first().map(|i| i.part.as_slice()),
        Intents::Program => None,
    };
    threads::check(
        &beside.thread_passes,
        (&toolpath.segments, stocks.s.tools),
        &sim.final_shapes,
        target,
        (&thread_stock, &thread_done),
        tol,
    )
}

/// The stock part-way through the run, where the removal kept it.
struct Stocks<'a> {
    s: &'a Settings<'a>,
    sim: &'a Simulation,
    moves: usize,
}

impl Stocks<'_> {
    /// The stock after `k` moves where the run kept it (the blank, a snapshot).
    fn kept_at(&self, k: usize) -> Option<Vec<Shape>> {
        if k == 0 {
            return Some(self.s.blank.shapes.clone());
        }
        self.sim
            .snapshots
            .iter()
            .find(|(at, _)| *at == k)
            .map(|(_, st)| st.clone())
    }

    /// ... or the final part: at the end, and where no snapshot was taken (a long program,
    /// see [`stock_marks`]).
    fn at(&self, k: usize) -> Vec<Shape> {
        (k < self.moves)
            .then(|| self.kept_at(k))
            .flatten()
            .unwrap_or_else(|| self.sim.final_shapes.clone())
    }
}

/// The G75.1 grooves the program defines, each with how far the final part strays from it.
fn grooves(toolpath: &Toolpath, final_shapes: &[Shape]) -> Vec<GrooveCheck> {
    toolpath
        .intended
        .iter()
        .filter(|i| i.kind == IntendedKind::Groove)
        .map(|i| {
            let ring: Vec<[f64; 2]> = i.points.iter().map(|p| [p.z, p.r]).collect();
            GrooveCheck {
                span: i.span,
                deviation_mm: groove_deviation(&ring, final_shapes),
                ring,
            }
        })
        .collect()
}
