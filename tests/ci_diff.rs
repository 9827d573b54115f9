//! `latsim diff` and `run --baseline` (issue 34) on two revisions of a corpus program:
//! `fanuc-a/shaft-stepped-4` and the same with its Ø30/Ø36 shoulder moved 0.2 mm left
//! (line 14 `Z-25.` → `Z-25.2`). By hand: the new part lacks the band Z-25.2…-25 between
//! Ø30 and Ø36, 0.2 mm × (36 − 30)/2 mm = 0.6 mm² of the half section, 0.2 mm deep (the
//! r0.4 fillet the uncompensated nose leaves in the corner moves with the shoulder, so the
//! band's area stays 0.2 × 3 however its lower end is rounded); it is one region, cut by
//! the new program's line 14 (the changed line) and left by the old one's.

mod common;

use serde_json::Value;
use std::path::{Path, PathBuf};

const CHANGED_LINE: usize = 14;

/// Both revisions in a fresh folder.
struct Revisions {
    dir: tempfile::TempDir,
    old: PathBuf,
    new: PathBuf,
}

fn revisions() -> Revisions {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(common::asset("corpus/fanuc-a/shaft-stepped-4.nc")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[CHANGED_LINE - 1], "Z-25.;", "the shoulder's line");
    let mut moved: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    moved[CHANGED_LINE - 1] = "Z-25.2;".into();
    let old = dir.path().join("shaft-rev1.nc");
    let new = dir.path().join("shaft-rev2.nc");
    std::fs::write(&old, &text).unwrap();
    std::fs::write(&new, moved.join("\n") + "\n").unwrap();
    Revisions { dir, old, new }
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// `latsim <cmd> <sides…> <the corpus sidecar's flags> <extra…>`.
fn latsim(cmd: &str, sides: &[&Path], extra: &[&str]) -> common::Out {
    let tools = common::asset("corpus/tools/shop.toml");
    let mut args: Vec<&str> = vec![cmd];
    args.extend(sides.iter().map(|p| s(p)));
    args.extend([
        "--control",
        "fanuc-a",
        "--stock",
        "50x80",
        "--tools",
        s(&tools),
    ]);
    args.extend(extra);
    common::latsim(&args)
}

fn read_json(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn close(v: &Value, want: f64, tol: f64) -> bool {
    v.as_f64().is_some_and(|x| (x - want).abs() <= tol)
}

/// The moved shoulder: one lost region of 0.6 mm², 0.2 mm deep, over Z-25.2…-25 and
/// Ø30…36, made by the new program's changed line and left by the old program's same line;
/// exit 1. The other way round it is one gained region of the same size.
#[test]
fn a_moved_shoulder_is_one_region_named_by_the_changed_line() {
    let r = revisions();
    let json = r.dir.path().join("diff.json");
    let png = r.dir.path().join("diff.png");
    let out = latsim(
        "diff",
        &[&r.old, &r.new],
        &["--json", s(&json), "--png", s(&png)],
    );
    assert_eq!(out.code, 1, "{}\n{}", out.stdout, out.stderr);
    assert!(
        out.stdout
            .contains("PART DIFFERS — lost 0.6000 mm² in 1 region"),
        "{}",
        out.stdout
    );
    let d = read_json(&json);
    assert_eq!(d["verdict"], "differs");
    assert_eq!(d["gained"].as_array().unwrap().len(), 0, "{}", d["gained"]);
    let lost = d["lost"].as_array().unwrap();
    assert_eq!(lost.len(), 1, "{lost:?}");
    let l = &lost[0];
    assert!(close(&l["area_mm2"], 0.6, 0.002), "area {}", l["area_mm2"]);
    assert!(close(&l["depth_mm"], 0.2, 0.002), "depth {}", l["depth_mm"]);
    assert!(close(&l["z_min"], -25.2, 1e-3), "{}", l["z_min"]);
    assert!(
        close(&l["x_min"], 30.0, 1e-3) && close(&l["x_max"], 36.0, 1e-3),
        "{l}"
    );
    let lines = |k: &str| -> Vec<u64> {
        l[k].as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap())
            .collect()
    };
    assert!(lines("new_lines").contains(&(CHANGED_LINE as u64)), "{l}");
    assert!(lines("old_lines").contains(&(CHANGED_LINE as u64)), "{l}");
    // the picture: a 1600 × 1000 PNG
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 1600);
    assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 1000);

    let back = r.dir.path().join("back.json");
    let out = latsim("diff", &[&r.new, &r.old], &["--json", s(&back)]);
    assert_eq!(out.code, 1);
    let d = read_json(&back);
    assert_eq!(d["lost"].as_array().unwrap().len(), 0);
    let gained = d["gained"].as_array().unwrap();
    assert_eq!(gained.len(), 1);
    assert!(close(&gained[0]["area_mm2"], 0.6, 0.002));
    assert!(close(&d["gained_area_mm2"], 0.6, 0.002));
}

/// A program against itself: the same part, no region, no finding changed, exit 0.
#[test]
fn a_program_diffed_with_itself_is_the_same_part() {
    let r = revisions();
    let json = r.dir.path().join("same.json");
    let html = r.dir.path().join("same.html");
    let out = latsim(
        "diff",
        &[&r.old, &r.old],
        &["--json", s(&json), "--html", s(&html)],
    );
    assert_eq!(out.code, 0, "{}\n{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("SAME PART"), "{}", out.stdout);
    let d = read_json(&json);
    assert_eq!(d["verdict"], "same");
    assert!(d["lost"].as_array().unwrap().is_empty() && d["gained"].as_array().unwrap().is_empty());
    assert!(close(&d["cycle_time_s"]["change"], 0.0, 1e-9));
    assert!(d["findings"]["appeared"].as_array().unwrap().is_empty());
    assert!(d["findings"]["gone"].as_array().unwrap().is_empty());
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.contains("the parts agree within 0.01 mm") && page.contains("<svg"));
}

