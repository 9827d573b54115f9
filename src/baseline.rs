//! Saved reports read back: `run --baseline F|DIR` (which report each program is compared
//! with) and the JSON side of `latsim diff`. A JSON report holds what a diff needs: the
//! final part, the cycle and tool times, the verdict and the findings (see README, "The
//! JSON report"); reading it back gives the run's `render::Report` with those fields.

use crate::cli::RunArgs;
use crate::diag;
use render::{Crash, Diagnostic, Gouge, Report, Shape};
use serde::Deserialize;
use std::path::{Path, PathBuf};

type Pair = [Option<f64>; 2];

#[derive(Deserialize)]
struct Polygon {
    outer: Vec<Pair>,
    #[serde(default)]
    holes: Vec<Vec<Pair>>,
}

#[derive(Deserialize)]
struct Diag {
    #[serde(default)]
    line: u32,
    #[serde(default)]
    column: u32,
    #[serde(default)]
    code: String,
    #[serde(default)]
    message: String,
}

#[derive(Deserialize)]
struct CrashJ {
    line: u32,
    #[serde(default)]
    column: u32,
    z: Option<f64>,
    x: Option<f64>,
    area_mm2: Option<f64>,
    depth_mm: Option<f64>,
    #[serde(default)]
    body: Option<String>,
    #[serde(default)]
    obstacle: Option<String>,
    /// A possible crash (its tool's size assumed): written only when true.
    #[serde(default)]
    assumed_tool: bool,
}

#[derive(Deserialize)]
struct GougeJ {
    line: u32,
    z: Option<f64>,
    x: Option<f64>,
    area_mm2: Option<f64>,
    depth_mm: Option<f64>,
    #[serde(default)]
    assumed_tool: bool,
}

/// The fields of the report a diff reads; the others are let be.
#[derive(Deserialize)]
struct Doc {
    #[serde(default)]
    program: String,
    verdict: String,
    #[serde(rename = "final")]
    final_part: Vec<Polygon>,
    cycle_time_s: Option<f64>,
    #[serde(default)]
    tools: Vec<String>,
    #[serde(default)]
    alarms: Vec<Diag>,
    #[serde(default)]
    warnings: Vec<Diag>,
    #[serde(default)]
    crashes: Vec<CrashJ>,
    #[serde(default)]
    rapid_cuts: Vec<CrashJ>,
    #[serde(default)]
    gouges: Vec<GougeJ>,
}

/// A JSON report written by `latsim run`, read back; a file that is not one is an error
/// at its line and column (printed).
pub(crate) fn read(path: &Path, max_bytes: u64) -> Result<Report, ()> {
    let failed = |e: &dyn std::fmt::Display| {
        diag::print_plain(
            &format!("cannot read the report {}: {e}", path.display()),
            "give a .json report written by `latsim run` (--json F, or --out DIR)",
        );
    };
    let size = std::fs::metadata(path).map_err(|e| failed(&e))?.len();
    if size > max_bytes {
        failed(&format!(
            "{size} bytes, more than latsim reads ({max_bytes})"
        ));
        return Err(());
    }
    let text = std::fs::read(path).map_err(|e| failed(&e))?;
    let doc: Doc = serde_json::from_slice(&text).map_err(|e| {
        failed(&format!(
            "line {} column {}: not a latsim JSON report: {e}",
            e.line(),
            e.column()
        ))
    })?;
    report(doc).map_err(|e| failed(&e))
}

