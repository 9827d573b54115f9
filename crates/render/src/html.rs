//! The report as one self-contained HTML page: the report picture (inline SVG), the
//! tables, and a move slider that replays the toolpath over the stock on a `<canvas>`.
//!
//! Nothing is loaded from elsewhere: the style, the script and the data are inline, so the
//! page works from `file://` without a network. The data for the script is a compact JSON
//! block (`<script type="application/json" id="ls-data">`) in program coordinates
//! (`z`, `x` = diameter), rounded to 4 decimals:
//!
//! - `moves`: the number of moves in the report; `stride`: 1 when every move is listed,
//!   k when only every k-th is (large programs, at most about [`PATH_POINT_CAP`] points);
//! - `path`: one entry per listed move, `[move, kind, line, z, x, z, x, …]` with `move`
//!   1-based and `kind` 0 rapid, 1 feed, 2 thread;
//! - `window`: `[zmin, zmax, xmin, xmax]` of the drawing;
//! - `blank`, `part`, `intended`, `gouges`, `leftovers`: rings `[z, x, z, x, …]`
//!   (fill even-odd), thinned to what the drawing can show;
//! - `crashes`: `[line, z, x]`; `snapshots`: `{"after": k, "rings": […]}` in move order;
//! - `fixture`, `tools`, `tool_runs`, `crash_tools`: the workholding and the tool drawn at
//!   the current move (see `html/tools.rs`).
//!
//! Every `<` inside the JSON is written as `\u003c`, so no `</script>` can end the block.

use std::fmt::Write as _;

mod sheet;
mod solid;
mod threads;

use crate::block::verdict_text;
use crate::layout::{colour, main_window};
use crate::path::thin_ring;
use crate::report::{Crash, Diagnostic, Gouge, PathKind, Report, Shape, Snapshot};
use crate::scale::Bbox;
use crate::text::{duration, esc, grouped, mm, num, push_num, quantity};

/// Cap on toolpath points embedded for the slider; beyond it only every k-th move is
/// listed.
pub(crate) const PATH_POINT_CAP: usize = 200_000;
/// Cap on the points of all embedded snapshots together (with the toolpath and the
/// inline picture, a report of 10^6 moves and 100 000-vertex snapshots stays under 10 MB).
const SNAPSHOT_POINT_CAP: usize = 100_000;
/// Cap on the points of each static layer (blank, part, …).
const LAYER_POINT_CAP: usize = 50_000;
/// Rows listed per diagnostic or finding table before "… N more" (the JSON lists them
/// all): 20 000 rows of four tables made a 13 MB page; the page stays under 10 MB.
const MAX_ROWS: usize = 1_000;
/// Rows of each findings table the printed setup sheet shows (the rest are marked
/// `extra`, which the print style hides, and counted in a note).
const PRINT_ROWS: usize = 6;
/// Coordinates beyond this (mm) are clamped in the embedded data.
const CLAMP_MM: f64 = 1e7;
/// The drawing is about this many px wide: points closer than a fraction of a px apart
/// are merged.
const DRAW_PX: f64 = 1600.0;

/// The page's style sheet.
const STYLE: &str = include_str!("html/page.css");
/// The slider's script.
const SCRIPT: &str = include_str!("html/player.js");
/// The tool and workholding drawing the slider calls (`html/tools.rs` writes its data).
const TOOLS_SCRIPT: &str = include_str!("html/tools.js");

mod tools;

/// A coordinate for the data block: clamped, rounded to 4 decimals, trailing zeros cut.
fn c4(v: f64) -> String {
    num(v.clamp(-CLAMP_MM, CLAMP_MM), 4)
}

