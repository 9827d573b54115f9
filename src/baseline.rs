//! `run --baseline F|DIR`: which saved report each program is compared with, and the
//! comparison (`diff_cmd`'s) that adds to its verdict line.

use crate::cli::RunArgs;
use crate::diag;
use crate::outcome::Against;
use render::Report;
use std::path::PathBuf;

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
            details: vec![],
        }));
    }
    let old = crate::diff_cmd::Facts::of_json(&path)?;
    let new = crate::diff_cmd::Facts::of_report(&report.program, report);
    let moves = (job.loaded.toolpath.segments.as_slice(), &job.tools);
    let d = crate::diff_cmd::compare(&old, None, &new, Some(moves), args.tol);
    Ok(Some(Against {
        suffix: crate::diff_cmd::verdict_suffix(&d),
        details: crate::diff_cmd::summary_lines(&d)
            .into_iter()
            .skip(1)
            .collect(),
        diff: Some(d),
    }))
}
