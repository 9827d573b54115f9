//! `latsim expand`: the expanded toolpath, one row per segment, in program coordinates.

use crate::cli::{ExpandArgs, Format};
use crate::input;
use crate::{EXIT_CLEAN, EXIT_FINDINGS, EXIT_UNUSABLE};
use expander::{Motion, Segment};
use std::io::Write;

#[derive(serde::Serialize)]
struct Row {
    line: u32,
    column: u32,
    kind: &'static str,
    z0: f64,
    x0: f64,
    z1: f64,
    x1: f64,
    /// Arc centre (z, x) and direction; null/empty for lines.
    cz: Option<f64>,
    cx: Option<f64>,
    dir: Option<&'static str>,
    tool: u32,
}

fn round(v: f64) -> f64 {
    (v * 1e6).round() / 1e6 + 0.0
}

fn row(s: &Segment) -> Row {
    Row {
        line: s.span.line,
        column: s.span.column,
        kind: match s.motion {
            Motion::Rapid => "rapid",
            Motion::Feed if s.arc.is_some() => "arc",
            Motion::Feed => "feed",
            Motion::Thread => "thread",
        },
        z0: round(s.from.z),
        x0: round(2.0 * s.from.r),
        z1: round(s.to.z),
        x1: round(2.0 * s.to.r),
        cz: s.arc.map(|a| round(a.center.z)),
        cx: s.arc.map(|a| round(2.0 * a.center.r)),
        dir: s.arc.map(|a| if a.ccw { "ccw" } else { "cw" }),
        tool: s.tool,
    }
}

/// Print every segment; alarms go to stderr and make the exit status 1.
pub(crate) fn expand(args: &ExpandArgs) -> u8 {
    let Ok(tools) = input::load_tools(args.tools.as_deref()) else {
        return EXIT_UNUSABLE;
    };
    let [path] = args.program.programs.as_slice() else {
        crate::diag::print_plain("expand takes one program", "run expand once per program");
        return EXIT_UNUSABLE;
    };
    // the tools' tips read from the program's feeds as `run` reads them (LS-HOLDER-HAND)
    let Ok((_, loaded)) = crate::job::load_with_use(&args.program, path, tools, None) else {
        return EXIT_UNUSABLE;
    };
    input::print_diagnostics(&loaded, args.program.quiet);
    let rows = loaded.toolpath.segments.iter().map(row);
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let written = match args.format {
        Format::Json => serde_json::to_writer_pretty(&mut out, &rows.collect::<Vec<_>>())
            .map_err(std::io::Error::other)
            .and_then(|_| writeln!(out)),
        Format::Csv => (|| {
            writeln!(out, "line,column,kind,z0,x0,z1,x1,cz,cx,dir,tool")?;
            let opt = |v: Option<f64>| v.map(|v| v.to_string()).unwrap_or_default();
            for r in rows {
                writeln!(
                    out,
                    "{},{},{},{},{},{},{},{},{},{},{}",
                    r.line,
                    r.column,
                    r.kind,
                    r.z0,
                    r.x0,
                    r.z1,
                    r.x1,
                    opt(r.cz),
                    opt(r.cx),
                    r.dir.unwrap_or(""),
                    r.tool
                )?;
            }
            Ok(())
        })(),
    };
    if written.and_then(|_| out.flush()).is_err() {
        return EXIT_UNUSABLE;
    }
    if loaded.toolpath.alarms.is_empty() {
        EXIT_CLEAN
    } else {
        EXIT_FINDINGS
    }
}
