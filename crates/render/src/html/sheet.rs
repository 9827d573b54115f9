//! The setup sheet: what the operator sets the machine up with — the blank, the chuck, its
//! jaws and the stick-out, the tailstock, every tool with its offsets, ISO designation and
//! time in cut, the cycle time. A section of the page on screen; printed (page.css's print
//! rules, A4 or Letter) it comes first, with the picture, the 3D view and the findings
//! after it, on one or two pages.

use std::fmt::Write as _;

use super::row;
use crate::report::{Fixture, Report, ToolEntry};
use crate::scale::Bbox;
use crate::text::{duration, esc, grouped, num};

/// The setup sheet's section.
pub(super) fn section(out: &mut String, report: &Report) {
    out.push_str("<section id=\"ls-sheet\"><h2>Setup sheet</h2>\n<div class=\"sheet\">\n");
    out.push_str("<table class=\"kv\" id=\"ls-setup\">\n");
    let mut program = report.program.clone();
    if !report.title.is_empty() && !program.starts_with(&report.title) {
        program = format!("{program} ({})", report.title);
    }
    row(out, "program", &esc(&program));
    if !report.control.is_empty() {
        row(out, "control", &esc(&report.control));
    }
    row(out, "blank", &esc(&report.stock.description));
    for (label, text) in workholding(report) {
        row(out, &label, &esc(&text));
    }
    row(out, "cycle time", &esc(&duration(report.cycle_time_s)));
    row(out, "moves", &esc(&grouped(report.segments as f64, 0)));
    out.push_str("</table>\n");
    tools_table(out, report);
    out.push_str("</div></section>\n");
}

/// The tool table: from [`Report::tool_list`], else one line per [`Report::tools`].
fn tools_table(out: &mut String, report: &Report) {
    out.push_str("<table class=\"list tools\" id=\"ls-tools\"><thead><tr><th>T</th><th>offset</th><th>tool</th><th>ISO designation</th><th>in cut</th><th>all moves</th></tr></thead><tbody>\n");
    if report.tool_list.is_empty() {
        for t in &report.tools {
            let _ = writeln!(out, "<tr><td colspan=\"6\">{}</td></tr>", esc(t));
        }
        if report.tools.is_empty() {
            out.push_str("<tr><td colspan=\"6\">no tool moved</td></tr>\n");
        }
    }
    for t in &report.tool_list {
        tool_row(out, t);
    }
    out.push_str("</tbody></table>\n");
}

fn tool_row(out: &mut String, t: &ToolEntry) {
    let number = if t.number == 0 {
        "—".to_string()
    } else {
        format!("T{:02}", t.number)
    };
    let offsets = if t.offsets.is_empty() {
        "—".to_string()
    } else {
        let list: Vec<String> = t.offsets.iter().map(|o| format!("{o:02}")).collect();
        list.join(", ")
    };
    let mut what = t.description.clone();
    if t.number == 0 {
        what.push_str(" (before the first T word)");
    }
    if t.assumed && t.in_table {
        // (the setup sheet said "not in the tool table" of a tool the table lists)
        what.push_str(" (its size not in the tool table: assumed)");
    } else if t.assumed && t.from_moves {
        what.push_str(" (not in the tool table: taken from its moves, its size assumed)");
    } else if t.assumed {
        what.push_str(" (not in the tool table: the default assumed)");
    }
    let _ = writeln!(
        out,
        "<tr><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td><td><code>{}</code></td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
        esc(&number),
        esc(&offsets),
        esc(&what),
        esc(t.designation.as_deref().unwrap_or("—")),
        esc(&duration(t.cut_time_s)),
        esc(&duration(t.time_s)),
    );
}

/// A length for the sheet: up to 3 decimals, a typographic minus.
fn len(v: f64) -> String {
    let s = num(v, 3);
    match s.strip_prefix('-') {
        Some(rest) => format!("\u{2212}{rest}"),
        None => s,
    }
}

/// The box of a workholding piece's section, `None` when it has no point.
fn extent(f: &Fixture) -> Option<Bbox> {
    let pts = f.shapes.iter().flat_map(|s| s.outer.iter());
    let mut b: Option<Bbox> = None;
    for p in pts.filter(|p| p[0].is_finite() && p[1].is_finite()) {
        b = Some(match b {
            None => Bbox::new(p[0], p[0], p[1], p[1]),
            Some(b) => Bbox::new(
                b.zmin.min(p[0]),
                b.zmax.max(p[0]),
                b.rmin.min(p[1]),
                b.rmax.max(p[1]),
            ),
        });
    }
    b
}

