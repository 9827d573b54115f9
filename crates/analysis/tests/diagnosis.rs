//! Issue 33: every gouge, crash and leftover explained from the geometry, with a remedy
//! latsim has checked by re-running the program with it. Hand-built cases, numbers by hand.

use analysis::diagnose::{Change, Rerun, Rerunning};
use analysis::{CauseKind, Findings, Intents, Settings};
use expander::Machine;
use stock::{Blank, Shape, SimOptions, ToolTable};

/// A program, its tools and blank, run like `latsim run` and re-runnable with a change.
struct Job {
    text: String,
    tools: ToolTable,
    blank: Blank,
    machine: Machine,
    intents: Intents,
}

impl Job {
    fn new(text: &str, tools: &str, blank: Blank) -> Self {
        Self {
            text: text.into(),
            tools: ToolTable::from_toml(tools).expect("tool table"),
            blank,
            machine: Machine::default(),
            intents: Intents::Program,
        }
    }

    /// Judged against a drawn part (a profile TOML, as `--target` reads it).
    fn target(mut self, profile: &str) -> Self {
        self.intents = Intents::Target(stock::profile_from_toml(profile, 0.0001).unwrap());
        self
    }

    fn run(&self, text: &str, tools: &ToolTable) -> (expander::Toolpath, Findings, Vec<Shape>) {
        let program = gcode::parse(text).expect("program parses");
        let opts = expander::Options {
            tools: tools.facts(),
            start_tool: tools.numbers().first().copied(),
            ..Default::default()
        };
        let tp = expander::expand(&program, &self.machine, &opts);
        let (sim, f) = analysis::pipeline(
            &tp,
            &self.intents,
            &self.settings(tools),
            &SimOptions::default(),
            &mut |_| {},
        );
        (tp, f, sim.final_shapes)
    }

    fn settings<'a>(&'a self, tools: &'a ToolTable) -> Settings<'a> {
        Settings {
            blank: &self.blank,
            tools,
            machine: &self.machine,
            fixture: None,
            tol: 0.01,
        }
    }

    /// The run, diagnosed.
    fn diagnosed(&self) -> (expander::Toolpath, Findings) {
        let (tp, mut f, part) = self.run(&self.text, &self.tools);
        analysis::diagnose::diagnose(
            &mut f,
            (&tp, &part, &self.text),
            &self.settings(&self.tools),
            self,
        );
        (tp, f)
    }
}

impl Rerun for Job {
    fn rerun(&self, change: &Change) -> Option<Rerunning> {
        let (text, tools) = match change {
            Change::Tool { t, entry } => (self.text.clone(), self.tools.replaced(*t, entry).ok()?),
            program => (program.edited(&self.text)?, self.tools.clone()),
        };
        let (tp, findings, part) = self.run(&text, &tools);
        Some(Rerunning {
            findings,
            part,
            alarms: tp.alarms.len(),
        })
    }
}

/// The crashes of `f` (not possible ones) made by moves of program line `line`.
fn certain_crashes_at<'a>(
    tp: &expander::Toolpath,
    f: &'a Findings,
    line: u32,
) -> Vec<&'a analysis::Crash> {
    f.crashes
        .iter()
        .filter(|c| !c.assumed && tp.segments[c.segment].span.line == line)
        .collect()
}

fn bar(d: f64, l: f64) -> Blank {
    Blank::bar(d, l, 0.0, None).unwrap()
}

/// A CNMG 12 in a PCLNR (T01) and a 3 mm grooving blade reaching 20 mm (T03).
const CNMG_AND_BLADE: &str = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n\
     [[tool]]\nt = 3\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\nreach = 20.0\n";

const D55: &str =
    "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"DNMG 150404\"\nholder = \"PDJNR 2525M15\"\n";

