//! Faults around the simulation (issue 17): diagnostics that cannot panic, outputs written
//! whole or not at all, never over an input or a foreign file, batches that survive one
//! program's failure, name collisions, and inputs too large to read.

mod common;
use common::*;

const GOOD: &[u8] = b"G0 X50 Z5\nG1 X40 F100\nG0 X60\nM30\n";

#[test]
fn a_caret_past_column_65535_is_shown_in_a_window() {
    // found/minimal/P1: miette panicked formatting an underline past column 65535
    let text = format!("({}) G65\n", "a".repeat(69_960));
    let (_d, prog) = temp_program("p1.nc", text.as_bytes());
    let out = latsim(&["check", prog.to_str().unwrap()]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("p1.nc:1:69964"), "{}", out.stderr);
    assert!(out.stderr.lines().all(|l| l.chars().count() < 300));
}

#[test]
fn deeply_nested_parentheses_do_not_panic() {
    // found/hostile-panic-0c7206c4f8: 100 000 nested parentheses made miette panic
    let text = format!(
        "O0001;\nG99 M03 S500 T0101;\n{}{}\nM30;\n",
        "(".repeat(100_000),
        ")".repeat(100_000)
    );
    let (_d, prog) = temp_program("deep.nc", text.as_bytes());
    let out = latsim(&["check", prog.to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stderr.contains("nested parentheses"), "{}", out.stderr);
    assert!(out.stderr.contains("deep.nc:3:1"), "{}", out.stderr);
    assert!(out.stderr.lines().all(|l| l.chars().count() < 300));
    // unbalanced: FANUC's reading, the comment ends at the first ')' and the rest is code
    let (_d, prog) = temp_program(
        "open.nc",
        format!("G0 X10 {}Z5\n", "(".repeat(30_000)).as_bytes(),
    );
    let out = latsim(&["check", prog.to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stderr.contains("not closed"), "{}", out.stderr);
}

#[test]
fn non_utf8_input_names_its_line_and_column() {
    // issue 31: a GBK file is decoded (tests/reading.rs); forced to UTF-8 it is refused at
    // its first bad byte
    let (_d, prog) = temp_program("gbk.nc", b"G0 X50 Z5\nG1 X40 (\xb5\xb6) F100\n");
    assert_eq!(latsim(&["check", prog.to_str().unwrap()]).code, 0);
    let out = latsim(&["check", prog.to_str().unwrap(), "--encoding", "utf-8"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("gbk.nc:2:9"), "{}", out.stderr);
    assert!(out.stderr.contains("UTF-8"), "{}", out.stderr);
}

#[test]
fn numbers_with_more_than_nine_whole_digits_are_refused_at_their_word() {
    let (_d, prog) = temp_program("n.nc", b"G0 X99999999999 Z5\n");
    let out = latsim(&["check", prog.to_str().unwrap()]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("n.nc:1:4"), "{}", out.stderr);
    assert!(out.stderr.contains("11 digits"), "{}", out.stderr);
    let (_d, prog) = temp_program("ok.nc", b"G0 X000000000050.000 Z5\n");
    assert_eq!(latsim(&["check", prog.to_str().unwrap()]).code, 0);
}

#[test]
fn a_program_given_where_a_report_goes_is_never_overwritten() {
    let (dir, prog) = temp_program("a.nc", GOOD);
    let json = dir.path().join("a.json");
    std::fs::write(&json, b"G0 X1\n").unwrap();
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        json.to_str().unwrap(),
        "--stock",
        "60x50",
        "--out",
        dir.path().to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(std::fs::read(&json).unwrap(), b"G0 X1\n", "{}", out.stdout);
    // both are programs of the run: their reports take their whole file names
    let files = files_in(dir.path());
    assert!(files.contains(&"a.nc.json".to_string()), "{files:?}");
    assert!(files.contains(&"a.json.json".to_string()), "{files:?}");
}

#[test]
fn programs_sharing_a_stem_get_their_own_reports() {
    let (dir, prog) = temp_program("part.nc", GOOD);
    std::fs::write(
        dir.path().join("part.tap"),
        b"G0 X50 Z5\nG1 X30 F100\nG0 X60\nM30\n",
    )
    .unwrap();
    let out_dir = tempfile::tempdir().unwrap();
    let out = latsim(&[
        "run",
        dir.path().to_str().unwrap(),
        "--stock",
        "60x50",
        "--out",
        out_dir.path().to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0, "{}{}", out.stdout, out.stderr);
    let files = files_in(out_dir.path());
    for f in [
        "part.nc.json",
        "part.tap.json",
        "part.nc.svg",
        "part.tap.png",
    ] {
        assert!(files.contains(&f.to_string()), "{files:?}");
    }
    let a = std::fs::read_to_string(out_dir.path().join("part.nc.json")).unwrap();
    let b = std::fs::read_to_string(out_dir.path().join("part.tap.json")).unwrap();
    assert_ne!(a, b);
    let _ = prog;
}

#[test]
fn one_file_flags_are_refused_with_several_programs() {
    let (dir, prog) = temp_program("a.nc", GOOD);
    std::fs::write(dir.path().join("b.nc"), GOOD).unwrap();
    let html = dir.path().join("x.html");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        dir.path().join("b.nc").to_str().unwrap(),
        "--stock",
        "60x50",
        "--html",
        html.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("--html"), "{}", out.stderr);
    assert!(!html.exists());
}

#[test]
fn links_fifos_and_devices_are_never_replaced() {
    let (dir, prog) = temp_program("a.nc", GOOD);
    let target = dir.path().join("elsewhere.txt");
    std::fs::write(&target, b"keep").unwrap();
    let link = dir.path().join("link.json");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let fifo = dir.path().join("fifo.svg");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    for out_path in [
        link.to_str().unwrap(),
        "/dev/null",
        if made.is_ok_and(|s| s.success()) {
            fifo.to_str().unwrap()
        } else {
            "/dev/zero"
        },
    ] {
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock",
            "60x50",
            "--json",
            out_path,
        ]);
        assert_eq!(out.code, 2, "{out_path}: {}", out.stderr);
    }
    assert_eq!(std::fs::read(&target).unwrap(), b"keep");
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
}

#[test]
fn a_refused_output_leaves_every_other_report_of_the_run_as_it_was() {
    let (dir, prog) = temp_program("a.nc", GOOD);
    let json = dir.path().join("a.json");
    std::fs::write(&json, b"old").unwrap();
    let sub = dir.path().join("folder.svg");
    std::fs::create_dir(&sub).unwrap();
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "60x50",
        "--json",
        json.to_str().unwrap(),
        "--svg",
        sub.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert_eq!(std::fs::read(&json).unwrap(), b"old");
    assert_eq!(files_in(dir.path()), ["a.json", "a.nc", "folder.svg"]);
}

#[test]
fn killed_runs_leave_whole_reports_or_none_and_no_litter() {
    // a program that takes a moment, killed at different points of its run
    let mut text = String::from("G99 M3 S800\nG0 X62 Z2\n");
    for i in 0..12000 {
        let x = 60.0 - (i % 200) as f64 * 0.1;
        text.push_str(&format!("G1 X{x:.3} F0.2\nZ-{}.\nG0 X62\nZ2\n", 5 + i % 30));
    }
    let (dir, prog) = temp_program("k.nc", text.as_bytes());
    let out_dir = tempfile::tempdir().unwrap();
    for delay_ms in [30u64, 250, 500, 750, 1000, 1300] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_latsim"))
            .args([
                "run",
                prog.to_str().unwrap(),
                "--stock",
                "64x80",
                "--out",
                out_dir.path().to_str().unwrap(),
                "--quiet",
            ])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(delay_ms));
        let _ = child.kill();
        let _ = child.wait();
        for f in files_in(out_dir.path()) {
            assert!(
                !f.starts_with('.'),
                "litter after kill at {delay_ms} ms: {f}"
            );
            if f.ends_with(".json") {
                let j = std::fs::read_to_string(out_dir.path().join(&f)).unwrap();
                assert!(j.trim_end().ends_with('}'), "half a report: {f}");
            }
        }
    }
    let _ = dir;
}

