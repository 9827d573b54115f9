//! `latsim diff OLD NEW` and `run --baseline F`: what the part gained and lost between two
//! runs, the times and the findings that changed. A side is a program (run here with the
//! run's flags) or a JSON report of an earlier run (which holds the final part, the times
//! and the findings, but not the moves: its regions name no lines). The regions are the
//! analysis stage's (`analysis::diff`); this file reads the sides, matches the findings,
//! prints and writes.

use crate::cli::{DiffArgs, RunArgs};
use crate::diag;
use crate::job::Job;
use crate::outcome::crash_words;
use crate::write;
use crate::{EXIT_CLEAN, EXIT_FINDINGS, EXIT_UNUSABLE};
use expander::Segment;
use render::{DiffFinding, DiffReport, Report, ToolTime};
use std::path::{Path, PathBuf};

/// Two findings of the same kind and code within this distance (mm, along Z and along the
/// radius) are the same finding moved by the edit: a gouge's deepest point shifts a little
/// when its surface moves.
const MATCH_MM: f64 = 0.5;
/// Largest JSON report read, bytes (a report holds the final part and the findings, not
/// the toolpath: a million-move run's is a few MB).
const MAX_REPORT_BYTES: u64 = 256 * 1024 * 1024;
/// Most regions printed on the terminal (the reports list them all).
const MAX_PRINTED: usize = 20;

/// A program's moves and the tools that made them.
type Moves<'a> = (&'a [Segment], &'a stock::ToolTable);

/// One side of a diff as its report shows it.
pub(crate) struct Facts {
    name: String,
    verdict: render::Verdict,
    part: Vec<stock::Shape>,
    cycle_time: f64,
    /// (`T01`, seconds), in order of first use.
    tools: Vec<(String, f64)>,
    findings: Vec<DiffFinding>,
}

impl Facts {
    /// The facts of a run's report (`name`: how the diff names the side).
    pub(crate) fn of_report(name: &str, r: &Report) -> Self {
        let mut findings: Vec<DiffFinding> = vec![];
        let note = |kind: &str, d: &render::Diagnostic| DiffFinding {
            kind: kind.into(),
            code: d.code.clone(),
            line: d.line,
            at: None,
            message: d.message.clone(),
        };
        findings.extend(r.alarms.iter().map(|d| note("alarm", d)));
        // a rapid scrape is listed as a rapid cut too; the caps are no findings
        let own = ["LS-RAPID-SCRAPE", "LS-LIST-CAPPED", "LS-FINDINGS-CAPPED"];
        let warnings = r
            .warnings
            .iter()
            .filter(|d| !own.contains(&d.code.as_str()));
        findings.extend(warnings.map(|d| note("warning", d)));
        let crash = |kind: &str, code: &str, c: &render::Crash| {
            let (what, of) = crash_words(c.body.as_deref(), c.obstacle.as_deref());
            DiffFinding {
                kind: kind.into(),
                code: code.into(),
                line: c.line,
                at: Some([c.z, c.r]),
                message: format!(
                    "{what}, {:.3} mm deep, {:.3} mm² {of}",
                    c.depth_mm, c.area_mm2
                ),
            }
        };
        findings.extend(r.crashes.iter().map(|c| {
            let code = if c.assumed {
                crate::outcome::POSSIBLE_CRASH
            } else {
                crate::outcome::CRASH
            };
            crash("crash", code, c)
        }));
        let scrape = |c| crash("rapid_scrape", "LS-RAPID-SCRAPE", c);
        findings.extend(r.rapid_cuts.iter().map(scrape));
        findings.extend(r.gouges.iter().map(|g| {
            DiffFinding {
                kind: "gouge".into(),
                code: if g.assumed {
                    crate::outcome::POSSIBLE_GOUGE
                } else {
                    crate::outcome::GOUGE
                }
                .into(),
                line: g.line,
                at: Some([g.z, g.r]),
                message: format!("{:.4} mm deep, {:.4} mm²", g.depth_mm, g.area_mm2),
            }
        }));
        Self {
            name: name.to_string(),
            verdict: r.verdict,
            part: r
                .final_part
                .iter()
                .map(|s| stock::Shape {
                    outer: s.outer.clone(),
                    holes: s.holes.clone(),
                })
                .collect(),
            cycle_time: r.cycle_time_s,
            tools: r.tools.iter().filter_map(|t| tool_time(t)).collect(),
            findings,
        }
    }