/// A D 55° insert on a 93° holder (PDJNR) finishing, under G42, a 41° flank descending
/// from Φ40 at Z-10 to Φ29.569 at Z-16 (5.216 mm over 6: tan 41°). Its trailing edge has
/// 180 − 93 − 55 = 32° of clearance: it cuts into the flank. Remedy: a 35° V on 93°
/// (VBMT 160404 in SVJBR 2525M16: 180 − 93 − 35 = 52°), checked by the re-run. The G73
/// leaves U1.2 for the G70: its last pass, which no G42 compensates, would leave any r0.4
/// nose 0.4 − 0.4 (cos 41° − sin 41°) = 0.360 mm into the flank, and 0.6 cos 41° = 0.453
/// of allowance clears that (with U0 the V was offered as a cure, and the re-run left the
/// 0.36 mm).
#[test]
fn a_d55_trailing_edge_on_a_41_degree_flank_gets_a_v35() {
    let text = "G99 M03 S600 T0101\nG00 X52 Z2\nG73 U6 W0 R4\nG73 P10 Q20 U1.2 W0 F0.2\nN10 G00 G42 X40 Z2\nG01 Z-10 F0.1\nX29.569 Z-16\nZ-30\nN20 G40 X52\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let (_, f) = Job::new(text, D55, bar(50.0, 60.0)).diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    let c = g.cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::TrailingEdge, "{}", c.text);
    let num = |k: &str| c.numbers.iter().find(|(n, _)| *n == k).unwrap().1;
    assert!((num("clearance_deg") - 32.0).abs() < 1e-9);
    assert!(
        (num("flank_deg") - 41.0).abs() < 0.01,
        "{}",
        num("flank_deg")
    );
    let r = g.remedy.as_ref().expect("a checked remedy");
    assert!(r.verified);
    assert_eq!(r.tool.as_deref(), Some("VBMT 160404 in SVJBR 2525M16"));
    assert!(r.text.contains("52°"), "{}", r.text);
}

/// A sharp D 55° (no nose) descending the 41° flank uncompensated; the table's T02, a
/// V 35° on 93°, clears the flank with its trailing edge but leaves its r0.8 nose 0.72 mm
/// deep in the same flank: no cure (it was offered as "checked" while the re-run's gouge
/// lay 5 mm from where the first was deepest). The ISO V offered keeps the program's sharp
/// nose (VBMT 160400, not 160404 and its 0.4 mm), and re-running with it leaves no gouge.
#[test]
fn a_tool_that_leaves_the_flank_gouged_is_no_remedy() {
    let text = "G99 M03 S600 T0101\nG00 X52 Z2\nG73 U6 W0 R4\nG73 P10 Q20 U0 W0 F0.2\nN10 G00 X40 Z2\nG01 Z-10 F0.1\nX29.569 Z-16\nZ-30\nN20 X52\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.0\ntip = 3\nentering_angle = 93\nedge = 15\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"V\"\nnose_radius = 0.8\ntip = 3\nentering_angle = 93\nedge = 16\n";
    let job = Job::new(text, tools, bar(50.0, 60.0));
    let (_, f) = job.diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    assert_eq!(g.cause.as_ref().unwrap().kind, CauseKind::TrailingEdge);
    let r = g.remedy.as_ref().expect("a checked remedy");
    assert_eq!(
        r.tool.as_deref(),
        Some("VBMT 160400 in SVJBR 2525M16"),
        "{}",
        r.text
    );
    // what "checked" means: the program re-run with it has no gouge
    let entry =
        "kind = \"turning\"\ninsert = \"VBMT 160400\"\nholder = \"SVJBR 2525M16\"\ntip = 3\n";
    let run = job
        .rerun(&Change::Tool {
            t: 1,
            entry: entry.into(),
        })
        .unwrap();
    assert!(run.findings.deviation.unwrap().gouges.is_empty());
    // and with T02 the flank is still gouged
    let t02 = "kind = \"turning\"\ninsert = \"V\"\nnose_radius = 0.8\ntip = 3\nentering_angle = 93\nedge = 16\n";
    let run = job
        .rerun(&Change::Tool {
            t: 1,
            entry: t02.into(),
        })
        .unwrap();
    let left = run.findings.deviation.unwrap().gouges;
    assert!(left.iter().any(|g| g.depth > 0.7), "{left:?}");
}

