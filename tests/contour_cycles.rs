//! Acceptance of the contour cycles G70–G73 against hand-computed geometry.

mod common;
use common::*;

/// The O0006 shape (seed 003) in (z, r), moved by (dz, dr), closed by the cast face Z0
/// (the shape starts on it), the cast flange Φ180 behind it and the chuck end Z-100.
fn o0006_part(dz: f64, dr: f64) -> stock::Shape {
    let mut ring = vec![[0.0, 0.0], [0.0, 40.0 + dr], [-20.0 + dz, 40.0 + dr]];
    ring.push([-30.0 + dz, 60.0 + dr]);
    ring.push([-50.0 + dz, 60.0 + dr]);
    let (a, b) = ([-50.0 + dz, 60.0 + dr], [-70.0 + dz, 80.0 + dr]);
    let c = arc_centre(a, b, 20.0, false);
    arc_points(a, b, c, false, &mut ring);
    // the 45° chamfer meets the flange r = 90 where r rises by 90 - (80 + dr)
    ring.push([-70.0 + dz - (10.0 - dr), 90.0]);
    ring.push([-100.0, 90.0]);
    ring.push([-100.0, 0.0]);
    shape(ring)
}

fn o0006(program: &str) -> (expander::Toolpath, stock::Simulation) {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank =
        stock::Blank::from_profile_toml(&read(&asset("blanks/o0006-casting.toml")), 0.001).unwrap();
    simulate(&read(&asset(program)), &blank, &tools)
}

/// G73 alone leaves exactly the allowance: the shape moved by Δu/2 = 0.25 in X (radius)
/// and Δw = 0.3 in Z.
#[test]
fn o0006_g73_leaves_the_allowance_on_the_casting() {
    let (tp, sim) = o0006("programs/O0006-rough.nc");
    let want = [o0006_part(0.3, 0.25)];
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    let h = stock::hausdorff(&sim.final_shapes, &want);
    eprintln!(
        "{} segments, {} crashes, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len(),
        sim.crashes.len()
    );
    assert!(h <= 0.01, "Hausdorff {h}, symmetric difference {sym}");
}

/// G73 then G70 (O0006 as printed): the part equals the shape.
#[test]
fn o0006_g70_finishes_the_shape() {
    let (tp, sim) = o0006("programs/O0006.nc");
    let want = [o0006_part(0.0, 0.0)];
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    let h = stock::hausdorff(&sim.final_shapes, &want);
    eprintln!(
        "{} segments, {} crashes, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len(),
        sim.crashes.len()
    );
    assert!(h <= 0.01, "Hausdorff {h}, symmetric difference {sym}");
}
