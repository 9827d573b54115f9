//! The removal run end to end: exact cuts, crashes, merging, paths, snapshots, part-offs,
//! and the shortcuts (covering, ring air tests) against the runs without them.

use super::*;
use crate::sweep::SweepBuilder;
use crate::{hausdorff, symmetric_difference_area, Insert, Tool};
use expander::{Arc, FeedId, Motion, Pt, Span};

/// A move of tool 1 (shared with the other modules' tests).
pub(crate) fn seg(motion: Motion, from: [f64; 2], to: [f64; 2]) -> Segment {
    Segment {
        motion,
        from: Pt::new(from[0], from[1]),
        to: Pt::new(to[0], to[1]),
        arc: None,
        tool: 1,
        hint: expander::ToolHint::Table,
        lead: 0.0,
        thread_phase: 0.0,
        feed: FeedId::default(),
        span: Span::default(),
    }
}

fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
    Shape {
        outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
        holes: vec![],
    }
}

fn run(blank: &Blank, tools: &ToolTable, segs: &[Segment]) -> Simulation {
    simulate(blank, tools, segs, &SimOptions::default(), &mut |_| {})
}

/// T1: a V 35° insert, r0.4, tip 3, 93° (shared with the other modules' tests).
pub(crate) fn v35() -> ToolTable {
    ToolTable::from_tools(vec![(
        1,
        Tool::Turning {
            insert: Insert::V,
            nose_radius: 0.4,
            tip: 3,
            entering_angle: 93.0,
            edge: 11.0,
        },
    )])
}

#[test]
fn straight_turning_pass_removes_exactly_the_rectangle() {
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let sim = run(
        &blank,
        &v35(),
        &[seg(Motion::Feed, [5.0, 20.0], [-115.0, 20.0])],
    );
    let expected = [rect(-110.0, 0.0, 0.0, 20.0)];
    let d = symmetric_difference_area(&sim.final_shapes, &expected);
    assert!(d < 1e-6 * 2200.0, "symmetric difference {d}");
    assert!(
        (sim.removed_area - 110.0 * 5.0).abs() < 1e-6,
        "{}",
        sim.removed_area
    );
    let pi = std::f64::consts::PI;
    assert!(
        (sim.removed_volume - pi * (625.0 - 400.0) * 110.0).abs() < 1e-3,
        "{}",
        sim.removed_volume
    );
    assert!(sim.crashes.is_empty());
}

#[test]
fn arc_with_a_sharp_tool_gives_the_arc() {
    let tools = ToolTable::from_tools(vec![(
        1,
        Tool::Turning {
            insert: Insert::V,
            nose_radius: 0.0,
            tip: 3,
            entering_angle: 93.0,
            edge: 11.0,
        },
    )]);
    let blank = Blank::bar(40.0, 50.0, 0.0, None).unwrap();
    let mut arc = seg(Motion::Feed, [0.0, 10.0], [-10.0, 20.0]);
    arc.arc = Some(Arc {
        center: Pt::new(-10.0, 10.0),
        ccw: true,
    });
    let segs = [
        seg(Motion::Feed, [5.0, 10.0], [0.0, 10.0]),
        arc,
        seg(Motion::Feed, [-10.0, 20.0], [-12.0, 20.0]),
    ];
    let sim = run(&blank, &tools, &segs);
    // the intended dome, chorded 100 times finer than the simulation
    let mut outer = vec![[-50.0, 0.0], [0.0, 0.0]];
    outer.extend(arc.polyline(1e-5).iter().map(|p| [p.z, p.r]));
    outer.push([-50.0, 20.0]);
    let expected = [Shape {
        outer,
        holes: vec![],
    }];
    let h = hausdorff(&sim.final_shapes, &expected);
    assert!(h < 0.002, "hausdorff {h}");
    // and it is a real cut, not the blank
    assert!(sim.removed_area > 20.0, "{}", sim.removed_area);
}

#[test]
fn rapid_into_the_stock_is_a_crash() {
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let segs = [
        seg(Motion::Rapid, [10.0, 30.0], [10.0, 20.0]),
        seg(Motion::Rapid, [10.0, 20.0], [-20.0, 20.0]),
        // back out along the same line: inside its own earlier sweep, no second crash
        seg(Motion::Rapid, [-20.0, 20.0], [10.0, 20.0]),
        // straight up from there would plough the sliver the 87° edge left: a crash
        seg(Motion::Rapid, [-20.0, 20.0], [-20.0, 40.0]),
    ];
    let sim = run(&blank, &v35(), &segs);
    assert_eq!(
        sim.crashes.iter().map(|c| c.segment).collect::<Vec<_>>(),
        vec![1, 3],
        "{:?}",
        sim.crashes
    );
    let c = &sim.crashes[0];
    assert_eq!(c.segment, 1);
    // it ploughed through r 20..25 over z -20..0 (less the sliver under the 87° edge)
    assert!(c.area > 99.0 && c.area <= 100.0, "{}", c.area);
    let total: f64 = sim.crashes.iter().map(|c| c.area).sum();
    assert!(
        (total - sim.removed_area).abs() < 1e-6,
        "{total} vs {}",
        sim.removed_area
    );
    assert!(
        (c.at[0] - 0.0).abs() < 1e-6 && (c.at[1] - 20.0).abs() < 1e-6,
        "{:?}",
        c.at
    );
}

#[test]
fn rapid_in_air_is_not_a_crash() {
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let segs = [
        seg(Motion::Rapid, [10.0, 30.0], [-20.0, 30.0]),
        seg(Motion::Rapid, [-20.0, 30.0], [-20.0, 25.0]),
    ];
    let sim = run(&blank, &v35(), &segs);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    assert!(sim.removed_area.abs() < 1e-9);
}

