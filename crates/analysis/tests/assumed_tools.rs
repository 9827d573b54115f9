//! Issue 38: a guessed tool makes a possible finding, never a failed gate
//! (spec/simulation.md, "Findings from assumed tools"). The library pipeline on hand-made
//! cases.

mod common;

use analysis::{Findings, Verdict};
use expander::Toolpath;
use stock::{Blank, ToolTable};

/// The pipeline on a Φ40 × 60 bar with the tool table `tools`.
fn judge(text: &str, tools: &str) -> (Toolpath, Findings) {
    let tools = ToolTable::from_toml(tools).expect("tool table");
    let blank = Blank::bar(40.0, 60.0, 0.0, None).unwrap();
    let (tp, _, f) = common::judge(text, &blank, &tools);
    (tp, f)
}

const T01: &str =
    "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";

/// Φ40 bar; T01 (stated) turns Φ30 to Z-30 by G71/G70; T03 parts off at Z-33 from X42 to
/// X2. Without T03 in the table the default 55° insert's trailing edge wipes the Φ30
/// shoulder as it plunges: 7.5 mm deep (20 − 15 … down to r 7.5 where the 32° edge
/// leaves it), a *possible* gouge: clean, exit 0, one LS-ASSUMED-TOOL naming T03. T03 as a
/// 3 mm blade: clean, no warning. T03 as a stated 55° insert: the gouge, certain.
#[test]
fn a_guessed_part_off_tool_makes_a_possible_gouge() {
    let text = "G99 M03 S600\nT0101\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X30\nG01 Z-30\nN20 X42\nG70 P10 Q20\nG00 X100 Z100\nT0303\nG00 X42 Z-33\nG01 X2 F0.05\nG00 X50\nM30\n";
    let (tp, f) = judge(text, T01);
    assert_eq!(f.verdict, Verdict::Clean);
    let d = f.deviation.as_ref().unwrap();
    assert_eq!(d.gouges.len(), 1, "{:?}", d.gouges);
    let g = &d.gouges[0];
    assert!(g.assumed && (g.depth - 7.5).abs() < 0.01, "{g:?}");
    assert_eq!(g.made_by.map(|s| tp.segments[s].span.line), Some(13));
    let notes: Vec<_> = f
        .part_warnings
        .iter()
        .filter(|n| n.code == "LS-ASSUMED-TOOL")
        .collect();
    assert_eq!(notes.len(), 1);
    assert!(notes[0].message.contains("T03"), "{}", notes[0].message);
    assert!(
        notes[0].message.contains("possible gouge 7.500 mm"),
        "{}",
        notes[0].message
    );

    let blade = format!("{T01}[[tool]]\nt = 3\nkind = \"grooving\"\nwidth = 3\nwidth_dir = \"-z\"\nshank_dir = \"+x\"\nreach = 20\n");
    let (_, f) = judge(text, &blade);
    assert_eq!(f.verdict, Verdict::Clean);
    assert!(f.deviation.as_ref().unwrap().gouges.is_empty());
    assert!(f
        .warnings
        .iter()
        .chain(&f.part_warnings)
        .all(|n| n.code != "LS-ASSUMED-TOOL"));

    let d55 = format!("{T01}[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DNMG 110404\"\nholder = \"PDJNR 2525M11\"\n");
    let (_, f) = judge(text, &d55);
    assert_eq!(f.verdict, Verdict::Gouge);
    assert!(!f.deviation.as_ref().unwrap().gouges[0].assumed);
}

/// A rapid of a tool with no entry whose reference point enters the uncut bar stays a
/// crash (`G00 X30 Z-10` into a Φ40 bar); one whose assumed outline alone reaches stock —
/// the default insert, its tip inside a groove, meeting the groove's right wall with its
/// body — is a possible crash: clean, with the warning.
#[test]
fn a_rapid_of_a_guessed_tool_is_certain_only_where_its_point_enters_stock() {
    let (tp, f) = judge(
        "G99 M03 S600\nT0101\nG00 X42 Z2\nG00 X30 Z-10\nG00 X50\nM30\n",
        "",
    );
    assert_eq!(f.verdict, Verdict::Crash);
    let first = &f.crashes[0];
    assert!(!first.assumed);
    assert_eq!(tp.segments[first.segment].span.line, 4);

    let groove = "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 10\nwidth_dir = \"-z\"\nshank_dir = \"+x\"\nreach = 20\n";
    let (tp, f) = judge(
        "G99 M03 S600\nT0101\nG00 X42 Z-10\nG01 X30 F0.05\nG00 X42\nT0303\nG00 X36 Z-12\nG00 Z-18\nG00 X50\nG00 Z5\nM30\n",
        groove,
    );
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
    assert_eq!(f.crashes.len(), 1);
    assert!(f.crashes[0].assumed);
    assert_eq!(tp.segments[f.crashes[0].segment].span.line, 7);
    assert!(f
        .warnings
        .iter()
        .any(|n| n.code == "LS-ASSUMED-TOOL" && n.message.contains("possible crash")));
}

