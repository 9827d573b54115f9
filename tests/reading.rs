//! Reading every file a shop has (issue 31): what the field test on public programs found,
//! each shown on a program of our own. The corpus (`assets/corpus`) holds the programs that
//! read; these are the readings a sidecar cannot state (refusals, warnings, flags).

mod common;

use common::{latsim, report_of, run_json, temp_program};

/// The warnings' codes of a report.
fn warning_codes(report: &serde_json::Value) -> Vec<String> {
    report["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["code"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn binary_bytes_without_motion_are_no_program() {
    // NUL and control bytes and a G0 with no move read CLEAN, 0 segments, exit 0 before
    let (_dir, path) = temp_program("junk.nc", b"\0\0\x01\x02G0\x03\x04\x05\0\x06\x07\n\0\0");
    let out = latsim(&["check", path.to_str().unwrap()]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("not a program text"), "{}", out.stderr);
    // a text program without motion still reads (nothing binary in it)
    let (_dir, path) = temp_program("nomove.nc", b"O0001\nM03 S500\nM05\nM30\n");
    assert_eq!(latsim(&["check", path.to_str().unwrap()]).code, 0);
}

#[test]
fn gbk_program_names_its_encoding_and_keeps_columns() {
    let text = "O1 (外圆精车)\nG0 X44. Z2. (快速)\nG1 X36. F100 Q7\nM30\n";
    let (_dir, path) = temp_program("gbk.nc", &gbk(text));
    // the error is found on line 3 at the Q, column 14, counted in characters
    let out = latsim(&["check", path.to_str().unwrap()]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("gbk.nc:3:14"), "{}", out.stderr);
    // without the error, the report's warnings name the encoding
    let (_dir, path) = temp_program("gbk.nc", &gbk(&text.replace(" Q7", "")));
    let (out, report) = run_json(&path, &["--stock", "50x40", "--quiet"]);
    let report = report.unwrap_or_else(|| panic!("{}", out.stderr));
    let w = &report["warnings"][0];
    assert_eq!(w["code"], "LS-ENCODING");
    assert!(w["message"].as_str().unwrap().ends_with("GBK"), "{w}");
    // and the report says which it was read in
    assert_eq!(report["encoding"], "GBK");
}

/// GBK bytes of a text (the test's own encoder: the reverse of what latsim decodes).
fn gbk(text: &str) -> Vec<u8> {
    let mut out = vec![];
    for c in text.chars() {
        let code = match c {
            '外' => [0xCD, 0xE2],
            '圆' => [0xD4, 0xB2],
            '精' => [0xBE, 0xAB],
            '车' => [0xB3, 0xB5],
            '快' => [0xBF, 0xEC],
            '速' => [0xCB, 0xD9],
            c => {
                out.push(c as u8);
                continue;
            }
        };
        out.extend_from_slice(&code);
    }
    out
}

#[test]
fn encoding_flag_forces_one() {
    // 0xD8 is Ø in Windows-1252; forced UTF-8 it is no character: exit 2 at that byte
    let (_dir, path) = temp_program("w.nc", b"O1 (\xd820)\nG0 X44. Z2.\nG1 X36. F100\nM30\n");
    let p = path.to_str().unwrap();
    let out = latsim(&["check", p, "--encoding", "utf-8"]);
    assert_eq!(out.code, 2);
    assert!(
        out.stderr.contains("not UTF-8 text: byte 4"),
        "{}",
        out.stderr
    );
    let out = latsim(&["check", p, "--encoding", "klingon"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("no such encoding"), "{}", out.stderr);
    let (out, report) = run_json(
        &path,
        &["--encoding", "windows-1252", "--stock", "50x40", "--quiet"],
    );
    let report = report.unwrap_or_else(|| panic!("{}", out.stderr));
    assert_eq!(report["warnings"][0]["message"], "read as windows-1252");
}

#[test]
fn x_mode_flag_reads_radii_like_the_profile_key() {
    // r16 to Z-10, a quarter round of radius 4 up to r20, r20 to Z-20 (X as radii)
    let prog = "G0 X22. Z2.\nG1 X16. F100\nZ-10.\nG3 X20. Z-14. I0. K-4.\nG1 Z-20.\nX22.\nM30\n";
    // read as diameters the arc's end is not on its circle: an alarm
    let report = report_of(prog, &["--stock", "44x40"]);
    assert_eq!(report["verdict"], "alarm");
    let report = report_of(prog, &["--stock", "44x40", "--x-mode", "radius"]);
    assert_eq!(report["verdict"], "clean", "{}", report["alarms"]);
    assert!(warning_codes(&report).contains(&"LS-X-RADIUS".to_string()));
    // the default tool's nose leaves its fillets: compare with the profile key instead
    let dir = tempfile::tempdir().unwrap();
    let machine = dir.path().join("m.toml");
    std::fs::write(&machine, "x_mode = \"radius\"\n").unwrap();
    let by_key = report_of(
        prog,
        &["--stock", "44x40", "--machine", machine.to_str().unwrap()],
    );
    assert_eq!(by_key["removed_area_mm2"], report["removed_area_mm2"]);
    // a cycle's depth U(Δd) stays a radius, its allowance U(Δu) is doubled like X
    let g71 = "G0 X22. Z2.\nG71 U1. R0.5\nG71 P1 Q2 U0.2 W0. F100\nN1 G0 X16.\nG1 Z-10. F100\nN2 X22.\nM30\n";
    let report = report_of(g71, &["--stock", "44x40", "--x-mode", "radius"]);
    assert_eq!(report["verdict"], "clean", "{}", report["alarms"]);
}

#[test]
fn linuxcnc_o_words_are_named() {
    let (_dir, path) = temp_program("l.ngc", b"O100 SUB\nG0 X1\nO100 ENDSUB\nO100 CALL\nM2\n");
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("LinuxCNC"), "{}", out.stderr);
    assert!(out.stderr.contains("l.ngc:1:1"), "{}", out.stderr);
}

#[test]
fn haas_g53_with_g01_feeds_and_fanuc_g53_rapids() {
    let prog = "G21 G99\nT101\nG0 X50. Z2.\nG53 G01 X0. F0.3\nM30\n";
    let moves = |control: &str| {
        let (_dir, path) = temp_program("g53.nc", prog.as_bytes());
        let out = latsim(&[
            "expand",
            path.to_str().unwrap(),
            "--control",
            control,
            "--format",
            "csv",
        ]);
        assert_eq!(out.code, 0, "{}", out.stderr);
        out.stdout.lines().last().unwrap().to_string()
    };
    assert!(moves("haas").contains("feed"), "{}", moves("haas"));
    assert!(moves("fanuc-a").contains("rapid"), "{}", moves("fanuc-a"));
}

/// `G28 G00 U0 W0` (Haas class programs write it before every tool) stopped with PS010;
/// it goes home at rapid and leaves G00 in force: the next block's bare `X… Z…` is a rapid.
/// `G28 G01 U0` stays an alarm (docs/field-rules.md §10).
#[test]
fn g28_with_g00_goes_home_and_leaves_g00() {
    let expand = |prog: &str| {
        let (_dir, path) = temp_program("g28.nc", prog.as_bytes());
        latsim(&[
            "expand",
            path.to_str().unwrap(),
            "--control",
            "haas",
            "--format",
            "csv",
        ])
    };
    let out = expand("G21 G99\nT101\nG01 X50. Z2. F0.2\nG28 G00 U0 W0\nX40. Z5.\nM30\n");
    assert_eq!(out.code, 0, "{}", out.stderr);
    let last = out.stdout.lines().last().unwrap().to_string();
    assert!(last.contains("rapid"), "{last}");
    let out = expand("G21 G99\nT101\nG28 G01 U0\nM30\n");
    assert!(out.stderr.contains("PS010"), "{}", out.stderr);
}

/// Okuma OSP programs (the field test's `$NAME.MIN%` files) stopped at "unexpected
/// character '$'"; they are named, at the line, as Okuma syntax.
#[test]
fn okuma_programs_are_named() {
    let (_dir, path) = temp_program("o.min", b"$PART.MIN%\nDEF WORK\nEND\nG50 S2000\nM02\n");
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("Okuma OSP syntax"), "{}", out.stderr);
    assert!(out.stderr.contains("o.min:1:1"), "{}", out.stderr);
    // a variable of another control's language (Okuma's PRES=1, Philips' N1=8001)
    let (_dir, path) = temp_program("p.nc", b"G0 X100 Z2\nN180 G13 N1=8001 N2=8011\nM30\n");
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr
            .contains("the assignment N1=8001 is another control's language"),
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("p.nc:2:1"), "{}", out.stderr);
}

/// A `LinuxCNC` named parameter assigned on a line of its own (`#<_depth> = 0.5`, the
/// field test's `LatheEasyStep` output) stopped at "unexpected character '<' in a macro
/// expression" under a control with macro B on; it is named as `LinuxCNC`'s.
#[test]
fn linuxcnc_named_parameter_statements_are_named() {
    let (_dir, path) = temp_program("n.ngc", b"G18 G21\n#<_depth> = 0.500\nG0 X10\nM2\n");
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr.contains("LinuxCNC (rs274ngc) syntax"),
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("n.ngc:2:1"), "{}", out.stderr);
}

/// `LinuxCNC`'s G7 (diameter mode) is an alarm at its word that says whose code it is.
#[test]
fn linuxcnc_g7_is_named_in_its_alarm() {
    let (_dir, path) = temp_program("g7.ngc", b"G18 G7 G90 G40\nG0 X10 Z2\nM2\n");
    let out = latsim(&["check", path.to_str().unwrap(), "--control", "fanuc-a"]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("g7.ngc:1:5"), "{}", out.stderr);
    assert!(
        out.stderr.contains("diameter mode in LinuxCNC"),
        "{}",
        out.stderr
    );
}
