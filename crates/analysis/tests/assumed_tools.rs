//! Issue 38: a guessed tool makes a possible finding, never a failed gate
//! (spec/simulation.md, "Findings from assumed tools"). The library pipeline on hand-made
//! cases.

use analysis::{Findings, Intents, Settings, Verdict};
use expander::{Machine, Toolpath};
use stock::{Blank, SimOptions, ToolTable};

fn judge(text: &str, tools: &str) -> (Toolpath, Findings) {
    let tools = ToolTable::from_toml(tools).expect("tool table");
    let program = gcode::parse(text).expect("program parses");
    let machine = Machine::default();
    let opts = expander::Options {
        tools: tools.facts(),
        start_tool: tools.numbers().first().copied(),
        ..Default::default()
    };
    let tp = expander::expand(&program, &machine, &opts);
    let blank = Blank::bar(40.0, 60.0, 0.0, None).unwrap();
    let settings = Settings {
        blank: &blank,
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
