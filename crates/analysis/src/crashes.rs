//! Crash or scrape: the removal's rapid cuts split by the machine's `rapid_cut_tol`
//! (spec/simulation.md, "Rapids that cut"), merged with the workholding's crashes, and the
//! tool drawn where the first of them hit.

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

/// The crashes of a run in program order: the removal's deeper than `cut_tol` (a body
/// touching stock always) and the workholding's (always); at one move, the stock's crash
/// before the workholding's.
pub(crate) fn crashes(sim: &Simulation, fixture: &[FixtureCrash], cut_tol: f64) -> Vec<Crash> {
    let mut out: Vec<Crash> = sim
        .crashes
        .iter()
        .filter(|c| c.body.is_some() || c.depth > cut_tol)
        .map(of_removal)
        .collect();
    out.extend(fixture.iter().map(|f| Crash {
        segment: f.segment,
        at: f.at,
        area: f.area,
        depth: f.depth,
        body: f.body,
        obstacle: Some(f.obstacle),
        tool: vec![],
    }));
    // stable: at one move, the stock's crash before the workholding's
    out.sort_by_key(|c| c.segment);
    out
}

/// The rapids that cut no deeper than `cut_tol`: scrapes, not crashes.
pub(crate) fn scrapes(sim: &Simulation, cut_tol: f64) -> Vec<Crash> {
    sim.crashes
        .iter()
        .filter(|c| c.body.is_none() && c.depth <= cut_tol)
        .map(of_removal)
        .collect()
}

/// The warning of each scrape, at its move's line.
pub(crate) fn scrape_notes(scrapes: &[Crash], segments: &[Segment], cut_tol: f64) -> Vec<Note> {
    scrapes
        .iter()
        .map(|c| Note {
            span: segments[c.segment].span,
            code: "LS-RAPID-SCRAPE",
            message: format!(
                "rapid scrapes {:.3} mm deep ({:.4} mm² of stock) at Z{:.3} X{:.3}: not more than rapid_cut_tol {cut_tol} mm, so not a crash; a rapid should clear the stock",
                c.depth,
                c.area,
                c.at[0],
                2.0 * c.at[1]
            ),
        })
        .collect()
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
