//! Acceptance of the single-pass turning cycles against hand-computed geometry.

mod common;
use common::*;

/// O0002 (seed 001) on a Φ125 × 110 bar with a sharp 35° insert: Φ60 from Z0 to Z−30,
/// cone to Φ120 at Z−80, Φ120 to Z−110 — even with the seed's odd pass order.
#[test]
fn o0002_turns_the_seed_001_part() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank = stock::Blank::bar(125.0, 110.0, 0.0, None).unwrap();
    let (tp, sim) = simulate(&read(&asset("programs/O0002.nc")), &blank, &tools);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let want = [shape(vec![
        [0.0, 0.0],
        [0.0, 30.0],
        [-30.0, 30.0],
        [-80.0, 60.0],
        [-110.0, 60.0],
        [-110.0, 0.0],
    ])];
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    let h = stock::hausdorff(&sim.final_shapes, &want);
    eprintln!(
        "{} segments, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len()
    );
    assert!(
        h <= 0.01 && sym <= 1e-3,
        "Hausdorff {h}, symmetric difference {sym}"
    );
}

/// The four moves of G90 from seed 001's figure: rapid X, feed to the end, feed X back, rapid Z back.
#[test]
fn g90_moves_and_modal_words() {
    let p = gcode::parse("M3 S300\nG0 X130 Z3\nG90 X120 Z-110 F200\nX110 Z-30\nX100\nG0 X120 Z-30\nG90 X120 Z-44 R-7.5 F150\nZ-56 R-15\n").unwrap();
    let tp = expander::expand(&p, &expander::Machine::default(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let ends: Vec<(f64, f64)> = tp.segments.iter().map(|s| (s.to.z, 2.0 * s.to.r)).collect();
    assert_eq!(
        &ends[1..5],
        &[(3.0, 120.0), (-110.0, 120.0), (-110.0, 130.0), (3.0, 130.0)]
    );
    assert_eq!(
        &ends[5..9],
        &[(3.0, 110.0), (-30.0, 110.0), (-30.0, 130.0), (3.0, 130.0)]
    );
    // "X100;" keeps Z-30
    assert_eq!(
        &ends[9..13],
        &[(3.0, 100.0), (-30.0, 100.0), (-30.0, 130.0), (3.0, 130.0)]
    );
    // cone: cut start X = 120 + 2R = 105 at Z-30, then Z-56 R-15 keeps X120: start X90
    let after_g0 = 14;
    assert_eq!(ends[after_g0], (-30.0, 105.0));
    assert_eq!(ends[after_g0 + 1], (-44.0, 120.0));
    assert_eq!(ends[after_g0 + 3], (-30.0, 90.0));
    assert_eq!(ends[after_g0 + 4], (-56.0, 120.0));
    assert!(tp.segments[after_g0 + 1].span.line == 7);
}

#[test]
fn g90_r_larger_than_u_with_opposite_sign_is_an_alarm() {
    let p = gcode::parse("M3 S300\nG0 X40 Z3\nG90 X60 Z-20 R-15 F100\n").unwrap();
    let tp = expander::expand(&p, &expander::Machine::default(), &Default::default());
    assert_eq!(tp.alarms[0].code, "LS-G90-R");
    assert_eq!(tp.alarms[0].span.line, 3);
}

/// G94 facing: rapid Z, feed X to the end, feed Z back, rapid X back.
#[test]
fn g94_faces_a_bar() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank = stock::Blank::bar(50.0, 30.0, 2.0, None).unwrap();
    let program = "M3 S500 T0101\nG0 X55 Z5\nG94 X0 Z1 F100\nZ0\n";
    let (tp, sim) = simulate(program, &blank, &tools);
    let ends: Vec<(f64, f64)> = tp.segments.iter().map(|s| (s.to.z, 2.0 * s.to.r)).collect();
    assert_eq!(
        &ends[1..5],
        &[(1.0, 55.0), (1.0, 0.0), (5.0, 0.0), (5.0, 55.0)]
    );
    let want = [shape(vec![
        [0.0, 0.0],
        [0.0, 25.0],
        [-28.0, 25.0],
        [-28.0, 0.0],
    ])];
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    assert!(sym < 1e-3, "symmetric difference {sym}");
}

/// G92 threading, three passes to Φ27.4 at lead 2 on a Φ30 bar: the tool is stamped at
/// every lead from the pass start (Z5, 3, 1, −1, …, −19) and at the end (Z−20), all passes
/// in phase, so the section shows 60° teeth 1.3 mm deep with 0.5 mm crests.
#[test]
fn g92_cuts_the_thread_form() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/thread60.toml"))).unwrap();
    let blank = stock::Blank::bar(30.0, 30.0, 0.0, None).unwrap();
    let program =
        "G97 S500 M03 T0404\nG00 X32 Z5\nG92 X29 Z-20 F2\nX28\nX27.4\nG00 X100 Z50\nM30\n";
    let (tp, sim) = simulate(program, &blank, &tools);
    let threads: Vec<_> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .collect();
    assert_eq!(threads.len(), 3);
    assert!(threads.iter().all(|s| s.lead == 2.0 && s.span.line >= 3));
    // the hand-computed section: V flanks at ±30° from the radial, root r 13.7
    let (root, t30) = (13.7, 30f64.to_radians().tan());
    let mut stamps: Vec<f64> = (0..13)
        .map(|k| 5.0 - 2.0 * k as f64)
        .filter(|&z| z >= -19.0)
        .collect();
    stamps.push(-20.0);
    let surface = |z: f64| {
        stamps
            .iter()
            .map(|&s| root + (z - s).abs() / t30)
            .fold(15.0, f64::min)
    };
    let mut ring = vec![[-30.0, 0.0], [0.0, 0.0]];
    let n = 20_000;
    for i in 0..=n {
        let z = -21.0 * i as f64 / n as f64;
        ring.push([z, surface(z)]);
    }
    ring.push([-30.0, 15.0]);
    let want = [shape(ring)];
    let h = stock::hausdorff(&sim.final_shapes, &want);
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    eprintln!("G92: Hausdorff {h:.5} mm, symmetric difference {sym:.5} mm²");
    assert!(
        h <= 0.01 && sym <= 0.01,
        "Hausdorff {h}, symmetric difference {sym}"
    );
}
