//! The report picture as an SVG string: main half section with its mirror, toolpath layer,
//! findings, axes, legend, detail views and the title block.

use crate::doc::{marker, Doc};
use crate::layout::{self, colour, FS_TEXT, FS_TICK, FS_TITLE, MAIN};
use crate::plot::{centre_line, draw_content, grid_lines, tick_marks, tick_step};
use crate::report::{PathKind, Report};
use crate::scale::View;
use crate::text::{num, tick_label, truncate, width};
use crate::{block, detail, marks};

/// Cap on toolpath points in the main view.
pub(crate) const MAIN_POINT_CAP: usize = 200_000;

/// Minimum px between Z ticks so the widest label fits with room to spare.
fn tick_room(v: &View) -> f64 {
    let longest = [v.mm.zmin, v.mm.zmax, v.mm.rmin, v.mm.rmax]
        .iter()
        .map(|t| width(&tick_label(t.round(), 0), FS_TICK))
        .fold(0.0, f64::max);
    (longest + 28.0).max(64.0)
}

/// The full report picture.
pub(crate) fn svg(report: &Report) -> String {
    let mut doc = Doc::new(layout::W, layout::H, "DejaVu Sans");
    doc.rect([0.0, 0.0, layout::W, layout::H], "#ffffff", "none", 0.0);

    // Main view: drawn unclipped, then the page painted white around its frame, then what
    // lies outside the frame (the title, the ticks).
    let v = View::fit(layout::main_window(report), MAIN);
    doc.rect(MAIN, "#ffffff", "none", 0.0);
    let step = tick_step(&v, tick_room(&v));
    grid_lines(&mut doc, &v, step);
    let thinned = draw_content(&mut doc, report, &v, true, MAIN_POINT_CAP, Some("toolpath"));
    centre_line(&mut doc, &v);
    crate::fixture::label_fixture(&mut doc, report, &v);
    doc.matte(MAIN, [layout::W, layout::H]);
    tick_marks(&mut doc, &v, step);

    // Title line.
    let mut title = report.program.clone();
    let stem = report
        .program
        .rsplit_once('.')
        .map_or(report.program.as_str(), |(s, _)| s);
    if !report.title.is_empty() && report.title != stem && report.title != report.program {
        title = format!("{title} ({})", report.title);
    }
    if !report.stock.description.is_empty() {
        title = format!("{title} — {}", report.stock.description);
    }
    if title.is_empty() {
        title = "latsim report".to_string();
    }
    let max_chars = crate::text::chars_fitting(MAIN[2], FS_TITLE);
    doc.text(
        MAIN[0],
        MAIN[1] - 16.0,
        FS_TITLE,
        "start",
        colour::INK,
        &truncate(&title, max_chars),
    );

    doc.rect(MAIN, "none", "#2b2f36", 1.2);
    doc.text(
        MAIN[0] + MAIN[2] / 2.0,
        v.bottom() + 42.0,
        FS_TEXT,
        "middle",
        colour::INK,
        "Z (mm)",
    );
    doc.text_el(
        &[
            ("x", "0".into()),
            ("y", "0".into()),
            ("font-size", num(FS_TEXT, 1)),
            ("text-anchor", "middle".into()),
            ("fill", colour::INK.into()),
            (
                "transform",
                format!(
                    "translate(34 {}) rotate(-90)",
                    num(MAIN[1] + MAIN[3] / 2.0, 2)
                ),
            ),
        ],
        "X/2 (mm)",
    );

    marks::findings(&mut doc, report, &v);
    legend(&mut doc, report, thinned);
    let used = detail::details(
        &mut doc,
        report,
        &v,
        layout::RIGHT_BOTTOM - block::min_height(report),
    );
    block::title_block(&mut doc, report, used);
    doc.finish()
}

