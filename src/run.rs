//! `latsim run` and `latsim check`.

use crate::cli::{CheckArgs, ReportKind, RunArgs};
use crate::diag;
use crate::input;
use crate::job::Job;
use crate::outcome::Outcome;
use crate::write;
use crate::{EXIT_CLEAN, EXIT_FINDINGS, EXIT_UNUSABLE};
use analysis::{Findings, MAX_LISTED};
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
    // the tools' tips read from the program's feeds as `run` reads them (LS-HOLDER-HAND)
    let Ok((_, loaded)) = crate::job::load_with_use(&args.program, path, tools.clone(), None)
    else {
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

/// Why a report was not staged: it could not be made, or not written.
enum Unstaged {
    Render(String),
    Write(String),
}

/// Each report `targets` asks for, in its order, made and staged on disk
/// ([`write::stage`]) on a thread of its own, so that the writes and their flushes to disk
/// overlap. The picture is drawn once, on this thread, for the SVG, the PNG and the HTML
/// page that show it (drawn on a new thread, its million-move scratch memory came from a
/// new malloc arena instead of the memory the run had freed: 252 MiB peak against 181).
fn render_and_stage(
    report: &render::Report,
    targets: &[(PathBuf, &str)],
    dxf_x: crate::cli::DxfXArg,
    inputs: &[PathBuf],
) -> Vec<Result<write::Staged, Unstaged>> {
    // the HTML page's data needs no picture: worked out while the picture is drawn
    let (picture, mut html_data) = std::thread::scope(|s| {
        let data = targets
            .iter()
            .any(|(_, kind)| *kind == "html")
            .then(|| s.spawn(|| render::HtmlData::of(report)));
        let picture = targets
            .iter()
            .any(|(_, kind)| shows_picture(kind))
            .then(|| render::Picture::draw(report));
        let data = data.map(|t| t.join().unwrap_or_else(|p| std::panic::resume_unwind(p)));
        (picture, data)
    });
    std::thread::scope(|s| {
        let threads: Vec<_> = targets
            .iter()
            .map(|(path, kind)| {
                let data = if *kind == "html" {
                    html_data.take()
                } else {
                    None
                };
                let picture = picture.as_ref();
                s.spawn(move || {
                    let bytes =
                        render_one(report, kind, picture, data, dxf_x).map_err(Unstaged::Render)?;
                    write::stage(path, &bytes, inputs).map_err(Unstaged::Write)
                })
            })
            .collect();
        threads
            .into_iter()
            // a panic goes on to the run's guard, as it would have on this thread
            .map(|t| t.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    })
}

/// One report's bytes, from the picture drawn for it (`svg`, `png`, `html`) and the HTML
/// page's data worked out beforehand.
fn render_one(
    report: &render::Report,
    kind: &str,
    picture: Option<&render::Picture>,
    html_data: Option<render::HtmlData>,
    dxf_x: crate::cli::DxfXArg,
) -> Result<Vec<u8>, String> {
    let picture = || picture.expect("drawn for the reports that show it");
    match kind {
        "svg" => Ok(picture().svg().as_bytes().to_vec()),
        "json" => Ok(render::json(report).into_bytes()),
        "html" => Ok(match html_data {
            Some(data) => picture().html_with(report, data),
            None => picture().html(report),
        }
        .into_bytes()),
        "dxf" => crate::cad::section_dxf(report, dxf_x),
        // "png"
        _ => picture()
            .png()
            .map_err(|e| format!("cannot render the PNG: {e}")),
    }
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
    if !crate::baseline::usable(args, files.len()) {
        return EXIT_UNUSABLE;
    }
    let stems = output_stems(&files);
    let inputs = inputs_of(args, &files, &stems);
    let started = std::time::Instant::now();
    let memory = memory_of(args, &files);
    let job = |i: usize| {
        let t = std::time::Instant::now();
        let mut outcome = guarded(&files[i], files.len() > 1, || {
            let batch = files.len() > 1;
            run_one(args, &files[i], &stems[i], &inputs, (batch, memory(i)))
        });
        memory(i).inspect(stock::RunMemory::done);
        outcome.seconds = t.elapsed().as_secs_f64();
        outcome
    };
    if files.len() == 1 {
        let outcome = job(0);
        let code = outcome.code;
        return crate::ci::write(args, &[outcome], code, started, &inputs);
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
    let outcomes = in_parallel(files.len(), job);
    let worst = outcomes.iter().map(|o| o.code).max().unwrap_or(EXIT_CLEAN);
    crate::ci::write(args, &outcomes, worst, started, &inputs)
}

/// Each program's memory budget (`--max-memory`, else half the machine's), shared by the
/// batch through one ledger.
fn memory_of(args: &RunArgs, files: &[PathBuf]) -> impl Fn(usize) -> Option<stock::RunMemory> {
    let budget = memory_budget(args);
    let sizes = files
        .iter()
        .map(|f| std::fs::metadata(f).map_or(0, |m| m.len()));
    let ledger = (files.len() > 1).then(|| stock::Ledger::new(sizes));
    move |i| {
        budget.map(|b| match &ledger {
            Some(l) => stock::RunMemory::in_batch(b, l.clone(), i),
            None => stock::RunMemory::alone(b),
        })
    }
}

/// A program's memory budget: `--max-memory`, else half the machine's.
pub(crate) fn memory_budget(args: &RunArgs) -> Option<stock::MemoryBudget> {
    args.max_memory
        .or_else(stock::MemoryBudget::half_of_machine)
}

/// The files a run reads, which no report may replace: the programs, the tables and
/// profiles, and the baselines (`--out` naming the baseline folder is refused).
fn inputs_of(args: &RunArgs, files: &[PathBuf], stems: &[String]) -> Vec<PathBuf> {
    let mut inputs = files.to_vec();
    inputs.extend(
        stems
            .iter()
            .filter_map(|s| crate::baseline::path_for(args, s)),
    );
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
    inputs
}

/// `job(0)`, …, `job(n - 1)` on as many threads as there are cores, their outcomes in
/// program order.
fn in_parallel(n: usize, job: impl Fn(usize) -> Outcome + Sync) -> Vec<Outcome> {
    let next = std::sync::atomic::AtomicUsize::new(0);
    let outcomes = std::sync::Mutex::new(Vec::with_capacity(n));
    let workers = std::thread::available_parallelism()
        .map_or(2, |c| c.get())
        .min(n);
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                if i >= n {
                    break;
                }
                let outcome = job(i);
                // (a job's panic is caught inside it: the lock is never poisoned)
                let mut all = outcomes.lock().unwrap_or_else(|e| e.into_inner());
                all.push((i, outcome));
            });
        }
    });
    let mut outcomes = outcomes.into_inner().unwrap_or_else(|e| e.into_inner());
    outcomes.sort_by_key(|(i, _)| *i);
    outcomes.into_iter().map(|(_, o)| o).collect()
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
fn guarded(path: &Path, batch: bool, job: impl FnOnce() -> Outcome) -> Outcome {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(job)) {
        Ok(outcome) => outcome,
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
            Outcome::unusable(path.to_path_buf(), Some(message))
        }
    }
}

