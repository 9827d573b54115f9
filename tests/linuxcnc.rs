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
        ("G7 G0 X30 Z2\nG0 G38.2 Z-5\nM2\n", "G38.2", 4),
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

/// `G92 Z0` makes the tool's Z2 read Z0; `G92.1` (and `G92.2`) drop that offset: the same
/// `G0 Z-1` goes to Z1 under it and to Z-1 after ([G] "G92.1, G92.2 Reset G92 Offsets"), as
/// `LinuxCNC`'s own `lathe-g76.ngc` steps its passes along Z. `G92.3` stays an alarm.
#[test]
fn g92_1_and_g92_2_drop_the_g92_offset() {
    for reset in ["G92.1", "G92.2"] {
        let text = format!("G18 G21 G7 G90\nG0 X30 Z2\nG92 Z0\nG0 Z-1\n{reset}\nG0 Z-1\nM2\n");
        let p = path(&text, "linuxcnc");
        let ends: Vec<&str> = p.iter().map(|l| l.split(',').nth(3).unwrap()).collect();
        assert_eq!(ends[ends.len() - 2..], ["1", "-1"], "{reset}: {p:?}");
    }
    let (code, err) = check("G7 G0 X30 Z2\nG92 Z0\nG92.3\nM2\n");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("G92.3") && err.contains("p.ngc:3:1"), "{err}");
}

/// In G17 `LinuxCNC` drills along Z, the lathe's axis (`macros/lathe/drill.ngc` does):
/// G83 feeds a peck Q, rapids back to R, comes down to 1 mm (the clearance) short of the
/// depth reached and ends at R (power-on G99, `R_PLANE`); G73 backs off by D after each peck
/// and ends at the initial level under G98 (`interp_cycles.cc` `convert_cycle_g83`, `_g73`).
/// The moves worked out by hand; in G18 the same cycle drills along Y: an alarm at its word.
#[test]
fn drilling_cycles_in_g17_drill_along_the_axis() {
    let text = "G18 G21 G7 G90 G95\nT1 M6 G43\nG97 S800 M3\nG0 X0 Z5\nG17\nG83 Z-10 R2 Q4 F0.1\nG80\nG98 G73 Z-6 R1 Q2.5 D0.5\nG80\nG18\nG0 X20\nM2\n";
    let moves: Vec<String> = path(text, "linuxcnc")
        .iter()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            format!("{} {}", f[0], f[3])
        })
        .collect();
    let hand = [
        // G83: to R, pecks to -2 and -6 each followed by R and 1 mm short, bottom, R
        "rapid 2",
        "feed -2",
        "rapid 2",
        "rapid -1",
        "feed -6",
        "rapid 2",
        "rapid -5",
        "feed -10",
        "rapid 2",
        // G73: to R, pecks to -1.5 and -4 each backed off 0.5, bottom, initial level
        "rapid 1",
        "feed -1.5",
        "rapid -1",
        "feed -4",
        "rapid -3.5",
        "feed -6",
        "rapid 2",
        "rapid 2",
    ];
    assert_eq!(moves, hand);
    for (prog, col, says) in [
        (
            "G18 G21 G90\nG0 X0 Z5\nM3 S500\nG83 Z-10 R2 Q4 F100\nM2\n",
            1,
            "plane's normal",
        ),
        (
            "G17 G21 G90\nG0 X0 Z5\nM3 S500\nG83 Z-10 R2 F100\nM2\n",
            1,
            "without Q",
        ),
        (
            "G17 G21 G91\nG0 X0 Z5\nM3 S500\nG81 Z-10 R-3 F100\nM2\n",
            1,
            "G91",
        ),
    ] {
        let (code, err) = check(prog);
        assert_eq!(code, 1, "{prog}: {err}");
        assert!(
            err.contains(says) && err.contains(&format!("p.ngc:4:{col}")),
            "{prog}: {err}"
        );
    }
}

