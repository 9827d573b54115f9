//! What a view shows, in mm under its transform: the half section, the toolpath, the
//! deviation outlines, and the axes and centre line around it. Used by the main view
//! ([`crate::svg`]) and the detail views ([`crate::detail`]) alike.

use crate::doc::Doc;
use crate::layout::{self, colour, FS_TICK};
use crate::path::{deviation_d, shapes_d, toolpath_d, MIN_PX};
use crate::report::{Report, Shape};
use crate::scale::{nice_step, step_decimals, ticks, View};
use crate::text::{tick_label, width};

/// Width of the outline drawn around every gouge and leftover, px: it keeps a deviation
/// thinner than a pixel visible (a 0.25 mm band at 3 px/mm is otherwise lost under the
/// intended line and the toolpath).
pub(crate) const DEVIATION_EDGE_PX: f64 = 2.0;

/// How opaque the toolpath's lines are: the part shows through where they run over it.
const TOOLPATH_OPACITY: f64 = 0.9;

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
    crate::fixture::draw_crash_tools(doc, report, v);
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
    crate::fixture::draw_fixture(doc, report, v, mirror);
    if mirror {
        doc.open(
            "g",
            &[("id", "mirror".into()), ("transform", v.transform(true))],
        );
        doc.mm_path(v, &blank, colour::BLANK_MIRROR, "#d5d0c4", 1.0, &[]);
        doc.mm_path(v, &part, colour::PART_MIRROR, "#b9c4d3", 1.0, &[]);
        doc.close();
    }
    // Ids must be unique: only the main view's section gets one.
    let transform = ("transform", v.transform(false));
    if mirror {
        doc.open("g", &[("id", "section".into()), transform]);
    } else {
        doc.open("g", &[transform]);
    }
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
    let (possible, certain) = gouges_by_certainty(report);
    doc.mm_path(
        v,
        &deviation_d(&certain, md),
        colour::GOUGE,
        "none",
        0.0,
        &[],
    );
    if !possible.is_empty() {
        let id = format!("possible-hatch-{:.0}-{:.0}", v.px[0], v.px[1]);
        hatch_defs(doc, &id, v.s);
        doc.mm_path(
            v,
            &deviation_d(&possible, md),
            &format!("url(#{id})"),
            "none",
            0.0,
            &[],
        );
    }
    doc.mm_path(
        v,
        &shapes_d(&report.intended, md),
        "none",
        colour::INTENDED,
        1.6,
        &[7.0, 4.0],
    );
    doc.close();
}

/// The outlines of leftovers and gouges, [`DEVIATION_EDGE_PX`] wide whatever the scale,
/// in a darker shade of their fill (classes `leftover-edge` and `gouge-edge`).
fn draw_deviation_edges(doc: &mut Doc, report: &Report, v: &View) {
    if report.leftovers.is_empty() && report.gouge_shapes.is_empty() {
        return;
    }
    let md = MIN_PX / v.s;
    doc.open(
        "g",
        &[
            ("class", "deviations".into()),
            ("transform", v.transform(false)),
        ],
    );
    for (shapes, class, edge) in [
        (&report.leftovers, "leftover-edge", colour::LEFTOVER_EDGE),
        (&report.gouge_shapes, "gouge-edge", colour::GOUGE_EDGE),
    ] {
        let d = deviation_d(shapes, md);
        if d.is_empty() {
            continue;
        }
        doc.open("g", &[("class", class.into())]);
        doc.mm_path(v, &d, "none", edge, DEVIATION_EDGE_PX, &[]);
        doc.close();
    }
    doc.close();
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
    let transform = ("transform", v.transform(false));
    match toolpath_id {
        Some(id) => doc.open("g", &[("id", id.into()), transform]),
        None => doc.open("g", &[transform]),
    }
    doc.mm_line(
        v,
        &tp.rapid,
        colour::RAPID,
        1.1,
        &[5.0, 4.0],
        TOOLPATH_OPACITY,
    );
    doc.mm_line(v, &tp.feed, colour::FEED, 1.3, &[], TOOLPATH_OPACITY);
    doc.mm_line(v, &tp.thread, colour::THREAD, 1.3, &[], TOOLPATH_OPACITY);
    doc.close();
    tp.thinned()
}

