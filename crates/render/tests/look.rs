//! Writes pictures to tests/out for a human to look at (not a check); run with
//! `cargo test -p render --test look -- --ignored`.
mod common;

#[test]
#[ignore = "writes pictures for a human: cargo test -p render --test look -- --ignored"]
fn write_pictures() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/out");
    std::fs::create_dir_all(&dir).unwrap();
    let r = common::groove_bar();
    std::fs::write(dir.join("groove_bar.svg"), render::svg(&r)).unwrap();
    std::fs::write(dir.join("groove_bar.png"), render::png(&r).unwrap()).unwrap();
    let r = common::o0008_groove();
    std::fs::write(dir.join("o0008_groove.svg"), render::svg(&r)).unwrap();
    let png = render::png(&r).unwrap();
    std::fs::write(dir.join("o0008_groove.png"), &png).unwrap();
    // The right column's top at 2×, to read the groove detail's labels.
    let img = image::load_from_memory(&png).unwrap().to_rgb8();
    let crop = image::imageops::crop_imm(&img, 1090, 30, 510, 300).to_image();
    image::imageops::resize(&crop, 1020, 600, image::imageops::FilterType::Nearest)
        .save(dir.join("o0008_groove-detail-2x.png"))
        .unwrap();
    // A crash, a gouge and a groove (at the intended floor, 0.2 mm above the cut one).
    let mut r = common::groove_bar();
    r.grooves.push(render::Groove {
        line: 11,
        ring: vec![[-20.0, 18.0], [-20.0, 14.2], [-25.0, 14.2], [-25.0, 18.0]],
        deviation_mm: Some(0.2),
    });
    std::fs::write(dir.join("groove_findings.png"), render::png(&r).unwrap()).unwrap();
    // O0008 with its floor left 0.3 mm high (a leftover) and a chamfered mouth.
    let mut r = common::o0008_groove();
    let high = [[30.0, 25.0], [20.3, 15.3], [9.48, 15.3], [-7.32, 25.0]];
    let mut outer = vec![[-40.0, 0.0], [40.0, 0.0], [40.0, 25.0]];
    outer.extend(high);
    outer.push([-40.0, 25.0]);
    r.final_part = vec![render::Shape {
        outer,
        holes: vec![],
    }];
    r.leftovers = vec![render::Shape {
        outer: vec![[20.0, 15.0], [20.3, 15.3], [9.48, 15.3], [10.0, 15.0]],
        holes: vec![],
    }];
    r.grooves[0].ring = vec![
        [31.0, 25.0],
        [30.0, 24.0],
        [20.0, 15.0],
        [10.0, 15.0],
        [-6.0, 24.0],
        [-7.32, 25.0],
    ];
    r.grooves[0].deviation_mm = Some(0.3);
    r.leftover_spot = Some(render::LeftoverSpot {
        leftover: 0,
        centre: [15.0, 15.15],
        thickness: Some(0.3),
        measure: Some([[15.0, 15.3], [15.0, 15.0]]),
    });
    std::fs::write(dir.join("o0008_leftover.png"), render::png(&r).unwrap()).unwrap();
    // A 0.25 mm roughing allowance along a stepped shaft: outlined, with a leftover inset.
    let r = common::rough_band();
    std::fs::write(dir.join("rough_band.svg"), render::svg(&r)).unwrap();
    std::fs::write(dir.join("rough_band.png"), render::png(&r).unwrap()).unwrap();
}

#[test]
#[ignore = "writes pictures for a human: cargo test -p render --test look -- --ignored"]
fn write_more_pictures() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/out");
    std::fs::create_dir_all(&dir).unwrap();
    let r = common::many_segments(100_000);
    std::fs::write(dir.join("many.png"), render::png(&r).unwrap()).unwrap();
    let mut r = common::groove_bar();
    r.crashes.clear();
    r.gouges.clear();
    r.gouge_shapes.clear();
    r.intended.clear();
    r.deviation = None;
    r.warnings.clear();
    std::fs::write(dir.join("clean.png"), render::png(&r).unwrap()).unwrap();
    let mut r = common::groove_bar();
    for i in 0..12 {
        r.alarms.push(render::Diagnostic {
            line: 20 + i,
            column: 4,
            code: "E-ARC-RADIUS".into(),
            message: format!(
                "arc radius R{i} is smaller than half the chord; check the end point or use I/K"
            ),
        });
    }
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
    r.leftovers.push(render::Shape {
        outer: vec![[-40.0, 18.0], [-38.0, 18.0], [-38.0, 18.4], [-40.0, 18.4]],
        holes: vec![],
    });
    std::fs::write(dir.join("alarms.png"), render::png(&r).unwrap()).unwrap();
}

