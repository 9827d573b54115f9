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

/// O0006's G73 with 3 000 passes (21 000 moves; each pass (1, 0.5) mm / 2 999 = 0.00037 mm
/// from the last, within the merge tolerance): its
/// passes are cut as groups (`stock::SimOptions::pass_groups`), and the part is within
/// `merge_tol / 2` of the one cut pass by pass, with the same (no) crashes; both leave the
/// allowance.
#[test]
fn o0006_g73_of_3000_passes_groups_within_half_the_merge_tolerance() {
    let text = read(&asset("programs/O0006-rough.nc"))
        .replace("g73 u1.0 w1.0 r3 ", "g73 u1.0 w1.0 r3000 ");
    assert!(text.contains("r3000"));
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank =
        stock::Blank::from_profile_toml(&read(&asset("blanks/o0006-casting.toml")), 0.001).unwrap();
    let (tp, grouped) = simulate(&text, &blank, &tools);
    assert!(tp.segments.len() > 20_000, "{}", tp.segments.len());
    let single = stock::simulate(
        &blank,
        &tools,
        &tp.segments,
        &stock::SimOptions {
            pass_groups: false,
            ..Default::default()
        },
        &mut |_| {},
    );
    let h = stock::hausdorff(&grouped.final_shapes, &single.final_shapes);
    eprintln!("grouped against pass by pass: Hausdorff {h:.7} mm");
    assert!(h <= 0.00025, "Hausdorff {h}");
    assert_eq!(grouped.crashes, single.crashes);
    let want = [o0006_part(0.3, 0.25)];
    assert!(stock::hausdorff(&grouped.final_shapes, &want) <= 0.01);
}

/// Run `program` (from assets/programs) on a Φ60 × 80 bar with its face at Z0, with or
/// without its G70 line.
fn on_bar(program: &str, with_g70: bool) -> (expander::Toolpath, stock::Simulation) {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank = stock::Blank::bar(60.0, 80.0, 0.0, None).unwrap();
    let text: String = read(&asset(&format!("programs/{program}")))
        .lines()
        .filter(|l| with_g70 || !l.starts_with("G70"))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(text.contains("G70"), with_g70);
    simulate(&text, &blank, &tools)
}

/// Compare the part with the expected ring (z, r), printing the measures.
fn assert_part(sim: &stock::Simulation, tp: &expander::Toolpath, ring: Vec<[f64; 2]>) {
    let want = [shape(ring)];
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    let h = stock::hausdorff(&sim.final_shapes, &want);
    eprintln!(
        "{} segments, {} crashes, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len(),
        sim.crashes.len()
    );
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    assert!(h <= 0.01, "Hausdorff {h}, symmetric difference {sym}");
}

/// The G71 type I part (z, r), moved by (dz, dr): chamfer, concave R5, convex R10, then
/// the bar Φ60 behind Z-50.
fn type1_part(dz: f64, dr: f64) -> Vec<[f64; 2]> {
    // the chamfer (Z0 r8)-(Z-2 r10) moved, cut by the bar face Z0
    let mut ring = vec![[0.0, 0.0], [0.0, 8.0 + dr + dz], [-2.0 + dz, 10.0 + dr]];
    ring.push([-15.0 + dz, 10.0 + dr]);
    let (a, b) = ([-15.0 + dz, 10.0 + dr], [-20.0 + dz, 15.0 + dr]);
    arc_points(a, b, arc_centre(a, b, 5.0, false), false, &mut ring);
    let (a, b) = ([-30.0 + dz, 15.0 + dr], [-38.0 + dz, 23.0 + dr]);
    ring.push(a);
    arc_points(a, b, arc_centre(a, b, 10.0, true), true, &mut ring);
    ring.extend([
        [-50.0 + dz, 23.0 + dr],
        [-50.0 + dz, 30.0],
        [-80.0, 30.0],
        [-80.0, 0.0],
    ]);
    ring
}

/// G71 type I: before G70 the part is the shape moved by the allowance (Δu/2 = 0.2,
/// Δw = 0.1); after G70 it is the shape.
#[test]
fn g71_type_1_roughs_to_the_allowance_and_g70_finishes() {
    let (tp, sim) = on_bar("G71-type1.nc", false);
    assert_part(&sim, &tp, type1_part(0.1, 0.2));
    let (tp, sim) = on_bar("G71-type1.nc", true);
    assert_part(&sim, &tp, type1_part(0.0, 0.0));
}

