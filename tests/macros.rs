//! Custom macro B through the reader and the interpreter (spec/dialects.md §5, §7 T6 and T7,
//! issue 12): the worked examples with their numbers, the vacancy and precedence tables row
//! by row, calls and system variables, and bad input as clear alarms at line and column.

mod common;
use common::*;

use expander::{Control, Machine, Motion, Toolpath};

fn read_macro(src: &str, dialect: macro_b::Dialect) -> gcode::Program {
    gcode::parse_with(
        src,
        gcode::ReadOptions {
            macros: Some(dialect),
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| panic!("{}: {} ({})", e.span, e.message, e.help))
}

fn expand_with(src: &str, control: Control, options: macro_b::Options) -> Toolpath {
    let program = read_macro(src, options.dialect);
    let opts = expander::Options {
        macros: Some(options),
        ..Default::default()
    };
    expander::expand(&program, &Machine::for_control(control), &opts)
}

/// Read and run under `fanuc-a` (custom macro B on, FANUC 0i rules).
fn run(src: &str) -> Toolpath {
    expand_with(src, Control::FanucA, macro_b::Options::fanuc())
}

/// [`run`], asserting no alarm.
fn clean(src: &str) -> Toolpath {
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "alarms: {:?}", tp.alarms);
    tp
}

/// The reported final value of a variable; one the run neither read nor set is not
/// reported, and vacant.
fn var(tp: &Toolpath, name: &str) -> Option<f64> {
    tp.variables
        .iter()
        .find(|(n, _)| n == name)
        .and_then(|v| v.1)
}

/// The moves as (z0, x0, z1, x1, line), X as a diameter.
fn moves(tp: &Toolpath) -> Vec<(f64, f64, f64, f64, u32)> {
    let r = |v: f64| (v * 1e6).round() / 1e6;
    tp.segments
        .iter()
        .map(|s| {
            (
                r(s.from.z),
                r(2.0 * s.from.r),
                r(s.to.z),
                r(2.0 * s.to.r),
                s.span.line,
            )
        })
        .collect()
}

