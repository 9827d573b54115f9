//! Hand-built reports shared by the integration tests.
#![allow(dead_code)]

use render::*;

fn shape(outer: &[[f64; 2]]) -> Shape {
    Shape {
        outer: outer.to_vec(),
        holes: vec![],
    }
}

fn mv(kind: PathKind, line: u32, pts: &[[f64; 2]]) -> PathLine {
    PathLine {
        kind,
        line,
        points: pts.to_vec().into(),
    }
}

/// A Φ40 × 60 bar turned to Φ36 with a 5 mm groove, one crash (a rapid into the
/// shoulder), one slightly deep groove (a gouge against the intended Φ28.4), one warning.
pub(crate) fn groove_bar() -> Report {
    use PathKind::*;
    let blank = shape(&[[-60.0, 0.0], [0.0, 0.0], [0.0, 20.0], [-60.0, 20.0]]);
    let part = |groove_r: f64| {
        shape(&[
            [-60.0, 0.0],
            [0.0, 0.0],
            [0.0, 17.0],
            [-1.0, 18.0],
            [-20.0, 18.0],
            [-20.0, groove_r],
            [-25.0, groove_r],
            [-25.0, 18.0],
            [-40.0, 18.0],
            [-40.0, 20.0],
            [-60.0, 20.0],
        ])
    };
    Report {
        program: "O0042.nc".into(),
        title: "O0042".into(),
        control: "gsk980 — GSK 980TD (G-code system A)".into(),
        stock: StockInfo {
            description: "bar Ø40 × 60, face at Z0".into(),
            shapes: vec![blank],
        },
        final_part: vec![part(14.0)],
        intended: vec![part(14.2)],
        toolpath: vec![
            mv(Rapid, 3, &[[100.0, 100.0], [2.0, 22.0], [2.0, 18.0]]),
            mv(Feed, 5, &[[2.0, 18.0], [-40.0, 18.0]]),
            mv(Feed, 6, &[[-40.0, 18.0], [-40.0, 21.0]]),
            mv(Rapid, 7, &[[-40.0, 21.0], [2.0, 21.0], [2.0, 16.0]]),
            mv(Feed, 8, &[[2.0, 16.0], [0.0, 17.0], [-1.0, 18.0]]),
            mv(Rapid, 10, &[[-1.0, 18.0], [-1.0, 21.0], [-20.0, 21.0]]),
            mv(Feed, 11, &[[-20.0, 21.0], [-20.0, 14.0]]),
            mv(Rapid, 12, &[[-20.0, 14.0], [-20.0, 21.0], [-25.0, 21.0]]),
            mv(Feed, 13, &[[-25.0, 21.0], [-25.0, 14.0], [-20.0, 14.0]]),
            mv(Rapid, 14, &[[-20.0, 14.0], [-20.0, 21.0], [-45.0, 21.0], [-50.0, 12.0]]),
            mv(Rapid, 15, &[[-50.0, 12.0], [-50.0, 25.0], [100.0, 100.0]]),
        ],
        crashes: vec![Crash { line: 14, column: 1, z: -46.667, r: 18.0, area_mm2: 21.5 , depth_mm: 1.0, body: None, ..Default::default()}],
        rapid_cuts: vec![],
        gouges: vec![Gouge { line: 11, z: -22.5, r: 14.0, area_mm2: 1.0, depth_mm: 0.2, assumed: false, cause: None, remedy: None }],
        gouge_shapes: vec![shape(&[[-25.0, 14.0], [-20.0, 14.0], [-20.0, 14.2], [-25.0, 14.2]])],
        leftovers: vec![],
        leftover_spot: None,
        deviation: Some(Deviation {
            overcut_area_mm2: 1.0,
            undercut_area_mm2: 0.0,
            max_overcut_mm: 0.2,
            max_undercut_mm: 0.0,
        }),
        alarms: vec![],
        warnings: vec![Diagnostic {
            line: 9,
            column: 1,
            code: "W-TOOL-DEFAULT".into(),
            message: "T02 has no entry in the tool table; using the default 3 mm grooving blade referenced at its left corner".into(),
        }],
        tools: vec!["T01 turning D 55°, r0.4, tip 3".into(), "T02 grooving 5 mm, ref. left corner (default)".into()],
        removed_area_mm2: 163.0,
        removed_volume_mm3: 19_123.4,
        segments: 11,
        rapid_segments: 5,
        cycle_time_s: 102.0,
        tolerance_mm: 0.01,
        snapshots: vec![],
        grooves: vec![],
        // as the analysis decides it: a crash is worse than the gouge
        verdict: Verdict::Crash,
        ..Report::default()
    }
}