#[test]
fn rapid_through_material_cut_earlier_in_the_batch_is_not_a_crash() {
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let back = seg(Motion::Rapid, [-20.0, 22.0], [10.0, 22.0]);
    let segs = [
        seg(Motion::Feed, [10.0, 20.0], [-20.0, 20.0]),
        seg(Motion::Feed, [-20.0, 20.0], [-20.0, 22.0]),
        back,
    ];
    let sim = run(&blank, &v35(), &segs);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    // the same rapid without the feeds before it ploughs through stock
    let sim = run(&blank, &v35(), &[back]);
    assert_eq!(sim.crashes.len(), 1);
    assert_eq!(sim.crashes[0].segment, 0);
    // and a crash many batches later still carries its own index
    let mut many: Vec<Segment> = (0..100)
        .map(|_| seg(Motion::Rapid, [10.0, 40.0], [10.0, 45.0]))
        .collect();
    many.push(back);
    let sim = run(&blank, &v35(), &many);
    assert_eq!(
        sim.crashes.iter().map(|c| c.segment).collect::<Vec<_>>(),
        vec![100]
    );
}

#[test]
fn thread_pass_stamps_one_tooth_per_lead() {
    let tools = ToolTable::from_tools(vec![(
        1,
        Tool::Threading {
            angle: 60.0,
            tip_flat: 0.0,
            side: crate::tools::ThreadSide::Od,
        },
    )]);
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let mut t = seg(Motion::Thread, [5.0, 24.0], [-30.0, 24.0]);
    t.lead = 2.0;
    let sim = run(&blank, &tools, &[t]);
    // stamps at z = 5, 3, ..., -29 and at the end -30; those at z <= -1 are in the bar
    let tooth = 30f64.to_radians().tan(); // 1 mm deep, 2 tan 30° wide: area tan 30°
    let overlap = (tooth - 0.5) * (tooth - 0.5) / tooth; // the last two teeth are 1 mm apart
    let expected = 16.0 * tooth - overlap;
    // grid rounding (~0.1 nm) along 37 mm of tooth flanks
    assert!(
        (sim.removed_area - expected).abs() < 1e-5,
        "{} vs {expected}",
        sim.removed_area
    );
}

/// A thread cut with G76's flank infeed: 150 passes whose tips all lie on the thread's
/// leading flank, so that every pass's V holds the last ones. The part is the last pass's
/// cut (the same area), with the thread's own few vertices a tooth, not the zigzag of a
/// vertex a pass and tooth grid rounding left where the passes' flanks meet along that line
/// (8 715 vertices before the kinks were dropped).
#[test]
fn flank_infeed_passes_leave_no_zigzag_along_the_flank() {
    let tools = ToolTable::from_tools(vec![(
        1,
        Tool::Threading {
            angle: 60.0,
            tip_flat: 0.0,
            side: crate::tools::ThreadSide::Od,
        },
    )]);
    let blank = Blank::bar(20.0, 40.0, 0.0, None).unwrap();
    let tan30 = 30f64.to_radians().tan();
    let pass = |d: f64| {
        let dz = -d * tan30;
        let mut t = seg(Motion::Thread, [2.0 + dz, 8.5 - d], [-17.3 + dz, 8.5 - d]);
        t.lead = 1.5;
        [
            seg(Motion::Rapid, [2.0 + dz, 10.5], [2.0 + dz, 8.5 - d]),
            t,
            seg(Motion::Rapid, [-17.3 + dz, 8.5 - d], [-17.3 + dz, 10.5]),
            seg(Motion::Rapid, [-17.3 + dz, 10.5], [2.0 + dz, 10.5]),
        ]
    };
    let passes = 150;
    let segs: Vec<Segment> = (1..=passes)
        .flat_map(|k| pass(0.92 * (f64::from(k) / f64::from(passes)).sqrt()))
        .collect();
    let sim = run(&blank, &tools, &segs);
    let last = run(&blank, &tools, &pass(0.92));
    let vertices: usize = sim
        .final_shapes
        .iter()
        .map(|s| s.outer.len() + s.holes.iter().map(Vec::len).sum::<usize>())
        .sum();
    assert!(vertices < 150, "{vertices} vertices");
    // grid rounding (~0.1 nm) along the 27 mm of flanks, where the epochs that end at the
    // snapshot stops (every 20 moves here) end batches
    assert!(
        (sim.removed_area - last.removed_area).abs() < 1e-5,
        "{} against {}",
        sim.removed_area,
        last.removed_area
    );
    assert!(sim.crashes.is_empty() && sim.removed_area > 5.0);
}