const T6: &str = "O0600
G21 G99 T0101 ;
G97 S800 M03 ;
#1 = 50. ;
#2 = 40. ;
#3 = 2. ;
G00 X52. Z2. ;
WHILE [#1 GT #2] DO1 ;
#1 = #1 - #3 ;
IF [#1 LT #2] THEN #1 = #2 ;
G00 X#1 ;
G01 Z-25. F0.2 ;
G00 U2. ;
Z2. ;
END1 ;
#4 = #0 ;
G00 X#4 Z5. ;
G00 X100. Z100. ;
M30 ;
";

#[test]
fn t6_loop_and_a_vacant_address() {
    let tp = clean(T6);
    let m = moves(&tp);
    // five passes at X48 … X40, each: rapid X, feed Z-25, rapid X+2, rapid Z2 — every
    // move names its line in the loop
    let mut at = 1;
    let mut x_prev = 52.0;
    for x in [48.0, 46.0, 44.0, 42.0, 40.0] {
        assert_eq!(m[at], (2.0, x_prev, 2.0, x, 11), "pass at X{x}");
        assert_eq!(m[at + 1], (2.0, x, -25.0, x, 12));
        assert_eq!(m[at + 2], (-25.0, x, -25.0, x + 2.0, 13));
        assert_eq!(m[at + 3], (-25.0, x + 2.0, 2.0, x + 2.0, 14));
        assert_eq!(tp.segments[at + 1].motion, Motion::Feed);
        x_prev = x + 2.0;
        at += 4;
    }
    // G00 X#4 Z5. with #4 vacant moves only Z: (42, 2) → (42, 5)
    assert_eq!(m[at], (2.0, 42.0, 5.0, 42.0, 17));
    assert_eq!(m.len(), at + 2);
    // 5 loop iterations: the body lines ran 5 times, the WHILE 6
    for line in 9..=15 {
        assert!(tp.line_counts.contains(&(line, 5)), "{:?}", tp.line_counts);
    }
    assert!(tp.line_counts.contains(&(8, 6)), "{:?}", tp.line_counts);
    assert_eq!(var(&tp, "#1"), Some(40.0));
    assert_eq!(var(&tp, "#4"), None);
}

#[test]
fn t7_arithmetic_functions_vacancy() {
    let tp = clean(
        "#1 = 2 + 3 * 4 ;
#2 = [2 + 3] * 4 ;
#3 = #0 + 5 ;
#4 = #0 * 10 ;
#5 = FIX[-1.7] ;
#6 = FUP[-1.2] ;
#7 = ROUND[2.5] ;
#8 = ATAN[1]/[-1] ;
#9 = SQRT[16] + ABS[-3] ;
IF [#10 EQ #0] THEN #11 = 1 ;
IF [#10 EQ 0] THEN #12 = 1 ;
IF [#10 GE 0] THEN #13 = 1 ;
G00 X#1 Z#2 ;
G00 X#12 Z[#13 + #3] ;
M30 ;
",
    );
    let want: Vec<(String, Option<f64>)> = [
        ("#1", Some(14.0)),
        ("#2", Some(20.0)),
        ("#3", Some(5.0)),
        ("#4", Some(0.0)),
        ("#5", Some(-1.0)),
        ("#6", Some(-2.0)),
        ("#7", Some(3.0)),
        ("#8", Some(135.0)),
        ("#9", Some(7.0)),
        ("#10", None),
        ("#11", Some(1.0)),
        ("#12", None),
        ("#13", Some(1.0)),
    ]
    .into_iter()
    .map(|(n, v)| (n.to_string(), v))
    .collect();
    assert_eq!(tp.variables, want);
    let m = moves(&tp);
    assert_eq!((m[0].2, m[0].3), (20.0, 14.0));
    assert_eq!(m[1], (20.0, 14.0, 6.0, 14.0, 14));
    assert_eq!(m.len(), 2);
}

/// spec/dialects.md §5.2, the vacant-variable table, row by row.
#[test]
fn vacancy_table_rows() {
    let tp = clean(
        "#1 = #0 ;
#2 = #1 ;
#3 = #0 + 1 ;
#4 = 1 + #0 ;
#5 = #0 + #0 ;
#6 = #0 * 10 ;
#7 = #0 - #0 ;
#8 = #0 / 5 ;
#9 = SIN[#0] ;
#10 = ABS[#0] ;
IF [#0 EQ #0] THEN #11 = 1 ;
IF [0 EQ #0] THEN #12 = 1 ;
IF [#0 NE 0] THEN #13 = 1 ;
IF [#0 GE 0] THEN #14 = 1 ;
IF [#0 GT 0] THEN #15 = 1 ;
IF [0 LE #0] THEN #16 = 1 ;
IF [#20] THEN #17 = 1 ;
#21 = 0 ;
IF [#21] THEN #18 = 1 ;
#22 = 2 ;
IF [#22] THEN #19 = 1 ;
G00 X30. Z10. ;
G00 X#1 Z5. ;
G00 X[#1 + 10] ;
M30 ;
",
    );
    let rows = [
        ("#1", None),       // #1 = #0: vacant
        ("#2", None),       // #2 = #1 (#1 vacant): vacant
        ("#3", Some(1.0)),  // #0 + 1
        ("#4", Some(1.0)),  // 1 + #0
        ("#5", Some(0.0)),  // #0 + #0
        ("#6", Some(0.0)),  // #0 * 10
        ("#7", Some(0.0)),  // #0 - #0
        ("#8", Some(0.0)),  // #0 / 5
        ("#9", Some(0.0)),  // SIN[#0]: the function of 0
        ("#10", Some(0.0)), // ABS[#0]
        ("#11", Some(1.0)), // #0 EQ #0 true
        ("#12", None),      // 0 EQ #0 false
        ("#13", Some(1.0)), // #0 NE 0 true
        ("#14", Some(1.0)), // #0 GE 0 true
        ("#15", None),      // #0 GT 0 false
        ("#16", Some(1.0)), // 0 LE #0 true
        ("#17", None),      // [#20], vacant: false
        ("#18", None),      // [0]: false
        ("#19", Some(1.0)), // [2]: true
    ];
    for (name, want) in rows {
        assert_eq!(var(&tp, name), want, "{name}");
    }
    let m = moves(&tp);
    // G00 X#1 Z5. with #1 vacant is G00 Z5.; X[#1 + 10] is X10
    assert_eq!(m[1], (10.0, 30.0, 5.0, 30.0, 23));
    assert_eq!(m[2], (5.0, 30.0, 5.0, 10.0, 24));
    // 5 / #0: division by zero, an alarm at the expression
    let tp = run("#1 = 5 / #0 ;\nM30 ;\n");
    assert_eq!(tp.alarms.len(), 1);
    assert_eq!(tp.alarms[0].code, "PS0112");
    assert_eq!((tp.alarms[0].span.line, tp.alarms[0].span.column), (1, 6));
}

/// spec/dialects.md §5.3, the precedence table, level by level, and §5.4's functions.
#[test]
fn precedence_table_rows_and_functions() {
    let cases: [(&str, f64); 22] = [
        ("[2 + 3] * 4", 20.0), // level 1: brackets first
        ("-2 * 3", -6.0),      // level 2: unary minus before *
        ("SQRT[16] * 2", 8.0), // level 2: functions before *
        ("2 + 3 * 4", 14.0),   // level 3 over level 4
        ("10 - 6 / 2", 7.0),   // / over -
        ("7 AND 3 + 1", 4.0),  // AND (3) over + (4): [7 AND 3] + 1
        ("1 OR 2 * 2", 5.0),   // * (3) over OR (4): 1 OR 4
        ("6 XOR 3", 5.0),      // bitwise on integers
        ("1 + 1 EQ 2", 1.0),   // level 5 last: [1 + 1] EQ 2
        ("[1 LT 5]", 1.0),     // a comparison as a value
        ("8 / 4 / 2", 1.0),    // equal levels left to right
        ("10 - 3 - 2", 5.0),   // left to right
        ("FIX[1.2]", 1.0),     // §5.4
        ("FIX[-1.2]", -1.0),   //
        ("FUP[1.2]", 2.0),     //
        ("FUP[-1.2]", -2.0),   // away from zero, not ceil
        ("ROUND[1.714]", 2.0), //
        ("ROUND[3.54]", 4.0),  //
        ("ROUND[-2.5]", -3.0), // halves away from zero
        ("SIN[30]", 0.5),      // degrees
        ("ATAN[1,-1]", 135.0), // 0 ≤ θ < 360
        ("ACOS[-1] + ASIN[1]", 270.0),
    ];
    let mut src = String::new();
    for (i, (e, _)) in cases.iter().enumerate() {
        src.push_str(&format!("#{} = {e} ;\n", 100 + i));
    }
    src.push_str("IF [[#100 GT 3] AND [#103 LT 20]] THEN #130 = 1 ;\n");
    src.push_str("IF [[#100 GT 30] OR [#103 LT 10]] THEN #131 = 1 ;\nM30 ;\n");
    let tp = clean(&src);
    for (i, (e, want)) in cases.iter().enumerate() {
        assert_eq!(var(&tp, &format!("#{}", 100 + i)), Some(*want), "{e}");
    }
    assert_eq!(var(&tp, "#130"), Some(1.0));
    assert_eq!(var(&tp, "#131"), None);
    // MOD: Haas (and 30i) only; on a FANUC 0i an error naming it
    let haas = expand_with(
        "#1 = 27 MOD 20 ;\nM30 ;\n",
        Control::Haas,
        macro_b::Options::haas(),
    );
    assert!(haas.alarms.is_empty(), "{:?}", haas.alarms);
    assert_eq!(var(&haas, "#1"), Some(7.0));
    let tp = run("#1 = 27 MOD 20 ;\nM30 ;\n");
    assert!(tp.alarms[0].message.contains("MOD"), "{:?}", tp.alarms);
    // brackets deeper than 5 levels: refused when read, at the sixth
    let e = gcode::parse_with(
        "#1 = [[[[[[1]]]]]] ;\n",
        gcode::ReadOptions {
            macros: Some(macro_b::Dialect::Fanuc),
            ..Default::default()
        },
    )
    .unwrap_err();
    assert_eq!((e.span.line, e.span.column), (1, 11));
}

/// §5.6: a computed GOTO target is rounded (4.49 → N4, 4.5 → N5); GOTO searches the N
/// numbers of the current program.
#[test]
fn goto_rounds_its_target() {
    for (v, want) in [("4.49", 4.0), ("4.5", 5.0)] {
        let tp = clean(&format!(
            "#1 = {v} ;\nGOTO #1 ;\nN4 #2 = 4 ;\nGOTO 9 ;\nN5 #2 = 5 ;\nN9 M30 ;\n"
        ));
        assert_eq!(var(&tp, "#2"), Some(want), "GOTO {v}");
    }
    // IF … GOTO backwards: a counted loop
    let tp = clean("#1 = 0 ;\nN10 #1 = #1 + 1 ;\nIF [#1 LT 7] GOTO 10 ;\nM30 ;\n");
    assert_eq!(var(&tp, "#1"), Some(7.0));
    assert!(tp.line_counts.contains(&(2, 7)), "{:?}", tp.line_counts);
}

/// §5.5: G65 arguments (assignment I and II), a new local level, L repeats with locals
/// kept between them; §5.1: M98 keeps the caller's locals.
#[test]
fn g65_arguments_and_local_levels() {
    let tp = clean(
        "#1 = 5. ;
G65 P9010 A1. B2. C3. D7. E8. F9. H11. M13. Q17. R18. S19. T20. U21. V22. W23. X24. Y25. Z26. ;
#101 = #1 ;
M98 P9011 ;
#102 = #1 ;
G65 P9012 L3 A1. ;
G65 P9013 A1. I4. J5. K6. I7. K9. ;
M30 ;
O9010 ;
#130 = #1 + #2 + #3 + #7 + #8 + #9 + #11 + #13 + #17 + #18 + #19 + #20 + #21 + #22 + #23 + #24 + #25 + #26 ;
#131 = #4 ;
#1 = 99. ;
M99 ;
O9011 ;
#1 = #1 + 1. ;
M99 ;
O9012 ;
#1 = #1 + 1. ;
#132 = #1 ;
M99 ;
O9013 ;
#133 = #1 * 1000000 + #4 * 100000 + #5 * 10000 + #6 * 1000 + #7 * 100 + #8 * 10 + #9 ;
M99 ;
",
    );
    // every argument arrived in its variable: 1+2+3+7+8+9+11+13+17+…+26
    let sum = [
        1, 2, 3, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26,
    ]
    .iter()
    .sum::<i32>();
    assert_eq!(var(&tp, "#130"), Some(f64::from(sum)));
    assert_eq!(var(&tp, "#131"), None, "locals not passed are vacant");
    // the macro's #1 = 99 stayed on its level
    assert_eq!(var(&tp, "#101"), Some(5.0));
    // M98 runs with the caller's locals
    assert_eq!(var(&tp, "#102"), Some(6.0));
    // L3: A sets #1 on the first repetition only, locals persist: 2, 3, 4
    assert_eq!(var(&tp, "#132"), Some(4.0));
    // assignment II: I4 J5 K6 → #4 #5 #6, then I7 (a second I) starts the next triplet:
    // #7, and K9 → #9; #8 (J of that triplet) vacant
    assert_eq!(var(&tp, "#133"), Some(1_456_709.0));
}

/// §5.2: a G65 argument without a decimal point passes the least increment for length
/// letters (X5 → 0.005 mm) with an info line, whole units for the others.
#[test]
fn g65_argument_without_decimal_point() {
    let tp = clean("G65 P9020 X5 D5 ;\nM30 ;\nO9020 ;\n#100 = #24 ;\n#101 = #7 ;\nM99 ;\n");
    assert_eq!(var(&tp, "#100"), Some(0.005));
    assert_eq!(var(&tp, "#101"), Some(5.0));
    let info: Vec<_> = tp
        .warnings
        .iter()
        .filter(|w| w.code == "LS-G65-ARG")
        .collect();
    assert_eq!(info.len(), 2, "{:?}", tp.warnings);
    assert!(info[0].message.contains("passes 0.005"), "{:?}", info[0]);
    assert_eq!(info[0].span.column, 11);
}

/// §5.7: position reads, modal reads, #3006 stops, common variables.
#[test]
fn system_variables_read_the_simulated_state() {
    let tp = clean(
        "G99 G00 X30. Z2. ;
#100 = #5001 ;
#101 = #5002 ;
G01 Z-10. F0.2 ;
#102 = #5042 ;
#103 = #4001 ;
#104 = #4005 ;
#105 = #4109 ;
#3006 = 1 (CHECK THE BAR) ;
#500 = #500 + 1 ;
M30 ;
",
    );
    assert_eq!(var(&tp, "#100"), Some(30.0));
    assert_eq!(var(&tp, "#101"), Some(2.0));
    assert_eq!(var(&tp, "#102"), Some(-10.0));
    assert_eq!(var(&tp, "#103"), Some(1.0));
    assert_eq!(var(&tp, "#104"), Some(99.0));
    assert_eq!(var(&tp, "#105"), Some(0.2));
    assert_eq!(var(&tp, "#500"), Some(1.0));
    let stop = tp.warnings.iter().find(|w| w.code == "LS-STOP").unwrap();
    assert!(stop.message.contains("CHECK THE BAR"), "{stop:?}");
    assert_eq!(stop.span.line, 9);
    // a system variable latsim does not keep: an alarm naming it
    let tp = run("#1 = #4321 ;\nM30 ;\n");
    assert!(tp.alarms[0].message.contains("#4321"), "{:?}", tp.alarms);
}

/// Values put into addresses: M S T P Q rounded half away from zero (`M#1`, #1 = 3.5 is
/// M04), lengths to the increment; `G#1` is allowed.
#[test]
fn values_into_addresses() {
    let tp = clean(
        "#1 = 1 ;\n#2 = 30.0006 ;\n#3 = 0.25 ;\n#5 = 202.4 ;\nT#5 ;\nG00 X40. Z2. ;\nG#1 X#2 F#3 ;\nM30 ;\n",
    );
    let s = tp.segments.last().unwrap();
    assert_eq!(s.motion, Motion::Feed);
    // X to the least increment (0.001 mm)
    assert!((2.0 * s.to.r - 30.001).abs() < 1e-9, "{}", 2.0 * s.to.r);
    // T#5 with 202.4 is T0202
    assert_eq!(s.tool, 2);
    assert!(
        matches!(tp.feeds.get(s.feed), expander::Feed::PerRev { feed, .. } if (feed - 0.25).abs() < 1e-12),
        "{:?}",
        tp.feeds.get(s.feed)
    );
}

/// The 8 grooves of the WHILE loop leave the same section as the 8 written out
/// (assets/corpus/macro/grooves-*.nc): Hausdorff ≤ 0.001 mm.
#[test]
fn while_grooves_equal_written_out_grooves() {
    let tools = stock::ToolTable::from_toml(&read(&asset("corpus/tools/shop.toml"))).unwrap();
    let blank = stock::Blank::bar(40.0, 60.0, 0.0, None).unwrap();
    let machine = Machine::for_control(Control::FanucA);
    let section = |name: &str| {
        let program = read_macro(
            &read(&asset(&format!("corpus/macro/{name}"))),
            macro_b::Dialect::Fanuc,
        );
        let opts = expander::Options {
            tools: tools.facts(),
            start_tool: tools.numbers().first().copied(),
            macros: Some(macro_b::Options::fanuc()),
            ..Default::default()
        };
        let tp = expander::expand(&program, &machine, &opts);
        assert!(tp.alarms.is_empty(), "{name}: {:?}", tp.alarms);
        let sim = stock::simulate(
            &blank,
            &tools,
            &tp.segments,
            &stock::SimOptions::default(),
            &mut |_| {},
        );
        (tp, sim)
    };
    let (looped, a) = section("grooves-while.nc");
    let (flat, b) = section("grooves-flat.nc");
    assert_eq!(looped.segments.len(), flat.segments.len());
    let h = stock::hausdorff(&a.final_shapes, &b.final_shapes);
    assert!(h <= 0.001, "Hausdorff {h} mm");
    assert!((a.removed_area - 72.0).abs() < 0.1, "{}", a.removed_area);
    // each groove's plunge names the loop's line
    assert!(looped
        .segments
        .iter()
        .filter(|s| s.motion == Motion::Feed)
        .all(|s| s.span.line == 13));
}

/// A rapid into the stock inside a loop is reported at the loop's line (every executed
/// block keeps its source line); the JSON lists the variables and the line counts.
#[test]
fn a_crash_in_a_loop_names_its_line_and_the_json_lists_variables() {
    let (dir, prog) = temp_program(
        "crash.nc",
        b"G99 T0101 ;\nG97 S800 M03 ;\n#1 = 0 ;\nWHILE [#1 LT 3] DO1 ;\n#1 = #1 + 1 ;\nG00 X[52. - 4. * #1] Z2. ;\nG00 Z-10. ;\nG00 Z2. ;\nEND1 ;\nM30 ;\n",
    );
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--stock",
        "50x60",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    let doc: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    let crash = &doc["crashes"][0];
    assert_eq!(crash["line"], 7, "{doc:#}");
    assert_eq!(
        doc["variables"],
        serde_json::json!([{"name": "#1", "value": 3.0}])
    );
    assert!(doc["line_counts"]
        .as_array()
        .unwrap()
        .contains(&serde_json::json!({"line": 7, "count": 3})));
}

/// Bad macro input: a clear alarm at line and column, exit 1 (run-time alarm) or 2
/// (refused when read), never a panic or a hang; `check` and `run` alike.
fn bad(name: &str, text: &str, code: i32, needles: &[&str]) {
    let (dir, prog) = temp_program(name, text.as_bytes());
    for cmd in ["check", "run"] {
        let out_dir = dir.path().join("out");
        let mut args = vec![cmd, prog.to_str().unwrap(), "--control", "fanuc-a"];
        if cmd == "run" {
            args.extend(["--stock", "50x60", "--out", out_dir.to_str().unwrap()]);
        }
        let out = latsim(&args);
        assert_eq!(out.code, code, "{cmd} {name}: stderr:\n{}", out.stderr);
        assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
        for n in needles {
            assert!(
                out.stderr.contains(n),
                "{cmd} {name}: {n:?} missing from:\n{}",
                out.stderr
            );
        }
    }
}

#[test]
fn division_by_zero() {
    bad(
        "div.nc",
        "#1 = 0 ;\n#2 = 5 / #1 ;\nM30 ;\n",
        1,
        &["div.nc:2:6", "PS0112", "division by zero in 5/#1"],
    );
}

#[test]
fn vacant_variable_in_a_required_address() {
    bad(
        "vacant.nc",
        "#1 = 1 ;\nGOTO #7 ;\nN1 M30 ;\n",
        1,
        &["vacant.nc:2:6", "LS-VACANT", "#7 is vacant"],
    );
    bad(
        "g65p.nc",
        "G65 P#1 A2. ;\nM30 ;\n",
        1,
        &["g65p.nc:1:5", "G65 P: the variable is vacant"],
    );
    // a vacant P drops the address (§5.2), and M98 needs it
    bad(
        "m98p.nc",
        "G00 X50. Z2. ;\nM98 P#1 ;\nM30 ;\n",
        1,
        &["m98p.nc:2:1", "M98 without P"],
    );
}

#[test]
fn end_without_do() {
    bad(
        "end.nc",
        "G00 X50. Z2. ;\nEND1 ;\nM30 ;\n",
        1,
        &["end.nc:2:1", "PS0124", "END1 without DO1"],
    );
}

#[test]
fn do_nested_beyond_the_limit() {
    bad(
        "nest.nc",
        "WHILE [1 EQ 1] DO1 ;\nWHILE [1 EQ 1] DO2 ;\nWHILE [1 EQ 1] DO3 ;\nWHILE [1 EQ 1] DO1 ;\nEND1 ;\nEND3 ;\nEND2 ;\nEND1 ;\nM30 ;\n",
        1,
        &["nest.nc:4:1", "PS0124", "4 deep"],
    );
}

#[test]
fn goto_to_a_missing_n() {
    bad(
        "goto.nc",
        "#1 = 3 ;\nIF [#1 GT 2] GOTO 40 ;\nN30 M30 ;\n",
        1,
        &["goto.nc:2:19", "PS0128", "no block N40"],
    );
}

#[test]
fn program_alarm_3000() {
    bad(
        "alarm.nc",
        "G00 X52. Z2. ;\n#3000 = 12 (BAR END) ;\nM30 ;\n",
        1,
        &["alarm.nc:2:1", "MACRO-ALARM", "alarm 3012: BAR END"],
    );
}

#[test]
fn macro_syntax_is_refused_when_read() {
    bad(
        "br.nc",
        "#1 = [[[[[[1]]]]]] ;\nM30 ;\n",
        2,
        &["br.nc:1:11", "nested 6 deep"],
    );
    bad("if.nc", "IF [#1 GT 2 GOTO 4 ;\n", 2, &["if.nc:1:"]);
}

#[test]
fn hash_without_macro_b_says_how_to_turn_it_on() {
    let (_dir, prog) = temp_program("gsk.nc", b"G00 X50. Z2. ;\nG01 X#1 F0.2 ;\nM30 ;\n");
    for control in ["gsk980", "fanuc-a"] {
        let out = latsim(&[
            "check",
            prog.to_str().unwrap(),
            "--control",
            control,
            "--macro",
            "off",
        ]);
        assert_eq!(out.code, 2, "{}", out.stderr);
        assert!(out.stderr.contains("gsk.nc:2:6"), "{}", out.stderr);
        assert!(
            out.stderr
                .contains("`#` needs custom macro B: run with --control fanuc-a or --macro on"),
            "{}",
            out.stderr
        );
    }
    let out = latsim(&["check", prog.to_str().unwrap(), "--control", "gsk980"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    let out = latsim(&[
        "check",
        prog.to_str().unwrap(),
        "--control",
        "gsk980",
        "--macro",
        "on",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
}

/// A runaway loop ends by the block budget (10⁷ executed blocks) with an alarm that names
/// the loop: in well under a second in release (generous room for a debug build on a
/// shared machine).
#[test]
fn runaway_loop_ends_by_the_block_budget() {
    let (_dir, prog) = temp_program(
        "runaway.nc",
        b"G00 X52. Z2. ;\n#1 = 1 ;\nWHILE [#1 GT 0] DO1 ;\n#1 = #1 + 1 ;\nEND1 ;\nM30 ;\n",
    );
    let t = std::time::Instant::now();
    let out = latsim(&["check", prog.to_str().unwrap(), "--control", "fanuc-a"]);
    let secs = t.elapsed().as_secs_f64();
    assert_eq!(out.code, 1, "{}", out.stderr);
    for n in [
        "runaway.nc:3:1",
        "LS-LOOP",
        "more than 10000000 blocks executed",
        "the loop at line 3 ran",
    ] {
        assert!(
            out.stderr.contains(n),
            "{n:?} missing from:\n{}",
            out.stderr
        );
    }
    let limit = if cfg!(debug_assertions) { 60.0 } else { 1.0 };
    assert!(secs < limit, "{secs} s");
    // a smaller budget from the command line, and a GOTO loop
    let (_dir, prog) = temp_program("goto-loop.nc", b"N1 #1 = #1 + 1 ;\nGOTO 1 ;\nM30 ;\n");
    let out = latsim(&[
        "check",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--max-steps",
        "1000",
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr.contains("the loop at line 2 ran 500 times"),
        "{}",
        out.stderr
    );
}

/// A small deterministic generator (no dependency; the same programs on every run).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[(self.next() as usize) % items.len()]
    }
}

const STATEMENTS: &[&str] = &[
    "#1 = #1 + 1",
    "#2 = #1 / #3",
    "#3 = [#1 - 2] * SIN[#2]",
    "#[#1] = 5",
    "#100 = #500 MOD 3",
    "#0 = 1",
    "#3000 = 7 (STOP)",
    "#3006 = 1 (MSG)",
    "#4 = #5001 + #5002 + #4001",
    "#5 = SQRT[#1 - 3]",
    "#6 = ATAN[#1, #2]",
    "#7 = ROUND[#1 * 1.5] AND 3",
    "IF [#1 GT 3] GOTO 10",
    "IF [#1 LT 100] GOTO 20",
    "IF [#2 EQ #0] THEN #2 = 1",
    "IF [#1] THEN G01 X#1",
    "WHILE [#1 LT 5] DO1",
    "WHILE [#2 LE #1] DO2",
    "DO3",
    "END1",
    "END2",
    "END3",
    "GOTO #1",
    "GOTO 20",
    "N10",
    "N20",
    "G65 P9001 A#1 B2. I1. J2. K3. I4.",
    "G65 P9001 L3 X5",
    "M98 P9001",
    "M99",
    "M30",
    "O9001",
    "G00 X#1 Z[#2 + 1.]",
    "G01 X[50. - #1 * 2] Z-#3 F0.2",
    "G#1 U#2 W-[#3]",
    "G71 U1. R0.5",
    "G71 P10 Q20 U0.2 W0.1 F0.2",
    "G70 P10 Q20",
    "T#1 M#2 S#3",
    "[",
    "#",
    "X#",
];

fn random_macro_program(rng: &mut Lcg) -> String {
    let mut s = String::new();
    for _ in 0..(rng.next() % 30) {
        s += rng.pick(STATEMENTS);
        s += if rng.next().is_multiple_of(5) {
            " ;"
        } else {
            "\n"
        };
    }
    s
}

/// Random macro programs (loops, jumps, calls, alarms, broken syntax) go through the reader
/// and the interpreter under FANUC and Haas rules without panic, each run ending with at
/// most one alarm (the fuzz target `interpret_macro` does the same at scale).
#[test]
fn random_macro_programs_never_panic() {
    let mut rng = Lcg(0x3ac0);
    let (mut read, mut ran) = (0, 0);
    for _ in 0..5000 {
        let text = random_macro_program(&mut rng);
        for (control, options) in [
            (Control::FanucA, macro_b::Options::fanuc()),
            (Control::Haas, macro_b::Options::haas()),
        ] {
            let Ok(program) = gcode::parse_with(
                &text,
                gcode::ReadOptions {
                    macros: Some(options.dialect),
                    ..Default::default()
                },
            ) else {
                continue;
            };
            read += 1;
            let opts = expander::Options {
                max_segments: 20_000,
                max_blocks: 20_000,
                macros: Some(options),
                ..Default::default()
            };
            let tp = expander::expand(&program, &Machine::for_control(control), &opts);
            assert!(tp.alarms.len() <= 1, "{text}: {:?}", tp.alarms);
            ran += usize::from(tp.blocks > 0);
        }
    }
    eprintln!("{read} programs read, {ran} ran");
    // most are refused when read or prepared (unbalanced DO/END); enough run to matter
    assert!(read > 3000 && ran > 800, "{read} read, {ran} ran");
}

/// `--vars FILE` starts common variables with values (spec §5.1): a dispatcher reads #500
/// from it; a variable that is not common is refused before anything runs.
#[test]
fn vars_file_sets_common_variables() {
    let (dir, prog) = temp_program(
        "pick.nc",
        b"IF [#500 EQ 3] GOTO 30 ;\n#3000 = 1 (NOT 3) ;\nN30 G00 X[#500 * 10.] Z2. ;\nM30 ;\n",
    );
    let vars = dir.path().join("vars.toml");
    std::fs::write(&vars, "500 = 3.0\n\"#501\" = 2\n").unwrap();
    let out = latsim(&[
        "expand",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--vars",
        vars.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.contains("3,1,rapid"), "{}", out.stdout);
    assert!(out.stdout.contains(",2,30,"), "{}", out.stdout);
    std::fs::write(&vars, "1 = 3.0\n").unwrap();
    let out = latsim(&[
        "check",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--vars",
        vars.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr.contains("#1 is not a common variable"),
        "{}",
        out.stderr
    );
}

/// Haas `IF [cond] THEN <NC block>` (§5.6): the block runs when the condition holds; on
/// FANUC the form is refused when read.
#[test]
fn haas_if_then_nc_block() {
    let tp = expand_with(
        "#1 = 1 ;\nG00 X40. Z10. ;\nIF [#1 EQ 1] THEN G00 X#24 Z5. ;\nIF [#1 EQ 2] THEN G00 X20. Z2. ;\nM30 ;\n",
        Control::Haas,
        macro_b::Options::haas(),
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let m = moves(&tp);
    // the first THEN ran (X#24 vacant: only Z), the second did not
    assert_eq!(m.len(), 2, "{m:?}");
    assert_eq!(m[1], (10.0, 40.0, 5.0, 40.0, 3));
    let e = gcode::parse_with(
        "IF [#1 EQ 1] THEN G00 X20. ;\n",
        gcode::ReadOptions {
            macros: Some(macro_b::Dialect::Fanuc),
            ..Default::default()
        },
    )
    .unwrap_err();
    assert!(e.message.contains("Haas"), "{}", e.message);
}

/// A macro program in a `--lib` folder runs with its own loop structure: its O program
/// index (0 in its own file) does not alias the main file's program 0, whose blocks differ.
#[test]
fn a_library_macro_program_runs_its_own_loops() {
    let dir = tempfile::tempdir().unwrap();
    let lib = dir.path().join("lib");
    std::fs::create_dir(&lib).unwrap();
    // three grooves 4 mm apart from the Z given in #26 (argument Z), each a plunge to X#24
    std::fs::write(
        lib.join("O9002.nc"),
        "O9002 (GROOVES)\n#10 = 0 ;\nWHILE [#10 LT 3] DO1 ;\nG00 Z[#26 - 4 * #10] ;\nG01 X#24 F0.05 ;\nG00 X42. ;\n#10 = #10 + 1 ;\nEND1 ;\nM99 ;\n",
    )
    .unwrap();
    let main = dir.path().join("main.nc");
    std::fs::write(
        &main,
        "O0100\nG21 G99 T0505\nG97 S600 M03\nG00 X42. Z2.\nG65 P9002 X34. Z-10.\nG00 X100. Z100.\nM30\n",
    )
    .unwrap();
    let out = latsim(&[
        "expand",
        main.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--lib",
        lib.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    // the three plunges to X34 at Z-10, -14, -18
    let plunges: Vec<&str> = out
        .stdout
        .lines()
        .filter(|r| r.contains(",feed,") && r.contains(",34,"))
        .collect();
    assert_eq!(plunges.len(), 3, "{}", out.stdout);
    for (k, z) in ["-10", "-14", "-18"].iter().enumerate() {
        assert!(
            plunges[k].contains(&format!(",{z},42,{z},34,")),
            "{}",
            plunges[k]
        );
    }
}

/// Under macro B a G70 evaluates its finishing shape's expressions first; a shape named
/// backwards (Q's block before P's) is the cycle's alarm, not a panic (fuzz, found after a
/// change of that loop).
#[test]
fn a_finishing_shape_named_backwards_is_an_alarm_with_macro_b() {
    let tp = run("O0040\nN20 Z100.\nG96 S220 M03\nG00 X52. Z2.\nN10 X#103\nG70 P10 Q20\nM30\n");
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    assert_eq!(tp.alarms[0].code, "LS-SHAPE-ORDER");
}

/// An alarm inside a macro statement or expression of a `--lib` program is shown in that
/// file, at its line and column (its spans were left in the main file's range before).
#[test]
fn a_library_macro_alarm_is_shown_in_its_own_file() {
    let dir = tempfile::tempdir().unwrap();
    let lib = dir.path().join("lib");
    std::fs::create_dir(&lib).unwrap();
    let main = dir.path().join("main.nc");
    std::fs::write(
        &main,
        "O0001\nG99 G21 M3 S500 T0101\nG0 X60. Z2.\nG65 P1000 A2.\nM30\n",
    )
    .unwrap();
    for (body, at, shown) in [
        ("#2 = #1 / 0\nM99\n", "O1000.nc:2:6", "2 │ #2 = #1 / 0"),
        (
            "IF [#1 / 0 GT 1] GOTO 5\nM99\n",
            "O1000.nc:2:5",
            "2 │ IF [#1 / 0 GT 1] GOTO 5",
        ),
        (
            "#2 = 0\nG1 X[#1 / #2] F0.2\nM99\n",
            "O1000.nc:3:6",
            "3 │ G1 X[#1 / #2] F0.2",
        ),
    ] {
        std::fs::write(lib.join("O1000.nc"), format!("O1000\n{body}")).unwrap();
        let out = latsim(&[
            "check",
            main.to_str().unwrap(),
            "--control",
            "fanuc-a",
            "--lib",
            lib.to_str().unwrap(),
        ]);
        assert_eq!(out.code, 1, "{}", out.stderr);
        assert!(out.stderr.contains("division by zero"), "{}", out.stderr);
        assert!(out.stderr.contains(at), "{at}: {}", out.stderr);
        assert!(out.stderr.contains(shown), "{shown}: {}", out.stderr);
        assert!(!out.stderr.contains("main.nc:"), "{}", out.stderr);
    }
}

/// The parts counters #3901/#3902 (spec/dialects.md §5.7): 0 at the start, set by the
/// program; a loop on them runs its count. The modal groups 2 (G96/G97), 3
/// (G90/G91) and 7 (G40/G41/G42) read the interpreter's state.
#[test]
fn parts_counters_and_more_modal_groups() {
    let tp = clean(
        "#3902=3\n#3901=0\n#101=0\nWHILE[#3901LT#3902]DO1\n#101=#101+1\n#3901=#3901+1\nEND1\n#102=#4002\n#103=#4003\n#104=#4007\nG96 S150 M03 T0101\nG42 G00 X20 Z2\n#105=#4002\n#106=#4007\nG40 G00 X40 Z5\nM30\n",
    );
    assert_eq!(var(&tp, "#101"), Some(3.0), "{:?}", tp.variables);
    assert_eq!(
        [102, 103, 104, 105, 106].map(|n| var(&tp, &format!("#{n}"))),
        [Some(97.0), Some(90.0), Some(40.0), Some(96.0), Some(42.0)]
    );
}