/// `3rd`, `11th`, `21st`.
fn ordinal(n: usize) -> String {
    let suffix = match (n % 10, n % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// A position for the tables (`—` when not finite).
fn pos(v: f64) -> String {
    if v.is_finite() {
        num(v, 4)
    } else {
        "—".to_string()
    }
}

fn finite(p: &[f64; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

fn dist2(a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dz, dr) = (a[0] - b[0], a[1] - b[1]);
    dz * dz + dr * dr
}

/// Push `[z, r]` as `,z,x` (x = 2r).
fn push_zx(out: &mut String, p: [f64; 2]) {
    out.push(',');
    push_num(out, p[0].clamp(-CLAMP_MM, CLAMP_MM), 4);
    out.push(',');
    push_num(out, (2.0 * p[1]).clamp(-CLAMP_MM, CLAMP_MM), 4);
}

/// All rings of some shapes, thinned with `md` doubled until at most `cap` points remain.
fn rings(shapes: &[Shape], md: f64, cap: usize) -> Vec<Vec<[f64; 2]>> {
    let mut md = md;
    for _ in 0..60 {
        let out: Vec<Vec<[f64; 2]>> = shapes
            .iter()
            .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
            .map(|r| thin_ring(r, md))
            .filter(|r| r.len() >= 3)
            .collect();
        if out.iter().map(Vec::len).sum::<usize>() <= cap {
            return out;
        }
        md *= 2.0;
    }
    Vec::new()
}

/// Rings as a JSON array of flat `[z, x, …]` arrays.
fn rings_json(out: &mut String, rings: &[Vec<[f64; 2]>]) {
    out.push('[');
    for (i, r) in rings.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push('[');
        let start = out.len();
        for p in r {
            push_zx(out, *p);
        }
        // the first point's comma
        if out.len() > start {
            out.remove(start);
        }
        out.push(']');
    }
    out.push(']');
}

/// The toolpath chosen for the slider: per move, its finite points with interior points
/// closer than `md` merged ([`thin_move`]); every `stride`-th move (and the last) when over
/// the cap.
struct Moves {
    /// The moves listed, 1-based, ascending.
    list: Vec<usize>,
    /// 1 when every move is listed.
    stride: usize,
    /// The merge distance, squared.
    md2: f64,
}

/// Calls `keep` with the finite points of `pts` that the slider shows: the first and the
/// last, and each one farther than `md2` (squared) from the one kept before it.
fn thin_move(pts: &[[f64; 2]], md2: f64, mut keep: impl FnMut([f64; 2])) {
    let last = pts.iter().rposition(finite);
    let mut kept: Option<[f64; 2]> = None;
    for (i, p) in pts.iter().enumerate().filter(|(_, p)| finite(p)) {
        match kept {
            Some(l) if Some(i) != last && dist2(l, *p) <= md2 => {}
            _ => {
                keep(*p);
                kept = Some(*p);
            }
        }
    }
}

fn choose_moves(report: &Report, md: f64) -> Moves {
    let md2 = md * md;
    let n = report.toolpath.len();
    // First pass: count points after merging, without keeping them.
    let counts: Vec<usize> = report
        .toolpath
        .iter()
        .map(|l| {
            let mut c = 0;
            thin_move(&l.points, md2, |_| c += 1);
            c
        })
        .collect();
    let total: usize = counts.iter().sum();
    let mut stride = 1usize;
    // Strides are odd, so that alternating kinds (cut, retract, cut, …) both show.
    if total > PATH_POINT_CAP {
        stride = total.div_ceil(PATH_POINT_CAP) | 1;
        loop {
            let kept: usize = counts
                .iter()
                .enumerate()
                .filter(|(i, _)| i % stride == 0 || i + 1 == n)
                .map(|(_, c)| c)
                .sum();
            if kept <= PATH_POINT_CAP || stride >= n {
                break;
            }
            stride = (stride + (stride / 4).max(2)) | 1;
        }
    }
    let list = (0..n)
        .filter(|i| i % stride == 0 || i + 1 == n)
        .map(|i| i + 1)
        .collect();
    Moves { list, stride, md2 }
}

/// The drawing's window in `[z, r]`: the report picture's window, upper half plus a
/// margin below the axis.
fn window(report: &Report) -> Bbox {
    let w = main_window(report);
    let below = (0.04 * w.rmax.abs().max(1.0)).min(w.rmax - w.rmin);
    Bbox::new(w.zmin, w.zmax, (-below).max(w.rmin), w.rmax)
}

/// The data block (JSON, not yet escaped) and whether the toolpath was thinned.
fn data_json(report: &Report) -> (String, Moves) {
    let win = window(report);
    let size = win.w().max(win.h());
    let md = if size.is_finite() && size > 0.0 {
        size / DRAW_PX / 3.0
    } else {
        1e-4
    };
    let moves = choose_moves(report, md);
    let mut out = String::with_capacity(1 << 16);
    let _ = write!(
        out,
        "{{\"coords\":\"z,x (x = diameter), mm\",\"moves\":{},\"stride\":{},\"window\":[{},{},{},{}],",
        report.toolpath.len(),
        moves.stride,
        c4(win.zmin),
        c4(win.zmax),
        c4(2.0 * win.rmin),
        c4(2.0 * win.rmax)
    );
    let _ = write!(
        out,
        "\"style\":{{\"rapid\":\"{}\",\"feed\":\"{}\",\"thread\":\"{}\",\"part\":\"{}\",\"part_edge\":\"{}\",\"blank_edge\":\"{}\",\"intended\":\"{}\",\"gouge\":\"{}\",\"gouge_edge\":\"{}\",\"leftover\":\"{}\",\"leftover_edge\":\"{}\",\"crash\":\"{}\"}},",
        colour::RAPID,
        colour::FEED,
        colour::THREAD,
        colour::PART,
        colour::PART_EDGE,
        colour::BLANK_EDGE,
        colour::INTENDED,
        colour::GOUGE,
        colour::GOUGE_EDGE,
        colour::LEFTOVER,
        colour::LEFTOVER_EDGE,
        colour::CRASH
    );
    for (key, shapes) in [
        ("blank", &report.stock.shapes),
        ("part", &report.final_part),
        ("intended", &report.intended),
        ("gouges", &report.gouge_shapes),
        ("leftovers", &report.leftovers),
    ] {
        let _ = write!(out, "\"{key}\":");
        rings_json(&mut out, &rings(shapes, md, LAYER_POINT_CAP));
        out.push(',');
    }
    tools::data(&mut out, report);
    solid::data(&mut out, report, md);
    out.push_str("\"crashes\":[");
    let crashes: Vec<&Crash> = report
        .crashes
        .iter()
        .filter(|c| c.z.is_finite() && c.r.is_finite())
        .collect();
    for (i, c) in crashes.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        let _ = write!(out, "[{}", c.line);
        push_zx(&mut out, [c.z, c.r]);
        out.push(']');
    }
    out.push_str("],\"snapshots\":");
    snapshots_json(&mut out, &report.snapshots, md);
    out.push_str(",\"path\":[\n");
    for (j, &i) in moves.list.iter().enumerate() {
        if j > 0 {
            out.push_str(",\n");
        }
        let l = &report.toolpath[i - 1];
        let kind = match l.kind {
            PathKind::Rapid => 0,
            PathKind::Feed => 1,
            PathKind::Thread => 2,
        };
        let _ = write!(out, "[{i},{kind},{}", l.line);
        thin_move(&l.points, moves.md2, |p| push_zx(&mut out, p));
        out.push(']');
    }
    out.push_str("]}");
    (out, moves)
}

/// Snapshots in move order, thinned; when their points exceed the cap, only an even
/// selection of them (always the last) is kept.
fn snapshots_json(out: &mut String, snaps: &[Snapshot], md: f64) {
    let mut order: Vec<&Snapshot> = snaps.iter().collect();
    order.sort_by_key(|s| s.after_move);
    let thinned: Vec<(usize, Vec<Vec<[f64; 2]>>)> = order
        .iter()
        .map(|s| (s.after_move, rings(&s.shapes, md, LAYER_POINT_CAP)))
        .collect();
    let total: usize = thinned
        .iter()
        .map(|(_, r)| r.iter().map(Vec::len).sum::<usize>())
        .sum();
    let n = thinned.len();
    let every = if total > SNAPSHOT_POINT_CAP {
        total.div_ceil(SNAPSHOT_POINT_CAP)
    } else {
        1
    };
    out.push('[');
    let mut first = true;
    for (i, (after, rs)) in thinned.iter().enumerate() {
        if i % every != 0 && i + 1 != n {
            continue;
        }
        if !first {
            out.push(',');
        }
        first = false;
        let _ = write!(out, "{{\"after\":{after},\"rings\":");
        rings_json(out, rs);
        out.push('}');
    }
    out.push(']');
}

/// Make JSON safe inside a `<script>` element: `<` only occurs in strings, where
/// `\u003c` means the same.
fn script_safe(json: String) -> String {
    if json.contains('<') {
        json.replace('<', "\\u003c")
    } else {
        json
    }
}

/// A `<tr>` of label and value (value already escaped).
fn row(out: &mut String, label: &str, value_html: &str) {
    let _ = writeln!(
        out,
        "<tr><th scope=\"row\">{}</th><td>{value_html}</td></tr>",
        esc(label)
    );
}

/// A [`row`] the printed page leaves out (the setup sheet says it).
fn screen_row(out: &mut String, label: &str, value_html: &str) {
    let _ = writeln!(
        out,
        "<tr class=\"screen-only\"><th scope=\"row\">{}</th><td>{value_html}</td></tr>",
        esc(label)
    );
}

fn summary_table(out: &mut String, report: &Report) {
    let (verdict, vc) = verdict_text(report);
    out.push_str("<table class=\"kv\" id=\"ls-summary\">\n");
    row(
        out,
        "verdict",
        &format!(
            "<strong class=\"verdict\" style=\"color:{vc}\">{}</strong>",
            esc(&verdict)
        ),
    );
    let mut program = report.program.clone();
    if !report.title.is_empty() && !program.starts_with(&report.title) {
        program = format!("{program} ({})", report.title);
    }
    screen_row(out, "program", &esc(&program));
    if !report.control.is_empty() {
        screen_row(out, "control", &esc(&report.control));
    }
    screen_row(out, "stock", &esc(&report.stock.description));
    let tools = if report.tools.is_empty() {
        "—".to_string()
    } else {
        report
            .tools
            .iter()
            .map(|t| esc(t))
            .collect::<Vec<_>>()
            .join("<br>")
    };
    screen_row(out, "tools", &tools);
    let feed = report.segments.saturating_sub(report.rapid_segments);
    screen_row(
        out,
        "moves",
        &esc(&format!(
            "{} (rapid {}, feed {})",
            grouped(report.segments as f64, 0),
            grouped(report.rapid_segments as f64, 0),
            grouped(feed as f64, 0)
        )),
    );
    row(
        out,
        "removed",
        &esc(&format!(
            "{} mm² section / {} mm³",
            quantity(report.removed_area_mm2),
            quantity(report.removed_volume_mm3)
        )),
    );
    screen_row(out, "cycle time", &esc(&duration(report.cycle_time_s)));
    row(out, "tolerance", &esc(&mm(report.tolerance_mm)));
    match &report.deviation {
        Some(d) => {
            row(
                out,
                "overcut",
                &esc(&format!(
                    "{} mm², max {}",
                    quantity(d.overcut_area_mm2),
                    mm(d.max_overcut_mm)
                )),
            );
            row(
                out,
                "undercut",
                &esc(&format!(
                    "{} mm², max {}",
                    quantity(d.undercut_area_mm2),
                    mm(d.max_undercut_mm)
                )),
            );
        }
        None => row(out, "deviation", "no intended shape known"),
    }
    out.push_str("</table>\n");
}

/// Header of a list section, with its count.
/// An empty list's header is marked `empty` (the printed sheet leaves it out).
fn list_head(out: &mut String, id: &str, title: &str, n: usize) {
    let class = if n == 0 { " class=\"empty\"" } else { "" };
    let _ = writeln!(
        out,
        "<h3 id=\"{id}\"{class}>{} <span class=\"count\">({n})</span></h3>",
        esc(title)
    );
}

/// The class attribute of the `i`-th row of a findings table: ` class="extra"` past what
/// the printed sheet shows.
fn extra(i: usize) -> &'static str {
    if i >= PRINT_ROWS {
        " class=\"extra\""
    } else {
        ""
    }
}

