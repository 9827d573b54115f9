//! The final part as a solid in the HTML page, drawn by `solid.js` with WebGL: the section
//! revolved about the axis, cut open by a quarter, the findings coloured on it, the blank a
//! ghost. The page carries only the section, thinned to a bounded number of points; the
//! script revolves it, so a million-move program's page is no bigger or slower for it.
//!
//! Data block field `solid`: `{"part", "blank", "gouges", "leftovers"}`, each rings
//! `[z, x, z, x, …]` (x a diameter, fill even-odd) as the other layers.

use std::fmt::Write as _;

use super::{rings, rings_json};
use crate::layout::colour;
use crate::report::Report;
use crate::text::esc;

/// Points of the part's section the solid is made from: with the blank's and the
/// findings', at most about 150 000 quads are drawn (`solid.js` picks the steps about
/// the axis), which a software renderer draws in a fraction of a second.
pub(crate) const PART_POINTS: usize = 3_000;
/// Points of the gouges, and of the leftovers, each.
pub(crate) const FINDING_POINTS: usize = 2_000;
/// Points of the blank's section (a ghost: its outline is enough).
pub(crate) const BLANK_POINTS: usize = 500;

/// The script drawing the solid.
pub(super) const SCRIPT: &str = include_str!("solid.js");

/// Appends the `solid` field (followed by a comma) to the data block; `md` is the drawing's
/// merge distance, the finest the section is kept at.
pub(super) fn data(out: &mut String, report: &Report, md: f64) {
    out.push_str("\"solid\":{");
    // a possible gouge (an assumed tool's) is not coloured on the solid
    let (_, certain) = crate::plot::gouges_by_certainty(report);
    let layers = [
        ("part", &report.final_part, PART_POINTS),
        ("blank", &report.stock.shapes, BLANK_POINTS),
        ("gouges", &certain, FINDING_POINTS),
        ("leftovers", &report.leftovers, FINDING_POINTS),
    ];
    for (i, (key, shapes, cap)) in layers.into_iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        let _ = write!(out, "\"{key}\":");
        rings_json(out, &rings(shapes, md, cap));
    }
    out.push_str("},");
}

/// The page's section holding the 3D view, its legend and how to use it.
pub(super) fn section(out: &mut String, report: &Report) {
    out.push_str("<section id=\"ls-solid-view\"><h2>The part in 3D</h2>\n");
    out.push_str("<noscript><p class=\"note\">The 3D view needs JavaScript.</p></noscript>\n");
    out.push_str("<div class=\"solidbox\"><canvas id=\"ls-solid\" width=\"1200\" height=\"520\" aria-label=\"the final part as a solid, cut open by a quarter\"></canvas></div>\n");
    let key = |out: &mut String, style: &str, label: &str| {
        let _ = write!(
            out,
            "<span class=\"key\"><i style=\"{style}\"></i>{}</span>",
            esc(label)
        );
    };
    out.push_str("<p class=\"legend\">");
    key(out, "background:#9eadc2", "final part");
    key(out, "background:#ccc2a8", "cut face");
    let (possible, certain) = crate::plot::gouges_by_certainty(report);
    if !certain.is_empty() {
        key(out, &format!("background:{}", colour::GOUGE), "gouge");
    }
    if !possible.is_empty() {
        key(
            out,
            "background:#ffffff;border:1px dashed #a31515",
            "possible gouge (tool size assumed): not coloured",
        );
    }
    if !report.leftovers.is_empty() {
        key(out, &format!("background:{}", colour::LEFTOVER), "leftover");
    }
    key(
        out,
        "border:1px solid #8c8576;background:#f3f1ec",
        "blank (ghost)",
    );
    out.push_str("</p>\n");
    out.push_str("<p class=\"note\" id=\"ls-solid-note\">The final section turned about the axis, the quarter toward you cut away so that the bore shows. Drag to turn it, the wheel zooms, a double click turns it back.</p>\n");
    out.push_str("</section>\n");
}
