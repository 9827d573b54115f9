//! Crashes only a tool's non-cutting body can make (issue 15), each at its line with the
//! body named, and clean counterparts. Hand numbers in the comments.

mod common;
use common::*;

/// A right-hand boring bar Ø20 (S20R-SCLCR09: tip 2) with a CCMT 09T304 insert.
const BAR20: &str =
    "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CCMT 09T304\"\nholder = \"S20R-SCLCR09\"\n";

/// Bores to `x` (diameter) from Z2 to Z-30, then retracts along the bore's axis line.
fn boring(x: f64) -> String {
    format!(
        "O0001;\nG99 M03 S600 T0101;\nG00 X{x:.1} Z2.;\nG01 Z-30. F0.1;\nG00 Z2.;\nG00 X150. Z100.;\nM30;\n"
    )
}

fn lines(tp: &expander::Toolpath, sim: &stock::Simulation) -> Vec<(u32, Option<&'static str>)> {
    sim.crashes
        .iter()
        .map(|c| (tp.segments[c.segment].span.line, c.body))
        .collect()
}

#[test]
fn boring_bar_shank_rubs_a_phi20_bore() {
    let tools = stock::ToolTable::from_toml(BAR20).unwrap();
    // a Φ60 tube with a Φ20 bore; the insert opens it to Φ21 (r 10.5)
    let blank = stock::Blank::bar(60.0, 50.0, 0.0, Some(20.0)).unwrap();
    let (tp, sim) = simulate(&boring(21.0), &blank, &tools);
    // the bar runs +Z from behind the insert, its top 3 mm below the cutting corner:
    // r from 10.5 - 3 - 20 = -12.5 to 7.5, so in the section (folded about the axis) it
    // reaches r 12.5: 2 mm into the bore wall the insert left at r 10.5
    let c = sim.crashes.first().expect("the bar rubs the bore");
    assert_eq!(
        (tp.segments[c.segment].span.line, c.body),
        (4, Some("boring bar")),
        "{:?}",
        lines(&tp, &sim)
    );
    assert!((c.depth - 2.0).abs() < 1e-6, "depth {}", c.depth);
    // over Z from the bar's front to the face Z0. The bar starts 2 mm behind the insert,
    // whose far corner lies 9.672 (cos 5° + cos 85°) = 10.478 along Z from the sharp
    // corner, less 0.040 from the sharp corner to the imaginary tip (nose centre at
    // 0.4 / sin 40° along the 45° bisector = 0.440, minus r 0.4): the front is 12.438
    // behind the tip, at Z-17.562, so the area is 2 × 17.562 = 35.124
    assert!((c.area - 35.124).abs() < 1e-3, "area {}", c.area);
    // the bar never removes material: the bore is Φ21 exactly where the insert went
    assert!(sim.removed_area < 0.5 * 30.0 + 1e-6, "{}", sim.removed_area);
    // the retract along the same line drags the bar back through the wall: the same
    // crash going on, reported once
    assert_eq!(sim.crashes.len(), 1, "{:?}", lines(&tp, &sim));
}

#[test]
fn boring_bar_in_a_phi32_bore_is_clean() {
    let tools = stock::ToolTable::from_toml(BAR20).unwrap();
    let blank = stock::Blank::bar(60.0, 50.0, 0.0, Some(32.0)).unwrap();
    // tip at r 16.5: the bar reaches r 16.5 - 23 = -6.5 (6.5 folded) up to 13.5 < 16
    let (_, sim) = simulate(&boring(33.0), &blank, &tools);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    // 0.5 × 30 less the nose's rounding at the ends
    assert!(sim.removed_area > 14.9, "{}", sim.removed_area);
}

const BLADE8: &str = "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\nreach = 8.0\n";

/// A 3 mm blade (left corner referenced) plunging at Z-10 into a Φ50 bar down to `x`.
fn groove(x: f64) -> String {
    format!("O0002;\nG99 M03 S500 T0101;\nG00 X54. Z-10.;\nG01 X{x:.1} F0.05;\nG00 X54.;\nM30;\n")
}

