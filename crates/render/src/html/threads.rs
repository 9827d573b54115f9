//! The threads table of the HTML page: each thread as programmed and as cut (depth, pitch
//! diameter, flank angle), the figures a machinist checks with wires or a gauge.

use std::fmt::Write as _;

use super::{extra, list_head, pos, print_more};
use crate::report::ThreadCheck;
use crate::text::esc;

/// A cell for an optional figure: "—" where it was not measurable.
fn cell(v: Option<f64>, f: impl Fn(f64) -> String) -> String {
    v.map_or_else(|| "—".to_string(), f)
}

/// A depth error to the µm, signed ("0.000" when it rounds to nothing, never "-0.000").
fn signed(e: f64) -> String {
    let um = (e * 1000.0).round();
    if um == 0.0 {
        "0.000".to_string()
    } else {
        esc(&format!("{:+.3}", um / 1000.0))
    }
}

/// The threads section; nothing when the program cuts no thread.
pub(super) fn threads_table(out: &mut String, list: &[ThreadCheck]) {
    if list.is_empty() {
        return;
    }
    list_head(
        out,
        "ls-threads",
        "Threads (as cut in the final section)",
        list.len(),
    );
    out.push_str("<table class=\"list thread\"><thead><tr><th>line</th><th>side</th><th>lead (mm)</th><th>passes</th><th>X programmed</th><th>X expected</th><th>X reached</th><th>depth error (mm)</th><th>pitch Ø (mm)</th><th>flank angle (°)</th></tr></thead><tbody>\n");
    for (i, t) in list.iter().enumerate() {
        let _ = writeln!(
            out,
            "<tr data-line=\"{}\"{}><td class=\"n\">{}</td><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            t.line,
            extra(i),
            t.line,
            if t.inside { "ID" } else { "OD" },
            lead_cell(t),
            t.pass_depths_mm.len(),
            pos(t.x_mm),
            cell(t.expected_x_mm, pos),
            cell(t.achieved_x_mm, pos),
            cell(t.depth_error_mm, signed),
            cell(t.pitch_diameter_mm, pos),
            cell(t.included_angle_deg, |a| format!("{a:.2}")),
        );
    }
    out.push_str("</tbody></table>\n");
    print_more(out, list.len());
}

/// The lead, with the number of starts of a multi-start thread (`3 (2 starts)`).
fn lead_cell(t: &ThreadCheck) -> String {
    if t.starts > 1 {
        format!("{} ({} starts)", pos(t.lead_mm), t.starts)
    } else {
        pos(t.lead_mm)
    }
}