/// A G73 finishing a concave R6 half circle from Φ20 (the forum's program) with a sharp D
/// 55° on 93°: its trailing edge cuts the circle's start, which falls vertically. The
/// flank named is the steepest edge the gouge lies against (~89°, a chord of the circle's
/// start), not the Φ20 diameter nearest its deepest point (0°); no V clears it, so no
/// remedy is offered (a V 35° on 93° was, and left 1.3 mm).
#[test]
fn the_flank_is_the_steepest_edge_the_gouge_lies_against() {
    let text = "G99 M03 S600 T0101\nG00 X31 Z1\nG73 U6 R10\nG73 P10 Q20 U0.1 W0 F0.2\nN10 G00 X20\nG01 Z-10\nN20 G02 X20 Z-22 R6\nG70 P10 Q20 F0.08\nG00 X100 Z100\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.0\ntip = 3\nentering_angle = 93\nedge = 11\n";
    let (_, f) = Job::new(text, tools, bar(32.0, 60.0)).diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    let c = g.cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::TrailingEdge, "{}", c.text);
    let flank = c.numbers.iter().find(|(n, _)| *n == "flank_deg").unwrap().1;
    assert!(flank > 85.0, "{}", c.text);
    assert!(g.remedy.is_none(), "{:?}", g.remedy);
}

/// The same flank with the table's own sharper tool (T02 a V 35° on 93°): the remedy names
/// it.
#[test]
fn the_tables_own_tool_comes_first() {
    let text = "G99 M03 S600 T0101\nG00 X52 Z2\nG73 U6 W0 R4\nG73 P10 Q20 U1.2 W0 F0.2\nN10 G00 G42 X40 Z2\nG01 Z-10 F0.1\nX29.569 Z-16\nZ-30\nN20 G40 X52\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let tools = format!("{D55}[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"V\"\nnose_radius = 0.4\ntip = 3\nentering_angle = 93\nedge = 16\n");
    let (_, f) = Job::new(text, &tools, bar(50.0, 60.0)).diagnosed();
    let r = f.deviation.as_ref().unwrap().gouges[0]
        .remedy
        .clone()
        .expect("a checked remedy");
    assert!(
        r.tool.as_deref().is_some_and(|t| t.starts_with("T02")),
        "{r:?}"
    );
}

/// A leading edge on a wall that leans toward it: the drawn part's shoulder rises from Φ30
/// at Z-20 to Φ40 at Z-19.118 (10° from square: its run is 5 tan 10° = 0.882 over its 5 mm
/// rise), turned straight to Z-20 with a 93° holder (its leading edge 3° from square): at
/// the end of the pass the edge stands in the wall.
#[test]
fn a_leading_edge_in_a_wall_leaning_more_than_the_holder() {
    let text =
        "G99 M03 S600 T0101\nG00 X30 Z2\nG01 Z-20 F0.1\nX40 Z-19.1184\nG00 X42\nG00 Z2\nM30\n";
    let part = "start = [0.0, 0.0]\npath = [\n { to = [0.0, 30.0] },\n { to = [-20.0, 30.0] },\n { to = [-19.1184, 40.0] },\n { to = [-60.0, 40.0] },\n { to = [-60.0, 0.0] },\n]\n";
    let (_, f) = Job::new(text, D55, bar(40.0, 60.0))
        .target(part)
        .diagnosed();
    let g = &f.deviation.as_ref().expect("intents").gouges;
    let c = g
        .iter()
        .filter_map(|g| g.cause.as_ref())
        .find(|c| c.kind == CauseKind::LeadingEdge);
    let c = c.unwrap_or_else(|| panic!("{:?}", g.iter().map(|g| &g.cause).collect::<Vec<_>>()));
    let num = |k: &str| c.numbers.iter().find(|(n, _)| *n == k).unwrap().1;
    assert!((num("holder_lean_deg") - 3.0).abs() < 1e-9);
    assert!(
        (num("wall_lean_deg") - 10.0).abs() < 0.01,
        "{}",
        num("wall_lean_deg")
    );
}

/// The nose left uncompensated: the same finish without G42 on a 30° taper (Φ40 at Z-10
/// down to Φ34.226 at Z-15: 2.887 = 5 tan 30°) with an r0.4 D insert. Cause: compensation,
/// G42 named (OD, toward the chuck: the part on the left of travel).
#[test]
fn a_nose_left_uncompensated_names_g42() {
    let text = "G99 M03 S600 T0101\nG00 X52 Z2\nG73 U6 W0 R4\nG73 P10 Q20 U0 W0 F0.2\nN10 G00 X40 Z2\nG01 Z-10 F0.1\nX34.226 Z-15\nZ-30\nN20 X52\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let (_, f) = Job::new(text, D55, bar(50.0, 60.0)).diagnosed();
    let gouges = &f.deviation.as_ref().unwrap().gouges;
    let c = gouges[0].cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::Compensation, "{}", c.text);
    assert!(c.text.contains("G42"), "{}", c.text);
    assert!(c
        .numbers
        .iter()
        .any(|(k, v)| *k == "nose_radius" && (*v - 0.4).abs() < 1e-9));
}

