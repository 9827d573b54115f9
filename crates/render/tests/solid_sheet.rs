//! The HTML page's 3D view and setup sheet (issue 35): the solid is made from a section
//! thinned to a bounded number of points, whatever the part; the sheet lists the tools with
//! their offsets, ISO designations and times, and the workholding; the print style keeps
//! the findings to a few rows each.
mod common;

use render::{Diagnostic, Fixture, Report, Shape, ToolEntry};

/// The embedded data block, parsed.
fn data(page: &str) -> serde_json::Value {
    let open = r#"<script type="application/json" id="ls-data">"#;
    let start = page.find(open).expect("data block") + open.len();
    let len = page[start..].find("</script>").expect("data block end");
    serde_json::from_str(&page[start..start + len]).expect("data block is JSON")
}

/// The rings of a `solid` layer as `[z, x]` points.
fn layer(d: &serde_json::Value, key: &str) -> Vec<Vec<[f64; 2]>> {
    d["solid"][key]
        .as_array()
        .unwrap_or_else(|| panic!("solid.{key}"))
        .iter()
        .map(|r| {
            let v: Vec<f64> = r
                .as_array()
                .unwrap()
                .iter()
                .map(|c| c.as_f64().unwrap())
                .collect();
            v.chunks(2).map(|p| [p[0], p[1]]).collect()
        })
        .collect()
}

fn points(rings: &[Vec<[f64; 2]>]) -> usize {
    rings.iter().map(Vec::len).sum()
}

fn shape(outer: Vec<[f64; 2]>) -> Shape {
    Shape {
        outer,
        holes: vec![],
    }
}