/// A tube Φ60 × 40 with a Φ30 bore, bored to Φ34 in one pass by T02 with no entry: the
/// default OD insert fed along the bore cuts the wall above its point, not the bore below
/// it, and the retract (`X33.6`, then `G00 Z2`) runs back through the 2 mm it left. That
/// stock is there only because the guess is the wrong way round for a boring bar: a
/// possible crash, clean. With T02 stated as a boring bar the pass cuts the bore and the
/// retract meets nothing; with T02 stated as an OD insert the crash is certain.
#[test]
fn a_rapid_through_stock_a_guessed_tool_left_is_a_possible_crash() {
    let text =
        "G99 M03 S600\nT0202\nG00 X34 Z2\nG01 Z-20 F0.2\nX33.6\nG00 Z2\nG00 X100 Z100\nM30\n";
    let tube = Blank::bar(60.0, 40.0, 0.0, Some(30.0)).unwrap();
    let run = |tools: &str| {
        let tools = ToolTable::from_toml(tools).expect("tool table");
        let (tp, _, f) = common::judge(text, &tube, &tools);
        (tp, f)
    };
    let (tp, f) = run("");
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.crashes);
    assert_eq!(f.crashes.len(), 1, "{:?}", f.crashes);
    assert!(f.crashes[0].assumed);
    assert_eq!(tp.segments[f.crashes[0].segment].span.line, 6);
    assert!(f
        .warnings
        .iter()
        .any(|n| n.code == "LS-ASSUMED-TOOL" && n.message.contains("possible crash")));

    let bar = "[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.4\ntip = 2\nentering_angle = 93\nedge = 11.0\nshank = 20.0\n";
    let (_, f) = run(bar);
    assert!(f.crashes.is_empty(), "{:?}", f.crashes);

    let od = "[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"DNMG 110404\"\nholder = \"PDJNR 2525M11\"\n";
    let (_, f) = run(od);
    assert_eq!(f.verdict, Verdict::Crash);
    assert!(f.crashes.iter().all(|c| !c.assumed));
}

/// Where a tool with no entry turned (Φ40 to Φ30 over Z0…-10), the stock it left is a
/// guess; a rapid into the bar 30 mm beyond it (`G00 X30 Z-40`), farther than any tool of
/// the guessed size reaches from that cut, is certain: the gate still fails.
#[test]
fn a_rapid_into_bar_far_from_a_guessed_cut_stays_certain() {
    let (tp, f) = judge(
        "G99 M03 S600\nT0101\nG00 X42 Z2\nG00 X30\nG01 Z-10 F0.2\nG00 X42\nG00 Z-40\nG00 X30\nG00 X50\nM30\n",
        "",
    );
    assert_eq!(f.verdict, Verdict::Crash, "{:?}", f.crashes);
    let certain: Vec<_> = f.crashes.iter().filter(|c| !c.assumed).collect();
    assert_eq!(certain.len(), 1, "{:?}", f.crashes);
    assert_eq!(tp.segments[certain[0].segment].span.line, 8);
}

/// No tool table: T01 turns Φ20 to Z-20 on a Φ30 bar; then T03 rapids from X60 Z100
/// straight to X22 Z-25, through the shoulder face at Z-20 and 4 mm into bar no tool cut.
/// T01's shoulder pass at Z-20 leaves the bar beyond it whichever way its tool points (an
/// OD insert or a boring bar both cut toward +Z of their point): a certain crash at line
/// 13. (A disc around each guessed feed, any way round, made it possible: the gate passed
/// a part-off approach into the bar.)
#[test]
fn a_rapid_into_bar_beyond_a_guessed_shoulder_stays_certain() {
    let text = "G21 G40 G98\nT0101\nM03 S1000\nG00 X32. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.4 W0.1 F100\nN10 G00 X20.\nG01 Z-20.\nN20 X32.\nG70 P10 Q20 F50\nG00 X60. Z100.\nT0303\nG00 X22. Z-25.\nG01 X2. F20\nG00 X46.\nM30\n";
    let bar = Blank::bar(30.0, 60.0, 0.0, None).unwrap();
    let (tp, _, f) = common::judge(text, &bar, &ToolTable::empty());
    assert_eq!(f.verdict, Verdict::Crash, "{:?}", f.crashes);
    let certain: Vec<_> = f.crashes.iter().filter(|c| !c.assumed).collect();
    assert_eq!(certain.len(), 1, "{:?}", f.crashes);
    assert_eq!(tp.segments[certain[0].segment].span.line, 13);
}

/// The verdict is clean, and every gouge (there is one at least) is possible.
fn assert_clean_with_possible_gouges(f: &Findings) {
    assert_eq!(f.verdict, Verdict::Clean, "{:?}", f.deviation);
    let d = f.deviation.as_ref().unwrap();
    assert!(
        !d.gouges.is_empty() && d.gouges.iter().all(|g| g.assumed),
        "{:?}",
        d.gouges
    );
}

