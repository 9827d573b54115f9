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
    let (sym, h) = compare(&sim.final_shapes, &want);
    eprintln!(
        "O0209: {} segments, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len()
    );
    assert!(
        h <= 0.01 && sym <= 1e-3,
        "Hausdorff {h}, symmetric difference {sym}"
    );
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
    let (sym, h) = compare(&sim.final_shapes, &want);
    eprintln!(
        "O0209 chamfers: {} segments, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len()
    );
    assert!(
        h <= 0.01 && sym <= 1e-3,
        "Hausdorff {h}, symmetric difference {sym}"
    );
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
    let (sym, h) = compare(&sim.final_shapes, &want);
    eprintln!(
        "O0210: {} segments, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len()
    );
    assert!(
        h <= 0.01 && sym <= 1e-3,
        "Hausdorff {h}, symmetric difference {sym}"
    );
}