/// The G71 type II part (z, r) moved by (dz, dr): Φ30, a pocket to Φ20, up to Φ40.
fn type2_part(dz: f64, dr: f64) -> Vec<[f64; 2]> {
    vec![
        [0.0, 0.0],
        [0.0, 15.0 + dr],
        [-10.0 + dz, 15.0 + dr],
        [-20.0 + dz, 10.0 + dr],
        [-30.0 + dz, 10.0 + dr],
        [-40.0 + dz, 20.0 + dr],
        [-50.0 + dz, 20.0 + dr],
        [-50.0 + dz, 30.0],
        [-80.0, 30.0],
        [-80.0, 0.0],
    ]
}

/// G71 type II with a pocket: the layers reach into the pocket without a rapid through
/// stock (no crash), the allowance is left, and G70 finishes the shape.
#[test]
fn g71_type_2_cuts_the_pocket() {
    let (tp, sim) = on_bar("G71-type2.nc", false);
    assert_part(&sim, &tp, type2_part(0.1, 0.2));
    let (tp, sim) = on_bar("G71-type2.nc", true);
    assert_part(&sim, &tp, type2_part(0.0, 0.0));
}

/// The G72 part (z, r) moved by (dz, dr): face Z-12 down to Φ40, 45° cone to Φ30 at Z-7,
/// Φ30 to Z-2, chamfer to Φ26 at Z0.
fn g72_part(dz: f64, dr: f64) -> Vec<[f64; 2]> {
    vec![
        [0.0, 0.0],
        [0.0, 13.0 + dr + dz],
        [-2.0 + dz, 15.0 + dr],
        [-7.0 + dz, 15.0 + dr],
        [-12.0 + dz, 20.0 + dr],
        [-12.0 + dz, 30.0],
        [-80.0, 30.0],
        [-80.0, 0.0],
    ]
}

/// G72 facing: layers of 2 mm along −Z cut along −X; allowance Δu/2 = 0.2, Δw = 0.2.
#[test]
fn g72_faces_to_the_allowance_and_g70_finishes() {
    let (tp, sim) = on_bar("G72-facing.nc", false);
    let layers = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Feed && s.from.z == s.to.z && s.span.line == 5)
        .count();
    // from A at Z2 to B' at Z-11.8 (13.8 deep): layers at Z0, -2, -4, -6, -8, -10; the last
    // 1.8 mm is the final pass along the moved shape
    assert_eq!(layers, 6);
    assert_part(&sim, &tp, g72_part(0.2, 0.2));
    let (tp, sim) = on_bar("G72-facing.nc", true);
    assert_part(&sim, &tp, g72_part(0.0, 0.0));
}

/// A finishing shape of 3000 blocks (X = 10 + 40·t², Z = −60·t) roughed by G71 in 1 mm
/// layers and finished by G70: the part equals the shape (the run takes well under a
/// second in release; see PERFORMANCE.md).
#[test]
fn g71_with_a_3000_block_shape() {
    let n = 3000;
    let mut prog = String::from("O0713\nG99 M03 S800 T0101\nG00 X62 Z2\nG71 U1 R0.5\n");
    prog += "G71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X10\nG01 Z0 F0.1\n";
    let mut ring = vec![[0.0, 0.0], [0.0, 5.0]];
    for k in 1..=n {
        let t = k as f64 / n as f64;
        let (z, x) = (-60.0 * t, 10.0 + 40.0 * t * t);
        prog += &format!("X{x:.4} Z{z:.4}\n");
        ring.push([z, x / 2.0]);
    }
    prog += "N20 X62\nG70 P10 Q20\nM30\n";
    ring.extend([[-60.0, 30.0], [-80.0, 30.0], [-80.0, 0.0]]);
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let blank = stock::Blank::bar(60.0, 80.0, 0.0, None).unwrap();
    let t0 = std::time::Instant::now();
    let (tp, sim) = simulate(&prog, &blank, &tools);
    eprintln!("{:?}", t0.elapsed());
    assert!(tp.segments.len() > 2 * n, "{}", tp.segments.len());
    assert_part(&sim, &tp, ring);
}
