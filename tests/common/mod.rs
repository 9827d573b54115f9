//! Shared helpers of the end-to-end tests: run the CLI, run the pipeline as a library,
//! build hand-computed expected polygons.
#![allow(dead_code, unreachable_pub)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The files under `dir` (every depth) whose name ends in `.ext`, sorted, leaving out
/// folders named in `skip`.
pub fn files_under(dir: &Path, ext: &str, skip: &[&str]) -> Vec<PathBuf> {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    let mut out = vec![];
    for p in entries {
        if p.is_dir() {
            if !p.file_name().is_some_and(|n| skip.iter().any(|s| n == *s)) {
                out.extend(files_under(&p, ext, skip));
            }
        } else if p.extension().is_some_and(|e| e == ext) {
            out.push(p);
        }
    }
    out
}

/// A file under `assets/`.
pub fn asset(rel: &str) -> PathBuf {
    root().join("assets").join(rel)
}

/// Result of one CLI call.
pub struct Out {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// Run the `latsim` binary with `args`.
pub fn latsim(args: &[&str]) -> Out {
    let out = Command::new(env!("CARGO_BIN_EXE_latsim"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("latsim runs");
    Out {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Write `text` as `name` in a fresh temporary folder and return its path (the folder lives
/// as long as the returned guard).
pub fn temp_program(name: &str, text: &[u8]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    (dir, path)
}

/// Parse and expand with the tool table's noses and blades, the first entry as start tool,
/// like the CLI.
pub fn expand(
    program: &str,
    machine: &expander::Machine,
    tools: &stock::ToolTable,
) -> expander::Toolpath {
    let p = gcode::parse(program).expect("program parses");
    let opts = expander::Options {
        tools: tools.facts(),
        start_tool: tools.numbers().first().copied(),
        ..Default::default()
    };
    expander::expand(&p, machine, &opts)
}

/// [`expand`], then the library pipeline `latsim run` calls (`analysis::pipeline`): the
/// removal and what the run concludes (intents, deviation, crashes, threads, verdict),
/// against the program's own shapes.
#[allow(dead_code)]
pub fn judge(
    program: &str,
    machine: &expander::Machine,
    blank: &stock::Blank,
    tools: &stock::ToolTable,
) -> (expander::Toolpath, stock::Simulation, analysis::Findings) {
    let tp = expand(program, machine, tools);
    let settings = analysis::Settings {
        blank,
        tools,
        machine,
        fixture: None,
        tol: 0.01,
    };
    let (sim, findings) = analysis::pipeline(
        &tp,
        &analysis::Intents::Program,
        &settings,
        &stock::SimOptions::default(),
        &mut |_| {},
    );
    (tp, sim, findings)
}

/// [`expand`] and the removal alone, in-process; alarms are left to the caller.
pub fn pipeline(
    program: &str,
    machine: &expander::Machine,
    blank: &stock::Blank,
    tools: &stock::ToolTable,
) -> (expander::Toolpath, stock::Simulation) {
    let tp = expand(program, machine, tools);
    let sim = stock::simulate(
        blank,
        tools,
        &tp.segments,
        &stock::SimOptions::default(),
        &mut |_| {},
    );
    (tp, sim)
}

/// [`pipeline`] on `machine`, asserting the program ran without alarm.
pub fn simulate_with(
    program: &str,
    machine: &expander::Machine,
    blank: &stock::Blank,
    tools: &stock::ToolTable,
) -> (expander::Toolpath, stock::Simulation) {
    let (tp, sim) = pipeline(program, machine, blank, tools);
    assert!(tp.alarms.is_empty(), "alarms: {:?}", tp.alarms);
    (tp, sim)
}

/// Compare the final part with `want`: Hausdorff distance ≤ 0.01 mm and area of symmetric
/// difference ≤ `sym_max` mm², no crash; prints the measures under `label`.
pub fn assert_part(
    label: &str,
    tp: &expander::Toolpath,
    sim: &stock::Simulation,
    want: &[stock::Shape],
    sym_max: f64,
) {
    let sym = stock::symmetric_difference_area(&sim.final_shapes, want);
    let h = stock::hausdorff(&sim.final_shapes, want);
    eprintln!(
        "{label}: {} segments, symmetric difference {sym:.6} mm², Hausdorff {h:.5} mm",
        tp.segments.len()
    );
    assert!(sim.crashes.is_empty(), "{label}: crashes {:?}", sim.crashes);
    assert!(
        h <= 0.01 && sym <= sym_max,
        "{label}: Hausdorff {h}, symmetric difference {sym}"
    );
}

/// [`simulate_with`] on the default machine.
pub fn simulate(
    program: &str,
    blank: &stock::Blank,
    tools: &stock::ToolTable,
) -> (expander::Toolpath, stock::Simulation) {
    simulate_with(program, &expander::Machine::default(), blank, tools)
}

/// Read an asset as text.
pub fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap()
}

/// Centre of an arc of radius `r` (≤ 180°) from `a` to `b`, counter-clockwise if `ccw`,
/// written out here so the expected geometry does not reuse the interpreter's code.
pub fn arc_centre(a: [f64; 2], b: [f64; 2], r: f64, ccw: bool) -> [f64; 2] {
    let (dz, dr) = (b[0] - a[0], b[1] - a[1]);
    let c = (dz * dz + dr * dr).sqrt();
    let h = (r * r - c * c / 4.0).sqrt();
    let s = if ccw { 1.0 } else { -1.0 };
    [
        (a[0] + b[0]) / 2.0 - s * h * dr / c,
        (a[1] + b[1]) / 2.0 + s * h * dz / c,
    ]
}

/// Points of an arc from `a` to `b` about `centre` (exclusive of `a`, inclusive of `b`), every `step` rad.
pub fn arc_points(a: [f64; 2], b: [f64; 2], centre: [f64; 2], ccw: bool, out: &mut Vec<[f64; 2]>) {
    let r = ((a[0] - centre[0]).powi(2) + (a[1] - centre[1]).powi(2)).sqrt();
    let t0 = (a[1] - centre[1]).atan2(a[0] - centre[0]);
    let mut t1 = (b[1] - centre[1]).atan2(b[0] - centre[0]);
    if ccw && t1 < t0 {
        t1 += std::f64::consts::TAU;
    }
    if !ccw && t1 > t0 {
        t1 -= std::f64::consts::TAU;
    }
    let n = 2000;
    for i in 1..n {
        let t = t0 + (t1 - t0) * i as f64 / n as f64;
        out.push([centre[0] + r * t.cos(), centre[1] + r * t.sin()]);
    }
    out.push(b);
}

/// A shape from one counter-clockwise or clockwise ring (orientation fixed here).
pub fn shape(mut ring: Vec<[f64; 2]>) -> stock::Shape {
    let a: f64 = ring
        .iter()
        .zip(ring.iter().cycle().skip(1))
        .map(|(p, q)| p[0] * q[1] - q[0] * p[1])
        .sum();
    if a < 0.0 {
        ring.reverse();
    }
    stock::Shape {
        outer: ring,
        holes: vec![],
    }
}

/// The programmed profile of seed 004 on a Φ36 × 40 bar, computed by hand in (z, r):
/// Φ10 at Z0, the R10 dome to Φ30 at Z−10, Φ30 to Z−17.639, the concave R10 to
/// Φ32.111 at Z−22.111, the 45° line to Φ33.803 at Z−23.803, the convex R14 to Φ35.914 at
/// Z−28.275, Φ35.914 to Z−35, then the bar (Φ36) to Z−40.
pub fn seed004_profile() -> stock::Shape {
    let p = |z: f64, x: f64| [z, x / 2.0];
    let mut ring = vec![p(-40.0, 0.0), p(0.0, 0.0), p(0.0, 10.0)];
    // G03 X30 Z-10 R10: centre (Z-10, r5), a quarter circle.
    arc_points(p(0.0, 10.0), p(-10.0, 30.0), [-10.0, 5.0], true, &mut ring);
    ring.push(p(-17.639, 30.0));
    let (a, b) = (p(-17.639, 30.0), p(-22.111, 32.111));
    arc_points(a, b, arc_centre(a, b, 10.0, false), false, &mut ring);
    ring.push(p(-23.803, 33.803));
    let (a, b) = (p(-23.803, 33.803), p(-28.275, 35.914));
    arc_points(a, b, arc_centre(a, b, 14.0, true), true, &mut ring);
    ring.extend([p(-35.0, 35.914), p(-35.0, 36.0), p(-40.0, 36.0)]);
    shape(ring)
}

/// The names of the entries of `dir`, sorted.
pub fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// `latsim run prog <args> --json <a temporary file>`: the outcome and the JSON report,
/// when one was written.
pub fn run_json(prog: &Path, args: &[&str]) -> (Out, Option<serde_json::Value>) {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("r.json");
    let mut all = vec!["run", prog.to_str().unwrap()];
    all.extend_from_slice(args);
    all.extend(["--json", json.to_str().unwrap()]);
    let out = latsim(&all);
    let report = std::fs::read_to_string(&json)
        .ok()
        .map(|t| serde_json::from_str(&t).expect("the report is JSON"));
    (out, report)
}

/// `latsim run` on the program text `program` with `args` (`--quiet` added) and its JSON
/// report; panics with the error output when no report was written.
pub fn report_of(program: &str, args: &[&str]) -> serde_json::Value {
    let (dir, path) = temp_program("p.nc", program.as_bytes());
    let _keep = dir;
    let mut all = args.to_vec();
    all.push("--quiet");
    let (out, report) = run_json(&path, &all);
    report.unwrap_or_else(|| panic!("{}", out.stderr))
}

/// The messages of a JSON report's warnings of this code.
pub fn warning_messages<'a>(v: &'a serde_json::Value, code: &str) -> Vec<&'a str> {
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == code)
        .map(|w| w["message"].as_str().unwrap())
        .collect()
}