/// Rows `(label, text)` for the chuck, its jaws, the stick-out and the tailstock, read off
/// the workholding drawn ([`Report::fixture`]).
fn workholding(report: &Report) -> Vec<(String, String)> {
    let mut rows = Vec::new();
    for f in &report.fixture {
        let Some(b) = extent(f) else { continue };
        let text = match f.name.as_str() {
            "chuck face" => format!(
                "face at Z{}, body Ø{} × {} deep",
                len(b.zmax),
                len(2.0 * b.rmax),
                len(b.zmax - b.zmin)
            ),
            "chuck jaw" if f.shapes.iter().all(|s| s.outer.len() == 4) => format!(
                "hard jaws gripping {} mm over Ø{}, {} mm high",
                len(b.zmax - b.zmin),
                len(2.0 * b.rmin),
                len(b.rmax - b.rmin)
            ),
            "chuck jaw" => format!(
                "soft jaws, Z{} to Z{}, Ø{} to Ø{}",
                len(b.zmin),
                len(b.zmax),
                len(2.0 * b.rmin),
                len(2.0 * b.rmax)
            ),
            name if name.starts_with("tailstock centre") => format!(
                "{name}: tip at Z{}, quill Ø{}",
                len(b.zmin),
                len(2.0 * b.rmax)
            ),
            name => format!("{name}: Z{} to Z{}", len(b.zmin), len(b.zmax)),
        };
        let label = match f.name.as_str() {
            "chuck face" => "chuck",
            "chuck jaw" => "jaws",
            name if name.starts_with("tailstock") => "tailstock",
            _ => "workholding",
        };
        rows.push((label.to_string(), text));
    }
    if let Some(so) = report.stick_out_mm {
        rows.push(("stick-out".to_string(), format!("{} mm", len(so))));
    }
    if report.fixture.is_empty() {
        rows.push((
            "workholding".to_string(),
            "none given (latsim run --chuck, or the machine profile's [chuck]): no check against the chuck or tailstock"
                .to_string(),
        ));
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::Shape;

    fn piece(name: &str, outer: &[[f64; 2]]) -> Fixture {
        Fixture {
            name: name.to_string(),
            shapes: vec![Shape {
                outer: outer.to_vec(),
                holes: vec![],
            }],
        }
    }

    /// The chuck, hard jaws and centre read back as the `--chuck` numbers that made them
    /// (`grip=20,jaw=25,face=-80,od=200,depth=100,tail=2,quill=40`, a Φ60 blank).
    #[test]
    fn workholding_reads_back_the_chuck_numbers() {
        let mut r = Report {
            fixture: vec![
                piece(
                    "chuck face",
                    &[[-180.0, 0.0], [-80.0, 0.0], [-80.0, 100.0], [-180.0, 100.0]],
                ),
                piece(
                    "chuck jaw",
                    &[[-80.0, 30.0], [-60.0, 30.0], [-60.0, 55.0], [-80.0, 55.0]],
                ),
                piece(
                    "tailstock centre",
                    &[[2.0, 0.0], [36.64, 20.0], [186.64, 20.0], [186.64, 0.0]],
                ),
            ],
            stick_out_mm: Some(70.0),
            ..Report::default()
        };
        let rows = workholding(&r);
        let text = |label: &str| {
            rows.iter()
                .find(|(l, _)| l == label)
                .map(|(_, t)| t.clone())
                .unwrap()
        };
        assert_eq!(text("chuck"), "face at Z\u{2212}80, body Ø200 × 100 deep");
        assert_eq!(
            text("jaws"),
            "hard jaws gripping 20 mm over Ø60, 25 mm high"
        );
        assert_eq!(text("tailstock"), "tailstock centre: tip at Z2, quill Ø40");
        assert_eq!(text("stick-out"), "70 mm");
        r.fixture.clear();
        r.stick_out_mm = None;
        assert!(workholding(&r)[0].1.starts_with("none given"));
    }
}
