//! The diff picture: the old and the new half section overlaid in the main view (the new
//! part filled, the old part's edge dashed over it), material the new part lost red and
//! material it gained green, each region numbered (`L1`, `G1`); the right column gives the
//! verdict, a zoomed inset of the largest regions with their lines, the cycle and tool
//! times and the findings that appeared or went away.

use super::{DiffRegion, DiffReport};
use crate::doc::Doc;
use crate::layout::{self, colour, FS_SMALL, FS_TEXT, FS_TITLE, FS_VERDICT, MAIN};
use crate::path::MIN_PX;
use crate::path::{deviation_d, shapes_d};
use crate::plot::{axes, centre_line, grid_lines, tick_marks, tick_step, DEVIATION_EDGE_PX};
use crate::scale::{Bbox, View};
use crate::text::{chars_fitting, duration, num, quantity, truncate, width, wrap};

/// Material the new part lost: red like a gouge.
const LOST: &str = "#d62728";
/// Its outline.
const LOST_EDGE: &str = "#a31515";
/// Material the new part gained: green.
const GAINED: &str = "#2ca02c";
/// Its outline.
const GAINED_EDGE: &str = "#17661a";
/// The old part's fill, under the new one: what shows of it is what the new part lost.
const OLD_FILL: &str = "#e9e4d8";
/// The old part's edge, dashed over everything.
const OLD_EDGE: &str = "#2b2f36";
/// Most regions numbered in the main view (the JSON lists them all).
const MAX_MARKS: usize = 12;
/// Most zoomed insets in the right column.
const MAX_INSETS: usize = 2;
/// Room left of an inset for its tick labels.
const LABEL_ROOM: f64 = 58.0;
/// Height of an inset's plot, px.
const INSET_H: f64 = 230.0;
/// Line height of the right column's text, px.
const LINE_H: f64 = 18.0;

/// The picture as an SVG document.
pub(super) fn svg(d: &DiffReport) -> String {
    let mut doc = Doc::new(layout::W, layout::H, "DejaVu Sans");
    doc.rect([0.0, 0.0, layout::W, layout::H], "#ffffff", "none", 0.0);
    // the main view drawn unclipped, then the page painted white around its frame (as in
    // the run's picture, `crate::svg`), then the title and the ticks outside the frame
    let v = main_view(d);
    doc.rect(MAIN, "#ffffff", "none", 0.0);
    let step = tick_step(&v, 64.0);
    grid_lines(&mut doc, &v, step);
    layers(&mut doc, d, &v, Some("diff"));
    centre_line(&mut doc, &v);
    marks(&mut doc, d, &v);
    doc.matte(MAIN, [layout::W, layout::H]);
    tick_marks(&mut doc, &v, step);
    let title = format!("latsim diff: {} → {}", d.old, d.new);
    doc.text(
        MAIN[0],
        MAIN[1] - 16.0,
        FS_TITLE,
        "start",
        colour::INK,
        &truncate(&title, chars_fitting(MAIN[2], FS_TITLE)),
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
    legend(&mut doc, d);
    let top = verdict(&mut doc, d);
    let top = insets(&mut doc, d, &v, top);
    summary(&mut doc, d, top);
    doc.finish()
}

/// The main view: both parts fitted, the axis kept at the bottom (a wide part's window is
/// widened upward, not below the axis, where nothing is drawn).
fn main_view(d: &DiffReport) -> View {
    let data = window(d);
    let mut v = View::fit(data, MAIN);
    let up = data.rmin - v.mm.rmin;
    if up > 0.0 {
        v.mm.rmin += up;
        v.mm.rmax += up;
    }
    v
}

/// Both parts' upper half with a margin (the differences are in the section: no mirror).
fn window(d: &DiffReport) -> Bbox {
    let b = Bbox::of_shapes(&d.old_part).union(&Bbox::of_shapes(&d.new_part));
    if b.is_empty() {
        return Bbox::new(-10.0, 10.0, 0.0, 10.0);
    }
    let b = Bbox::new(b.zmin, b.zmax, b.rmin.min(0.0), b.rmax);
    b.grow(0.04 * b.w().max(b.h()).max(1.0))
}

/// The regions in the order they are numbered: lost (`L1`, …), then gained (`G1`, …).
fn numbered(d: &DiffReport) -> impl Iterator<Item = (String, &DiffRegion, bool)> {
    let lost = d.lost.iter().enumerate();
    let gained = d.gained.iter().enumerate();
    lost.map(|(i, r)| (format!("L{}", i + 1), r, true))
        .chain(gained.map(|(i, r)| (format!("G{}", i + 1), r, false)))
}

/// The old part, the new part, the regions and the old part's dashed edge, in mm.
fn layers(doc: &mut Doc, d: &DiffReport, v: &View, id: Option<&str>) {
    let md = MIN_PX / v.s;
    let lost: Vec<_> = d.lost.iter().map(|r| r.shape.clone()).collect();
    let gained: Vec<_> = d.gained.iter().map(|r| r.shape.clone()).collect();
    let transform = ("transform", v.transform(false));
    match id {
        Some(id) => doc.open("g", &[("id", id.into()), transform]),
        None => doc.open("g", &[transform]),
    }
    doc.mm_path(v, &shapes_d(&d.old_part, md), OLD_FILL, "none", 0.0, &[]);
    doc.mm_path(
        v,
        &shapes_d(&d.new_part, md),
        colour::PART,
        colour::PART_EDGE,
        1.3,
        &[],
    );
    for (shapes, fill, edge, class) in [
        (&lost, LOST, LOST_EDGE, "lost"),
        (&gained, GAINED, GAINED_EDGE, "gained"),
    ] {
        let path = deviation_d(shapes, md);
        doc.open("g", &[("class", class.into())]);
        doc.mm_path(v, &path, fill, edge, DEVIATION_EDGE_PX, &[]);
        doc.close();
    }
    doc.mm_path(
        v,
        &shapes_d(&d.old_part, md),
        "none",
        OLD_EDGE,
        1.2,
        &[6.0, 4.0],
    );
    doc.close();
}

/// A ring and a label at the deepest point of the first regions.
fn marks(doc: &mut Doc, d: &DiffReport, v: &View) {
    let mut placed: Vec<[f64; 4]> = vec![];
    for (label, r, lost) in numbered(d).take(MAX_MARKS) {
        let (x, y) = (v.x(r.z), v.y(r.r));
        let c = if lost { LOST_EDGE } else { GAINED_EDGE };
        doc.circle([x, y], 11.0, "none", c, 2.0);
        let w = width(&label, FS_TEXT) + 10.0;
        // up and to the right, stepping down past labels already placed
        let mut bx = [x + 14.0, y - 34.0, w, 20.0];
        while placed.iter().any(|p| overlap(p, &bx)) {
            bx[1] += 22.0;
        }
        placed.push(bx);
        doc.line([x + 8.0, y - 8.0], [bx[0], bx[1] + 10.0], c, 1.2, "");
        doc.label_box(bx, 3.0, 0.9, c, 1.2);
        doc.text(bx[0] + 5.0, bx[1] + 15.0, FS_TEXT, "start", c, &label);
    }
}

fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[0] + b[2] && b[0] < a[0] + a[2] && a[1] < b[1] + b[3] && b[1] < a[1] + a[3]
}