/// The report the document holds.
fn report(doc: Doc) -> Result<Report, String> {
    let verdict = match doc.verdict.as_str() {
        "clean" => render::Verdict::Clean,
        "alarm" => render::Verdict::Alarm,
        "crash" => render::Verdict::Crash,
        "gouge" => render::Verdict::Gouge,
        v => return Err(format!("unknown verdict `{v}`")),
    };
    let ring = |r: &[Pair]| -> Result<Vec<[f64; 2]>, String> {
        r.iter()
            .map(|p| match p {
                [Some(z), Some(x)] => Ok([*z, x / 2.0]),
                _ => Err("a point of the final part is null (not a finite number)".to_string()),
            })
            .collect()
    };
    let mut final_part = vec![];
    for p in &doc.final_part {
        final_part.push(Shape {
            outer: ring(&p.outer)?,
            holes: p.holes.iter().map(|h| ring(h)).collect::<Result<_, _>>()?,
        });
    }
    let f = |v: Option<f64>| v.unwrap_or(f64::NAN);
    let diag = |d: &Diag| Diagnostic {
        line: d.line,
        column: d.column,
        code: d.code.clone(),
        message: d.message.clone(),
    };
    let crash = |c: &CrashJ| Crash {
        line: c.line,
        column: c.column,
        z: f(c.z),
        r: f(c.x) / 2.0,
        area_mm2: f(c.area_mm2),
        depth_mm: f(c.depth_mm),
        body: c.body.clone(),
        obstacle: c.obstacle.clone(),
        tool: vec![],
        assumed: c.assumed_tool,
        // a baseline is compared by place and size: why and the fix are the new run's
        cause: None,
        remedy: None,
    };
    Ok(Report {
        program: doc.program,
        verdict,
        final_part,
        cycle_time_s: f(doc.cycle_time_s),
        tools: doc.tools,
        alarms: doc.alarms.iter().map(diag).collect(),
        warnings: doc.warnings.iter().map(diag).collect(),
        crashes: doc.crashes.iter().map(crash).collect(),
        rapid_cuts: doc.rapid_cuts.iter().map(crash).collect(),
        gouges: doc
            .gouges
            .iter()
            .map(|g| Gouge {
                line: g.line,
                z: f(g.z),
                r: f(g.x) / 2.0,
                area_mm2: f(g.area_mm2),
                depth_mm: f(g.depth_mm),
                assumed: g.assumed_tool,
                cause: None,
                remedy: None,
            })
            .collect(),
        ..Report::default()
    })
}

/// The saved report a program of the run is compared with: `--baseline`'s file, or
/// `<stem>.json` in its folder; `None` without `--baseline`.
pub(crate) fn path_for(args: &RunArgs, stem: &str) -> Option<PathBuf> {
    let b = args.baseline.as_ref()?;
    Some(if b.is_dir() {
        b.join(format!("{stem}.json"))
    } else {
        b.clone()
    })
}

/// Whether `--baseline` fits the run (a file for one program, a folder for any number);
/// prints the problem.
pub(crate) fn usable(args: &RunArgs, programs: usize) -> bool {
    let Some(b) = &args.baseline else {
        return true;
    };
    let problem = if b.is_dir() {
        None
    } else if !b.is_file() {
        Some(format!(
            "--baseline {}: no such file or folder",
            b.display()
        ))
    } else if programs > 1 {
        Some(format!(
            "--baseline {} is one report: it takes one program",
            b.display()
        ))
    } else {
        None
    };
    if let Some(p) = &problem {
        diag::print_plain(
            p,
            "give --baseline a .json report for one program, or a folder holding <prog>.json for each program of the run",
        );
    }
    problem.is_none()
}

/// A run compared with its baseline: what the verdict line adds, and the diff when there
/// was a baseline to compare with.
pub(crate) struct Against {
    /// `; against base/part.json: same part, …`, or the note that there is no baseline.
    pub(crate) suffix: String,
    /// The diff; `None`: the baseline folder holds no report of this program.
    pub(crate) diff: Option<render::DiffReport>,
}

impl Against {
    /// Whether the part differs from the baseline's (a failed run).
    pub(crate) fn differs(&self) -> bool {
        self.diff.as_ref().is_some_and(render::DiffReport::differs)
    }
}

/// Compare a run (its report and moves) with its baseline, when `--baseline` is given. A
/// folder without this program's report is a note (a new program); a report that cannot
/// be read is an error (printed).
pub(crate) fn against(
    args: &RunArgs,
    stem: &str,
    report: &Report,
    job: &crate::job::Job,
) -> Result<Option<Against>, ()> {
    let Some(path) = path_for(args, stem) else {
        return Ok(None);
    };
    if !path.exists() {
        return Ok(Some(Against {
            suffix: format!("; no baseline ({} does not exist)", path.display()),
            diff: None,
        }));
    }
    let old = crate::diff_cmd::Facts::of_json(&path)?;
    let new = crate::diff_cmd::Facts::of_report(&report.program, report);
    let moves = (job.loaded.toolpath.segments.as_slice(), &job.tools);
    let d = crate::diff_cmd::compare(&old, None, &new, Some(moves), args.tol);
    Ok(Some(Against {
        suffix: crate::diff_cmd::verdict_suffix(&d),
        diff: Some(d),
    }))
}
