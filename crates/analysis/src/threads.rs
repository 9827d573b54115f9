//! The threads, checked in the final section (spec/simulation.md and README, "threads"):
//! the diameter reached against the programmed final X, or against a `--target`'s surface
//! over the thread (a target draws a thread at its minor diameter, OD, or major, ID). A
//! thread deeper than expected by more than `--tol` fails the run like a gouge (part
//! material removed, [`crate::Findings::judge`]); one too shallow is only a warning (like a
//! leftover). Both are warnings `LS-THREAD-DEPTH` at the thread's line; a tool that cuts
//! away from its own side is the alarm `LS-THREAD-SIDE`.

use crate::findings::{Note, ThreadCheck};
use crate::measure::{least_gap, Reference, Surface, Thread, ThreadPasses};
use expander::Segment;
use stock::{Shape, ToolTable};

/// The stock after so many moves, where the run kept it.
type KeptStock = (usize, Vec<Shape>);

/// The threads' checks, with the notes they raise.
#[derive(Debug, Default)]
pub(crate) struct Checked {
    pub(crate) threads: Vec<ThreadCheck>,
    pub(crate) alarms: Vec<Note>,
    pub(crate) warnings: Vec<Note>,
}

/// Checks every thread of `passes` in `shapes` (the final part). `before`: the stock each
/// thread cut into, by its first move, where it was kept: the depth is measured only where
/// that stock came up to the root (a relief groove cut deeper before is not the thread's
/// depth). `done`: the stock once each thread's last pass ran, by [`Thread::done_at`],
/// where it was kept: its depth and form are measured there, as the thread cut itself (a
/// later tool deburring its first turn made it "0.8 too deep", a gouge; field run 5, D).
pub(crate) fn check(
    passes: &ThreadPasses,
    (segments, tools): (&[Segment], &ToolTable),
    shapes: &[Shape],
    target: Option<&[Shape]>,
    (before, done): (&[KeptStock], &[KeptStock]),
    tol: f64,
) -> Checked {
    let mut out = Checked::default();
    for t in passes.measure(segments, shapes) {
        let final_shapes = shapes;
        let shapes = done
            .iter()
            .find(|(k, _)| *k == t.done_at)
            .map_or(shapes, |(_, s)| s.as_slice());
        if let Some(cut) = t.cut_through_later(shapes, final_shapes, tol) {
            out.warnings.push(cut_through(&t, cut, segments));
        }
        if t.wrong_side {
            let tool = segments[t.first_move].tool;
            if tools.get(tool).is_some() {
                out.alarms.push(wrong_side(&t));
            } else {
                out.warnings.push(default_side(&t, tool));
            }
        }
        let cut_into = before
            .iter()
            .find(|(k, _)| *k == t.first_move)
            .map(|(_, s)| s.as_slice());
        let achieved = t.achieved_x(shapes, cut_into);
        let form = t.form(shapes);
        let (z0, z1) = t.z_span();
        let sign = match t.surface {
            Surface::Outer => 1.0,
            Surface::Bore => -1.0,
        };
        // the least gap between the section and what it should be (negative: deeper)
        let (gap, expected) = match target {
            Some(part) => {
                let gap = least_gap(shapes, Reference::Shapes(part), z0, z1, t.surface);
                (gap, achieved.zip(gap).map(|(a, g)| a - sign * 2.0 * g))
            }
            None => (achieved.map(|a| sign * (a - t.x()) / 2.0), Some(t.x())),
        };
        let depth_error = gap.map(|g| -g);
        if let Some(e) = depth_error.filter(|e| e.abs() > tol) {
            out.warnings.push(depth_note(&t, e, achieved, expected));
        }
        out.threads.push(ThreadCheck {
            span: t.span,
            inside: t.surface == Surface::Bore,
            lead_mm: t.lead,
            starts: t.starts,
            x_mm: t.x(),
            expected_x_mm: expected,
            pass_depths_mm: t.pass_depths.clone(),
            achieved_x_mm: achieved,
            depth_error_mm: depth_error,
            pitch_diameter_mm: form.map(|f| f.pitch_diameter),
            included_angle_deg: form.and_then(|f| f.included_angle),
            z_start_mm: z0,
            z_end_mm: z1,
        });
    }
    out
}

/// For a thread cut in `surface` whose passes go deeper away from its tool's side: the
/// tool's side ("an OD"), where the passes go, and the side the tool should be given.
fn sides(surface: Surface) -> (&'static str, &'static str, &'static str) {
    match surface {
        Surface::Outer => ("an OD", "outward (an inside thread)", "id"),
        Surface::Bore => ("an ID", "inward (an outside thread)", "od"),
    }
}

/// The alarm of a threading tool whose passes go deeper away from its own side.
fn wrong_side(t: &Thread) -> Note {
    let (side, toward, other) = sides(t.surface);
    Note {
        span: t.span,
        code: "LS-THREAD-SIDE",
        message: format!(
            "the thread passes go deeper {toward} but the threading tool is {side} insert: its body sweeps through the part; give the tool `side = \"{other}\"` in the tool table"
        ),
    }
}

/// The warning of a thread cut the other way than the default threading insert points,
/// by a tool `t` the table says nothing of: the side is the default's guess, not the
/// program's error (spec/simulation.md, "Findings from assumed tools").
fn default_side(t: &Thread, tool: u32) -> Note {
    let (default, toward, other) = sides(t.surface);
    Note {
        span: t.span,
        code: "LS-ASSUMED-TOOL",
        message: format!(
            "the thread passes go deeper {toward}; T{tool:02} is not in the tool table and the tool it is taken for is {default} insert, whose body sweeps through the part: state T{tool:02} with `side = \"{other}\"` to check this thread"
        ),
    }
}

/// The warning of a thread that a later move cuts through over `(z0, z1)`, at that move's
/// line: measured as it cut itself, the thread is right, and no intent speaks within its
/// band (the thread's own business), so nothing else would say so (review of field run 5,
/// D).
fn cut_through(t: &Thread, (z0, z1): (f64, f64), segments: &[Segment]) -> Note {
    let later = segments[t.done_at.min(segments.len())..].iter().find(|s| {
        s.motion != expander::Motion::Rapid
            && s.from.z.min(s.to.z) <= z1
            && s.from.z.max(s.to.z) >= z0
    });
    Note {
        span: later.map_or(t.span, |s| s.span),
        code: "LS-THREAD-CUT",
        message: format!(
            "the thread of line {} is cut below its root from Z{z1:.3} to Z{z0:.3} after its last pass{}",
            t.span.line,
            later.map_or(String::new(), |s| format!(" (line {})", s.span.line)),
        ),
    }
}

/// The warning of a thread cut `e` mm too deep (positive) or too shallow.
fn depth_note(t: &Thread, e: f64, achieved: Option<f64>, expected: Option<f64>) -> Note {
    Note {
        span: t.span,
        code: "LS-THREAD-DEPTH",
        message: format!(
            "thread depth error: the thread is cut {:.3} mm too {}{}",
            e.abs(),
            if e > 0.0 { "deep" } else { "shallow" },
            match (achieved, expected) {
                (Some(a), Some(x)) => format!(" (X{a:.3} reached, X{x:.3} expected)"),
                _ => String::new(),
            },
        ),
    }
}