#[test]
#[ignore = "writes pictures for a human: cargo test -p render --test look -- --ignored"]
fn write_big_part_picture() {
    use render::*;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/out");
    std::fs::create_dir_all(&dir).unwrap();
    let sq = |z0: f64, z1: f64, r0: f64, r1: f64| Shape {
        outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
        holes: vec![],
    };
    // A fillet by chords, a thread zone, a bore (hole-free tube section).
    let mut outer = vec![[-110.0, 20.0], [0.0, 20.0], [0.0, 50.0]];
    for i in 0..=40 {
        let a = std::f64::consts::FRAC_PI_2 * i as f64 / 40.0;
        outer.push([-10.0 - 10.0 * a.sin(), 50.0 + 10.0 - 10.0 * a.cos()]);
    }
    outer.extend([[-60.0, 60.0], [-60.0, 62.5], [-110.0, 62.5]]);
    let mut tp = vec![PathLine {
        kind: PathKind::Rapid,
        line: 2,
        points: vec![[200.0, 100.0], [2.0, 64.0]].into(),
    }];
    for k in 0..8 {
        let r = 62.0 - k as f64 * 1.5;
        tp.push(PathLine {
            kind: PathKind::Feed,
            line: 10 + k,
            points: vec![[2.0, r], [-60.0, r], [-60.0, r + 1.0]].into(),
        });
        tp.push(PathLine {
            kind: PathKind::Rapid,
            line: 10 + k,
            points: vec![[-60.0, r + 1.0], [2.0, r + 1.0], [2.0, r - 1.5]].into(),
        });
    }
    for k in 0..4 {
        let r = 50.0 - 0.3 * k as f64;
        tp.push(PathLine {
            kind: PathKind::Thread,
            line: 30,
            points: vec![[2.0, r], [-8.0, r]].into(),
        });
    }
    let r = Report {
        program: "O0001.nc".into(),
        title: "FLANGE SHAFT".into(),
        stock: StockInfo {
            description: "tube Ø125 × 110, bore Ø40, face at Z0".into(),
            shapes: vec![sq(-110.0, 0.0, 20.0, 62.5)],
        },
        final_part: vec![Shape {
            outer,
            holes: vec![],
        }],
        toolpath: tp,
        gouges: vec![Gouge {
            line: 31,
            z: -18.0,
            r: 57.0,
            area_mm2: 0.0004,
            depth_mm: 0.004,
            assumed: false,
            cause: None,
            remedy: None,
        }],
        gouge_shapes: vec![sq(-18.05, -17.95, 56.996, 57.0)],
        warnings: (0..3)
            .map(|i| Diagnostic {
                line: 40 + i,
                column: 1,
                code: "W".into(),
                message: "spindle stopped during feed".into(),
            })
            .collect(),
        tools: vec![
            "T01 turning C 80°, r0.8, tip 3".into(),
            "T04 threading 60°".into(),
        ],
        removed_area_mm2: 1234.5,
        removed_volume_mm3: 1_234_567.0,
        segments: 21,
        rapid_segments: 9,
        cycle_time_s: 4000.0,
        tolerance_mm: 0.001,
        deviation: Some(Deviation {
            overcut_area_mm2: 0.0004,
            undercut_area_mm2: 0.0,
            max_overcut_mm: 0.004,
            max_undercut_mm: 0.0,
        }),
        ..Report::default()
    };
    std::fs::write(dir.join("big.png"), render::png(&r).unwrap()).unwrap();
}

/// Crops and enlarges any PNG for a closer look: `LATSIM_CROP="in.png x y w h k out.png"`
/// (k: integer magnification, nearest neighbour).
#[test]
#[ignore = "for a human: LATSIM_CROP=\"in.png x y w h k out.png\" cargo test -p render --test look crop -- --ignored"]
fn crop() {
    let Ok(spec) = std::env::var("LATSIM_CROP") else {
        return;
    };
    let a: Vec<&str> = spec.split_whitespace().collect();
    let n = |i: usize| a[i].parse::<u32>().unwrap();
    let img = image::open(a[0]).unwrap().to_rgb8();
    let crop = image::imageops::crop_imm(&img, n(1), n(2), n(3), n(4)).to_image();
    let (w, h) = (crop.width() * n(5), crop.height() * n(5));
    image::imageops::resize(&crop, w, h, image::imageops::FilterType::Nearest)
        .save(a[6])
        .unwrap();
}
