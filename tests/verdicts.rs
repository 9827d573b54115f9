//! Verdicts a machinist trusts (issue 13): each reproduction of a false (or missed) finding,
//! with its hand-computed numbers.

mod common;
use common::*;

fn expand(text: &str) -> expander::Toolpath {
    let program = gcode::parse(text).unwrap();
    expander::expand(&program, &expander::Machine::default(), &Default::default())
}

/// Item 7: `T0` in the G40 block must not make the last compensated move the cancel move
/// (it turned the R10 dome into a straight feed and a false 2.9 mm gouge).
#[test]
fn t0_in_the_g40_block_keeps_the_last_compensated_arc() {
    let body = "G99 M03 S800 T0101\nG00 X50 Z5\nG00 G42 X0 Z2\nG01 Z0 F0.1\nG03 X20 Z-10 R10\n";
    let with_t0 = expand(&format!("{body}G00 G40 X50 Z5 T0\nM30\n"));
    let without = expand(&format!("{body}G00 G40 X50 Z5\nM30\n"));
    assert!(with_t0.alarms.is_empty(), "{:?}", with_t0.alarms);
    assert_eq!(with_t0.segments.len(), without.segments.len());
    for (a, b) in with_t0.segments.iter().zip(&without.segments) {
        assert_eq!(
            (a.from, a.to, a.arc.is_some()),
            (b.from, b.to, b.arc.is_some())
        );
    }
    // the dome (line 5) is still an arc: the default r0.4 nose runs outside it (G42,
    // travelling toward -Z over the dome)
    let dome: Vec<_> = with_t0
        .segments
        .iter()
        .filter(|s| s.span.line == 5 && s.arc.is_some())
        .collect();
    assert!(!dome.is_empty());
    // the nose centre runs on R10.4 around the dome centre (Z-10, r0); the segments move
    // the imaginary tip, nose centre + (-0.4, -0.4) for tip 3
    let arc = dome[0].arc.unwrap();
    assert!(
        (arc.center.z + 10.4).abs() < 1e-9 && (arc.center.r + 0.4).abs() < 1e-9,
        "{arc:?}"
    );
    assert!((dome[0].from.dist(arc.center) - 10.4).abs() < 1e-9);
    // it starts where the offset face line r = 0.4 meets the offset dome:
    // z = sqrt(10.4² - 0.4²) - 10 - 0.4 = sqrt(108) - 10.4
    assert!(
        (dome[0].from.z - (108f64.sqrt() - 10.4)).abs() < 1e-9,
        "{:?}",
        dome[0]
    );
    let _ = asset("");
}

/// Item 8: a rounded corner programmed with 3 decimals is tangent within the control's
/// tolerance: no false PS041, and the same path as with the exact tangent point
/// (X24.7176 Z-26.5504) to within 0.002 mm.
#[test]
fn tangency_within_the_tolerance_is_tangency() {
    let prog = |end: &str| {
        format!("G99 M03 S800 T0101\nG00 X50 Z5\nG00 G42 X25 Z2\nG01 X19.925 Z-1.125 F0.1\nZ-25\nX20.82\nG03 {end} I0 K-2\nG01 X30 Z-38\nG00 G40 X40\nM30\n")
    };
    let printed = expand(&prog("X24.716 Z-26.551"));
    let exact = expand(&prog("X24.7176 Z-26.5504"));
    assert!(printed.alarms.is_empty(), "{:?}", printed.alarms);
    assert!(exact.alarms.is_empty(), "{:?}", exact.alarms);
    assert_eq!(printed.segments.len(), exact.segments.len());
    for (a, b) in printed.segments.iter().zip(&exact.segments) {
        assert!(a.to.dist(b.to) < 0.002, "{:?} vs {:?}", a.to, b.to);
    }
}

/// Item 9: a type II ns block that stays at the start Z (`G00 X20 Z2` from Z2) with a Z
/// allowance W0.1 is a sound G71, not PS064: it roughs down to the shape moved by the
/// allowances (r = 10 + 0.4/2 = 10.2 along the Φ20 stretch).
#[test]
fn g71_with_w_and_a_repeated_start_z_is_sound() {
    let text = "G99 M03 S800 T0101\nG00 X50 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X20 Z2\nG01 Z-20\nX40 Z-30\nN20 X50\nM30\n";
    let tp = expand(text);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let deepest = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Feed && s.to.z < 0.5 && s.to.z > -19.95)
        .map(|s| s.to.r)
        .fold(f64::INFINITY, f64::min);
    assert!((deepest - 10.2).abs() < 1e-9, "{deepest}");
}

