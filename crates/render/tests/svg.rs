//! The SVG: layers and texts present, sizes bounded for huge toolpaths, no panics.
mod common;

use render::Shape;

#[test]
fn has_layers_legend_and_title_block() {
    let s = render::svg(&common::groove_bar());
    assert!(s.starts_with("<svg"));
    assert!(s.trim_end().ends_with("</svg>"));
    for needle in [
        r#"id="toolpath""#,
        r#"id="legend""#,
        r#"id="title-block""#,
        r#"id="details""#,
        r#"font-family="DejaVu Sans""#,
        "Z (mm)",
        "X/2 (mm)",
        "CRASH — 1 crash, 1 gouge (0.2 mm deep)",
        "crash line 14",
        "1 min 42 s",
        "bar Ø40 × 60, face at Z0",
        "warnings (1)",
        "line 9: T02",
        "clip-path=",
    ] {
        assert!(s.contains(needle), "missing {needle}");
    }
    assert!(!s.contains("NaN"));
    // Ids are unique.
    let mut ids: Vec<&str> = s
        .split(" id=\"")
        .skip(1)
        .map(|t| t.split('"').next().unwrap())
        .collect();
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n, "duplicate ids");
}

/// The main view is drawn straight on the page: no group opacity nor clip path around it
/// (resvg draws such a group on a layer of its own and blends or masks it back: 40 % of a
/// small program's PNG). The white matte around its frame hides what it draws past the
/// frame (the reference pictures show it), and the toolpath's opacity is its stroke's.
#[test]
fn main_view_draws_on_the_page_without_layers() {
    let s = render::svg(&common::o0008_groove());
    let matte = s
        .find("M0 0H1600V1000H0Z")
        .expect("the matte around the main view");
    let main = &s[..matte];
    assert!(main.contains(r#"id="toolpath""#));
    assert!(!main.contains("clip-path="), "a clip path in the main view");
    assert!(
        !main.contains(" opacity="),
        "a group opacity in the main view"
    );
    assert!(main.contains(r#"stroke-opacity="0.9""#));
}

#[test]
fn clean_report_says_clean() {
    let mut r = common::groove_bar();
    r.crashes.clear();
    r.gouges.clear();
    r.gouge_shapes.clear();
    r.verdict = render::Verdict::Clean;
    let s = render::svg(&r);
    assert!(s.contains("CLEAN — no gouge, no crash"));
    assert!(!s.contains(r#"id="details""#));
}

#[test]
fn million_segments_stay_bounded() {
    let r = common::many_segments(1_000_000);
    let t = std::time::Instant::now();
    let s = render::svg(&r);
    println!(
        "svg of 10^6 segments: {} bytes in {:?}",
        s.len(),
        t.elapsed()
    );
    // 200k points at ~16 bytes, plus the page.
    assert!(s.len() < 5_000_000, "{} bytes", s.len());
    assert!(s.contains("toolpath thinned"));
}

#[test]
fn small_toolpath_is_not_thinned() {
    let s = render::svg(&common::groove_bar());
    assert!(!s.contains("toolpath thinned"));
}

#[test]
fn degenerate_reports_do_not_panic() {
    let mut reports = common::degenerate_reports();
    let mut r = common::groove_bar();
    r.final_part.clear();
    reports.push(r);
    let mut r = common::groove_bar();
    r.toolpath.clear();
    r.stock.shapes.clear();
    reports.push(r);
    // Many diagnostics, tools and long words.
    let mut r = common::groove_bar();
    for i in 0..50 {
        r.alarms.push(render::Diagnostic {
            line: i,
            column: 1,
            code: "E-X".into(),
            message: format!("alarm {i} {}", "x".repeat(200)),
        });
    }
    r.tools = (0..20)
        .map(|i| format!("T{i:02} {}", "long ".repeat(30)))
        .collect();
    r.program = "<&>\"".repeat(100);
    reports.push(r);
    for r in &reports {
        let s = render::svg(r);
        assert!(
            !s.contains("NaN") && !s.contains("inf"),
            "non-finite number in SVG"
        );
        render::png(r).expect("renders");
        serde_json::from_str::<serde_json::Value>(&render::json(r)).expect("valid JSON");
    }
}

#[test]
fn groove_report_has_a_groove_detail_with_corner_labels() {
    let s = render::svg(&common::o0008_groove());
    assert!(s.contains(r#"id="details""#));
    assert!(s.contains(r#"class="groove" data-line="2""#));
    assert!(
        s.contains("detail 1: groove line 2 (deviation ≤ 0.001 mm)"),
        "groove title"
    );
    for label in [
        "P1 Z30.00 Φ50.00",
        "P2 Z20.00 Φ30.00",
        "P3 Z10.00 Φ30.00",
        "P4 Z-7.32 Φ50.00",
    ] {
        assert!(s.contains(label), "missing corner label {label}");
    }
    assert!(!s.contains("NaN"));
}

#[test]
fn grooves_come_after_findings_and_insets_stay_bounded() {
    let groove = render::Groove {
        line: 4,
        ring: vec![[-20.0, 18.0], [-20.0, 14.0], [-25.0, 14.0], [-25.0, 18.0]],
        deviation_mm: Some(0.0),
    };
    // One crash, one gouge, one groove: three insets, the groove last.
    let mut r = common::groove_bar();
    r.grooves.push(groove.clone());
    let s = render::svg(&r);
    assert!(s.contains("detail 1: crash"));
    assert!(s.contains("detail 2: gouge"));
    assert!(s.contains("detail 3: groove line 4"), "groove is third");
    assert!(s.contains("groove line 4 (deviation ≤ 0.001 mm)"));
    // The title shows the measured deviation rounded up to a micron; unmeasured, none.
    let mut r2 = r.clone();
    r2.grooves[0].deviation_mm = Some(0.2 + 1e-12);
    assert!(render::svg(&r2).contains("groove line 4 (deviation ≤ 0.2 mm)"));
    r2.grooves[0].deviation_mm = None;
    assert!(render::svg(&r2).contains("detail 3: groove line 4</text>"));
    // A second crash: the findings take the three places, the groove is left out.
    r.crashes.push(render::Crash {
        line: 30,
        column: 1,
        z: -55.0,
        r: 19.0,
        area_mm2: 4.0,
        depth_mm: 1.0,
        body: None,
        ..Default::default()
    });
    let s = render::svg(&r);
    assert!(s.contains("detail 3: gouge"));
    assert!(!s.contains("groove line 4"));
    assert!(!s.contains("detail 4"));
}

#[test]
fn odd_grooves_do_not_panic() {
    let nan = f64::NAN;
    for ring in [
        vec![],
        vec![[0.0, 1.0]],
        vec![[0.0, 1.0], [0.0, 1.0], [0.0, 1.0]],
        vec![[nan, 1.0], [2.0, nan], [1.0, 1.0]],
        vec![[0.0, 20.0], [1e-7, 19.0], [0.0, 18.0]],
        vec![[1e300, 1.0], [-1e300, 2.0], [0.0, 3.0]],
    ] {
        let mut r = common::o0008_groove();
        r.grooves = vec![render::Groove {
            line: 9,
            ring,
            deviation_mm: Some(f64::NAN),
        }];
        let s = render::svg(&r);
        assert!(!s.contains("NaN") && !s.contains("inf"));
        render::png(&r).expect("renders");
    }
}

#[test]
fn leftover_gets_an_outline_and_an_inset() {
    let r = common::rough_band();
    let s = render::svg(&r);
    // The band (0.25 mm, under a pixel in the main view) is outlined 2 px wide: in the
    // main view and again in its inset.
    assert_eq!(
        s.matches(r#"<g class="leftover-edge">"#).count(),
        2,
        "outlines"
    );
    let edge = s.split(r#"<g class="leftover-edge">"#).nth(1).unwrap();
    assert!(
        edge.contains(r##"stroke="#d9650b""##),
        "darker orange stroke"
    );
    // Its stroke width is 2 px at the main view's scale (mm under the transform).
    let main = s
        .split(r#"id="section" transform="matrix("#)
        .nth(1)
        .unwrap();
    let scale: f64 = main.split(' ').next().unwrap().parse().unwrap();
    let w: f64 = edge
        .split(r#"stroke-width=""#)
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((w * scale - 2.0).abs() < 1e-6, "{w} mm at {scale} px/mm");
    // The outline is drawn over the toolpath.
    assert!(s.find(r#"id="toolpath""#).unwrap() < s.find(r#"class="leftover-edge""#).unwrap());
    // With room, the largest leftover gets an inset at its thickest place.
    assert!(s.contains(r#"id="details""#));
    assert!(
        s.contains("detail 1: leftover up to 0.354 mm, Z-3"),
        "leftover title"
    );
    assert!(s.contains(r#"class="leftover-spot""#));
    // No leftover: no outline, no inset.
    let mut clean = r.clone();
    clean.leftovers.clear();
    let s = render::svg(&clean);
    assert!(!s.contains("leftover-edge") && !s.contains(r#"id="details""#));
}

#[test]
fn leftover_inset_comes_last_and_only_with_room() {
    let mut r = common::groove_bar();
    let band = common::rough_band();
    r.leftovers = band.leftovers;
    r.leftover_spot = band.leftover_spot;
    // Crash and gouge first, the leftover third.
    let s = render::svg(&r);
    assert!(s.contains("detail 1: crash"));
    assert!(s.contains("detail 2: gouge"));
    assert!(s.contains("detail 3: leftover up to "), "leftover is third");
    // A second crash takes its place.
    r.crashes.push(render::Crash {
        line: 30,
        column: 1,
        z: -55.0,
        r: 19.0,
        area_mm2: 4.0,
        depth_mm: 1.0,
        body: None,
        ..Default::default()
    });
    let s = render::svg(&r);
    assert!(!s.contains(": leftover"));
    assert!(s.contains("leftover-edge"), "still outlined");
}

#[test]
fn sub_pixel_gouge_still_draws() {
    let mut r = common::groove_bar();
    // 2 µm square: far below a pixel; its outline must still be written.
    r.gouge_shapes = vec![Shape {
        outer: vec![
            [-22.5, 14.0],
            [-22.498, 14.0],
            [-22.498, 14.002],
            [-22.5, 14.002],
        ],
        holes: vec![],
    }];
    let s = render::svg(&r);
    let edge = s
        .split(r#"<g class="gouge-edge">"#)
        .nth(1)
        .expect("gouge outline");
    assert!(
        edge.trim_start().starts_with("<path d=\"M"),
        "{}",
        &edge[..80.min(edge.len())]
    );
}

fn m20_thread() -> render::ThreadCheck {
    render::ThreadCheck {
        line: 4,
        lead_mm: 1.5,
        x_mm: 18.05,
        expected_x_mm: Some(18.05),
        achieved_x_mm: Some(18.05),
        pass_depths_mm: vec![0.4, 0.3, 0.275],
        pitch_diameter_mm: Some(19.349038),
        included_angle_deg: Some(60.0),
        z_start_mm: -2.0,
        z_end_mm: -30.0,
        ..Default::default()
    }
}

/// A thread gets an inset of its teeth with the expected and pitch diameters labelled,
/// after the findings; when they take the three places, it is left out.
#[test]
fn a_thread_gets_an_inset_after_the_findings() {
    let mut r = common::groove_bar();
    r.crashes.clear();
    r.gouges.clear();
    r.gouge_shapes.clear();
    r.threads.push(m20_thread());
    let s = render::svg(&r);
    assert!(
        s.contains("detail 1: thread line 4, lead 1.5: X18.05 reached, 60°</text>"),
        "thread title"
    );
    assert!(s.contains(r#"class="thread-lines""#));
    assert!(s.contains("expected Φ18.05"));
    assert!(s.contains("pitch Φ19.349"));
    // Nothing cut there: said so, and no pitch line without a pitch diameter.
    let mut r2 = r.clone();
    r2.threads[0].achieved_x_mm = None;
    r2.threads[0].pitch_diameter_mm = None;
    r2.threads[0].included_angle_deg = None;
    let s2 = render::svg(&r2);
    assert!(s2.contains("detail 1: thread line 4, lead 1.5: no material cut</text>"));
    assert!(!s2.contains("pitch Φ"));
    // Crash, gouge and a groove take the three places.
    let mut r3 = common::groove_bar();
    r3.threads.push(m20_thread());
    r3.grooves.push(render::Groove {
        line: 9,
        ring: vec![[-20.0, 18.0], [-20.0, 14.0], [-25.0, 14.0], [-25.0, 18.0]],
        deviation_mm: Some(0.0),
    });
    let s3 = render::svg(&r3);
    assert!(s3.contains("detail 3: groove line 9"));
    assert!(!s3.contains("thread line 4"));
}

#[test]
fn odd_threads_do_not_panic() {
    let nan = f64::NAN;
    for (lead, z0, x) in [
        (nan, -2.0, 18.0),
        (0.0, -2.0, 18.0),
        (1.5, nan, 18.0),
        (1.5, -2.0, nan),
        (1e300, -1e300, 1e300),
        (1e-12, -2.0, 18.0),
    ] {
        let mut r = common::groove_bar();
        let mut t = m20_thread();
        t.lead_mm = lead;
        t.z_start_mm = z0;
        t.x_mm = x;
        t.pass_depths_mm = vec![nan, 1e300];
        r.threads = vec![t];
        let s = render::svg(&r);
        assert!(
            !s.contains("NaN") && !s.contains("inf"),
            "lead {lead} z {z0} x {x}"
        );
        render::png(&r).expect("renders");
    }
}
