//! Two calls of spec/dialects.md: Haas `M98 (path/O00001.nc)` (§3.6: the file next to the main
//! program, else an alarm) and custom macro B's modal call `G66 P… args` / `G67` (§5.5: the
//! macro runs after each later block that moves an axis). Toolpaths computed by hand.

mod common;
use common::*;
use expander::{Control, Machine, Motion, Toolpath};
use std::sync::Arc;

/// The moves as (kind, z0, x0, z1, x1, line), X as a diameter, rounded to 1 µm.
fn moves(tp: &Toolpath) -> Vec<(char, f64, f64, f64, f64, u32)> {
    let r = |v: f64| (v * 1e3).round() / 1e3;
    tp.segments
        .iter()
        .map(|s| {
            let kind = if s.motion == Motion::Rapid { 'R' } else { 'F' };
            let (a, b) = (s.from, s.to);
            (
                kind,
                r(a.z),
                r(2.0 * a.r),
                r(b.z),
                r(2.0 * b.r),
                s.span.line,
            )
        })
        .collect()
}

/// [`moves`] without the lines: two programs that write the same path differently.
fn path(tp: &Toolpath) -> Vec<(char, f64, f64, f64, f64)> {
    moves(tp)
        .into_iter()
        .map(|(k, z0, x0, z1, x1, _)| (k, z0, x0, z1, x1))
        .collect()
}

// ---------------------------------------------------------------------------------------
// G66 / G67