#[test]
fn a_batch_gives_every_program_its_verdict_line() {
    // P2 of found/minimal made tiny-skia panic in the PNG: whatever one program does,
    // the others still get their verdict
    let (dir, _) = temp_program("a.nc", GOOD);
    std::fs::write(
        dir.path().join("b.nc"),
        b"G00 X62 Z5\nG92 X40 R123456789 F1\n",
    )
    .unwrap();
    std::fs::write(dir.path().join("c.nc"), GOOD).unwrap();
    let out_dir = tempfile::tempdir().unwrap();
    let out = latsim(&[
        "run",
        dir.path().to_str().unwrap(),
        "--stock",
        "60x80",
        "--out",
        out_dir.path().to_str().unwrap(),
    ]);
    for name in ["a.nc", "b.nc", "c.nc"] {
        assert_eq!(
            out.stdout.lines().filter(|l| l.contains(name)).count(),
            1,
            "{name}: {}",
            out.stdout
        );
    }
}

#[test]
fn a_machine_profile_with_an_absurd_home_is_refused_at_its_value() {
    // found/minimal/P4: home = [1e308, -1e308] overflowed the removal grid (a panic)
    let dir = tempfile::tempdir().unwrap();
    let machine = dir.path().join("m.toml");
    std::fs::write(&machine, "power_on_feed = 100.0\nhome = [1e308, -1e308]\n").unwrap();
    let out = latsim(&[
        "run",
        asset("programs/O0008.nc").to_str().unwrap(),
        "--stock",
        "60x80",
        "--stock-z",
        "40",
        "--machine",
        machine.to_str().unwrap(),
        "--json",
        dir.path().join("x.json").to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("m.toml:2:8"), "{}", out.stderr);
    assert!(!dir.path().join("x.json").exists());
}

#[test]
fn thread_leads_below_the_chord_tolerance_are_swept_continuously() {
    // found/minimal H1 (G32 F0.001 over 4 mm: 4000 stamps, > 20 s) and H2 (F0.0001 over
    // 2 mm: memory cap): the notches between stamps would be under the chord tolerance
    for (name, text) in [
        ("h1.nc", "G99 M03 S500\nG00 X40 Z2\nG32 Z-2 F0.001\nM30\n"),
        ("h2.nc", "G99 M03 S500\nG00 X40 Z2\nG32 Z0 F0.0001\nM30\n"),
    ] {
        let (_dir, prog) = temp_program(name, text.as_bytes());
        let (out, report) = run_json(&prog, &["--stock", "60x80"]);
        assert_eq!(out.code, 0, "{name}: {}", out.stderr);
        let report = report.unwrap().to_string();
        assert!(report.contains("swept continuously"), "{name}: {report}");
    }
}

#[test]
fn a_sawtooth_blank_does_not_flood_the_report_with_sliver_gouges() {
    // found/toml-stock-slow-exit1: a 100 000-point sawtooth blank profile made 77 580
    // "gouges" of 0.0000 mm² against O0006's finishing shape (here 20 000 points)
    let mut path = String::new();
    for i in 1..20_000 {
        let x = if i % 2 == 1 { 45.0 } else { 40.0 };
        path.push_str(&format!("{{ to = [{:.4}, {x}] }}, ", -0.004 * i as f64));
    }
    let toml = format!(
        "start = [0.0, 0.0]\npath = [{{ to = [0.0, 40.0] }}, {path}{{ to = [-80.0, 0.0] }}]\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let blank = dir.path().join("saw.toml");
    std::fs::write(&blank, toml).unwrap();
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        asset("programs/O0006.nc").to_str().unwrap(),
        "--stock-file",
        blank.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(out.code == 0 || out.code == 1, "{}", out.stderr);
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let gouges = report["gouges"].as_array().unwrap();
    assert!(gouges.len() <= 1000, "{} gouges listed", gouges.len());
    assert!(
        gouges
            .iter()
            .all(|g| g["area_mm2"].as_f64().unwrap() > 1e-4),
        "sliver gouges: {gouges:?}"
    );
}

#[test]
fn lengths_beyond_ten_metres_are_alarms_at_their_word() {
    // found/minimal P2 and P3: `G92 X40 R123456789` reached tiny-skia (a panic, an abort)
    for (name, text, at) in [
        ("p2.nc", "G00 X62 Z5\nG92 X40 R123456789 F1\n", "p2.nc:2:9"),
        (
            "p3.nc",
            "G00 X62 Z5\nG92 X40 R100 F0.0001\nR123456789\n",
            "p3.nc:3:1",
        ),
        ("inch.nc", "G20 G00 X400. Z5.\n", "inch.nc:1:9"),
    ] {
        let (dir, prog) = temp_program(name, text.as_bytes());
        let png = dir.path().join("x.png");
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock",
            "60x80",
            "--png",
            png.to_str().unwrap(),
        ]);
        assert_eq!(out.code, 1, "{name}: {}", out.stderr);
        assert!(out.stderr.contains(at), "{name}: {}", out.stderr);
        assert!(out.stderr.contains("LS-RANGE"), "{name}: {}", out.stderr);
        assert!(png.exists());
    }
}

