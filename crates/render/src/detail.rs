//! Detail views: a zoomed, framed inset around each crash, gouge and G75.1 groove, then
//! one for the largest leftover, then one for each thread (at most three; crashes first,
//! then gouges, grooves, the leftover and threads — findings win when room is short),
//! stacked at the top of the right column.
//!
//! The leftover view is centred on the leftover's thickest place (the report's
//! [`crate::LeftoverSpot`], measured by the simulator) with a window about ten times its thickness, so that a thin
//! roughing allowance shows as a band; its title gives the thickness (the report's
//! `max_undercut_mm` when there is a single leftover region) and the Z range shown.
//!
//! A groove view is zoomed on the groove's box with a margin and shows the blank, the
//! final part, the leftover and gouge overlays and the groove ring dashed (no
//! toolpath), with its principal corners labelled `P1 Z30.00 Φ50.00` (see
//! [`crate::groove`] for the corners and the labels' places; the deviation in the title
//! is the report's [`Groove::deviation_mm`]).
//!
//! A thread view shows four leads around the middle of the deepest pass (the whole thread
//! when it is shorter), from below the root to above the crest, so that the teeth as cut
//! can be read: the diameter the thread should reach dashed, the pitch diameter dotted,
//! each labelled, and what the simulator measured in the title.

use crate::doc::{marker, Doc};
use crate::groove;
use crate::layout::{colour, FS_SMALL, RIGHT_TOP, RIGHT_W, RIGHT_X};
use crate::path::shapes_d;
use crate::plot::{axes, centre_line, draw_content, draw_shapes, MIN_PX};
use crate::report::{Groove, Report, Shape, ThreadCheck};
use crate::scale::{Bbox, View};
use crate::text::{chars_fitting, num, truncate, width};

/// At most this many detail views.
const MAX_DETAILS: usize = 3;
/// Room left of an inset for its tick labels.
const LABEL_ROOM: f64 = 58.0;
/// Cap on toolpath points per inset.
const DETAIL_POINT_CAP: usize = 20_000;

/// Width of an inset's plot.
const PLOT_W: f64 = RIGHT_W - LABEL_ROOM;
/// Corner label font size, px.
const FS_CORNER: f64 = 12.0;
/// Corner label box height, px.
const CORNER_BOX_H: f64 = 16.0;
/// Room kept around a groove's box for its corner labels, px.
const GROOVE_LABEL_PX: f64 = 30.0;

enum Kind<'a> {
    Crash,
    Gouge,
    /// A groove with its cleaned ring.
    Groove(&'a Groove, Vec<[f64; 2]>),
    /// The largest leftover, with where its thickness is measured (`[from, to]`); the
    /// title gets the Z range shown once the view is fitted.
    Leftover(Option<[[f64; 2]; 2]>),
    /// A thread, with the window that shows its teeth.
    Thread(&'a ThreadCheck, Bbox),
}

struct Finding<'a> {
    title: String,
    /// Lines under the inset: the cause and the checked remedy of a finding.
    why: Vec<String>,
    z: f64,
    r: f64,
    half: f64,
    kind: Kind<'a>,
}

impl Finding<'_> {
    /// The mm box to show.
    fn window(&self) -> Bbox {
        match &self.kind {
            Kind::Groove(_, ring) => groove_window(ring),
            Kind::Thread(_, window) => *window,
            _ => Bbox::new(
                self.z - self.half,
                self.z + self.half,
                self.r - self.half,
                self.r + self.half,
            ),
        }
    }

    /// The plot height this view wants at most `max_h` (grooves are only as tall as
    /// their window needs at the inset's width).
    fn plot_h(&self, max_h: f64) -> f64 {
        match &self.kind {
            Kind::Groove(..) | Kind::Thread(..) => {
                let w = self.window();
                (w.h() * PLOT_W / w.w().max(1e-9)).clamp(MIN_PLOT_H, max_h)
            }
            _ => max_h,
        }
    }
}

