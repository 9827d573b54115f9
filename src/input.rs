//! Reading the user's files: program, machine profile, tool table, blank. Each failure is
//! printed here with its place and a help line; the caller only sees `Err(())`.

use crate::cli::{IncrementArg, ProgramArgs, RunArgs, XModeArg};
use crate::diag::{self, Source};
use crate::library::Folders;
use expander::{Increment, Machine, Options, Toolpath};
use std::path::Path;
use std::sync::Arc;

/// Largest program file read (a million-move program is ~20 MB and peaks at ~430 MB, so
/// 64 MB at ~1.3 GB). Larger files are refused before they are read, so memory stays
/// bounded whatever is given.
const MAX_PROGRAM_BYTES: u64 = 64 * 1024 * 1024;
/// Largest TOML file read (blank, target, tool table, machine profile, variables): the
/// TOML reader builds a document tree of ~95 bytes per byte of text (a 100 000-vertex blank
/// profile, 2.6 MB, peaks at 250 MB), so 16 MB (600 000 vertices) stays near 1.5 GB.
const MAX_TABLE_BYTES: u64 = 16 * 1024 * 1024;

/// A read, parsed and expanded program.
pub(crate) struct Loaded {
    pub(crate) source: Source,
    /// The `--lib` folders, which know the files of the subprograms read from them.
    pub(crate) library: Option<Arc<Folders>>,
    pub(crate) machine: Machine,
    pub(crate) toolpath: Toolpath,
    pub(crate) blocks: usize,
    /// The encoding the program was read in (`UTF-8`, `GBK`, …; WHATWG names): for the
    /// report (its warning LS-ENCODING says it when it is not UTF-8).
    pub(crate) encoding: &'static str,
    /// How the program was read and expanded: what a re-run of it with a change needs
    /// (`rerun.rs`).
    pub(crate) read: gcode::ReadOptions,
    pub(crate) opts: Options,
}

/// Read a file whole, with a clear message when it is missing or too big.
fn read_bytes(path: &Path, what: &str) -> Result<Vec<u8>, ()> {
    let meta = std::fs::metadata(path).map_err(|e| {
        diag::print_plain(
            &format!("cannot read {what} {}: {e}", path.display()),
            "check the path",
        )
    })?;
    let (max, help) = if what == "program" {
        (
            MAX_PROGRAM_BYTES,
            "split the program into subprograms, or check that this is the right file",
        )
    } else {
        (
            MAX_TABLE_BYTES,
            "check that this is the right file (a blank or target profile of 600 000 points is more than any drawing needs)",
        )
    };
    if meta.len() > max {
        diag::print_plain(
            &format!(
                "{what} {} is {} bytes, more than latsim reads ({} MB)",
                path.display(),
                meta.len(),
                max / (1024 * 1024)
            ),
            help,
        );
        return Err(());
    }
    std::fs::read(path).map_err(|e| {
        diag::print_plain(
            &format!("cannot read {what} {}: {e}", path.display()),
            "check the path and its permissions",
        )
    })
}

/// Read a UTF-8 text file whole (a TOML table), with a clear message when it is missing,
/// too big or not text.
pub(crate) fn read_text(path: &Path, what: &str) -> Result<String, ()> {
    let bytes = read_bytes(path, what)?;
    String::from_utf8(bytes).map_err(|e| {
        // Show the bad byte in its line: the text before it is valid, so its offset holds
        // in the lossy copy too.
        let at = e.utf8_error().valid_up_to();
        let src = Source {
            name: path.display().to_string(),
            text: String::from_utf8_lossy(e.as_bytes()).into(),
        };
        diag::print_at(
            &src,
            at,
            char::REPLACEMENT_CHARACTER.len_utf8(),
            "encoding",
            &format!("{what} is not UTF-8 text: this byte is not a character"),
            "save the file as UTF-8",
            false,
        );
    })
}

