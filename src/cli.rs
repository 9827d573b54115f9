//! The command line: flag names are a contract (spec/simulation.md).

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// latsim — 2D lathe toolpath simulator with material removal.
#[derive(Debug, Parser)]
#[command(name = "latsim", version, about, long_about = None)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Simulate programs on a blank and write the SVG, PNG, JSON and HTML reports.
    Run(Box<RunArgs>),
    /// Read and expand a program and report its alarms (no material removal).
    Check(CheckArgs),
    /// Print the expanded toolpath, one row per segment.
    Expand(ExpandArgs),
    /// What the part gained and lost between two programs (run with the same flags as
    /// `run`) or two JSON reports of earlier runs: regions, times and findings. Exit 0
    /// when the parts agree within --tol, 1 when they differ.
    Diff(Box<DiffArgs>),
}

/// `latsim diff OLD NEW [run's flags]`: `--json`, `--svg`, `--png` and `--html` name the
/// diff's own reports.
#[derive(Debug, Args)]
pub(crate) struct DiffArgs {
    #[command(flatten)]
    pub(crate) run: RunArgs,
}

/// Options that shape how a program is read and interpreted.
#[derive(Debug, Args, Clone)]
pub(crate) struct ProgramArgs {
    /// The program file(s) (FANUC / GSK lathe G-code). `run` also takes several files or
    /// folders and simulates them in parallel, one verdict line each.
    #[arg(required = true, num_args = 1..)]
    pub(crate) programs: Vec<PathBuf>,
    /// Machine profile (TOML): increment system, P/Q units, rapid rates, home position.
    #[arg(long, value_name = "F")]
    pub(crate) machine: Option<PathBuf>,
    /// The control the program is written for: its G-code system, power-on modes and
    /// cycle forms (spec/dialects.md §0). Wins over the machine profile's `control` key.
    #[arg(long, value_enum, value_name = "CONTROL")]
    pub(crate) control: Option<ControlArg>,
    /// Custom macro B (`#` variables, expressions, IF/GOTO/WHILE, G65): on by default for
    /// the FANUC and Haas controls, off for gsk980 (spec/dialects.md §0).
    #[arg(long = "macro", value_enum, value_name = "ON|OFF")]
    pub(crate) macro_b: Option<Switch>,
    /// Common variables to start with (custom macro B, spec/dialects.md §5.1): TOML such as
    /// `500 = 2.0` (#100–#199 and #500–#999; the rest start vacant).
    #[arg(long, value_name = "F")]
    pub(crate) vars: Option<PathBuf>,
    /// The block budget: a run that executes more blocks (macro statements included) ends
    /// with an alarm naming the loop.
    #[arg(long, value_name = "N", default_value_t = 10_000_000)]
    pub(crate) max_steps: usize,
    /// The move budget: a run that makes more moves (segments) ends with an alarm at the
    /// block that exceeded it; what was simulated until then is reported.
    #[arg(
        long,
        value_name = "N",
        default_value_t = 10_000_000,
        alias = "max-segments"
    )]
    pub(crate) max_moves: usize,
    /// Least input increment, overriding the machine profile.
    #[arg(long, value_enum, value_name = "SYSTEM")]
    pub(crate) increment: Option<IncrementArg>,
    /// A folder of subprograms (repeatable): `M98 P1234` / `G65 P1234` find `O1234`,
    /// `O1234.nc` (any NC extension) or the file whose first program number is 1234.
    #[arg(long = "lib", value_name = "DIR")]
    pub(crate) lib: Vec<PathBuf>,
    /// Skip blocks that start with '/'.
    #[arg(long)]
    pub(crate) block_delete: bool,
    /// Read a decimal comma (`F0,2`) as a decimal point throughout the file (German-style
    /// posts); without it a decimal comma is an error at its place.
    #[arg(long)]
    pub(crate) decimal_comma: bool,
    /// The program files' text encoding (`gbk`, `windows-1252`, `shift_jis`, `utf-8`, … any
    /// WHATWG label). Without it a file that is not UTF-8 is read in the encoding detected,
    /// which a warning (LS-ENCODING) names.
    #[arg(long, value_name = "LABEL")]
    pub(crate) encoding: Option<String>,
    /// What X is: `diameter` (the usual) or `radius` (FANUC parameter DIA off, Linux CNC G8,
    /// CNC trainers); overrides the machine profile's `x_mode`. Reports stay in diameters.
    #[arg(long, value_enum, value_name = "MODE")]
    pub(crate) x_mode: Option<XModeArg>,
    /// No progress bar and no warnings on the terminal.
    #[arg(long, short)]
    pub(crate) quiet: bool,
}

