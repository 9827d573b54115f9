//! Detail views: a zoomed, framed inset around each crash and gouge (at most three,
//! crashes first), stacked at the top of the right column.

use std::fmt::Write as _;

use crate::layout::{colour, FS_SMALL, RIGHT_TOP, RIGHT_W, RIGHT_X};
use crate::report::Report;
use crate::scale::{Bbox, View};
use crate::svg::{axes, centre_line, draw_content, marker, Doc};
use crate::text::{chars_fitting, num, truncate};

/// At most this many detail views.
const MAX_DETAILS: usize = 3;
/// Room left of an inset for its tick labels.
const LABEL_ROOM: f64 = 58.0;
/// Cap on toolpath points per inset.
const DETAIL_POINT_CAP: usize = 20_000;

struct Finding {
    title: String,
    z: f64,
    r: f64,
    half: f64,
    crash: bool,
}

fn findings(report: &Report, main: &View) -> Vec<Finding> {
    // A detail wider than a sixth of the main view shows nothing the main view doesn't.
    let max_half = (main.mm.h().min(main.mm.w()) / 6.0).max(0.05);
    let clampf = |v: f64, lo: f64| {
        if v.is_finite() {
            v.max(lo).min(max_half.max(lo))
        } else {
            lo
        }
    };
    let mut out = Vec::new();
    for c in &report.crashes {
        out.push(Finding {
            title: format!(
                "crash, line {} at Z{} X{}",
                c.line,
                num(c.z, 3),
                num(2.0 * c.r, 3)
            ),
            z: c.z,
            r: c.r,
            half: clampf(2.5 * c.area_mm2.abs().sqrt(), 1.0),
            crash: true,
        });
    }
    for g in &report.gouges {
        out.push(Finding {
            title: format!(
                "gouge, line {} at Z{} X{}, depth {} mm",
                g.line,
                num(g.z, 3),
                num(2.0 * g.r, 3),
                num(g.depth_mm, 3)
            ),
            z: g.z,
            r: g.r,
            half: clampf(
                (6.0 * g.depth_mm.abs()).max(2.5 * g.area_mm2.abs().sqrt()),
                0.2,
            ),
            crash: false,
        });
    }
    out.retain(|f| f.z.is_finite() && f.r.is_finite());
    out.truncate(MAX_DETAILS);
    out
}

/// Each inset's title, tick labels and gap, px.
const OVERHEAD: f64 = 58.0;
/// Smallest useful inset plot height.
const MIN_PLOT_H: f64 = 80.0;

/// Draw the detail views above `bottom`; returns the y below the last one (the title
/// block starts there).
pub(crate) fn details(doc: &mut Doc, report: &Report, main: &View, bottom: f64) -> f64 {
    let mut list = findings(report, main);
    // Fit into the room the title block leaves: shrink, then drop insets from the end.
    let plot_h = loop {
        if list.is_empty() {
            return RIGHT_TOP;
        }
        let h = ((bottom - RIGHT_TOP) / list.len() as f64 - OVERHEAD).min(230.0);
        if h >= MIN_PLOT_H {
            break h;
        }
        list.pop();
    };
    let mut top = RIGHT_TOP;
    doc.raw("<g id=\"details\">\n");
    for (i, f) in list.iter().enumerate() {
        let rect = [
            RIGHT_X + LABEL_ROOM,
            top + 10.0,
            RIGHT_W - LABEL_ROOM,
            plot_h,
        ];
        let title = format!("detail {}: {}", i + 1, f.title);
        let max = chars_fitting(RIGHT_W, FS_SMALL);
        doc.text(
            RIGHT_X,
            top - 4.0,
            FS_SMALL,
            "start",
            colour::INK,
            &truncate(&title, max),
        );
        let v = View::fit(
            Bbox::new(f.z - f.half, f.z + f.half, f.r - f.half, f.r + f.half),
            rect,
        );
        let id = format!("clip-detail-{i}");
        doc.raw("<defs>");
        doc.clip(&id, rect);
        doc.raw("</defs>\n");
        doc.rect(rect, "#ffffff", "none", 0.0);
        axes(doc, &v, 46.0, true);
        let _ = writeln!(doc.out, r#"<g clip-path="url(#{id})">"#);
        draw_content(doc, report, &v, false, DETAIL_POINT_CAP, None);
        centre_line(doc, &v);
        let (x, y) = (v.x(f.z), v.y(f.r));
        if f.crash {
            marker(doc, x, y, colour::CRASH);
        } else {
            let _ = writeln!(
                doc.out,
                r#"<circle cx="{}" cy="{}" r="10" fill="none" stroke="{}" stroke-width="2"/>"#,
                num(x, 2),
                num(y, 2),
                colour::GOUGE
            );
        }
        doc.raw("</g>\n");
        doc.rect(rect, "none", "#2b2f36", 1.0);
        top += plot_h + OVERHEAD;
    }
    doc.raw("</g>\n");
    top
}