/// The legend row under the main view.
fn legend(doc: &mut Doc, d: &DiffReport) {
    let mut items = vec![
        (
            colour::PART,
            colour::PART_EDGE,
            "",
            format!("new part ({})", d.new),
        ),
        (
            "none",
            OLD_EDGE,
            "6 4",
            format!("old part edge ({})", d.old),
        ),
    ];
    if !d.lost.is_empty() {
        items.push((LOST, LOST_EDGE, "", "lost by the new part".into()));
    }
    if !d.gained.is_empty() {
        items.push((GAINED, GAINED_EDGE, "", "gained by the new part".into()));
    }
    let (mut x, mut y) = (40.0, layout::LEGEND_Y);
    let max = chars_fitting(360.0, FS_TEXT);
    doc.open("g", &[("id", "legend".into())]);
    for (fill, edge, dash, label) in items {
        let label = truncate(&label, max);
        let w = 30.0 + width(&label, FS_TEXT) + 22.0;
        if x + w > MAIN[0] + MAIN[2] && x > 40.0 {
            x = 40.0;
            y += 26.0;
        }
        if dash.is_empty() {
            doc.rect([x, y - 12.0, 22.0, 14.0], fill, edge, 1.5);
        } else {
            doc.line([x, y - 5.0], [x + 22.0, y - 5.0], edge, 1.6, dash);
        }
        doc.text(x + 30.0, y, FS_TEXT, "start", colour::INK, &label);
        x += w;
    }
    doc.close();
}

/// The verdict and the areas at the top of the right column; returns the next top.
fn verdict(doc: &mut Doc, d: &DiffReport) -> f64 {
    let (text, fill) = if d.differs() {
        ("PART DIFFERS".to_string(), colour::BAD)
    } else {
        (
            format!("SAME PART (within {} mm)", num(d.tolerance_mm, 4)),
            colour::OK,
        )
    };
    let x = layout::RIGHT_X;
    let top = layout::RIGHT_TOP;
    doc.text(x, top - 16.0, FS_VERDICT, "start", fill, &text);
    let areas = format!(
        "lost {} mm² in {}, gained {} mm² in {}",
        quantity(d.lost_area()),
        regions(d.lost.len()),
        quantity(d.gained_area()),
        regions(d.gained.len())
    );
    doc.text(x, top + 4.0, FS_SMALL, "start", colour::INK, &areas);
    top + 34.0
}

fn regions(n: usize) -> String {
    match n {
        1 => "1 region".into(),
        n => format!("{n} regions"),
    }
}