#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    #[command(flatten)]
    pub(crate) program: ProgramArgs,
    /// Tool table (TOML): nose radii and tips for G41/G42.
    #[arg(long, value_name = "F")]
    pub(crate) tools: Option<PathBuf>,
}

/// `--control`: the spellings of `expander::Control::key`.
#[derive(Debug, Clone, Copy, ValueEnum)]
pub(crate) enum ControlArg {
    /// GSK 980TD (system A, G98 at power-on): the default
    #[value(name = "gsk980")]
    Gsk980,
    /// FANUC lathe, G-code system A (G99 at power-on)
    #[value(name = "fanuc-a")]
    FanucA,
    /// FANUC lathe, G-code system B
    #[value(name = "fanuc-b")]
    FanucB,
    /// FANUC lathe, G-code system C
    #[value(name = "fanuc-c")]
    FanucC,
    /// Haas lathe (system A plus Haas one-block cycles)
    #[value(name = "haas")]
    Haas,
}

impl ControlArg {
    /// The interpreter's control.
    pub(crate) fn control(self) -> expander::Control {
        match self {
            Self::Gsk980 => expander::Control::Gsk980,
            Self::FanucA => expander::Control::FanucA,
            Self::FanucB => expander::Control::FanucB,
            Self::FanucC => expander::Control::FanucC,
            Self::Haas => expander::Control::Haas,
        }
    }
}

/// An on/off switch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Switch {
    /// on
    On,
    /// off
    Off,
}

impl ProgramArgs {
    /// Custom macro B's rules for this control, or `None` when it is off: `--macro`, else
    /// on for FANUC and Haas and off for GSK.
    pub(crate) fn macros(&self, control: expander::Control) -> Option<macro_b::Dialect> {
        let on = match self.macro_b {
            Some(s) => s == Switch::On,
            None => control != expander::Control::Gsk980,
        };
        on.then_some(if control == expander::Control::Haas {
            macro_b::Dialect::Haas
        } else {
            macro_b::Dialect::Fanuc
        })
    }
}

