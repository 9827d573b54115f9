//! The report picture as an SVG string: main half section with its mirror, toolpath layer,
//! findings, axes, legend, detail views and the title block.

use std::fmt::Write as _;

use crate::layout::{self, colour, FS_TEXT, FS_TICK, FS_TITLE, MAIN};
use crate::path::{deviation_d, shapes_d, toolpath_d};
use crate::report::{PathKind, Report};
use crate::scale::{nice_step, step_decimals, ticks, View};
use crate::text::{esc, num, tick_label, truncate, width};
use crate::{block, detail};

/// Points closer than this (px) to the previous kept point are dropped.
pub(crate) const MIN_PX: f64 = 0.3;
/// Cap on toolpath points in the main view.
pub(crate) const MAIN_POINT_CAP: usize = 200_000;

/// An SVG document under construction, with px-space helpers.
pub(crate) struct Doc {
    /// The markup so far.
    pub(crate) out: String,
}

impl Doc {
    /// Append raw markup.
    pub(crate) fn raw(&mut self, s: &str) {
        self.out.push_str(s);
    }

    /// A text element; `anchor` is start, middle or end.
    pub(crate) fn text(&mut self, x: f64, y: f64, size: f64, anchor: &str, fill: &str, s: &str) {
        let _ = writeln!(
            self.out,
            r#"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}" fill="{fill}">{}</text>"#,
            num(x, 2),
            num(y, 2),
            num(size, 1),
            esc(s)
        );
    }

    /// A px-space line.
    pub(crate) fn line(&mut self, a: [f64; 2], b: [f64; 2], stroke: &str, w: f64, extra: &str) {
        let _ = writeln!(
            self.out,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{stroke}" stroke-width="{}" {extra}/>"#,
            num(a[0], 2),
            num(a[1], 2),
            num(b[0], 2),
            num(b[1], 2),
            num(w, 2)
        );
    }

    /// A px-space rectangle.
    pub(crate) fn rect(&mut self, r: [f64; 4], fill: &str, stroke: &str, w: f64) {
        let _ = writeln!(
            self.out,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{fill}" stroke="{stroke}" stroke-width="{}"/>"#,
            num(r[0], 2),
            num(r[1], 2),
            num(r[2].max(0.0), 2),
            num(r[3].max(0.0), 2),
            num(w, 2)
        );
    }

    /// Define a rectangular clip path.
    pub(crate) fn clip(&mut self, id: &str, r: [f64; 4]) {
        let _ = writeln!(
            self.out,
            r#"<clipPath id="{id}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>"#,
            num(r[0], 2),
            num(r[1], 2),
            num(r[2], 2),
            num(r[3], 2)
        );
    }