#[test]
fn a_self_intersecting_blank_profile_is_refused() {
    // issue 17: a bowtie --stock-file was accepted silently and ran CLEAN
    let dir = tempfile::tempdir().unwrap();
    let blank = dir.path().join("bowtie.toml");
    std::fs::write(
        &blank,
        "start = [0.0, 0.0]\npath = [{ to = [-10.0, 20.0] }, { to = [0.0, 20.0] }, { to = [-10.0, 0.0] }]\n",
    )
    .unwrap();
    let out = latsim(&[
        "run",
        asset("programs/O0002.nc").to_str().unwrap(),
        "--stock-file",
        blank.to_str().unwrap(),
        "--json",
        dir.path().join("x.json").to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("crosses itself"), "{}", out.stderr);
    assert!(out.stderr.contains("bowtie.toml:1:9"), "{}", out.stderr);
}

/// found/toml-stock-slow-timeout-dee1…: a blank profile of 10 000 points jumping back and
/// forth along Z between two radii crosses itself millions of times; the boolean engine
/// took minutes to split them before the crossing test. The kernel's sweep stops at the
/// first crossing: a clear error at the profile's start, exit 2.
#[test]
fn a_tangled_blank_profile_is_refused_at_once() {
    let mut seed = 0x2545_f491_u64;
    let mut text = String::from("start = [0.0, 0.0]\npath = [");
    for k in 0..10_000 {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        let z = -(((seed >> 33) % 60_000) as f64) / 1000.0;
        let x = if k % 2 == 0 { 40.0 } else { 45.0 };
        text.push_str(&format!("{{ to = [{z}, {x}] }}, "));
    }
    text.push_str("{ to = [-60.0, 0.0] }]\n");
    let (dir, blank) = temp_program("tangled.toml", text.as_bytes());
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        asset("programs/G75_1-cone.nc").to_str().unwrap(),
        "--stock-file",
        blank.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("crosses itself near"), "{}", out.stderr);
    assert!(!json.exists());
}