/// "… N more" after a capped table: on screen past [`MAX_ROWS`], printed past
/// [`PRINT_ROWS`].
fn more(out: &mut String, n: usize) {
    if n > MAX_ROWS {
        let _ = writeln!(
            out,
            "<p class=\"note screen-only\">… {} more not listed (see the JSON report).</p>",
            grouped((n - MAX_ROWS) as f64, 0)
        );
    }
    print_more(out, n);
}

/// "… N more not printed" after a table of `n` rows longer than the printed sheet shows.
fn print_more(out: &mut String, n: usize) {
    if n > PRINT_ROWS {
        let _ = writeln!(
            out,
            "<p class=\"note print-only\">… {} more not printed (see the page on screen or the JSON report).</p>",
            grouped((n - PRINT_ROWS) as f64, 0)
        );
    }
}

fn diag_table(out: &mut String, id: &str, title: &str, list: &[Diagnostic], class: &str) {
    list_head(out, id, title, list.len());
    if list.is_empty() {
        out.push_str("<p class=\"none\">none</p>\n");
        return;
    }
    let _ = writeln!(
        out,
        "<table class=\"list {class}\"><thead><tr><th>line</th><th>col</th><th>code</th><th>message</th></tr></thead><tbody>"
    );
    for (i, d) in list.iter().take(MAX_ROWS).enumerate() {
        let line = if d.line == 0 {
            "—".to_string()
        } else {
            d.line.to_string()
        };
        let _ = writeln!(
            out,
            "<tr data-line=\"{}\"{}><td class=\"n\">{line}</td><td class=\"n\">{}</td><td><code>{}</code></td><td>{}</td></tr>",
            d.line,
            extra(i),
            d.column,
            esc(&d.code),
            esc(&d.message)
        );
    }
    out.push_str("</tbody></table>\n");
    more(out, list.len());
}

