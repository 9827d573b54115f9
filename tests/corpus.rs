//! The corpus of shop-style programs in `assets/corpus/` (issues 11 and 13).
//!
//! Every `<name>.nc` with a sidecar `<name>.toml` is run through the `latsim` binary with the
//! sidecar's flags; the JSON report is checked against the sidecar's `[expect]` table.
//! `status = "expected"` programs must meet it exactly; `status = "pending"` programs must NOT
//! meet it yet (a ratchet: when one starts passing, this test fails and says to promote it).
//! Format of the sidecars: `assets/corpus/README.md`.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value as Json;
use toml::Value as Toml;

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/corpus")
}

/// The sidecars of the corpus: each `.toml` beside its `.nc` (the `tools` folders hold
/// tool tables).
fn sidecars(dir: &Path, out: &mut Vec<PathBuf>) {
    out.extend(
        common::files_under(dir, "toml", &["tools"])
            .into_iter()
            .filter(|p| p.with_extension("nc").exists()),
    );
}

/// Flags `latsim run` has today.
fn run_help() -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_latsim"))
        .args(["run", "--help"])
        .output()
        .unwrap();
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn has_flag(help: &str, flag: &str) -> bool {
    help.split(|c: char| c.is_whitespace() || c == ',' || c == '=')
        .any(|w| {
            w == flag || w.starts_with(&format!("{flag}=")) || w.starts_with(&format!("{flag}<"))
        })
}

fn num(v: &Toml) -> Option<f64> {
    v.as_float().or_else(|| v.as_integer().map(|i| i as f64))
}

/// Runs one program; `Err` says why it cannot meet its expectation (missing flag, no report).
fn run(sidecar: &Path, side: &Toml, help: &str) -> Result<Json, String> {
    let dir = sidecar.parent().unwrap();
    let prog = sidecar.with_extension("nc");
    let tmp = tempfile::tempdir().unwrap();
    let json = tmp.path().join("report.json");
    let mut args: Vec<String> = vec!["run".into(), prog.display().to_string()];
    let rel = |s: &str| dir.join(s).display().to_string();
    let mut flag = |name: &str, val: String| -> Result<(), String> {
        if !has_flag(help, name) {
            return Err(format!("`latsim run` has no {name} yet"));
        }
        args.push(name.into());
        args.push(val);
        Ok(())
    };
    let control = side
        .get("control")
        .and_then(Toml::as_str)
        .unwrap_or("gsk980");
    if control != "gsk980" {
        flag("--control", control.into())?;
    }
    if let Some(s) = side.get("stock").and_then(Toml::as_str) {
        flag("--stock", s.into())?;
    }
    if let Some(s) = side.get("stock_file").and_then(Toml::as_str) {
        flag("--stock-file", rel(s))?;
    }
    if let Some(z) = side.get("stock_z").and_then(num) {
        flag("--stock-z", z.to_string())?;
    }
    if let Some(b) = side.get("bore").and_then(num) {
        flag("--bore", b.to_string())?;
    }
    if let Some(s) = side.get("tools").and_then(Toml::as_str) {
        flag("--tools", rel(s))?;
    }
    if let Some(s) = side.get("machine").and_then(Toml::as_str) {
        flag("--machine", rel(s))?;
    }
    if let Some(libs) = side.get("lib").and_then(Toml::as_array) {
        for l in libs {
            flag("--lib", rel(l.as_str().unwrap()))?;
        }
    }
    args.push("--json".into());
    args.push(json.display().to_string());
    args.push("--quiet".into());
    let out = Command::new(env!("CARGO_BIN_EXE_latsim"))
        .args(&args)
        .output()
        .unwrap();
    let text = std::fs::read_to_string(&json).map_err(|_| {
        format!(
            "no report (exit {:?}): {}",
            out.status.code(),
            String::from_utf8_lossy(&out.stderr)
                .lines()
                .take(3)
                .collect::<Vec<_>>()
                .join(" | ")
        )
    })?;
    serde_json::from_str(&text).map_err(|e| format!("bad JSON: {e}"))
}

