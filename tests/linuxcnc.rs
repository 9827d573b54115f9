//! `LinuxCNC` lathe programs under `--control linuxcnc` (issue 36, docs/linuxcnc.md): each
//! construct on a program of our own, against hand-computed paths or the same part written
//! for FANUC. `LinuxCNC`'s own `nc_files` were tried by hand (docs/linuxcnc.md), not copied.

mod common;
use common::{asset, latsim, report_of, temp_program};

/// `latsim expand --format csv` of `text` under `control`: each segment as
/// (kind, z0, x0, z1, x1, cz, cx, dir, tool), the line and column left out.
fn path(text: &str, control: &str) -> Vec<String> {
    let (_dir, prog) = temp_program("p.ngc", text.as_bytes());
    let tools = asset("corpus/tools/shop.toml");
    let out = latsim(&[
        "expand",
        prog.to_str().unwrap(),
        "--control",
        control,
        "--tools",
        tools.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    out.stdout
        .lines()
        .skip(1)
        .map(|l| l.splitn(3, ',').nth(2).unwrap().to_string())
        .collect()
}

/// `latsim check --control linuxcnc` of `text`: (exit code, stderr).
fn check(text: &str) -> (i32, String) {
    let (_dir, prog) = temp_program("p.ngc", text.as_bytes());
    let out = latsim(&["check", prog.to_str().unwrap(), "--control", "linuxcnc"]);
    (out.code, out.stderr)
}

const SHAFT_G7: &str = "G18 G21 G7 G90 G95 ; diameter mode\nT1 M6 G43\nG96 D2500 S180 M3\nG0 X42 Z2\nX36\nG1 Z-30 F0.2\nX42\nG0 Z2\nM2\n";

#[test]
fn g7_reads_diameters_and_g8_radii_from_the_block_they_are_in() {
    let g7 = path(SHAFT_G7, "linuxcnc");
    assert_eq!(
        g7,
        [
            "rapid,150,250,2,42,,,,1",
            "rapid,2,42,2,36,,,,1",
            "feed,2,36,-30,36,,,,1",
            "feed,-30,36,-30,42,,,,1",
            "rapid,-30,42,2,42,,,,1",
        ]
    );
    let g8 = SHAFT_G7
        .replace("G7 G90", "G8 G90")
        .replace("X42", "X21")
        .replace("X36", "X18");
    assert_eq!(path(&g8, "linuxcnc"), g7);
    // power-on is G8: without G7 the same numbers are radii
    let plain = SHAFT_G7.replace("G7 G90", "G90");
    assert_eq!(path(&plain, "linuxcnc")[1], "rapid,2,84,2,72,,,,1");
    // switched mid-program: G8 X10 is Φ20, then G7 X30 is Φ30
    let switched = "G8 G0 X10 Z5\nG7 X30\nX40 G8\nM2\n";
    let p = path(switched, "linuxcnc");
    assert_eq!(p[0], "rapid,150,250,5,20,,,,1");
    assert_eq!(p[1], "rapid,5,20,5,30,,,,1");
    assert_eq!(p[2], "rapid,5,30,5,80,,,,1");
}

#[test]
fn x_mode_diameter_makes_g7_the_power_on_mode() {
    let (_dir, prog) = temp_program("p.ngc", SHAFT_G7.replace("G7 G90", "G90").as_bytes());
    let out = latsim(&[
        "expand",
        prog.to_str().unwrap(),
        "--control",
        "linuxcnc",
        "--x-mode",
        "diameter",
        "--format",
        "csv",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.contains("rapid,2,42,2,36"), "{}", out.stdout);
}

#[test]
fn t_m6_loads_the_tool_and_g43_h_picks_the_offset() {
    // T2 alone only prepares: tool 1 still cuts until M6
    let p = path(
        "G7 T1 M6 G43\nG0 X50 Z5\nT2\nG0 X40\nM6\nG43 H2\nG0 X30\nM2\n",
        "linuxcnc",
    );
    let tools: Vec<&str> = p.iter().map(|s| s.rsplit(',').next().unwrap()).collect();
    assert_eq!(tools, ["1", "1", "2"]);
    let (code, err) = check("G7 M6\nG0 X50 Z5\nM2\n");
    assert_eq!(code, 1);
    assert!(err.contains("M6 without a tool prepared"), "{err}");
}

/// The same shoulder finished with G42.1 D0.8 L2 (`LinuxCNC` orientation 2) and G90.1
/// absolute arc centres, and with FANUC's G42 and tool 2 of the table (r0.4, tip 3): the
/// same compensated path.
#[test]
fn dynamic_compensation_with_linuxcnc_orientation_equals_fanuc_tip_3() {
    let lcnc = "G18 G21 G7 G90 G95\nT2 M6 G43\nG97 S1000 M3\nG0 X44 Z2\nG42.1 D0.8 L2\nG1 X26 Z0 F0.1\nZ-10\nG90.1\nG3 X36 Z-15 I13 K-15\nG91.1\nG1 Z-25\nX44\nG40 G0 X50 Z5\nM2\n";
    let fanuc = "O1\nG18 G21 G99\nT0202\nG97 S1000 M3\nG0 X44 Z2\nG42\nG1 X26 Z0 F0.1\nZ-10\nG3 X36 Z-15 I0 K-5\nG1 Z-25\nX44\nG40 G0 X50 Z5\nM30\n";
    let p = path(lcnc, "linuxcnc");
    assert_eq!(p, path(fanuc, "fanuc-a"));
    // the nose centre runs 0.4 off the Φ26 diameter: compensation happened
    assert!(p[2].starts_with("feed,-0.4,26,"), "{p:?}");
    // L3 (FANUC tip 2) is another nose position: another path
    assert_ne!(path(&lcnc.replace("L2", "L3"), "linuxcnc"), p);
}

#[test]
fn g33_k_is_the_lead_and_g4_p_is_seconds() {
    let prog =
        "G7 G21 G95 T4 M6\nG97 S600 M3\nG0 X32 Z4\nX29.4\nG33 Z-18 K1.5\nG0 X32\nG4 P2\nM2\n";
    let r = report_of(
        prog,
        &[
            "--control",
            "linuxcnc",
            "--stock",
            "30x40",
            "--tools",
            asset("corpus/tools/shop.toml").to_str().unwrap(),
        ],
    );
    assert_eq!(r["verdict"], "clean", "{r}");
    let p = path(prog, "linuxcnc");
    assert_eq!(p[2], "thread,4,29.4,-18,29.4,,,,4");
    // 600 rpm at 1.5 mm/rev: 22 mm in 22/900 min = 1.467 s, the 2 s dwell, and the rapids
    // (146 mm in Z from home at 8000 mm/min = 1.095 s, the rest short): 4.56 s to 4.7 s
    let t = r["cycle_time_s"].as_f64().unwrap();
    assert!((4.56..4.7).contains(&t), "cycle time {t}");
    let (code, err) = check("G7 G0 X30 Z2\nG33 Z-10\nM2\n");
    assert_eq!(code, 1);
    assert!(err.contains("G33 without K"), "{err}");
}

#[test]
fn semicolon_comments_and_msg_read_silently_under_linuxcnc_only() {
    let prog = "%\n(MSG, hello)\nG7 G0 X30 Z2 ; a comment\nM2\n%\n";
    let (code, err) = check(prog);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("read as a comment"), "{err}");
    // the rest of the line after `;` is a comment, whatever it holds; `%` in a comment is
    // text (`(debug, %.3f#1)`); an M2 inside an o-word `if` leaves the endif reachable
    let prog2 = "G7\n#1 = [2 * 3]; X\n(debug, %.3f#1)\no1 if [#1 GT 9]\n  M2\no1 endif\nG0 X#1 Z1 ; >= 2\nM2\n";
    let (code, err) = check(prog2);
    assert_eq!((code, err.as_str()), (0, ""));
    assert_eq!(path(prog2, "linuxcnc"), ["rapid,150,250,1,6,,,,1"]);
    let (_dir, p) = temp_program("p.nc", prog.replace("G7 ", "").as_bytes());
    let out = latsim(&["check", p.to_str().unwrap(), "--control", "fanuc-a"]);
    assert!(out.stderr.contains("read as a comment"), "{}", out.stderr);
}

#[test]
fn linuxcnc_codes_latsim_does_not_run_are_alarms_at_their_word() {
    for (prog, word, col) in [
        ("G7 G0 X30 Z2\nG5 X1 Z1 I1 J1 P1 Q1\nM2\n", "G5", 1),
        ("G7 G0 X30 Z2\nG0 G33.1 Z-5 K1\nM2\n", "G33.1", 4),
        ("G7 G0 X30 Z2\nG70 Q100 X30 Z2\nM2\n", "G70", 1),
        ("G7 G0 X30 Z2\nG76 P1.5 Z-10 I-1 J0.1 K0.9\nM2\n", "G76", 1),
    ] {
        let (code, err) = check(prog);
        assert_eq!(code, 1, "{prog}: {err}");
        assert!(err.contains("LS-NOT-IMPLEMENTED"), "{err}");
        assert!(err.contains(&format!("p.ngc:2:{col}")), "{word}: {err}");
    }
    // U and W are axes of their own in LinuxCNC
    let (code, err) = check("G7 G0 X30 Z2\nG0 U5\nM2\n");
    assert_eq!(code, 1);
    assert!(err.contains("axis of its own in LinuxCNC"), "{err}");
    // a code LinuxCNC does not have is named as such
    let (code, err) = check("G7 G50 S2000\nM2\n");
    assert_eq!(code, 1);
    assert!(err.contains("not a LinuxCNC G code"), "{err}");
    // and LinuxCNC's G7 stays an alarm under FANUC
    let (_dir, p) = temp_program("p.nc", b"G7 G0 X30 Z2\nM30\n");
    let out = latsim(&["check", p.to_str().unwrap(), "--control", "fanuc-a"]);
    assert!(
        out.stderr.contains("diameter mode in LinuxCNC"),
        "{}",
        out.stderr
    );
}

/// Subroutines with arguments and a return value, `if`/`elseif`/`else`, `while`, `repeat`
/// and `do … while` with `continue` and `break` ([O]): the path worked out by hand.
#[test]
fn o_word_subroutines_and_flow_run_as_linuxcnc_runs_them() {
    let prog = "G18 G21 G7 G90 G95\nT1 M6 G43\n\
o100 sub\n  G0 X#1 Z2\n  G1 Z#2 F0.2\n  G0 X[#1+4] Z2\no100 endsub [#1 * 2]\n\
o<face> sub\n  o10 if [#1 GT 50]\n    G0 X#1 Z0\n  o10 elseif [#1 GT 30]\n    G0 X[#1+1] Z0\n  o10 else\n    G0 X[#1+2] Z0\n  o10 endif\no<face> endsub\n\
#1 = 40\n\
o1 while [#1 GT 30]\n  o100 call [#1] [-20]\n  #1 = [#1 - 4]\no1 endwhile\n\
G0 X#<_value> Z5\n\
o<face> call [60]\no<face> call [40]\no<face> call [20]\n\
o2 repeat [3]\n  G91 G0 Z1\no2 endrepeat\nG90\n\
#3 = 0\no3 do\n  #3 = [#3 + 1]\n  o4 if [#3 EQ 2]\n    o3 continue\n  o4 endif\n  o5 if [#3 EQ 4]\n    o3 break\n  o5 endif\no3 while [#3 LT 10]\n\
G0 X#<_value> Z#3\nM2\n";
    let p = path(prog, "linuxcnc");
    assert_eq!(
        p,
        [
            // o100 call [40] [-20], [36], [32]: #1 of the caller stays 40, 36, 32
            "rapid,150,250,2,40,,,,1",
            "feed,2,40,-20,40,,,,1",
            "rapid,-20,40,2,44,,,,1",
            "rapid,2,44,2,36,,,,1",
            "feed,2,36,-20,36,,,,1",
            "rapid,-20,36,2,40,,,,1",
            "rapid,2,40,2,32,,,,1",
            "feed,2,32,-20,32,,,,1",
            "rapid,-20,32,2,36,,,,1",
            // #<_value> = 2 × 32 from the last endsub
            "rapid,2,36,5,64,,,,1",
            // o<face>: 60 > 50; 40 > 30: 41; else 22
            "rapid,5,64,0,60,,,,1",
            "rapid,0,60,0,41,,,,1",
            "rapid,0,41,0,22,,,,1",
            // repeat [3]: three steps of 1 mm
            "rapid,0,22,1,22,,,,1",
            "rapid,1,22,2,22,,,,1",
            "rapid,2,22,3,22,,,,1",
            // o<face> returned no value: #<_value> cleared to 0 by its call; break at #3 = 4
            "rapid,3,22,4,0,,,,1",
        ]
    );
}

/// The loop guard of issue 37 watches o-word loops: a `while` whose state never changes
/// is an alarm at once, at its `endwhile`; a `do … while [1]` at its `while`; loops that
/// count to 1000 run to their end.
#[test]
fn o_word_loops_meet_the_loop_guard() {
    let (code, err) = check("G7 G0 X30 Z2\no1 while [1]\n  G0 X30 Z2\no1 endwhile\nM2\n");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("endless loop"), "{err}");
    assert!(err.contains("p.ngc:4:1"), "{err}");
    assert!(err.contains("o… break"), "{err}");
    let (code, err) = check("G7 G0 X30 Z2\no3 do\n  G0 X30\no3 while [1]\nM2\n");
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("endless loop") && err.contains("p.ngc:4:1"),
        "{err}"
    );
    let counting = "G7 G0 X30 Z2\n#1 = 0\no1 while [#1 LT 1000]\n  G0 X30 Z2\n  #1 = [#1 + 1]\no1 endwhile\no2 repeat [1000]\n  G0 X30\no2 endrepeat\n#2 = 0\no3 do\n  #2 = [#2 + 1]\no3 while [#2 LT 1000]\nG0 X#1 Z[#2 / 100]\nM2\n";
    let p = path(counting, "linuxcnc");
    assert_eq!(p.last().unwrap(), "rapid,2,30,10,1000,,,,1", "{p:?}");
}

