//! The Haas dialect, subprograms over files and drilling (issue 11): the acceptance programs
//! T4, T5, T8 and T9 of spec/dialects.md §7 with their numbers, and the bad inputs (a Haas
//! form under FANUC, a missing subprogram, M97 to a missing N, a recursive call).

mod common;
use common::*;
use expander::{Control, Machine, Motion, Segment};

fn tools(text: &str) -> stock::ToolTable {
    stock::ToolTable::from_toml(text).unwrap()
}

fn haas() -> Machine {
    Machine::for_control(Control::Haas)
}

/// (z, x) of a segment's end, x a diameter, rounded to 1 µm.
fn end(s: &Segment) -> (f64, f64) {
    let r = |v: f64| (v * 1000.0).round() / 1000.0;
    (r(s.to.z), r(2.0 * s.to.r))
}

const T4: &str = "%
O00400 (HAAS G71)
G18 G21 G99 ;
G50 S2000 ;
T101 ;
G97 S1000 M03 ;
G00 X52. Z2. ;
G71 P10 Q20 U0.5 W0.1 D2. F0.25 ;
N10 G00 X30. ;
G01 Z-20. F0.1 ;
X40. Z-30. ;
Z-45. ;
N20 X52. ;
G70 P10 Q20 ;
G28 U0. W0. ;
M30 ;
%
";

/// T4: type I; layers X48, 44, 40, 36, 32 and a last one at X30.5 from Z2 to the shape
/// offset by (U0.5, W0.1), each retracting 0.5 at 45° (Setting 73); one pass along the
/// offset shape; back to (52, 2); G70 the exact shape; the final section is the part.
#[test]
fn t4_haas_one_block_g71_and_g70() {
    let tools = tools(&read(&asset("tools/d55-sharp.toml")));
    let blank = stock::Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    let (tp, sim) = simulate_with(T4, &haas(), &blank, &tools);
    let g71: Vec<&Segment> = tp.segments.iter().filter(|s| s.span.line == 8).collect();
    let layers: Vec<(f64, f64)> = g71
        .windows(2)
        .filter(|w| w[0].motion == Motion::Feed && (w[0].from.r - w[0].to.r).abs() < 1e-9)
        .map(|w| {
            // the layer's end, then its retract: 0.5 up and 0.5 back
            let (a, b) = (w[0], w[1]);
            assert_eq!(b.motion, Motion::Feed);
            assert!((b.to.r - a.to.r - 0.5).abs() < 1e-9 && (b.to.z - a.to.z - 0.5).abs() < 1e-9);
            end(a)
        })
        .collect();
    assert_eq!(
        layers,
        [
            (-44.9, 48.0),
            (-44.9, 44.0),
            (-29.4, 40.0),
            (-25.4, 36.0),
            (-21.4, 32.0),
            (-19.9, 30.5)
        ]
    );
    // the pass along the offset shape (its moves carry the shape's lines), then back to A
    let pass: Vec<(f64, f64)> = tp
        .segments
        .iter()
        .skip_while(|s| s.span.line <= 8)
        .take(6)
        .map(end)
        .collect();
    assert_eq!(
        pass,
        [
            (2.1, 30.5),
            (-19.9, 30.5),
            (-29.9, 40.5),
            (-44.9, 40.5),
            (-44.9, 52.5),
            (2.0, 52.0)
        ]
    );
    let want = [shape(vec![
        [0.0, 0.0],
        [0.0, 15.0],
        [-20.0, 15.0],
        [-30.0, 20.0],
        [-45.0, 20.0],
        [-45.0, 25.0],
        [-60.0, 25.0],
        [-60.0, 0.0],
    ])];
    assert_part("T4", &tp, &sim, &want, 0.01);
    // G28 U0 W0 goes home without cutting
    assert_eq!(tp.segments.last().unwrap().to, Machine::default().home);
}

