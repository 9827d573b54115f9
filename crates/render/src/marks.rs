//! Crash, rapid-scrape and gouge markers in the main view, each with a label and a leader
//! line placed where it overlaps neither the frame nor another label.

use crate::doc::{marker, Doc};
use crate::layout::{colour, FS_TEXT};
use crate::report::Report;
use crate::scale::View;
use crate::text::width;

/// At most this many labelled markers of each kind (the title block lists the rest).
const MAX_LABELS: usize = 6;

type Rect = [f64; 4];

fn overlaps(a: &Rect, b: &Rect) -> bool {
    a[0] < b[0] + b[2] && b[0] < a[0] + a[2] && a[1] < b[1] + b[3] && b[1] < a[1] + a[3]
}

/// Find a spot for a `w` × `h` label near (x, y) inside the view and clear of `placed`.
fn place(v: &View, x: f64, y: f64, w: f64, h: f64, placed: &[Rect]) -> Option<Rect> {
    const OFFS: [(f64, f64); 12] = [
        (36.0, -40.0),
        (36.0, 40.0),
        (-36.0, -40.0),
        (-36.0, 40.0),
        (60.0, -80.0),
        (60.0, 80.0),
        (-60.0, -80.0),
        (-60.0, 80.0),
        (90.0, -16.0),
        (-90.0, -16.0),
        (20.0, -120.0),
        (20.0, 120.0),
    ];
    let inner = [v.px[0] + 4.0, v.px[1] + 4.0, v.px[2] - 8.0, v.px[3] - 8.0];
    OFFS.iter().find_map(|&(dx, dy)| {
        let left = if dx >= 0.0 { x + dx } else { x + dx - w };
        let top = y + dy - h / 2.0;
        let r = [left, top, w, h];
        let inside = left >= inner[0]
            && top >= inner[1]
            && left + w <= inner[0] + inner[2]
            && top + h <= inner[1] + inner[3];
        // Keep the marker itself visible too.
        let marker_box = [x - 9.0, y - 9.0, 18.0, 18.0];
        (inside && !overlaps(&r, &marker_box) && placed.iter().all(|p| !overlaps(&r, p)))
            .then_some(r)
    })
}

/// Draw markers and labels for crashes (purple), rapid scrapes (a brown square: a rapid
/// that re-cut no deeper than the profile's `rapid_cut_tol`, a warning) and gouges (red).
pub(crate) fn findings(doc: &mut Doc, report: &Report, v: &View) {
    let mut placed: Vec<Rect> = Vec::new();
    // a possible finding (an assumed tool's) says so on its label
    let crashes = report.crashes.iter().map(|c| {
        let what = if c.assumed { "possible crash" } else { "crash" };
        (c.z, c.r, c.line, what, colour::CRASH)
    });
    let gouges = report.gouges.iter().map(|g| {
        let what = if g.assumed { "possible gouge" } else { "gouge" };
        (g.z, g.r, g.line, what, colour::GOUGE)
    });
    let scrapes = report
        .rapid_cuts
        .iter()
        .map(|c| (c.z, c.r, c.line, "scrape", colour::SCRAPE));
    let items: Vec<_> = crashes
        .take(MAX_LABELS)
        .chain(scrapes.take(MAX_LABELS))
        .chain(gouges.take(MAX_LABELS))
        .collect();
    doc.open("g", &[("id", "findings".into())]);
    // Markers first, so labels can avoid all of them.
    let mut shown = Vec::new();
    for &(z, r, line, what, c) in &items {
        let (x, y) = (v.x(z), v.y(r));
        if !(x.is_finite() && y.is_finite() && v.contains_px(x, y)) {
            continue;
        }
        match what {
            "crash" => marker(doc, x, y, c),
            "scrape" => scrape_marker(doc, x, y),
            // a possible crash: the crash colour's ring, not the filled marker
            _ => doc.circle([x, y], 8.0, "none", c, 2.0),
        }
        placed.push([x - 9.0, y - 9.0, 18.0, 18.0]);
        shown.push((x, y, line, what, c));
    }
    for (x, y, line, what, c) in shown {
        let label = format!("{what} line {line}");
        let (w, h) = (width(&label, FS_TEXT) + 10.0, FS_TEXT + 8.0);
        let Some(r) = place(v, x, y, w, h, &placed) else {
            continue;
        };
        placed.push(r);
        // Leader from the marker's rim to the nearest side of the label.
        let lx = if r[0] > x { r[0] } else { r[0] + r[2] };
        let ly = r[1] + r[3] / 2.0;
        let (dx, dy) = (lx - x, ly - y);
        let len = (dx * dx + dy * dy).sqrt().max(1e-9);
        doc.line(
            [x + dx / len * 9.0, y + dy / len * 9.0],
            [lx, ly],
            c,
            1.3,
            "",
        );
        doc.label_box(r, 3.0, 0.9, c, 1.0);
        doc.text(r[0] + 5.0, r[1] + h - 7.0, FS_TEXT, "start", c, &label);
    }
    doc.close();
}

/// The rapid-scrape marker: a hollow square (a crash is a filled, crossed circle).
pub(crate) fn scrape_marker(doc: &mut Doc, x: f64, y: f64) {
    doc.rect([x - 6.0, y - 6.0, 12.0, 12.0], "none", colour::SCRAPE, 2.0);
}