/// Badly formed o-words are read errors (exit 2: a statement that does not read) or
/// alarms before the run (exit 1: the structure, as FANUC's DO/END) at their line and
/// column, never a panic.
#[test]
fn o_word_mistakes_are_named_at_their_place() {
    for (text, at, says, exit) in [
        (
            "o1 endwhile",
            "p.ngc:2:1",
            "o1 endwhile without o1 while",
            1,
        ),
        ("o1 if [1]\nG0 X1", "p.ngc:2:1", "o1 if without o1 endif", 1),
        (
            "o2 call",
            "p.ngc:2:1",
            "o2 call: the subroutine is not defined",
            1,
        ),
        ("o<x> call [1]", "p.ngc:2:1", "x.ngc", 1),
        (
            "o1 sub\no2 sub\no2 endsub\no1 endsub",
            "p.ngc:3:1",
            "inside the definition of o1",
            1,
        ),
        (
            "o1 while [1]\no2 if [1]\no1 endwhile\no2 endif",
            "p.ngc:4:1",
            "must not cross",
            1,
        ),
        ("o1 break", "p.ngc:2:1", "o1 break outside", 1),
        (
            "o1 if [1]\no1 else\no1 elseif [2]\no1 endif",
            "p.ngc:4:1",
            "elseif after o1 else",
            1,
        ),
        (
            "o1 repeat\no1 endrepeat",
            "p.ngc:2:10",
            "needs its value in brackets",
            2,
        ),
        ("o1 frob", "p.ngc:2:4", "o1 needs a keyword", 2),
        (
            "o1 sub\no1 endsub\no1 sub\no1 endsub",
            "p.ngc:4:1",
            "defined twice",
            1,
        ),
        ("o1 return", "p.ngc:2:1", "o1 return outside", 1),
    ] {
        let (code, err) = check(&format!("G7 G0 X30 Z2\n{text}\nM2\n"));
        assert_eq!(code, exit, "{text}: {err}");
        assert!(err.contains(at), "{text}: {err}");
        assert!(err.contains(says), "{text}: {err}");
    }
}