/// The same one-block G71 under fanuc-a is an alarm at its D word naming the control; the
/// CLI says where (line 8, column 23) and exits 1.
#[test]
fn haas_form_under_fanuc_a_is_an_alarm_naming_the_control() {
    let (_dir, path) = temp_program("t4.nc", T4.replace("G18 ", "").as_bytes());
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("t4.nc:8:23"), "{}", out.stderr);
    assert!(
        out.stderr
            .contains("Haas/FS15 form: run with --control haas"),
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("fanuc-a"), "{}", out.stderr);
    // and the G76 and G74/G75 one-block forms
    for (text, col) in [
        (
            "G00 X22 Z5\nG76 X17.835 Z-20. K1.082 D0.35 A60 F1.5\nM30\n",
            19,
        ),
        ("G00 X42 Z-10\nG75 X30. I1. K0. F0.05\nM30\n", 10),
    ] {
        let (_dir, path) = temp_program("one.nc", text.as_bytes());
        let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
        assert_eq!(out.code, 1, "{}", out.stderr);
        assert!(
            out.stderr.contains(&format!("one.nc:2:{col}")),
            "{}",
            out.stderr
        );
        assert!(
            out.stderr.contains("Haas") && out.stderr.contains("fanuc-a"),
            "{}",
            out.stderr
        );
    }
}

/// The thread passes: (pass start Z, cut diameter) of every pass.
fn passes(tp: &expander::Toolpath) -> Vec<(f64, f64)> {
    tp.segments
        .iter()
        .filter(|s| s.motion == Motion::Thread)
        .map(end)
        .zip(
            tp.segments
                .iter()
                .filter(|s| s.motion == Motion::Rapid && (s.from.r - 11.0).abs() < 1e-9)
                .filter(|s| s.to.r < 11.0)
                .map(|s| end(s).0),
        )
        .map(|((_, x), z)| (z, x))
        .collect()
}

/// T5: the FANUC two-block G76 and the Haas one-block G76 cut the same 11 passes (depths
/// 0.350 … 1.050, 1.062 capped at k − d, 1.082), shifted along the 30° flank, and leave
/// the same section.
#[test]
fn t5_fanuc_two_block_equals_haas_one_block() {
    let tools = tools(&read(&asset("tools/thread60.toml")));
    let blank = stock::Blank::bar(20.0, 40.0, 0.0, None).unwrap();
    let fanuc = "G21 G99 T0404 ;\nG97 S500 M03 ;\nG00 X22. Z5. ;\nG76 P010060 Q50 R0.02 ;\nG76 X17.835 Z-20. P1082 Q350 F1.5 ;\nG00 X100. Z100. ;\nM30 ;\n";
    let haas_text = "G21 G99 T0404 ;\nG97 S500 M03 ;\nM24 ;\nG00 X22. Z5. ;\nG76 X17.835 Z-20. K1.082 D0.35 A60 P1 F1.5 ;\nG00 X100. Z100. ;\nM30 ;\n";
    let mut m = haas();
    m.haas.setting86 = 0.02;
    m.haas.setting99 = 0.05;
    let (tf, sf) = simulate_with(
        fanuc,
        &Machine::for_control(Control::FanucA),
        &blank,
        &tools,
    );
    let (th, sh) = simulate_with(haas_text, &m, &blank, &tools);
    let pf = passes(&tf);
    assert_eq!(pf, passes(&th));
    let h = [
        0.350, 0.495, 0.606, 0.700, 0.783, 0.857, 0.926, 0.990, 1.050, 1.062, 1.082,
    ];
    assert_eq!(pf.len(), 11, "{pf:?}");
    for ((z, x), h) in pf.iter().zip(h) {
        let x_want = 17.835 + 2.0 * (1.082 - h);
        let z_want = 5.0 + (1.082 - h) * 30f64.to_radians().tan();
        assert!((x - x_want).abs() < 2e-3, "{x} vs {x_want}");
        assert!((z - z_want).abs() < 2e-3, "{z} vs {z_want}");
    }
    assert!((pf[0].0 - 5.423).abs() < 1e-3 && (pf[10].0 - 5.0).abs() < 1e-9);
    assert!(tf
        .segments
        .iter()
        .filter(|s| s.motion == Motion::Thread)
        .all(|s| (s.lead - 1.5).abs() < 1e-12 && (s.to.z + 20.0 - (s.from.z - 5.0)).abs() < 1e-9));
    let d = stock::hausdorff(&sf.final_shapes, &sh.final_shapes);
    assert!(d <= 0.001, "Hausdorff between the sections {d}");
    // the root of the thread is the programmed Φ17.835
    let min_r = sf
        .final_shapes
        .iter()
        .flat_map(|s| s.outer.iter())
        .filter(|p| p[0] > -19.0 && p[0] < -1.0 && p[1] > 1.0)
        .map(|p| p[1])
        .fold(f64::MAX, f64::min);
    assert!((2.0 * min_r - 17.835).abs() < 0.01, "root Φ{}", 2.0 * min_r);
}