/// `G33.1 Z K` taps on the axis: in to Z and back out to the start at the lead K, modal
/// (a block of Z and K taps again, `LinuxCNC`'s `G_33_1` motion); `LinuxCNC`'s own refusals
/// (no K, an F, the spindle stopped) and a hole off the axis are alarms at their line.
#[test]
fn g33_1_taps_in_and_back_out_on_the_axis() {
    let text = "G18 G21 G7 G90 G95\nT8 M6 G43\nG97 S300 M3\nG0 X0 Z5\nG33.1 Z-15 K1.5\nZ-20 K1.5\nG0 X60\nM2\n";
    let moves: Vec<String> = path(text, "linuxcnc")
        .iter()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            format!("{} {} {}", f[0], f[3], f[4])
        })
        .collect();
    let hand = [
        "feed -15 0",
        "feed 5 0",
        "feed -20 0",
        "feed 5 0",
        "rapid 5 60",
    ];
    assert_eq!(moves, hand);
    for (prog, says) in [
        ("G7 G0 X0 Z5\nM3 S300\nG33.1 Z-15\nM2\n", "without K"),
        (
            "G7 G0 X0 Z5\nM3 S300\nG33.1 Z-15 K1 F100\nM2\n",
            "F word used with G33.1",
        ),
        (
            "G7 G0 X0 Z5\nM5\nG33.1 Z-15 K1\nM2\n",
            "Spindle not turning",
        ),
        (
            "G7 G0 X10 Z5\nM3 S300\nG33.1 Z-15 K1\nM2\n",
            "off the spindle axis",
        ),
    ] {
        let (code, err) = check(prog);
        assert_eq!(code, 1, "{prog}: {err}");
        assert!(
            err.contains(says) && err.contains("p.ngc:3:"),
            "{prog}: {err}"
        );
    }
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
    let (code, err) =
        check("G7 G0 X30 Z2\n#<d> = 5\no1 while [#<d> GT 0]\n  G0 X30 Z2\no1 endwhile\nM2\n");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("#<d> (= 5) never changes"), "{err}");
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
    // LinuxCNC's predefined #<_x> (the radius inside, in program units), #<_z>, #<_metric>
    let p = path(
        "G7 G0 X30 Z2\nG0 X[#<_x> * 2 + 4 + #<_metric>] Z[#<_Z> - 1]\nM2\n",
        "linuxcnc",
    );
    assert_eq!(p[1], "rapid,2,30,1,35,,,,1", "{p:?}");
    // names are read without blanks and case (LinuxCNC: #<Tool Dia> is #<tooldia>)
    let p = path("G7\n#<Tool Dia> = 12\nG0 X#<tooldia> Z1\nM2\n", "linuxcnc");
    assert_eq!(p[0], "rapid,150,250,1,12,,,,1");
}