/// `#<name>` is local to the call level it is set in, `#<_name>` global ([OV] "Named
/// Parameters"); `EXISTS[#<name>]` asks without reading; reading one never set is an error.
#[test]
fn named_parameters_are_local_or_global_by_name() {
    let prog = "G7 G0 X30 Z2\n#<d> = 20\n\
o1 sub\n  o2 if [EXISTS[#<d>]]\n    G0 X99\n  o2 endif\n  #<d> = 50\n  #<_g> = [#<d> + #1]\no1 endsub\n\
o1 call [3]\nG0 X#<d> Z1\nG0 X#<_g> Z0\nM2\n";
    let p = path(prog, "linuxcnc");
    assert_eq!(
        p[1..],
        ["rapid,2,30,1,20,,,,1", "rapid,1,20,0,53,,,,1"],
        "{p:?}"
    );
    let (code, err) =
        check("G7 G0 X30 Z2\n#<d> = 20\no1 sub\n  G0 X#<d>\no1 endsub\no1 call\nM2\n");
    assert_eq!(code, 1);
    assert!(
        err.contains("#<d> is not defined") && err.contains("p.ngc:4:7"),
        "{err}"
    );
    // names are read without blanks and case (LinuxCNC: #<Tool Dia> is #<tooldia>)
    let p = path("G7\n#<Tool Dia> = 12\nG0 X#<tooldia> Z1\nM2\n", "linuxcnc");
    assert_eq!(p[0], "rapid,150,250,1,12,,,,1");
}

/// FANUC's macro statements are not `LinuxCNC` syntax: a read error naming the o-words.
#[test]
fn fanuc_macro_flow_is_an_error_under_linuxcnc() {
    for (text, word) in [
        ("IF [#1 EQ 1] GOTO 10", "IF"),
        ("WHILE [#1 LT 2] DO1\nEND1", "WHILE"),
        ("GOTO 10", "GOTO"),
    ] {
        let (code, err) = check(&format!("G7 G0 X30 Z2\n{text}\nN10 M2\n"));
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains(&format!("{word} is FANUC macro B, not LinuxCNC")),
            "{err}"
        );
        assert!(
            err.contains("o100 while") && err.contains("p.ngc:2:1"),
            "{err}"
        );
    }
}
