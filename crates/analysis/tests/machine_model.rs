//! Issue 30: no false crash from a tool latsim invented — ID tools carried along Z, retract
//! scrapes, only stated sizes past the axis — and the real crashes kept. Each case runs the
//! library pipeline (`analysis::pipeline`) with hand-computed expectations.

use analysis::{Findings, Intents, Settings, Verdict};
use expander::{Machine, Toolpath};
use stock::{Blank, SimOptions, ToolTable};

fn judge(text: &str, blank: &Blank, tools: &str) -> (Toolpath, Findings) {
    let tools = ToolTable::from_toml(tools).expect("tool table");
    let program = gcode::parse(text).expect("program parses");
    let machine = Machine::default();
    let opts = expander::Options {
        tools: tools.facts(),
        start_tool: tools.numbers().first().copied(),
        ..Default::default()
    };
    let tp = expander::expand(&program, &machine, &opts);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let settings = Settings {
        blank,
        tools: &tools,
        machine: &machine,
        fixture: None,
        tol: 0.01,
    };
    let (_, f) = analysis::pipeline(
        &tp,
        &Intents::Program,
        &settings,
        &SimOptions::default(),
        &mut |_| {},
    );
    (tp, f)
}

fn line(tp: &Toolpath, segment: usize) -> u32 {
    tp.segments[segment].span.line
}

fn tube(d: f64, l: f64, bore: f64) -> Blank {
    Blank::bar(d, l, 0.0, Some(bore)).unwrap()
}

const ID_BLADE: &str = "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3\nwidth_dir = \"+z\"\nshank_dir = \"-x\"\nreach = 6\n";

/// 1. An ID blade is carried on a bar along Z: a Φ80 tube with a Φ40 bore, a 3 mm blade of
///    reach 6 grooving from X36 to X46 at Z-20. The bar (Ø16 by default) lies 6 mm under the
///    blade's tip: r 12 … −4 at X36 (its 4 mm past the axis folds to r 0 … 4, inside the
///    bore), r 17 … 1 at X46, under the bore's r 20. Clean (it was a "blade holder" crash
///    20 mm deep: the holder drawn 100 mm toward −X, across the axis, into the far wall).
///    Sent to X56 (3 mm deeper than its reach), the bar's top at r 22 meets the wall: a body
///    crash at the feed.
#[test]
fn an_id_blade_rides_a_bar_along_z() {
    let groove = |x: f64| {
        format!("G99 M03 S600 T0101\nG00 X36 Z2\nG00 Z-20\nG01 X{x} F0.05\nG00 X36\nZ5\nM30\n")
    };
    let (_, f) = judge(&groove(46.0), &tube(80.0, 60.0, 40.0), ID_BLADE);
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
    let (tp, f) = judge(&groove(56.0), &tube(80.0, 60.0, 40.0), ID_BLADE);
    assert_eq!(f.verdict, Verdict::Crash);
    assert_eq!(f.crashes[0].body, Some("boring bar"));
    assert_eq!(line(&tp, f.crashes[0].segment), 4);
    // the bar's top reaches r 28 − 6 = 22 where the bore is r 20: 2 mm into the wall over
    // Z-17 … 0 (the groove took Z-20 … -17), 34 mm², 17 mm across the plunge
    let c = &f.crashes[0];
    assert!(
        (c.area - 34.0).abs() < 0.01 && (c.depth - 17.0).abs() < 0.01,
        "{c:?}"
    );
}

/// 2. An internal part-off: a Φ118 tube (bore Φ80) bored to Φ97 over 45 mm, then an ID
///    blade of reach 15 (its left corner at Z-45, 3 mm toward +Z) plunging from X97 to X118.
///    The Ø16 bar runs r 17.5 … 33.5 at the start and r 28 … 44 at the end, inside the Φ97
///    bore (r 48.5): clean (it was a "blade holder" crash at the outside of the face). With
///    a reach of 8 the bar's top reaches r 51 > 48.5: the bar really meets the bore.
#[test]
fn an_internal_part_off_inside_the_blades_reach_is_clean() {
    let tools = |reach: u32| {
        format!("[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CCMT 09T304\"\nholder = \"S20R-SCLCR09\"\n[[tool]]\nt = 2\nkind = \"grooving\"\nwidth = 3\nwidth_dir = \"+z\"\nshank_dir = \"-x\"\nreach = {reach}\n")
    };
    let text = "G99 M03 S600\nT0101\nG00 X78 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X97\nG01 Z-45\nN20 X78\nG00 Z5\nX200 Z100\nT0202\nG00 X94 Z5\nG00 Z-45\nG01 X118 F0.05\nG00 X94\nG00 Z5\nM30\n";
    let blank = tube(118.0, 60.0, 80.0);
    let (_, f) = judge(text, &blank, &tools(15));
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
    let (tp, f) = judge(text, &blank, &tools(8));
    assert_eq!(f.verdict, Verdict::Crash);
    assert_eq!(f.crashes[0].body, Some("boring bar"));
    assert_eq!(line(&tp, f.crashes[0].segment), 14);
    // 51 − 48.5 = 2.5 mm into the bore's wall over Z-42 … 0: 105 mm², 42 across the plunge
    let c = &f.crashes[0];
    assert!(
        (c.area - 105.0).abs() < 0.01 && (c.depth - 42.0).abs() < 0.01,
        "{c:?}"
    );
}