#[test]
fn blade_sent_deeper_than_its_reach_crashes_its_holder() {
    let tools = stock::ToolTable::from_toml(BLADE8).unwrap();
    let blank = stock::Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    // 10 mm deep: bottom at r 15, the holder from r 15 + 8 = 23 up, 2 mm wider than the
    // blade on each side (Z-12..-5): two 2 × 2 squares of the bar beside the slot
    let (tp, sim) = simulate(&groove(30.0), &blank, &tools);
    // (the retract that pulls the holder back out continues the crash: reported once)
    assert_eq!(lines(&tp, &sim), vec![(4, Some("blade holder"))]);
    let c = &sim.crashes[0];
    assert!((c.area - 8.0).abs() < 1e-6, "area {}", c.area);
    // measured normal to the plunge (across Z): Z-12 to Z-5
    assert!((c.depth - 7.0).abs() < 1e-6, "depth {}", c.depth);
    // first contact: the holder's corner meets the bar's surface at Z-10 + 5, r 25
    assert!((c.at[1] - 25.0).abs() < 1e-6, "{:?}", c.at);
    // the blade cut its own 3 × 10 slot, the holder nothing
    assert!(
        (sim.removed_area - 30.0).abs() < 1e-6,
        "{}",
        sim.removed_area
    );
}

#[test]
fn blade_within_its_reach_is_clean() {
    let tools = stock::ToolTable::from_toml(BLADE8).unwrap();
    let blank = stock::Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    // 7 mm deep: the holder stops at r 18 + 8 = 26, above the bar's r 25
    let (_, sim) = simulate(&groove(36.0), &blank, &tools);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
    assert!((sim.removed_area - 21.0).abs() < 1e-6);
}

#[test]
fn drill_deeper_than_its_flutes_crashes_its_holder() {
    let tools = stock::ToolTable::from_toml(
        "[[tool]]\nt = 1\nkind = \"drill\"\ndiameter = 10.0\nreach = 30.0\n",
    )
    .unwrap();
    let blank = stock::Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    let prog = |z: f64| {
        format!("O0003;\nG99 M03 S800 T0101;\nG00 X0. Z5.;\nG01 Z{z:.1} F0.1;\nG00 Z5.;\nM30;\n")
    };
    // 40 deep: the holder (Ø10 + 2 × 10 = Ø30) starts 30 behind the point, at Z-10;
    // the bar between r 5 (the hole) and r 15 over Z-10..0: 10 × 10 mm²
    let (tp, sim) = simulate(&prog(-40.0), &blank, &tools);
    let c = &sim.crashes[0];
    assert_eq!(
        (tp.segments[c.segment].span.line, c.body),
        (4, Some("drill holder"))
    );
    assert!((c.area - 100.0).abs() < 1e-6, "area {}", c.area);
    assert!((c.depth - 10.0).abs() < 1e-6, "depth {}", c.depth);
    // 25 deep: the holder stays 5 mm in front of the face
    let (_, sim) = simulate(&prog(-25.0), &blank, &tools);
    assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
}

#[test]
fn body_crash_is_in_the_json_with_its_body_and_exit_1() {
    let (dir, prog) = temp_program("blade.nc", groove(30.0).as_bytes());
    let tools = dir.path().join("blade.toml");
    std::fs::write(&tools, BLADE8).unwrap();
    let json = dir.path().join("blade.json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "50x60",
        "--tools",
        tools.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr
            .contains("blade.nc:4:1: crash: the tool's blade holder meets stock"),
        "{}",
        out.stderr
    );
    let v: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    assert_eq!(v["verdict"], "crash");
    assert_eq!(v["crashes"][0]["line"], 4);
    assert_eq!(v["crashes"][0]["body"], "blade holder");
    assert_eq!(v["crashes"][0]["area_mm2"], 8.0);
    // an ordinary rapid crash has no body field (the JSON only gains fields)
    assert!(v["rapid_cuts"].as_array().unwrap().is_empty());
}

/// A tool whose table entry does not state what places its body (no `reach`, no holder
/// designation or `shank`), or that has no entry at all, is probed by its cutting outline
/// only: a part-off 22.5 mm deep with an undescribed blade is no holder crash (a default
/// reach would cry wolf on every program whose tools are not described).
#[test]
fn an_undescribed_body_is_not_probed() {
    let blank = stock::Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    for table in [
        "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\n",
        "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\n",
    ] {
        let tools = stock::ToolTable::from_toml(table).unwrap();
        let (_, sim) = simulate(&groove(5.0), &blank, &tools);
        assert!(
            sim.crashes.iter().all(|c| c.body.is_none()),
            "{table}: {:?}",
            sim.crashes
        );
    }
    let (_, sim) = simulate(&groove(5.0), &blank, &stock::ToolTable::empty());
    assert!(
        sim.crashes.iter().all(|c| c.body.is_none()),
        "{:?}",
        sim.crashes
    );
}