/// Issue 32's CAM thread: single thread passes 0.0005 mm apart on the radius (0.001 on the
/// diameter; and 0.001 mm, a G76's least depth of cut) with a round nose (a V insert,
/// r0.4, 93°), each followed by its rapids. Stamped pass by pass (`merge_tol` 0), every
/// pass leaves a notch of 10⁻⁵ mm where its nose meets the last pass's on a flank of each
/// tooth (576 vertices for 120 passes), which the tiles split on. Swept from where the run
/// of passes began, the part has the few vertices of its teeth (72), lies within the
/// stated `merge_tol / 5` (10⁻⁴ mm) of the pass-by-pass part (8·10⁻⁶ and 1.6·10⁻⁵ mm: the
/// notches' depth), and the rapids crash alike.
#[test]
fn repeated_thread_passes_leave_no_notch_a_pass() {
    for step in [0.0005, 0.001] {
        let (swept, exact) = thread_passes_both_ways(step);
        let (n, n_exact) = (vertices(&swept), vertices(&exact));
        assert!(n < 100, "{step}: {n} vertices ({n_exact} pass by pass)");
        assert!(n_exact > 400, "{step}: {n_exact} vertices pass by pass");
        let h = hausdorff(&swept.final_shapes, &exact.final_shapes);
        let bound = SimOptions::default().merge_tol / 5.0;
        assert!(h <= bound + 1e-6, "{step}: Hausdorff {h} mm");
        // what the notches held (10⁻⁵ mm deep), filled: removed, never left
        let extra = swept.removed_area - exact.removed_area;
        let xor = symmetric_difference_area(&swept.final_shapes, &exact.final_shapes);
        assert!(
            (0.0..2e-5).contains(&extra) && xor < 2e-5,
            "{step}: {extra} {xor}"
        );
        // the same crash: the first retract, its insert leaning over the last tooth
        assert_eq!(swept.crashes.len(), 1);
        assert_eq!(swept.crashes.len(), exact.crashes.len());
        for (a, b) in swept.crashes.iter().zip(&exact.crashes) {
            assert_eq!(a.segment, b.segment);
            assert!((a.area - b.area).abs() < 1e-6, "{} {}", a.area, b.area);
        }
    }
}

/// 120 passes `step` apart (see [`repeated_thread_passes_leave_no_notch_a_pass`]), cut
/// with the default options and pass by pass (`merge_tol` 0).
fn thread_passes_both_ways(step: f64) -> (Simulation, Simulation) {
    let blank = Blank::bar(20.0, 40.0, 0.0, None).unwrap();
    let pass = |d: f64| {
        let r = 8.5 - d;
        let mut t = seg(Motion::Thread, [0.5, r], [-4.0, r]);
        t.lead = 1.5;
        [
            seg(Motion::Rapid, [0.5, 10.0], [0.5, r]),
            t,
            seg(Motion::Rapid, [-4.0, r], [-4.0, 10.0]),
            seg(Motion::Rapid, [-4.0, 10.0], [0.5, 10.0]),
        ]
    };
    let segs: Vec<Segment> = (0..120).flat_map(|k| pass(step * f64::from(k))).collect();
    let exact_opts = SimOptions {
        merge_tol: 0.0,
        ..SimOptions::default()
    };
    let swept = run(&blank, &v35(), &segs);
    let exact = simulate(&blank, &v35(), &segs, &exact_opts, &mut |_| {});
    (swept, exact)
}

/// Vertices of a run's part.
fn vertices(s: &Simulation) -> usize {
    s.final_shapes
        .iter()
        .map(|s| s.outer.len() + s.holes.iter().map(Vec::len).sum::<usize>())
        .sum()
}

/// A zig-zag written with X to 0.0001 mm (`scripts/zigzag.py cut` at 10⁵ moves): each feed
/// 0.00002 mm lower on the radius as computed, 0 or 0.00005 mm as written, so its steps are
/// uneven and its passes never group; a back-and-forth at one X is one run. Cut feed by
/// feed, the 93° side of the sharp insert leaves a notch of 3·10⁻⁶ mm at the turning
/// point for each X written (the part of 5 200 moves: 4 243 vertices). Each feed that
/// repeats an earlier one within `merge_tol` sweeps from where that run of passes began:
/// 9 vertices, within the stated `merge_tol / 2` of the part cut feed by feed (2.6·10⁻⁶
/// mm: the notches' depth), the same area to 10⁻⁵ mm² (+1.4·10⁻⁷), the same crashes.
#[test]
fn a_zig_zag_written_rounded_sweeps_its_repeated_feeds_as_one() {
    let blank = Blank::bar(20.0, 10.0, 0.0, None).unwrap();
    // the bench's tool: a sharp V 35°, 93°
    let tools = ToolTable::from_tools(vec![(
        1,
        Tool::Turning {
            insert: Insert::V,
            nose_radius: 0.0,
            tip: 3,
            entering_angle: 93.0,
            edge: 11.0,
        },
    )]);
    let n = 5_200;
    let mut segs = vec![
        seg(Motion::Rapid, [1.0, 10.5], [1.0, 9.9]),
        seg(Motion::Feed, [1.0, 9.9], [-1.0, 9.9]),
    ];
    let mut at = [-1.0, 9.9];
    for k in 0..n {
        let x = ((19.8 - 0.00004 * f64::from(k + 1)) * 1e4).round() / 1e4;
        let to = [if k % 2 == 0 { -6.0 } else { -1.0 }, x / 2.0];
        segs.push(seg(Motion::Feed, at, to));
        at = to;
    }
    segs.push(seg(Motion::Rapid, at, [at[0], 10.5]));
    assert!(segs.len() > crate::snapshot::EXACT_MAX_MOVES);
    let single_opts = SimOptions {
        pass_groups: false,
        ..SimOptions::default()
    };
    let ruled = run(&blank, &tools, &segs);
    let single = simulate(&blank, &tools, &segs, &single_opts, &mut |_| {});
    let (v, v_single) = (vertices(&ruled), vertices(&single));
    assert!(v < 40, "{v} vertices ({v_single} feed by feed)");
    assert!(v_single > 1_000, "{v_single} vertices feed by feed");
    let h = hausdorff(&ruled.final_shapes, &single.final_shapes);
    assert!(
        h <= SimOptions::default().merge_tol / 2.0,
        "Hausdorff {h} mm"
    );
    let extra = ruled.removed_area - single.removed_area;
    assert!((0.0..1e-5).contains(&extra), "{extra} mm²");
    let crashes = |s: &Simulation| -> Vec<usize> { s.crashes.iter().map(|c| c.segment).collect() };
    assert_eq!(crashes(&ruled), crashes(&single));
}

