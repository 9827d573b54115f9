//! Acceptance of tool nose radius compensation (seed 004, spec/tnrc.md).

mod common;
use common::*;

/// Parse, expand with the table's noses, simulate.
fn run(
    program: &str,
    blank: &stock::Blank,
    tools: &stock::ToolTable,
) -> (expander::Toolpath, stock::Simulation) {
    pipeline(program, &expander::Machine::default(), blank, tools)
}

/// Largest distance from the dome centre (Z−10, r5) to the part boundary along the 45°
/// ray, minus the dome radius 10: the leftover the nose leaves there.
fn leftover_on_dome_45(final_shapes: &[stock::Shape]) -> f64 {
    let (cz, cr) = (-10.0, 5.0);
    let d = std::f64::consts::FRAC_1_SQRT_2;
    // march outward along the ray until leaving the part
    let inside = |t: f64| {
        let p = [cz + d * t, cr + d * t];
        final_shapes.iter().any(|s| point_in(&s.outer, p))
    };
    let mut t = 10.0 - 0.5;
    assert!(inside(t));
    while inside(t) {
        t += 1e-4;
    }
    t - 10.0
}

fn point_in(ring: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    let n = ring.len();
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1])
            && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
        {
            inside = !inside;
        }
    }
    inside
}

/// Seed 004 with G42 and a r1 tip-3 insert: the part is the programmed contour except the
/// inside corner at Z−35, where the nose leaves a fillet of radius 1.
#[test]
fn seed_004_with_g42_cuts_the_programmed_contour() {
    check_seed_004_compensated("programs/tnrc-seed004-rough.nc");
}

/// The same contour as a G70 finishing shape with G42 in its ns block: G70 compensates.
#[test]
fn g70_runs_its_shape_compensated() {
    check_seed_004_compensated("programs/tnrc-g70-seed004.nc");
}

fn check_seed_004_compensated(program: &str) {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/seed004-v35-r1.toml"))).unwrap();
    let blank = stock::Blank::bar(36.0, 40.0, 0.0, None).unwrap();
    let (tp, sim) = run(&read(&asset(program)), &blank, &tools);
    assert!(
        tp.alarms.is_empty() && sim.crashes.is_empty(),
        "{:?} {:?}",
        tp.alarms,
        sim.crashes
    );
    // The programmed profile with the r1 fillet in the inside corner at (Z−35, r17.957):
    // nose centre (−34, 18.957) tangent to r = 17.957 and to the face Z−35; it meets the
    // bar's Φ36 (r 18) at z = −34 − √(1 − 0.957²).
    let r_line: f64 = 35.914 / 2.0;
    let centre = [-34.0, r_line + 1.0];
    let z18 = centre[0] - (1.0f64 - (centre[1] - 18.0).powi(2)).sqrt();
    let prof = seed004_profile();
    let mut ring: Vec<[f64; 2]> = prof
        .outer
        .iter()
        .copied()
        .filter(|p| !(p[0] < -34.0 && p[0] > -40.0 + 1e-9))
        .collect();
    // insert the fillet after the point (−28.275, r_line)
    let at = ring
        .iter()
        .position(|p| (p[0] + 28.275).abs() < 1e-9 && (p[1] - r_line).abs() < 1e-9)
        .unwrap();
    let mut fillet = vec![[-34.0, r_line]];
    arc_points([-34.0, r_line], [z18, 18.0], centre, false, &mut fillet);
    for (k, p) in fillet.into_iter().enumerate() {
        ring.insert(at + 1 + k, p);
    }
    let want = [shape(ring)];
    let h = stock::hausdorff(&sim.final_shapes, &want);
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    let h_plain = stock::hausdorff(&sim.final_shapes, &[seed004_profile()]);
    eprintln!("with G42: Hausdorff {h:.5} mm (vs the sharp profile {h_plain:.5}), symmetric difference {sym:.5} mm²");
    assert!(h <= 0.01, "Hausdorff {h}");
    assert!(sym <= 0.05, "symmetric difference {sym}");
    // On the dome the nose cuts the programmed radius.
    assert!(leftover_on_dome_45(&sim.final_shapes).abs() < 0.01);
}

/// The same contour without G42/G40: the classic nose-radius error, (√2 − 1)·r of leftover
/// on the 45° point of the R10 dome — measured.
#[test]
fn without_compensation_the_dome_keeps_the_nose_radius_error() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/seed004-v35-r1.toml"))).unwrap();
    let blank = stock::Blank::bar(36.0, 40.0, 0.0, None).unwrap();
    let (tp, sim) = run(&read(&asset("programs/seed004-contour.nc")), &blank, &tools);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let leftover = leftover_on_dome_45(&sim.final_shapes);
    let classic = std::f64::consts::SQRT_2 - 1.0;
    eprintln!("uncompensated leftover at the dome's 45° point: {leftover:.4} mm (classic (√2−1)·r = {classic:.4})");
    assert!((leftover - classic).abs() < 0.01, "leftover {leftover}");
}