/// Simulate one program and write its reports. In a batch, the terminal gets only the
/// verdict line (diagnostics are in the reports).
fn run_one(
    args: &RunArgs,
    path: &Path,
    stem: &str,
    inputs: &[PathBuf],
    (batch, memory): (bool, Option<stock::RunMemory>),
) -> Outcome {
    let unusable = || Outcome::unusable(path.to_path_buf(), None);
    let Ok(mut job) = Job::load(args, path, batch) else {
        return unusable();
    };
    input::print_diagnostics(&job.loaded, args.program.quiet || batch);
    let targets = outputs(args, stem);
    let html = targets.iter().any(|(_, kind)| *kind == "html");
    let (mut sim, findings) = simulate(args, &job, html, memory, args.program.quiet || batch);
    if let Some(over) = &sim.over_budget {
        return over_budget(path, over, batch);
    }
    let name = path.file_name().map_or_else(
        || job.loaded.source.name.clone(),
        |n| n.to_string_lossy().into_owned(),
    );
    let mut report = build_report(&job, &name, &mut sim, &findings, args.tol, html);
    let places = (!batch).then(|| Places::of(&job.loaded, &findings));
    let Ok(against) = crate::baseline::against(args, stem, &report, &job) else {
        return unusable();
    };
    let items = crate::outcome::items(&job.loaded, &sim, &findings, args.tol, against.as_ref());
    if targets.iter().any(|(_, kind)| shows_picture(kind)) {
        let segments = std::mem::take(&mut job.loaded.toolpath.segments);
        crate::report::add_toolpath(&mut report, segments);
    }
    if write_reports(&report, &targets, args.dxf_x, inputs).is_err() {
        return unusable();
    }
    if let Some(places) = places {
        print_findings(&job.loaded.source.name, &places, &report);
    }
    let line = verdict_line(&name, &report, &job.loaded, &findings);
    crate::outcome::finish(path, line, items, against, findings.verdict, batch)
}