/// A leftover in a sharp inside corner the r0.4 nose cannot fill: the Φ30 shoulder at
/// Z-20 (up to Φ36) turned under G42 leaves 0.4² (1 − π/4) = 0.0343 mm² there.
#[test]
fn a_nose_leaves_a_sharp_inside_corner() {
    let text = "G99 M03 S600 T0101\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 G42 X30\nG01 Z-20 F0.1\nX36\nZ-30\nX42\nN20 G40 X44\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let (_, f) = Job::new(text, D55, bar(40.0, 60.0)).diagnosed();
    let d = f.deviation.as_ref().unwrap();
    let l = d
        .leftovers
        .iter()
        .find(|l| (l.area - 0.0343).abs() < 0.002)
        .unwrap_or_else(|| {
            panic!(
                "{:?}",
                d.leftovers.iter().map(|l| l.area).collect::<Vec<_>>()
            )
        });
    assert_eq!(l.cause.as_ref().unwrap().kind, CauseKind::Nose);
}

/// Roughed by T01 (r0.8), finished by T02 (r0.2) under G42: the sharp shoulder keeps
/// (1 − 1/√2)·0.2 = 0.059 mm, what the finishing nose leaves, and the cause names r0.2 (it
/// named the program's largest nose, r0.8: a user would change the wrong insert).
#[test]
fn a_corner_leftover_names_the_nose_that_last_passed_it() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"VNMG 160402\"\nholder = \"MVJNR 2525M16\"\n";
    let text = "G21 G40 G99\nT0101\nG96 S200 M03\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 G42 X20.\nG01 Z-30.\nN20 X42.\nG40 G00 X60. Z10.\nT0202\nG96 S250 M03\nG00 X42. Z2.\nG70 P10 Q20 F0.1\nG40 G00 X60. Z10.\nM30\n";
    let (_, f) = Job::new(text, tools, bar(40.0, 50.0)).diagnosed();
    let d = f.deviation.as_ref().unwrap();
    let l = d
        .leftovers
        .iter()
        .find(|l| (l.depth - 0.0586).abs() < 0.002)
        .unwrap_or_else(|| {
            panic!(
                "{:?}",
                d.leftovers.iter().map(|l| l.depth).collect::<Vec<_>>()
            )
        });
    let cause = l.cause.as_ref().unwrap();
    assert_eq!(cause.kind, CauseKind::Nose);
    assert!(cause.text.starts_with("the r0.2 nose"), "{}", cause.text);
}

/// A 45° chamfer finished without G41/G42 by an r0.4 nose: the tip runs on the contour and
/// the nose leaves r(√2 − 1) = 0.166 mm on the slope, not in a corner: the cause is the
/// uncompensated radius (it read "cannot fill this inside corner", of the roughing r0.8).
#[test]
fn a_band_on_an_uncompensated_chamfer_is_the_compensation() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"DNMG 150404\"\nholder = \"PDJNR 2525M15\"\n";
    let text = "G21 G40 G99\nT0101\nG96 S200 M03\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X16.\nG01 Z0. F0.12\nX20. Z-2.\nZ-20.\nN20 X41.\nG00 X100. Z100.\nT0202\nG00 X42. Z2.\nG70 P10 Q20\nG00 X100. Z100.\nM30\n";
    let (_, f) = Job::new(text, tools, bar(40.0, 50.0)).diagnosed();
    let d = f.deviation.as_ref().unwrap();
    let l = d
        .leftovers
        .iter()
        .find(|l| (l.depth - 0.1657).abs() < 0.003)
        .unwrap_or_else(|| {
            panic!(
                "{:?}",
                d.leftovers.iter().map(|l| l.depth).collect::<Vec<_>>()
            )
        });
    let cause = l.cause.as_ref().unwrap();
    assert_eq!(cause.kind, CauseKind::Compensation, "{}", cause.text);
    assert!(
        cause
            .text
            .starts_with("the r0.4 nose leaves 0.166 mm on this slope"),
        "{}",
        cause.text
    );
}