/// Passes more than `2·merge_tol` apart are stamped pass by pass: a deeper cut's notches
/// are real geometry (the same part as with `merge_tol` 0).
#[test]
fn thread_passes_further_apart_than_twice_merge_tol_are_stamped_each() {
    let blank = Blank::bar(20.0, 40.0, 0.0, None).unwrap();
    let segs: Vec<Segment> = (0..6)
        .map(|k| {
            let r = 8.5 - 0.05 * f64::from(k);
            let mut t = seg(Motion::Thread, [0.5, r], [-4.0, r]);
            t.lead = 1.5;
            t
        })
        .collect();
    let exact_opts = SimOptions {
        merge_tol: 0.0,
        ..SimOptions::default()
    };
    let swept = run(&blank, &v35(), &segs);
    let exact = simulate(&blank, &v35(), &segs, &exact_opts, &mut |_| {});
    assert_eq!(swept.final_shapes, exact.final_shapes);
}

#[test]
fn grooving_hints_choose_the_blade() {
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let mut plunge = seg(Motion::Feed, [-10.0, 30.0], [-10.0, 20.0]);
    plunge.hint = expander::ToolHint::Grooving;
    let sim = run(&blank, &ToolTable::empty(), &[plunge]);
    // the default 3 mm blade, left corner referenced: a 3 x 5 groove at z -10..-7
    assert!(
        (sim.removed_area - 15.0).abs() < 1e-6,
        "{}",
        sim.removed_area
    );
    assert!(sim.warnings.iter().any(|(_, w)| w.contains("3 mm")));
    plunge.hint = expander::ToolHint::Blade {
        width: 4.0,
        toward_plus_z: false,
        shank_plus_x: true,
    };
    let sim = run(&blank, &ToolTable::empty(), &[plunge]);
    let expected = [
        rect(-110.0, -14.0, 0.0, 25.0),
        rect(-14.0, -10.0, 0.0, 20.0),
        rect(-10.0, 0.0, 0.0, 25.0),
    ];
    let expected = crate::boolean(&expected, &[], crate::BoolOp::Union);
    assert!(symmetric_difference_area(&sim.final_shapes, &expected) < 1e-6);
}

/// Number of cutting sweeps the builder makes of `segs` (with the defaults' chord tolerance),
/// without paths of feeds.
fn sweep_count(tools: &ToolTable, segs: &[Segment], merge_tol: f64) -> usize {
    let bb = Rect::new(geom::Pt::new(-200.0, -200.0), geom::Pt::new(200.0, 200.0));
    let grid = Grid::new(bb.grown(1.0));
    let mut b = SweepBuilder::new(&grid, bb, tools, 0.001, merge_tol);
    // merging alone (paths of feeds would make one sweep of every path)
    b.set_feed_paths(false);
    for (i, s) in segs.iter().enumerate() {
        b.push(i, s, None);
    }
    b.flush_run();
    // the cutting sweeps (each move also has its body's probe)
    b.take().items.iter().filter(|it| it.body.is_none()).count()
}

#[test]
fn chains_of_tiny_feeds_merge_within_the_merge_tolerance() {
    let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
    // 1000 points on a gentle arc (radius 60 mm, centre below the axis), 0.02 mm apart,
    // chorded as tiny G01 moves: CAM output
    let (c, rad) = ([-20.0, -40.0], 60.0);
    let pts: Vec<[f64; 2]> = (0..1000)
        .map(|k| {
            let t = (90.0f64 - 10.0).to_radians() + 0.02 * k as f64 / rad;
            [c[0] + rad * t.cos(), c[1] + rad * t.sin()]
        })
        .collect();
    let mut segs = vec![
        seg(Motion::Rapid, [10.0, 30.0], [pts[0][0], 30.0]),
        seg(Motion::Feed, [pts[0][0], 30.0], pts[0]),
    ];
    segs.extend(pts.windows(2).map(|w| seg(Motion::Feed, w[0], w[1])));
    segs.push(seg(Motion::Feed, pts[999], [pts[999][0], 30.0]));
    segs.push(seg(Motion::Rapid, [pts[999][0], 30.0], [10.0, 30.0]));
    let merged = sweep_count(&v35(), &segs, 0.0005);
    let unmerged = sweep_count(&v35(), &segs, 0.0);
    assert_eq!(unmerged, 1003);
    // chords of 60 mm arcs within 0.0005 mm are ~0.49 mm long: ~25 moves each
    assert!(merged < 60, "{merged} sweeps");
    let sim = |merge_tol| {
        let opts = SimOptions {
            merge_tol,
            ..SimOptions::default()
        };
        simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
    };
    let (a, b) = (sim(0.0005), sim(0.0));
    assert!(a.crashes.is_empty() && b.crashes.is_empty());
    assert!(b.removed_area > 10.0, "{}", b.removed_area);
    let h = hausdorff(&a.final_shapes, &b.final_shapes);
    assert!(h <= 0.0005, "hausdorff {h}");
    assert!(h > 0.0, "the merged result is an approximation");
    // the default merges
    assert_eq!(SimOptions::default().merge_tol, 0.0005);
}