/// The removal and the analysis (with a progress bar unless `quiet`), then the diagnosis
/// of what they found; the HTML player's snapshots only for an HTML report (each is a
/// union of the whole stock). A run over its memory budget is returned undiagnosed.
fn simulate(
    args: &RunArgs,
    job: &Job,
    html: bool,
    memory: Option<stock::RunMemory>,
    quiet: bool,
) -> (stock::Simulation, analysis::Findings) {
    let moves = job.loaded.toolpath.segments.len();
    let opts = stock::SimOptions {
        snapshot_after: if html {
            stock::player_marks(moves)
        } else {
            vec![]
        },
        max_memory: memory.clone(),
        ..stock::SimOptions::default()
    };
    let bar = progress_bar(moves as u64, quiet);
    let mut tick = |done: usize| {
        if let Some(b) = &bar {
            b.set_position(done as u64);
        }
    };
    let settings = job.settings(args.tol);
    let (sim, mut findings) = analysis::pipeline(
        &job.loaded.toolpath,
        &job.intents,
        &settings,
        &opts,
        &mut tick,
    );
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    if sim.over_budget.is_none() {
        let rerun = crate::rerun::Rerunner {
            job,
            tol: args.tol,
            memory,
        };
        analysis::diagnose::diagnose(
            &mut findings,
            (
                &job.loaded.toolpath,
                &sim.final_shapes,
                &job.loaded.source.text,
            ),
            &settings,
            &rerun,
        );
    }
    (sim, findings)
}

/// The report of a run (its snapshots for an HTML report; the player does not show the
/// stock the intents were read against: the epoch snapshots of a long program are
/// labelled with their own counts, not the marks).
fn build_report(
    job: &Job,
    name: &str,
    sim: &mut stock::Simulation,
    findings: &analysis::Findings,
    tol: f64,
    html: bool,
) -> render::Report {
    let moves = job.loaded.toolpath.segments.len();
    let marks = if html {
        stock::player_marks(moves)
    } else {
        vec![]
    };
    // the snapshots the analysis asked for are not the player's
    let toolpath = &job.loaded.toolpath;
    let mut asked = analysis::stock_marks(toolpath);
    asked.extend(analysis::thread_marks(toolpath, &job.tools));
    sim.snapshots
        .retain(|(k, _)| marks.contains(k) || !asked.contains(k));
    let mut report = crate::report::report(
        &crate::report::Run {
            loaded: &job.loaded,
            name,
            blank: &job.blank,
            tools: &job.tools,
            sim,
            fixture: job.fixture.as_ref(),
            tol,
        },
        findings,
    );
    if html {
        report.snapshots = crate::report::snapshots(&job.blank, moves, sim);
    }
    report
}

/// A run stopped over its memory budget: the message (the verdict line in a batch), exit 2.
fn over_budget(path: &Path, over: &stock::OverBudget, batch: bool) -> Outcome {
    let message = over.to_string();
    if batch {
        println!("{}: UNUSABLE — {message}", path.display());
    } else {
        print_over_budget(path, over);
    }
    Outcome::unusable(path.to_path_buf(), Some(message))
}

/// The message of a run stopped over its memory budget, with what to do.
pub(crate) fn print_over_budget(path: &Path, over: &stock::OverBudget) {
    diag::print_plain(
        &format!("{}: {over}", path.display()),
        "split the program, or give a larger --max-memory where the machine has the memory",
    );
}

