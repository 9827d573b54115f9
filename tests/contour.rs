//! Acceptance: the seed 004 contour (G01/G02/G03 only, G42/G40 removed) cut by a sharp
//! 35° insert gives the programmed profile.

mod common;
use common::*;

#[test]
fn seed_004_contour_with_a_sharp_insert_is_the_programmed_profile() {
    let program = read(&asset("programs/seed004-contour.nc"));
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank = stock::Blank::bar(36.0, 40.0, 0.0, None).unwrap();
    let (tp, sim) = simulate(&program, &blank, &tools);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let want = [seed004_profile()];
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    let h = stock::hausdorff(&sim.final_shapes, &want);
    let area = stock::area(&want);
    eprintln!(
        "segments {}, symmetric difference {sym:.6} mm² of {area:.1}, Hausdorff {h:.5} mm",
        tp.segments.len()
    );
    assert!(h <= 0.01, "Hausdorff {h} mm > 0.01 mm");
    // Arcs are chorded at 0.001 mm: the chords lose at most 0.001 mm × 26 mm of arc.
    assert!(sym <= 0.026, "symmetric difference {sym} mm²");
    // The dome must be there: a wrong arc direction would cut a hollow instead.
    assert!((area - stock::area(&sim.final_shapes)).abs() < 0.026);
}

#[test]
fn the_cli_reports_the_same_part() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
        "--stock",
        "36x40",
        "--tools",
        asset("tools/v35-sharp.toml").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    assert_eq!(v["verdict"], "clean");
    let removed = v["removed_area_mm2"].as_f64().unwrap();
    let want = 18.0 * 40.0 - stock::area(&[seed004_profile()]);
    assert!(
        (removed - want).abs() < 0.026,
        "removed {removed} mm², expected {want}"
    );
    // x in the JSON is a diameter: the final part touches Φ36.
    let max_x = v["final"][0]["outer"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p[1].as_f64().unwrap())
        .fold(0.0, f64::max);
    assert!((max_x - 36.0).abs() < 1e-6, "max x {max_x}");
}
