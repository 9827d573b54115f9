//! The HTML page: self-contained, has the slider, the tables and the embedded toolpath,
//! escapes what it shows, stays bounded for huge toolpaths, never panics.
mod common;

use render::{Diagnostic, PathKind, PathLine, Report, Shape, Snapshot};

/// The embedded data block, parsed.
fn data(page: &str) -> serde_json::Value {
    let open = r#"<script type="application/json" id="ls-data">"#;
    let start = page.find(open).expect("data block") + open.len();
    let len = page[start..].find("</script>").expect("data block end");
    serde_json::from_str(&page[start..start + len]).expect("data block is JSON")
}

/// Every `http(s)://` is an XML namespace, and nothing is fetched from elsewhere.
fn assert_self_contained(page: &str) {
    for scheme in ["http://", "https://"] {
        for (i, _) in page.match_indices(scheme) {
            let rest = &page[i + scheme.len()..];
            assert!(
                rest.starts_with("www.w3.org/"),
                "external reference: {}",
                &page[i..(i + 80).min(page.len())]
            );
        }
    }
    let lower = page.to_ascii_lowercase();
    for bad in [
        "<link", " src=", "@import", "<iframe", "<object", "<embed", "<img", "//cdn",
    ] {
        assert!(!lower.contains(bad), "found {bad}");
    }
    // Only local fragment references.
    for (i, _) in lower.match_indices("url(") {
        assert!(
            lower[i + 4..].starts_with('#'),
            "url() to a file: {}",
            &page[i..(i + 40).min(page.len())]
        );
    }
    for (i, _) in lower.match_indices("href=\"") {
        assert!(
            lower[i + 6..].starts_with('#'),
            "href to a file: {}",
            &page[i..(i + 40).min(page.len())]
        );
    }
}