/// A groove's window: its box with a margin of 8 % of its larger side, and at least
/// [`GROOVE_LABEL_PX`] at the inset's scale so the corner labels fit.
fn groove_window(ring: &[[f64; 2]]) -> Bbox {
    let b = groove::ring_box(ring);
    let size = b.w().max(b.h()).max(1e-3);
    let mut m = 0.08 * size;
    for _ in 0..3 {
        let s = PLOT_W / (b.w() + 2.0 * m).max(1e-9);
        m = m.max(GROOVE_LABEL_PX / s);
    }
    b.grow(m)
}

/// Where a finding is, in program words: `line 14 at Z-46.667 X36`.
fn place(line: u32, z: f64, r: f64) -> String {
    format!("line {line} at Z{} X{}", num(z, 3), num(2.0 * r, 3))
}

fn findings<'a>(report: &'a Report, main: &View) -> Vec<Finding<'a>> {
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
            why: why_lines(c.cause.as_ref(), c.remedy.as_ref()),
            title: format!(
                "{}, {}",
                if c.assumed { "possible crash" } else { "crash" },
                place(c.line, c.z, c.r)
            ),
            z: c.z,
            r: c.r,
            half: clampf(2.5 * c.area_mm2.abs().sqrt(), 1.0),
            kind: Kind::Crash,
        });
    }
    for g in &report.gouges {
        out.push(Finding {
            why: why_lines(g.cause.as_ref(), g.remedy.as_ref()),
            title: format!(
                "{}, {}, depth {} mm",
                if g.assumed { "possible gouge" } else { "gouge" },
                place(g.line, g.z, g.r),
                num(g.depth_mm, 3)
            ),
            z: g.z,
            r: g.r,
            half: clampf(
                (6.0 * g.depth_mm.abs()).max(2.5 * g.area_mm2.abs().sqrt()),
                0.2,
            ),
            kind: Kind::Gouge,
        });
    }
    out.retain(|f| f.z.is_finite() && f.r.is_finite());
    for g in &report.grooves {
        let Some(ring) = groove::clean_ring(&g.ring) else {
            continue;
        };
        let title = match g.deviation_mm.filter(|d| d.is_finite()) {
            Some(d) => format!(
                "groove line {} (deviation ≤ {} mm)",
                g.line,
                num(groove::shown_deviation(d), 3)
            ),
            None => format!("groove line {}", g.line),
        };
        out.push(Finding {
            why: Vec::new(),
            title,
            z: 0.0,
            r: 0.0,
            half: 0.0,
            kind: Kind::Groove(g, ring),
        });
    }
    if out.len() < MAX_DETAILS {
        if let Some(f) = leftover_finding(report, &clampf) {
            out.push(f);
        }
    }
    for t in &report.threads {
        if out.len() >= MAX_DETAILS {
            break;
        }
        if let Some(window) = thread_window(t) {
            out.push(Finding {
                why: Vec::new(),
                title: thread_title(t),
                z: 0.0,
                r: 0.0,
                half: 0.0,
                kind: Kind::Thread(t, window),
            });
        }
    }
    out.truncate(MAX_DETAILS);
    out
}

/// The radial depth the thread's teeth are drawn for: the passes' infeeds added up, else
/// the ISO depth of a 60° thread (0.6134 of the lead) when no infeed was measured.
fn thread_depth(t: &ThreadCheck) -> f64 {
    let sum: f64 = t.pass_depths_mm.iter().filter(|d| d.is_finite()).sum();
    if sum > 1e-6 {
        sum
    } else {
        0.6134 * t.lead_mm
    }
}