/// A report with `n` segments: a grooving pattern of pecks, each distinct, over a bar.
pub(crate) fn many_segments(n: usize) -> Report {
    let mut r = groove_bar();
    r.toolpath.clear();
    let mut i = 0usize;
    while r.toolpath.len() < n {
        let z = -((i % 5000) as f64) * 0.0117 - 1.0;
        let depth = 18.0 - (i / 5000) as f64 * 0.013;
        r.toolpath
            .push(mv(PathKind::Feed, (i + 1) as u32, &[[z, 21.0], [z, depth]]));
        if r.toolpath.len() < n {
            r.toolpath.push(mv(
                PathKind::Rapid,
                (i + 1) as u32,
                &[[z, depth], [z, 21.0]],
            ));
        }
        i += 1;
    }
    r.segments = n;
    r.rapid_segments = n / 2;
    r
}

/// The O0008 groove of the spec (`G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30`) on a
/// Φ50 × 80 bar faced at Z40: the final part is the blank minus the trapezoid P1 (30, 25),
/// P2 (20, 15), P3 (10, 15), P4 (−7.32, 25), which is also the groove ring. Clean.
pub(crate) fn o0008_groove() -> Report {
    use PathKind::*;
    let trapezoid = [[30.0, 25.0], [20.0, 15.0], [10.0, 15.0], [-7.32, 25.0]];
    let blank = shape(&[[-40.0, 0.0], [40.0, 0.0], [40.0, 25.0], [-40.0, 25.0]]);
    let mut outer = vec![[-40.0, 0.0], [40.0, 0.0], [40.0, 25.0]];
    outer.extend(trapezoid);
    outer.push([-40.0, 25.0]);
    let part = shape(&outer);
    Report {
        program: "O0008.nc".into(),
        title: "O0008".into(),
        control: "gsk980 — GSK 980TD (G-code system A)".into(),
        stock: StockInfo {
            description: "bar Ø50 × 80, face at Z40".into(),
            shapes: vec![blank],
        },
        final_part: vec![part.clone()],
        intended: vec![part],
        toolpath: vec![
            mv(Rapid, 1, &[[60.0, 40.0], [30.0, 26.0]]),
            mv(Feed, 2, &[[20.0, 26.0], [20.0, 15.0]]),
            mv(Rapid, 2, &[[20.0, 15.0], [20.0, 26.0], [15.0, 26.0]]),
            mv(Feed, 2, &[[15.0, 26.0], [15.0, 15.0]]),
            mv(Rapid, 2, &[[15.0, 15.0], [15.0, 26.0], [10.0, 26.0]]),
            mv(Feed, 2, &[[10.0, 26.0], [10.0, 15.0]]),
            mv(Rapid, 2, &[[10.0, 15.0], [10.0, 26.0], [30.0, 26.0]]),
            mv(
                Feed,
                2,
                &[[30.0, 25.0], [20.0, 15.0], [10.0, 15.0], [-7.32, 25.0]],
            ),
            mv(Rapid, 2, &[[-7.32, 25.0], [-7.32, 26.0], [60.0, 40.0]]),
        ],
        crashes: vec![],
        rapid_cuts: vec![],
        gouges: vec![],
        gouge_shapes: vec![],
        leftovers: vec![],
        leftover_spot: None,
        deviation: Some(Deviation {
            overcut_area_mm2: 0.0,
            undercut_area_mm2: 0.0,
            max_overcut_mm: 0.0,
            max_undercut_mm: 0.0,
        }),
        alarms: vec![],
        warnings: vec![],
        tools: vec!["T01 grooving 4 mm, ref. right corner".into()],
        removed_area_mm2: 236.6,
        removed_volume_mm3: 33_410.0,
        segments: 9,
        rapid_segments: 5,
        cycle_time_s: 102.0,
        tolerance_mm: 0.01,
        snapshots: vec![],
        grooves: vec![Groove {
            line: 2,
            ring: trapezoid.to_vec(),
            // The final part is cut exactly to the ring.
            deviation_mm: Some(0.0),
        }],
        ..Report::default()
    }
}