#[test]
fn page_is_self_contained_with_slider_and_picture() {
    let page = render::html(&common::groove_bar());
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert!(page.trim_end().ends_with("</html>"));
    assert_self_contained(&page);
    // The report picture, inline.
    assert!(page.contains(r#"<svg font-family="DejaVu Sans""#));
    assert!(page.contains(r#"xmlns="http://www.w3.org/2000/svg">"#));
    assert!(page.contains(r#"id="title-block""#));
    // The slider, its canvas and label.
    assert!(page.contains(r#"<input type="range" id="ls-slider" min="0" max="11""#));
    assert!(page.contains(r#"<canvas id="ls-canvas""#));
    assert!(page.contains(r#"id="ls-label""#));
    // Exactly two scripts: the data and the player (inline).
    assert_eq!(page.matches("<script").count(), 3);
    assert!(page.contains("<script>\n"));
    assert!(page.contains("keydown"));
    assert!(page.contains("move="));
    assert!(!page.contains("NaN"));
}

#[test]
fn tables_list_verdict_summary_and_findings() {
    let page = render::html(&common::groove_bar());
    for needle in [
        "CRASH — 1 crash, 1 gouge (0.2 mm deep)",
        "<th scope=\"row\">program</th><td>O0042.nc</td>",
        "bar Ø40 × 60, face at Z0",
        "T01 turning D 55°, r0.4, tip 3<br>T02 grooving 5 mm",
        "11 (rapid 5, feed 6)",
        "163.0 mm² section / 19 123 mm³",
        "1 min 42 s",
        "<th scope=\"row\">tolerance</th><td>0.01 mm</td>",
        "<th scope=\"row\">overcut</th><td>1.00 mm², max 0.2 mm</td>",
        "Crashes (rapids into stock, tool bodies, chuck and tailstock) <span class=\"count\">(1)</span>",
        "Gouges (part material removed) <span class=\"count\">(1)</span>",
        "Warnings <span class=\"count\">(1)</span>",
        "Alarms <span class=\"count\">(0)</span>",
    ] {
        assert!(page.contains(needle), "missing {needle}");
    }
    // The gouge row: line 11, Z −22.5, X Ø28 (r 14), 1 mm², 0.2 mm deep, certain.
    assert!(
        page.contains(
            "<tr data-line=\"11\"><td class=\"n\">11</td><td class=\"n\">-22.5</td><td class=\"n\">28</td><td class=\"n\">1.00</td><td class=\"n\">0.2</td><td>certain</td><td></td></tr>"
        ),
        "gouge row"
    );
    // The crash row: line 14 col 1, Z −46.667, X Ø36, 21.5 mm².
    assert!(
        page.contains(
            "<tr data-line=\"14\"><td class=\"n\">14</td><td class=\"n\">1</td><td class=\"n\">-46.667</td><td class=\"n\">36</td><td class=\"n\">21.5</td>"
        ),
        "crash row"
    );
    assert!(page.contains("<code>W-TOOL-DEFAULT</code>"));
}

#[test]
fn text_is_escaped() {
    let mut r = common::groove_bar();
    r.program = "<script>alert(1)</script>.nc".into();
    r.stock.description = "bar & <b>bold</b>".into();
    r.warnings.push(Diagnostic {
        line: 3,
        column: 2,
        code: "W-<x>".into(),
        message: "</script><script>alert(2)</script>".into(),
    });
    let page = render::html(&r);
    // Only our own three script elements (data, player, 3D view).
    assert_eq!(page.matches("<script").count(), 3);
    assert_eq!(page.matches("</script>").count(), 3);
    assert!(page.contains("&lt;script&gt;alert(1)&lt;/script&gt;.nc"));
    assert!(page.contains("bar &amp; &lt;b&gt;bold&lt;/b&gt;"));
    assert!(page.contains("<code>W-&lt;x&gt;</code>"));
    assert!(!page.contains("<b>bold"));
    data(&page);
}

#[test]
fn embedded_toolpath_parses_back() {
    let r = common::groove_bar();
    let page = render::html(&r);
    let d = data(&page);
    assert_eq!(d["moves"], 11);
    assert_eq!(d["stride"], 1);
    let path = d["path"].as_array().unwrap();
    assert_eq!(path.len(), r.toolpath.len());
    for (i, (m, l)) in path.iter().zip(&r.toolpath).enumerate() {
        let m = m.as_array().unwrap();
        assert_eq!(m[0], i + 1, "move number");
        let kind = match l.kind {
            PathKind::Rapid => 0,
            PathKind::Feed => 1,
            PathKind::Thread => 2,
        };
        assert_eq!(m[1], kind);
        assert_eq!(m[2], l.line);
        // Program coordinates: z, x = diameter.
        let coords: Vec<f64> = m[3..].iter().map(|v| v.as_f64().unwrap()).collect();
        let want: Vec<f64> = l.points.iter().flat_map(|p| [p[0], 2.0 * p[1]]).collect();
        assert_eq!(coords, want);
    }
    assert_eq!(d["crashes"][0][0], 14);
    assert_eq!(d["blank"].as_array().unwrap().len(), 1);
    assert_eq!(d["snapshots"].as_array().unwrap().len(), 0);
    assert!(page.contains("No stock snapshots"));
}

#[test]
fn coordinates_are_rounded_to_4_decimals() {
    let mut r = common::groove_bar();
    r.toolpath = vec![PathLine {
        kind: PathKind::Feed,
        line: 7,
        points: vec![[1.234_567_89, 2.000_011], [-0.000_01, 3.0]].into(),
    }];
    let d = data(&render::html(&r));
    let m = d["path"][0].as_array().unwrap();
    assert_eq!(m[3].as_f64(), Some(1.2346));
    assert_eq!(m[4].as_f64(), Some(4.0));
    assert_eq!(m[5].as_f64(), Some(0.0));
    assert_eq!(m[6].as_f64(), Some(6.0));
}

#[test]
fn snapshots_are_embedded_in_move_order() {
    let mut r = common::groove_bar();
    let sq = |z0: f64, r1: f64| Shape {
        outer: vec![[z0, 0.0], [0.0, 0.0], [0.0, r1], [z0, r1]],
        holes: vec![],
    };
    r.snapshots = vec![
        Snapshot {
            after_move: 6,
            shapes: vec![sq(-60.0, 18.0)],
        },
        Snapshot {
            after_move: 0,
            shapes: vec![sq(-60.0, 20.0)],
        },
    ];
    let page = render::html(&r);
    let d = data(&page);
    let s = d["snapshots"].as_array().unwrap();
    assert_eq!(s.len(), 2);
    assert_eq!(s[0]["after"], 0);
    assert_eq!(s[1]["after"], 6);
    // x is the diameter.
    let ring: Vec<f64> = s[1]["rings"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(ring, [-60.0, 0.0, 0.0, 0.0, 0.0, 36.0, -60.0, 36.0]);
    assert!(!page.contains("No stock snapshots"));
    assert!(page.contains("stock still to cut at this move"));
}

#[test]
fn million_segments_stay_bounded() {
    let r = common::many_segments(1_000_000);
    let t = std::time::Instant::now();
    let page = render::html(&r);
    println!(
        "html of 10^6 segments: {} bytes in {:?}",
        page.len(),
        t.elapsed()
    );
    assert!(page.len() < 30_000_000, "{} bytes", page.len());
    assert_self_contained(&page);
    assert!(page.contains("Toolpath thinned for this page"));
    assert!(page.contains(r#"max="1000000""#));
    let d = data(&page);
    assert_eq!(d["moves"], 1_000_000);
    let stride = d["stride"].as_u64().unwrap() as usize;
    assert!(stride > 1);
    let path = d["path"].as_array().unwrap();
    let points: usize = path
        .iter()
        .map(|m| (m.as_array().unwrap().len() - 3) / 2)
        .sum();
    assert!(points <= 200_000, "{points} points");
    // Every stride-th move and the last, in order.
    assert_eq!(path[0][0], 1);
    assert_eq!(path[1][0], 1 + stride);
    assert_eq!(path[path.len() - 1][0], 1_000_000);
}

#[test]
fn hundred_thousand_segments_size() {
    let r = common::many_segments(100_000);
    let page = render::html(&r);
    println!("html of 10^5 segments: {} bytes", page.len());
    assert!(page.len() < 10_000_000, "{} bytes", page.len());
    let d = data(&page);
    assert_eq!(d["stride"], 1);
    assert_eq!(d["path"].as_array().unwrap().len(), 100_000);
}

#[test]
fn output_is_deterministic() {
    let mut r = common::groove_bar();
    r.snapshots = vec![Snapshot {
        after_move: 3,
        shapes: r.final_part.clone(),
    }];
    assert_eq!(render::html(&r), render::html(&r));
}

#[test]
fn degenerate_reports_do_not_panic() {
    let nan = f64::NAN;
    let mut reports = common::degenerate_reports();
    reports[2].snapshots.push(Snapshot {
        after_move: usize::MAX,
        shapes: vec![Shape {
            outer: vec![[nan, 0.0]; 5],
            holes: vec![],
        }],
    });
    for r in &reports {
        let page = render::html(r);
        assert!(!page.contains("NaN"), "NaN in page");
        assert_self_contained(&page);
        let d = data(&page);
        assert_eq!(
            d["path"].as_array().unwrap().len(),
            r.toolpath.len(),
            "one entry per move"
        );
    }
}

#[test]
#[ignore = "writes pages for a human: cargo test -p render --test html -- --ignored"]
fn write_pages() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/out");
    std::fs::create_dir_all(&dir).unwrap();
    let mut r = common::groove_bar();
    // A few snapshots: the blank, after the turning pass, after the groove.
    let blank = r.stock.shapes.clone();
    let turned = Shape {
        outer: vec![
            [-60.0, 0.0],
            [0.0, 0.0],
            [0.0, 17.0],
            [-1.0, 18.0],
            [-40.0, 18.0],
            [-40.0, 20.0],
            [-60.0, 20.0],
        ],
        holes: vec![],
    };
    r.snapshots = vec![
        Snapshot {
            after_move: 0,
            shapes: blank,
        },
        Snapshot {
            after_move: 5,
            shapes: vec![turned],
        },
        Snapshot {
            after_move: 9,
            shapes: r.final_part.clone(),
        },
    ];
    std::fs::write(dir.join("groove_bar.html"), render::html(&r)).unwrap();
    std::fs::write(dir.join("empty.html"), render::html(&Report::default())).unwrap();
    std::fs::write(
        dir.join("many.html"),
        render::html(&common::many_segments(1_000_000)),
    )
    .unwrap();
}

/// Crash, rapid scrape, gouge and leftover are told apart (issue 13): the scrape gets its
/// own marker, label and legend entry in the picture and its own table in the page, and a
/// crash's depth is shown.
#[test]
fn rapid_scrapes_are_shown_apart_from_crashes() {
    let mut r = common::groove_bar();
    r.rapid_cuts.push(render::Crash {
        line: 9,
        column: 1,
        z: -38.1,
        r: 24.8,
        area_mm2: 0.014,
        depth_mm: 0.07,
        body: None,
        ..Default::default()
    });
    let svg = render::svg(&r);
    assert!(svg.contains("scrape line 9"), "the scrape is labelled");
    assert!(svg.contains("rapid scrape"), "the legend names it");
    assert!(
        svg.contains("crash line 14"),
        "the crash keeps its own label"
    );
    let page = render::html(&r);
    let scrapes = &page[page.find("id=\"ls-scrapes\"").expect("a scrape table")..];
    let table = &scrapes[..scrapes.find("</table>").expect("its rows")];
    assert!(table.contains("data-line=\"9\""), "{table}");
    assert!(table.contains("0.07"), "its depth: {table}");
    let crashes = &page[page.find("id=\"ls-crashes\"").unwrap()..];
    let crash_rows = &crashes[..crashes.find("</table>").unwrap()];
    assert!(
        !crash_rows.contains("data-line=\"9\""),
        "a scrape is no crash"
    );
    assert!(
        crash_rows.contains(">1<"),
        "the crash's depth 1 mm: {crash_rows}"
    );
}

/// A sawtooth ring of `teeth` sub-pixel teeth (a 100 000-vertex blank profile of issue 17).
fn sawtooth(teeth: usize, r0: f64) -> Shape {
    let mut outer = vec![[-80.0, 0.0], [0.0, 0.0]];
    for k in 0..=2 * teeth {
        let z = -80.0 * k as f64 / (2 * teeth) as f64;
        outer.push([z, if k % 2 == 0 { r0 } else { r0 + 5.0 }]);
    }
    Shape {
        outer,
        holes: vec![],
    }
}

/// Issue 16/17: a report of 10^6 moves with a 100 000-vertex blank, part, target and 32
/// snapshots of it (issue 17's sawtooth profile), and 30 000 warnings and alarms, makes a
/// page within 10 MB that still lists the first rows, says how many more there are and
/// keeps an even selection of the snapshots.
#[test]
fn big_report_page_stays_within_ten_megabytes() {
    let mut r = common::many_segments(1_000_000);
    r.stock.shapes = vec![sawtooth(50_000, 40.0)];
    r.final_part = vec![sawtooth(50_000, 38.0)];
    r.intended = vec![sawtooth(50_000, 37.0)];
    r.snapshots = (0..=31)
        .map(|k| Snapshot {
            after_move: k * 1_000_000 / 31,
            shapes: vec![sawtooth(50_000, 40.0 - 0.05 * k as f64)],
        })
        .collect();
    let long = "x".repeat(200);
    r.warnings = (0..30_000)
        .map(|i| Diagnostic {
            line: i,
            column: 1,
            code: "LS-TEST".into(),
            message: format!("warning {i} {long}"),
        })
        .collect();
    r.alarms = r.warnings.clone();
    let page = render::html(&r);
    assert!(page.len() <= 10_000_000, "{} bytes", page.len());
    assert_self_contained(&page);
    assert!(page.contains("warning 999 "));
    assert!(!page.contains("warning 1000 "));
    assert!(page.contains("more not listed"), "the count of the rest");
    let d = data(&page);
    let snaps = d["snapshots"].as_array().unwrap();
    assert!(snaps.len() >= 8, "{}", snaps.len());
}
