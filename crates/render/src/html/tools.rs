//! The tool and the workholding in the HTML player's data block (drawn by `tools.js`):
//!
//! - `fixture`: the chuck, jaws and tailstock centre, rings `[z, x, …]`;
//! - `tools`: each distinct tool outline as mounted, `{"edge": rings, "body": rings}`,
//!   relative to the reference point (`[dz, dx]`, dx a diameter difference);
//! - `tool_runs`: `[move, tool]` pairs, in move order: from that (1-based) move on, the
//!   tool drawn is `tools[tool]`;
//! - `crash_tools`: `[line, rings]`: the tool where it crashed at that line;
//! - `remedy_tools`: `[line, rings]`: a gouge's checked remedy tool (its cutting outline
//!   relative to the reference point), drawn dashed on the moves of the gouge's line.

use std::fmt::Write as _;

use super::rings_json;
use crate::report::Report;

/// Appends the fields above (each followed by a comma) to the data block.
pub(super) fn data(out: &mut String, report: &Report) {
    let fixture: Vec<Vec<[f64; 2]>> = report
        .fixture
        .iter()
        .flat_map(|f| f.shapes.iter())
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .cloned()
        .collect();
    out.push_str("\"fixture\":");
    rings_json(out, &fixture);
    out.push_str(",\"tools\":[");
    for (i, t) in report.tool_outlines.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str("{\"edge\":");
        rings_json(out, &t.edge);
        out.push_str(",\"body\":");
        rings_json(out, &t.body);
        out.push('}');
    }
    out.push_str("],\"tool_runs\":[");
    for (i, (first, k)) in report.tool_runs.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        let _ = write!(out, "[{},{k}]", first + 1);
    }
    out.push_str("],\"crash_tools\":[");
    let mut first = true;
    for c in report.crashes.iter().filter(|c| !c.tool.is_empty()) {
        if !first {
            out.push(',');
        }
        first = false;
        let _ = write!(out, "[{},", c.line);
        rings_json(out, &c.tool);
        out.push(']');
    }
    out.push_str("],\"remedy_tools\":[");
    let ghosts = report
        .gouges
        .iter()
        .filter_map(|g| Some((g.line, &g.remedy.as_ref()?.ghost)))
        .filter(|(_, ghost)| !ghost.is_empty());
    for (i, (line, ghost)) in ghosts.enumerate() {
        if i > 0 {
            out.push(',');
        }
        let _ = write!(out, "[{line},");
        rings_json(out, ghost);
        out.push(']');
    }
    out.push_str("],");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::{Gouge, Remedy};

    /// A gouge's checked tool change carries its tool to the player, on the gouge's line;
    /// a program change (no tool) carries nothing.
    #[test]
    fn a_remedy_tool_goes_to_the_player_on_its_line() {
        let ghost = vec![vec![[0.0, 0.0], [1.0, 0.5], [1.0, 2.0], [0.0, 1.0]]];
        let gouge = |line: u32, ghost: Vec<Vec<[f64; 2]>>| Gouge {
            line,
            z: -10.0,
            r: 20.0,
            area_mm2: 1.0,
            depth_mm: 0.5,
            assumed: false,
            cause: None,
            remedy: Some(Remedy {
                text: "use T06".into(),
                verified: true,
                ghost,
                ..Remedy::default()
            }),
        };
        let report = Report {
            gouges: vec![gouge(9, ghost), gouge(12, vec![])],
            ..Report::default()
        };
        let mut out = String::new();
        data(&mut out, &report);
        assert!(
            out.contains("\"remedy_tools\":[[9,[[0,0,1,1,1,4,0,2]]]]"),
            "{out}"
        );
    }
}