/// A G70 finishes Φ20 with a sharp front corner; then the same tool breaks that edge by
/// hand without compensation (`G00 X17. Z1. / G01 Z0. / X21. Z-2.`). The gouge lies across
/// the corner, on the tool's side of the path, while the part lies on its left (toward the
/// axis and the chuck): the remedy is G42, the side of the part. (The gouge's side named
/// G41, and the G41 the message asked for made two gouges, 1.13 mm.)
#[test]
fn an_edge_break_by_hand_names_the_side_of_the_part() {
    let cnmg = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let text = "G21 G40 G99\nT0101\nG96 S200 M03\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z0.\nZ-30.\nN20 X42.\nG70 P10 Q20 F0.1\nG00 X17. Z1.\nG01 Z0. F0.1\nX21. Z-2.\nG00 X42.\nG00 X60. Z10.\nM30\n";
    let (_, f) = Job::new(text, cnmg, bar(40.0, 80.0)).diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    let c = g.cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::Compensation, "{}", c.text);
    assert!(c.text.contains("(G42 from line"), "{}", c.text);
}

/// The program itself: a last pass at X19 where the drawn part is Φ20: the programmed point
/// goes 0.5 mm into the part (more than the 0.4 nose: no compensation puts it there). And a
/// G73 whose roughing passes, the shape moved out by U, run into a wall that leans toward
/// the tool: the roughing path itself enters the part.
#[test]
fn the_programmed_point_into_the_part_is_the_program() {
    let text = "G99 M03 S600 T0101\nG00 X42 Z2\nG71 U1.5 R0.5\nG71 P10 Q20 U0 W0 F0.25\nN10 G00 X20\nG01 Z0 F0.12\nZ-20\nX30\nZ-35\nN20 X41\nG00 X19 Z2\nG01 Z-19.8 F0.1\nG00 X42\nM30\n";
    let (_, f) = Job::new(text, D55, bar(40.0, 60.0)).diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    let c = g.cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::Program, "{}", c.text);
    assert!(c.text.contains("line 12"), "{}", c.text);
    let text = "G99 M03 S600 T0101\nG00 X42 Z2\nG73 U6 W0 R4\nG73 P10 Q20 U0 W0 F0.2\nN10 G00 G42 X30 Z2\nG01 Z-20 F0.1\nX40 Z-19.1184\nZ-40\nN20 G40 X42\nG70 P10 Q20\nG00 X100 Z100\nM30\n";
    let (_, f) = Job::new(text, D55, bar(40.0, 60.0)).diagnosed();
    let c = f.deviation.as_ref().unwrap().gouges[0]
        .cause
        .clone()
        .unwrap();
    assert_eq!(c.kind, CauseKind::Program, "{}", c.text);
}

/// The program, though shallower than the nose: the same X19 pass cut with an r0.8 insert
/// (CNMG 120408) goes 0.5 mm into the part, less than its radius; on a straight cut the
/// nose, compensated or not, reaches no deeper than its reference point, so no G41/G42
/// explains it: the programmed path goes as deep as the gouge.
#[test]
fn a_path_as_deep_as_the_gouge_is_the_program_not_compensation() {
    let text = "G99 M03 S600 T0101\nG00 X42 Z2\nG71 U1.5 R0.5\nG71 P10 Q20 U0 W0 F0.25\nN10 G00 X20\nG01 Z0 F0.12\nZ-20\nX30\nZ-35\nN20 X41\nG00 X19 Z2\nG01 Z-19.8 F0.1\nG00 X42\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let (_, f) = Job::new(text, tools, bar(40.0, 60.0)).diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    assert!((g.depth - 0.5).abs() < 0.01, "{}", g.depth);
    let c = g.cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::Program, "{}", c.text);
    assert!(c.text.contains("line 12"), "{}", c.text);
}