/// A small section reaches the script as it is: the groove bar's part ring in `[z, x]`,
/// x the diameter (hand: the ring of `common::groove_bar`, r doubled), the blank and the
/// gouge beside it.
#[test]
fn a_small_section_reaches_the_solid_as_it_is() {
    let page = render::html(&common::groove_bar());
    let d = data(&page);
    let part = layer(&d, "part");
    assert_eq!(part.len(), 1);
    assert_eq!(
        part[0],
        [
            [-60.0, 0.0],
            [0.0, 0.0],
            [0.0, 34.0],
            [-1.0, 36.0],
            [-20.0, 36.0],
            [-20.0, 28.0],
            [-25.0, 28.0],
            [-25.0, 36.0],
            [-40.0, 36.0],
            [-40.0, 40.0],
            [-60.0, 40.0]
        ]
    );
    assert_eq!(
        layer(&d, "blank")[0],
        [[-60.0, 0.0], [0.0, 0.0], [0.0, 40.0], [-60.0, 40.0]]
    );
    assert_eq!(
        layer(&d, "gouges")[0],
        [[-25.0, 28.0], [-20.0, 28.0], [-20.0, 28.4], [-25.0, 28.4]]
    );
    assert!(layer(&d, "leftovers").is_empty());
    assert!(page.contains(r#"<canvas id="ls-solid""#));
    assert!(page.contains("getContext('webgl'"));
    assert!(page.contains(r##"<a href="#ls-solid-view">3D</a>"##));
}

/// A sawtooth section of 200 000 points (and findings of 40 000) is thinned to the caps
/// (3 000, 2 000, 500 points) and keeps its extent within a fraction of a mm.
#[test]
fn a_huge_section_is_thinned_to_a_bounded_count() {
    let teeth = 100_000;
    let mut ring: Vec<[f64; 2]> = (0..2 * teeth)
        .map(|i| {
            let z = -100.0 + 100.0 * (i / 2) as f64 / teeth as f64;
            let r = if (i / 2) % 2 == 0 { 20.0 } else { 19.0 };
            [z + if i % 2 == 1 { 0.0005 } else { 0.0 }, r]
        })
        .collect();
    ring.push([0.0, 0.0]);
    ring.push([-100.0, 0.0]);
    ring.rotate_right(1);
    let band = |n: usize, r0: f64| -> Shape {
        let mut b: Vec<[f64; 2]> = (0..n)
            .map(|i| [-100.0 + 50.0 * i as f64 / n as f64, r0])
            .collect();
        b.extend(
            (0..n)
                .rev()
                .map(|i| [-100.0 + 50.0 * i as f64 / n as f64, r0 + 0.5]),
        );
        shape(b)
    };
    let mut r = Report {
        program: "saw.nc".into(),
        final_part: vec![shape(ring)],
        gouge_shapes: vec![band(20_000, 20.0)],
        leftovers: vec![band(20_000, 18.0)],
        ..Report::default()
    };
    r.stock.shapes = vec![band(5_000, 0.0)];
    let d = data(&render::html(&r));
    let part = layer(&d, "part");
    assert!(points(&part) <= 3_000, "{}", points(&part));
    assert!(points(&part) > 100);
    for (key, cap) in [("gouges", 2_000), ("leftovers", 2_000), ("blank", 500)] {
        let n = points(&layer(&d, key));
        assert!(n <= cap && n >= 3, "{key}: {n}");
    }
    let zs: Vec<f64> = part[0].iter().map(|p| p[0]).collect();
    let xs: Vec<f64> = part[0].iter().map(|p| p[1]).collect();
    let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    let max = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!(
        (min(&zs) + 100.0).abs() < 0.5 && max(&zs).abs() < 0.5,
        "{zs:?}"
    );
    assert!(min(&xs).abs() < 1e-9 && (max(&xs) - 40.0).abs() < 1e-9);
}

/// Tool T01 called with offsets 01 and 11, ISO designation and times; a default T03; T04 in
/// the table without its size; a chuck with hard jaws and the stick-out: what the sheet says
/// of them.
#[test]
fn setup_sheet_lists_tools_and_workholding() {
    let mut r = common::groove_bar();
    r.tool_list = vec![
        ToolEntry {
            number: 1,
            offsets: vec![1, 11],
            description: "turning C 80°, r0.8, tip 3, κr 95°".into(),
            designation: Some("CNMG 120408 in PCLNR 2525M12".into()),
            assumed: false,
            in_table: true,
            from_moves: false,
            time_s: 95.4,
            cut_time_s: 81.6,
        },
        ToolEntry {
            number: 3,
            offsets: vec![3],
            description: "turning D 55°, r0.4, tip 3, κr 93°".into(),
            designation: None,
            assumed: true,
            in_table: false,
            from_moves: false,
            time_s: 4.0,
            cut_time_s: 2.5,
        },
        ToolEntry {
            number: 4,
            offsets: vec![4],
            description: "turning C 80°, r0.8, tip 3, κr 95°".into(),
            designation: None,
            assumed: true,
            in_table: true,
            from_moves: false,
            time_s: 4.0,
            cut_time_s: 2.5,
        },
    ];
    r.fixture = vec![Fixture {
        name: "chuck jaw".into(),
        shapes: vec![shape(vec![
            [-60.0, 20.0],
            [-45.0, 20.0],
            [-45.0, 45.0],
            [-60.0, 45.0],
        ])],
    }];
    r.stick_out_mm = Some(45.0);
    let page = render::html(&r);
    let sheet = &page[page.find(r#"<section id="ls-sheet">"#).unwrap()..];
    let sheet = &sheet[..sheet.find("</section>").unwrap()];
    for needle in [
        "<td class=\"n\">T01</td><td class=\"n\">01, 11</td><td>turning C 80°, r0.8, tip 3, κr 95°</td><td><code>CNMG 120408 in PCLNR 2525M12</code></td><td class=\"n\">1 min 22 s</td><td class=\"n\">1 min 35 s</td>",
        "<td class=\"n\">T03</td><td class=\"n\">03</td><td>turning D 55°, r0.4, tip 3, κr 93° (not in the tool table: the default assumed)</td><td><code>—</code></td><td class=\"n\">2.5 s</td><td class=\"n\">4 s</td>",
        "<td class=\"n\">T04</td><td class=\"n\">04</td><td>turning C 80°, r0.8, tip 3, κr 95° (its size not in the tool table: assumed)</td>",
        "<th scope=\"row\">jaws</th><td>hard jaws gripping 15 mm over Ø40, 25 mm high</td>",
        "<th scope=\"row\">stick-out</th><td>45 mm</td>",
        "<th scope=\"row\">blank</th><td>bar Ø40 × 60, face at Z0</td>",
    ] {
        assert!(sheet.contains(needle), "missing {needle}\n{sheet}");
    }
    // the sheet comes first: printed, it heads the first page
    assert!(page.find("id=\"ls-sheet\"") < page.find("id=\"ls-picture\""));
}

/// Without a tool list (a report made by other means) the sheet lists the tools' lines.
#[test]
fn setup_sheet_falls_back_to_the_tool_lines() {
    let mut r = common::groove_bar();
    r.tools = vec!["T01 · 3.0 s · turning V 35°".into()];
    let page = render::html(&r);
    assert!(page.contains("<tr><td colspan=\"6\">T01 · 3.0 s · turning V 35°</td></tr>"));
    assert!(page.contains("none given (latsim run --chuck"));
}

/// The print style: A4 or Letter margins, the slider hidden, empty lists left out; the
/// findings tables print their first 6 rows and say how many more there are.
#[test]
fn printed_findings_are_kept_short() {
    let mut r = common::groove_bar();
    r.warnings = (1..=20)
        .map(|i| Diagnostic {
            line: i,
            column: 1,
            code: "W-X".into(),
            message: format!("warning {i}"),
        })
        .collect();
    let page = render::html(&r);
    assert!(page.contains("@media print"));
    assert!(page.contains("@page { margin: 10mm; }"));
    let warnings = &page[page.find("id=\"ls-warnings\"").unwrap()..];
    let rows: Vec<&str> = warnings.split("<tr data-line=").skip(1).collect();
    assert_eq!(rows.len(), 20);
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row.contains(r#" class="extra""#), i >= 6, "row {i}: {row}");
    }
    assert!(warnings.contains("… 14 more not printed (see the page on screen or the JSON report)."));
    // no alarm: its header is marked empty, which print leaves out
    assert!(page.contains(r#"<h3 id="ls-alarms" class="empty">"#));
    // the crash list has one row: printed whole, nothing more said
    let crashes =
        &page[page.find("id=\"ls-crashes\"").unwrap()..page.find("id=\"ls-scrapes\"").unwrap()];
    assert!(!crashes.contains("extra") && !crashes.contains("more not printed"));
}