    /// The facts of a JSON report written by `latsim run`.
    pub(crate) fn of_json(path: &Path) -> Result<Self, ()> {
        let report = crate::saved::read(path, MAX_REPORT_BYTES)?;
        Ok(Self::of_report(&path.display().to_string(), &report))
    }
}

/// `T01 · 32.6 s · turning …` → (`T01`, 32.6).
fn tool_time(line: &str) -> Option<(String, f64)> {
    let mut parts = line.split(" · ");
    let tool = parts.next()?;
    let secs = parts.next()?.strip_suffix(" s")?.parse().ok()?;
    Some((tool.to_string(), secs))
}

/// The findings of `a` that no finding of `b` matches (each matches at most one).
fn unmatched(a: &[DiffFinding], b: &[DiffFinding]) -> Vec<DiffFinding> {
    let mut used = vec![false; b.len()];
    let same = |x: &DiffFinding, y: &DiffFinding| {
        x.kind == y.kind
            && x.code == y.code
            && match (x.at, y.at) {
                (Some(p), Some(q)) => {
                    (p[0] - q[0]).abs() <= MATCH_MM && (p[1] - q[1]).abs() <= MATCH_MM
                }
                (None, None) => x.message == y.message,
                _ => false,
            }
    };
    a.iter()
        .filter(|x| {
            let hit = (0..b.len()).find(|&k| !used[k] && same(x, &b[k]));
            if let Some(k) = hit {
                used[k] = true;
            }
            hit.is_none()
        })
        .cloned()
        .collect()
}

/// The diff of two sides (the moves of each where its program was run).
pub(crate) fn compare(
    old: &Facts,
    old_moves: Option<Moves>,
    new: &Facts,
    new_moves: Option<Moves>,
    tol: f64,
) -> DiffReport {
    let o = analysis::diff::Side {
        part: &old.part,
        moves: old_moves,
    };
    let n = analysis::diff::Side {
        part: &new.part,
        moves: new_moves,
    };
    let parts = analysis::diff::compare(&o, &n, tol);
    let lines = |moves: &[usize], of: Option<Moves>| -> Vec<u32> {
        let Some((segments, _)) = of else {
            return vec![];
        };
        let mut l: Vec<u32> = moves
            .iter()
            .filter_map(|&i| segments.get(i).map(|s| s.span.line))
            .collect();
        l.sort_unstable();
        l.dedup();
        l
    };
    let region = |r: &analysis::diff::Region| render::DiffRegion {
        shape: shape(&r.shape),
        area_mm2: r.area,
        depth_mm: r.depth,
        z: r.at[0],
        r: r.at[1],
        lo: r.lo,
        hi: r.hi,
        new_lines: lines(&r.new_moves, new_moves),
        old_lines: lines(&r.old_moves, old_moves),
        new_place: new_moves.and_then(|(segments, _)| {
            let span = segments.get(*r.new_moves.last()?)?.span;
            Some([span.line, span.column])
        }),
    };
    DiffReport {
        old: old.name.clone(),
        new: new.name.clone(),
        tolerance_mm: tol,
        verdicts: [old.verdict, new.verdict],
        old_part: old.part.iter().map(shape).collect(),
        new_part: new.part.iter().map(shape).collect(),
        gained: parts.gained.iter().map(region).collect(),
        lost: parts.lost.iter().map(region).collect(),
        cycle_time_s: [old.cycle_time, new.cycle_time],
        tools: tool_times(old, new),
        appeared: unmatched(&new.findings, &old.findings),
        gone: unmatched(&old.findings, &new.findings),
    }
}

fn shape(s: &stock::Shape) -> render::Shape {
    render::Shape {
        outer: s.outer.clone(),
        holes: s.holes.clone(),
    }
}

/// Each tool's time on both sides: the new run's tools in their order, then the old run's
/// tools the new one no longer uses.
fn tool_times(old: &Facts, new: &Facts) -> Vec<ToolTime> {
    let secs = |f: &Facts, t: &str| f.tools.iter().find(|(n, _)| n == t).map(|x| x.1);
    let mut names: Vec<&str> = new.tools.iter().map(|(t, _)| t.as_str()).collect();
    for (t, _) in &old.tools {
        if !names.contains(&t.as_str()) {
            names.push(t);
        }
    }
    names
        .into_iter()
        .map(|t| ToolTime {
            tool: t.to_string(),
            old_s: secs(old, t),
            new_s: secs(new, t),
        })
        .collect()
}

