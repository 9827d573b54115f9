//! Endless loops end at once (issue 37): a jump back that finds the state the run had there
//! before is an alarm at the jump, naming what could have ended the loop; loops whose state
//! changes run on. And the move budget (`--max-moves`). The programs are written in the
//! shape of the two found ones: a shaft macro whose decrement was lost, a dispatcher whose
//! `GOTO` jumps back over a G90 cycle.

mod common;
use common::*;

use expander::{Control, Machine, Toolpath};

/// A block budget far below the default: without the loop guard these programs end by it,
/// with another message, so the tests fail fast instead of running for minutes.
const SMALL_BUDGET: usize = 200_000;

fn expand_on(src: &str, control: Control, macros: bool) -> Toolpath {
    let options = if control == Control::Haas {
        macro_b::Options::haas()
    } else {
        macro_b::Options::fanuc()
    };
    let program = gcode::parse_with(
        src,
        gcode::ReadOptions {
            macros: macros.then_some(options.dialect),
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| panic!("{}: {} ({})", e.span, e.message, e.help));
    let opts = expander::Options {
        macros: macros.then_some(options),
        max_blocks: SMALL_BUDGET,
        ..Default::default()
    };
    expander::expand(&program, &Machine::for_control(control), &opts)
}

/// Under `fanuc-a` with custom macro B.
fn expand(src: &str) -> Toolpath {
    expand_on(src, Control::FanucA, true)
}

/// The run ended with the endless-loop alarm at `line`, with every piece of `says` in its
/// message: the guard's alarm, at once (the block budget's names no state). No timed
/// assertion: the reproductions' times are in the closing note, measured outside tests.
fn assert_endless(tp: &Toolpath, line: u32, says: &[&str]) {
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    let a = &tp.alarms[0];
    assert_eq!((a.code, a.span.line), ("LS-LOOP", line), "{a:?}");
    assert!(a.message.starts_with("endless loop: "), "{}", a.message);
    for s in says {
        assert!(a.message.contains(s), "{s:?} missing from: {}", a.message);
    }
}

fn value(tp: &Toolpath, name: &str) -> Option<f64> {
    let found = tp.variables.iter().find(|(n, _)| n == name);
    found
        .unwrap_or_else(|| panic!("{name} not in {:?}", tp.variables))
        .1
}

/// The shaft macro with its `#31 = #31 - #7` lost: `WHILE [#31 GT #1]` comes back to the
/// same state each time round (#31 stays at the bar diameter, the tool at the same place).
const SHAFT_STEP_LOST: &str = "\
%
O0201 (SHAFT FROM ARGUMENTS - STEP LOST)
G21 G40 G99 ;
G28 U0. W0. ;
T0101 ;
G97 S1000 M03 ;
G65 P9200 A36. B25. C46. D1.5 F0.18 ;
G28 U0. W0. ;
M30 ;
O9200 (ROUGH DIA A OVER LENGTH B FROM BAR C)
IF [#1 EQ #0] GOTO 99 ;
#31 = #3 ;
WHILE [#31 GT #1] DO1 ;
IF [#31 LT #1] THEN #31 = #1 ;
G00 X#31 Z1. ;
G01 Z-#2 F#9 ;
G00 U1. ;
Z1. ;
END1 ;
M99 ;
N99 #3000 = 1 (A REQUIRED) ;
%
";

#[test]
fn a_while_loop_whose_step_was_lost_is_an_alarm_at_its_end() {
    let tp = expand(SHAFT_STEP_LOST);
    assert_endless(
        &tp,
        19,
        &[
            "this loop (back to line 13) repeats the same state every time round",
            "#31 (= 46) and #1 (= 36) never change",
        ],
    );
    // what ran until then is kept: two times round, 4 moves each (G28 from home is none)
    assert_eq!(tp.segments.len(), 2 * 4, "{:?}", tp.segments);
    // with the step the same program runs to its end
    let with_step = SHAFT_STEP_LOST.replace(
        "IF [#31 LT #1] THEN",
        "#31 = #31 - #7 ;\nIF [#31 LT #1] THEN",
    );
    let tp = expand(&with_step);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
}

/// A dispatcher whose `GOTO 90` was put after `N90` with a G90 cycle between: G28 and the
/// cycle leave the same state every time.
const DISPATCHER_GOTO_BACK: &str = "\
%
O3101 (JOB SELECTOR)
#501 = 1 ;
G21 G40 G99 ;
G28 U0. W0. ;
IF [#501 EQ 1] GOTO 10 ;
IF [#501 EQ 2] GOTO 20 ;
#3000 = 1 (#501 MUST BE 1 OR 2) ;
N10 (TURN DIA 36) ;
T0101 ;
G97 S900 M03 ;
G00 X48. Z2. ;
G90 X44. Z-25. F0.2 ;
X40. ;
X36. ;
GOTO 90 ;
N20 (FACE) ;
T0101 ;
G00 X50. Z0. ;
G01 X-1.6 F0.15 ;
N90 G28 U0. W0. ;
G90 X44. Z-25. F0.2 ;
GOTO 90 ;
M05 ;
M30 ;
%
";

#[test]
fn a_goto_back_over_a_cycle_is_an_alarm_at_the_goto() {
    let tp = expand(DISPATCHER_GOTO_BACK);
    assert_endless(
        &tp,
        23,
        &[
            "this loop (back to line 21)",
            "repeats the same state",
            "nothing in it can end it",
        ],
    );
    assert!(tp.alarms[0].help.contains("way out"), "{:?}", tp.alarms[0]);
    // at once: the 14 blocks before the loop and a few times round it, not the block
    // budget's 10⁷
    assert!(tp.blocks < 14 + 3 * 4, "{} blocks", tp.blocks);
}

/// A counter to 1 000 whose body moves the tool to the same places every time runs to
/// completion: only the counter changes, and that is enough.
#[test]
fn a_counted_loop_over_the_same_moves_runs_to_completion() {
    let src = "\
G21 G99 T0101 M03 S800 ;
G00 X52. Z2. ;
#1 = 0 ;
WHILE [#1 LT 1000] DO1 ;
G01 X50. F0.2 ;
G00 X52. ;
#1 = #1 + 1 ;
END1 ;
N10 #2 = [#2 + 1] ;
IF [#2 LT 1000] GOTO 10 ;
M30 ;
";
    let tp = expand(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(value(&tp, "#1"), Some(1000.0));
    assert_eq!(value(&tp, "#2"), Some(1000.0));
    assert_eq!(tp.segments.len(), 1 + 2 * 1000);
}

/// A loop whose condition reads the position runs while the tool moves, and is an alarm
/// when the move was lost (the tool stays where it is).
#[test]
fn a_loop_on_the_position_runs_while_the_tool_moves() {
    let moving = "G00 X40. Z2. ;\nN10 G01 W-1. F0.2 ;\nIF [#5002 GT -20.] GOTO 10 ;\nM30 ;\n";
    let tp = expand(moving);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(tp.segments.len(), 1 + 22);
    let tp = expand(&moving.replace("W-1.", "W0."));
    assert_endless(&tp, 3, &["#5002 (= 2) never changes"]);
}

/// Loops whose counter lives in the machine, not in a macro variable, run on: the parts
/// counter `#3901`, the feed read back through `#4109`.
#[test]
fn loops_counting_in_the_machine_state_run_on() {
    let parts = "N10 #3901 = #3901 + 1 ;\nIF [#3901 LT 50] GOTO 10 ;\nM30 ;\n";
    let tp = expand(parts);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(tp.blocks, 2 * 50 + 1);
    let feed = "G99 F0.1 ;\nN10 F[#4109 + 0.01] ;\nIF [#4109 LT 0.3] GOTO 10 ;\nM30 ;\n";
    let tp = expand(feed);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(tp.blocks, 1 + 2 * 20 + 1);
}

/// A state that comes back every second time round (a variable and the tool toggling) is
/// caught too.
#[test]
fn a_state_that_comes_back_every_other_time_is_caught() {
    let src =
        "#1 = 0 ;\nN10 #1 = 1 - #1 ;\nG00 X[40. + #1 * 2.] Z2. ;\nIF [#2 LT 5] GOTO 10 ;\nM30 ;\n";
    let tp = expand(src);
    assert_endless(
        &tp,
        4,
        &[
            "comes back to the same state every 2 times round",
            "#2 (vacant) comes back to the same value",
        ],
    );
}

/// A loop that counts for 3 000 times round and then gets stuck is caught within the
/// guard's longest period (1 024 times round) of getting stuck, long before the budget.
#[test]
fn a_loop_stuck_after_a_long_honest_run_is_caught_soon() {
    let src =
        "#1 = 0 ;\nWHILE [#2 EQ #0] DO1 ;\nIF [#1 LT 3000] THEN #1 = #1 + 1 ;\nEND1 ;\nM30 ;\n";
    let tp = expand(src);
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    let a = &tp.alarms[0];
    assert_eq!((a.code, a.span.line), ("LS-LOOP", 4), "{a:?}");
    assert!(
        a.message.contains("#2 (vacant) never changes"),
        "{}",
        a.message
    );
    assert_eq!(value(&tp, "#1"), Some(3000.0));
    let rounds = tp.blocks / 3;
    assert!((3000..3000 + 2 * 1024 + 2).contains(&rounds), "{rounds}");
}

/// A macro call in a loop: the call level comes and goes, the caller's counter decides.
#[test]
fn g65_calls_in_a_loop_run_on_while_the_counter_counts() {
    let src = "\
O0001 ;
#1 = 0 ;
N10 G65 P9001 A5. ;
#1 = #1 + 1 ;
IF [#1 LT 20] GOTO 10 ;
M30 ;
O9001 ;
#2 = #1 * 2. ;
G00 X[40. + #2] Z2. ;
M99 ;
";
    let tp = expand(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(value(&tp, "#1"), Some(20.0));
    let tp = expand(&src.replace("#1 = #1 + 1 ;\n", ""));
    assert_endless(&tp, 4, &["#1 (= 0) never changes"]);
}

/// Each repeat of `M98 … L` runs its loops afresh from the same state (the repeat count
/// is the state that differs): no alarm.
#[test]
fn repeats_of_a_subprogram_meet_the_same_states_and_run_on() {
    let src = "\
O0001 ;
G00 X40. Z2. ;
M98 P2 L3 ;
M30 ;
O0002 ;
#100 = 0 ;
WHILE [#100 LT 3] DO1 ;
G00 W-1. ;
#100 = #100 + 1 ;
END1 ;
G00 W3. ;
M99 ;
";
    let tp = expand(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(tp.segments.len(), 1 + 3 * 4);
}

/// Field run 4: a bar-fed job ends its main program with `M99` (the control starts the
/// next part: dialects.md §5.8 for FANUC, §3.6 for Haas). Simulated once with the warning
/// LS-M99-MAIN under every control, not an alarm (it stopped FANUC and GSK programs).
#[test]
fn m99_ending_the_main_program_runs_it_once_under_every_control() {
    let src = "O1001 ;\nG00 X24. Z2. ;\nG01 Z-10. F0.2 ;\nG00 X26. ;\nZ2. ;\nM99 ;\n";
    for control in [
        Control::FanucA,
        Control::FanucB,
        Control::Gsk980,
        Control::Haas,
    ] {
        let tp = expand_on(src, control, false);
        assert!(tp.alarms.is_empty(), "{control:?}: {:?}", tp.alarms);
        assert_eq!(tp.segments.len(), 4, "{control:?}");
        let warned: Vec<_> = tp
            .warnings
            .iter()
            .filter(|w| w.code == "LS-M99-MAIN")
            .collect();
        assert_eq!(warned.len(), 1, "{control:?}: {:?}", tp.warnings);
        assert_eq!(warned[0].span.line, 6);
    }
}

/// Without custom macro B: FANUC `M99 P` back to the caller's call, and a Haas `M99 P`
/// branch in the main program, are alarms at the M99.
#[test]
fn m99_p_loops_without_macro_b_are_alarms_at_the_m99() {
    let fanuc = "O0001 ;\nN1 M98 P2 ;\nM30 ;\nO0002 ;\nG00 W1. ;\nG00 W-1. ;\nM99 P1 ;\n";
    let tp = expand_on(fanuc, Control::FanucA, false);
    assert_endless(&tp, 7, &["back to line 2", "nothing in it can end it"]);
    let haas =
        "O00001 ;\nG00 X40. Z2. ;\nN10 G01 Z-10. F0.2 ;\nG00 X42. ;\nZ2. ;\nX40. ;\nM99 P10 ;\n";
    let tp = expand_on(haas, Control::Haas, false);
    assert_endless(&tp, 7, &["back to line 3"]);
}

/// The reproductions through the command line with the default budgets: the alarm at the
/// jump's line, exit 1, in well under a second (a debug build on a shared machine gets
/// room).
#[test]
fn the_reproductions_end_at_once_on_the_command_line() {
    for (name, text, place) in [
        ("shaft.nc", SHAFT_STEP_LOST, "shaft.nc:19:1"),
        ("dispatcher.nc", DISPATCHER_GOTO_BACK, "dispatcher.nc:23:1"),
    ] {
        let (_dir, prog) = temp_program(name, text.as_bytes());
        let out = latsim(&["check", prog.to_str().unwrap(), "--control", "fanuc-a"]);
        assert_eq!(out.code, 1, "{}", out.stderr);
        for s in [place, "LS-LOOP", "endless loop"] {
            assert!(
                out.stderr.contains(s),
                "{s:?} missing from:\n{}",
                out.stderr
            );
        }
    }
}

/// A batch in which one program loops for ever: the others get their verdicts, the loop
/// its alarm, exit 1.
#[test]
fn a_batch_with_an_endless_program_gives_every_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| std::fs::write(dir.path().join(name), text).unwrap();
    write("loop.nc", DISPATCHER_GOTO_BACK);
    let ok = "G21 G99 T0101 M03 S800 ;\nG00 X52. Z2. ;\nG01 X46. F0.2 ;\nZ-20. ;\nG00 X52. ;\nZ2. ;\nM30 ;\n";
    write("ok1.nc", ok);
    write("ok2.nc", &ok.replace("X46.", "X48."));
    let out_dir = tempfile::tempdir().unwrap();
    let out = latsim(&[
        "run",
        dir.path().to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--stock",
        "50x60",
        "--reports",
        "json",
        "--out",
        out_dir.path().to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("loop.nc: ALARM"), "{}", out.stdout);
    for ok in ["ok1.nc: ", "ok2.nc: "] {
        let line = out.stdout.lines().find(|l| l.starts_with(ok));
        let line = line.unwrap_or_else(|| panic!("{ok} missing:\n{}", out.stdout));
        assert!(!line.contains("ALARM"), "{line}");
    }
    let report = read(&out_dir.path().join("loop.json"));
    assert!(report.contains("\"LS-LOOP\""), "{report}");
    // the guard's alarm (at once), not the block budget's (after 10⁷ blocks)
    assert!(report.contains("repeats the same state"), "{report}");
}

/// `--max-moves N` (`run` and `check`): the alarm at the block whose move went past N,
/// exit 1, the N moves made until then simulated and reported.
#[test]
fn the_move_budget_ends_a_run_at_the_block_that_exceeded_it() {
    let src = "O0001 ;\nG00 X48. Z0.5 M03 S800 ;\nM98 P2 L9999 ;\nM30 ;\nO0002 ;\nG01 W-1. F0.2 ;\nG00 W1. ;\nM99 ;\n";
    let (_dir, prog) = temp_program("long.nc", src.as_bytes());
    let out = latsim(&[
        "check",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--max-moves",
        "101",
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    for s in [
        "long.nc:6:1",
        "LS-TOO-LONG",
        "more than 101 moves (the move budget)",
        "--max-moves",
    ] {
        assert!(
            out.stderr.contains(s),
            "{s:?} missing from:\n{}",
            out.stderr
        );
    }
    assert!(out.stdout.contains("101 segments"), "{}", out.stdout);
    let json = prog.with_extension("json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--stock",
        "50x60",
        "--max-moves",
        "100",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    let report: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    assert_eq!(report["verdict"], "alarm");
    assert_eq!(report["segments"], 100);
    assert_eq!(report["alarms"][0]["code"], "LS-TOO-LONG");
    assert_eq!(report["alarms"][0]["line"], 7);
    assert!(report["removed_area_mm2"].as_f64().unwrap() > 0.0);
}