/// Another tool cut it: T01 finishes Φ30 to Z-30, then T02 (a stated turning tool) feeds
/// to X28 over Z-5 … -10: a gouge of T01's contour by another tool.
#[test]
fn another_tool_into_a_finished_contour() {
    let text = "G99 M03 S600\nT0101\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X30\nG01 Z-30\nN20 X42\nG70 P10 Q20\nG00 X100 Z100\nT0202\nG00 X32 Z-5\nG01 X28 F0.1\nZ-10\nX32\nG00 X100 Z100\nM30\n";
    let tools = format!("{D55}[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n");
    let (_, f) = Job::new(text, &tools, bar(40.0, 60.0)).diagnosed();
    let g = &f.deviation.as_ref().unwrap().gouges[0];
    let c = g.cause.as_ref().expect("a cause");
    assert_eq!(c.kind, CauseKind::OtherTool, "{}", c.text);
    assert!(
        c.text.contains("T02") && c.text.contains("T01"),
        "{}",
        c.text
    );
}

/// A rapid into uncut bar, from a safe point diagonally to X42 Z-30 past a Φ40 bar's
/// shoulder it meets at the face: cause rapid (the face named), and a remedy checked by the
/// re-run: rapid to X42 first, then Z-30.
#[test]
fn a_diagonal_rapid_into_the_bar_is_split() {
    let text =
        "G99 M03 S600 T0101\nG00 X100 Z2\nG00 X30 Z2\nG00 X42 Z-30\nG01 X38 F0.1\nG00 X100\nM30\n";
    let (tp, f) = Job::new(text, D55, bar(40.0, 60.0)).diagnosed();
    let c = &f.crashes[0];
    assert_eq!(tp.segments[c.segment].span.line, 4);
    let cause = c.cause.as_ref().unwrap();
    assert_eq!(cause.kind, CauseKind::Rapid);
    assert!(cause.text.contains("the face at Z0"), "{}", cause.text);
    let r = c.remedy.as_ref().expect("a checked remedy");
    assert_eq!((r.line, r.edit.as_deref()), (Some(4), Some("G00 X42.")));
    assert!(
        r.text.contains("rapid to X42. first, then Z-30."),
        "{}",
        r.text
    );
}

/// A body crash: a Φ20 boring bar (S20R-SCLCR09) sent into a Φ16 bore: cause body, naming
/// the bar.
#[test]
fn a_bar_too_thick_for_the_bore_is_the_body() {
    let text = "G99 M03 S600 T0101\nG00 X18 Z2\nG01 Z-20 F0.1\nG00 X16\nG00 Z5\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CCMT 09T304\"\nholder = \"S20R-SCLCR09\"\n";
    let (_, f) = Job::new(
        text,
        tools,
        Blank::bar(40.0, 40.0, 0.0, Some(16.0)).unwrap(),
    )
    .diagnosed();
    let c = f.crashes[0].cause.as_ref().unwrap();
    assert_eq!(c.kind, CauseKind::Body, "{}", c.text);
    assert!(c.text.contains("boring bar"), "{}", c.text);
}

/// A grooving subprogram called twice (field run 10, B3): each call plunges a neck at Ø30,
/// backs out to Ø36 and rapids 10 mm toward the chuck along Ø36 — the second call's rapid
/// runs from Z-22 into the R4 fillet the turning left between Ø36 at Z-30 and Ø44 at Z-34
/// (0.5 mm deep at Z-32). A retract inserted before that rapid (`G00 Z2.`) runs on every
/// call: the incremental `W-10.` then ends at Z-8, the second neck is cut at Z-8 instead of
/// Z-22, and the re-run has no finding (no shape to compare). No remedy that moves the
/// program's own cuts is offered; the crash keeps its cause.
#[test]
fn a_fix_that_moves_the_programs_own_cuts_is_no_remedy() {
    let text = "G99\nT0101\nG96 S180 M03\nG00 X46. Z2.\nG01 Z-45. F0.25\nG00 X48. Z2.\n\
                G00 X40.\nG01 Z-30. F0.25\nG00 X46. Z2.\nG00 X36.\nG01 Z-30. F0.15\n\
                G02 X44. Z-34. R4.\nG01 X52.\nG00 X60. Z50.\nT0303\nG97 S700 M03\n\
                G00 X40. Z-12.\nM98 P0035 L2\nG00 X60.\nM30\nO0035\nG01 X30. F0.05\n\
                G00 X36.\nW-10.\nM99\n";
    let job = Job::new(text, CNMG_AND_BLADE, bar(50.0, 60.0));
    let (tp, f) = job.diagnosed();
    let c = f
        .crashes
        .iter()
        .find(|c| !c.assumed)
        .expect("the rapid into the fillet");
    assert!(
        (c.at[0] + 29.5).abs() < 0.5 && (c.at[1] - 18.0).abs() < 0.01,
        "{:?}",
        c.at
    );
    assert_eq!(c.cause.as_ref().unwrap().kind, CauseKind::Rapid);
    assert_eq!(tp.segments[c.segment].span.line, 24);
    // the retract the re-run alone would have taken: no finding, but the part lost a neck
    let moved = job
        .rerun(&Change::Insert {
            line: 24,
            text: "G00 Z2.".into(),
        })
        .unwrap();
    assert!(moved.findings.crashes.iter().all(|c| c.assumed));
    assert!(c.remedy.is_none(), "{:?}", c.remedy);
}

