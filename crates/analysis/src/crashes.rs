//! Crash or scrape: the removal's rapid cuts split by the machine's `rapid_cut_tol`
//! (spec/simulation.md, "Rapids that cut") and the retract-scrape rule ([`crate::retract`]),
//! merged with the workholding's crashes, and the tool drawn where the first of them hit.

use crate::findings::{Crash, Note};
use crate::fixture::FixtureCrash;
use crate::pose::tool_at_crash;
use expander::Segment;
use stock::{Simulation, ToolTable};

/// Crashes whose tool is drawn where it hit (the first ones: more would hide the picture).
pub const MAX_TOOL_POSES: usize = 20;

/// A removal crash as a finding.
fn of_removal(c: &stock::Crash) -> Crash {
    Crash {
        segment: c.segment,
        at: c.at,
        area: c.area,
        depth: c.depth,
        body: c.body,
        ..Crash::default()
    }
}

/// The removal's rapid cuts told apart: (crashes, scrapes). A body touching stock is a
/// crash; a cut of the cutting outline is a scrape when no deeper than `cut_tol` or when it
/// is a retract scrape, else a crash.
pub(crate) fn split(
    sim: &Simulation,
    cut_tol: f64,
    segments: &[Segment],
    tools: &ToolTable,
    rear: &[u32],
) -> (Vec<Crash>, Vec<Crash>) {
    sim.crashes.iter().map(of_removal).partition(|c| {
        c.body.is_some()
            || (c.depth > cut_tol && !crate::retract::is_retract(c, segments, tools, rear))
    })
}

/// The crashes of a run in program order: the removal's (`removal`, [`split`]) and the
/// workholding's (always); at one move, the stock's crash before the workholding's.
pub(crate) fn crashes(removal: Vec<Crash>, fixture: &[FixtureCrash]) -> Vec<Crash> {
    let mut out = removal;
    out.extend(fixture.iter().map(|f| Crash {
        segment: f.segment,
        at: f.at,
        area: f.area,
        depth: f.depth,
        body: f.body,
        obstacle: Some(f.obstacle),
        tool: vec![],
        assumed: false,
        cause: None,
        remedy: None,
    }));
    // stable: at one move, the stock's crash before the workholding's
    out.sort_by_key(|c| c.segment);
    out
}

/// The warning of each scrape, at its move's line: a retract scrape's with its fix.
pub(crate) fn scrape_notes(
    scrapes: &[Crash],
    segments: &[Segment],
    tools: &ToolTable,
    rear: &[u32],
    cut_tol: f64,
) -> Vec<Note> {
    scrapes
        .iter()
        .map(|c| {
            if crate::retract::is_retract(c, segments, tools, rear) {
                return crate::retract::note(c, segments, tools);
            }
            Note {
            span: segments[c.segment].span,
            code: "LS-RAPID-SCRAPE",
            message: format!(
                "rapid scrapes {:.3} mm deep ({:.4} mm² of stock) at Z{:.3} X{:.3}: not more than rapid_cut_tol {cut_tol} mm, so not a crash; a rapid should clear the stock",
                c.depth,
                c.area,
                c.at[0],
                2.0 * c.at[1]
            ),
        }
        })
        .collect()
}

/// Marks the crashes of guessed tools whose reference point alone meets nothing as possible
/// ([`crate::assumed`]): a removal crash whose path does not enter uncut stock, a
/// workholding crash whose path does not enter the obstacle; returns their warnings.
pub(crate) fn mark_assumed(
    crashes: &mut [Crash],
    segments: &[Segment],
    s: &crate::Settings,
    rear: &[u32],
    chord_tol: f64,
) -> Vec<Note> {
    let mut mounts = stock::Mounts::new(s.tools, rear.to_vec());
    let mut notes = Vec::new();
    let mut tested = 0;
    for c in crashes.iter_mut() {
        let seg = &segments[c.segment];
        if !crate::assumed::guessed(s.tools, seg) {
            continue;
        }
        tested += 1;
        if tested > crate::assumed::MAX_TESTED {
            c.assumed = true;
            notes.push(crate::assumed::note("crash", c.depth, seg, s.tools));
            continue;
        }
        let core = mounts.of(seg).core.clone();
        let certain = match c.obstacle {
            None => {
                crate::assumed::enters_uncut(
                    c.segment,
                    (segments, s.tools),
                    &s.blank.shapes,
                    &mut mounts,
                    (chord_tol, s.machine.rapid_cut_tol),
                ) || core.is_some_and(|core| {
                    crate::assumed::core_enters_uncut(
                        c.segment,
                        &core,
                        (segments, s.tools),
                        &s.blank.shapes,
                        &mut mounts,
                        chord_tol,
                    )
                })
            }
            Some(name) => s.fixture.is_some_and(|f| {
                f.obstacles.iter().filter(|o| o.name == name).any(|o| {
                    let region = crate::assumed::Region::new(&o.shapes);
                    crate::assumed::path_enters(seg, &region, chord_tol)
                })
            }),
        };
        if !certain {
            c.assumed = true;
            notes.push(crate::assumed::note("crash", c.depth, seg, s.tools));
        }
    }
    notes
}

/// The tool drawn where each of the first [`MAX_TOOL_POSES`] crashes hit.
pub(crate) fn place_tools(
    crashes: &mut [Crash],
    segments: &[Segment],
    tools: &ToolTable,
    rear: &[u32],
    chord_tol: f64,
) {
    for c in crashes.iter_mut().take(MAX_TOOL_POSES) {
        c.tool = tool_at_crash(tools, &segments[c.segment], rear, c.at, c.body, chord_tol);
    }
}