/// FANUC's macro statements are not `LinuxCNC` syntax: a read error naming the o-words;
/// and `LinuxCNC`'s named parameters are no FANUC syntax.
#[test]
fn fanuc_macro_flow_is_an_error_under_linuxcnc() {
    for text in ["#<d> = 1\nG0 X30\nM30\n", "#1 = 1\nG0 X#<d>\nM30\n"] {
        let (_dir, p) = temp_program("p.nc", text.as_bytes());
        let out = latsim(&["check", p.to_str().unwrap(), "--control", "fanuc-a"]);
        assert_eq!(out.code, 2, "{}", out.stderr);
        assert!(out.stderr.contains("LinuxCNC"), "{}", out.stderr);
    }
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

/// The profile of the pawn-like job below (diameters), the same blocks in both programs.
const PAWN_PROFILE: &str =
    "G1 X0 Z0\nG3 X12 Z-6 R6\nG1 X8 Z-10\nZ-14\nX20 Z-20\nZ-26\nX28 Z-30\nZ-36\nX32\n";

/// The pawn-like job written the `LinuxCNC` way (profile in o100, G71.1 without the pocket,
/// G71.2 with it, G70) leaves the same part as the job written for FANUC (G71 type II with
/// P/Q blocks, G70): the final sections within the simulation's chord tolerance (0.001 mm).
#[test]
fn pawn_job_with_g71_1_g71_2_g70_equals_the_fanuc_job() {
    let lcnc = format!(
        "G18 G21 G7 G90 G95\nT1 M6 G43\nG96 D2500 S180 M3\nF0.2\no100 sub\n{PAWN_PROFILE}o100 endsub\nG0 X32 Z2\nG71.1 Q100 X32 Z2 D0.5 I1.5 R0.5\nG71.2 Q100 X32 Z2 D0.5 I1.5 R0.5\nG70 Q100 X32 Z2\nG0 X60 Z50\nM2\n"
    );
    let numbered: String = PAWN_PROFILE
        .lines()
        .enumerate()
        .map(|(i, l)| format!("N{} {l}\n", 10 + i))
        .collect();
    let fanuc = format!(
        "O1\nG18 G21 G99\nT0101\nG50 S2500\nG96 S180 M3\nG0 X32 Z2\nG71 U1.5 R0.5\nG71 P10 Q18 U1.0 W0.5 F0.2\n{numbered}G70 P10 Q18\nG0 X60 Z50\nM30\n"
    );
    let tools = stock::ToolTable::from_toml(
        &std::fs::read_to_string(asset("corpus/tools/shop.toml")).unwrap(),
    )
    .unwrap();
    let blank = stock::Blank::bar(32.0, 50.0, 0.0, None).unwrap();
    let read = gcode::ReadOptions {
        macros: Some(macro_b::Dialect::LinuxCnc),
        ..Default::default()
    };
    let run = |text: &str, control, read| {
        let p = gcode::parse_with(text, read).unwrap();
        let opts = expander::Options {
            tools: tools.facts(),
            macros: read.macros.map(|d| match d {
                macro_b::Dialect::LinuxCnc => macro_b::Options::linuxcnc(),
                _ => macro_b::Options::fanuc(),
            }),
            ..Default::default()
        };
        let tp = expander::expand(&p, &expander::Machine::for_control(control), &opts);
        assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
        let sim = stock::simulate(
            &blank,
            &tools,
            &tp.segments,
            &stock::SimOptions::default(),
            &mut |_| {},
        );
        (tp, sim)
    };
    let (tl, sl) = run(&lcnc, expander::Control::LinuxCnc, read);
    let (tf, sf) = run(
        &fanuc,
        expander::Control::FanucA,
        gcode::ReadOptions::default(),
    );
    let h = stock::hausdorff(&sl.final_shapes, &sf.final_shapes);
    eprintln!(
        "LinuxCNC {} moves, FANUC {} moves, Hausdorff {h:.6} mm",
        tl.segments.len(),
        tf.segments.len()
    );
    assert!(h <= 0.001, "Hausdorff between the final sections {h}");
    // the part is the profile: Φ8 in the neck's pocket (Z-10 … Z-14)
    let neck = |s: &stock::Simulation| surface_diameter(s, -12.0);
    assert!((neck(&sl) - 8.0).abs() < 0.01, "neck Φ{}", neck(&sl));
    // G71.1 alone does not cut the pocket: it bridges it at Φ12 + 2 × D
    let only_1 = lcnc
        .replace("G71.2 Q100 X32 Z2 D0.5 I1.5 R0.5\n", "")
        .replace("G70 Q100 X32 Z2\n", "");
    let (_, s1) = run(&only_1, expander::Control::LinuxCnc, read);
    assert!(
        (neck(&s1) - 13.0).abs() < 0.01,
        "G71.1 at the neck: Φ{}",
        neck(&s1)
    );
}

/// The diameter of the part's outer surface at `z`: where the outline's edges cross z,
/// the largest radius, doubled.
fn surface_diameter(sim: &stock::Simulation, z: f64) -> f64 {
    let mut r = f64::MIN;
    for shape in &sim.final_shapes {
        let pts = &shape.outer;
        for k in 0..pts.len() {
            let (a, b) = (pts[k], pts[(k + 1) % pts.len()]);
            if (a[0] - z) * (b[0] - z) <= 0.0 && a[0] != b[0] {
                let t = (z - a[0]) / (b[0] - a[0]);
                r = r.max(a[1] + t * (b[1] - a[1]));
            }
        }
    }
    2.0 * r
}

/// G70 Q D E P ([G] "G70"): pass k of P at distance (k − 1)(D − E)/P + E off the profile
/// toward the start point, each from a rapid to the start point and to the profile's start;
/// the tool stays at the profile's end. Worked out by hand: the step Φ10 → Φ20 at Z-10
/// kept 0.5 away is Φ11 to Z-9.5, then the shoulder at Z-9.5.
#[test]
fn g70_passes_run_at_their_distances() {
    let prog = "G7 G18 G21 G95 F0.1\no1 sub\n  G1 X10 Z0\n  Z-10\n  X20\no1 endsub\nG0 X30 Z2\nG70 Q1 X30 Z2 D1 P2\nM2\n";
    let p = path(prog, "linuxcnc");
    assert_eq!(
        p[1..],
        [
            "rapid,2,30,0,11,,,,1",
            "feed,0,11,-9.5,11,,,,1",
            "feed,-9.5,11,-9.5,20,,,,1",
            "rapid,-9.5,20,2,30,,,,1",
            "rapid,2,30,0,10,,,,1",
            "feed,0,10,-10,10,,,,1",
            "feed,-10,10,-10,20,,,,1",
        ],
        "{p:?}"
    );
    // the profile's lines are the moves' lines: line 3 is the first move of o1
    let (_dir, f) = temp_program("p.ngc", prog.as_bytes());
    let out = latsim(&[
        "expand",
        f.to_str().unwrap(),
        "--control",
        "linuxcnc",
        "--format",
        "csv",
    ]);
    assert!(
        out.stdout
            .lines()
            .any(|l| l.starts_with("4,3,feed,0,10,-10,10,")),
        "{}",
        out.stdout
    );
}

/// G71/G72 words and profiles that `LinuxCNC` refuses are alarms at their place; a fillet
/// A on a profile corner rounds it (r 1 at the Φ10 shoulder), a chamfer C has its ends.
#[test]
fn g7x_mistakes_are_alarms_and_corners_round() {
    for (text, at, says) in [
        ("G70 Q100 X30 Z2", "p.ngc:7:1", "no o100 sub"),
        ("G71 X30 Z2 D1", "p.ngc:7:1", "without Q"),
        (
            "G41.1 D0.8 L2\nG71 Q1 X30 Z2",
            "p.ngc:8:1",
            "cutter compensation on",
        ),
        ("G71 Q1 X30 Z2 I0", "p.ngc:7:1", "greater than zero"),
        ("G71 Q1 X30 Z2 K3", "p.ngc:7:15", "address K"),
        // G71.2 continues a G71.1 of the same profile; alone LinuxCNC cuts only the pockets
        ("G71.2 Q1 X30 Z2", "p.ngc:7:1", "no G71.1 Q1 before it"),
        (
            "G72.1 Q1 X30 Z2\nG71.2 Q1 X30 Z2",
            "p.ngc:8:1",
            "no G71.1 Q1 before it",
        ),
    ] {
        let prog =
            format!("G7 G0 X30 Z2 F0.2\no1 sub\nG1 X10 Z0\nZ-10\nX30\no1 endsub\n{text}\nM2\n");
        let (code, err) = check(&prog);
        assert_eq!(code, 1, "{text}: {err}");
        assert!(err.contains(at) && err.contains(says), "{text}: {err}");
    }
    let corner = "G7 G18 G21 G95 F0.1\no1 sub\n  G1 X10 Z0\n  Z-10 A1\n  X20\no1 endsub\nG0 X30 Z2\nG70 Q1 X30 Z2\nM2\n";
    let p = path(corner, "linuxcnc");
    assert_eq!(
        p[1..],
        [
            "rapid,2,30,0,10,,,,1",
            "feed,0,10,-9,10,,,,1",
            "arc,-9,10,-10,12,-9,12,cw,1",
            "feed,-10,12,-10,20,,,,1",
        ],
        "{p:?}"
    );
    let p = path(&corner.replace("A1", "C1"), "linuxcnc");
    assert_eq!(p[3], "feed,-9,10,-10,12,,,,1", "{p:?}");
    // after a G71.1 of the profile, its G71.2 runs (warned: simulated as the whole cycle)
    let (code, err) =
        check(&corner.replace("G70 Q1 X30 Z2", "G71.1 Q1 X30 Z2 D0.5\nG71.2 Q1 X30 Z2"));
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("LS-G7X-2"), "{err}");
}