fn crash_table(out: &mut String, id: &str, title: &str, list: &[Crash]) {
    list_head(out, id, title, list.len());
    if list.is_empty() {
        out.push_str("<p class=\"none\">none</p>\n");
        return;
    }
    out.push_str("<table class=\"list crash\"><thead><tr><th>line</th><th>col</th><th>Z (mm)</th><th>X Ø (mm)</th><th>area (mm²)</th><th>depth (mm)</th><th>what</th><th>why, and the fix latsim checked</th></tr></thead><tbody>\n");
    for (i, c) in list.iter().take(MAX_ROWS).enumerate() {
        let part = c.body.as_deref().unwrap_or("cutting edge");
        let what = match &c.obstacle {
            Some(o) => format!("{part} in the {o}"),
            None if c.body.is_some() => format!("{part} in stock"),
            None => "rapid in stock".to_string(),
        };
        let what = if c.assumed {
            format!("possible: {what} (tool size assumed)")
        } else {
            what
        };
        let _ = writeln!(
            out,
            "<tr data-line=\"{}\"{}><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td><td>{}</td></tr>",
            c.line,
            extra(i),
            c.line,
            c.column,
            pos(c.z),
            pos(2.0 * c.r),
            esc(&quantity(c.area_mm2)),
            esc(&quantity(c.depth_mm)),
            esc(&what),
            why(c.cause.as_ref(), c.remedy.as_ref())
        );
    }
    out.push_str("</tbody></table>\n");
    more(out, list.len());
}

