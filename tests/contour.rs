//! Acceptance: the seed 004 contour (G01/G02/G03 only, G42/G40 removed) cut by a sharp
//! 35° insert gives the programmed profile.

mod common;
use common::*;

/// The programmed profile of seed 004 on a Φ36 × 40 bar, computed by hand in (z, r):
/// Φ10 at Z0, the R10 dome to Φ30 at Z−10, Φ30 to Z−17.639, the concave R10 to
/// Φ32.111 at Z−22.111, the 45° line to Φ33.803 at Z−23.803, the convex R14 to Φ35.914 at
/// Z−28.275, Φ35.914 to Z−35, then the bar (Φ36) to Z−40.
fn expected() -> stock::Shape {
    let p = |z: f64, x: f64| [z, x / 2.0];
    let mut ring = vec![p(-40.0, 0.0), p(0.0, 0.0), p(0.0, 10.0)];
    // G03 X30 Z-10 R10: centre (Z-10, r5), a quarter circle.
    arc_points(p(0.0, 10.0), p(-10.0, 30.0), [-10.0, 5.0], true, &mut ring);
    ring.push(p(-17.639, 30.0));
    let (a, b) = (p(-17.639, 30.0), p(-22.111, 32.111));
    arc_points(a, b, arc_centre(a, b, 10.0, false), false, &mut ring);
    ring.push(p(-23.803, 33.803));
    let (a, b) = (p(-23.803, 33.803), p(-28.275, 35.914));
    arc_points(a, b, arc_centre(a, b, 14.0, true), true, &mut ring);
    ring.extend([p(-35.0, 35.914), p(-35.0, 36.0), p(-40.0, 36.0)]);
    shape(ring)
}

#[test]
fn seed_004_contour_with_a_sharp_insert_is_the_programmed_profile() {
    let program = read(&asset("programs/seed004-contour.nc"));
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank = stock::Blank::bar(36.0, 40.0, 0.0, None).unwrap();
    let (tp, sim) = simulate(&program, &blank, &tools);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    let want = [expected()];
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
    let want = 18.0 * 40.0 - stock::area(&[expected()]);
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
