//! The `check` and `expand` subcommands and the default outputs of `run`.

mod common;
use common::*;

#[test]
fn expand_csv_has_one_row_per_segment_in_program_coordinates() {
    let out = latsim(&[
        "expand",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let rows: Vec<&str> = out.stdout.lines().collect();
    assert_eq!(rows[0], "line,column,kind,z0,x0,z1,x1,cz,cx,dir,tool");
    assert_eq!(rows.len(), 1 + 17);
    // the R10 dome: G03 from (Z0, X10) to (Z-10, X30), centre (Z-10, X10)
    assert!(
        rows.contains(&"14,1,arc,0,10,-10,30,-10,10,ccw,1"),
        "{}",
        out.stdout
    );
}

#[test]
fn expand_json_rows() {
    let out = latsim(&[
        "expand",
        asset("programs/O0002.nc").to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    let rows = v.as_array().unwrap();
    // G90 X120 Z-110 F200 at line 3: rapid X to 120, feed to Z-110, feed X back, rapid Z back
    let line3: Vec<_> = rows
        .iter()
        .filter(|r| r["line"] == 3)
        .map(|r| r["kind"].as_str().unwrap())
        .collect();
    assert_eq!(line3, vec!["rapid", "feed", "feed", "rapid"]);
}

#[test]
fn check_counts_and_exit_status() {
    let out = latsim(&[
        "check",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0);
    assert!(
        out.stdout.contains("17 segments, 0 alarm(s)"),
        "{}",
        out.stdout
    );
    let (_dir, prog) = temp_program(
        "thread.nc",
        b"G99 M3 S300\nG0 X30 Z5\nG76 P010060 Q100 R0.05\nG76 X27.4 Z-20 P1300 Q300 F2\nM30\n",
    );
    let out = latsim(&["check", prog.to_str().unwrap()]);
    assert_eq!(out.code, 0, "the two-block G76 runs: {}", out.stderr);
    // seed 004 as printed runs with its G42 (the default nose, with a warning)
    let out = latsim(&["check", asset("programs/tnrc-seed004.nc").to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stderr.contains("LS-TNRC-DEFAULT"), "{}", out.stderr);
}

#[test]
fn increment_flag_is_accepted() {
    let out = latsim(&[
        "check",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
        "--increment",
        "is-c",
        "--quiet",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let out = latsim(&[
        "check",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
        "--increment",
        "is-x",
    ]);
    assert_eq!(out.code, 2);
}

#[test]
fn run_writes_all_four_reports_by_default() {
    let dir = tempfile::tempdir().unwrap();
    let out = latsim(&[
        "run",
        asset("programs/O0002.nc").to_str().unwrap(),
        "--stock",
        "125x110",
        "--tools",
        asset("tools/v35-sharp.toml").to_str().unwrap(),
        "--out",
        dir.path().to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    for ext in ["svg", "png", "json", "html"] {
        let p = dir.path().join(format!("O0002.{ext}"));
        assert!(
            std::fs::metadata(&p)
                .map(|m| m.len() > 100)
                .unwrap_or(false),
            "{} missing",
            p.display()
        );
    }
    let png = std::fs::read(dir.path().join("O0002.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    // no temporary files left behind
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 4);
    let html = std::fs::read_to_string(dir.path().join("O0002.html")).unwrap();
    assert!(
        html.contains("type=\"range\"") && html.contains("id=\"ls-data\""),
        "the HTML report has its slider and data"
    );
    // small programs carry stock snapshots for the slider
    assert!(
        html.contains("\"snapshots\":[{\"after\":0"),
        "snapshots missing"
    );
}

/// A run that writes only the JSON report leaves the toolpath out of the report (issue 16:
/// 48 bytes a move); the JSON is the one written beside the pictures, byte for byte.
#[test]
fn json_alone_is_the_json_written_with_the_pictures() {
    alone_and_with_the_others(&["json"]);
}

/// The reports of a run are made on threads of their own, the SVG, PNG and HTML page from
/// one drawing: each, made alone, is the same bytes, and the page holds the SVG.
#[test]
fn each_report_alone_is_the_report_written_with_the_others() {
    alone_and_with_the_others(&["svg", "png", "html"]);
}

/// Each report of `kinds` made alone is the one a run writing all four writes.
fn alone_and_with_the_others(kinds: &[&str]) {
    let all = tempfile::tempdir().unwrap();
    let program = asset("programs/O0002.nc");
    let tools = asset("tools/v35-sharp.toml");
    let run = |out: [&str; 2]| {
        let mut args = vec!["run", program.to_str().unwrap(), "--stock", "125x110"];
        args.extend(["--tools", tools.to_str().unwrap(), "--quiet"]);
        args.extend(out);
        let r = latsim(&args);
        assert_eq!(r.code, 0, "{}", r.stderr);
    };
    run(["--out", all.path().to_str().unwrap()]);
    for kind in kinds {
        let alone = tempfile::tempdir().unwrap();
        let file = alone.path().join(format!("O0002.{kind}"));
        run([&format!("--{kind}"), file.to_str().unwrap()]);
        assert_eq!(std::fs::read_dir(alone.path()).unwrap().count(), 1);
        let with_others = std::fs::read(all.path().join(format!("O0002.{kind}"))).unwrap();
        assert!(with_others.len() > 1000, "{kind}");
        assert!(std::fs::read(&file).unwrap() == with_others, "{kind}");
    }
    let svg = std::fs::read_to_string(all.path().join("O0002.svg")).unwrap();
    let page = std::fs::read_to_string(all.path().join("O0002.html")).unwrap();
    assert!(page.contains(&svg));
}

#[test]
fn machine_profile_errors_point_at_the_line() {
    let (dir, prog) = temp_program("p.nc", b"G0 X50 Z5\nM30\n");
    let m = dir.path().join("machine.toml");
    std::fs::write(&m, "increment = \"is-b\"\nrapid_q = 3\n").unwrap();
    let out = latsim(&[
        "check",
        prog.to_str().unwrap(),
        "--machine",
        m.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("machine.toml:2:1"), "{}", out.stderr);
}

/// Several programs (a folder and a file) run in parallel: one verdict line each, reports
/// for each in --out, and the worst exit status. A folder gives the files with an NC
/// extension and those named by a program number (`O0005`, no extension, as DNC software
/// saves them); its subfolders are named on stderr, not searched.
#[test]
fn run_on_a_folder_prints_one_verdict_line_per_program() {
    let src = tempfile::tempdir().unwrap();
    for f in ["O0002.nc", "seed004-contour.nc"] {
        std::fs::copy(asset(&format!("programs/{f}")), src.path().join(f)).unwrap();
    }
    std::fs::copy(asset("programs/O0002.nc"), src.path().join("O0005")).unwrap();
    std::fs::write(src.path().join("notes.md"), "not a program").unwrap();
    std::fs::write(src.path().join("O12ab"), "not a program number").unwrap();
    std::fs::create_dir(src.path().join("lib")).unwrap();
    std::fs::write(src.path().join("lib/O9001.nc"), "G0 X20 Z-10\nM99\n").unwrap();
    let (_d, crash) = temp_program(
        "crash.nc",
        b"G99 M3 S500 T0101\nG0 X50 Z5\nG0 X20 Z-10\nM30\n",
    );
    let out_dir = tempfile::tempdir().unwrap();
    let out = latsim(&[
        "run",
        src.path().to_str().unwrap(),
        crash.to_str().unwrap(),
        "--stock",
        "125x110",
        "--tools",
        asset("tools/v35-sharp.toml").to_str().unwrap(),
        "--out",
        out_dir.path().to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}\n{}", out.stdout, out.stderr);
    let lines: Vec<&str> = out.stdout.lines().collect();
    assert_eq!(lines.len(), 4, "{}", out.stdout);
    for clean in ["O0002.nc: CLEAN", "O0005: CLEAN"] {
        assert!(
            lines.iter().any(|l| l.starts_with(clean)),
            "{clean}\n{}",
            out.stdout
        );
    }
    assert!(
        out.stderr
            .contains("are not searched: lib (give a subfolder to run its programs)"),
        "{}",
        out.stderr
    );
    assert!(
        lines.iter().any(|l| l.starts_with("crash.nc: CRASH")),
        "{}",
        out.stdout
    );
    for stem in ["O0002", "O0005", "seed004-contour", "crash"] {
        assert!(
            out_dir.path().join(format!("{stem}.json")).exists(),
            "{stem}"
        );
    }
    // a single --json names one file: refused with several programs
    let out = latsim(&[
        "run",
        src.path().to_str().unwrap(),
        "--stock",
        "125x110",
        "--json",
        "x.json",
    ]);
    assert_eq!(out.code, 2);
}

#[test]
fn control_sets_the_power_on_feed_mode_and_is_named_in_the_report() {
    // F0.2 with no G98/G99: mm/min on a GSK 980TD (the default), mm/rev on a FANUC lathe.
    let (dir, prog) = temp_program(
        "feed.nc",
        b"T0101\nM3 S1000\nG0 X40 Z2\nG1 Z-50 F0.2\nG0 X100 Z100\nM30\n",
    );
    let time = |control: &str| {
        let json = dir.path().join(format!("{control}.json"));
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock",
            "50x60",
            "--control",
            control,
            "--json",
            json.to_str().unwrap(),
        ]);
        assert_eq!(out.code, 0, "{}", out.stderr);
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap();
        assert!(
            v["control"].as_str().unwrap().starts_with(control),
            "{}",
            v["control"]
        );
        v["cycle_time_s"].as_f64().unwrap()
    };
    let gsk = time("gsk980");
    let fanuc = time("fanuc-a");
    // 52 mm at 0.2 mm/min is 15 600 s; at 0.2 mm/rev and 1000 rev/min, 15.6 s.
    assert!(gsk > 15_000.0, "{gsk}");
    assert!(fanuc < 60.0 && fanuc > 15.0, "{fanuc}");
    let out = latsim(&["check", prog.to_str().unwrap(), "--control", "siemens"]);
    assert_eq!(out.code, 2, "{}", out.stderr);
}

/// `--reports` picks which reports `--out` writes for each program: JSON only for a batch
/// (rasterising the PNG is most of a small program's time), or none (verdict lines and the
/// exit status only); `none` with another kind is a usage error.
#[test]
fn reports_picks_what_out_writes() {
    let src = tempfile::tempdir().unwrap();
    for f in ["O0002.nc", "seed004-contour.nc"] {
        std::fs::copy(asset(&format!("programs/{f}")), src.path().join(f)).unwrap();
    }
    let run = |reports: &str, out_dir: &std::path::Path| {
        latsim(&[
            "run",
            src.path().to_str().unwrap(),
            "--stock",
            "125x110",
            "--tools",
            asset("tools/v35-sharp.toml").to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
            "--reports",
            reports,
        ])
    };
    let json_only = tempfile::tempdir().unwrap();
    // (seed004 on this bar ends with a finding: exit 1)
    let out = run("json", json_only.path());
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(out.stdout.lines().count(), 2, "{}", out.stdout);
    assert_eq!(
        files_in(json_only.path()),
        ["O0002.json", "seed004-contour.json"]
    );
    let two = tempfile::tempdir().unwrap();
    assert_eq!(run("svg,json", two.path()).code, 1);
    assert_eq!(
        files_in(two.path()),
        [
            "O0002.json",
            "O0002.svg",
            "seed004-contour.json",
            "seed004-contour.svg"
        ]
    );
    let none = tempfile::tempdir().unwrap();
    let out = run("none", none.path());
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(out.stdout.lines().count(), 2, "{}", out.stdout);
    assert!(files_in(none.path()).is_empty());
    let out = run("none,json", none.path());
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(out.stderr.contains("--reports none"), "{}", out.stderr);
    // it picks what --out writes: with a file named by --json it is refused, not ignored
    let out = latsim(&[
        "run",
        src.path().join("O0002.nc").to_str().unwrap(),
        "--stock",
        "125x110",
        "--json",
        none.path().join("x.json").to_str().unwrap(),
        "--reports",
        "svg",
    ]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(
        out.stderr.contains("--reports picks what --out writes"),
        "{}",
        out.stderr
    );
    assert!(files_in(none.path()).is_empty());
    // the JSON of a batch is the JSON of the same program run alone with all four reports
    let alone = tempfile::tempdir().unwrap();
    let out = latsim(&[
        "run",
        src.path().join("O0002.nc").to_str().unwrap(),
        "--stock",
        "125x110",
        "--tools",
        asset("tools/v35-sharp.toml").to_str().unwrap(),
        "--out",
        alone.path().to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        std::fs::read(alone.path().join("O0002.json")).unwrap(),
        std::fs::read(json_only.path().join("O0002.json")).unwrap()
    );
}

/// Field run 4: a facing pass that grazes the bar's face removes −2·10⁻⁶ mm² (boolean
/// noise, kept as it is in the JSON); the verdict line prints `removed 0.0 mm² / 0 mm³`,
/// never `-0.0`.
#[test]
fn the_verdict_line_never_prints_a_negative_zero_removal() {
    let program = "%\nO01011\nG20\nG28 U0.\nT101\nG50 S3000\nG96 S500 M03\nG00 X1.1 Z0.1\nG01 X-0.06 F0.006\nG00 X1.1 Z0.1\nM30\n%\n";
    let (_dir, path) = temp_program("graze.nc", program.as_bytes());
    let out = latsim(&[
        "run",
        path.to_str().unwrap(),
        "--stock",
        "25.4x50",
        "--control",
        "haas",
        "--reports",
        "none",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(
        out.stdout.contains("removed 0.0 mm² / 0 mm³"),
        "{}",
        out.stdout
    );
    assert!(!out.stdout.contains("-0"), "{}", out.stdout);
}