/// A finding's cause and checked remedy for a table cell (escaped HTML).
fn why(cause: Option<&crate::Cause>, remedy: Option<&crate::Remedy>) -> String {
    let mut cell = cause.map_or_else(String::new, |c| esc(&c.text));
    if let Some(r) = remedy {
        let _ = write!(cell, "<br><b>fix (checked):</b> {}", esc(&r.text));
    }
    cell
}

fn gouge_table(out: &mut String, list: &[Gouge]) {
    list_head(
        out,
        "ls-gouges",
        "Gouges (part material removed)",
        list.len(),
    );
    if list.is_empty() {
        out.push_str("<p class=\"none\">none</p>\n");
        return;
    }
    out.push_str("<table class=\"list gouge\"><thead><tr><th>line</th><th>Z (mm)</th><th>X Ø (mm)</th><th>area (mm²)</th><th>depth (mm)</th><th>certainty</th><th>why, and the fix latsim checked</th></tr></thead><tbody>\n");
    for (i, g) in list.iter().take(MAX_ROWS).enumerate() {
        let certainty = if g.assumed {
            "possible: tool size assumed, not in the verdict"
        } else {
            "certain"
        };
        let _ = writeln!(
            out,
            "<tr data-line=\"{}\"{}><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td><td>{}</td></tr>",
            g.line,
            extra(i),
            g.line,
            pos(g.z),
            pos(2.0 * g.r),
            esc(&quantity(g.area_mm2)),
            pos(g.depth_mm),
            certainty,
            why(g.cause.as_ref(), g.remedy.as_ref())
        );
    }
    out.push_str("</tbody></table>\n");
    more(out, list.len());
}

