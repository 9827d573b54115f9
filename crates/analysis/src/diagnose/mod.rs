//! Why each finding happened, and how to fix it (issue 33). The cause comes from the
//! geometry: which part of the tool met what, with the numbers that show it. A remedy is
//! given only when latsim has checked it: the program re-run with it, in memory on the same
//! blank ([`Rerun`]), loses the finding and gains none — otherwise the cause stands alone.

mod cause;
mod edit;
mod insert;
mod remedy;

use crate::{Findings, Intent, Settings};
use expander::Toolpath;

pub use remedy::{Change, Rerun, Rerunning};

/// Most re-runs tried for one program: each is a whole simulation.
const MAX_RERUNS: usize = 12;
/// Most moves re-simulated for one program's remedies, all re-runs together: the checks
/// cost at most about four runs of a 10⁵-move program (a program of 33 000 moves or fewer
/// gets all [`MAX_RERUNS`]).
const MAX_RERUN_MOVES: usize = 400_000;
/// Programs with more moves get causes only: a re-run costs as much as the run.
const MAX_MOVES_FOR_REMEDIES: usize = 200_000;

/// Gives every crash and gouge of `findings` (and every leftover) its cause, and the first
/// ones a checked remedy, re-running the program through `rerun` (`part`: the part the
/// program leaves, which a remedy must not change but where it acts; `source`: the main
/// program's text, which a remedy edits).
pub fn diagnose(
    findings: &mut Findings,
    (toolpath, part, source): (&Toolpath, &[stock::Shape], &str),
    s: &Settings,
    rerun: &dyn Rerun,
) {
    let segments = &toolpath.segments;
    let Findings {
        crashes,
        deviation,
        intents,
        facts,
        ..
    } = findings;
    let intents: &[Intent] = intents;
    let mut mounts = stock::Mounts::new(s.tools, facts.rear.clone());
    for c in crashes.iter_mut() {
        c.cause = Some(cause::crash(c, segments, s, &facts.rear));
    }
    if let Some(d) = deviation {
        for g in &mut d.gouges {
            g.cause = cause::gouge(
                g,
                (intents, &toolpath.comp_starts),
                segments,
                s,
                &mut mounts,
            );
        }
        for l in &mut d.leftovers {
            l.cause = Some(cause::leftover(l, intents, segments, s));
        }
    }
    if segments.len() > MAX_MOVES_FOR_REMEDIES {
        return;
    }
    let original = findings.clone();
    let mut budget = (MAX_RERUN_MOVES / segments.len().max(1)).clamp(1, MAX_RERUNS);
    let mut tries = remedy::Tries {
        original: &original,
        part,
        source,
        alarms: toolpath.alarms.len(),
        segments,
        tools: s.tools,
        face: s
            .blank
            .shapes
            .iter()
            .flat_map(|sh| sh.outer.iter())
            .map(|p| p[0])
            .fold(f64::NEG_INFINITY, f64::max),
        blank: &s.blank.shapes,
        tol: s.tol,
        runs: std::cell::OnceCell::new(),
        rerun,
        budget: &mut budget,
    };
    for c in &mut findings.crashes {
        if c.assumed {
            continue;
        }
        c.remedy = tries.for_crash(c);
    }
    if let Some(d) = &mut findings.deviation {
        for g in &mut d.gouges {
            if g.assumed {
                continue;
            }
            g.remedy = tries.for_gouge(g);
        }
    }
}