/// A bush with no tool table: T01 turns the OD by G71/G70, T04 bores Φ22 to Φ25.6 by
/// G71/G70. The default OD insert standing in for T04 cuts the bore wall above its point,
/// so the G70's ID contour lay wholly in the air where its cycle began and was dropped:
/// T01's OD contour then claimed the wall and the default's own passes "entered" it, a
/// certain 3.9 mm gouge. A tool the table says nothing of, cutting inside a contour another
/// tool finished before, makes a possible gouge (and the ID contour, read against the blank
/// now, is T04's again): clean. (Second field run.)
#[test]
fn a_guessed_boring_bar_does_not_lose_its_own_contour() {
    let text = "G21 G18 G40 G99\nT0101\nG96 S200 M03\nG00 X54. Z2.\nG71 U1.5 R0.5\nG71 P100 Q110 U0.3 W0.1 F0.25\nN100 G00 X32.\nG01 Z0. F0.1\nG01 X35. Z-1.5\nG01 Z-15.\nG01 X50.\nN110 G01 Z-18.\nG70 P100 Q110 F0.1\nG00 X54. Z2.\nG28 U0. W0.\nT0404\nG96 S120 M03\nG00 X22. Z2.\nG71 U0.4 R0.3\nG71 P200 Q210 U-0.3 W0.0 F0.12\nN200 G00 X25.6\nG01 Z0. F0.08\nG01 Z-30.\nN210 G00 X22.\nG70 P200 Q210 F0.06\nG00 X22. Z5.\nG28 U0. W0.\nM30\n";
    let tube = Blank::bar(50.0, 40.0, 0.0, Some(22.0)).unwrap();
    let (_, _, f) = common::judge(text, &tube, &ToolTable::empty());
    assert_clean_with_possible_gouges(&f);
}

/// No tool table: T01 turns Φ20, T04 threads it by G76, T05 centre-drills 8 deep on the
/// axis. The default insert standing in for T05 cuts the core far beyond a centre drill;
/// its reference point on the axis enters T01's finished contour, which made the gouge
/// certain. A tool the table says nothing of may be a drill or a blade, whose own hole or
/// groove that is (LS-LATER-CUT for stated ones): a possible gouge, clean.
#[test]
fn an_unknown_tool_inside_another_tools_contour_is_possible() {
    let text = "G21 G40 G99\nT0101\nG50 S3000\nG96 S200 M03\nG00 X42. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.3\nN10 G00 X14.\nG01 X20. Z-1. F0.1\nZ-20.\nN20 X42.\nG70 P10 Q20\nG28 U0. W0.\nT0404\nG97 S1200 M03\nG00 X22. Z5.\nG76 P010060 Q50 R0.05\nG76 X18.16 Z-17. P920 Q300 F1.5\nG00 X44.\nG28 U0. W0.\nT0505\nG97 S1500 M03\nG00 X0. Z2.\nG01 Z-8. F0.05\nG00 Z5.\nG28 U0. W0.\nM30\n";
    let bar = Blank::bar(40.0, 50.0, 0.0, None).unwrap();
    let (_, _, f) = common::judge(text, &bar, &ToolTable::empty());
    assert_clean_with_possible_gouges(&f);
}

/// No tool table: an internal M30 × 1.5 thread by G76 in a bored sleeve. The default
/// threading insert is an OD one, so its passes went deeper away from its side: the alarm
/// LS-THREAD-SIDE told the user to give the tool `side = "id"` though they gave no tool.
/// The side is the default's guess: a warning LS-ASSUMED-TOOL naming T04, no alarm.
#[test]
fn an_inside_thread_of_an_unknown_tool_is_no_side_alarm() {
    let text = "G18 G21 G40 G80 G99\nT0303\nG96 S150 M03\nG00 X18. Z2.\nG71 U1.5 R0.5\nG71 P30 Q40 U-0.4 W0.1 F0.2\nN30 G00 X32.\nG01 X28.4 Z-0.8 F0.1\nZ-25.\nN40 X18.\nG70 P30 Q40\nG00 Z5.\nG28 U0. W0.\nT0404\nG97 S700 M03\nG00 X26. Z5.\nG76 P010060 Q50 R0.05\nG76 X30. Z-22. P812 Q250 F1.5\nG00 Z10.\nG28 U0. W0.\nM30\n";
    let sleeve = Blank::bar(50.0, 40.0, 0.0, Some(20.0)).unwrap();
    let (_, _, f) = common::judge(text, &sleeve, &ToolTable::empty());
    assert!(
        f.alarms.iter().all(|a| a.code != "LS-THREAD-SIDE"),
        "{:?}",
        f.alarms
    );
    assert!(
        f.part_warnings
            .iter()
            .any(|n| n.code == "LS-ASSUMED-TOOL"
                && n.message.contains("state T04 with `side = \"id\"`")),
        "{:?}",
        f.part_warnings
    );
}