/// `run --baseline` against the old revision's saved report: the new revision fails with
/// exit 1 and its verdict line says what changed; the old one passes. Two saved reports
/// diff like the programs (their regions name no lines: a report holds no moves).
#[test]
fn run_against_a_baseline_report_fails_a_changed_part() {
    let r = revisions();
    let base = r.dir.path().join("base.json");
    let out = latsim("run", &[&r.old], &["--json", s(&base)]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let new_json = r.dir.path().join("rev2.json");
    let out = latsim(
        "run",
        &[&r.new],
        &["--json", s(&new_json), "--baseline", s(&base)],
    );
    assert_eq!(out.code, 1, "{}\n{}", out.stdout, out.stderr);
    let line = out.stdout.lines().last().unwrap();
    assert!(line.starts_with("shaft-rev2.nc: CLEAN — "), "{line}");
    assert!(
        line.contains("PART DIFFERS — lost 0.6000 mm² in 1 region, gained 0.0000 mm² in 0 regions"),
        "{line}"
    );
    let out = latsim(
        "run",
        &[&r.old],
        &["--reports", "none", "--baseline", s(&base)],
    );
    assert_eq!(out.code, 0, "{}", out.stdout);
    assert!(
        out.stdout.contains(": same part, cycle time +0.0 s"),
        "{}",
        out.stdout
    );

    let json = r.dir.path().join("reports.json");
    let out = common::latsim(&["diff", s(&base), s(&new_json), "--json", s(&json)]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    let d = read_json(&json);
    let lost = d["lost"].as_array().unwrap();
    assert_eq!(lost.len(), 1);
    // the reports' points are rounded to 10⁻⁶ mm: the same area
    assert!(
        close(&lost[0]["area_mm2"], 0.6, 0.002),
        "{}",
        lost[0]["area_mm2"]
    );
    assert!(lost[0]["new_lines"].as_array().unwrap().is_empty());
}

/// A batch against a folder of saved reports: each program is compared with its own
/// `<stem>.json`; one without a report there is a new program, not a failure.
#[test]
fn a_batch_compares_each_program_with_its_report_in_the_baseline_folder() {
    let r = revisions();
    let base = r.dir.path().join("baseline");
    let progs = r.dir.path();
    let out = latsim("run", &[progs], &["--out", s(&base), "--reports", "json"]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let out = latsim(
        "run",
        &[progs],
        &["--reports", "none", "--baseline", s(&base)],
    );
    assert_eq!(out.code, 0, "{}", out.stdout);
    assert_eq!(
        out.stdout.matches(": same part").count(),
        2,
        "{}",
        out.stdout
    );
    // revision 2 compared with revision 1's report, and a program the folder has no report of
    std::fs::copy(base.join("shaft-rev1.json"), base.join("shaft-rev2.json")).unwrap();
    std::fs::copy(&r.old, progs.join("shaft-rev3.nc")).unwrap();
    let out = latsim(
        "run",
        &[progs],
        &["--reports", "none", "--baseline", s(&base)],
    );
    assert_eq!(out.code, 1, "{}", out.stdout);
    let line = |stem: &str| {
        out.stdout
            .lines()
            .find(|l| l.starts_with(stem))
            .unwrap_or_else(|| panic!("{stem}: {}", out.stdout))
            .to_string()
    };
    assert!(line("shaft-rev1.nc").contains(": same part"));
    assert!(line("shaft-rev2.nc").contains("PART DIFFERS"));
    assert!(
        line("shaft-rev3.nc").contains("; no baseline ("),
        "{}",
        line("shaft-rev3.nc")
    );
}

/// Findings that appear and go away: a program whose rapid crashes into the face against
/// one that does not (both GSK corpus programs on a Φ40 bar).
#[test]
fn a_crash_that_appears_is_listed_with_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("d.json");
    let tools = common::asset("corpus/tools/shop.toml");
    let clean = common::asset("corpus/gsk980/clean-leadin-face.nc");
    let crash = common::asset("corpus/gsk980/fault-face-rapid.nc");
    let run = |a: &Path, b: &Path| {
        common::latsim(&[
            "diff",
            s(a),
            s(b),
            "--stock",
            "40x60",
            "--tools",
            s(&tools),
            "--json",
            s(&json),
        ])
    };
    let out = run(&clean, &crash);
    assert!(out.code == 0 || out.code == 1, "{}", out.stderr);
    let d = read_json(&json);
    let appeared = d["findings"]["appeared"].as_array().unwrap();
    assert!(
        appeared
            .iter()
            .any(|f| f["kind"] == "crash" && f["code"] == "LS-CRASH" && f["line"] == 7),
        "{appeared:?}"
    );
    assert_eq!(d["new_verdict"], "crash");
    assert_eq!(d["old_verdict"], "clean");
    run(&crash, &clean);
    let d = read_json(&json);
    let gone = d["findings"]["gone"].as_array().unwrap();
    assert!(
        gone.iter().any(|f| f["kind"] == "crash" && f["line"] == 7),
        "{gone:?}"
    );
    assert!(d["findings"]["appeared"]
        .as_array()
        .unwrap()
        .iter()
        .all(|f| f["kind"] != "crash"));
}