/// The diff's lines for the terminal: the verdict, then each region, the times and the
/// findings that changed.
pub(crate) fn summary_lines(d: &DiffReport) -> Vec<String> {
    let mut out = vec![format!(
        "{} → {}: {} — lost {:.4} mm² in {}, gained {:.4} mm² in {} (tolerance {} mm)",
        d.old,
        d.new,
        if d.differs() {
            "PART DIFFERS"
        } else {
            "SAME PART"
        },
        d.lost_area(),
        count(d.lost.len(), "region"),
        d.gained_area(),
        count(d.gained.len(), "region"),
        d.tolerance_mm
    )];
    let regions = numbered(d);
    let n = regions.len();
    for (label, r, lost) in regions.into_iter().take(MAX_PRINTED) {
        out.push(format!("  {}", r.describe(&label, lost)));
    }
    if n > MAX_PRINTED {
        out.push(format!(
            "  … and {} more regions, listed in the reports",
            n - MAX_PRINTED
        ));
    }
    let [old, new] = d.cycle_time_s;
    out.push(format!(
        "  cycle time {old:.1} s → {new:.1} s ({:+.1} s)",
        diag::tenths(new - old)
    ));
    let s = |v: Option<f64>| v.map_or("—".to_string(), |v| format!("{v:.1} s"));
    for t in d.changed_tools(0.05) {
        out.push(format!("  {} {} → {}", t.tool, s(t.old_s), s(t.new_s)));
    }
    out.push(format!(
        "  findings: {} appeared, {} gone",
        d.appeared.len(),
        d.gone.len()
    ));
    for (sign, list) in [("+", &d.appeared), ("-", &d.gone)] {
        for f in list.iter().take(MAX_PRINTED) {
            out.push(format!(
                "  {sign} {} line {} {}: {}",
                f.kind, f.line, f.code, f.message
            ));
        }
    }
    out
}

fn count(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

/// The regions as numbered in every report: `L1`, … then `G1`, ….
fn numbered(d: &DiffReport) -> Vec<(String, &render::DiffRegion, bool)> {
    let lost = d.lost.iter().enumerate();
    let gained = d.gained.iter().enumerate();
    lost.map(|(i, r)| (format!("L{}", i + 1), r, true))
        .chain(gained.map(|(i, r)| (format!("G{}", i + 1), r, false)))
        .collect()
}

/// What the verdict line of `run --baseline` adds: the part's difference and the cycle
/// time's change.
pub(crate) fn verdict_suffix(d: &DiffReport) -> String {
    let [old, new] = d.cycle_time_s;
    if !d.differs() {
        return format!(
            "; against {}: same part, cycle time {:+.1} s",
            d.old,
            diag::tenths(new - old)
        );
    }
    let first = d
        .lost
        .iter()
        .chain(&d.gained)
        .find_map(|r| r.new_place)
        .map_or(String::new(), |p| {
            format!(", the largest made at line {}", p[0])
        });
    format!(
        "; against {}: PART DIFFERS — lost {:.4} mm² in {}, gained {:.4} mm² in {}{first}, cycle time {:+.1} s",
        d.old,
        d.lost_area(),
        count(d.lost.len(), "region"),
        d.gained_area(),
        count(d.gained.len(), "region"),
        diag::tenths(new - old)
    )
}

/// A program run for the diff: its job (the moves, the tools) and its report.
struct Ran {
    job: Job,
    facts: Facts,
}

/// Run the program at `path` as `latsim run` would (its alarms printed).
fn simulate(args: &RunArgs, path: &Path) -> Result<Ran, ()> {
    let job = Job::load(args, path, false)?;
    crate::input::print_diagnostics(&job.loaded, true);
    let settings = job.settings(args.tol);
    let opts = stock::SimOptions {
        max_memory: crate::run::memory_budget(args).map(stock::RunMemory::alone),
        ..stock::SimOptions::default()
    };
    let (sim, findings) = analysis::pipeline(
        &job.loaded.toolpath,
        &job.intents,
        &settings,
        &opts,
        &mut |_| {},
    );
    if let Some(over) = &sim.over_budget {
        crate::run::print_over_budget(path, over);
        return Err(());
    }
    let name = path.display().to_string();
    let report = crate::report::report(
        &crate::report::Run {
            loaded: &job.loaded,
            name: &name,
            blank: &job.blank,
            tools: &job.tools,
            sim: &sim,
            fixture: job.fixture.as_ref(),
            tol: args.tol,
        },
        &findings,
    );
    let facts = Facts::of_report(&name, &report);
    Ok(Ran { job, facts })
}

/// A side: a `.json` report, or a program to run.
fn side(args: &RunArgs, path: &Path) -> Result<(Facts, Option<Job>), ()> {
    if is_report(path) {
        return Facts::of_json(path).map(|f| (f, None));
    }
    simulate(args, path).map(|r| (r.facts, Some(r.job)))
}

/// Whether a diff side is a JSON report rather than a program.
fn is_report(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"))
}

/// `latsim diff OLD NEW`.
pub(crate) fn diff(args: &DiffArgs) -> u8 {
    let run = &args.run;
    if usage_problem(run) {
        return EXIT_UNUSABLE;
    }
    let [old_path, new_path] = [&run.program.programs[0], &run.program.programs[1]];
    let Ok((old, old_job)) = side(run, old_path) else {
        return EXIT_UNUSABLE;
    };
    let Ok((new, new_job)) = side(run, new_path) else {
        return EXIT_UNUSABLE;
    };
    fn moves(j: &Option<Job>) -> Option<Moves<'_>> {
        j.as_ref()
            .map(|j| (j.loaded.toolpath.segments.as_slice(), &j.tools))
    }
    let d = compare(&old, moves(&old_job), &new, moves(&new_job), run.tol);
    for line in summary_lines(&d) {
        println!("{line}");
    }
    let mut inputs: Vec<PathBuf> = vec![old_path.clone(), new_path.clone()];
    inputs.extend(run.tools.clone());
    inputs.extend(run.stock_file.clone());
    inputs.extend(run.target.clone());
    inputs.extend(run.program.machine.clone());
    if write_outputs(&d, run, &inputs).is_err() {
        return EXIT_UNUSABLE;
    }
    if d.differs() {
        EXIT_FINDINGS
    } else {
        EXIT_CLEAN
    }
}