/// A path of feeds swept as one ring removes what the moves swept one by one remove:
/// a wavy contour of 0.05 mm moves, two small arcs, sharp corners, a reversal and a
/// 180° turn, in two passes, then a rapid that ploughs the stock left (the same crash
/// either way).
#[test]
fn feed_paths_remove_exactly_what_the_single_moves_remove() {
    let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
    let wave = |z: f64| 20.0 + 1.5 * (z / 1.7).sin() + 0.4 * (z / 0.3).sin();
    let mut segs = Vec::new();
    for (pass, off) in [(0, 2.0), (1, 0.0)] {
        let n = 600;
        let pts: Vec<[f64; 2]> = (0..=n)
            .map(|k| {
                let z = 1.0 - 31.0 * f64::from(k) / f64::from(n);
                [z, wave(z.min(0.0)) + off]
            })
            .collect();
        segs.push(seg(Motion::Rapid, [5.0, 30.0], [pts[0][0], 30.0]));
        segs.push(seg(Motion::Feed, [pts[0][0], 30.0], pts[0]));
        segs.extend(pts.windows(2).map(|w| seg(Motion::Feed, w[0], w[1])));
        let last = pts[n as usize];
        // two R0.5 half circles (chorded arcs join the path), then a sharp corner, a
        // reversal back along the path and a 180° turn
        let end = [last[0] - 2.0, last[1]];
        for (k, ccw) in [(0.0, false), (1.0, true)] {
            let mut arc = seg(
                Motion::Feed,
                [last[0] - k, last[1]],
                [last[0] - k - 1.0, last[1]],
            );
            arc.arc = Some(Arc {
                center: Pt::new(last[0] - k - 0.5, last[1]),
                ccw,
            });
            segs.push(arc);
        }
        segs.push(seg(Motion::Feed, end, [end[0], end[1] - 1.0]));
        segs.push(seg(
            Motion::Feed,
            [end[0], end[1] - 1.0],
            [end[0] + 2.0, end[1] - 1.0],
        ));
        segs.push(seg(
            Motion::Feed,
            [end[0] + 2.0, end[1] - 1.0],
            [end[0] + 1.0, end[1] - 1.0],
        ));
        segs.push(seg(
            Motion::Feed,
            [end[0] + 1.0, end[1] - 1.0],
            [end[0] + 1.0, 30.0],
        ));
        if pass == 1 {
            segs.push(seg(
                Motion::Rapid,
                [end[0] + 1.0, 30.0],
                [end[0] - 3.0, 10.0],
            ));
        }
        segs.push(seg(Motion::Rapid, [end[0] + 1.0, 30.0], [5.0, 30.0]));
    }
    let sim = |feed_paths| {
        let opts = SimOptions {
            feed_paths,
            ..SimOptions::default()
        };
        simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
    };
    let (paths, single) = (sim(true), sim(false));
    assert!(single.removed_area > 100.0, "{}", single.removed_area);
    let xor = symmetric_difference_area(&paths.final_shapes, &single.final_shapes);
    assert!(xor < 1e-6, "symmetric difference {xor} mm²");
    let h = hausdorff(&paths.final_shapes, &single.final_shapes);
    assert!(h < 1e-6, "hausdorff {h}");
    let verdicts = |s: &Simulation| s.crashes.iter().map(|c| c.segment).collect::<Vec<_>>();
    assert_eq!(verdicts(&paths), verdicts(&single));
    assert_eq!(verdicts(&paths).len(), 1);
    assert!((paths.crashes[0].area - single.crashes[0].area).abs() < 1e-6);
    // and far fewer sweeps: one ring per path of up to 128 vertices
    let count = |on: bool| {
        let bb = Rect::new(geom::Pt::new(-200.0, -200.0), geom::Pt::new(200.0, 200.0));
        let grid = Grid::new(bb.grown(1.0));
        let tools = v35();
        let mut b = SweepBuilder::new(&grid, bb, &tools, 0.001, 0.0005);
        b.set_feed_paths(on);
        for (i, s) in segs.iter().enumerate() {
            b.push(i, s, None);
        }
        b.flush_run();
        b.take().items.len()
    };
    let (with, without) = (count(true), count(false));
    assert!(
        with * 5 < without,
        "{with} sweeps with paths, {without} without"
    );
}

#[test]
fn snapshots_in_the_one_pass_match_the_prefix_runs() {
    let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
    // a chain of tiny feeds (merged across the snapshot counts) between two plain cuts
    let pts: Vec<[f64; 2]> = (0..400)
        .map(|k| [-2.0 - 0.02 * k as f64, 22.0 - 0.001 * k as f64])
        .collect();
    let mut segs = vec![
        seg(Motion::Rapid, [10.0, 30.0], [2.0, 23.0]),
        seg(Motion::Feed, [2.0, 23.0], [-30.0, 23.0]),
        seg(Motion::Rapid, [-30.0, 30.0], [pts[0][0], 30.0]),
        seg(Motion::Feed, [pts[0][0], 30.0], pts[0]),
    ];
    segs.extend(pts.windows(2).map(|w| seg(Motion::Feed, w[0], w[1])));
    segs.push(seg(Motion::Feed, pts[399], [pts[399][0], 30.0]));
    let marks = vec![1, 2, 100, 250, segs.len(), 0, 100];
    let opts = SimOptions {
        snapshot_after: marks,
        ..SimOptions::default()
    };
    let sim = simulate(&blank, &v35(), &segs, &opts, &mut |_| {});
    let counts: Vec<usize> = sim.snapshots.iter().map(|s| s.0).collect();
    assert_eq!(counts, [1, 2, 100, 250]);
    for (k, shapes) in &sim.snapshots {
        let prefix = run(&blank, &v35(), &segs[..*k]);
        let h = hausdorff(shapes, &prefix.final_shapes);
        assert!(h <= 0.0005, "after {k} moves: hausdorff {h}");
    }
    assert_eq!(sim.final_shapes, run(&blank, &v35(), &segs).final_shapes);
}

