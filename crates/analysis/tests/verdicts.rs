//! Verdicts decided by the library, without the binary: the removal and the analysis as
//! `latsim run` wires them (`analysis::pipeline`), on hand-computed cases.

mod common;

use analysis::Verdict;
use common::{judge, line};
use stock::{Blank, ToolTable};

/// A rapid that scrapes is not a crash. `G01 X48 / Z-38.1 / G00 X52` on a Φ50.8 bar with
/// the default 55° insert on a 93° holder: the leading edge re-touches the wedge its 3°
/// clearance left, 0.05 mm thick normal to the retract — a rapid cut below `rapid_cut_tol`
/// (0.1 mm), and a retract off the tool's own shoulder (issue 30): a scrape and its
/// warning, not a crash.
#[test]
fn a_rapid_that_scrapes_is_not_a_crash() {
    let text = "G99 M03 S800 T0101\nG00 X52 Z2\nG01 X48 F0.2\nZ-38.1\nG00 X52\nG00 Z2\nM30\n";
    let blank = Blank::bar(50.8, 60.0, 0.0, None).unwrap();
    let (tp, _, f) = judge(text, &blank, &ToolTable::empty());
    assert_eq!(f.verdict, Verdict::Clean);
    assert!(f.crashes.is_empty(), "{:?}", f.crashes);
    assert_eq!(f.scrapes.len(), 1, "{:?}", f.scrapes);
    assert_eq!(line(&tp, f.scrapes[0].segment), 5);
    // the wedge between the 3° edge and the retract: tan 3° × the 1.4 mm cut depth ≈ 0.07
    // along the edge, 0.05 normal to the X retract at the corner the insert meets
    let depth = f.scrapes[0].depth;
    assert!(depth > 0.0 && depth < 0.1, "{depth}");
    assert!(f.warnings.iter().any(|n| n.code == "LS-RETRACT-SCRAPE"));
}

/// A part-off blade rapiding 0.5 mm into a Φ50 bar is a crash as deep as the blade is wide
/// (3 mm across the X move), 3 × 0.5 = 1.5 mm².
#[test]
fn a_blade_rapiding_into_the_bar_is_a_crash_with_its_depth() {
    let tools = ToolTable::from_toml(
        "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"-z\"\nshank_dir = \"+x\"\nreach = 20.0\n",
    )
    .unwrap();
    let text = "G99 M03 S600 T0101\nG00 X60 Z-20\nG00 X49\nG00 X60\nM30\n";
    let blank = Blank::bar(50.0, 60.0, 0.0, None).unwrap();
    let (tp, _, f) = judge(text, &blank, &tools);
    assert_eq!(f.verdict, Verdict::Crash);
    assert_eq!(f.crashes.len(), 1, "{:?}", f.crashes);
    assert_eq!(line(&tp, f.crashes[0].segment), 3);
    assert!(
        (f.crashes[0].depth - 3.0).abs() < 0.01,
        "{}",
        f.crashes[0].depth
    );
    assert!((f.crashes[0].area - 1.5).abs() < 0.01);
    // the tool is drawn where it hit
    assert!(!f.crashes[0].tool.is_empty());
}

/// A finishing shape's lead-in in front of the face is no part: a Φ40 bar faced from Z1 to
/// Z0 (G94), then G71/G70 to Φ20 × 20 and Φ30 to Z-35. Hand: removed = face 20 × 1 + Φ20
/// stretch (20 − 10) × 20 + Φ30 stretch (20 − 15) × 15 = 295 mm²; no gouge, clean.
#[test]
fn a_lead_in_in_front_of_the_face_is_no_part() {
    let text = "G99 M03 S600 T0101\nG00 X42 Z2\nG94 X-2 Z0 F0.15\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20\nG01 Z0 F0.12\nZ-20\nX30\nZ-35\nN20 X41\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let blank = Blank::bar(40.0, 60.0, 1.0, None).unwrap();
    let (_, sim, f) = judge(text, &blank, &ToolTable::empty());
    assert_eq!(f.verdict, Verdict::Clean);
    let d = f
        .deviation
        .as_ref()
        .expect("the program's shape is an intent");
    assert!(d.gouges.is_empty(), "{:?}", d.gouges);
    assert!(
        (sim.removed_area - 295.0).abs() < 1.0,
        "{}",
        sim.removed_area
    );
}

/// A gouge fails the run: the same shape with a last pass 1 mm under the diameter of the
/// Φ20 diameter (X19 where the shape says X20) gouges it 0.5 mm deep (radial) over 19.8 mm.
#[test]
fn a_finishing_pass_below_its_own_shape_is_a_gouge() {
    let text = "G99 M03 S600 T0101\nG00 X42 Z2\nG71 U1.5 R0.5\nG71 P10 Q20 U0 W0 F0.25\nN10 G00 X20\nG01 Z0 F0.12\nZ-20\nX30\nZ-35\nN20 X41\nG00 X19 Z2\nG01 Z-19.8 F0.1\nG00 X42\nM30\n";
    let blank = Blank::bar(40.0, 60.0, 0.0, None).unwrap();
    let (tp, _, f) = judge(text, &blank, &ToolTable::empty());
    assert_eq!(f.verdict, Verdict::Gouge);
    let d = f.deviation.as_ref().unwrap();
    assert_eq!(d.gouges.len(), 1, "{:?}", d.gouges);
    assert!(
        (d.gouges[0].depth - 0.5).abs() < 0.01,
        "{}",
        d.gouges[0].depth
    );
    assert_eq!(d.gouges[0].made_by.map(|s| line(&tp, s)), Some(12));
}