/// The legend of the slider drawing.
fn player_legend(out: &mut String, report: &Report) {
    let sw = |out: &mut String, style: &str, label: &str| {
        let _ = write!(
            out,
            "<span class=\"key\"><i style=\"{style}\"></i>{}</span>",
            esc(label)
        );
    };
    out.push_str("<p class=\"legend\">");
    sw(
        out,
        &format!("border:1px solid {};background:#ffffff", colour::BLANK_EDGE),
        "blank",
    );
    if !report.snapshots.is_empty() {
        sw(
            out,
            "border:1px solid #8c7b5a;background:#dccfae",
            "stock still to cut at this move",
        );
    }
    sw(
        out,
        &format!(
            "border:1px solid {};background:{};opacity:.5",
            colour::PART_EDGE,
            colour::PART
        ),
        "final part",
    );
    sw(
        out,
        &format!("border-top:2px solid {}", colour::FEED),
        "feed",
    );
    sw(
        out,
        &format!("border-top:2px dashed {}", colour::RAPID),
        "rapid",
    );
    if report.toolpath.iter().any(|l| l.kind == PathKind::Thread) {
        sw(
            out,
            &format!("border-top:2px solid {}", colour::THREAD),
            "thread",
        );
    }
    sw(out, "border-top:4px solid #e0218a", "current move");
    if !report.tool_outlines.is_empty() {
        sw(
            out,
            "border:1px solid #e0218a;background:rgba(224,33,138,.25)",
            "tool (insert; holder grey)",
        );
    }
    let ghosted = report
        .gouges
        .iter()
        .any(|g| g.remedy.as_ref().is_some_and(|r| !r.ghost.is_empty()));
    if ghosted {
        sw(
            out,
            "border-top:2px dashed #1a7f37",
            "the checked fix's tool, on the gouge's line",
        );
    }
    if !report.fixture.is_empty() {
        sw(
            out,
            &format!(
                "border:1px solid {};background:{}",
                colour::FIXTURE_EDGE,
                colour::FIXTURE
            ),
            "chuck, jaws, tailstock",
        );
    }
    sw(
        out,
        "border:2px solid #111;border-radius:50%;width:10px",
        "tool reference point",
    );
    out.push_str("</p>\n");
}