/// A part-off in the middle of a long program (epochs of 1 024 moves, the next one's
/// sweeps built while the last is cut): the pin falls before any later epoch is built,
/// so a rapid through its place three epochs later meets air, while a rapid into the
/// bar at the end is a crash. Removed: a 3 mm groove 2 mm deep, the kerf to the axis
/// and the crash's 3 × 5, 6 + 75 + 15 = 96 mm² (the fallen pin stays in the section).
#[test]
fn a_part_off_inside_a_long_program_drops_the_piece_for_later_epochs() {
    let blank = Blank::bar(50.0, 100.0, 0.0, None).unwrap();
    let blade = |motion, from, to| {
        let mut s = seg(motion, from, to);
        s.hint = expander::ToolHint::Grooving;
        s
    };
    let mut segs = vec![];
    for k in 1..=2_000 {
        let r = 24.0 - 0.0005 * f64::from(k);
        segs.push(blade(Motion::Feed, [-40.0, 26.0], [-40.0, r]));
        segs.push(blade(Motion::Rapid, [-40.0, r], [-40.0, 26.0]));
    }
    segs.push(blade(Motion::Rapid, [-40.0, 26.0], [-13.0, 26.0]));
    let part_off = segs.len();
    segs.push(blade(Motion::Feed, [-13.0, 26.0], [-13.0, 0.0]));
    segs.push(blade(Motion::Rapid, [-13.0, 0.0], [-13.0, 26.0]));
    for _ in 0..750 {
        segs.push(blade(Motion::Rapid, [-13.0, 26.0], [-60.0, 30.0]));
        segs.push(blade(Motion::Rapid, [-60.0, 30.0], [-13.0, 26.0]));
    }
    segs.push(blade(Motion::Rapid, [-13.0, 26.0], [-6.0, 26.0]));
    let through_pin = segs.len();
    segs.push(blade(Motion::Rapid, [-6.0, 26.0], [-6.0, 10.0]));
    segs.push(blade(Motion::Rapid, [-6.0, 10.0], [-6.0, 26.0]));
    segs.push(blade(Motion::Rapid, [-6.0, 26.0], [-70.0, 26.0]));
    segs.push(blade(Motion::Rapid, [-70.0, 26.0], [-70.0, 20.0]));
    assert!(part_off % 1_024 > 0 && through_pin / 1_024 > part_off / 1_024);
    let sim = run(&blank, &ToolTable::empty(), &segs);
    let crashed: Vec<usize> = sim.crashes.iter().map(|c| c.segment).collect();
    assert_eq!(crashed, vec![segs.len() - 1], "{:?}", sim.crashes);
    assert!(
        (sim.crashes[0].area - 15.0).abs() < 1e-6,
        "{:?}",
        sim.crashes
    );
    assert!(
        (sim.removed_area - 96.0).abs() < 1e-6,
        "{}",
        sim.removed_area
    );
}

/// A program of more than 5 000 moves gets its snapshots at epoch ends: 6 400 grooving
/// pecks (3 mm blade-like V35 plunges stepped 0.01 mm, each followed by a retract) ask
/// for two counts; each snapshot is labelled with the moves it holds (at or after the
/// count asked for, before the end) and is the stock of that prefix run.
#[test]
fn a_long_program_gets_its_snapshots_at_epoch_ends() {
    let blank = Blank::bar(50.0, 100.0, 0.0, None).unwrap();
    let mut segs = vec![];
    for k in 0..3_200 {
        let z = -1.0 - 0.01 * f64::from(k);
        segs.push(seg(
            Motion::Feed,
            [z, 26.0],
            [z, 24.0 - 0.0001 * f64::from(k)],
        ));
        segs.push(seg(
            Motion::Rapid,
            [z, 24.0 - 0.0001 * f64::from(k)],
            [z - 0.01, 26.0],
        ));
    }
    let opts = SimOptions {
        snapshot_after: vec![1_000, 4_000],
        ..SimOptions::default()
    };
    let sim = simulate(&blank, &v35(), &segs, &opts, &mut |_| {});
    let counts: Vec<usize> = sim.snapshots.iter().map(|s| s.0).collect();
    assert_eq!(counts.len(), 2, "{counts:?}");
    assert!(
        counts[0] >= 1_000 && counts[1] >= 4_000 && counts[1] < segs.len(),
        "{counts:?}"
    );
    for (k, shapes) in &sim.snapshots {
        let prefix = run(&blank, &v35(), &segs[..*k]);
        let h = hausdorff(shapes, &prefix.final_shapes);
        assert!(h <= 0.0005, "after {k} moves: hausdorff {h}");
        assert!((area(shapes) - area(&prefix.final_shapes)).abs() < 1e-6);
    }
    // and the removal does not depend on whether snapshots were asked for
    assert_eq!(sim.final_shapes, run(&blank, &v35(), &segs).final_shapes);
}