/// ID boring toward the chuck with G41 and tip 2 on a tube: the bore and its 45° chamfer
/// come out as programmed.
#[test]
fn id_boring_with_g41_tip_2() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/boring-r08-tip2.toml"))).unwrap();
    let blank = stock::Blank::bar(60.0, 40.0, 0.0, Some(30.0)).unwrap();
    let (tp, sim) = run(&read(&asset("programs/tnrc-id-boring.nc")), &blank, &tools);
    assert!(
        tp.alarms.is_empty() && sim.crashes.is_empty(),
        "{:?} {:?}",
        tp.alarms,
        sim.crashes
    );
    // tube Φ60 × 40, bore Φ40 with a 1 × 45° (radius) … 2 mm chamfer to Φ44 at the face
    let want = [shape(vec![
        [-40.0, 20.0],
        [-2.0, 20.0],
        [0.0, 22.0],
        [0.0, 30.0],
        [-40.0, 30.0],
    ])];
    let h = stock::hausdorff(&sim.final_shapes, &want);
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    eprintln!("ID boring with G41: Hausdorff {h:.5} mm, symmetric difference {sym:.5} mm²");
    assert!(
        h <= 0.01 && sym <= 0.01,
        "Hausdorff {h}, symmetric difference {sym}"
    );
    // and without compensation the chamfer is off by the nose error
    let (_, plain) = run(
        &read(&asset("programs/tnrc-id-boring.nc"))
            .replace("G41 ", "")
            .replace("G40 ", ""),
        &blank,
        &tools,
    );
    let h_plain = stock::hausdorff(&plain.final_shapes, &want);
    assert!(h_plain > 0.1, "uncompensated chamfer error {h_plain}");
}

/// A concave arc smaller than the nose: interference alarm at the arc's line.
#[test]
fn interference_is_an_alarm_at_its_line() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/seed004-v35-r1.toml"))).unwrap();
    let program = "M3 S800 T0101\nG0 X40 Z2\nG42 G1 X20 Z0 F100\nG1 Z-10\nG2 X21 Z-10.5 R0.5\nG1 X30\nG1 Z-20\nG40 G0 X50\n";
    let p = gcode::parse(program).unwrap();
    let opts = expander::Options {
        tools: tools.facts(),
        ..Default::default()
    };
    let tp = expander::expand(&p, &expander::Machine::default(), &opts);
    let a = tp.alarms.first().expect("interference alarm");
    assert_eq!((a.code, a.span.line), ("PS041", 5), "{a}");
    // the path is still there so the report can show the overcut
    assert!(tp.segments.len() >= 6);
}

#[test]
fn compensation_with_a_blade_is_ignored_with_a_warning() {
    let tools =
        stock::ToolTable::from_toml("[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\n").unwrap();
    let p = gcode::parse("M3 S800 T0101\nG0 X40 Z2\nG42 G1 X20 Z0 F100\nG1 Z-10\nG40 G0 X50\n")
        .unwrap();
    let opts = expander::Options {
        tools: tools.facts(),
        ..Default::default()
    };
    let tp = expander::expand(&p, &expander::Machine::default(), &opts);
    assert!(tp.alarms.is_empty());
    assert!(tp.warnings.iter().any(|w| w.code == "LS-TNRC-BLADE"));
    assert_eq!(
        tp.segments[2].to,
        expander::Pt::new(-10.0, 10.0),
        "uncompensated"
    );
}

#[test]
fn compensation_cannot_start_on_an_arc() {
    let p = gcode::parse("M3 S800 T0101\nG0 X40 Z2\nG42 G2 X20 Z0 R20 F100\n").unwrap();
    let tp = expander::expand(&p, &expander::Machine::default(), &Default::default());
    assert_eq!(tp.alarms[0].code, "PS034");
}

#[test]
fn t_word_suspends_and_the_next_move_starts_up_again() {
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/seed004-v35-r1.toml"))).unwrap();
    // r1 tip 3: along Z the imaginary tip runs on the programmed line; a taper shows the offset
    let src = "M3 S800 T0101\nG0 X40 Z2\nG42 G1 X20 Z0 F100\nG1 X30 Z-5\nT0101\nG1 X40 Z-10\nG1 Z-20\nG40 G0 X60\n";
    let p = gcode::parse(src).unwrap();
    let opts = expander::Options {
        tools: tools.facts(),
        ..Default::default()
    };
    let tp = expander::expand(&p, &expander::Machine::default(), &opts);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    // the taper X30 Z-5 ends the first section as its cancel move: at its programmed end
    let cancel = tp.segments.iter().find(|s| s.span.line == 4).unwrap();
    assert_eq!(cancel.to, expander::Pt::new(-5.0, 15.0));
    // line 6 starts up again: it ends off its programmed end by r·normal of line 7 (+r), + tip
    let startup = tp.segments.iter().find(|s| s.span.line == 6).unwrap();
    assert!(
        (startup.to.z - (-11.0)).abs() < 1e-9 && (startup.to.r - 20.0).abs() < 1e-9,
        "{:?}",
        startup.to
    );
}