const BLADE: &str = "[[tool]]\nt = 2\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\nreach = 30.0\n";

/// T8: M97 P100 L3 plunges to Φ34 at Z−10, −18, −26; the tool ends at (42, −34), then goes
/// to (100, 100); grooves Φ34 3 wide in the Φ40 bar; the local subprogram after M30 gives
/// no warning.
#[test]
fn t8_haas_local_subprogram_with_repeats() {
    let text = "%\nO00800 (HAAS M97)\nG18 G21 G99 ;\nT202 ;\nG97 S800 M03 ;\nG00 X42. Z-10. ;\nM97 P100 L3 ;\nG00 X100. Z100. ;\nM30 ;\nN100 G01 X34. F0.05 ;\nG00 X42. ;\nW-8. ;\nM99 ;\n%\n";
    let blank = stock::Blank::bar(40.0, 50.0, 0.0, None).unwrap();
    let (tp, sim) = simulate_with(text, &haas(), &blank, &tools(BLADE));
    let plunges: Vec<(f64, f64)> = tp
        .segments
        .iter()
        .filter(|s| s.motion == Motion::Feed)
        .map(end)
        .collect();
    assert_eq!(plunges, [(-10.0, 34.0), (-18.0, 34.0), (-26.0, 34.0)]);
    let n = tp.segments.len();
    assert_eq!(end(&tp.segments[n - 2]), (-34.0, 42.0));
    assert_eq!(end(&tp.segments[n - 1]), (100.0, 100.0));
    assert!(tp.warnings.is_empty(), "{:?}", tp.warnings);
    let mut ring = vec![[0.0, 0.0], [0.0, 20.0]];
    for z in [-7.0, -15.0, -23.0] {
        ring.extend([[z, 20.0], [z, 17.0], [z - 3.0, 17.0], [z - 3.0, 20.0]]);
    }
    ring.extend([[-50.0, 20.0], [-50.0, 0.0]]);
    assert_part("T8", &tp, &sim, &[shape(ring)], 0.01);
    // under fanuc-a, M97 is not a code: an alarm at its line
    let p = gcode::parse(text).unwrap();
    let tp = expander::expand(
        &p,
        &Machine::for_control(Control::FanucA),
        &Default::default(),
    );
    assert_eq!(tp.alarms.len(), 1);
    assert_eq!(tp.alarms[0].span.line, 7);
}

/// M97 to an N the program does not have: an alarm at the M97 word.
#[test]
fn m97_to_a_missing_n_is_an_alarm_at_the_call() {
    let (_dir, path) = temp_program(
        "m97.nc",
        b"O00001\nG21 G99\nG00 X42. Z2.\nM97 P200\nM30\nN100 G00 W-1.\nM99\n",
    );
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "haas"]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("m97.nc:4:1"), "{}", out.stderr);
    assert!(out.stderr.contains("N200"), "{}", out.stderr);
}