fn run_json(name: &str, text: &str, extra: &[&str]) -> (i32, serde_json::Value) {
    let (dir, prog) = temp_program(name, text.as_bytes());
    let json = dir.path().join("r.json");
    let mut args = vec![
        "run",
        prog.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let out = latsim(&args);
    let report = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    (out.code, report)
}

/// Item 10: a rear tool post (X < 0). Facing `G00 Z0 X-25.5 / G01 Z-2 / G01 X0` on a Φ25 bar
/// removed a slanted wedge (17.4 mm²); the section sees the move mirrored, and the tool's
/// tip number reads the same on a rear post (tnrc.md): it must remove what the same moves at
/// X+25.5 remove. Hand: the slab 2 × 12.5 = 25 mm² less the corner the r0.4 nose leaves at
/// the axis, 0.4² (1 − π/4) = 0.0343: 24.966 mm². The rapid back out through the pip the
/// 32° minor edge leaves at the centre is the same crash on both sides.
#[test]
fn a_rear_tool_cuts_the_mirror_of_a_front_tool() {
    let run = |x: &str| {
        let text = format!("G99 M03 S800\nG00 Z0 X{x}\nG01 Z-2 F0.1\nG01 X0\nG00 Z5\nM30\n");
        run_json("rear.nc", &text, &["--stock", "25x40"]).1
    };
    let (front, rear) = (run("25.5"), run("-25.5"));
    let hand = 25.0 - 0.16 * (1.0 - std::f64::consts::FRAC_PI_4);
    for r in [&front, &rear] {
        let removed = r["removed_area_mm2"].as_f64().unwrap();
        assert!((removed - hand).abs() < 0.005, "{removed}");
    }
    assert_eq!(front["crashes"], rear["crashes"]);
    assert_eq!(front["final"], rear["final"]);
}

/// Item 10: front and rear tools in one program. T1 (C80 r0.8, tip 3) turns Φ36 over
/// Z0..-45 from the front; T2 (D55 r0.4, tip 3 — the same number on the rear post) turns
/// Φ32 over Z0..-20 from the back at X-32. Hand: (20 − 18) × 45 + (18 − 16) × 20 = 90 + 40 =
/// 130 mm², less the nose fillet each leaves in its inside corner: 0.8² (1 − π/4) + 0.4² (1 −
/// π/4) = 0.1717 mm². No crash; the same part as with both tools at +X.
#[test]
fn front_and_rear_tools_in_one_program() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"C\"\nnose_radius = 0.8\ntip = 3\nentering_angle = 95\n\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.4\ntip = 3\nentering_angle = 93\n";
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("t.toml");
    std::fs::write(&table, tools).unwrap();
    let prog = |rear: &str| {
        format!("G99 M03 S800\nT0101\nG00 X42 Z2\nX36\nG01 Z-45 F0.2\nX42\nG00 X100 Z100\nT0202\nG00 X{rear}100 Z100\nX{rear}42 Z2\nX{rear}32\nG01 Z-20 F0.2\nX{rear}42\nG00 X{rear}100 Z100\nM30\n")
    };
    let args = ["--stock", "40x60", "--tools", table.to_str().unwrap()];
    let (code, mixed) = run_json("mixed.nc", &prog("-"), &args);
    let (_, front) = run_json("front.nc", &prog(""), &args);
    assert_eq!(code, 0, "{mixed}");
    let hand = 130.0 - (0.64 + 0.16) * (1.0 - std::f64::consts::FRAC_PI_4);
    let removed = mixed["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - hand).abs() < 0.01, "{removed} vs {hand}");
    assert_eq!(mixed["final"], front["final"]);
    assert_eq!(mixed["crashes"].as_array().unwrap().len(), 0);
}

/// Item 10: compensation on a rear post. The seed-004-style contour (r1 nose, tip 3) cut
/// under G42 at +X and its mirror cut under G41 at −X (the tool below the contour is on the
/// left of the travel) with the same tip number (tnrc.md: the same on the rear post) make
/// the same part, and it matches the programmed taper: no gouge, no leftover, and the final
/// sections are identical.
#[test]
fn compensation_on_a_rear_post_mirrors_the_front() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"V\"\nnose_radius = 1.0\ntip = 3\nentering_angle = 93\n";
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("t.toml");
    std::fs::write(&table, tools).unwrap();
    let prog = |s: &str, g: &str| {
        format!("G99 M03 S800 T0101\nG00 X{s}50 Z5\nG00 {g} X{s}20 Z2\nG01 Z0 F0.1\nX{s}30 Z-10\nZ-20\nX{s}42\nG00 G40 X{s}50 Z5\nM30\n")
    };
    let args = ["--stock", "40x40", "--tools", table.to_str().unwrap()];
    let (code_f, front) = run_json("front.nc", &prog("", "G42"), &args);
    let (code_r, rear) = run_json("rear.nc", &prog("-", "G41"), &args);
    assert_eq!((code_f, code_r), (0, 0), "{front}\n{rear}");
    for r in [&front, &rear] {
        assert_eq!(r["gouges"].as_array().unwrap().len(), 0, "{r}");
    }
    // Hand: Φ40 bar (r20) over Z0..-20 to the contour r10 at Z0, the taper to r15 at Z-10,
    // r15 to Z-20: removed = 20·20 − (0.5·(10 + 15)·10 + 15·10) = 400 − 275 = 125 mm², less
    // the fillet the r1 nose leaves in the inside corner at Z-20, 1² (1 − π/4) = 0.2146 mm²
    // (reported as a leftover).
    let hand = 125.0;
    for r in [&front, &rear] {
        let removed = r["removed_area_mm2"].as_f64().unwrap();
        let left = r["deviation"]["undercut_area_mm2"].as_f64().unwrap();
        assert!(
            (removed + left - hand).abs() < 0.01,
            "{removed} + {left} vs {hand}"
        );
    }
    assert_eq!(front["final"], rear["final"]);
}