/// Issue 17: a TOML file larger than 16 MB (the TOML reader's tree takes ~95 bytes a byte)
/// is refused before it is read, with its size and the limit, exit 2.
#[test]
fn a_huge_stock_file_is_refused_before_it_is_read() {
    let (d, prog) = temp_program("p.nc", GOOD);
    let big = d.path().join("big.toml");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(17 * 1024 * 1024)
        .unwrap();
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock-file",
        big.to_str().unwrap(),
        "--out",
        d.path().to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr.contains("17825792 bytes") && out.stderr.contains("(16 MB)"),
        "{}",
        out.stderr
    );
    assert_eq!(files_in(d.path()), ["big.toml", "p.nc"]);
}

/// fuzz/findings/run-slow-deviation (a mutated facing and pecking program, converted to
/// UTF-8 as the fuzz harness reads it): 11 030 moves, a holder that meets the stock on 426
/// of them, two gouges of the Φ60 × 30 shaft with a Φ40 neck. Naming the moves that made
/// each gouge built every move's sweep once per gouge and asked a boolean for each: 19.8 s
/// in release. Now each sweep is built once and its convex parts are measured by clipping:
/// 0.33 s, and the report is byte for byte what it was.
#[test]
fn naming_the_moves_behind_gouges_stays_fast_with_a_rubbing_holder() {
    let found = root().join("tests/found");
    let (out, report) = run_json(
        &found.join("run-slow-deviation.nc"),
        &[
            "--stock",
            "40x30",
            "--tools",
            found.join("fuzz-run-tools.toml").to_str().unwrap(),
            "--target",
            found.join("shaft-target.toml").to_str().unwrap(),
        ],
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    let report = report.unwrap();
    assert_eq!(report["crashes"].as_array().unwrap().len(), 426);
    let gouges: Vec<(i64, f64)> = report["gouges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| (g["line"].as_i64().unwrap(), g["area_mm2"].as_f64().unwrap()))
        .collect();
    // the pecks of line 17 and the face cut of line 4 (the first move sweeping each)
    assert_eq!(gouges, vec![(17, 62.34375), (4, 99.861658)]);
}

/// found/hostile-exit1: a staircase of 0.001 mm steps under G42 with the default r0.4 nose
/// raises an interference alarm at every step (4 000). The terminal shows ten in full and
/// the count of the rest; the JSON lists the first 1 000 and says how many it left out; the
/// summary line counts them all.
#[test]
fn thousands_of_alarms_are_capped_on_the_terminal_and_in_the_report() {
    let mut text = String::from("O0001;\nG99 M03 S800 T0101;\nG00 X62 Z2;\nG42 G01 X20 Z0 F0.1;\n");
    for _ in 0..2000 {
        text.push_str("G01 W-0.001;\nG01 U0.001;\n");
    }
    text.push_str("G40 G00 X80;\nM30;\n");
    let (_dir, prog) = temp_program("stairs.nc", text.as_bytes());
    let (out, report) = run_json(&prog, &["--stock", "60x80"]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(out.stderr.matches("PS041").count(), 10, "{}", out.stderr);
    assert!(
        out.stderr.contains("… and 3990 more alarms"),
        "{}",
        out.stderr
    );
    assert!(out.stdout.contains("4000 alarm(s)"), "{}", out.stdout);
    let report = report.unwrap();
    assert_eq!(report["alarms"].as_array().unwrap().len(), 1000);
    assert!(report["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w["code"] == "LS-LIST-CAPPED"
            && w["message"] == "4000 alarms: the 1000 first are listed, 3000 more are not"));
}