/// Read a program file and decode it: UTF-8, the `--encoding` given, or the encoding
/// detected (`gcode::encoding`). A file no encoding reads is an error at its first bad byte.
fn read_program(path: &Path, args: &ProgramArgs) -> Result<gcode::Decoded, ()> {
    let forced = match &args.encoding {
        None => None,
        Some(label) => Some(gcode::encoding::encoding_for_label(label).ok_or_else(|| {
            diag::print_plain(
                &format!("--encoding {label}: no such encoding"),
                "give a WHATWG label: utf-8, gbk, gb18030, big5, shift_jis, euc-kr, windows-1252, iso-8859-2, …",
            )
        })?),
    };
    let bytes = read_bytes(path, "program")?;
    let binary = |b: &u8| *b < 0x20 && !matches!(b, b'\n' | b'\r' | b'\t' | 0x11..=0x14 | 0x1a);
    if forced.is_none() && std::str::from_utf8(&bytes).is_err() {
        // a text in another encoding holds no NUL or other binary control bytes
        if let Some(at) = bytes.iter().position(binary) {
            diag::print_plain(
                &format!(
                    "{}: the program is not UTF-8 text and byte {at} is binary (0x{:02X}): this is not a program text",
                    path.display(),
                    bytes[at]
                ),
                "give the NC program file, or its encoding with --encoding",
            );
            return Err(());
        }
    }
    gcode::decode(&bytes, forced).map_err(|e| {
        let src = Source {
            name: path.display().to_string(),
            text: String::from_utf8_lossy(&bytes).into(),
        };
        // the lossy copy keeps the offset of the first bad byte when the text before it is
        // ASCII; elsewhere the caret may sit a little off, the byte offset is in the message
        diag::print_at(
            &src,
            e.offset.min(src.text.len()),
            0,
            "encoding",
            &format!(
                "the program is not {} text: byte {} is not a character",
                e.encoding.name(),
                e.offset
            ),
            "give the file's encoding with --encoding (gbk, windows-1252, shift_jis, …)",
            false,
        );
    })
}

fn load_machine(args: &ProgramArgs) -> Result<Machine, ()> {
    let control = args.control.map(|c| c.control());
    let mut machine = match &args.machine {
        None => Machine::for_control(control.unwrap_or_default()),
        Some(path) => {
            let text = read_text(path, "machine profile")?;
            Machine::from_toml_for(&text, control).map_err(|e| {
                print_in_file(
                    path,
                    &text,
                    (e.line, e.column),
                    "machine",
                    &e.message,
                    "see the machine profile keys in README.md",
                );
            })?
        }
    };
    if let Some(mode) = args.x_mode {
        // LinuxCNC: the power-on G7/G8, which the interpreter changes as the program says
        machine.x_mode = match mode {
            XModeArg::Diameter => expander::XMode::Diameter,
            XModeArg::Radius => expander::XMode::Radius,
        };
    }
    if let Some(inc) = args.increment {
        machine.increment = match inc {
            IncrementArg::IsB => Increment::IsB,
            IncrementArg::IsC => Increment::IsC,
        };
    }
    Ok(machine)
}

/// `--vars FILE`: the common variables a run starts with, `"500" = 2.0` (or `500 = 2`).
fn load_vars(path: &Path) -> Result<Vec<(u32, f64)>, ()> {
    let text = read_text(path, "variables file")?;
    let fail = |message: String| {
        diag::print_plain(
            &format!("{}: {message}", path.display()),
            "write one common variable a line, e.g. 500 = 2.0 (#100–#199 and #500–#999)",
        );
    };
    let table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| fail(e.to_string()))?;
    let mut check = macro_b::Variables::new();
    let mut vars = Vec::with_capacity(table.len());
    for (key, value) in &table {
        let v = match value {
            toml::Value::Float(v) => *v,
            toml::Value::Integer(v) => *v as f64,
            _ => {
                fail(format!("#{key}: the value is not a number"));
                return Err(());
            }
        };
        let n: u32 = key
            .trim_start_matches('#')
            .parse()
            .map_err(|_| fail(format!("'{key}' is not a variable number")))?;
        check
            .load(n, v, gcode::Span::default())
            .map_err(|e| fail(e.message))?;
        vars.push((n, v));
    }
    Ok(vars)
}

