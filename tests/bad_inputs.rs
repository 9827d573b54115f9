//! Bad input gets a clear message with `file:line:column` and a non-zero exit, never a panic.

mod common;
use common::*;

/// (file contents, expected exit code, text that must appear on stderr)
fn case(name: &str, text: &[u8], code: i32, needles: &[&str]) {
    let (dir, prog) = temp_program(name, text);
    for cmd in ["check", "run"] {
        let mut args = vec![cmd, prog.to_str().unwrap()];
        let out_dir = dir.path().join("out");
        if cmd == "run" {
            args.extend(["--stock", "40x50", "--out", out_dir.to_str().unwrap()]);
        }
        let out = latsim(&args);
        assert_eq!(
            out.code, code,
            "{cmd} {name}: exit {} stderr:\n{}",
            out.code, out.stderr
        );
        assert!(
            !out.stderr.contains("panicked"),
            "{cmd} {name} panicked:\n{}",
            out.stderr
        );
        for n in needles {
            assert!(
                out.stderr.contains(n),
                "{cmd} {name}: {n:?} missing from:\n{}",
                out.stderr
            );
        }
        if cmd == "run" && code == 2 {
            assert!(
                !out_dir.exists(),
                "nothing may be written when nothing was simulated"
            );
        }
    }
}

#[test]
fn unknown_g_code_is_an_alarm_at_its_word() {
    case(
        "unknown.nc",
        b"G0 X50 Z5\nM3 S500\nG12 X10\nM30\n",
        1,
        &["unknown.nc:3:1", "G12", "PS010"],
    );
}

#[test]
fn unknown_m_code() {
    // An M code the control's table does not know is a machine function: accepted, with a
    // warning at its word (spec/dialects.md §6.6, issue 11); M98 with M30 is an error.
    case(
        "m.nc",
        b"G0 X50 Z5 M47\n",
        0,
        &["m.nc:1:11", "M47 is not in the gsk980 M-code table"],
    );
    case(
        "m2.nc",
        b"G0 X50 Z5\nM98 P1 M30\n",
        1,
        &["m2.nc:2:8", "M30 cannot share a block with M98"],
    );
}

#[test]
fn malformed_number() {
    case(
        "num.nc",
        b"G0 X50 Z5\nG1 X1.2.3 F1\n",
        2,
        &["num.nc:2:4", "malformed number"],
    );
}

#[test]
fn missing_value() {
    case(
        "missing.nc",
        b"G0 X50 Z5\nG1 Z F100\n",
        2,
        &["missing.nc:2:4", "has no value"],
    );
}

#[test]
fn arc_radius_too_small() {
    case(
        "arc.nc",
        b"M3 S500\nG0 X20 Z2\nG1 Z0 F100\nG3 X40 Z-30 R5\nM30\n",
        1,
        &["arc.nc:4:13", "too small", "PS020"],
    );
}

#[test]
fn recursive_m98_ends_with_the_nesting_alarm() {
    case(
        "rec.nc",
        b"O0001;\nM98 P2;\nM30;\nO0002;\nG0 X50 Z5;\nM98 P2;\nM99;\n",
        1,
        &["rec.nc:6:1", "PS077"],
    );
}

/// M99 ending the main program loops to its start on the control (a bar feeder's next
/// part): simulated once with a warning at the M99, exit 0 (it was an alarm before field
/// run 4; dialects.md §3.6, §5.8).
#[test]
fn m99_in_main_runs_it_once_with_a_warning() {
    case(
        "loop.nc",
        b"G0 X50 Z5\nM99\n",
        0,
        &["loop.nc:2:1", "LS-M99-MAIN", "simulated once"],
    );
}

#[test]
fn missing_subprogram() {
    case("sub.nc", b"M98 P1234\nM30\n", 1, &["sub.nc:1:1", "O1234"]);
}

#[test]
fn empty_file() {
    case("empty.nc", b"", 2, &["nothing to simulate"]);
    case(
        "comments.nc",
        b"%\n(only a comment)\n%\n",
        2,
        &["nothing to simulate"],
    );
}

#[test]
fn binary_garbage() {
    case(
        "bin.nc",
        &[0x7f, 0x45, 0x4c, 0x46, 0x02, 0x01, 0x01, 0x00, 0xff, 0xfe],
        2,
        &["not UTF-8"],
    );
    // control bytes are dropped (spec/dialects.md §1), the unexpected ones with a warning
    case(
        "ctl.nc",
        b"\x00\x01\x02G0 X50 Z5",
        0,
        &["ctl.nc:1:2", "2 unexpected control character(s) removed"],
    );
}

#[test]
fn unused_word_is_not_skipped() {
    case("word.nc", b"G0 X50 Z5 Y3\n", 1, &["word.nc:1:11", "Y"]);
}

#[test]
fn feed_missing() {
    case(
        "feed.nc",
        b"M3 S500\nG0 X50 Z5\nG1 X40\n",
        1,
        &["feed.nc:3:1", "PS011"],
    );
}

#[test]
fn missing_files_and_bad_flags() {
    let out = latsim(&["run", "/nonexistent/prog.nc", "--stock", "40x50"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("cannot read program"), "{}", out.stderr);
    let (_d, prog) = temp_program("ok.nc", b"G0 X50 Z5\nM30\n");
    let out = latsim(&["run", prog.to_str().unwrap(), "--stock", "40by50"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("40by50"), "{}", out.stderr);
    let out = latsim(&["run", prog.to_str().unwrap()]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("--stock"), "{}", out.stderr);
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "40x50",
        "--tol",
        "-1",
    ]);
    assert_eq!(out.code, 2);
    let out = latsim(&["frobnicate"]);
    assert_eq!(out.code, 2);
}

#[test]
fn bad_tool_table_points_at_its_line() {
    let (dir, prog) = temp_program("ok.nc", b"G0 X50 Z5\nM30\n");
    let tools = dir.path().join("tools.toml");
    std::fs::write(
        &tools,
        "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"Q\"\n",
    )
    .unwrap();
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "40x50",
        "--tools",
        tools.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("tools.toml:"), "{}", out.stderr);
}

#[test]
fn the_input_is_never_overwritten() {
    let (dir, prog) = temp_program("p.nc", b"G0 X50 Z5\nM30\n");
    let before = std::fs::read(&prog).unwrap();
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "40x50",
        "--json",
        prog.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert_eq!(std::fs::read(&prog).unwrap(), before);
    drop(dir);
}
