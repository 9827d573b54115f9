//! Acceptance of the grooving cycles G74, G75 and G75.1 against hand-computed geometry:
//! each program runs through the interpreter and the removal, and the final half section is
//! compared with a polygon written out here from the drawings.

mod common;
use common::*;

/// Symmetric difference (mm²) and Hausdorff distance (mm) of a result to the expected shape.
fn compare(got: &[stock::Shape], want: &[stock::Shape]) -> (f64, f64) {
    let sym = stock::symmetric_difference_area(got, want);
    let h = stock::hausdorff(got, want);
    (sym, h)
}

fn tools(name: &str) -> stock::ToolTable {
    stock::ToolTable::from_toml(&read(&asset(&format!("tools/{name}")))).unwrap()
}

/// O0209 (seed 002): `G75 X32 Z-31 P1500 Q2000` from X42 Z-28 with a 3 mm blade referenced
/// at its left corner on a Φ40 bar: a groove Φ32 from Z−31 to Z−25.
#[test]
fn o0209_cuts_the_plain_groove() {
    let blank = stock::Blank::bar(40.0, 60.0, 0.0, None).unwrap();
    let (tp, sim) = simulate(
        &read(&asset("programs/O0209.nc")),
        &blank,
        &tools("seed002-groove3.toml"),
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let want = [shape(vec![
        [0.0, 0.0],
        [0.0, 20.0],
        [-25.0, 20.0],
        [-25.0, 16.0],
        [-31.0, 16.0],
        [-31.0, 20.0],
        [-60.0, 20.0],
        [-60.0, 0.0],
    ])];
    assert_part("O0209", &tp, &sim, &want, 1e-3);
}

/// O0209 with the seed's chamfer blocks: both corners of the same blade cut the flanks to a
/// Φ40 mouth from Z−33 to Z−23 over the Φ32 floor from Z−31 to Z−25.
#[test]
fn o0209_chamfers_cut_both_flanks() {
    let blank = stock::Blank::bar(40.0, 60.0, 0.0, None).unwrap();
    let (tp, sim) = simulate(
        &read(&asset("programs/O0209-chamfers.nc")),
        &blank,
        &tools("seed002-groove3.toml"),
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let want = [shape(vec![
        [0.0, 0.0],
        [0.0, 20.0],
        [-23.0, 20.0],
        [-25.0, 16.0],
        [-31.0, 16.0],
        [-33.0, 20.0],
        [-60.0, 20.0],
        [-60.0, 0.0],
    ])];
    assert_part("O0209 chamfers", &tp, &sim, &want, 1e-3);
}

/// O0210 (seed 002) on a Φ40 × 40 bar: the G74 face groove Φ20…Φ30, 5 deep (a 3 mm face
/// blade referenced at its inner corner, plunges at Φ20, Φ22, Φ24), then the Φ10 hole
/// peck-drilled to Z−28 with its 118° point.
#[test]
fn o0210_face_groove_and_drilled_hole() {
    let blank = stock::Blank::bar(40.0, 40.0, 0.0, None).unwrap();
    let (tp, sim) = simulate(
        &read(&asset("programs/O0210.nc")),
        &blank,
        &tools("seed002-face3-drill10.toml"),
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let cone = 5.0 / 59f64.to_radians().tan();
    let want = [shape(vec![
        [-28.0, 0.0],
        [-28.0 + cone, 5.0],
        [0.0, 5.0],
        [0.0, 10.0],
        [-5.0, 10.0],
        [-5.0, 15.0],
        [0.0, 15.0],
        [0.0, 20.0],
        [-40.0, 20.0],
        [-40.0, 0.0],
    ])];
    assert_part("O0210", &tp, &sim, &want, 1e-3);
}

fn is_c() -> expander::Machine {
    expander::Machine {
        increment: expander::Increment::IsC,
        ..expander::Machine::default()
    }
}

/// Φ50 bar from Z40 to Z−20 minus the O0008 groove P1 (Z30, Φ50), P2 (Z20, Φ30),
/// P3 (Z10, Φ30), P4 (Z−7.32, Φ50).
fn o0008_part() -> [stock::Shape; 1] {
    let p4 = 10.0 - 10.0 / 30f64.to_radians().tan();
    [shape(vec![
        [-20.0, 0.0],
        [40.0, 0.0],
        [40.0, 25.0],
        [30.0, 25.0],
        [20.0, 15.0],
        [10.0, 15.0],
        [p4, 25.0],
        [-20.0, 25.0],
    ])]
}

/// O0008 (seed 000, IS-C) with a 4 mm blade (I4): the trapezoid P1..P4 exactly — the blade
/// stays inside both flanks, the groove has its drawn size.
#[test]
fn o0008_cuts_the_seed_trapezoid() {
    let blank = stock::Blank::bar(50.0, 60.0, 40.0, None).unwrap();
    let (tp, sim) = simulate_with(
        &read(&asset("programs/O0008-I4.nc")),
        &is_c(),
        &blank,
        &tools("seed000-groove4.toml"),
    );
    assert_part("O0008", &tp, &sim, &o0008_part(), 1e-3);
}

/// J2: the finishing pass alone traces the same trapezoid (no plunges: few moves).
#[test]
fn g75_1_finish_only_traces_the_trapezoid() {
    let blank = stock::Blank::bar(50.0, 60.0, 40.0, None).unwrap();
    let (tp, sim) = simulate_with(
        &read(&asset("programs/G75_1-finish-only.nc")),
        &is_c(),
        &blank,
        &tools("seed000-groove4.toml"),
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let cycle: Vec<_> = tp.segments.iter().filter(|s| s.span.line == 6).collect();
    assert!(cycle.len() <= 10, "{} moves", cycle.len());
    assert_part("J2", &tp, &sim, &o0008_part(), 1e-3);
}

/// All four corners (round, chamfer, chamfer, round), three layers (V6), rough + finish (J1):
/// the rounds are real arcs in the finishing pass, the part is the drawn section.
#[test]
fn g75_1_corners_layers_and_finish() {
    let blank = stock::Blank::bar(60.0, 40.0, 10.0, None).unwrap();
    let (tp, sim) = simulate(
        &read(&asset("programs/G75_1-corners.nc")),
        &blank,
        &tools("seed000-groove4.toml"),
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let arcs: Vec<_> = tp.segments.iter().filter(|s| s.arc.is_some()).collect();
    assert_eq!(arcs.len(), 2, "the two rounds are arcs");
    // three layers: plunge bottoms at X54, X48 and the floor X44
    let bottoms: std::collections::BTreeSet<i64> = tp
        .segments
        .iter()
        .filter(|s| s.span.line == 8 && s.motion == expander::Motion::Feed && s.from.z == s.to.z)
        .map(|s| (2000.0 * s.to.r).round() as i64)
        .collect();
    for x in [54_000, 48_000, 44_000] {
        assert!(
            bottoms.contains(&x),
            "no plunge bottom at X{}",
            x as f64 / 1000.0
        );
    }
    // hand-computed: P1 (0, 30), P2 (0, 22), P3 (−12, 22), P4 (−12 − 8/tan 60°, 30)
    let t60 = 60f64.to_radians().tan();
    let p4z = -12.0 - 8.0 / t60;
    let (s60, c60) = (60f64.to_radians().sin(), 60f64.to_radians().cos());
    let te = 2.0 / t60; // tangent length of the R2 round in the 120° floor corner
    let mut ring = vec![[-30.0, 0.0], [10.0, 0.0], [10.0, 30.0], [1.0, 30.0]];
    arc_points([1.0, 30.0], [0.0, 29.0], [1.0, 29.0], true, &mut ring);
    ring.extend([[0.0, 23.0], [-1.0, 22.0], [-12.0 + te, 22.0]]);
    let e_end = [-12.0 - te * c60, 22.0 + te * s60];
    arc_points(
        [-12.0 + te, 22.0],
        e_end,
        [-12.0 + te, 24.0],
        false,
        &mut ring,
    );
    ring.extend([
        [p4z + 1.5 * c60, 30.0 - 1.5 * s60],
        [p4z - 1.5, 30.0],
        [-30.0, 30.0],
    ]);
    let want = [shape(ring)];
    // the two rounds are chorded within 0.001 mm by the removal: a few thousandths of mm²
    assert_part("corners", &tp, &sim, &want, 5e-3);
}

/// L10 on a conical blank (profile TOML): the mouth follows the cone, the far mouth corner
/// P4 lies on it at Z−8, the floor Φ30 from Z0 to Z−8.
#[test]
fn g75_1_sloped_mouth_on_a_cone() {
    let blank =
        stock::Blank::from_profile_toml(&read(&asset("blanks/cone-10deg.toml")), 0.001).unwrap();
    let (tp, sim) = simulate(
        &read(&asset("programs/G75_1-cone.nc")),
        &blank,
        &tools("seed002-groove3.toml"),
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let t10 = 10f64.to_radians().tan();
    let want = [shape(vec![
        [-30.0, 0.0],
        [10.0, 0.0],
        [10.0, 20.0 - 10.0 * t10],
        [0.0, 20.0],
        [0.0, 15.0],
        [-8.0, 15.0],
        [-8.0, 20.0 + 8.0 * t10],
        [-30.0, 20.0 + 30.0 * t10],
    ])];
    assert_part("cone", &tp, &sim, &want, 1e-3);
}

/// O0008 exactly as printed (no I, no F): the blade width comes from the tool table's
/// T01 (a 4 mm blade, the first entry, as the program has no T word) and the feed from a
/// GSK machine profile; through the CLI.
#[test]
fn o0008_as_printed_with_the_table_blade_and_a_gsk_profile() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("o.json");
    let out = latsim(&[
        "run",
        asset("programs/O0008.nc").to_str().unwrap(),
        "--stock",
        "50x60",
        "--stock-z",
        "40",
        "--tools",
        asset("tools/seed000-groove4.toml").to_str().unwrap(),
        "--machine",
        asset("machines/gsk980tdi-isc.toml").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    let shapes: Vec<stock::Shape> = v["final"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| stock::Shape {
            outer: s["outer"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap() / 2.0])
                .collect(),
            holes: vec![],
        })
        .collect();
    let (sym, h) = compare(&shapes, &o0008_part());
    eprintln!("O0008 as printed: symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm");
    assert!(
        h <= 0.01 && sym <= 1e-3,
        "Hausdorff {h}, symmetric difference {sym}"
    );
}