#[test]
fn zig_zags_and_reversals_are_not_merged() {
    // sideways zig-zag: every move advances along Z, but the points are 0.002 mm apart
    let zz: Vec<Segment> = (0..100)
        .map(|k| {
            let r = |k: i32| 20.0 + 0.002 * f64::from(k % 2);
            let (z0, z1) = (-0.05 * f64::from(k), -0.05 * f64::from(k + 1));
            seg(Motion::Feed, [z0, r(k)], [z1, r(k + 1)])
        })
        .collect();
    assert_eq!(sweep_count(&v35(), &zz, 0.0005), 100);
    // back and forth along almost the same line (0.0001 mm apart): each move reverses
    let back: Vec<Segment> = (0..100)
        .map(|k| {
            let z = |k: i32| -0.05 * f64::from(k % 2);
            let r = |k: i32| 20.0 + 0.0001 * f64::from(k);
            seg(Motion::Feed, [z(k), r(k)], [z(k + 1), r(k + 1)])
        })
        .collect();
    assert_eq!(sweep_count(&v35(), &back, 0.0005), 100);
    // a rapid in between always ends a merged run
    let mut with_rapid = vec![
        seg(Motion::Feed, [0.0, 20.0], [-0.05, 20.0001]),
        seg(Motion::Feed, [-0.05, 20.0001], [-0.1, 20.0]),
        seg(Motion::Rapid, [-0.1, 20.0], [-0.1, 20.0]),
    ];
    with_rapid.push(seg(Motion::Feed, [-0.1, 20.0], [-0.15, 20.0001]));
    assert_eq!(sweep_count(&v35(), &with_rapid, 0.0005), 3);
}

#[test]
fn bad_input_is_skipped_with_a_warning_never_a_panic() {
    let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
    let mut arc = seg(Motion::Feed, [1e300, 0.0], [0.0, 1e300]);
    arc.arc = Some(Arc {
        center: Pt::new(f64::NAN, 0.0),
        ccw: false,
    });
    let mut thread = seg(Motion::Thread, [0.0, 24.0], [-1e6, 24.0]);
    thread.lead = 1e-9;
    let segs = [
        seg(Motion::Feed, [f64::NAN, 1.0], [0.0, 0.0]),
        seg(
            Motion::Rapid,
            [f64::INFINITY, 1.0],
            [0.0, f64::NEG_INFINITY],
        ),
        arc,
        seg(Motion::Feed, [1e11, 20.0], [-1e11, 20.0]),
        seg(Motion::Feed, [3.0, 3.0], [3.0, 3.0]),
        thread,
    ];
    let mut calls = Vec::new();
    let sim = simulate(
        &blank,
        &ToolTable::empty(),
        &segs,
        &SimOptions {
            chord_tol: -1.0,
            ..SimOptions::default()
        },
        &mut |n| calls.push(n),
    );
    assert!(sim.warnings.iter().any(|(i, _)| *i == 0));
    assert!(sim.warnings.iter().any(|(i, _)| *i == 1));
    assert!(sim.warnings.iter().any(|(i, _)| *i == 2));
    assert!(sim
        .warnings
        .iter()
        .any(|(i, w)| *i == 5 && w.contains("swept continuously")));
    // the huge pass still turned the whole bar down to r 20
    assert!(
        (area(&sim.final_shapes) - 110.0 * 20.0).abs() < 1e-6,
        "{}",
        area(&sim.final_shapes)
    );
    assert_eq!(calls.last(), Some(&segs.len()));
}

/// Arcs swept as rings over a tube with a sawtooth of 3 000 teeth (split into tiles
/// about 1.2 mm long, many wholly inside an R10 arc's sweep without meeting one of its
/// edges, others in its box but outside it): the removal with the rings' air tests
/// equals the one without (every tile tried with the ring's full edge test), so no tile
/// an arc cuts was skipped; then a rapid that crashes into what is left.
/// Roughing passes (each lowering the flat top, so each covers the last there),
/// rapids back over the cut, one rapid through material a pass in the same batch cut
/// and one into stock: leaving covered sweeps out of the batches removes exactly what
/// every boolean call removes, with the same crashes.
#[test]
fn covered_sweeps_left_out_remove_exactly_what_every_sweep_removes() {
    let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
    let mut segs = Vec::new();
    for k in 1..=40 {
        let r = 25.0 - 0.05 * f64::from(k);
        let zend = -30.0 + 0.1 * f64::from(k % 3);
        segs.push(seg(Motion::Rapid, [5.0, r + 0.55], [5.0, r]));
        segs.push(seg(Motion::Feed, [5.0, r], [zend, r]));
        segs.push(seg(Motion::Feed, [zend, r], [zend + 0.5, r + 0.5]));
        segs.push(seg(Motion::Rapid, [zend + 0.5, r + 0.5], [5.0, r + 0.5]));
    }
    // back through the last pass's cut, then down into the stock
    segs.push(seg(Motion::Rapid, [5.0, 23.1], [-20.0, 23.1]));
    segs.push(seg(Motion::Rapid, [-20.0, 23.1], [-20.0, 21.0]));
    let sim = |cover| {
        let opts = SimOptions {
            cover,
            ..SimOptions::default()
        };
        simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
    };
    let (with, without) = (sim(true), sim(false));
    assert!(without.removed_area > 50.0, "{}", without.removed_area);
    assert_eq!(same_cut(&with, &without), [segs.len() - 1]);
}

/// Asserts that two runs cut the same stock (symmetric difference and removed area
/// within 10⁻⁹) with the same crashes (move and area); returns the crashes' moves.
fn same_cut(a: &Simulation, b: &Simulation) -> Vec<usize> {
    let xor = symmetric_difference_area(&a.final_shapes, &b.final_shapes);
    assert!(xor < 1e-9, "symmetric difference {xor} mm²");
    assert!((a.removed_area - b.removed_area).abs() < 1e-9);
    let verdicts = |s: &Simulation| {
        s.crashes
            .iter()
            .map(|c| (c.segment, c.area))
            .collect::<Vec<_>>()
    };
    assert_eq!(verdicts(a), verdicts(b));
    a.crashes.iter().map(|c| c.segment).collect()
}

