//! `latsim run` and `latsim check`.

use crate::cli::{CheckArgs, ReportKind, RunArgs};
use crate::diag;
use crate::input;
use crate::write;
use crate::{EXIT_CLEAN, EXIT_FINDINGS, EXIT_UNUSABLE};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

/// `latsim check`: read and expand, print alarms; no removal.
pub(crate) fn check(args: &CheckArgs) -> u8 {
    let Ok(tools) = input::load_tools(args.tools.as_deref()) else {
        return EXIT_UNUSABLE;
    };
    args.program
        .programs
        .iter()
        .map(|path| check_one(args, path, &tools))
        .max()
        .unwrap_or(EXIT_UNUSABLE)
}

fn check_one(args: &CheckArgs, path: &Path, tools: &stock::ToolTable) -> u8 {
    let Ok(loaded) = input::load_program(&args.program, path, tools, None) else {
        return EXIT_UNUSABLE;
    };
    input::print_diagnostics(&loaded, args.program.quiet);
    let tp = &loaded.toolpath;
    println!(
        "{}: {} blocks, {} segments, {} alarm(s), {} warning(s)",
        loaded.source.name,
        loaded.blocks,
        tp.segments.len(),
        tp.alarms.len(),
        tp.warnings.len()
    );
    if tp.alarms.is_empty() {
        EXIT_CLEAN
    } else {
        EXIT_FINDINGS
    }
}

/// Where each report goes: the explicit paths, or all four into `--out`.
fn outputs(args: &RunArgs, stem: &str) -> Vec<(PathBuf, &'static str)> {
    let explicit: Vec<(PathBuf, &'static str)> = [
        (&args.svg, "svg"),
        (&args.png, "png"),
        (&args.json, "json"),
        (&args.html, "html"),
        (&args.dxf, "dxf"),
    ]
    .into_iter()
    .filter_map(|(p, kind)| p.clone().map(|p| (p, kind)))
    .collect();
    if explicit.iter().any(|(_, kind)| *kind != "dxf") {
        return explicit;
    }
    let dir = args.out.clone().unwrap_or_else(|| PathBuf::from("."));
    // `--dxf` alone adds the drawing to the default reports (`--reports`, all four unless told).
    [
        (ReportKind::Svg, "svg"),
        (ReportKind::Png, "png"),
        (ReportKind::Json, "json"),
        (ReportKind::Html, "html"),
    ]
    .into_iter()
    .filter(|(k, _)| args.reports.as_ref().is_none_or(|r| r.contains(k)))
    .map(|(_, kind)| (dir.join(format!("{stem}.{kind}")), kind))
    .chain(explicit)
    .collect()
}

/// Whether a report of this kind shows the report picture (and so its toolpath).
fn shows_picture(kind: &str) -> bool {
    matches!(kind, "svg" | "png" | "html")
}