/// Four leads around the middle of the root line (the whole thread with half a lead either
/// side when it is shorter), radially from the root to the crest with a third of the depth
/// as margin; `None` for a thread without a lead or a place.
fn thread_window(t: &ThreadCheck) -> Option<Bbox> {
    let lead = t.lead_mm;
    let finite = [lead, t.z_start_mm, t.z_end_mm, t.x_mm]
        .iter()
        .all(|v| v.is_finite());
    if !(finite && lead > 0.0) {
        return None;
    }
    let (z0, z1) = (t.z_start_mm.min(t.z_end_mm), t.z_start_mm.max(t.z_end_mm));
    let half_w = (2.0 * lead).min((z1 - z0) / 2.0 + 0.5 * lead);
    let zc = (z0 + z1) / 2.0;
    let depth = thread_depth(t);
    // the crest is away from the axis on an outside thread, toward it in a bore
    let root = t.x_mm / 2.0;
    let crest = if t.inside { root - depth } else { root + depth };
    let mut rs = vec![root, crest];
    rs.extend(
        t.achieved_x_mm
            .iter()
            .chain(&t.expected_x_mm)
            .map(|x| x / 2.0),
    );
    let rmin = rs.iter().copied().fold(f64::INFINITY, f64::min);
    let rmax = rs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let m = depth / 3.0;
    Some(Bbox::new(zc - half_w, zc + half_w, rmin - m, rmax + m))
}

/// `thread line 14, lead 1.5: X18.05 reached, 60°` (the flanks' included angle; the
/// expected diameter is labelled on its line inside the view); a multi-start thread says
/// `lead 3, 2 starts`.
fn thread_title(t: &ThreadCheck) -> String {
    let mut s = format!("thread line {}, lead {}", t.line, num(t.lead_mm, 3));
    if t.starts > 1 {
        s += &format!(", {} starts", t.starts);
    }
    match t.achieved_x_mm.filter(|a| a.is_finite()) {
        Some(a) => s += &format!(": X{} reached", num(a, 3)),
        None => s += ": no material cut",
    }
    if let Some(a) = t.included_angle_deg.filter(|a| a.is_finite()) {
        s += &format!(", {}°", num(a, 1));
    }
    s
}

/// The view of the largest leftover, zoomed on its thickest place: `half` is five times
/// the thickness there (clamped by `clampf` like the other findings), so the window is
/// about ten thicknesses wide.
fn leftover_finding<'a>(report: &Report, clampf: &dyn Fn(f64, f64) -> f64) -> Option<Finding<'a>> {
    let spot = report.leftover_spot?;
    let shape = report.leftovers.get(spot.leftover)?;
    let reported = report
        .deviation
        .as_ref()
        .map(|d| d.max_undercut_mm)
        .filter(|t| t.is_finite() && *t > 0.0);
    // The report's maximum is exact and belongs to this region when it is the only one.
    let thickness = match (report.leftovers.len(), reported, spot.thickness) {
        (1, Some(t), _) => Some(t),
        (_, _, Some(t)) => Some(t),
        (_, t, None) => t,
    };
    let size = spot.thickness.or(thickness).unwrap_or_else(|| {
        let b = Bbox::of_shapes(std::slice::from_ref(shape));
        b.w().min(b.h())
    });
    let title = match thickness {
        Some(t) => format!("leftover up to {} mm", num(t, 3)),
        None => "leftover".to_string(),
    };
    let [z, r] = spot.centre;
    let why = report
        .leftover_list
        .get(spot.leftover)
        .map(|l| why_lines(l.cause.as_ref(), None))
        .unwrap_or_default();
    (z.is_finite() && r.is_finite()).then(|| Finding {
        why,
        title,
        z,
        r,
        half: clampf(5.0 * size, 0.02),
        kind: Kind::Leftover(spot.measure),
    })
}

/// Each inset's title, tick labels and gap, px.
const OVERHEAD: f64 = 58.0;
/// Each line of cause or remedy under an inset, px.
const WHY_LINE: f64 = 15.0;