/// The start of a latsim page up to its header: the document head with the stylesheet,
/// then the title and the verdict in its colour (the report's page and the diff's).
pub(crate) fn page_head(out: &mut String, title: &str, verdict: &str, colour: &str) {
    out.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    out.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    out.push_str("<meta name=\"generator\" content=\"latsim\">\n");
    let _ = writeln!(out, "<title>{}</title>", esc(title));
    let _ = writeln!(out, "<style>\n{STYLE}</style>\n</head>\n<body>");
    let _ = writeln!(
        out,
        "<header><h1>{}</h1><p class=\"verdict\" style=\"color:{colour}\">{}</p></header>",
        esc(title),
        esc(verdict)
    );
}

/// The whole page, showing `svg`, the report picture of `report`.
/// The page's data block, worked out apart from the picture (a long program's toolpath
/// data is most of the page's work, and needs no picture): escaped, with the slider's
/// stride.
pub(crate) struct Data {
    json: String,
    stride: usize,
}

impl Data {
    pub(crate) fn of(report: &Report) -> Self {
        let (json, moves) = data_json(report);
        Self {
            json: script_safe(json),
            stride: moves.stride,
        }
    }
}

/// The page of `report`, whose picture is `svg`.
pub(crate) fn html(report: &Report, svg: &str) -> String {
    page(report, svg, Data::of(report))
}

/// The page of `report` from its picture and its data block.
pub(crate) fn page(report: &Report, svg: &str, data: Data) -> String {
    let Data { json: data, stride } = data;
    let n = report.toolpath.len();

    let mut title = if report.program.is_empty() {
        "latsim report".to_string()
    } else {
        format!("latsim — {}", report.program)
    };
    if !report.stock.description.is_empty() {
        title = format!("{title} — {}", report.stock.description);
    }
    let (verdict, vc) = verdict_text(report);

    let mut out = String::with_capacity(svg.len() + data.len() + 64 * 1024);
    page_head(&mut out, &title, &verdict, vc);
    out.push_str("<nav><a href=\"#ls-sheet\">setup sheet</a> · <a href=\"#ls-picture\">picture</a> · <a href=\"#ls-solid-view\">3D</a> · <a href=\"#ls-player\">moves</a> · <a href=\"#ls-tables\">tables</a> · <a href=\"#ls-findings\">findings</a></nav>\n");

    // 1. The setup sheet.
    sheet::section(&mut out, report);

    // 2. The report picture.
    out.push_str("<section id=\"ls-picture\"><h2>Report picture</h2>\n<div class=\"picture\">\n");
    out.push_str(svg);
    out.push_str("</div></section>\n");

    // 3. The part in 3D.
    solid::section(&mut out, report);

    // 4. The move slider.
    player_section(&mut out, report, n, stride);

    // 5. Tables.
    tables_section(&mut out, report);

    let _ = writeln!(
        out,
        "<script type=\"application/json\" id=\"ls-data\">{data}</script>"
    );
    // the 3D view in a script of its own: neither stops the other
    let _ = writeln!(
        out,
        "<script>\n{TOOLS_SCRIPT}{SCRIPT}</script>\n<script>\n{}</script>\n</body>\n</html>",
        solid::SCRIPT
    );
    out
}