/// Grid lines, tick marks and labels of a view. Returns the tick step.
pub(crate) fn axes(doc: &mut Doc, v: &View, min_px: f64, grid: bool) -> f64 {
    let step = tick_step(v, min_px);
    if grid {
        grid_lines(doc, v, step);
    }
    tick_marks(doc, v, step);
    step
}

/// The tick step (mm) of a view: ticks at least `min_px` apart, widened until the widest
/// label fits between them with room to spare.
pub(crate) fn tick_step(v: &View, min_px: f64) -> f64 {
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
    step
}

/// The grid lines inside a view's frame, one per tick.
pub(crate) fn grid_lines(doc: &mut Doc, v: &View, step: f64) {
    let (x0, y0, x1, y1) = (v.px[0], v.px[1], v.right(), v.bottom());
    for t in ticks(v.mm.zmin, v.mm.zmax, step) {
        let x = v.x(t);
        doc.line([x, y0], [x, y1], colour::GRID, 1.0, "");
    }
    for t in ticks(v.mm.rmin, v.mm.rmax, step) {
        let y = v.y(t);
        doc.line([x0, y], [x1, y], colour::GRID, 1.0, "");
    }
}

/// The tick marks and labels outside a view's frame, below it (Z) and left of it (r).
pub(crate) fn tick_marks(doc: &mut Doc, v: &View, step: f64) {
    let (x0, y1) = (v.px[0], v.bottom());
    let dec = step_decimals(step);
    for t in ticks(v.mm.zmin, v.mm.zmax, step) {
        let x = v.x(t);
        doc.line([x, y1], [x, y1 + 5.0], colour::INK, 1.0, "");
        let label = tick_label(t, dec);
        // A label that would run off the page is left out (its tick stays).
        let half = width(&label, FS_TICK) / 2.0;
        if x + half <= layout::W - 4.0 && x - half >= 4.0 {
            doc.text(x, y1 + 19.0, FS_TICK, "middle", colour::INK, &label);
        }
    }
    for t in ticks(v.mm.rmin, v.mm.rmax, step) {
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
}

/// The axis centre line (dash-dot) across a view, at r = 0.
pub(crate) fn centre_line(doc: &mut Doc, v: &View) {
    let y = v.y(0.0);
    if y >= v.px[1] && y <= v.bottom() {
        doc.line([v.px[0], y], [v.right(), y], "#2b2f36", 1.0, "16 4 3 4");
    }
}

/// The pattern `id` of a possible finding (spec/simulation.md, "Findings from assumed
/// tools"): the gouge colour in diagonal lines 6 px apart on white, drawn hatched rather
/// than red. `px_per_mm`: the scale of the view whose mm paths it fills.
pub(crate) fn hatch_defs(doc: &mut Doc, id: &str, px_per_mm: f64) {
    let step = crate::text::num(HATCH_PX / px_per_mm, 6);
    doc.open("defs", &[]);
    doc.open(
        "pattern",
        &[
            ("id", id.into()),
            ("patternUnits", "userSpaceOnUse".into()),
            ("width", step.clone()),
            ("height", step.clone()),
            ("patternTransform", "rotate(45)".into()),
        ],
    );
    doc.leaf(
        "rect",
        &[
            ("width", step.clone()),
            ("height", step.clone()),
            ("fill", "#ffffff".into()),
        ],
    );
    doc.leaf(
        "rect",
        &[
            ("width", crate::text::num(HATCH_PX / 2.5 / px_per_mm, 6)),
            ("height", step),
            ("fill", colour::GOUGE.into()),
        ],
    );
    doc.close();
    doc.close();
}

/// Spacing of a possible finding's hatch lines, px.
const HATCH_PX: f64 = 6.0;

/// The gouge shapes split into (possible, certain): a shape is possible when the gouge at
/// its index is `assumed`.
pub(crate) fn gouges_by_certainty(report: &Report) -> (Vec<Shape>, Vec<Shape>) {
    let (possible, certain): (Vec<_>, Vec<_>) = report
        .gouge_shapes
        .iter()
        .enumerate()
        .partition(|(i, _)| report.gouges.get(*i).is_some_and(|g| g.assumed));
    let shapes = |v: Vec<(usize, &Shape)>| v.into_iter().map(|(_, s)| s.clone()).collect();
    (shapes(possible), shapes(certain))
}
