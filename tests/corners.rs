//! Direct drawing dimensions on G01 (spec/dialects.md §6.5): `,C` chamfers and `,R` rounds
//! the corner at a line's end, against the next G01; the part they cut is checked against
//! the profile drawn by hand, also under G42.
mod common;

use common::{arc_points, asset, shape, simulate};

/// Up the face from Φ20 to Φ30 with a 1 mm chamfer, along Φ30 to a Φ40 shoulder at Z−20
/// with an R2 fillet.
const PART: &str = "G99 M03 S600 T0101\nG00 X20 Z2\nG01 Z0 F0.2\nG01 X30 ,C1.\nG01 Z-20 ,R2.\nG01 X40\nG00 X50 Z50\nM30\n";

/// The section by hand, (z, r): the face at Z0 up to r14, the chamfer to (−1, 15), r15 to
/// Z−18, the concave R2 about (−18, 17) to (−20, 17), the shoulder to the bar's r20.
fn part_by_hand() -> stock::Shape {
    let mut ring = vec![
        [-40.0, 0.0],
        [0.0, 0.0],
        [0.0, 14.0],
        [-1.0, 15.0],
        [-18.0, 15.0],
    ];
    arc_points(
        [-18.0, 15.0],
        [-20.0, 17.0],
        [-18.0, 17.0],
        false,
        &mut ring,
    );
    ring.extend([[-20.0, 20.0], [-40.0, 20.0]]);
    shape(ring)
}

fn bar() -> stock::Blank {
    stock::Blank::bar(40.0, 40.0, 0.0, None).unwrap()
}

fn tools(name: &str) -> stock::ToolTable {
    stock::ToolTable::from_toml(&common::read(&asset(&format!("tools/{name}")))).unwrap()
}

/// A sharp tool cuts the chamfered and rounded profile: within the arc's chord tolerance
/// (0.001 mm) of the hand-drawn section; the removed area is 99.6416 mm² (5.5 for the
/// chamfer band, 85 along Φ30, 6 + π under the fillet) less the chords' segments.
#[test]
fn chamfer_and_round_cut_the_part_drawn_by_hand() {
    let (tp, sim) = simulate(PART, &bar(), &tools("v35-sharp.toml"));
    let want = [part_by_hand()];
    let h = stock::hausdorff(&sim.final_shapes, &want);
    let sym = stock::symmetric_difference_area(&sim.final_shapes, &want);
    assert!(
        h <= 0.002 && sym <= 0.005,
        "Hausdorff {h}, symmetric difference {sym}"
    );
    let removed = stock::area(&bar().shapes) - stock::area(&sim.final_shapes);
    assert!(
        (removed - (96.5 + std::f64::consts::PI)).abs() < 0.003,
        "{removed}"
    );
    // the chamfer and the fillet belong to the blocks that asked for them
    let lines: Vec<u32> = tp.segments.iter().map(|s| s.span.line).collect();
    assert_eq!(lines, [2, 3, 4, 4, 5, 5, 6, 7]);
    assert!(tp.segments[5].arc.is_some_and(|a| !a.ccw));
}

/// Under G42 with an r0.8 insert the control offsets the chamfered path: the same part.
#[test]
fn the_offset_path_follows_the_chamfer_and_the_round() {
    let program = PART
        .replace("G01 Z0 F0.2", "G42 G01 Z0 F0.2")
        .replace("G00 X50 Z50", "G40 G00 X50 Z50");
    let (_, sim) = simulate(&program, &bar(), &tools("c80-r08-95.toml"));
    let want = [part_by_hand()];
    let h = stock::hausdorff(&sim.final_shapes, &want);
    assert!(h <= 0.002, "Hausdorff {h}");
}

/// The same corners written in a G71 shape: G71 roughs to the chamfered and rounded
/// profile, G70 finishes it, and the report finds the part exactly as intended.
const G71_PART: &str = "G99 M03 S600 T0101\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X20\nG01 Z0\nG01 X30 ,C1.\nG01 Z-20 ,R2.\nN20 G01 X42\nG70 P10 Q20\nG00 X100 Z100\nM30\n";

#[test]
fn corners_in_a_finishing_shape() {
    let (_, sim) = simulate(G71_PART, &bar(), &tools("v35-sharp.toml"));
    let h = stock::hausdorff(&sim.final_shapes, &[part_by_hand()]);
    assert!(h <= 0.002, "Hausdorff {h}");
    let table = asset("tools/v35-sharp.toml");
    let j = common::report_of(
        G71_PART,
        &["--stock", "40x40", "--tools", table.to_str().unwrap()],
    );
    assert_eq!(j["verdict"], "clean", "{j:#}");
    let d = &j["deviation"];
    assert!(d["max_overcut_mm"].as_f64().unwrap() < 0.002, "{d:#}");
    assert!(d["max_undercut_mm"].as_f64().unwrap() < 0.002, "{d:#}");
    // a corner left open at the shape's end is the control's alarm
    let open = G71_PART.replace("N20 G01 X42", "N20 G01 X42 ,C1.");
    let (tp, _) = common::pipeline(
        &open,
        &expander::Machine::default(),
        &bar(),
        &tools("v35-sharp.toml"),
    );
    let got: Vec<&str> = tp.alarms.iter().map(|a| a.message.as_str()).collect();
    assert!(
        got.iter()
            .any(|m| m
                .contains("line 9 needs a G01 line next, but the finishing shape ends (line 9)")),
        "{got:?}"
    );
}

