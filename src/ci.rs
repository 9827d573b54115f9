//! The run's CI reports, written once every program has run: `--junit F` and
//! `--sarif F`, rendered first and then written together like the other reports (whole or
//! not at all, never over an input).

use crate::cli::RunArgs;
use crate::outcome::Outcome;
use crate::{diag, write};
use std::path::PathBuf;

/// Write the CI reports the run asks for; the run's exit status `code`, or 2 when they
/// cannot be written (printed).
pub(crate) fn write(
    args: &RunArgs,
    outcomes: &[Outcome],
    code: u8,
    started: std::time::Instant,
    inputs: &[PathBuf],
) -> u8 {
    if args.junit.is_none() && args.sarif.is_none() {
        return code;
    }
    let seconds = started.elapsed().as_secs_f64();
    let cwd = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("/"));
    let mut docs: Vec<(&PathBuf, String)> = vec![];
    if let Some(path) = &args.junit {
        docs.push((path, crate::junit::junit(outcomes, seconds)));
    }
    if let Some(path) = &args.sarif {
        docs.push((path, crate::sarif::sarif(outcomes, code, &cwd)));
    }
    let mut staged = vec![];
    for (path, text) in docs {
        match write::stage(path, text.as_bytes(), inputs) {
            Ok(s) => staged.push(s),
            Err(e) => {
                diag::print_plain(&e, "choose another path for --junit or --sarif");
                return crate::EXIT_UNUSABLE;
            }
        }
    }
    match write::commit(staged) {
        Ok(()) => code,
        Err(e) => {
            diag::print_plain(&e, "check the output folder: free space, permissions");
            crate::EXIT_UNUSABLE
        }
    }
}