/// `diff` takes two sides and names its reports with `--json`, `--svg`, `--png`, `--html`;
/// the run's batch and CI flags mean nothing here. Prints the problem.
fn usage_problem(run: &RunArgs) -> bool {
    let problem = if run.program.programs.len() != 2 {
        Some(format!(
            "latsim diff takes two sides, OLD and NEW, not {}",
            run.program.programs.len()
        ))
    } else if run.out.is_some()
        || run.reports.is_some()
        || run.dxf.is_some()
        || run.junit.is_some()
        || run.sarif.is_some()
        || run.baseline.is_some()
    {
        Some(
            "--out, --reports, --dxf, --junit, --sarif and --baseline are run's flags, not diff's"
                .to_string(),
        )
    } else {
        None
    };
    if let Some(p) = &problem {
        diag::print_plain(
            p,
            "latsim diff OLD NEW [--stock …] [--json F] [--svg F] [--png F] [--html F]: each side is a program (run with the flags given) or a .json report",
        );
    }
    problem.is_some()
}

/// The diff's reports: rendered first, then written together (whole or not at all).
fn write_outputs(d: &DiffReport, run: &RunArgs, inputs: &[PathBuf]) -> Result<(), ()> {
    let targets = [
        (&run.json, "json"),
        (&run.svg, "svg"),
        (&run.png, "png"),
        (&run.html, "html"),
    ];
    let mut staged = vec![];
    for (path, kind) in targets {
        let Some(path) = path else { continue };
        let bytes = match kind {
            "json" => render::diff_json(d).into_bytes(),
            "svg" => render::diff_svg(d).into_bytes(),
            "html" => render::diff_html(d).into_bytes(),
            _ => render::diff_png(d)
                .map_err(|e| diag::print_plain(&format!("cannot render the PNG: {e}"), ""))?,
        };
        let s = write::stage(path, &bytes, inputs)
            .map_err(|e| diag::print_plain(&e, "choose another output path"))?;
        staged.push(s);
    }
    write::commit(staged)
        .map_err(|e| diag::print_plain(&e, "check the output folder: free space, permissions"))
}