/// A plunge written `G00` where `G01` was meant, into a Φ40 bar at Z-10: fed, it cuts what
/// it cut, and it meets the bar as the bar came: the remedy is the feed (a retract first
/// would move the plunge to the face and turn 10 mm more of the bar). A rapid into a fillet
/// the program turned (field run 10, B1) gets no such remedy: fed, it would take the
/// fillet's stock off as the rapid did.
#[test]
fn a_rapid_plunge_into_the_bar_is_fed_but_not_one_into_a_turned_fillet() {
    let text = "G99 M03 S600 T0101 F0.1\nG00 X42 Z-10\nG00 X38\nG01 Z-20\nG00 X50\nM30\n";
    let (tp, f) = Job::new(text, D55, bar(40.0, 60.0)).diagnosed();
    let c = &f.crashes[0];
    assert_eq!(tp.segments[c.segment].span.line, 3);
    let r = c.remedy.as_ref().expect("a checked remedy");
    assert_eq!(
        (r.line, r.edit.as_deref()),
        (Some(3), Some("G01")),
        "{}",
        r.text
    );

    let text = "G99 M03 S600 T0101\nG00 X46. Z2.\nG01 Z-45. F0.25\nG00 X48. Z2.\nG00 X40.\n\
                G01 Z-30. F0.25\nG00 X46. Z2.\nG00 X36.\nG01 Z-30. F0.15\nG02 X44. Z-34. R4.\n\
                G01 X52.\nG00 X60. Z50.\nT0303\nG00 X40. Z-22.\nG00 X36.\nG00 Z-32.\n\
                G00 X60.\nM30\n";
    let (tp, f) = Job::new(text, CNMG_AND_BLADE, bar(50.0, 60.0)).diagnosed();
    let c = f
        .crashes
        .iter()
        .find(|c| !c.assumed)
        .expect("the rapid into the fillet");
    assert_eq!(tp.segments[c.segment].span.line, 16);
    assert!(c.remedy.is_none(), "{:?}", c.remedy);
}