const CNMG_95: &str =
    "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";

/// 3. A 95° holder's retract off its own shoulder is a retract scrape: Φ50 bar, CNMG 120408
///    in PCLNR 2525M12, `G00 X40 Z2 / G01 Z-50 / G00 X60`. The leading edge (5° lean) re-
///    touches the wedge it left on the 5 mm shoulder: at most 5 tan 5° = 0.437 mm across
///    the retract (the nose takes the corner: 0.364 mm). A warning with the fix, clean.
#[test]
fn a_95_degree_retract_off_its_own_shoulder_is_a_retract_scrape() {
    let (tp, f) = judge(
        "G99 M03 S600 T0101\nG00 X40 Z2\nG01 Z-50 F0.2\nG00 X60\nM30\n",
        &Blank::bar(50.0, 80.0, 0.0, None).unwrap(),
        CNMG_95,
    );
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
    assert_eq!(f.scrapes.len(), 1);
    let s = &f.scrapes[0];
    assert_eq!(line(&tp, s.segment), 4);
    let wedge = 5.0 * 5f64.to_radians().tan();
    assert!(s.depth > 0.1 && s.depth <= wedge, "{s:?}");
    let note = &f.warnings[0];
    assert_eq!(note.code, "LS-RETRACT-SCRAPE");
    assert!(note.message.contains("retract at 45°"), "{}", note.message);
}

/// 3b. The same tool's rapids into material it did not just leave stay crashes: from the
///     end of the feed diagonally into the uncut bar beyond the shoulder, and straight into
///     the bar from the feed's end toward the axis.
#[test]
fn a_rapid_into_uncut_bar_from_the_feeds_end_stays_a_crash() {
    let bar = Blank::bar(50.0, 80.0, 0.0, None).unwrap();
    for (exit, why) in [("G00 X48 Z-55", "diagonal"), ("G00 X30", "toward the axis")] {
        let text = format!("G99 M03 S600 T0101\nG00 X40 Z2\nG01 Z-50 F0.2\n{exit}\nM30\n");
        let (tp, f) = judge(&text, &bar, CNMG_95);
        assert_eq!(f.verdict, Verdict::Crash, "{why}");
        assert_eq!(line(&tp, f.crashes[0].segment), 4, "{why}");
        assert!(f.warnings.iter().all(|n| n.code != "LS-RETRACT-SCRAPE"));
    }
}

/// 4. An invented size does not cross the axis: a Φ60 tube with a Φ20 bore, a boring tool
///    given only as `insert = "V"`, tip 2, 93°. The default 11 mm rhombus reaches past the
///    axis at X16 and was folded into the far wall (a rapid crash at the bore's mouth): now
///    clean, with a warning that the size is assumed. With `edge = 11` stated the crash stays.
#[test]
fn an_assumed_insert_size_is_not_checked_past_the_axis() {
    let text = "G99 M03 S600 T0101\nG00 X16 Z2\nG00 Z-30\nG01 X22 F0.1\nG01 Z2\nM30\n";
    let blank = tube(60.0, 60.0, 20.0);
    let v = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"V\"\ntip = 2\nentering_angle = 93\n";
    let (_, f) = judge(text, &blank, v);
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
    let (tp, f) = judge(text, &blank, &format!("{v}edge = 11\n"));
    assert_eq!(f.verdict, Verdict::Crash);
    assert_eq!(line(&tp, f.crashes[0].segment), 3);
}

/// 5. A Φ20 boring bar does not enter a Φ16 bore, a Φ10 one does (boring Φ16 to Φ18).
#[test]
fn a_boring_bar_fits_its_bore_or_crashes() {
    let text = "G99 M03 S600 T0101\nG00 X18 Z2\nG01 Z-20 F0.1\nG00 X16\nG00 Z5\nM30\n";
    let blank = tube(40.0, 40.0, 16.0);
    let bar = |b: &str, i: &str| {
        format!("[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"{i}\"\nholder = \"{b}\"\n")
    };
    let (tp, f) = judge(text, &blank, &bar("S20R-SCLCR09", "CCMT 09T304"));
    assert_eq!(f.verdict, Verdict::Crash);
    assert_eq!(f.crashes[0].body, Some("boring bar"));
    assert_eq!(line(&tp, f.crashes[0].segment), 3);
    let (_, f) = judge(text, &blank, &bar("S10K-SCLCR06", "CCMT 060204"));
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
}