/// The lines under a finding's inset: why, and the fix latsim checked.
fn why_lines(cause: Option<&crate::Cause>, remedy: Option<&crate::Remedy>) -> Vec<String> {
    cause
        .map(|c| format!("why: {}", c.text))
        .into_iter()
        .chain(remedy.map(|r| format!("fix (checked): {}", r.text)))
        .collect()
}
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
        let lines: f64 = list.iter().map(|f| f.why.len() as f64 * WHY_LINE).sum();
        let h = ((bottom - RIGHT_TOP - lines) / list.len() as f64 - OVERHEAD).min(230.0);
        if h >= MIN_PLOT_H {
            break h;
        }
        list.pop();
    };
    let mut top = RIGHT_TOP;
    doc.open("g", &[("id", "details".into())]);
    for (i, f) in list.iter().enumerate() {
        let h = f.plot_h(plot_h);
        let rect = [RIGHT_X + LABEL_ROOM, top + 10.0, PLOT_W, h];
        let v = View::fit(f.window(), rect);
        let title = match f.kind {
            Kind::Leftover(_) => format!("detail {}: {}, {}", i + 1, f.title, z_range(&v)),
            _ => format!("detail {}: {}", i + 1, f.title),
        };
        let max = chars_fitting(RIGHT_W, FS_SMALL);
        doc.text(
            RIGHT_X,
            top - 4.0,
            FS_SMALL,
            "start",
            colour::INK,
            &truncate(&title, max),
        );
        let id = format!("clip-detail-{i}");
        doc.clip(&id, rect);
        doc.rect(rect, "#ffffff", "none", 0.0);
        axes(doc, &v, 46.0, true);
        doc.open("g", &[("clip-path", format!("url(#{id})"))]);
        match &f.kind {
            Kind::Groove(g, ring) => {
                draw_shapes(doc, report, &v, false);
                centre_line(doc, &v);
                groove_ring(doc, &v, g.line, ring);
            }
            Kind::Thread(t, _) => {
                draw_shapes(doc, report, &v, false);
                centre_line(doc, &v);
                thread_lines(doc, &v, t);
            }
            kind => {
                draw_content(doc, report, &v, false, DETAIL_POINT_CAP, None);
                centre_line(doc, &v);
                let (x, y) = (v.x(f.z), v.y(f.r));
                if matches!(kind, Kind::Crash) {
                    marker(doc, x, y, colour::CRASH);
                } else if let Kind::Leftover(measure) = kind {
                    if let Some(m) = measure {
                        thickness_mark(doc, &v, *m);
                    }
                } else {
                    doc.circle([x, y], 10.0, "none", colour::GOUGE, 2.0);
                }
            }
        }
        doc.close();
        if let Kind::Groove(_, ring) = &f.kind {
            corner_labels(doc, &v, ring);
        }
        doc.rect(rect, "none", "#2b2f36", 1.0);
        for (k, line) in f.why.iter().enumerate() {
            doc.text(
                RIGHT_X,
                top + 10.0 + h + 34.0 + k as f64 * WHY_LINE,
                FS_SMALL,
                "start",
                colour::INK,
                &truncate(line, max),
            );
        }
        top += h + OVERHEAD + f.why.len() as f64 * WHY_LINE;
    }
    doc.close();
    top
}

/// The leftover's thickness where it is greatest: a dark line across the band from its
/// farthest point to the intended edge, with a dot at each end.
fn thickness_mark(doc: &mut Doc, v: &View, m: [[f64; 2]; 2]) {
    let [a, b] = m.map(|p| [v.x(p[0]), v.y(p[1])]);
    doc.open("g", &[("class", "leftover-spot".into())]);
    doc.line(a, b, colour::INK, 1.5, "");
    for p in [a, b] {
        doc.circle(p, 2.5, colour::INK, "none", 0.0);
    }
    doc.close();
}