/// Read and run with custom macro B on under `control`.
fn run_macro(src: &str, control: Control) -> Toolpath {
    let options = match control {
        Control::Haas => macro_b::Options::haas(),
        _ => macro_b::Options::fanuc(),
    };
    let program = gcode::parse_with(
        src,
        gcode::ReadOptions {
            macros: Some(options.dialect),
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| panic!("{}: {}", e.span, e.message));
    let opts = expander::Options {
        macros: Some(options),
        ..Default::default()
    };
    expander::expand(&program, &Machine::for_control(control), &opts)
}

fn fanuc(src: &str) -> Toolpath {
    run_macro(src, Control::FanucA)
}

fn clean(src: &str) -> Toolpath {
    let tp = fanuc(src);
    assert!(tp.alarms.is_empty(), "alarms: {:?}", tp.alarms);
    tp
}

/// The first alarm: (code, line, column, message).
fn first_alarm(tp: &Toolpath) -> (&str, u32, u32, &str) {
    let a = tp.alarms.first().expect("an alarm");
    (a.code, a.span.line, a.span.column, a.message.as_str())
}

/// O9100: feed W by argument W (#23), then rapid back up 2 mm on the diameter.
const O9100: &str = "O9100
G01 W#23 F0.2
G00 U2.
M99
";

const G66_TWO_RAPIDS: &str = "O0001
G21 G99 T0101
G00 X40. Z2.
G66 P9100 W-1.
G00 X38.
X36.
G67
G00 X34.
M30
";

/// G66 sets the call, and does not move; each of the two rapids is followed by the macro's
/// feed W-1 and its rapid U2; the macro's own moves (lines 11, 12) do not call it again;
/// after G67 the rapid to X34 stands alone.
#[test]
fn g66_calls_the_macro_after_each_move_until_g67() {
    let tp = clean(&format!("{G66_TWO_RAPIDS}{O9100}"));
    let home = (250.0, 150.0);
    assert_eq!(
        moves(&tp),
        vec![
            ('R', home.1, home.0, 2.0, 40.0, 3),
            ('R', 2.0, 40.0, 2.0, 38.0, 5),
            ('F', 2.0, 38.0, 1.0, 38.0, 11),
            ('R', 1.0, 38.0, 1.0, 40.0, 12),
            ('R', 1.0, 40.0, 1.0, 36.0, 6),
            ('F', 1.0, 36.0, 0.0, 36.0, 11),
            ('R', 0.0, 36.0, 0.0, 38.0, 12),
            ('R', 0.0, 38.0, 0.0, 34.0, 8),
        ]
    );
}

/// The arguments are evaluated at the G66 block (as G65's): changing #1 afterwards does not
/// change the call; L2 runs the macro twice after each move.
#[test]
fn g66_arguments_are_taken_at_the_g66_block_and_l_repeats() {
    let tp = clean(&format!(
        "O0001
G21 G99 T0101
G00 X40. Z2.
#1 = -1.
G66 P9100 L2 W#1
#1 = -5.
G00 X38.
G67
M30
{O9100}"
    ));
    assert_eq!(
        moves(&tp)[1..],
        [
            ('R', 2.0, 40.0, 2.0, 38.0, 7),
            ('F', 2.0, 38.0, 1.0, 38.0, 11),
            ('R', 1.0, 38.0, 1.0, 40.0, 12),
            ('F', 1.0, 40.0, 0.0, 40.0, 11),
            ('R', 0.0, 40.0, 0.0, 42.0, 12),
        ]
    );
}

/// Moves inside the macro the modal call runs do not trigger it, also in a subprogram the
/// macro calls; the moves of a subprogram the main program calls do; blocks that move no
/// axis (F, M, a dwell, a macro statement) do not.
#[test]
fn only_moves_outside_the_called_macro_trigger_it() {
    let tp = clean(
        "O0001
G21 G99 T0101
G00 X40. Z2.
G66 P9200
F0.1
#5 = 1.
G04 X1.
M98 P1000
G67
M30
O1000
G01 Z0.
M99
O9200
G01 U-2.
M98 P2000
M99
O2000
G00 U2.
M99
",
    );
    assert_eq!(
        moves(&tp)[1..],
        [
            ('F', 2.0, 40.0, 0.0, 40.0, 12),
            ('F', 0.0, 40.0, 0.0, 38.0, 15),
            ('R', 0.0, 38.0, 0.0, 40.0, 19),
        ]
    );
}

/// The modal call counts toward the call nesting limit (FANUC: 4 levels): a move four
/// subprograms deep calls the macro at level five, PS077 at that move.
#[test]
fn the_modal_call_counts_toward_the_nesting_limit() {
    let nest = |levels: u32| {
        let mut src = String::from(
            "O0001\nG21 G99 T0101\nG00 X40. Z2.\nG66 P9100 W-1.\nM98 P1001\nG67\nM30\n",
        );
        for k in 1..=levels {
            let next = if k < levels {
                format!("M98 P{}\n", 1001 + k)
            } else {
                "G00 X38.\n".to_string()
            };
            src.push_str(&format!("O{}\n{next}M99\n", 1000 + k));
        }
        src + O9100
    };
    let tp = clean(&nest(3));
    assert_eq!(path(&tp)[2], ('F', 2.0, 38.0, 1.0, 38.0));
    let tp = fanuc(&nest(4));
    // O1004 is lines 17-19: the move at line 18
    let (code, line, _, message) = first_alarm(&tp);
    assert_eq!((code, line), ("PS077", 18), "{message}");
}

/// Clear alarms at line and column: a second G66 in force, G67 with other words, a moving
/// block that also ends the program, G66 without P.
#[test]
fn bad_modal_calls_are_alarms() {
    let cases: [(&str, (&str, u32, u32)); 4] = [
        (
            "G21 G99\nG66 P9100 W-1.\nG00 X30.\nG66 P9100 W-2.\nM30\n",
            ("LS-NOT-SIMULATED", 4, 1),
        ),
        ("G21 G99\nG66 P9100 W-1.\nG67 X30.\nM30\n", ("PS0115", 3, 5)),
        (
            "G21 G99\nG66 P9100 W-1.\nG00 X30. M30\n",
            ("LS-NOT-SIMULATED", 3, 1),
        ),
        ("G21 G99\nG66 W-1.\nM30\n", ("PS078", 2, 1)),
    ];
    for (main, want) in cases {
        let tp = fanuc(&format!("{main}{O9100}"));
        let (code, line, column, message) = first_alarm(&tp);
        assert_eq!((code, line, column), want, "{main}: {message}");
    }
}

/// Without custom macro B (gsk980 by default) G66 stays what it was: not a G code.
#[test]
fn without_macro_b_g66_is_not_a_g_code() {
    let program = gcode::parse("G21 G98\nG66 P9100 W-1.\nG00 X30.\nM30\n").unwrap();
    let tp = expander::expand(
        &program,
        &Machine::for_control(Control::Gsk980),
        &Default::default(),
    );
    let (code, line, column, message) = first_alarm(&tp);
    assert_eq!((code, line, column), ("PS010", 2, 1), "{message}");
    assert!(message.contains("G66"), "{message}");
}

// ---------------------------------------------------------------------------------------
// Haas M98 (path)

/// The reader keeps the comment after M98 for those blocks only (a side table of the O
/// program), the first comment after the M98.
#[test]
fn the_reader_keeps_the_comment_after_m98_only() {
    let p = gcode::parse(
        "(HEAD)\nG00 X1. (NOT A CALL)\n(BEFORE) M98 ( subs/a.nc ) L2 (SECOND)\nM98P1(x)\n",
    )
    .unwrap();
    let texts: Vec<(usize, &str, u32, u32)> = p.programs[0]
        .call_texts
        .iter()
        .map(|c| (c.block, c.text.as_str(), c.span.line, c.span.column))
        .collect();
    assert_eq!(texts, vec![(1, "subs/a.nc", 3, 14), (2, "x", 4, 6)]);
    assert_eq!(p.programs[0].call_text(0), None);
    assert_eq!(p.programs[0].call_text(2).unwrap().text, "x");
}

/// A library of files held in memory, as the CLI's folders would hand them out.
struct Files(Vec<(&'static str, &'static str)>);

impl expander::Library for Files {
    fn find(&self, _: u32) -> Result<Option<Arc<gcode::Program>>, String> {
        Ok(None)
    }
    fn has_folders(&self) -> bool {
        false
    }
    fn file(&self, path: &str) -> Result<Arc<gcode::Program>, String> {
        let (_, text) = self
            .0
            .iter()
            .find(|(name, _)| *name == path)
            .ok_or_else(|| format!("no file {path}"))?;
        gcode::parse(text).map(Arc::new).map_err(|e| e.message)
    }
}

fn haas(src: &str, files: Vec<(&'static str, &'static str)>) -> Toolpath {
    let opts = expander::Options {
        library: Some(expander::LibraryRef(Arc::new(Files(files)))),
        ..Default::default()
    };
    let program = gcode::parse(src).unwrap();
    expander::expand(&program, &Machine::for_control(Control::Haas), &opts)
}

const SUB: &str = "O00101\nG01 W-1. F0.2\nU-2.\nM99\n";

/// `M98 (sub.nc) L2` runs the file's program twice: the same path as its blocks written out.
#[test]
fn m98_path_runs_the_file_like_its_blocks_inlined() {
    let called = haas(
        "G21 G99\nT101\nG00 X40. Z2.\nM98 (sub.nc) L2\nG00 X100. Z100.\nM30\n",
        vec![("sub.nc", SUB)],
    );
    assert!(called.alarms.is_empty(), "{:?}", called.alarms);
    let inlined = haas(
        "G21 G99\nT101\nG00 X40. Z2.\nG01 W-1. F0.2\nU-2.\nW-1.\nU-2.\nG00 X100. Z100.\nM30\n",
        vec![],
    );
    assert_eq!(path(&called), path(&inlined));
    assert_eq!(
        path(&called)[1..5],
        [
            ('F', 2.0, 40.0, 1.0, 40.0),
            ('F', 1.0, 40.0, 1.0, 38.0),
            ('F', 1.0, 38.0, 0.0, 38.0),
            ('F', 0.0, 38.0, 0.0, 36.0),
        ]
    );
    // the segments made by the file carry its lines
    assert_eq!(moves(&called)[1].5, 2);
}

/// A P word wins over a comment (`M98 P1000 (ROUGHING)` calls O1000); without P a
/// comment that names no file is an alarm at the M98; other controls keep "M98 without P".
#[test]
fn m98_comment_only_calls_without_p_and_only_under_haas() {
    let tp = haas(
        "G21 G99\nG00 X40. Z2.\nM98 P1000 (ROUGHING)\nM30\nO1000\nG01 W-1. F0.2\nM99\n",
        vec![],
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(path(&tp)[1], ('F', 2.0, 40.0, 1.0, 40.0));

    let tp = haas("G21 G99\n  M98 (ROUGHING)\nM30\n", vec![]);
    let (code, line, column, message) = first_alarm(&tp);
    assert_eq!((code, line, column), ("PS078", 2, 3), "{message}");
    assert!(message.contains("M98 (ROUGHING)"), "{message}");

    let program = gcode::parse("G21 G99\nM98 (sub.nc)\nM30\n").unwrap();
    let opts = expander::Options {
        library: Some(expander::LibraryRef(Arc::new(Files(vec![("sub.nc", SUB)])))),
        ..Default::default()
    };
    let tp = expander::expand(&program, &Machine::for_control(Control::FanucA), &opts);
    let (code, line, _, message) = first_alarm(&tp);
    assert_eq!((code, line, message), ("PS078", 2, "M98 without P"));
}

/// Through the CLI: the file is found next to the main program (in a subfolder too, from
/// any working folder); a missing file, a path that leaves the folder, and a file that does
/// not parse are alarms at the M98's line and column.
#[test]
fn m98_path_through_the_cli() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(&p, text).unwrap();
        p
    };
    write("subs/O00101.nc", SUB);
    write("bad.nc", "O00102\nG01 W-1. F0.2 \"quoted\"\nM99\n");
    let expand = |name: &str, text: &str| {
        let main = write(name, text);
        latsim(&["expand", main.to_str().unwrap(), "--control", "haas"])
    };
    let main = "%\nO00100\nG21 G99\nT101\nG00 X40. Z2.\n";
    let ok = expand("ok.nc", &format!("{main}M98 (subs/O00101.nc) L2\nM30\n%\n"));
    assert_eq!(ok.code, 0, "{}", ok.stderr);
    let inlined = expand(
        "inlined.nc",
        &format!("{main}G01 W-1. F0.2\nU-2.\nW-1.\nU-2.\nM30\n%\n"),
    );
    let rows = |o: &common::Out| -> Vec<String> {
        o.stdout
            .lines()
            .map(|l| l.split(',').skip(2).collect::<Vec<_>>().join(","))
            .collect()
    };
    assert_eq!(rows(&ok), rows(&inlined));
    assert_eq!(rows(&ok).len(), 6, "{}", ok.stdout);

    for (name, call, needle) in [
        ("missing.nc", "M98 (subs/O00999.nc)", "no file"),
        (
            "escape.nc",
            "M98 (../O00101.nc)",
            "leaves the main program's folder",
        ),
        ("absolute.nc", "M98 (/etc/hostname)", "absolute path"),
        ("unparsed.nc", "M98 (bad.nc)", "bad.nc:2:15"),
    ] {
        let o = expand(name, &format!("{main}  {call}\nM30\n%\n"));
        assert_eq!(o.code, 1, "{name}: {}", o.stderr);
        assert!(o.stderr.contains("PS078"), "{name}: {}", o.stderr);
        assert!(
            o.stderr.contains(&format!("{name}:6:3")),
            "{name}: {}",
            o.stderr
        );
        assert!(o.stderr.contains(needle), "{name}: {}", o.stderr);
    }
}