const DRILL: &str =
    "[[tool]]\nt = 3\nkind = \"drill\"\ndiameter = 10.0\npoint_angle = 118\nreach = 60.0\n";

/// T9: the Z sequence of G83 with full retract, and with high-speed pecks; both make the
/// Φ10 hole with its 118° point at Z−30 (full diameter to Z−27.00).
#[test]
fn t9_face_peck_drilling_on_the_axis() {
    let text = "G21 G99 T0303 ;\nG97 S600 M03 ;\nG00 X0. Z5. ;\nG83 Z-30. R-3. Q8000 P500 F0.1 ;\nG80 ;\nG00 X100. Z100. ;\nM30 ;\n";
    let blank = stock::Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    let tools = tools(DRILL);
    let point = 5.0 / 59f64.to_radians().tan();
    assert!((point - 3.0).abs() < 0.005);
    let want = [shape(vec![
        [0.0, 5.0],
        [0.0, 25.0],
        [-60.0, 25.0],
        [-60.0, 0.0],
        [-30.0, 0.0],
        [-30.0 + point, 5.0],
    ])];
    for (full, seq) in [
        (
            true,
            vec![
                (Motion::Rapid, 2.0),
                (Motion::Feed, -6.0),
                (Motion::Rapid, 2.0),
                (Motion::Rapid, -5.0),
                (Motion::Feed, -14.0),
                (Motion::Rapid, 2.0),
                (Motion::Rapid, -13.0),
                (Motion::Feed, -22.0),
                (Motion::Rapid, 2.0),
                (Motion::Rapid, -21.0),
                (Motion::Feed, -30.0),
                (Motion::Rapid, 5.0),
            ],
        ),
        (
            false,
            vec![
                (Motion::Rapid, 2.0),
                (Motion::Feed, -6.0),
                (Motion::Rapid, -5.0),
                (Motion::Feed, -14.0),
                (Motion::Rapid, -13.0),
                (Motion::Feed, -22.0),
                (Motion::Rapid, -21.0),
                (Motion::Feed, -30.0),
                (Motion::Rapid, 5.0),
            ],
        ),
    ] {
        let mut m = Machine::for_control(Control::FanucA);
        m.g83_full_retract = full;
        m.drill_clearance = 1.0;
        let (tp, sim) = simulate_with(text, &m, &blank, &tools);
        let got: Vec<(Motion, f64)> = tp
            .segments
            .iter()
            .filter(|s| s.span.line == 4)
            .map(|s| {
                assert_eq!(s.to.r, 0.0);
                (s.motion, s.to.z)
            })
            .collect();
        assert_eq!(got, seq, "full retract {full}");
        assert!((tp.dwell_s - 0.5).abs() < 1e-12);
        let h = stock::hausdorff(&sim.final_shapes, &want);
        assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
        assert!(h < 0.02, "hole off by {h}");
    }
}

/// Drilling off the axis, or with C, is an alarm at its word.
#[test]
fn drilling_off_the_axis_is_an_alarm() {
    // off the axis: the drilling cycle's alarm; with C: the C-axis word's (not simulated)
    for (text, col, code) in [
        ("G00 X20. Z5.\nG83 Z-30. R-3. F0.1\nM30\n", 1, "LS-OFF-AXIS"),
        (
            "G00 X0. Z5.\nG83 C90. Z-30. R-3. F0.1\nM30\n",
            5,
            "LS-NOT-SIMULATED",
        ),
    ] {
        let p = gcode::parse(text).unwrap();
        let tp = expander::expand(
            &p,
            &Machine::for_control(Control::FanucA),
            &Default::default(),
        );
        assert_eq!(tp.alarms.len(), 1, "{text}");
        assert_eq!((tp.alarms[0].span.line, tp.alarms[0].span.column), (2, col));
        assert_eq!(tp.alarms[0].code, code);
    }
}

