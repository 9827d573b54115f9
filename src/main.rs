//! `latsim`: simulate a FANUC/GSK lathe program on a blank and report the part it makes.
//!
//! The CLI reads the job (`job`, `input`: files and flags), runs the library pipeline
//! (`gcode` → `expander` → `analysis::pipeline`, which removes with `stock` and concludes),
//! maps the findings onto `render`'s report (`report`) and owns progress, atomic writing
//! and exit codes. It decides nothing about the part.

mod baseline;
mod cad;
mod ci;
mod cli;
mod diag;
mod diff_cmd;
mod expand_cmd;
mod input;
mod job;
mod junit;
mod library;
mod outcome;
mod report;
mod rerun;
mod run;
mod sarif;
mod write;

use clap::Parser;
use std::process::ExitCode;

/// Exit status: the run finished and found nothing wrong.
const EXIT_CLEAN: u8 = 0;
/// The run finished but found an alarm, crash or gouge (the report is written).
const EXIT_FINDINGS: u8 = 1;
/// Nothing could be simulated (usage, unreadable input, parse error).
const EXIT_UNUSABLE: u8 = 2;

fn main() -> ExitCode {
    diag::install_panic_hook();
    let args = match cli::Cli::try_parse() {
        Ok(a) => a,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() {
                EXIT_UNUSABLE
            } else {
                EXIT_CLEAN
            });
        }
    };
    let code = match args.command {
        cli::Command::Run(a) => run::run(&a),
        cli::Command::Check(a) => run::check(&a),
        cli::Command::Expand(a) => expand_cmd::expand(&a),
        cli::Command::Diff(a) => diff_cmd::diff(&a),
    };
    ExitCode::from(code)
}