/// `--x-mode`: the spellings of the profile's `x_mode`.
#[derive(Debug, Clone, Copy, ValueEnum, PartialEq, Eq)]
pub(crate) enum XModeArg {
    /// X is the diameter
    Diameter,
    /// X is the radius
    Radius,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub(crate) enum IncrementArg {
    /// 0.001 mm
    #[value(name = "is-b")]
    IsB,
    /// 0.0001 mm
    #[value(name = "is-c")]
    IsC,
}

#[derive(Debug, Args)]
pub(crate) struct RunArgs {
    #[command(flatten)]
    pub(crate) program: ProgramArgs,
    /// Bar blank `DIAMETERxLENGTH` in mm, right face at Z0 (e.g. 125x110).
    #[arg(long, value_name = "DxL")]
    pub(crate) stock: Option<String>,
    /// Z of the blank's right face (default 0).
    #[arg(
        long,
        value_name = "Z",
        allow_hyphen_values = true,
        default_value_t = 0.0
    )]
    pub(crate) stock_z: f64,
    /// Bore diameter: makes the bar a tube.
    #[arg(long, value_name = "D")]
    pub(crate) bore: Option<f64>,
    /// Blank profile for castings and forgings: a profile TOML (start and path in program
    /// coordinates) or a DXF drawing of the half section (`.dxf`).
    #[arg(long, value_name = "F", conflicts_with = "stock")]
    pub(crate) stock_file: Option<PathBuf>,
    /// Tool table (TOML, [[tool]] entries).
    #[arg(long, value_name = "F")]
    pub(crate) tools: Option<PathBuf>,
    /// The intended part (profile TOML or `.dxf`, as --stock-file); default: the shapes the program
    /// defines (G70–G73 finishing shapes, G75.1 grooves).
    #[arg(long, value_name = "F")]
    pub(crate) target: Option<PathBuf>,
    /// Tool to use before the program's first T word (default: the table's first entry).
    #[arg(long, value_name = "N")]
    pub(crate) tool: Option<u32>,
    /// Write the JSON report here.
    #[arg(long, value_name = "F")]
    pub(crate) json: Option<PathBuf>,
    /// Write the SVG report here.
    #[arg(long, value_name = "F")]
    pub(crate) svg: Option<PathBuf>,
    /// Write the PNG report here.
    #[arg(long, value_name = "F")]
    pub(crate) png: Option<PathBuf>,
    /// Write the self-contained HTML report (picture, tables, move slider) here.
    #[arg(long, value_name = "F")]
    pub(crate) html: Option<PathBuf>,
    /// Folder for the default outputs <prog>.svg, <prog>.png, <prog>.json, <prog>.html
    /// (default: current folder).
    #[arg(long, value_name = "DIR")]
    pub(crate) out: Option<PathBuf>,
    /// Which reports `--out` writes for each program, comma-separated (default: all four);
    /// `none` writes no file, for a batch whose verdict lines and exit status are all a CI
    /// gate reads.
    #[arg(long, value_name = "KINDS", value_delimiter = ',')]
    pub(crate) reports: Option<Vec<ReportKind>>,
    /// Write the final half section (layer PART) and the intended part (layer INTENDED)
    /// as a DXF drawing (DXF version 2000) here.
    #[arg(long, value_name = "F")]
    pub(crate) dxf: Option<PathBuf>,
    /// How a DXF's Y maps to the lathe's X, for `--stock-file`/`--target` `.dxf` files and
    /// `--dxf`: the radius (a true half section) or the diameter.
    #[arg(long, value_enum, value_name = "AXIS", default_value_t = DxfXArg::Radius)]
    pub(crate) dxf_x: DxfXArg,
    /// Chuck and tailstock, replacing the machine profile's `[chuck]` and `[tailstock]`:
    /// `grip=20,jaw=25,face=-80,od=200,depth=100,tail=2,quill=40,quill_length=150` (grip:
    /// the blank length held from its left end or `face`; tail: the centre's tip Z), or a
    /// TOML file with those tables. A tool entering them, or cutting inside the jaws, crashes.
    #[arg(long, value_name = "SPEC|F", allow_hyphen_values = true)]
    pub(crate) chuck: Option<String>,
    /// Write a `JUnit` XML report of the run here: one test case per program (a gouge, crash
    /// or alarm fails it), for the CI's test reporter.
    #[arg(long, value_name = "F")]
    pub(crate) junit: Option<PathBuf>,
    /// Write the run's findings as SARIF 2.1.0 here (alarms, crashes, gouges; leftovers and
    /// warnings as notes), for code scanning.
    #[arg(long, value_name = "F")]
    pub(crate) sarif: Option<PathBuf>,
    /// Compare the final part with a saved JSON report (`latsim diff`): a `.json` file for
    /// one program, or a folder holding each program's `<prog>.json`. A part that differs
    /// by more than --tol fails the run (exit 1); the verdict line says what changed.
    #[arg(long, value_name = "F|DIR")]
    pub(crate) baseline: Option<PathBuf>,
    /// Deviation tolerance in mm for gouges and leftovers.
    #[arg(long, value_name = "MM", default_value_t = 0.01, allow_hyphen_values = true, value_parser = positive_length)]
    pub(crate) tol: f64,
}

/// `--reports`: a report kind `--out` writes.
#[derive(Debug, Clone, Copy, ValueEnum, PartialEq, Eq)]
pub(crate) enum ReportKind {
    /// The picture as SVG.
    Svg,
    /// The picture rasterised.
    Png,
    /// The machine-readable report.
    Json,
    /// The self-contained page with the move slider.
    Html,
    /// No report file.
    None,
}

/// `--dxf-x`: what a DXF drawing's Y is.
#[derive(Debug, Clone, Copy, ValueEnum, PartialEq, Eq)]
pub(crate) enum DxfXArg {
    /// Y is the radius (the true half section)
    Radius,
    /// Y is the diameter
    Diameter,
}

#[derive(Debug, Clone, Copy, ValueEnum, PartialEq, Eq)]
pub(crate) enum Format {
    /// Comma-separated values with a header row.
    Csv,
    /// A JSON array of objects.
    Json,
}

#[derive(Debug, Args)]
pub(crate) struct ExpandArgs {
    #[command(flatten)]
    pub(crate) program: ProgramArgs,
    /// Tool table (TOML): nose radii and tips for G41/G42.
    #[arg(long, value_name = "F")]
    pub(crate) tools: Option<PathBuf>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    pub(crate) format: Format,
}

/// A length that must be positive and finite (`--tol`).
fn positive_length(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!(
            "`{text}` is not a positive length: give the deviation tolerance in mm, e.g. --tol 0.01"
        )),
    }
}
