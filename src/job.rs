//! One program's job, read whole before any work: the blank, the tools, the expanded
//! program, the workholding and the intended part. Each reader prints its own message; a
//! job that cannot be read is not simulated (exit 2).

use crate::cli::RunArgs;
use crate::diag;
use crate::input::{self, Loaded};

/// Chord tolerance of a `--target` profile's arcs, mm: as fine as a DXF drawing's arcs are
/// read (`tooling_iso::dxf_io::ReadOptions`), so the intended part drawn and written back
/// with `--dxf` stays within 0.0005 mm of the true arcs.
const TARGET_CHORD_TOL: f64 = 0.0001;

/// Everything a run of one program is given.
pub(crate) struct Job {
    pub(crate) blank: stock::Blank,
    pub(crate) tools: stock::ToolTable,
    pub(crate) loaded: Loaded,
    pub(crate) fixture: Option<analysis::Fixture>,
    pub(crate) intents: analysis::Intents,
}

impl Job {
    /// Reads the job of `path` (in a batch, an unreadable program says so on its verdict
    /// line).
    pub(crate) fn load(args: &RunArgs, path: &std::path::Path, batch: bool) -> Result<Self, ()> {
        let blank = input::load_blank(args)?;
        let tools = input::load_tools(args.tools.as_deref())?;
        let Ok(loaded) = input::load_program(&args.program, path, &tools, args.tool) else {
            if batch {
                println!(
                    "{}: UNUSABLE — not simulated (see the message above)",
                    path.display()
                );
            }
            return Err(());
        };
        let workholding = input::load_workholding(args, &loaded.machine)?;
        let fixture = analysis::Fixture::new(&workholding, &blank).map_err(|e| {
            diag::print_plain(
                &e.to_string(),
                "the jaws hold the blank from the chuck face (default: the blank's left end) over grip mm: check --stock-z, face and grip",
            );
        })?;
        let intents = load_intents(args)?;
        Ok(Self {
            blank,
            tools,
            loaded,
            fixture,
            intents,
        })
    }

    /// What the analysis is given besides the program.
    pub(crate) fn settings(&self, tol: f64) -> analysis::Settings<'_> {
        analysis::Settings {
            blank: &self.blank,
            tools: &self.tools,
            machine: &self.loaded.machine,
            fixture: self.fixture.as_ref(),
            tol,
        }
    }
}

/// `--target F` (a profile TOML or a DXF drawing), else the program's own shapes.
fn load_intents(args: &RunArgs) -> Result<analysis::Intents, ()> {
    let Some(path) = &args.target else {
        return Ok(analysis::Intents::Program);
    };
    if crate::cad::is_dxf(path) {
        let rings = crate::cad::read_rings(path, args.dxf_x, crate::cad::Role::Target)?;
        let part = stock::Blank::from_rings(&rings, "").shapes;
        return Ok(analysis::Intents::Target(part));
    }
    let text = input::read_text(path, "target")?;
    let part = stock::profile_from_toml(&text, TARGET_CHORD_TOL)
        .map_err(|e| input::print_stock_error(path, &text, &e))?;
    Ok(analysis::Intents::Target(part))
}