/// Zoomed insets of the largest regions, each titled with its numbers and lines; a region
/// wider or taller than a sixth of the main view shows there as it is (no inset).
fn insets(doc: &mut Doc, d: &DiffReport, main: &View, mut top: f64) -> f64 {
    let big = main.mm.w().max(main.mm.h()) / 6.0;
    let mut list: Vec<(String, &DiffRegion, bool)> = numbered(d)
        .filter(|(_, r, _)| (r.hi[0] - r.lo[0]).max(r.hi[1] - r.lo[1]) < big)
        .collect();
    list.sort_by(|a, b| b.1.area_mm2.total_cmp(&a.1.area_mm2));
    let max = chars_fitting(layout::RIGHT_W, FS_SMALL);
    for (i, (label, r, lost)) in list.into_iter().take(MAX_INSETS).enumerate() {
        let title = wrap(&r.describe(&label, lost), max, 2);
        for (k, t) in title.iter().enumerate() {
            doc.text(
                layout::RIGHT_X,
                top + k as f64 * LINE_H,
                FS_SMALL,
                "start",
                colour::INK,
                t,
            );
        }
        let rect = [
            layout::RIGHT_X + LABEL_ROOM,
            top + title.len() as f64 * LINE_H - 6.0,
            layout::RIGHT_W - LABEL_ROOM,
            INSET_H,
        ];
        let v = View::fit(inset_window(r), rect);
        let id = format!("clip-diff-{i}");
        doc.clip(&id, rect);
        doc.rect(rect, "#ffffff", "none", 0.0);
        axes(doc, &v, 46.0, true);
        doc.open("g", &[("clip-path", format!("url(#{id})"))]);
        layers(doc, d, &v, None);
        let c = if lost { LOST_EDGE } else { GAINED_EDGE };
        doc.circle([v.x(r.z), v.y(r.r)], 10.0, "none", c, 2.0);
        doc.close();
        doc.rect(rect, "none", "#2b2f36", 1.0);
        top = rect[1] + INSET_H + 40.0;
    }
    top
}

/// An inset's window: the region's box with room around it to see the surfaces it lies
/// between (a 0.2 mm step shows a few mm of its shoulder).
fn inset_window(r: &DiffRegion) -> Bbox {
    let (w, h) = (r.hi[0] - r.lo[0], r.hi[1] - r.lo[1]);
    let m = 0.4 * w.max(h) + (4.0 * r.depth_mm).max(0.2);
    Bbox::new(r.lo[0], r.hi[0], r.lo[1], r.hi[1]).grow(m)
}

/// The times and the findings that changed, as far as the column has room.
fn summary(doc: &mut Doc, d: &DiffReport, top: f64) {
    let [old, new] = d.cycle_time_s;
    // the change in tenths of a second, never `−0`
    let change = ((new - old) * 10.0).round() / 10.0;
    let mut rows: Vec<(String, &str)> = vec![(
        format!(
            "cycle time {} → {} ({}{} s)",
            duration(old),
            duration(new),
            if change >= 0.0 { "+" } else { "−" },
            num(change.abs(), 1)
        ),
        colour::INK,
    )];
    for t in d.changed_tools(0.05) {
        let s = |v: Option<f64>| v.map_or("—".to_string(), |v| format!("{} s", num(v, 1)));
        rows.push((
            format!("{} {} → {}", t.tool, s(t.old_s), s(t.new_s)),
            colour::MUTED,
        ));
    }
    rows.push((
        format!(
            "findings: {} appeared, {} gone (runs: old {}, new {})",
            d.appeared.len(),
            d.gone.len(),
            crate::verdict_word(d.verdicts[0]),
            crate::verdict_word(d.verdicts[1])
        ),
        colour::INK,
    ));
    let finding = |sign: &str, f: &super::DiffFinding| {
        format!(
            "{sign} {} line {} {}: {}",
            f.kind, f.line, f.code, f.message
        )
    };
    rows.extend(d.appeared.iter().map(|f| (finding("+", f), colour::BAD)));
    rows.extend(d.gone.iter().map(|f| (finding("−", f), colour::OK)));
    for (label, r, lost) in numbered(d) {
        rows.push((r.describe(&label, lost), colour::MUTED));
    }
    let max = chars_fitting(layout::RIGHT_W, FS_SMALL);
    let room = ((layout::RIGHT_BOTTOM - top) / LINE_H).floor().max(0.0) as usize;
    let cut = rows.len() > room;
    let shown = if cut {
        room.saturating_sub(1)
    } else {
        rows.len()
    };
    let mut y = top;
    for (text, fill) in rows.iter().take(shown) {
        doc.text(
            layout::RIGHT_X,
            y,
            FS_SMALL,
            "start",
            fill,
            &truncate(text, max),
        );
        y += LINE_H;
    }
    if cut {
        let more = format!(
            "… {} more lines in the JSON and HTML reports",
            rows.len() - shown
        );
        doc.text(layout::RIGHT_X, y, FS_SMALL, "start", colour::MUTED, &more);
    }
}