#[test]
fn ring_air_tests_remove_exactly_what_every_tile_test_removes() {
    let mut outline = vec![[-30.0, 28.0], [0.0, 28.0]];
    outline.extend((0..=3000).map(|k| [-0.01 * f64::from(k), 30.0 + 0.02 * f64::from(k % 2)]));
    let blank = Blank::from_rings(&[outline], "sawtooth tube");
    let mut segs = Vec::new();
    for pass in 0..6 {
        let (z0, r0) = (-4.0 - 0.37 * f64::from(pass), 31.5 - 0.3 * f64::from(pass));
        segs.push(seg(Motion::Rapid, [5.0, 40.0], [z0, 40.0]));
        segs.push(seg(Motion::Feed, [z0, 40.0], [z0, r0]));
        // a lower R10 half circle, an upper R2.5 one, then out
        let mut a = seg(Motion::Feed, [z0, r0], [z0 - 20.0, r0]);
        a.arc = Some(Arc {
            center: Pt::new(z0 - 10.0, r0),
            ccw: false,
        });
        let mut b = seg(Motion::Feed, [z0 - 20.0, r0], [z0 - 25.0, r0]);
        b.arc = Some(Arc {
            center: Pt::new(z0 - 22.5, r0),
            ccw: true,
        });
        segs.extend([a, b]);
        segs.push(seg(Motion::Feed, [z0 - 25.0, r0], [z0 - 25.0, 40.0]));
    }
    segs.push(seg(Motion::Rapid, [5.0, 40.0], [-1.0, 29.0]));
    let sim = |ring_air| {
        let opts = SimOptions {
            ring_air,
            ..SimOptions::default()
        };
        simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
    };
    let (with, without) = (sim(true), sim(false));
    assert!(without.removed_area > 40.0, "{}", without.removed_area);
    assert_eq!(same_cut(&with, &without).len(), 1);
}

/// Over its memory budget a run stops at the first look (an epoch end, or a worker's 256th
/// boolean call) and says how far it got and what the removal held; within it, it runs to
/// the end as without one.
#[test]
fn a_run_over_its_memory_budget_stops_and_says_what_grew() {
    use crate::budget::{Ledger, MemoryBudget, RunMemory};
    let blank = Blank::bar(50.0, 100.0, 0.0, None).unwrap();
    // 3 000 passes 0.001 mm apart: an epoch of 1 024 moves each (programs over 5 000 moves)
    let segs: Vec<Segment> = (0..3_000)
        .flat_map(|k| {
            let r = 24.0 - 0.001 * f64::from(k);
            [
                seg(Motion::Rapid, [5.0, r + 1.0], [5.0, r]),
                seg(Motion::Feed, [5.0, r], [-40.0 - 0.01 * f64::from(k % 7), r]),
                seg(Motion::Rapid, [-40.0, r], [-40.0, r + 1.0]),
                seg(Motion::Rapid, [-40.0, r + 1.0], [5.0, r + 1.0]),
            ]
        })
        .collect();
    let with = |max_memory| {
        let opts = SimOptions {
            max_memory,
            ..SimOptions::default()
        };
        simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
    };
    if cfg!(target_os = "linux") {
        let over = with(Some(RunMemory::alone(MemoryBudget::new(1))));
        let why = over.over_budget.expect("over a budget of one byte");
        assert_eq!(why.budget, MemoryBudget::new(1));
        assert!(why.held > 1 << 20 && why.moves < segs.len(), "{why:?}");
        assert!(why.what.contains("the stock's outline"), "{}", why.what);
        let message = why.to_string();
        assert!(
            message.contains("over the memory budget of 0 KiB"),
            "{message}"
        );
        assert!(message.contains("--max-memory"), "{message}");
        // it stopped: less was cut than by the whole run
        let whole = with(Some(RunMemory::alone(MemoryBudget::new(u64::MAX / 4))));
        assert!(whole.over_budget.is_none());
        assert!(over.removed_area < whole.removed_area - 1.0);
        assert_eq!(whole.final_shapes, with(None).final_shapes);
        // in a batch the program that holds less goes on while a larger one is not done,
        // and stops once that one is
        let ledger = Ledger::new([1, u64::MAX / 2]);
        let small = with(Some(RunMemory::in_batch(
            MemoryBudget::new(1),
            ledger.clone(),
            0,
        )));
        assert!(small.over_budget.is_none());
        assert_eq!(small.final_shapes, whole.final_shapes);
        ledger.done(1);
        let alone = with(Some(RunMemory::in_batch(MemoryBudget::new(1), ledger, 0)));
        assert!(alone.over_budget.is_some());
        // a program stopped over the budget leaves what it held as the bar: one holding no
        // more goes on after it, whatever the process's own memory (it stopped too, or not,
        // as the two raced)
        let ledger = Ledger::new([1, 1]);
        let first = RunMemory::in_batch(MemoryBudget::new(1), ledger.clone(), 1);
        first.holds(u64::MAX / 2);
        assert!(first.over().is_some(), "the one to stop");
        ledger.done(1);
        let after = with(Some(RunMemory::in_batch(MemoryBudget::new(1), ledger, 0)));
        assert!(after.over_budget.is_none());
    }
}