/// Read, parse and expand the program. Parse errors and an empty program are `Err`.
pub(crate) fn load_program(
    args: &ProgramArgs,
    path: &Path,
    tools: &stock::ToolTable,
    start_tool: Option<u32>,
) -> Result<Loaded, ()> {
    let machine = load_machine(args)?;
    let decoded = read_program(path, args)?;
    // LinuxCNC switches between G7 and G8 in the program: its interpreter doubles a radius
    // X block by block, the reader reads X as written
    let x_radius =
        machine.x_mode == expander::XMode::Radius && machine.control != expander::Control::LinuxCnc;
    let (reading, encoding) = (reading_notes(&decoded, x_radius), decoded.encoding.name());
    // the decoded text is given up as it is copied into the shared one: one copy of the
    // program's text while it runs, not two (24 MB at 10⁶ moves, at the run's peak)
    let source = Source {
        name: path.display().to_string(),
        text: decoded.text.into(),
    };
    let macros = args.macros(machine.control);
    let vars = macro_vars(args, macros.is_some())?;
    let read = gcode::ReadOptions {
        decimal_comma: args.decimal_comma,
        macros,
        x_radius,
    };
    let program = parse(&source, read)?;
    let blocks = program.block_count();
    let library = library(args, &machine, path, source.text.len(), read)?;
    let opts = Options {
        block_delete: args.block_delete,
        tools: tools.facts(),
        library: library
            .clone()
            .map(|l| expander::LibraryRef(l as Arc<dyn expander::Library>)),
        start_tool: start_tool.or_else(|| tools.numbers().first().copied()),
        max_blocks: args.max_steps,
        max_segments: args.max_moves,
        vars,
        macros: macros.map(|d| macro_options(d, args.max_steps)),
    };
    let mut toolpath = expander::expand(&program, &machine, &opts);
    if toolpath.segments.is_empty() {
        not_a_program(&source)?;
    }
    toolpath.warnings.splice(0..0, reading);
    Ok(Loaded {
        source,
        library,
        machine,
        toolpath,
        blocks,
        encoding,
        read,
        opts,
    })
}

/// The `--vars` file's variables (only with macro B on).
fn macro_vars(args: &ProgramArgs, macros_on: bool) -> Result<Vec<(u32, f64)>, ()> {
    match &args.vars {
        Some(path) if macros_on => load_vars(path),
        Some(_) => {
            diag::print_plain(
                "--vars sets macro variables, and custom macro B is off",
                "run with --macro on, or a FANUC or Haas --control",
            );
            Err(())
        }
        None => Ok(vec![]),
    }
}

/// The program read into blocks; a parse error printed at its place; a file with no
/// blocks is an error too.
fn parse(source: &Source, read: gcode::ReadOptions) -> Result<gcode::Program, ()> {
    let program = gcode::parse_shared(Arc::clone(&source.text), read).map_err(|e| {
        diag::print_at(
            source,
            e.span.offset as usize,
            e.span.len as usize,
            "parse",
            &e.message,
            &e.help,
            false,
        );
    })?;
    if program.block_count() == 0 {
        diag::print_plain(
            &format!(
                "{}: nothing to simulate, the file has no blocks",
                source.name
            ),
            "give a program file with at least one block",
        );
        return Err(());
    }
    Ok(program)
}

/// The subprogram files of `--lib` (Haas `M98 (path)` looks next to the main program even
/// without it).
fn library(
    args: &ProgramArgs,
    machine: &Machine,
    path: &Path,
    main_len: usize,
    read: gcode::ReadOptions,
) -> Result<Option<Arc<Folders>>, ()> {
    // Haas `M98 (path)` and LinuxCNC `o<name> call` find files in the program's folder
    if args.lib.is_empty()
        && !matches!(
            machine.control,
            expander::Control::Haas | expander::Control::LinuxCnc
        )
    {
        return Ok(None);
    }
    let home = path.parent().unwrap_or(Path::new("."));
    match Folders::scan(&args.lib, home, main_len, read) {
        Ok(f) => Ok(Some(Arc::new(f))),
        Err(e) => {
            diag::print_plain(&e, "give --lib the folder that holds the subprogram files");
            Err(())
        }
    }
}