/// The diameter the thread should reach (dashed, intended colour) and its pitch diameter
/// as cut (dotted), across the inset, each labelled at its left end.
fn thread_lines(doc: &mut Doc, v: &View, t: &ThreadCheck) {
    let lines = [
        (t.expected_x_mm, "expected", colour::INTENDED, "6 4"),
        (t.pitch_diameter_mm, "pitch", colour::INK, "2 3"),
    ];
    doc.open("g", &[("class", "thread-lines".into())]);
    for (x, what, stroke, dash) in lines {
        let Some(x) = x.filter(|x| x.is_finite()) else {
            continue;
        };
        let y = v.y(x / 2.0);
        if !(v.px[1]..=v.bottom()).contains(&y) {
            continue;
        }
        doc.line([v.px[0], y], [v.right(), y], stroke, 1.4, dash);
        let label = format!("{what} Φ{}", num(x, 3));
        let w = width(&label, FS_CORNER) * 0.92 + 8.0;
        // above the line, unless that leaves the inset
        let top = if y - CORNER_BOX_H - 2.0 >= v.px[1] {
            y - CORNER_BOX_H - 2.0
        } else {
            y + 2.0
        };
        boxed_label(doc, [v.px[0] + 4.0, top, w, CORNER_BOX_H], stroke, &label);
    }
    doc.close();
}

/// The Z range a view shows, e.g. `Z-81.2 … Z-77.3`, with enough decimals to tell its
/// ends apart.
fn z_range(v: &View) -> String {
    let w = v.mm.w();
    let dec = if w >= 20.0 {
        1
    } else if w >= 2.0 {
        2
    } else {
        3
    };
    // Fixed decimals, so both ends read alike; never `-0.00`.
    let fixed = |z: f64| {
        let s = format!("{z:.dec$}");
        if s.trim_start_matches(['-', '0', '.']).is_empty() {
            s.trim_start_matches('-').to_string()
        } else {
            s
        }
    };
    format!("Z{} … Z{}", fixed(v.mm.zmin), fixed(v.mm.zmax))
}

/// The groove ring, dashed in the intended colour, with a dot on each principal corner.
fn groove_ring(doc: &mut Doc, v: &View, line: u32, ring: &[[f64; 2]]) {
    let shape = Shape {
        outer: ring.to_vec(),
        holes: vec![],
    };
    doc.open(
        "g",
        &[
            ("class", "groove".into()),
            ("data-line", line.to_string()),
            ("transform", v.transform(false)),
        ],
    );
    doc.mm_path(
        v,
        &shapes_d(std::slice::from_ref(&shape), MIN_PX / v.s),
        "none",
        colour::INTENDED,
        1.8,
        &[7.0, 4.0],
    );
    doc.close();
    for &i in &groove::corners(ring) {
        let p = [v.x(ring[i][0]), v.y(ring[i][1])];
        doc.circle(p, 3.0, colour::INTENDED, "none", 0.0);
    }
}

/// The principal corners' labels (`P1 Z30.00 Φ50.00`), on white boxes placed apart
/// from each other inside the inset.
fn corner_labels(doc: &mut Doc, v: &View, ring: &[[f64; 2]]) {
    let idx = groove::corners(ring);
    let labels: Vec<String> = idx
        .iter()
        .enumerate()
        .map(|(k, &i)| groove::corner_label(k + 1, ring[i]))
        .collect();
    let at: Vec<[f64; 2]> = idx
        .iter()
        .map(|&i| [v.x(ring[i][0]), v.y(ring[i][1])])
        .collect();
    let size: Vec<[f64; 2]> = labels
        .iter()
        .map(|l| [width(l, FS_CORNER) * 0.92 + 8.0, CORNER_BOX_H])
        .collect();
    let px_ring: Vec<[f64; 2]> = ring.iter().map(|p| [v.x(p[0]), v.y(p[1])]).collect();
    let b = groove::ring_box(ring);
    let centre = [v.x((b.zmin + b.zmax) / 2.0), v.y((b.rmin + b.rmax) / 2.0)];
    let frame = [
        v.px[0] + 2.0,
        v.px[1] + 2.0,
        v.right() - 2.0,
        v.bottom() - 2.0,
    ];
    let boxes = groove::place_labels(&at, &size, centre, &px_ring, frame);
    doc.open("g", &[("class", "corner-labels".into())]);
    for (label, b) in labels.iter().zip(boxes) {
        let Some(b) = b else { continue };
        let r = [b[0], b[1], b[2] - b[0], b[3] - b[1]];
        boxed_label(doc, r, colour::INTENDED, label);
    }
    doc.close();
}