/// Item 11: a G70 shape that writes G42 in its second block (`N10 G00 X10` / `G42 G01 Z0` /
/// `G03 X30 Z-10 R10` …) starts the compensation there, as the same blocks outside the cycle
/// do: the start-up `G42 G01 Z0` ends with the r1 nose tangent to the dome at its start
/// (tip at Z0 X8), not at the intersection of the offsets (Z-0.0455 X10), which left a
/// 0.045 mm sliver. Hand: the part is the same as the plain program's; the only deviation
/// is the nose fillet in the inside corner at Z-20, 1² (1 − π/4) = 0.2146 mm².
#[test]
fn g70_starts_compensation_where_the_shape_writes_it() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"V\"\nnose_radius = 1.0\ntip = 3\nentering_angle = 93\n";
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("t.toml");
    std::fs::write(&table, tools).unwrap();
    let shape = "G00 X10\nG42 G01 Z0 F0.1\nG03 X30 Z-10 R10\nG01 Z-20\n";
    let g70 = format!(
        "G99 M03 S800 T0101\nG00 X42 Z2\nG70 P10 Q20\nN10 {shape}N20 X42\nG00 X100 Z100\nM30\n"
    );
    let plain =
        format!("G99 M03 S800 T0101\nG00 X42 Z2\n{shape}X42\nG40 G00 X42 Z2\nG00 X100 Z100\nM30\n");
    let args = ["--stock", "40x30", "--tools", table.to_str().unwrap()];
    let (code_a, a) = run_json("g70.nc", &g70, &args);
    let (code_b, b) = run_json("plain.nc", &plain, &args);
    assert_eq!((code_a, code_b), (0, 0), "{a}\n{b}");
    assert_eq!(a["final"], b["final"]);
    let fillet = 1.0 - std::f64::consts::FRAC_PI_4;
    for r in [&a, &b] {
        assert_eq!(r["gouges"].as_array().unwrap().len(), 0, "{r}");
        let left = r["deviation"]["undercut_area_mm2"].as_f64().unwrap();
        assert!((left - fillet).abs() < 0.002, "{left} vs {fillet}");
    }
    // the start-up ends with the nose centre on the dome's normal at its start (Z0, r5):
    // without a tool table the default r0.4 nose, centre (Z0.4, r5), tip at Z0 r4.6
    let tp = expand(&g70);
    let dome = tp.segments.iter().find(|s| s.arc.is_some()).unwrap();
    assert!(
        dome.from.dist(expander::Pt::new(0.0, 4.6)) < 1e-9,
        "{dome:?}"
    );
}