/// The bytes of each report `targets` asks for, in its order, each made on a thread of its
/// own. The picture is drawn once, on this thread, for the SVG, the PNG and the HTML page
/// that show it (drawn on a new thread, its million-move scratch memory came from a new
/// malloc arena instead of the memory the run had freed: 252 MiB peak against 181).
fn render_all(
    report: &render::Report,
    targets: &[(PathBuf, &str)],
    dxf_x: crate::cli::DxfXArg,
) -> Vec<Result<Vec<u8>, String>> {
    let picture = targets
        .iter()
        .any(|(_, kind)| shows_picture(kind))
        .then(|| render::Picture::draw(report));
    let picture = || {
        picture
            .as_ref()
            .expect("drawn for the reports that show it")
    };
    let one = |kind: &str| match kind {
        "svg" => Ok(picture().svg().as_bytes().to_vec()),
        "json" => Ok(render::json(report).into_bytes()),
        "html" => Ok(picture().html(report).into_bytes()),
        "dxf" => crate::cad::section_dxf(report, dxf_x),
        // "png"
        _ => picture()
            .png()
            .map_err(|e| format!("cannot render the PNG: {e}")),
    };
    std::thread::scope(|s| {
        let threads: Vec<_> = targets
            .iter()
            .map(|(_, kind)| s.spawn(|| one(kind)))
            .collect();
        threads
            .into_iter()
            // a panic goes on to the run's guard, as it would have on this thread
            .map(|t| t.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    })
}

/// Program files to run: the files given, and the program files directly inside the
/// folders given ([`crate::library::is_program_file`]: an NC extension, or a program
/// number for a name, as `O1234`), sorted. The subfolders a folder holds are not searched
/// (a `lib` of subprograms must not run as main programs); each is named on stderr, so that
/// none is passed over silently.
fn program_files(paths: &[PathBuf]) -> Vec<PathBuf> {
    let mut out = vec![];
    for p in paths {
        if !p.is_dir() {
            out.push(p.clone());
            continue;
        }
        let entries: Vec<PathBuf> = std::fs::read_dir(p)
            .into_iter()
            .flatten()
            .flatten()
            .map(|e| e.path())
            .collect();
        let mut found: Vec<PathBuf> = entries
            .iter()
            .filter(|f| f.is_file() && crate::library::is_program_file(f))
            .cloned()
            .collect();
        found.sort();
        out.extend(found);
        let mut folders: Vec<String> = entries
            .iter()
            .filter(|f| f.is_dir())
            .filter_map(|f| f.file_name().map(|n| n.to_string_lossy().into_owned()))
            .collect();
        folders.sort();
        if !folders.is_empty() {
            eprintln!(
                "note: subfolders of {} are not searched: {} (give a subfolder to run its programs)",
                p.display(),
                folders.join(", ")
            );
        }
    }
    out
}

/// `latsim run`: one program in detail, or several in parallel with one verdict line
/// each (for CI). The exit status is the worst of them: 2 if any could not be simulated.
pub(crate) fn run(args: &RunArgs) -> u8 {
    if let Some(kinds) = &args.reports {
        let named_files = [&args.svg, &args.png, &args.json, &args.html]
            .iter()
            .any(|f| f.is_some());
        let problem = if kinds.contains(&ReportKind::None) && kinds.len() > 1 {
            Some((
                "--reports none cannot be combined with other report kinds",
                "give `--reports none` alone, or a list such as `--reports json,svg`",
            ))
        } else if named_files {
            Some((
                "--reports picks what --out writes; --svg, --png, --json and --html name their files themselves",
                "give either --out DIR --reports KINDS, or the files you want with --json F, --svg F, …",
            ))
        } else {
            None
        };
        if let Some((message, help)) = problem {
            diag::print_plain(message, help);
            return EXIT_UNUSABLE;
        }
    }
    let files = program_files(&args.program.programs);
    if files.is_empty() {
        diag::print_plain(
            "no program files found",
            "give program files, or folders holding .nc files",
        );
        return EXIT_UNUSABLE;
    }
    let stems = output_stems(&files);
    let mut inputs = files.clone();
    inputs.extend(args.tools.clone());
    inputs.extend(args.stock_file.clone());
    inputs.extend(args.program.machine.clone());
    inputs.extend(args.target.clone());
    inputs.extend(
        args.chuck
            .as_ref()
            .filter(|c| !c.contains('='))
            .map(PathBuf::from),
    );
    let job = |i: usize| {
        guarded(&files[i], files.len() > 1, || {
            run_one(args, &files[i], &stems[i], &inputs, files.len() > 1)
        })
    };
    if files.len() == 1 {
        return job(0);
    }
    if args.svg.is_some()
        || args.png.is_some()
        || args.json.is_some()
        || args.html.is_some()
        || args.dxf.is_some()
    {
        diag::print_plain(
            "--svg, --png, --json, --html and --dxf name one file: they take one program",
            "with several programs use --out DIR: each gets <prog>.svg, .png, .json and .html there (or those --reports picks)",
        );
        return EXIT_UNUSABLE;
    }
    let next = std::sync::atomic::AtomicUsize::new(0);
    let worst = std::sync::atomic::AtomicU8::new(EXIT_CLEAN);
    let workers = std::thread::available_parallelism()
        .map_or(2, |n| n.get())
        .min(files.len());
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                if i >= files.len() {
                    break;
                }
                let code = job(i);
                worst.fetch_max(code, std::sync::atomic::Ordering::Relaxed);
            });
        }
    });
    worst.into_inner()
}