/// `--lib`: a subprogram in another file runs, keeps its own file and line in diagnostics;
/// a program that is nowhere is an alarm at the call; a recursive call is bounded.
#[test]
fn subprograms_over_files() {
    let dir = tempfile::tempdir().unwrap();
    let lib = dir.path().join("lib");
    std::fs::create_dir(&lib).unwrap();
    std::fs::write(
        lib.join("O1001.nc"),
        "O1001\nG00 W-8.\nG01 U-10. F0.05\nG00 U10.\nM99\n",
    )
    .unwrap();
    // found by its first program number, not its name; line 3 has a bad word
    std::fs::write(
        lib.join("finish.tap"),
        "%\nO2002 (FINISH)\nG01 U-2. Q7\nM99\n%\n",
    )
    .unwrap();
    let main = dir.path().join("main.nc");
    std::fs::write(
        &main,
        "O0100\nG21 G99 T0505\nG00 X42. Z-5.\nM98 P41001\nM98 P2002\nM30\n",
    )
    .unwrap();
    let libs = lib.to_str().unwrap();
    let out = latsim(&[
        "check",
        main.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--lib",
        libs,
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    // the alarm names the library file and its own line
    assert!(out.stderr.contains("finish.tap:3:"), "{}", out.stderr);
    // without the call to O2002 it runs clean: four grooves
    std::fs::write(
        &main,
        "O0100\nG21 G99 T0505\nG00 X42. Z-5.\nM98 P41001\nM30\n",
    )
    .unwrap();
    let out = latsim(&[
        "expand",
        main.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--lib",
        libs,
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        out.stdout.lines().filter(|l| l.contains(",feed,")).count(),
        4
    );
    // missing program: alarm at the call's line and column
    std::fs::write(&main, "O0100\nG21 G99\nG00 X42. Z-5.\n  M98 P7777\nM30\n").unwrap();
    let out = latsim(&[
        "check",
        main.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--lib",
        libs,
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("main.nc:4:3"), "{}", out.stderr);
    assert!(out.stderr.contains("O7777"), "{}", out.stderr);
    // a library program calling itself: the nesting limit stops it, fast
    std::fs::write(lib.join("O3003.nc"), "O3003\nG00 W-1.\nM98 P3003\nM99\n").unwrap();
    std::fs::write(&main, "O0100\nG21 G99\nG00 X42. Z-5.\nM98 P3003\nM30\n").unwrap();
    let out = latsim(&[
        "check",
        main.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--lib",
        libs,
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("PS077"), "{}", out.stderr);
    assert!(out.stderr.contains("O3003.nc:3:1"), "{}", out.stderr);
    // a folder that is not there
    let out = latsim(&["check", main.to_str().unwrap(), "--lib", "/no/such/folder"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
}

/// A gouge made by a subprogram from `--lib` names that file and its line on the terminal.
#[test]
fn a_gouge_in_a_library_subprogram_names_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let lib = dir.path().join("lib");
    std::fs::create_dir(&lib).unwrap();
    std::fs::write(
        lib.join("O1001.nc"),
        "O1001\nG00 X42. Z-10.\nG01 X30. F0.1\nG00 X52.\nM99\n",
    )
    .unwrap();
    let main = dir.path().join("main.nc");
    std::fs::write(&main, "O0100\nG21 G99 T0101 M03 S800\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0 W0 F0.25\nN10 G00 X40.\nG01 Z-30. F0.1\nN20 X52.\nG70 P10 Q20\nM98 P1001\nG00 X100. Z100.\nM30\n").unwrap();
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        main.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--stock",
        "50x60",
        "--lib",
        lib.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr.contains("O1001.nc:3: gouge: 5.0000 mm deep"),
        "{}",
        out.stderr
    );
}

/// Haas M98 P is the program number and L the repeats; Haas M99 P branches within the
/// program (it does not return to the caller).
#[test]
fn haas_m98_and_m99_p() {
    let text = "O00001\nG21 G99\nG00 X42. Z0.\nM98 P10001 L2\nG00 X100.\nM30\nO10001\nG00 W-1.\nM99 P5\nG00 W-100.\nN5 G00 W-2.\nM99\n";
    let p = gcode::parse(text).unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let z: Vec<f64> = tp.segments.iter().map(|s| end(s).0).collect();
    assert_eq!(z, [0.0, -1.0, -3.0, -4.0, -6.0, -6.0]);
}

/// Haas G73 one block: I = total X relief (radius), D = 3 passes: the shape moved by 2, 1
/// and 0 mm radius (X44, X42, X40 along Z−20).
#[test]
fn haas_g73_one_block() {
    let text = "G21 G99 T0101\nG00 X52. Z2.\nG73 P10 Q20 U0. W0. I2. K0. D3 F0.2\nN10 G00 X40.\nG01 Z-20.\nN20 X52.\nM30\n";
    let p = gcode::parse(text).unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let cuts: Vec<(f64, f64)> = tp
        .segments
        .iter()
        .filter(|s| s.motion == Motion::Feed && s.span.line == 5)
        .map(end)
        .collect();
    assert_eq!(cuts, [(-20.0, 44.0), (-20.0, 42.0), (-20.0, 40.0)]);
    // the two-block relief block is not Haas's
    let p = gcode::parse("G00 X52. Z2.\nG73 U2. W0. R3\nM30\n").unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert_eq!(tp.alarms[0].code, "LS-ONE-BLOCK-FORM");
}

/// Haas G71 I/K (**Interpretation**): the layers stop at the shape moved by (U/2 + I, W + K),
/// the final pass follows the shape moved by (U/2, W).
#[test]
fn haas_g71_i_k_rough_allowance() {
    let text = T4.replace("D2. F0.25", "D2. I0.5 K0.2 F0.25");
    let p = gcode::parse(&text).unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let g71: Vec<&Segment> = tp.segments.iter().filter(|s| s.span.line == 8).collect();
    let layer_ends: Vec<(f64, f64)> = g71
        .iter()
        .filter(|s| s.motion == Motion::Feed && (s.from.r - s.to.r).abs() < 1e-9)
        .map(|s| end(s))
        .collect();
    assert_eq!(
        layer_ends,
        [
            (-44.7, 48.0),
            (-44.7, 44.0),
            (-28.2, 40.0),
            (-24.2, 36.0),
            (-20.2, 32.0),
            (-19.7, 31.5)
        ]
    );
    let pass: Vec<(f64, f64)> = tp
        .segments
        .iter()
        .filter(|s| s.span.line == 10 || s.span.line == 11)
        .take(2)
        .map(end)
        .collect();
    assert_eq!(pass, [(-19.9, 30.5), (-29.9, 40.5)]);
    // the report states the offsets used
    assert!(tp
        .warnings
        .iter()
        .any(|w| w.code == "LS-HAAS-IK" && w.message.contains("X+1.5000 (diameter) Z+0.3000")));
}

/// FANUC with the FS15 tape format (`fs15_format = true`) reads the one-block G71 and G76.
#[test]
fn fs15_format_admits_the_one_block_forms() {
    let mut m = Machine::for_control(Control::FanucA);
    let text = "G21 G99 T0101\nG00 X52. Z2.\nG71 P10 Q20 U0.5 W0.1 D2. F0.25\nN10 G00 X30.\nG01 Z-20.\nN20 X52.\nT0404\nG00 X22. Z5.\nG76 X17.835 Z-20. K1.082 D0.35 A60 F1.5\nM30\n";
    let p = gcode::parse(text).unwrap();
    let tp = expander::expand(&p, &m, &Default::default());
    assert_eq!(tp.alarms[0].code, "LS-ONE-BLOCK-FORM");
    assert_eq!(tp.alarms[0].span.line, 3);
    m.fs15_format = true;
    let tp = expander::expand(&p, &m, &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!(tp.segments.iter().any(|s| s.motion == Motion::Thread));
}

/// Haas G04 P with a decimal point is seconds, without one milliseconds.
#[test]
fn haas_dwell_p_in_seconds() {
    let p = gcode::parse("G04 P1.5\nG04 P500\nM30\n").unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!((tp.dwell_s - 2.0).abs() < 1e-12);
}

/// A drilling cycle is modal: a later block with Z repeats it with the retained R, Q and
/// initial level; a block with only M98 P does not; G80 (or G00) ends it.
#[test]
fn drilling_is_modal_until_g80() {
    let text = "O0001\nG21 G99 T0303\nG00 X0. Z5.\nG85 Z-10. R-3. F0.1\nZ-20.\nM98 P2\nG80\nZ-30.\nM30\nO0002\nM99\n";
    let p = gcode::parse(text).unwrap();
    let tp = expander::expand(
        &p,
        &Machine::for_control(Control::FanucA),
        &Default::default(),
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let z: Vec<(u32, f64)> = tp
        .segments
        .iter()
        .skip(1)
        .map(|s| (s.span.line, s.to.z))
        .collect();
    assert_eq!(
        z,
        [
            (4, 2.0),
            (4, -10.0),
            (4, 2.0),
            (4, 5.0),
            (5, 2.0),
            (5, -20.0),
            (5, 2.0),
            (5, 5.0),
            (8, -30.0)
        ]
    );
}

/// Haas G74 one block as peck drilling on one line: K4. mm pecks with the 0.5 mm retract of
/// `haas.peck_retract`, then back to the start; P/Q are not Haas G74 words.
#[test]
fn haas_g74_peck_drilling_in_mm() {
    let p = gcode::parse("G21 G99\nG00 X0. Z2.\nG74 Z-10. K4. F0.1\nM30\n").unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let z: Vec<(Motion, f64)> = tp
        .segments
        .iter()
        .filter(|s| s.span.line == 3)
        .map(|s| (s.motion, s.to.z))
        .collect();
    assert_eq!(
        z,
        [
            (Motion::Feed, -2.0),
            (Motion::Rapid, -1.5),
            (Motion::Feed, -6.0),
            (Motion::Rapid, -5.5),
            (Motion::Feed, -10.0),
            (Motion::Rapid, 2.0)
        ]
    );
    let p = gcode::parse("G21 G99\nG00 X0. Z2.\nG74 Z-10. Q4000 F0.1\nM30\n").unwrap();
    let tp = expander::expand(&p, &haas(), &Default::default());
    assert_eq!(
        (tp.alarms[0].code, tp.alarms[0].span.column),
        ("LS-ONE-BLOCK-FORM", 11)
    );
}

/// Field run 4 (5b): Haas `M143 P1500` starts the sub-spindle at 1500 rpm (M133 P: a live
/// tool's speed); it was the alarm "address P has no meaning in this block". The P is that
/// spindle's speed and moves nothing of the main spindle's section; under FANUC, where
/// M143 means nothing, the P still has no meaning.
#[test]
fn haas_sub_spindle_and_live_tool_speeds_take_p() {
    let program = "O01430\nG21 G99\nT101\nG97 S1000 M03\nM143 P1500\nM133 P2000\nM135\nG00 X42. Z2.\nG01 Z-10. F0.2\nM145\nG00 X60. Z20.\nM30\n";
    let tp = expand(program, &haas(), &stock::ToolTable::empty());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!(tp.segments.iter().any(|s| s.motion == Motion::Feed));
    let fanuc = expand(
        program,
        &Machine::for_control(Control::FanucA),
        &stock::ToolTable::empty(),
    );
    assert!(
        fanuc.alarms.iter().any(|a| a.code == "LS-WORD-UNUSED"),
        "{:?}",
        fanuc.alarms
    );
}
