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