/// A label on a white box `r` (px: x, y, width, height) framed in `stroke`, the text
/// centred near its bottom.
fn boxed_label(doc: &mut Doc, r: [f64; 4], stroke: &str, text: &str) {
    doc.label_box(r, 2.0, 0.88, stroke, 0.8);
    doc.text(
        r[0] + r[2] / 2.0,
        r[1] + r[3] - 4.0,
        FS_CORNER,
        "middle",
        colour::INK,
        text,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m20() -> ThreadCheck {
        ThreadCheck {
            line: 4,
            lead_mm: 1.5,
            x_mm: 18.05,
            expected_x_mm: Some(18.05),
            achieved_x_mm: Some(18.05),
            pass_depths_mm: vec![0.4, 0.3, 0.275],
            z_start_mm: -2.0,
            z_end_mm: -30.0,
            ..Default::default()
        }
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    /// The title names the starts of a multi-start thread, and says nothing of one start.
    #[test]
    fn a_multi_start_thread_title_names_its_starts() {
        assert_eq!(
            thread_title(&m20()),
            "thread line 4, lead 1.5: X18.05 reached"
        );
        let two = ThreadCheck {
            lead_mm: 3.0,
            starts: 2,
            ..m20()
        };
        assert_eq!(
            thread_title(&two),
            "thread line 4, lead 3, 2 starts: X18.05 reached"
        );
    }

    /// Four leads around the middle of the root line; radially root to crest (the passes'
    /// 0.975 mm) with a third of that as margin.
    #[test]
    fn a_long_thread_shows_four_leads_in_its_middle() {
        let w = thread_window(&m20()).expect("a window");
        assert!(close(w.zmin, -19.0) && close(w.zmax, -13.0), "{w:?}");
        assert!(close(w.rmin, 9.025 - 0.325), "{w:?}");
        assert!(close(w.rmax, 9.025 + 0.975 + 0.325), "{w:?}");
    }

    /// A thread shorter than four leads is shown whole with half a lead either side; an
    /// inside thread's crest is toward the axis.
    #[test]
    fn a_short_or_inside_thread_is_framed_whole() {
        let mut t = m20();
        t.z_start_mm = -2.0;
        t.z_end_mm = -4.0;
        let w = thread_window(&t).expect("a window");
        assert!(close(w.zmin, -4.75) && close(w.zmax, -1.25), "{w:?}");
        t.inside = true;
        t.x_mm = 30.0;
        t.expected_x_mm = Some(30.0);
        t.achieved_x_mm = Some(29.9);
        let w = thread_window(&t).expect("a window");
        assert!(close(w.rmax, 15.0 + 0.325), "{w:?}");
        assert!(close(w.rmin, 15.0 - 0.975 - 0.325), "{w:?}");
        // no infeed measured: the ISO depth of the lead
        t.pass_depths_mm.clear();
        let w = thread_window(&t).expect("a window");
        assert!(
            close(w.rmin, 15.0 - 0.6134 * 1.5 * (1.0 + 1.0 / 3.0)),
            "{w:?}"
        );
    }

    #[test]
    fn a_thread_without_lead_or_place_has_no_view() {
        for (lead, z) in [(0.0, -2.0), (f64::NAN, -2.0), (-1.0, -2.0), (1.5, f64::NAN)] {
            let mut t = m20();
            t.lead_mm = lead;
            t.z_start_mm = z;
            assert!(thread_window(&t).is_none(), "lead {lead}, z {z}");
        }
    }
}