/// Field run 10 (B4): a DNMG 11 boring insert on a 93° bar in a Ø16 drilled hole reaches
/// past the axis into the far wall; the crash is in the G71's own retract. A block inserted
/// before the G71 line (`G00 X16.`) moved the cycle's start point, and the re-run dodged
/// the crash by it: it was offered as "rapid to X16. first". A rapid a cycle makes is not
/// the block's to split: no program remedy. The cause says the tool is too big for the
/// bore (it said "a rapid at X16 meets stock at Ø17.9", which sent the programmer to a
/// coordinate that is right).
#[test]
fn a_rapid_a_cycle_makes_gets_no_block_inserted_before_the_cycle() {
    let text = "G21 G40 G99\nT0505\nG97 S900 M03\nG00 X0. Z5.\nG01 Z-30. F0.1\nG00 Z5.\n\
                G00 X100. Z100.\nT0606\nG96 S150 M03\nG00 X15. Z2.\nG71 U1. R0.5\n\
                G71 P30 Q40 U-0.3 W0.05 F0.15\nN30 G00 X22.\nG01 X20. Z-1. F0.08\nZ-26.\n\
                N40 X15.\nG70 P30 Q40\nG00 Z5.\nG00 X100. Z100.\nM30\n";
    let tools = "[[tool]]\nt = 5\nkind = \"drill\"\ndiameter = 16.0\npoint_angle = 118\nreach = 50.0\n\
                 [[tool]]\nt = 6\nkind = \"turning\"\ninsert = \"DNMG 110404\"\ntip = 2\nentering_angle = 93\nshank = 12.0\n";
    let (tp, f) = Job::new(text, tools, bar(40.0, 50.0)).diagnosed();
    let in_cycle = certain_crashes_at(&tp, &f, 12);
    assert!(!in_cycle.is_empty(), "{:#?}", f.crashes);
    for c in &in_cycle {
        assert!(c.remedy.is_none(), "{:?}", c.remedy);
    }
    // the cause names the tool's far side, not the programmed diameter: the insert reaches
    // 9–10 mm past the axis from its point at Ø15–16 (by hand: the 55° rhombus's far corner
    // lies 17.7 mm below its tip), onto the wall opposite: at Ø17.9 it spans the bore
    // (17.4 mm, less than a millimetre of play), at Ø19.7 its point only runs too low
    let texts: Vec<&str> = in_cycle
        .iter()
        .map(|c| c.cause.as_ref().unwrap().text.as_str())
        .collect();
    assert!(
        texts.iter().all(|t| t.contains("mm past the axis")),
        "{texts:#?}"
    );
    assert!(
        texts[0].starts_with("T06 is too big for the bore here"),
        "{texts:#?}"
    );
}

/// Review 1128h (#3): a small boring bar (D 55°, 7.75 mm edges, Φ10 bar: 11.5 mm across)
/// fits the Ø16 drilled hole, but rapids on centre at X6: its far side, 8.5 mm past the axis,
/// meets the wall opposite. The cause says it runs too near the axis and where its point must
/// stay (above Ø7: 11.5 − 8), not that it is too big.
#[test]
fn a_tool_that_fits_the_bore_but_runs_near_the_axis_is_told_so() {
    let text = "G21 G40 G99\nT0808\nG97 S700 M03\nG00 X0. Z5.\nG01 Z-30. F0.1\nG00 Z5.\n\
                G00 X100. Z100.\nT0909\nG96 S150 M03\nG00 X20. Z2.\nG01 Z-25. F0.1\nX16.\n\
                G00 Z2.\nG00 X6.\nG00 Z-32.5\nG00 Z2.\nG00 X100. Z100.\nM30\n";
    let tools =
        "[[tool]]\nt = 8\nkind = \"drill\"\ndiameter = 16.0\npoint_angle = 118\nreach = 80.0\n\
                 [[tool]]\nt = 9\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.4\ntip = 2\n\
                 entering_angle = 93\nedge = 7.75\nshank = 10.0\n";
    let (tp, f) = Job::new(text, tools, bar(40.0, 60.0)).diagnosed();
    let c = certain_crashes_at(&tp, &f, 15)[0];
    let text = &c.cause.as_ref().unwrap().text;
    assert!(
        text.starts_with("T09 runs too near the axis here"),
        "{text}"
    );
    assert!(text.ends_with("keep its point above Ø7.0)"), "{text}");
}

/// Review 1128h (#1): a 3 mm blade's groove plunge written `G00 X40.` into a diameter T01
/// turned to Ø48. "Retract to Z2 first" plunged it in the air: the re-run kept exactly the
/// crash's 12 mm² (the groove), within what a cured crash may keep, and was offered as
/// checked. A rapid along one axis is a cut written G00: no split or retract is tried (and it
/// is not fed either, as it meets a turned surface, not the bar as it came).
#[test]
fn a_groove_plunged_at_rapid_is_not_moved_into_the_air() {
    let text = "G21 G99\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG01 X48. F0.2\nZ-40.\n\
                G00 X60. Z50.\nT0303\nG97 S600 M03\nG00 X52. Z-20.\nG00 X40.\nG04 X0.5\n\
                G00 X52.\nG00 X60. Z50.\nM30\n";
    let (tp, f) = Job::new(text, CNMG_AND_BLADE, bar(50.0, 60.0)).diagnosed();
    let c = certain_crashes_at(&tp, &f, 11)[0];
    assert!(c.remedy.is_none(), "{:?}", c.remedy);
}