/// Macro B's options for a dialect, with the block budget.
fn macro_options(d: macro_b::Dialect, max_steps: usize) -> macro_b::Options {
    let mut o = match d {
        macro_b::Dialect::Haas => macro_b::Options::haas(),
        macro_b::Dialect::Fanuc => macro_b::Options::fanuc(),
        macro_b::Dialect::LinuxCnc => macro_b::Options::linuxcnc(),
    };
    o.limits.max_blocks = max_steps as u64;
    o
}

/// Warnings that say how the file was read when it is not the usual: its encoding when
/// not UTF-8, X as a radius. They open the report's warnings (JSON `warnings`).
fn reading_notes(decoded: &gcode::Decoded, x_radius: bool) -> Vec<expander::Diagnostic> {
    let top = expander::Span {
        line: 1,
        column: 1,
        offset: 0,
        len: 0,
    };
    let mut notes = vec![];
    if decoded.encoding != gcode::encoding::Encoding::for_label(b"utf-8").expect("utf-8") {
        let how = if decoded.guessed {
            "the file is not UTF-8: read as"
        } else {
            "read as"
        };
        notes.push(expander::Diagnostic::new(
            top,
            "LS-ENCODING",
            format!("{how} {}", decoded.encoding.name()),
            "if comments read wrong, give the file's encoding with --encoding",
        ));
    }
    if x_radius {
        notes.push(expander::Diagnostic::new(
            top,
            "LS-X-RADIUS",
            "X is read as a radius (x_mode = radius); the report gives diameters",
            "",
        ));
    }
    notes
}

/// A file with no motion that holds binary bytes (NUL and other control bytes beyond the
/// tape's flow control) is no program: exit 2, like an empty file (issue 31).
fn not_a_program(source: &Source) -> Result<(), ()> {
    let binary = source
        .text
        .chars()
        .filter(|&c| {
            c.is_control() && !matches!(c, '\n' | '\r' | '\t' | '\u{11}'..='\u{14}' | '\u{1a}')
        })
        .count();
    if binary == 0 {
        return Ok(());
    }
    diag::print_plain(
        &format!(
            "{}: nothing to simulate: no motion, and {binary} binary (control) bytes — this is not a program text",
            source.name
        ),
        "give the NC program file (a text of blocks such as G0 X50 Z2)",
    );
    Err(())
}

impl Loaded {
    /// The file a span's byte offset lies in (the main file or a `--lib` file), with the
    /// offset within it.
    pub(crate) fn source_at(&self, offset: usize) -> (std::borrow::Cow<'_, Source>, usize) {
        match self.library.as_ref().and_then(|l| l.place(offset)) {
            Some((src, local)) => (std::borrow::Cow::Owned(src), local),
            None => (std::borrow::Cow::Borrowed(&self.source), offset),
        }
    }

    /// `file:line` of a span, for terminal lines (the file a subprogram came from).
    pub(crate) fn place(&self, span: expander::Span) -> String {
        let (src, _) = self.source_at(span.offset as usize);
        format!("{}:{}", src.name, span.line)
    }

    fn print(&self, d: &expander::Diagnostic, warning: bool) {
        let (src, offset) = self.source_at(d.span.offset as usize);
        diag::print_at(
            &src,
            offset,
            d.span.len as usize,
            d.code,
            &d.message,
            &d.help,
            warning,
        );
    }
}

/// Print the interpreter's alarms (always) and warnings (unless quiet), the first ten of
/// each in full: a 4 000-step staircase under G42 raised 4 000 interference alarms, 55 000
/// lines of terminal output.
pub(crate) fn print_diagnostics(loaded: &Loaded, quiet: bool) {
    const SHOWN: usize = 10;
    let tp = &loaded.toolpath;
    let mut lists = vec![("alarms", &tp.alarms, false)];
    if !quiet {
        lists.push(("warnings", &tp.warnings, true));
    }
    for (what, list, warning) in lists {
        for d in list.iter().take(SHOWN) {
            loaded.print(d, warning);
        }
        if list.len() > SHOWN {
            eprintln!(
                "… and {} more {what} (all are in the report)",
                list.len() - SHOWN
            );
        }
    }
}

