//! One program's job, read whole before any work: the blank, the tools, the expanded
//! program, the workholding and the intended part. Each reader prints its own message; a
//! job that cannot be read is not simulated (exit 2).

use crate::cli::{ProgramArgs, RunArgs};
use crate::diag;
use crate::input::{self, Loaded};

/// The program read with `tools`, and the tools as its moves use them: when it feeds a
/// tool whose tip came from its holder's hand letter clearly the other way along Z, read
/// again with the tip its feeds give, and a warning LS-HOLDER-HAND (docs/field-rules.md
/// §14: a left-hand holder mounted upside down, or behind the centre line with M04, cuts
/// toward the chuck); a tool with no entry that only cuts thread passes is taken for a
/// threading insert, one that only drills for a drill (`stock::ToolFromUse`,
/// docs/field-rules.md §17).
pub(crate) fn load_with_use(
    program: &ProgramArgs,
    path: &std::path::Path,
    tools: stock::ToolTable,
    start_tool: Option<u32>,
) -> Result<(stock::ToolTable, Loaded), ()> {
    let (tools, loaded) = load_with_hand_tips(program, path, tools, start_tool)?;
    let found = tools.tools_from_use(&loaded.toolpath);
    // the entries whose tip their moves gave (a table tool found is one: it has an entry)
    let tips: Vec<expander::Diagnostic> = found
        .iter()
        .filter(|f| tools.get(f.t).is_some())
        .map(|f| {
            expander::Diagnostic::new(
                loaded.toolpath.segments[f.first].span,
                "LS-STOCK",
                stock::tip_taken_note(f.t, &f.tool),
                match f.tool {
                    stock::Tool::Grooving(_) => {
                        format!(
                            "state T{:02}'s side in the tool table: shank_dir = \"-x\"",
                            f.t
                        )
                    }
                    _ => format!("state T{:02}'s tip in the tool table: tip = 2", f.t),
                },
            )
        })
        .collect();
    let tools = tools.with_tools_from_use(&found);
    // a boring bar compensates as one (its tip): the program read again with it
    if found
        .iter()
        .any(|f| matches!(f.tool, stock::Tool::Turning { .. }))
    {
        let mut again = input::load_program(program, path, &tools, start_tool)?;
        // (the holders' hands were read from the first reading)
        let hands = loaded.toolpath.warnings.into_iter();
        again
            .toolpath
            .warnings
            .extend(hands.filter(|w| w.code == "LS-HOLDER-HAND"));
        again.toolpath.warnings.extend(tips);
        return Ok((tools, again));
    }
    let mut loaded = loaded;
    loaded.toolpath.warnings.extend(tips);
    Ok((tools, loaded))
}

/// The program read with `tools`, and again with the tips its feeds give (above).
fn load_with_hand_tips(
    program: &ProgramArgs,
    path: &std::path::Path,
    tools: stock::ToolTable,
    start_tool: Option<u32>,
) -> Result<(stock::ToolTable, Loaded), ()> {
    let loaded = input::load_program(program, path, &tools, start_tool)?;
    let read = tools.tips_from_use(&loaded.toolpath.segments);
    if read.is_empty() {
        return Ok((tools, loaded));
    }
    let notes: Vec<expander::Diagnostic> = read
        .iter()
        .map(|r| hand_note(r, &tools, &loaded.toolpath.segments))
        .collect();
    let tools = tools.with_tips(&read);
    let mut loaded = input::load_program(program, path, &tools, start_tool)?;
    loaded.toolpath.warnings.extend(notes);
    Ok((tools, loaded))
}

/// The warning of a tool read with the other tip than its holder's hand gives.
fn hand_note(
    r: &stock::TipFromUse,
    tools: &stock::ToolTable,
    segments: &[expander::Segment],
) -> expander::Diagnostic {
    let (hand, usual, way) = match r.hand {
        3 | 2 => ("right-hand", "toward the chuck", "toward the tailstock"),
        _ => ("left-hand", "toward the tailstock", "toward the chuck"),
    };
    let (along, total) = match r.tip {
        3 | 2 => (r.toward_chuck, r.toward_chuck + r.toward_tailstock),
        _ => (r.toward_tailstock, r.toward_chuck + r.toward_tailstock),
    };
    let name = tools
        .designation(r.t)
        .map_or(String::new(), |d| format!(" ({d})"));
    expander::Diagnostic::new(
        segments[r.first].span,
        "LS-HOLDER-HAND",
        format!(
            "T{:02}{name}: a {hand} holder cuts {usual} mounted upright with M03 (tip {}), but the program feeds it {way} ({along:.1} of {total:.1} mm along Z): read as tip {}, as the holder cuts mounted upside down or behind the centre line with M04",
            r.t, r.hand, r.tip
        ),
        format!(
            "state the tip in the tool table: tip = {} (or check the holder's hand and the spindle's direction)",
            r.tip
        ),
    )
}

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
        let Ok((tools, loaded)) = load_with_use(&args.program, path, tools, args.tool) else {
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