/// Item 5: an inch program (G20) gets no gouge on the axis (it got "10.1600 mm deep,
/// 0.0004 mm² at X-0.000"). The corpus job `clean-inch-g20`: a Φ2.0 in bar, G71/G70 to
/// Φ1.0 × 0.75 in and Φ1.5 × 0.75 in. Hand (mm): (25.4 − 12.7) × 19.05 + (25.4 − 19.05) ×
/// 19.05 = 362.9025 mm², less the two r0.4 fillets of the finishing nose, 2 × 0.4² (1 − π/4)
/// = 0.0687: 362.834 mm².
#[test]
fn an_inch_program_does_not_gouge_on_the_axis() {
    let prog = asset("corpus/gsk980/clean-inch-g20.nc");
    let tools = asset("corpus/tools/shop.toml");
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "50.8x76.2",
        "--tools",
        tools.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(out.code, 0, "{r}");
    assert_eq!(r["gouges"].as_array().unwrap().len(), 0, "{}", r["gouges"]);
    let hand = 19.05 * (12.7 + 6.35) - 2.0 * 0.16 * (1.0 - std::f64::consts::FRAC_PI_4);
    let removed = r["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - hand).abs() < 0.01, "{removed} vs {hand}");
}

/// Item 12: a threading tool is not "a grooving blade" in warnings: G42 with a threading
/// tool's offset is ignored with a warning that names it.
#[test]
fn a_threading_tool_is_named_as_one() {
    let tools = stock::ToolTable::from_toml(
        "[[tool]]\nt = 4\nkind = \"threading\"\nangle = 60\n\n[[tool]]\nt = 5\nkind = \"grooving\"\nwidth = 3.0\n",
    )
    .unwrap();
    let opts = expander::Options {
        tools: tools.facts(),
        ..Default::default()
    };
    let warning = |t: &str| {
        let p = gcode::parse(&format!(
            "M3 S800 {t}\nG0 X40 Z2\nG42 G1 X20 Z0 F100\nG1 Z-10\nG40 G0 X50\n"
        ))
        .unwrap();
        let tp = expander::expand(&p, &expander::Machine::default(), &opts);
        tp.warnings
            .into_iter()
            .find(|w| w.code == "LS-TNRC-BLADE")
            .unwrap()
            .message
    };
    let thread = warning("T0404");
    assert!(
        thread.contains("threading tool") && !thread.contains("blade"),
        "{thread}"
    );
    assert!(warning("T0505").contains("grooving blade"));
}

/// Item 12: G75 with P (Δi) larger than the X travel |U/2| is an alarm at the cycle block,
/// as the control gives it (seed 002 §6 ③, FANUC: "Δi值大于U/2 … 将会出现程序报警"), not one
/// peck: from X42 to X32 the travel is 5 mm, P6000 asks 6 mm.
#[test]
fn g75_with_a_peck_deeper_than_the_travel_is_an_alarm() {
    let tp =
        expand("G99 M3 S500 T0505\nG0 X42 Z-28\nG75 R0.3\nG75 X32 Z-31 P6000 Q2000 F0.1\nM30\n");
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    let a = &tp.alarms[0];
    assert_eq!((a.code, a.span.line), ("LS-G75-STEP", 4));
    assert!(
        a.message.contains("larger than the X travel 5.0000"),
        "{}",
        a.message
    );
    // nothing of the cycle was cut
    assert!(tp.segments.iter().all(|s| s.span.line != 4));
}

/// Item 3 under G41/G42: a compensated contour's lead-in `G01 Z0` from Z2 at Φ20 runs in
/// front of a face the G94 made at Z0 (blank face Z1): no part. It was a 1 mm deep, 10 mm²
/// gouge. Hand: face slab 20 × 1 = 20, the contour Φ20 → taper to Φ30 at Z-10 → Φ30 to
/// Z-20 on a Φ40 bar 20·20 − (0.5·(10 + 15)·10 + 15·10) = 125, less the r1 fillet in the
/// inside corner at Z-20, 1 − π/4 = 0.2146: 144.785 mm²; no gouge.
#[test]
fn a_compensated_lead_in_in_front_of_the_face_is_no_part() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"V\"\nnose_radius = 1.0\ntip = 3\nentering_angle = 93\n";
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("t.toml");
    std::fs::write(&table, tools).unwrap();
    let text = "G99 M03 S800 T0101\nG00 X44 Z2\nG94 X-2 Z0 F0.1\nG00 X50 Z5\nG00 G42 X20 Z2\nG01 Z0 F0.1\nX30 Z-10\nZ-20\nX42\nG00 G40 X50 Z5\nM30\n";
    let (code, r) = run_json(
        "comp-leadin.nc",
        text,
        &[
            "--stock",
            "40x40",
            "--stock-z",
            "1",
            "--tools",
            table.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 0, "{r}");
    assert_eq!(r["gouges"].as_array().unwrap().len(), 0, "{}", r["gouges"]);
    let hand = 20.0 + 125.0 - (1.0 - std::f64::consts::FRAC_PI_4);
    let removed = r["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - hand).abs() < 0.01, "{removed} vs {hand}");
}