/// A stepped shaft roughed with a 0.25 mm allowance left everywhere (like a G73 pass):
/// one long, thin leftover band (0.35 mm round the shoulders' outer edges), no crash, no gouge.
pub(crate) fn rough_band() -> Report {
    use PathKind::*;
    let profile = |a: f64| {
        vec![
            [-100.0, 0.0],
            [0.0, 0.0],
            [0.0, 20.0 + a],
            [-30.0 + a, 20.0 + a],
            [-30.0 + a, 30.0 + a],
            [-60.0 + a, 30.0 + a],
            [-60.0 + a, 40.0 + a],
            [-100.0, 40.0 + a],
        ]
    };
    let band = shape(&[
        [0.0, 20.0],
        [0.0, 20.25],
        [-29.75, 20.25],
        [-29.75, 30.25],
        [-59.75, 30.25],
        [-59.75, 40.25],
        [-100.0, 40.25],
        [-100.0, 40.0],
        [-60.0, 40.0],
        [-60.0, 30.0],
        [-30.0, 30.0],
        [-30.0, 20.0],
    ]);
    let fin = profile(0.25);
    Report {
        program: "O0106.nc".into(),
        title: "O0106".into(),
        stock: StockInfo {
            description: "bar Ø90 × 100, face at Z0".into(),
            shapes: vec![shape(&[
                [-100.0, 0.0],
                [0.0, 0.0],
                [0.0, 45.0],
                [-100.0, 45.0],
            ])],
        },
        final_part: vec![shape(&fin)],
        intended: vec![shape(&profile(0.0))],
        toolpath: vec![
            mv(Rapid, 3, &[[150.0, 100.0], [2.0, 47.0], [2.0, 18.0]]),
            mv(
                Feed,
                5,
                &fin[2..]
                    .iter()
                    .copied()
                    .chain([[-100.0, 46.0]])
                    .collect::<Vec<_>>(),
            ),
            mv(Rapid, 6, &[[-100.0, 46.0], [150.0, 100.0]]),
        ],
        leftovers: vec![band],
        // As the simulator measures it: the band is thickest round the Z-30 shoulder.
        leftover_spot: Some(LeftoverSpot {
            leftover: 0,
            centre: [-29.875, 30.125],
            thickness: Some(0.25 * std::f64::consts::SQRT_2),
            measure: Some([[-29.75, 30.25], [-30.0, 30.0]]),
        }),
        deviation: Some(Deviation {
            overcut_area_mm2: 0.0,
            undercut_area_mm2: 30.1,
            max_overcut_mm: 0.0,
            max_undercut_mm: 0.25 * std::f64::consts::SQRT_2,
        }),
        tools: vec!["T01 turning V 35°, r0, tip 3".into()],
        removed_area_mm2: 1270.0,
        removed_volume_mm3: 456_789.0,
        segments: 3,
        rapid_segments: 2,
        cycle_time_s: 60.0,
        tolerance_mm: 0.01,
        ..Report::default()
    }
}

/// Reports no renderer may panic on: empty, emptied, non-finite values, a single point
/// and a huge coordinate. Index 2 is the non-finite one.
pub(crate) fn degenerate_reports() -> Vec<Report> {
    let nan = f64::NAN;
    let mut reports = vec![Report::default()];
    let mut r = groove_bar();
    r.toolpath.clear();
    r.stock.shapes.clear();
    r.final_part.clear();
    reports.push(r);
    let mut r = groove_bar();
    r.final_part.push(Shape {
        outer: vec![[nan, nan], [1.0, nan]],
        holes: vec![vec![]],
    });
    r.toolpath.push(PathLine {
        kind: PathKind::Thread,
        line: 1,
        points: vec![[nan, 1.0], [f64::INFINITY, 2.0]].into(),
    });
    r.toolpath.push(PathLine {
        kind: PathKind::Feed,
        line: 2,
        points: vec![].into(),
    });
    r.crashes[0].z = nan;
    r.gouges[0].depth_mm = nan;
    r.cycle_time_s = nan;
    r.removed_area_mm2 = f64::INFINITY;
    r.tolerance_mm = nan;
    reports.push(r);
    // A single point and a huge coordinate.
    let mut r = Report::default();
    r.toolpath.push(PathLine {
        kind: PathKind::Rapid,
        line: 1,
        points: vec![[1e300, -1e300], [0.0, 0.0]].into(),
    });
    r.final_part.push(Shape {
        outer: vec![[5.0, 5.0]],
        holes: vec![],
    });
    reports.push(r);
    reports
}