/// What the control refuses: the alarm names the `,C`/`,R` word and says why.
#[test]
fn a_corner_without_its_second_line_is_an_alarm() {
    let run = |body: &str| {
        let program = format!("G99 M03 S600 T0101\nG00 X20 Z2\nG01 Z0 F0.2\n{body}M30\n");
        let (tp, _) = common::pipeline(
            &program,
            &expander::Machine::default(),
            &bar(),
            &tools("v35-sharp.toml"),
        );
        tp.alarms
            .iter()
            .map(|a| format!("{}:{} {}", a.span.line, a.span.column, a.message))
            .collect::<Vec<_>>()
            .join("\n")
    };
    for (body, want) in [
        ("G01 X30 ,C1.\nG00 X50\n", "4:9 the chamfer or round at the end of line 4 needs a G01 line next, but a rapid comes (line 5)"),
        ("G01 X30 ,R1.\nG02 X34 Z-2 R2\n", "needs a G01 line next, but an arc comes (line 5)"),
        ("G01 X30 ,C1.\n", "needs a G01 line next, but the program ends"),
        ("G01 X30 ,C6.\nG01 Z-20\n", "4:9 the corner at the end of line 4 cannot be made: the chamfer needs 6.0000 mm of each line, but the lines are 5.0000 and 20.0000 mm long"),
        ("G01 X30 ,C1.\nG01 X40\n", "there is no corner"),
        ("G01 X30 ,C1. ,R1.\nG01 Z-20\n", "both ,C and ,R on one block"),
        ("G01 X30 ,C0\nG01 Z-20\n", ",C0 is not a size"),
        ("G00 X30 ,C1.\nG01 Z-20\n", "address ,C has no meaning in this block"),
        ("G00 X30 ,A30.\n", "address ,A has no meaning in this block"),
        ("G01 X30 Z-5 ,A150.\n", "not both (,A150)"),
        ("G01 X30 ,A0\n", "never reaches the X given (,A0)"),
        ("G01 X30 ,A200.\n", "never reaches the X given (,A200)"),
    ] {
        let got = run(body);
        assert!(got.contains(want), "{body:?}:\n{got}");
    }
    // a dwell between the two lines is allowed
    assert_eq!(run("G01 X30 ,C1.\nG04 X0.5\nG01 Z-20\n"), "");
}

/// `,A a` gives the line's angle from +Z (counter-clockwise, X up) instead of one end
/// coordinate: from (Z0, r10), `X30 ,A150.` rises 5 mm at 150° and ends 5 / tan 30° =
/// 8.660 mm toward −Z; `Z-10 ,A165.` ends 10 · tan 15° = 2.679 mm higher.
#[test]
fn a_line_angle_gives_the_other_coordinate() {
    let end = |line: &str| {
        let program = format!("G99 M03 S600 T0101\nG00 X20 Z2\nG01 Z0 F0.2\n{line}\nM30\n");
        let (tp, _) = common::pipeline(
            &program,
            &expander::Machine::default(),
            &bar(),
            &tools("v35-sharp.toml"),
        );
        assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
        tp.segments.last().unwrap().to
    };
    let p = end("G01 X30 ,A150.");
    assert!(
        (p.z + 5.0 / 30f64.to_radians().tan()).abs() < 1e-9 && (p.r - 15.0).abs() < 1e-12,
        "{p:?}"
    );
    let p = end("G01 Z-10 ,A165.");
    assert!(
        (p.z + 10.0).abs() < 1e-12 && (p.r - (10.0 + 10.0 * 15f64.to_radians().tan())).abs() < 1e-9,
        "{p:?}"
    );
    // with a chamfer after it, as in a drawing: the taper, then ,C against the next line
    let p = end("G01 X30 ,A150. ,C1.\nG01 Z-20");
    assert!(
        (p.z + 20.0).abs() < 1e-12 && (p.r - 15.0).abs() < 1e-12,
        "{p:?}"
    );
}