/// The legend row(s) under the main plot; only kinds present are listed, except the
/// always-present part, blank and toolpath basics.
fn legend(doc: &mut Doc, report: &Report, thinned: bool) {
    let items = legend_items(report);
    let note = thinned.then_some("toolpath thinned (not every move drawn)");
    let (x_start, x_end) = (40.0, MAIN[0] + MAIN[2]);
    let mut x = x_start;
    let mut y = layout::LEGEND_Y;
    doc.open("g", &[("id", "legend".into())]);
    for (sw, label) in items {
        let w = 30.0 + width(label, FS_TEXT) + 22.0;
        if x + w > x_end && x > x_start {
            x = x_start;
            y += 26.0;
        }
        match sw {
            Sw::Fill(f, s) => doc.rect([x, y - 12.0, 22.0, 14.0], f, s, 1.0),
            Sw::Line(c, dash) => doc.line([x, y - 5.0], [x + 22.0, y - 5.0], c, 2.2, dash),
            Sw::Marker => marker(doc, x + 11.0, y - 5.0, colour::CRASH),
            Sw::Scrape => crate::marks::scrape_marker(doc, x + 11.0, y - 5.0),
            Sw::Hatch => {
                crate::plot::hatch_defs(doc, "possible-hatch-legend", 1.0);
                doc.rect(
                    [x, y - 12.0, 22.0, 14.0],
                    "url(#possible-hatch-legend)",
                    colour::GOUGE_EDGE,
                    1.0,
                );
            }
        }
        doc.text(x + 30.0, y, FS_TEXT, "start", colour::INK, label);
        x += w;
    }
    if let Some(n) = note {
        let w = width(n, FS_TEXT);
        if x + w > x_end && x > x_start {
            x = x_start;
            y += 26.0;
        }
        doc.text(x, y, FS_TEXT, "start", colour::BAD, n);
    }
    doc.close();
}

/// A legend entry's swatch.
enum Sw {
    Fill(&'static str, &'static str),
    Line(&'static str, &'static str),
    Marker,
    Scrape,
    Hatch,
}

/// The legend's entries: what this picture shows.
fn legend_items(report: &Report) -> Vec<(Sw, &'static str)> {
    let has = |k: PathKind| report.toolpath.iter().any(|l| l.kind == k);
    let mut items: Vec<(Sw, &'static str)> = vec![
        (Sw::Fill(colour::PART, colour::PART_EDGE), "final part"),
        (
            Sw::Fill(colour::BLANK, colour::BLANK_EDGE),
            "blank (removed)",
        ),
    ];
    if !report.intended.is_empty() {
        items.push((Sw::Line(colour::INTENDED, "7 4"), "intended (dashed)"));
    }
    items.push((Sw::Line(colour::FEED, ""), "feed"));
    items.push((Sw::Line(colour::RAPID, "5 4"), "rapid (dashed)"));
    if has(PathKind::Thread) {
        items.push((Sw::Line(colour::THREAD, ""), "thread"));
    }
    let certain = report.gouges.iter().any(|g| !g.assumed)
        || (report.gouges.is_empty() && !report.gouge_shapes.is_empty());
    if certain {
        items.push((Sw::Fill(colour::GOUGE, colour::GOUGE_EDGE), "gouge"));
    }
    if report.gouges.iter().any(|g| g.assumed) || report.crashes.iter().any(|c| c.assumed) {
        items.push((
            Sw::Hatch,
            "possible (tool size assumed: not in the verdict)",
        ));
    }
    if !report.leftovers.is_empty() {
        items.push((
            Sw::Fill(colour::LEFTOVER, colour::LEFTOVER_EDGE),
            "leftover",
        ));
    }
    if !report.crashes.is_empty() {
        items.push((Sw::Marker, "crash"));
    }
    if report.crashes.iter().any(|c| !c.tool.is_empty()) {
        items.push((Sw::Line(colour::CRASH, ""), "tool at crash"));
    }
    if !report.fixture.is_empty() {
        items.push((
            Sw::Fill(colour::FIXTURE, colour::FIXTURE_EDGE),
            "chuck, jaws, tailstock",
        ));
    }
    if !report.rapid_cuts.is_empty() {
        items.push((Sw::Scrape, "rapid scrape"));
    }
    items
}