/// The name each program's reports take: its file stem, or its whole file name where two
/// programs of the run share a stem (`part.nc` and `part.tap` write `part.nc.json` and
/// `part.tap.json`, never the same `part.json`).
fn output_stems(files: &[PathBuf]) -> Vec<String> {
    let stem = |p: &PathBuf| {
        p.file_stem().map_or_else(
            || "program".to_string(),
            |s| s.to_string_lossy().into_owned(),
        )
    };
    let stems: Vec<String> = files.iter().map(stem).collect();
    files
        .iter()
        .zip(&stems)
        .map(|(f, s)| {
            if stems.iter().filter(|t| *t == s).count() > 1 {
                f.file_name()
                    .map_or_else(|| s.clone(), |n| n.to_string_lossy().into_owned())
            } else {
                s.clone()
            }
        })
        .collect()
}

/// Runs one program's job; a panic (a bug in latsim) becomes that program's own verdict,
/// exit 2, instead of ending the whole batch.
fn guarded(path: &Path, batch: bool, job: impl FnOnce() -> u8) -> u8 {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(job)) {
        Ok(code) => code,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            let message = format!("internal error while simulating {}: {what}", path.display());
            if batch {
                println!("{}: UNUSABLE — {message}", path.display());
            } else {
                diag::print_plain(
                    &message,
                    "this is a bug in latsim: please report it with the program",
                );
            }
            EXIT_UNUSABLE
        }
    }
}