/// Report entries of one finding kind.
fn findings<'a>(report: &'a Json, kind: &str) -> Vec<&'a Json> {
    let key = match kind {
        "crash" => "crashes",
        "gouge" => "gouges",
        "rapid_scrape" => "rapid_cuts",
        "alarm" => "alarms",
        other => panic!("unknown finding kind {other}"),
    };
    report[key]
        .as_array()
        .map(|a| a.iter().collect())
        .unwrap_or_default()
}

/// Distance from point p to segment ab, in (z, x) mm.
fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    };
    let (cx, cy) = (a.0 + t * dx, a.1 + t * dy);
    ((p.0 - cx).powi(2) + (p.1 - cy).powi(2)).sqrt()
}

fn sample(poly: &[(f64, f64)], closed: bool) -> Vec<(f64, f64)> {
    let mut pts = Vec::new();
    let n = poly.len();
    let segs = if closed { n } else { n.saturating_sub(1) };
    for i in 0..segs {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let len = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        let k = (len / 0.05).ceil().max(1.0) as usize;
        for j in 0..k {
            let t = j as f64 / k as f64;
            pts.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
    pts.extend(poly.last());
    pts
}

/// Hausdorff distance between the expected outline and the final section's boundary within
/// the expected outline's Z span, leaving out the boundary that lies on the axis (x = 0).
/// Both are given as (z, diameter); the distance is measured in the section (z, radius), in mm.
fn hausdorff(report: &Json, expected: &[(f64, f64)]) -> f64 {
    let zmin = expected.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) - 1e-6;
    let zmax = expected
        .iter()
        .map(|p| p.0)
        .fold(f64::NEG_INFINITY, f64::max)
        + 1e-6;
    let mut rings: Vec<Vec<(f64, f64)>> = Vec::new();
    for poly in report["final"].as_array().into_iter().flatten() {
        let ring = |r: &Json| -> Vec<(f64, f64)> {
            r.as_array()
                .unwrap()
                .iter()
                .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap() / 2.0))
                .collect()
        };
        rings.push(ring(&poly["outer"]));
        for h in poly["holes"].as_array().into_iter().flatten() {
            rings.push(ring(h));
        }
    }
    let mut fin: Vec<((f64, f64), (f64, f64))> = Vec::new();
    for r in &rings {
        for i in 0..r.len() {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            if a.1.abs() < 1e-6 && b.1.abs() < 1e-6 {
                continue; // on the axis
            }
            fin.push((a, b));
        }
    }
    if fin.is_empty() {
        return f64::INFINITY;
    }
    let expected: Vec<(f64, f64)> = expected.iter().map(|&(z, x)| (z, x / 2.0)).collect();
    let expected = &expected[..];
    let exp_pts = sample(expected, false);
    let d1 = exp_pts
        .iter()
        .map(|&p| {
            fin.iter()
                .map(|&(a, b)| seg_dist(p, a, b))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    let mut d2: f64 = 0.0;
    for &(a, b) in &fin {
        for p in sample(&[a, b], false) {
            if p.0 < zmin || p.0 > zmax || p.1.abs() < 1e-6 {
                continue;
            }
            let d = expected
                .windows(2)
                .map(|w| seg_dist(p, w[0], w[1]))
                .fold(f64::INFINITY, f64::min);
            d2 = d2.max(d);
        }
    }
    d1.max(d2)
}

/// Every way the report misses the sidecar's expectation (empty: it meets it).
fn misses(report: &Json, expect: &Toml) -> Vec<String> {
    let mut m = Vec::new();
    let verdict = expect
        .get("verdict")
        .and_then(Toml::as_str)
        .expect("[expect] verdict");
    if report["verdict"].as_str() != Some(verdict) {
        m.push(format!(
            "verdict {} (expected {verdict})",
            report["verdict"]
        ));
    }
    let exp: Vec<&Toml> = expect
        .get("finding")
        .and_then(Toml::as_array)
        .map(|a| a.iter().collect())
        .unwrap_or_default();
    // Exactly the listed crashes and gouges: no more, no fewer.
    for kind in ["crash", "gouge", "rapid_scrape", "alarm"] {
        let want: Vec<&&Toml> = exp
            .iter()
            .filter(|f| f.get("kind").and_then(Toml::as_str) == Some(kind))
            .collect();
        let got = findings(report, kind);
        if (kind == "crash" || kind == "gouge" || !want.is_empty()) && got.len() != want.len() {
            let lines: Vec<String> = got.iter().map(|g| format!("{}", g["line"])).collect();
            m.push(format!(
                "{} {kind}(s) at lines [{}] (expected {})",
                got.len(),
                lines.join(","),
                want.len()
            ));
        }
        for f in want {
            let line = f.get("line").and_then(Toml::as_integer).unwrap();
            let hit = got.iter().find(|g| g["line"].as_i64() == Some(line));
            let Some(hit) = hit else {
                m.push(format!("no {kind} at line {line}"));
                continue;
            };
            if let Some(d) = f.get("depth_mm").and_then(num) {
                let tol = f.get("depth_tol").and_then(num).unwrap_or(0.05);
                match hit["depth_mm"].as_f64() {
                    Some(got) if (got - d).abs() <= tol => {}
                    Some(got) => m.push(format!(
                        "{kind} line {line}: depth {got:.3} (expected {d} ± {tol})"
                    )),
                    None => m.push(format!("{kind} line {line}: the report gives no depth")),
                }
            }
            // issue 33: the cause's kind, and whether a checked remedy is given
            if let Some(want) = f.get("cause").and_then(Toml::as_str) {
                let got = hit["cause"]["kind"].as_str().unwrap_or("none");
                if got != want {
                    m.push(format!("{kind} line {line}: cause {got} (expected {want})"));
                }
            }
            if let Some(want) = f.get("remedy").and_then(Toml::as_str) {
                let got = if hit["remedy"]["verified"].as_bool() == Some(true) {
                    "verified"
                } else {
                    "none"
                };
                if got != want {
                    m.push(format!(
                        "{kind} line {line}: remedy {got} (expected {want})"
                    ));
                }
            }
        }
    }
    if let Some(a) = expect.get("removed_area_mm2").and_then(num) {
        let tol = expect.get("area_tol").and_then(num).unwrap_or(0.5);
        match report["removed_area_mm2"].as_f64() {
            Some(got) if (got - a).abs() <= tol => {}
            got => m.push(format!("removed area {got:?} (expected {a} ± {tol})")),
        }
    }
    if let Some(p) = expect.get("final_profile").and_then(Toml::as_array) {
        let pts: Vec<(f64, f64)> = p
            .iter()
            .map(|q| {
                let q = q.as_array().unwrap();
                (num(&q[0]).unwrap(), num(&q[1]).unwrap())
            })
            .collect();
        let tol = expect.get("hausdorff_mm").and_then(num).unwrap_or(0.05);
        let h = hausdorff(report, &pts);
        if h > tol {
            m.push(format!(
                "final profile off by {h:.3} mm (Hausdorff, expected ≤ {tol})"
            ));
        }
    }
    m
}

#[test]
fn corpus() {
    let help = run_help();
    let mut files = Vec::new();
    sidecars(&corpus_dir(), &mut files);
    assert!(
        files.len() >= 40,
        "the corpus has {} programs, expected at least 40",
        files.len()
    );
    let (mut ok, mut pending) = (0, 0);
    let mut failures = Vec::new();
    for sc in &files {
        let name = sc
            .strip_prefix(corpus_dir())
            .unwrap()
            .with_extension("")
            .display()
            .to_string();
        let text = std::fs::read_to_string(sc).unwrap();
        let side: Toml = toml::from_str(&text).unwrap_or_else(|e| panic!("{name}.toml: {e}"));
        let status = side
            .get("status")
            .and_then(Toml::as_str)
            .unwrap_or("pending");
        let expect = side
            .get("expect")
            .unwrap_or_else(|| panic!("{name}.toml: no [expect]"));
        let result = run(sc, &side, &help).map(|r| misses(&r, expect));
        match (status, result) {
            ("expected", Ok(m)) if m.is_empty() => ok += 1,
            ("expected", Ok(m)) => failures.push(format!("{name}: {}", m.join("; "))),
            ("expected", Err(e)) => failures.push(format!("{name}: {e}")),
            ("pending", Ok(m)) if m.is_empty() => failures.push(format!(
                "{name} now meets its expectation: promote {name} to expected (was pending: {})",
                side.get("pending").and_then(Toml::as_str).unwrap_or("?")
            )),
            ("pending", Ok(m)) => {
                pending += 1;
                eprintln!("pending {name}: {}", m.join("; "));
            }
            ("pending", Err(e)) => {
                pending += 1;
                eprintln!("pending {name}: {e}");
            }
            (s, _) => failures.push(format!("{name}: unknown status {s:?}")),
        }
    }
    println!("corpus: {ok} expected ok, {pending} pending");
    eprintln!("corpus: {ok} expected ok, {pending} pending");
    assert!(
        failures.is_empty(),
        "corpus failures:\n{}",
        failures.join("\n")
    );
}

/// `latsim run FOLDER` (the batch a shop's CI runs, issue 11): every dialect folder of the
/// corpus under its control, one verdict line per program, never "unusable" (exit 2), and
/// each program's JSON report byte-identical to its run on its own with the same flags.
#[test]
fn corpus_folders_run_as_batches() {
    let bin = env!("CARGO_BIN_EXE_latsim");
    let root = corpus_dir();
    let common = |out: &Path| -> Vec<String> {
        [
            "--tools",
            root.join("tools/shop.toml").to_str().unwrap(),
            "--stock",
            "60x100",
            "--lib",
            root.join("subprograms/lib").to_str().unwrap(),
            "--quiet",
            "--out",
            out.to_str().unwrap(),
        ]
        .iter()
        .map(ToString::to_string)
        .collect()
    };
    let mut programs = 0;
    for (folder, control) in [
        ("gsk980", "gsk980"),
        ("fanuc-a", "fanuc-a"),
        ("fanuc-b", "fanuc-b"),
        ("fanuc-c", "fanuc-c"),
        ("haas", "haas"),
        ("subprograms", "fanuc-a"),
        ("macro", "fanuc-a"),
    ] {
        let dir = root.join(folder);
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|e| e == "nc"))
            .collect();
        files.sort();
        let batch_out = tempfile::tempdir().unwrap();
        let o = Command::new(bin)
            .args(["run", dir.to_str().unwrap(), "--control", control])
            .args(common(batch_out.path()))
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&o.stdout);
        let code = o.status.code().unwrap_or(-1);
        assert!(code == 0 || code == 1, "{folder}: exit {code}\n{stdout}");
        assert_eq!(
            stdout.lines().count(),
            files.len(),
            "{folder}: one verdict line per program\n{stdout}"
        );
        for f in &files {
            let name = f.file_name().unwrap().to_string_lossy().into_owned();
            assert!(
                stdout.lines().any(|l| l.starts_with(&format!("{name}: "))),
                "{folder}: no verdict line for {name}\n{stdout}"
            );
            let stem = f.file_stem().unwrap().to_string_lossy().into_owned();
            let one_out = tempfile::tempdir().unwrap();
            let one = Command::new(bin)
                .args(["run", f.to_str().unwrap(), "--control", control])
                .args(common(one_out.path()))
                .output()
                .unwrap();
            assert!(one.status.code().unwrap_or(-1) <= 1, "{name}");
            let read = |d: &Path| std::fs::read(d.join(format!("{stem}.json"))).unwrap();
            assert!(
                read(batch_out.path()) == read(one_out.path()),
                "{folder}/{name}: the batch JSON differs from the single run's"
            );
            programs += 1;
        }
    }
    assert!(programs >= 70, "only {programs} corpus programs");
}