/// `o<name> call` of a subroutine the file does not define runs the `o<name> sub` of
/// `name.ngc` beside the program (`LinuxCNC`'s `SUBROUTINE_PATH`; the file's own `M2` after its
/// `endsub` is not reached); a missing file is an alarm at the call naming it.
#[test]
fn a_subroutine_of_another_file_is_called_by_its_name() {
    let (dir, prog) = temp_program(
        "main.ngc",
        b"G7 G18 G21 G95 F0.2\nG0 X30 Z2\no<step> call [24] [-10]\nG0 X40 Z5\nM2\n",
    );
    std::fs::write(
        dir.path().join("step.ngc"),
        "(a subroutine file)\no<step> sub\n  G0 X#1 Z2\n  G1 Z#2\n  G0 X30\no<step> endsub\nM2\n",
    )
    .unwrap();
    let out = latsim(&[
        "expand",
        prog.to_str().unwrap(),
        "--control",
        "linuxcnc",
        "--format",
        "csv",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let moves: Vec<&str> = out.stdout.lines().skip(2).collect();
    assert!(moves[0].ends_with("rapid,2,30,2,24,,,,0"), "{moves:?}");
    assert!(moves[1].ends_with("feed,2,24,-10,24,,,,0"), "{moves:?}");
    assert!(moves[3].ends_with("rapid,-10,30,5,40,,,,0"), "{moves:?}");
    let (code, err) = check("G7 G0 X30 Z2\no<nowhere> call\nM2\n");
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("o<nowhere> call") && err.contains("nowhere.ngc"),
        "{err}"
    );
}

/// Field run 8 (F): a centre-drilling position written with both axes, `G0 X0 Y0 Z5` after
/// `G17`, keeps the tool on the spindle's centre line: Y0 is noted W-Y0 and the run goes
/// on (it stopped with "the Y axis moves off the spindle centre line"). T3 has no entry and
/// only drills: the assumed Ø10 drill, 20 deep by its tip, 5 · (20 − 5/tan 59°) + 5 · (5/tan
/// 59°) / 2 = 92.49 mm². A Y away from the centre stays the alarm.
#[test]
fn y0_keeps_the_tool_on_the_centre_line() {
    let program = "( LinuxCNC lathe: centre drill at X0 Y0 in G17 )\nG7 G18 G21 G90 G95\nT3 M6 G43\nS500 M3\nG17\nG0 X0 Y0 Z5\nG83 Z-20 R2 Q5 F0.08\nG80\nG18\nG0 X100 Z50\nM2\n";
    let v = report_of(program, &["--stock", "40x40", "--control", "linuxcnc"]);
    assert_eq!(v["verdict"], "clean", "{v:#}");
    let noted = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == "W-Y0")
        .count();
    assert_eq!(noted, 1, "{:#}", v["warnings"]);
    let slope = 5.0 / 59f64.to_radians().tan();
    let hand = 5.0 * (20.0 - slope) + 5.0 * slope / 2.0;
    let removed = v["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - hand).abs() < 0.01, "{removed} vs {hand}");
    let off = report_of(
        &program.replace("X0 Y0 Z5", "X0 Y2 Z5"),
        &["--stock", "40x40", "--control", "linuxcnc"],
    );
    assert_eq!(off["verdict"], "alarm", "{off:#}");
}