/// Thread teeth are not gouges: Φ24 finished by G71/G70 over Z0..-30 on a Φ30 bar, then an
/// M24×2 thread by G92 to X21.4 over Z4..-24. Hand: OD (15 − 12) × 30 = 90 less the r0.8
/// fillet at Z-30, 0.64 (1 − π/4) = 0.1373; a groove h² tan 30° = 0.9757 mm² (h = 1.3),
/// 12.5 of them: 102.059 mm²; clean, and the fillet is the shape's leftover.
#[test]
fn thread_teeth_are_not_gouges() {
    let text = "G40 G97 G99 G21\nT0101\nM03 S800\nG00 X32 Z2\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X24\nG01 Z0 F0.1\nZ-30\nN20 X32\nG70 P10 Q20\nG00 X100 Z100\nT0404\nM03 S400\nG00 X26 Z4\nG92 X23.2 Z-24 F2\nX22.6\nX22.1\nX21.7\nX21.5\nX21.4\nG00 X100 Z100\nM30\n";
    let shop = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/corpus/tools/shop.toml"
    );
    let tools = ToolTable::from_toml(&std::fs::read_to_string(shop).unwrap()).unwrap();
    let blank = Blank::bar(30.0, 50.0, 0.0, None).unwrap();
    let (_, sim, f) = judge(text, &blank, &tools);
    assert_eq!(f.verdict, Verdict::Clean);
    let d = f.deviation.as_ref().unwrap();
    assert!(d.gouges.is_empty(), "{:?}", d.gouges);
    let groove = 1.3f64.powi(2) * 30f64.to_radians().tan();
    let hand = 90.0 - 0.64 * (1.0 - std::f64::consts::FRAC_PI_4) + 12.5 * groove;
    assert!(
        (sim.removed_area - hand).abs() < 0.005,
        "{} vs {hand}",
        sim.removed_area
    );
    assert!(
        (d.undercut_area() - 0.1373).abs() < 0.002,
        "{}",
        d.undercut_area()
    );
    assert_eq!(f.threads.len(), 1);
    assert!(f.threads[0].depth_error_mm.is_some_and(|e| e.abs() <= 0.01));
}

/// Zig-zag roughing by hand under one G42 (a field program's habit): Φ46 to Z-40, fed back
/// at X52 to Z2, then Φ42 to Z-20. The section is two passes and a return, not one
/// contour: the second pass supersedes the first over its stretch and the return is no
/// contour at all, so the Φ42 cut is no gouge of the Φ46 (as one contour it was a 1 mm
/// gouge); clean with a stated CNMG. One pass fed back the same way is clean too.
#[test]
fn zig_zag_roughing_under_one_g42_is_its_passes() {
    let tools = ToolTable::from_toml(
        "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n",
    )
    .unwrap();
    let blank = Blank::bar(50.0, 80.0, 0.0, None).unwrap();
    let two = "G21 G99 G40\nT0101\nG96 S180 M03\nG00 X54. Z2.\nG01 G42 X46. F0.25\nZ-40.\nX52.\nZ2.\nX42.\nZ-20.\nX52.\nG40 G00 X60. Z10.\nM30\n";
    let (_, _, f) = judge(two, &blank, &tools);
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.deviation);
    let one = "G21 G99 G40\nT0101\nG96 S180 M03\nG00 X54. Z2.\nG01 G42 X46. F0.25\nZ-40.\nX52.\nZ2.\nG40 G00 X60. Z10.\nM30\n";
    let (_, _, f) = judge(one, &blank, &tools);
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.deviation);
}

/// T02 turns Φ18 to Z-20 first; then T01's G71/G70 finishes Φ20 to Z-20. Where the G71
/// began, its contour lay wholly in the air (the part was already smaller), so it was
/// dropped and the 1 mm the Φ18 took out of the Φ20 went unjudged. A contour that touches
/// no stock where its cycle began is read against the blank: a gouge, 1 mm deep.
#[test]
fn a_contour_already_cut_below_is_still_the_intent() {
    let tools = ToolTable::from_toml(
        "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"DNMG 150404\"\nholder = \"PDJNR 2525M15\"\n",
    )
    .unwrap();
    let blank = Blank::bar(30.0, 60.0, 0.0, None).unwrap();
    let text = "G21 G40 G99\nT0202\nG96 S180 M03\nG00 X32. Z2.\nG01 X18. F0.2\nZ-20.\nX32.\nG00 Z2.\nT0101\nG00 X32. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0 W0 F0.25\nN10 G00 X20.\nG01 Z-20.\nN20 X32.\nG70 P10 Q20\nG00 X60. Z60.\nM30\n";
    let (_, _, f) = judge(text, &blank, &tools);
    assert_eq!(f.verdict, Verdict::Gouge, "{:?}", f.deviation);
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    assert!((g.depth - 1.0).abs() < 0.01, "{}", g.depth);
}