/// The tool table from `--tools`, or an empty one (every tool gets the documented default).
pub(crate) fn load_tools(path: Option<&Path>) -> Result<stock::ToolTable, ()> {
    let Some(path) = path else {
        return Ok(stock::ToolTable::empty());
    };
    let text = read_text(path, "tool table")?;
    stock::ToolTable::from_toml(&text).map_err(|e| print_stock_error(path, &text, &e))
}

/// The chuck and tailstock: `--chuck` (its compact form, or a file when it holds no `=`),
/// else the machine profile's.
pub(crate) fn load_workholding(
    args: &RunArgs,
    machine: &Machine,
) -> Result<expander::Workholding, ()> {
    let Some(spec) = &args.chuck else {
        return Ok(machine.workholding.clone());
    };
    let help = "give --chuck grip=LENGTH[,jaw=H,face=Z,od=D,depth=L,tail=Z,quill=D,quill_length=L] or a file with [chuck] and [tailstock] tables (README, \"Chuck and tailstock\")";
    if spec.contains('=') {
        return expander::Workholding::from_compact(spec)
            .map_err(|e| diag::print_plain(&e.message, help));
    }
    let path = Path::new(spec);
    let text = read_text(path, "chuck file")?;
    expander::Workholding::from_toml(&text).map_err(|e| {
        print_in_file(path, &text, (e.line, e.column), "chuck", &e.message, help);
    })
}

/// An error at a line and column of a file already read (a machine profile, a chuck file).
fn print_in_file(
    path: &Path,
    text: &str,
    (line, column): (u32, u32),
    code: &str,
    message: &str,
    help: &str,
) {
    let src = Source {
        name: path.display().to_string(),
        text: text.into(),
    };
    diag::print_line_col(&src, line as usize, column as usize, code, message, help);
}

/// The blank from `--stock`/`--bore`/`--stock-z` or `--stock-file`.
pub(crate) fn load_blank(args: &RunArgs) -> Result<stock::Blank, ()> {
    if let Some(path) = &args.stock_file {
        if crate::cad::is_dxf(path) {
            let rings = crate::cad::read_rings(path, args.dxf_x, crate::cad::Role::Blank)?;
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            return Ok(stock::Blank::from_rings(
                &rings,
                &format!("profile {name} (DXF)"),
            ));
        }
        let text = read_text(path, "stock file")?;
        return stock::Blank::from_profile_toml(&text, 0.001)
            .map_err(|e| print_stock_error(path, &text, &e));
    }
    let Some(dims) = &args.stock else {
        diag::print_plain("no blank given", "give the blank with --stock DIAMETERxLENGTH (e.g. --stock 125x110) or --stock-file profile.toml");
        return Err(());
    };
    let fail = |e: stock::StockError| diag::print_plain(&e.to_string(), e.help().unwrap_or(""));
    let (d, l) = stock::Blank::parse_dims(dims).map_err(fail)?;
    stock::Blank::bar(d, l, args.stock_z, args.bore).map_err(fail)
}

pub(crate) fn print_stock_error(path: &Path, text: &str, e: &stock::StockError) {
    let src = Source {
        name: path.display().to_string(),
        text: text.into(),
    };
    match e {
        stock::StockError::Toml {
            line,
            column,
            message,
            help,
            ..
        } => diag::print_line_col(&src, *line, *column, "toml", message, help),
        stock::StockError::Tool { line, .. } => diag::print_line_col(
            &src,
            *line,
            1,
            "tool",
            &e.to_string(),
            e.help().unwrap_or(""),
        ),
        other => diag::print_plain(
            &format!("{}: {other}", path.display()),
            other.help().unwrap_or(""),
        ),
    }
}