    /// A path in mm inside a view transform; widths and dashes are given in px and
    /// converted so they look the same at any scale.
    pub(crate) fn mm_path(
        &mut self,
        v: &View,
        d: &str,
        fill: &str,
        stroke: &str,
        px_w: f64,
        dash: &[f64],
    ) {
        if d.is_empty() {
            return;
        }
        let _ = write!(
            self.out,
            r#"<path d="{d}" fill="{fill}" fill-rule="evenodd" stroke="{stroke}" stroke-width="{}" stroke-linejoin="round""#,
            num(px_w / v.s, 9)
        );
        if !dash.is_empty() {
            let ds: Vec<String> = dash.iter().map(|x| num(x / v.s, 9)).collect();
            let _ = write!(self.out, r#" stroke-dasharray="{}""#, ds.join(" "));
        }
        self.out.push_str("/>\n");
    }
}

/// Width of the outline drawn around every gouge and leftover, px: it keeps a deviation
/// thinner than a pixel visible (a 0.25 mm band at 3 px/mm is otherwise lost under the
/// intended line and the toolpath).
pub(crate) const DEVIATION_EDGE_PX: f64 = 2.0;

/// Shapes and toolpath of a view, in mm under its transform: used by the main view and
/// the detail views alike. `mirror`: also draw the lighter lower half. The gouge and
/// leftover outlines go on top of the toolpath, so that no line hides them.
pub(crate) fn draw_content(
    doc: &mut Doc,
    report: &Report,
    v: &View,
    mirror: bool,
    point_cap: usize,
    toolpath_id: Option<&str>,
) -> bool {
    draw_section(doc, report, v, mirror);
    let thinned = draw_toolpath(doc, report, v, point_cap, toolpath_id);
    draw_deviation_edges(doc, report, v);
    thinned
}

/// Blank, final part, leftovers, gouges (filled and outlined) and the intended shape of
/// a view, in mm under its transform (no toolpath). `mirror`: also draw the lighter
/// lower half.
pub(crate) fn draw_shapes(doc: &mut Doc, report: &Report, v: &View, mirror: bool) {
    draw_section(doc, report, v, mirror);
    draw_deviation_edges(doc, report, v);
}

/// Blank, final part, the fills of leftovers and gouges, and the intended shape (dashed).
fn draw_section(doc: &mut Doc, report: &Report, v: &View, mirror: bool) {
    let md = MIN_PX / v.s;
    let blank = shapes_d(&report.stock.shapes, md);
    let part = shapes_d(&report.final_part, md);
    if mirror {
        let _ = writeln!(
            doc.out,
            r#"<g id="mirror" transform="{}">"#,
            v.transform(true)
        );
        doc.mm_path(v, &blank, colour::BLANK_MIRROR, "#d5d0c4", 1.0, &[]);
        doc.mm_path(v, &part, colour::PART_MIRROR, "#b9c4d3", 1.0, &[]);
        doc.raw("</g>\n");
    }
    let _ = writeln!(
        doc.out,
        r#"<g{} transform="{}">"#,
        // Ids must be unique: only the main view's section gets one.
        if mirror { r#" id="section""# } else { "" },
        v.transform(false)
    );
    doc.mm_path(v, &blank, colour::BLANK, colour::BLANK_EDGE, 1.0, &[]);
    doc.mm_path(v, &part, colour::PART, colour::PART_EDGE, 1.3, &[]);
    doc.mm_path(
        v,
        &deviation_d(&report.leftovers, md),
        colour::LEFTOVER,
        "none",
        0.0,
        &[],
    );
    doc.mm_path(
        v,
        &deviation_d(&report.gouge_shapes, md),
        colour::GOUGE,
        "none",
        0.0,
        &[],
    );
    doc.mm_path(
        v,
        &shapes_d(&report.intended, md),
        "none",
        colour::INTENDED,
        1.6,
        &[7.0, 4.0],
    );
    doc.raw("</g>\n");
}

/// The outlines of leftovers and gouges, [`DEVIATION_EDGE_PX`] wide whatever the scale,
/// in a darker shade of their fill (classes `leftover-edge` and `gouge-edge`).
fn draw_deviation_edges(doc: &mut Doc, report: &Report, v: &View) {
    if report.leftovers.is_empty() && report.gouge_shapes.is_empty() {
        return;
    }
    let md = MIN_PX / v.s;
    let _ = writeln!(
        doc.out,
        r#"<g class="deviations" transform="{}">"#,
        v.transform(false)
    );
    for (shapes, class, edge) in [
        (&report.leftovers, "leftover-edge", colour::LEFTOVER_EDGE),
        (&report.gouge_shapes, "gouge-edge", colour::GOUGE_EDGE),
    ] {
        let d = deviation_d(shapes, md);
        if d.is_empty() {
            continue;
        }
        let _ = writeln!(doc.out, r#"<g class="{class}">"#);
        doc.mm_path(v, &d, "none", edge, DEVIATION_EDGE_PX, &[]);
        doc.raw("</g>\n");
    }
    doc.raw("</g>\n");
}

/// The toolpath layer of a view (see [`draw_content`]); returns whether it was thinned.
fn draw_toolpath(
    doc: &mut Doc,
    report: &Report,
    v: &View,
    point_cap: usize,
    toolpath_id: Option<&str>,
) -> bool {
    let md = MIN_PX / v.s;
    let tp = toolpath_d(
        &report.toolpath,
        md,
        &v.mm.grow(v.mm.w().max(v.mm.h()) * 0.05),
        point_cap,
    );
    match toolpath_id {
        Some(id) => {
            let _ = writeln!(
                doc.out,
                r#"<g id="{id}" transform="{}" opacity="0.9">"#,
                v.transform(false)
            );
        }
        None => {
            let _ = writeln!(
                doc.out,
                r#"<g transform="{}" opacity="0.9">"#,
                v.transform(false)
            );
        }
    }
    doc.mm_path(v, &tp.rapid, "none", colour::RAPID, 1.1, &[5.0, 4.0]);
    doc.mm_path(v, &tp.feed, "none", colour::FEED, 1.3, &[]);
    doc.mm_path(v, &tp.thread, "none", colour::THREAD, 1.3, &[]);
    doc.raw("</g>\n");
    tp.thinned()
}

/// Grid lines, frame, tick marks and labels of a view. Returns the tick step.
pub(crate) fn axes(doc: &mut Doc, v: &View, min_px: f64, grid: bool) -> f64 {
    let (x0, y0, x1, y1) = (v.px[0], v.px[1], v.right(), v.bottom());
    // Widen the step until the widest label fits between ticks with room to spare.
    let mut step = nice_step(min_px / v.s);
    for _ in 0..4 {
        let dec = step_decimals(step);
        let widest = [v.mm.zmin, v.mm.zmax]
            .iter()
            .map(|t| width(&tick_label((t / step).round() * step, dec), FS_TICK))
            .fold(0.0, f64::max);
        if step * v.s >= widest + 14.0 {
            break;
        }
        step = nice_step((widest + 14.0) / v.s);
    }
    let dec = step_decimals(step);
    let zt = ticks(v.mm.zmin, v.mm.zmax, step);
    let rt = ticks(v.mm.rmin, v.mm.rmax, step);
    if grid {
        for &t in &zt {
            let x = v.x(t);
            doc.line([x, y0], [x, y1], colour::GRID, 1.0, "");
        }
        for &t in &rt {
            let y = v.y(t);
            doc.line([x0, y], [x1, y], colour::GRID, 1.0, "");
        }
    }
    for &t in &zt {
        let x = v.x(t);
        doc.line([x, y1], [x, y1 + 5.0], colour::INK, 1.0, "");
        let label = tick_label(t, dec);
        // A label that would run off the page is left out (its tick stays).
        let half = width(&label, FS_TICK) / 2.0;
        if x + half <= layout::W - 4.0 && x - half >= 4.0 {
            doc.text(x, y1 + 19.0, FS_TICK, "middle", colour::INK, &label);
        }
    }
    for &t in &rt {
        let y = v.y(t);
        doc.line([x0 - 5.0, y], [x0, y], colour::INK, 1.0, "");
        doc.text(
            x0 - 8.0,
            y + FS_TICK * 0.35,
            FS_TICK,
            "end",
            colour::INK,
            &tick_label(t, dec),
        );
    }
    step
}

/// The axis centre line (dash-dot) across a view, at r = 0.
pub(crate) fn centre_line(doc: &mut Doc, v: &View) {
    let y = v.y(0.0);
    if y >= v.px[1] && y <= v.bottom() {
        doc.line(
            [v.px[0], y],
            [v.right(), y],
            "#2b2f36",
            1.0,
            r#"stroke-dasharray="16 4 3 4""#,
        );
    }
}

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
    let mut doc = Doc {
        out: String::with_capacity(64 * 1024),
    };
    let _ = writeln!(
        doc.out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="DejaVu Sans">"#,
        w = layout::W,
        h = layout::H
    );
    doc.rect([0.0, 0.0, layout::W, layout::H], "#ffffff", "none", 0.0);

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

    // Main view.
    let v = View::fit(layout::main_window(report), MAIN);
    doc.raw("<defs>\n");
    doc.clip("clip-main", MAIN);
    doc.raw("</defs>\n");
    doc.rect(MAIN, "#ffffff", "none", 0.0);
    let step_px = tick_room(&v);
    axes(&mut doc, &v, step_px, true);
    doc.raw("<g clip-path=\"url(#clip-main)\">\n");
    let thinned = draw_content(&mut doc, report, &v, true, MAIN_POINT_CAP, Some("toolpath"));
    centre_line(&mut doc, &v);
    doc.raw("</g>\n");
    doc.rect(MAIN, "none", "#2b2f36", 1.2);
    doc.text(
        MAIN[0] + MAIN[2] / 2.0,
        v.bottom() + 42.0,
        FS_TEXT,
        "middle",
        colour::INK,
        "Z (mm)",
    );
    let _ = writeln!(
        doc.out,
        r#"<text x="0" y="0" font-size="{FS_TEXT}" text-anchor="middle" fill="{}" transform="translate(34 {}) rotate(-90)">X/2 (mm)</text>"#,
        colour::INK,
        num(MAIN[1] + MAIN[3] / 2.0, 2)
    );

    crate::marks::findings(&mut doc, report, &v);
    legend(&mut doc, report, thinned);
    let used = detail::details(
        &mut doc,
        report,
        &v,
        layout::RIGHT_BOTTOM - block::min_height(report),
    );
    block::title_block(&mut doc, report, used);
    doc.raw("</svg>\n");
    doc.out
}

/// The legend row(s) under the main plot; only kinds present are listed, except the
/// always-present part, blank and toolpath basics.
fn legend(doc: &mut Doc, report: &Report, thinned: bool) {
    enum Sw {
        Fill(&'static str, &'static str),
        Line(&'static str, &'static str),
        Marker,
    }
    let has = |k: PathKind| report.toolpath.iter().any(|l| l.kind == k);
    let mut items: Vec<(Sw, &str)> = vec![
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
    if !report.gouge_shapes.is_empty() || !report.gouges.is_empty() {
        items.push((Sw::Fill(colour::GOUGE, colour::GOUGE_EDGE), "gouge"));
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
    let note = thinned.then_some("toolpath thinned (not every move drawn)");
    let (x_start, x_end) = (40.0, MAIN[0] + MAIN[2]);
    let mut x = x_start;
    let mut y = layout::LEGEND_Y;
    doc.raw("<g id=\"legend\">\n");
    for (sw, label) in items {
        let w = 30.0 + width(label, FS_TEXT) + 22.0;
        if x + w > x_end && x > x_start {
            x = x_start;
            y += 26.0;
        }
        match sw {
            Sw::Fill(f, s) => doc.rect([x, y - 12.0, 22.0, 14.0], f, s, 1.0),
            Sw::Line(c, dash) => {
                let extra = if dash.is_empty() {
                    String::new()
                } else {
                    format!(r#"stroke-dasharray="{dash}""#)
                };
                doc.line([x, y - 5.0], [x + 22.0, y - 5.0], c, 2.2, &extra);
            }
            Sw::Marker => marker(doc, x + 11.0, y - 5.0, colour::CRASH),
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
    doc.raw("</g>\n");
}

/// A crash marker: a filled circle with a white cross.
pub(crate) fn marker(doc: &mut Doc, x: f64, y: f64, c: &str) {
    let _ = writeln!(
        doc.out,
        r##"<circle cx="{}" cy="{}" r="7" fill="{c}" stroke="#ffffff" stroke-width="1.2"/>"##,
        num(x, 2),
        num(y, 2)
    );
    doc.line([x - 3.5, y - 3.5], [x + 3.5, y + 3.5], "#ffffff", 1.6, "");
    doc.line([x - 3.5, y + 3.5], [x + 3.5, y - 3.5], "#ffffff", 1.6, "");
}