/// The move slider's section: its buttons, legend and canvas, and notes on what it shows.
fn player_section(out: &mut String, report: &Report, n: usize, stride: usize) {
    out.push_str("<section id=\"ls-player\"><h2>Step through the moves</h2>\n");
    out.push_str("<noscript><p class=\"note\">The move slider needs JavaScript.</p></noscript>\n");
    let _ = writeln!(
        out,
        "<div class=\"controls\"><button type=\"button\" id=\"ls-first\" title=\"first move (Home)\">|◀</button><button type=\"button\" id=\"ls-prev\" title=\"previous move (←)\">◀</button><button type=\"button\" id=\"ls-play\" title=\"play / pause\">play</button><button type=\"button\" id=\"ls-next\" title=\"next move (→)\">▶</button><button type=\"button\" id=\"ls-last\" title=\"last move (End)\">▶|</button>\
<input type=\"range\" id=\"ls-slider\" min=\"0\" max=\"{n}\" step=\"1\" value=\"{n}\" aria-label=\"move\">\
<output id=\"ls-label\" for=\"ls-slider\">move {n} / {n}</output></div>"
    );
    player_legend(out, report);
    out.push_str("<div class=\"canvasbox\"><canvas id=\"ls-canvas\" width=\"1200\" height=\"600\"></canvas></div>\n");
    let mut notes = vec![
        "The ← and → keys step one move (with the slider focused, also Page Up/Down and Home/End); a link ending in #move=20 opens at move 20; click a row of the findings tables to jump to the first move of its line.".to_string(),
    ];
    if stride > 1 {
        notes.push(format!(
            "Toolpath thinned for this page: {} moves, only every {} is drawn (at most about {} points); the slider still counts every move and names the nearest drawn one.",
            grouped(n as f64, 0),
            ordinal(stride),
            grouped(PATH_POINT_CAP as f64, 0)
        ));
    }
    if report.snapshots.is_empty() {
        notes.push(
            "No stock snapshots in this report: the drawing shows the blank and the final part only."
                .to_string(),
        );
    }
    for note in notes {
        let _ = writeln!(out, "<p class=\"note\">{}</p>", esc(&note));
    }
    out.push_str("</section>\n");
}

/// The summary and the findings tables.
fn tables_section(out: &mut String, report: &Report) {
    out.push_str("<section id=\"ls-tables\"><h2>Summary</h2>\n");
    summary_table(out, report);
    out.push_str("</section>\n<section id=\"ls-findings\"><h2>Findings</h2>\n");
    diag_table(out, "ls-alarms", "Alarms", &report.alarms, "alarm");
    crash_table(
        out,
        "ls-crashes",
        "Crashes (rapids into stock, tool bodies, chuck and tailstock)",
        &report.crashes,
    );
    crash_table(
        out,
        "ls-scrapes",
        "Rapid scrapes (rapids that re-cut no deeper than rapid_cut_tol: warnings)",
        &report.rapid_cuts,
    );
    gouge_table(out, &report.gouges);
    threads::threads_table(out, &report.threads);
    diag_table(out, "ls-warnings", "Warnings", &report.warnings, "warning");
    let quiet = report.alarms.is_empty()
        && report.crashes.is_empty()
        && report.rapid_cuts.is_empty()
        && report.gouges.is_empty()
        && report.threads.is_empty()
        && report.warnings.is_empty();
    if quiet {
        // the printed sheet leaves the empty lists out
        out.push_str("<p class=\"print-only\">No alarm, crash, rapid scrape, gouge, thread or warning.</p>\n");
    }
    out.push_str("</section>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn assets_cannot_break_out() {
        for s in [STYLE, SCRIPT, TOOLS_SCRIPT, solid::SCRIPT] {
            let l = s.to_ascii_lowercase();
            assert!(!l.contains("</"), "`</` in an inline asset");
            assert!(!l.contains("http"), "network reference in an inline asset");
            assert!(!l.contains("import"), "import in an inline asset");
        }
    }

    #[test]
    fn json_is_made_script_safe() {
        assert_eq!(
            script_safe(r#"{"a":"</script>"}"#.to_string()),
            r#"{"a":"\u003c/script>"}"#
        );
    }

    #[test]
    fn ordinals() {
        assert_eq!(ordinal(3), "3rd");
        assert_eq!(ordinal(11), "11th");
        assert_eq!(ordinal(21), "21st");
        assert_eq!(ordinal(112), "112th");
    }

    #[test]
    fn coordinates_are_rounded_and_clamped() {
        assert_eq!(c4(1.234_567), "1.2346");
        assert_eq!(c4(1e300), "10000000");
        assert_eq!(c4(-0.000_01), "0");
    }
}