/// The reader takes `,C`, `,R` and `,A` with spaces, in either case, beside a decimal comma.
#[test]
fn comma_addresses_are_read() {
    let words = |src: &str, options: gcode::ReadOptions| {
        let p = gcode::parse_with(src, options).expect("reads");
        p.programs[0]
            .blocks
            .at(0)
            .words
            .iter()
            .map(|w| (gcode::address(w.letter), w.value, w.span.column, w.span.len))
            .collect::<Vec<_>>()
    };
    let plain = gcode::ReadOptions::default();
    assert_eq!(
        words("G01 X30. ,C1.", plain),
        [
            ("G".into(), 1.0, 1, 3),
            ("X".into(), 30.0, 5, 4),
            (",C".into(), 1.0, 10, 4)
        ]
    );
    assert_eq!(words("G1Z-20,r2", plain)[2], (",R".into(), 2.0, 7, 3));
    assert_eq!(words("G1 X10 , A 30.", plain)[2], (",A".into(), 30.0, 8, 7));
    let comma = gcode::ReadOptions {
        decimal_comma: true,
        ..Default::default()
    };
    let w = words("G1 X30,5 ,C0,5", comma);
    assert_eq!((w[1].1, w[2].0.as_str(), w[2].1), (30.5, ",C", 0.5));
    let e = gcode::parse("G01 X30 ,C1. ,C2.").unwrap_err();
    assert!(
        e.message.contains("address ,C given twice"),
        "{}",
        e.message
    );
    let e = gcode::parse("G01 X30 ,C").unwrap_err();
    assert!(
        e.message.contains("address ,C has no value"),
        "{}",
        e.message
    );
}

/// `,A` in a G71 shape: the taper from (Z0, r10) at 150° to Φ30, then Φ30 to Z−20: G71 and
/// G70 cut the section drawn by hand (Hausdorff ≤ 0.002 mm).
#[test]
fn a_line_angle_in_a_finishing_shape() {
    let program = "G99 M03 S600 T0101\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X20\nG01 Z0\nG01 X30 ,A150.\nG01 Z-20\nN20 G01 X42\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let (_, sim) = simulate(program, &bar(), &tools("v35-sharp.toml"));
    let zt = -5.0 / 30f64.to_radians().tan();
    let want = shape(vec![
        [-40.0, 0.0],
        [0.0, 0.0],
        [0.0, 10.0],
        [zt, 15.0],
        [-20.0, 15.0],
        [-20.0, 20.0],
        [-40.0, 20.0],
    ]);
    let h = stock::hausdorff(&sim.final_shapes, &[want]);
    assert!(h <= 0.002, "Hausdorff {h}");
}

/// System A's corners without a comma under the profile's `g01_cr = "plain"`: `X30 C-1.`
/// (the next move goes toward −Z) and `Z-20 R2.` (toward +X) cut the same part as `,C1.` and
/// `,R2.`; a sign against the next move, or a corner between moves not at 90°, is an alarm;
/// under the comma form (the default) a plain R on a G01 is an error naming the key.
#[test]
fn plain_corners_of_system_a() {
    let plain = expander::Machine::from_toml("g01_cr = \"plain\"").unwrap();
    let program = |a: &str, b: &str| {
        format!("G99 M03 S600 T0101\nG00 X20 Z2\nG01 Z0 F0.2\nG01 X30 {a}\nG01 {b}\nG01 X40\nG00 X50 Z50\nM30\n")
    };
    let (tp, sim) = common::pipeline(
        &program("C-1.", "Z-20 R2."),
        &plain,
        &bar(),
        &tools("v35-sharp.toml"),
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let h = stock::hausdorff(&sim.final_shapes, &[part_by_hand()]);
    assert!(h <= 0.002, "Hausdorff {h}");
    let alarms = |machine: &expander::Machine, a: &str, b: &str| {
        let (tp, _) = common::pipeline(&program(a, b), machine, &bar(), &tools("v35-sharp.toml"));
        tp.alarms
            .iter()
            .map(|a| a.message.clone())
            .collect::<Vec<_>>()
            .join("\n")
    };
    let wrong = alarms(&plain, "C1.", "Z-20");
    assert!(
        wrong.contains("goes toward +Z, but it goes the other way"),
        "{wrong}"
    );
    let slanted = alarms(&plain, "C-1.", "X34 Z-20");
    assert!(
        slanted.contains("between a Z and an X move at 90°"),
        "{slanted}"
    );
    let comma = alarms(&expander::Machine::default(), ",C1.", "Z-20 R2.");
    assert!(
        comma.contains("R2 on a G01: a corner round is written ,R here"),
        "{comma}"
    );
    // in a G71 shape too
    let g71 = G71_PART
        .replace("G01 X30 ,C1.", "G01 X30 C-1.")
        .replace("G01 Z-20 ,R2.", "G01 Z-20 R2.");
    let (tp, sim) = common::pipeline(&g71, &plain, &bar(), &tools("v35-sharp.toml"));
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let h = stock::hausdorff(&sim.final_shapes, &[part_by_hand()]);
    assert!(h <= 0.002, "Hausdorff {h}");
}