/// Simulate one program and write its reports. In a batch, the terminal gets only the
/// verdict line (diagnostics are in the reports).
fn run_one(args: &RunArgs, path: &Path, stem: &str, inputs: &[PathBuf], batch: bool) -> u8 {
    if !(args.tol.is_finite() && args.tol > 0.0) {
        diag::print_plain(
            &format!("--tol {} is not a positive length", args.tol),
            "give the deviation tolerance in mm, e.g. --tol 0.01",
        );
        return EXIT_UNUSABLE;
    }
    // Read everything before any work, so a bad flag fails fast.
    let Ok(blank) = input::load_blank(args) else {
        return EXIT_UNUSABLE;
    };
    let Ok(tools) = input::load_tools(args.tools.as_deref()) else {
        return EXIT_UNUSABLE;
    };
    let Ok(mut loaded) = input::load_program(&args.program, path, &tools, args.tool) else {
        if batch {
            println!(
                "{}: UNUSABLE — not simulated (see the message above)",
                path.display()
            );
        }
        return EXIT_UNUSABLE;
    };
    let Ok(workholding) = input::load_workholding(args, &loaded.machine) else {
        return EXIT_UNUSABLE;
    };
    let fixture = match stock::Fixture::new(&workholding, &blank) {
        Ok(f) => f,
        Err(e) => {
            diag::print_plain(
                &e.to_string(),
                "the jaws hold the blank from the chuck face (default: the blank's left end) over grip mm: check --stock-z, face and grip",
            );
            return EXIT_UNUSABLE;
        }
    };
    let quiet = args.program.quiet || batch;
    input::print_diagnostics(&loaded, quiet);

    let segments = &loaded.toolpath.segments;
    let bar = progress_bar(segments.len() as u64, quiet);
    let mut tick = |done: usize| {
        if let Some(b) = &bar {
            b.set_position(done as u64);
        }
    };
    // the HTML player's snapshots cost a second cut of every sweep: only for an HTML report
    let targets = outputs(args, stem);
    let html = targets.iter().any(|(_, kind)| *kind == "html");
    let pictures = targets.iter().any(|(_, kind)| shows_picture(kind));
    let marks = if html {
        crate::report::snapshot_marks(segments.len())
    } else {
        vec![]
    };
    let stock_marks = crate::analysis::stock_marks(&loaded, &tools);
    let mut snapshot_after = marks.clone();
    snapshot_after.extend(&stock_marks);
    snapshot_after.sort_unstable();
    snapshot_after.dedup();
    // what the reports read from the moves alone is worked out beside the removal (the
    // cores are not both busy all through it)
    let (mut sim, (facts, fixture_crashes, thread_passes)) = std::thread::scope(|s| {
        let side = s.spawn(|| {
            (
                crate::report::MoveFacts::of(&loaded, &tools),
                fixture
                    .as_ref()
                    .map(|f| {
                        f.check(
                            &tools,
                            segments,
                            stock::SimOptions::default().chord_tol,
                            &loaded.toolpath.tailstock,
                        )
                    })
                    .unwrap_or_default(),
                stock::ThreadPasses::of(segments, &tools),
            )
        });
        let sim = stock::simulate(
            &blank,
            &tools,
            segments,
            &stock::SimOptions {
                snapshot_after,
                ..stock::SimOptions::default()
            },
            &mut tick,
        );
        // a panic there is a bug in latsim: `guarded` reports it
        let side = side.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        (sim, side)
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }

    let name = path.file_name().map_or_else(
        || loaded.source.name.clone(),
        |n| n.to_string_lossy().into_owned(),
    );
    // the stock after `k` moves where the run kept it (the blank, a snapshot)
    let kept_at = |k: usize| -> Option<Vec<stock::Shape>> {
        if k == 0 {
            return Some(blank.shapes.clone());
        }
        sim.snapshots
            .iter()
            .find(|(at, _)| *at == k)
            .map(|(_, s)| s.clone())
    };
    // ... or the final part: at the end, and where no snapshot was taken (a long program,
    // see analysis::stock_marks)
    let stock_at = |k: usize| -> Vec<stock::Shape> {
        (k < segments.len())
            .then(|| kept_at(k))
            .flatten()
            .unwrap_or_else(|| sim.final_shapes.clone())
    };
    let Ok(intents) = crate::analysis::intents(args, &loaded, &tools, &stock_at) else {
        return EXIT_UNUSABLE;
    };
    // the stock each thread cuts into, where it was kept (short programs)
    let thread_stock: Vec<(usize, Vec<stock::Shape>)> = thread_passes
        .starts()
        .into_iter()
        .filter_map(|k| kept_at(k).map(|s| (k, s)))
        .collect();
    // the HTML player does not show the stock the intents were read against (the epoch
    // snapshots of a long program are labelled with their own counts, not the marks)
    sim.snapshots
        .retain(|(k, _)| marks.contains(k) || !stock_marks.contains(k));
    let deviation = (!intents.is_empty()).then(|| {
        stock::deviation(
            &blank.shapes,
            &sim.final_shapes,
            &intents,
            args.tol,
            segments,
            &tools,
            0.001,
        )
    });
    let crashes = crate::report::crash_list(&loaded, &sim, &fixture_crashes);
    let mut report = crate::report::build(&loaded, &name, &blank, &tools, &sim, args.tol, &facts);
    crate::report::add_crashes(
        &mut report,
        &loaded,
        &tools,
        &crashes,
        fixture.as_ref(),
        facts,
    );
    crate::report::add_deviation(&mut report, &loaded, &intents, deviation.as_ref());
    let target = args.target.is_some().then(|| intents[0].part.as_slice());
    crate::report::add_threads(
        &mut report,
        &loaded,
        &sim,
        target,
        &thread_stock,
        &thread_passes,
    );
    if html {
        report.snapshots = crate::report::snapshots(&blank, segments.len(), &sim);
    }
    let findings = (!batch).then(|| {
        let crash_at: Vec<String> = crashes
            .iter()
            .map(|c| loaded.place(segments[c.segment].span))
            .collect();
        let gouge_at: Vec<String> = deviation
            .as_ref()
            .map(|d| {
                d.gouges
                    .iter()
                    .map(|g| {
                        g.made_by.and_then(|i| segments.get(i)).map_or_else(
                            || format!("{}:0", loaded.source.name),
                            |s| loaded.place(s.span),
                        )
                    })
                    .collect()
            })
            .unwrap_or_default();
        (crash_at, gouge_at)
    });
    if pictures {
        crate::report::add_toolpath(&mut report, std::mem::take(&mut loaded.toolpath.segments));
    }

    // Render every report first, then write them all to disk, then make them visible:
    // a failure anywhere leaves the previous reports as they were.
    let mut staged = vec![];
    for ((path, _), bytes) in targets
        .iter()
        .zip(render_all(&report, &targets, args.dxf_x))
    {
        let bytes = match bytes {
            Ok(b) => b,
            Err(e) => {
                diag::print_plain(&e, "");
                return EXIT_UNUSABLE;
            }
        };
        match write::stage(path, &bytes, inputs) {
            Ok(s) => staged.push(s),
            Err(e) => {
                diag::print_plain(
                    &e,
                    "choose another output path with --out, --svg, --png, --json or --html",
                );
                return EXIT_UNUSABLE;
            }
        }
    }
    if let Err(e) = write::commit(staged) {
        diag::print_plain(&e, "check the output folder: free space, permissions");
        return EXIT_UNUSABLE;
    }

    if let Some((crash_at, gouge_at)) = findings {
        print_findings(&loaded.source.name, &crash_at, &gouge_at, &report);
    }
    let verdict = report.verdict();
    println!(
        "{}: {} — {} segments, removed {:.1} mm² / {:.0} mm³, cycle time {:.1} s, {} alarm(s), {} crash(es), {} gouge(s)",
        name,
        render::verdict_word(verdict).to_uppercase(),
        report.segments,
        report.removed_area_mm2,
        report.removed_volume_mm3,
        report.cycle_time_s,
        // (the report lists the first alarms only)
        report.alarms.len() + loaded.toolpath.alarms.len().saturating_sub(crate::report::MAX_LISTED),
        report.crashes.len(),
        deviation.as_ref().map_or(0, |d| d.gouges.len())
    );
    if verdict == render::Verdict::Clean {
        EXIT_CLEAN
    } else {
        EXIT_FINDINGS
    }
}

/// Most crashes and gouges printed on the terminal; the reports list them all (up to
/// their own cap).
const MAX_PRINTED: usize = 20;

/// Crashes and gouges on the terminal, `file:line` first (the file a subprogram came from:
/// `crash_at`, `gouge_at`), at most [`MAX_PRINTED`] of each.
fn print_findings(name: &str, crash_at: &[String], gouge_at: &[String], report: &render::Report) {
    for (c, at) in report.crashes.iter().zip(crash_at).take(MAX_PRINTED) {
        let what = match (&c.obstacle, &c.body) {
            (Some(o), _) if o == stock::GRIPPED_LENGTH => {
                "the tool cuts the blank inside the chuck jaws (gripped length)".to_string()
            }
            (Some(o), Some(body)) => format!("the tool's {body} meets the {o}"),
            (Some(o), None) => format!("the tool's cutting edge meets the {o}"),
            (None, Some(body)) => format!("the tool's {body} meets stock"),
            (None, None) => "rapid into stock".to_string(),
        };
        let of = match c.obstacle.as_deref() {
            None | Some(stock::GRIPPED_LENGTH) => "of stock",
            Some(_) => "of overlap",
        };
        eprintln!(
            "{at}:{}: crash: {what} at Z{:.3} X{:.3}, {:.3} mm deep, {:.3} mm² {of}",
            c.column,
            c.z,
            2.0 * c.r,
            c.depth_mm,
            c.area_mm2
        );
    }
    for (g, at) in report.gouges.iter().zip(gouge_at).take(MAX_PRINTED) {
        eprintln!(
            "{at}: gouge: {:.4} mm deep, {:.4} mm² at Z{:.3} X{:.3}",
            g.depth_mm,
            g.area_mm2,
            g.z,
            2.0 * g.r
        );
    }
    for (what, n) in [
        ("crash(es)", report.crashes.len()),
        ("gouge(s)", report.gouges.len()),
    ] {
        if n > MAX_PRINTED {
            eprintln!(
                "{name}: … and {} more {what}, listed in the reports",
                n - MAX_PRINTED
            );
        }
    }
}

fn progress_bar(len: u64, quiet: bool) -> Option<indicatif::ProgressBar> {
    if quiet || !std::io::stderr().is_terminal() || len < 10_000 {
        return None;
    }
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "{spinner} removing material {bar:40} {pos}/{len} moves ({eta})",
    ) {
        bar.set_style(style);
    }
    Some(bar)
}