/// Renders and writes every report to disk, then makes them visible: a failure anywhere
/// leaves the previous reports as they were (the first, in the targets' order, is printed;
/// the reports staged are dropped unseen).
fn write_reports(
    report: &render::Report,
    targets: &[(PathBuf, &'static str)],
    dxf_x: crate::cli::DxfXArg,
    inputs: &[PathBuf],
) -> Result<(), ()> {
    let staged = render_and_stage(report, targets, dxf_x, inputs)
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| match e {
            Unstaged::Render(e) => diag::print_plain(&e, ""),
            Unstaged::Write(e) => diag::print_plain(
                &e,
                "choose another output path with --out, --svg, --png, --json or --html",
            ),
        })?;
    write::commit(staged)
        .map_err(|e| diag::print_plain(&e, "check the output folder: free space, permissions"))
}

/// The verdict line: program, verdict, moves, removal, cycle time and the counts.
fn verdict_line(
    name: &str,
    report: &render::Report,
    loaded: &input::Loaded,
    f: &Findings,
) -> String {
    format!(
        "{}: {} — {} segments, removed {:.1} mm² / {:.0} mm³, cycle time {:.1} s, {} alarm(s), {} crash(es), {} gouge(s)",
        name,
        render::verdict_word(report.verdict).to_uppercase(),
        report.segments,
        diag::tenths(report.removed_area_mm2),
        report.removed_volume_mm3.round() + 0.0,
        report.cycle_time_s,
        // (the report lists the first alarms only)
        report.alarms.len() + loaded.toolpath.alarms.len().saturating_sub(MAX_LISTED),
        f.crashes.iter().filter(|c| !c.assumed).count(),
        f.deviation
            .as_ref()
            .map_or(0, |d| d.gouges.iter().filter(|g| !g.assumed).count())
    ) + &threads_too_deep(f, report.tolerance_mm)
}

/// ", 1 thread(s) too deep" when threads cut too deep fail the run (a gouge's verdict
/// beside "0 gouge(s)" read as a contradiction), else nothing.
fn threads_too_deep(f: &Findings, tol: f64) -> String {
    match f.threads.iter().filter(|t| t.too_deep(tol)).count() {
        0 => String::new(),
        n => format!(", {n} thread(s) too deep"),
    }
}

/// Where each crash and gouge is, `file:line` (the file a subprogram came from), for the
/// terminal.
struct Places {
    crashes: Vec<String>,
    gouges: Vec<String>,
}

impl Places {
    fn of(loaded: &input::Loaded, f: &Findings) -> Self {
        let segments = &loaded.toolpath.segments;
        Self {
            crashes: f
                .crashes
                .iter()
                .map(|c| loaded.place(segments[c.segment].span))
                .collect(),
            gouges: f
                .deviation
                .iter()
                .flat_map(|d| d.gouges.iter())
                .map(|g| {
                    g.made_by.and_then(|i| segments.get(i)).map_or_else(
                        || format!("{}:0", loaded.source.name),
                        |s| loaded.place(s.span),
                    )
                })
                .collect(),
        }
    }
}

/// Most crashes and gouges printed on the terminal; the reports list them all (up to
/// their own cap).
const MAX_PRINTED: usize = 20;

/// Crashes and gouges on the terminal, `file:line` first (the file a subprogram came from),
/// at most [`MAX_PRINTED`] of each.
fn print_findings(name: &str, places: &Places, report: &render::Report) {
    for (c, at) in report.crashes.iter().zip(&places.crashes).take(MAX_PRINTED) {
        let (what, of) = crate::outcome::crash_words(c.body.as_deref(), c.obstacle.as_deref());
        let kind = if c.assumed {
            "possible crash (tool size assumed, not in the verdict)"
        } else {
            "crash"
        };
        eprintln!(
            "{at}:{}: {kind}: {what} at Z{:.3} X{:.3}, {:.3} mm deep, {:.3} mm² {of}",
            c.column,
            c.z,
            2.0 * c.r,
            c.depth_mm,
            c.area_mm2
        );
        print_why(c.cause.as_ref(), c.remedy.as_ref());
    }
    for (g, at) in report.gouges.iter().zip(&places.gouges).take(MAX_PRINTED) {
        let kind = if g.assumed {
            "possible gouge (tool size assumed, not in the verdict)"
        } else {
            "gouge"
        };
        eprintln!(
            "{at}: {kind}: {:.4} mm deep, {:.4} mm² at Z{:.3} X{:.3}",
            g.depth_mm,
            g.area_mm2,
            g.z,
            2.0 * g.r
        );
        print_why(g.cause.as_ref(), g.remedy.as_ref());
    }
    // the ones not printed, certain and possible apart (possible ones are not in the verdict)
    let rest = |assumed: &mut dyn Iterator<Item = bool>| {
        let (possible, certain): (Vec<bool>, Vec<bool>) =
            assumed.skip(MAX_PRINTED).partition(|&a| a);
        (certain.len(), possible.len())
    };
    for (what, (certain, possible)) in [
        (
            "crash(es)",
            rest(&mut report.crashes.iter().map(|c| c.assumed)),
        ),
        (
            "gouge(s)",
            rest(&mut report.gouges.iter().map(|g| g.assumed)),
        ),
    ] {
        let mut more = vec![];
        if certain > 0 {
            more.push(format!("{certain} more {what}"));
        }
        if possible > 0 {
            more.push(format!("{possible} more possible {what}"));
        }
        if !more.is_empty() {
            eprintln!(
                "{name}: … and {}, listed in the reports",
                more.join(" and ")
            );
        }
    }
}

/// The cause and the checked remedy of a finding, indented under its line.
fn print_why(cause: Option<&render::Cause>, remedy: Option<&render::Remedy>) {
    if let Some(c) = cause {
        eprintln!("    why: {}", c.text);
    }
    if let Some(r) = remedy {
        eprintln!("    fix (checked by re-running): {}", r.text);
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
