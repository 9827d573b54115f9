//! Turn the stages' results into the render crate's plain `Report`.

use crate::input::Loaded;
use expander::{Motion, Segment};
use render::{Crash, Diagnostic, PathKind, PathLine, Points, Report, Shape, StockInfo};
use std::fmt::Write as _;

fn shape(s: &stock::Shape) -> Shape {
    Shape {
        outer: s.outer.clone(),
        holes: s.holes.clone(),
    }
}

/// A diagnostic for the report; one raised in a `--lib` file names that file first (the
/// report's line and column are that file's).
fn diagnostic(loaded: &Loaded, d: &expander::Diagnostic) -> Diagnostic {
    let message = match loaded
        .library
        .as_ref()
        .and_then(|l| l.place(d.span.offset as usize))
    {
        Some((src, _)) => format!("in {}: {}", src.name, d.message),
        None => d.message.clone(),
    };
    Diagnostic {
        line: d.span.line,
        column: d.span.column,
        code: d.code.to_string(),
        message,
    }
}

/// The toolpath the pictures draw, made from the segments in their own memory (a path line
/// is smaller than a segment, so the vector is reused): the last use of the segments, which
/// a million-move run would otherwise hold beside 48 MB of path lines (issue 16). The JSON
/// report does not list the toolpath, so a run that writes only JSON keeps it empty.
pub(crate) fn add_toolpath(report: &mut Report, segments: Vec<Segment>) {
    report.toolpath = segments.into_iter().map(|s| path_line(&s)).collect();
    // the segments' buffer, kept by the in-place collect, is 2.5 times what the lines
    // need: give the rest back before the pictures are made (126 → 48 MB at 10⁶ moves)
    report.toolpath.shrink_to_fit();
}

/// The toolpath as drawn: arcs chorded at a drawing tolerance (the removal uses its own).
fn path_line(seg: &Segment) -> PathLine {
    let kind = match seg.motion {
        Motion::Rapid => PathKind::Rapid,
        Motion::Feed => PathKind::Feed,
        Motion::Thread => PathKind::Thread,
    };
    PathLine {
        kind,
        line: seg.span.line,
        // a straight move without the intermediate polyline, nor any allocation
        points: match seg.arc {
            None => Points::Two([[seg.from.z, seg.from.r], [seg.to.z, seg.to.r]]),
            Some(_) => Points::from(
                seg.polyline(0.01)
                    .into_iter()
                    .map(|p| [p.z, p.r])
                    .collect::<Vec<_>>(),
            ),
        },
    }
}

/// One title-block line per tool; "tool 0" is whatever cuts before the first T word.
fn tool_line(tools: &stock::ToolTable, t: u32) -> String {
    match (t, tools.numbers().first()) {
        (0, Some(&first)) => format!("{} (no T word)", tools.describe(first)),
        (0, None) => format!("{} (no T word)", tools.describe(0)),
        _ => tools.describe(t),
    }
}

/// The setup sheet's tools: each tool of the moves in order of first use, with its offsets,
/// what it is, its ISO designation and its times.
fn tool_list(
    tools: &stock::ToolTable,
    times: &expander::timing::Times,
    offsets: &[(u32, u32)],
) -> Vec<render::ToolEntry> {
    let cut = |t: u32| times.cutting.iter().find(|c| c.0 == t).map_or(0.0, |c| c.1);
    times
        .per_tool
        .iter()
        .map(|&(t, secs)| render::ToolEntry {
            number: t,
            offsets: offsets.iter().filter(|o| o.0 == t).map(|o| o.1).collect(),
            description: tools.get(t).unwrap_or(&stock::Tool::DEFAULT).describe(),
            designation: tools.designation(t).map(str::to_string),
            assumed: tools.get(t).is_none(),
            time_s: secs,
            cut_time_s: cut(t),
        })
        .collect()
}

/// A removal crash as the report shows it.
fn stock_crash(loaded: &Loaded, c: &stock::Crash) -> Crash {
    crash_at(loaded, c.segment, c.at, c.area, c.depth, c.body)
}

/// A crash at `segment`'s line: where the tool met stock or an obstacle, how much and how
/// deep, and the tool body that did (none for the cutting outline).
fn crash_at(
    loaded: &Loaded,
    segment: usize,
    at: [f64; 2],
    area_mm2: f64,
    depth_mm: f64,
    body: Option<&str>,
) -> Crash {
    let span = loaded.toolpath.segments[segment].span;
    Crash {
        line: span.line,
        column: span.column,
        z: at[0],
        r: at[1],
        area_mm2,
        depth_mm,
        body: body.map(str::to_string),
        ..Crash::default()
    }
}

/// A crash of the report with the move that made it and the tool's part that hit.
pub(crate) struct Listed {
    pub(crate) segment: usize,
    pub(crate) crash: Crash,
    body: Option<&'static str>,
}

/// The crashes of a run in program order: the removal's (spec/simulation.md, "Rapids that
/// cut": deeper than the profile's `rapid_cut_tol` is a crash, else a rapid scrape, a
/// warning; a body touching stock is always a crash) and the workholding's (always).
pub(crate) fn crash_list(
    loaded: &Loaded,
    sim: &stock::Simulation,
    fixture: &[stock::FixtureCrash],
) -> Vec<Listed> {
    let cut_tol = loaded.machine.rapid_cut_tol;
    let mut out: Vec<Listed> = sim
        .crashes
        .iter()
        .filter(|c| c.body.is_some() || c.depth > cut_tol)
        .map(|c| Listed {
            segment: c.segment,
            crash: stock_crash(loaded, c),
            body: c.body,
        })
        .collect();
    out.extend(fixture.iter().map(|f| Listed {
        segment: f.segment,
        crash: Crash {
            obstacle: Some(f.obstacle.to_string()),
            ..crash_at(loaded, f.segment, f.at, f.area, f.depth, f.body)
        },
        body: f.body,
    }));
    // stable: at one move, the stock's crash before the workholding's
    out.sort_by_key(|l| l.segment);
    out
}

/// What the reports read from the moves alone, not from the stock, so that it can be
/// worked out beside the removal: each is a pass over the moves (120 MB of them in a
/// million-move program).
pub(crate) struct MoveFacts {
    times: expander::timing::Times,
    rapid_segments: usize,
    /// The tools on a rear post ([`stock::rear_tools`]).
    rear: Vec<u32>,
    /// Each move's tool outline for the HTML player ([`stock::tool_outlines`]).
    #[allow(clippy::type_complexity)]
    outlines: (
        Vec<(Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>)>,
        Vec<(usize, usize)>,
    ),
}

impl MoveFacts {
    pub(crate) fn of(loaded: &Loaded, tools: &stock::ToolTable) -> Self {
        let segments = &loaded.toolpath.segments;
        let rear = stock::rear_tools(segments);
        Self {
            times: expander::timing::times(&loaded.toolpath, &loaded.machine),
            rapid_segments: segments
                .iter()
                .filter(|s| s.motion == Motion::Rapid)
                .count(),
            outlines: stock::tool_outlines(tools, segments, &rear),
            rear,
        }
    }
}

/// Crashes whose tool is drawn where it hit (the first ones: more would hide the picture).
const MAX_TOOL_POSES: usize = 20;

/// The crashes (the first [`MAX_TOOL_POSES`] with the tool drawn where it hit), the
/// workholding drawn, and each move's tool outline for the HTML player.
pub(crate) fn add_crashes(
    report: &mut Report,
    loaded: &Loaded,
    tools: &stock::ToolTable,
    crashes: &[Listed],
    fixture: Option<&stock::Fixture>,
    facts: MoveFacts,
) {
    let segments = &loaded.toolpath.segments;
    let MoveFacts {
        rear,
        outlines: (outlines, runs),
        ..
    } = facts;
    let tol = stock::SimOptions::default().chord_tol;
    report.crashes = crashes
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let mut c = l.crash.clone();
            if i < MAX_TOOL_POSES {
                let seg = &segments[l.segment];
                c.tool = stock::tool_at_crash(tools, seg, &rear, [c.z, c.r], l.body, tol);
            }
            c
        })
        .collect();
    report.tool_outlines = outlines
        .into_iter()
        .map(|(edge, body)| render::ToolOutline { edge, body })
        .collect();
    report.tool_runs = runs;
    report.stick_out_mm = fixture.and_then(|f| f.stick_out);
    if let Some(so) = fixture.and_then(|f| f.stick_out) {
        // "stick-out 15 mm", "stick-out 69.5 mm": three decimals, trailing zeros cut
        let n = format!("{so:.3}");
        let n = n.trim_end_matches('0').trim_end_matches('.');
        let _ = write!(report.stock.description, ", stick-out {n} mm");
    }
    if fixture.is_some_and(|f| {
        f.obstacles
            .iter()
            .any(|o| o.name == stock::TAILSTOCK_CENTRE)
    }) {
        if let Some(moves) = tailstock_moves(loaded) {
            let _ = write!(report.stock.description, "; {moves}");
        }
    }
    // the picture shows the part at the end: a centre the program leaves retracted is drawn
    // where it stood, and its label says so
    let retracted = loaded.toolpath.tailstock.last().is_some_and(|c| !c.1);
    report.fixture = fixture
        .iter()
        .flat_map(|f| f.obstacles.iter())
        .filter(|o| !o.cut_only)
        .map(|o| render::Fixture {
            name: if retracted && o.name == stock::TAILSTOCK_CENTRE {
                format!("{} (retracted)", stock::TAILSTOCK_CENTRE)
            } else {
                o.name.to_string()
            },
            shapes: o.shapes.iter().map(shape).collect(),
        })
        .collect();
}

/// Where the program moves the tailstock (M21/M22, M10/M11), for the stock's description:
/// the picture draws the centre where it stands advanced, so a retract must be said
/// ("tailstock retracted before line 4"); the first two changes are named. None when it
/// never moves.
fn tailstock_moves(loaded: &Loaded) -> Option<String> {
    let segments = &loaded.toolpath.segments;
    let changes: Vec<String> = loaded
        .toolpath
        .tailstock
        .iter()
        .filter_map(|&(k, advanced)| {
            let line = segments.get(k)?.span.line;
            let what = if advanced { "advanced" } else { "retracted" };
            Some(format!("{what} before line {line}"))
        })
        .collect();
    match changes.len() {
        0 => None,
        1 | 2 => Some(format!("tailstock {}", changes.join(", "))),
        n => Some(format!(
            "tailstock {}, … {} more changes",
            changes[..2].join(", "),
            n - 2
        )),
    }
}

/// Everything a finished run shows, but the toolpath ([`add_toolpath`]).
pub(crate) fn build(
    loaded: &Loaded,
    program_name: &str,
    blank: &stock::Blank,
    tools: &stock::ToolTable,
    sim: &stock::Simulation,
    tol: f64,
    facts: &MoveFacts,
) -> Report {
    let tp = &loaded.toolpath;
    let times = &facts.times;
    let cut = |c: &stock::Crash| stock_crash(loaded, c);
    let cut_tol = loaded.machine.rapid_cut_tol;
    let rapid_cuts: Vec<Crash> = sim
        .crashes
        .iter()
        .filter(|c| c.body.is_none() && c.depth <= cut_tol)
        .map(cut)
        .collect();
    let mut warnings: Vec<Diagnostic> = tp.warnings.iter().map(|d| diagnostic(loaded, d)).collect();
    warnings.extend(rapid_cuts.iter().map(|c| Diagnostic {
        line: c.line,
        column: c.column,
        code: "LS-RAPID-SCRAPE".into(),
        message: format!(
            "rapid scrapes {:.3} mm deep ({:.4} mm² of stock) at Z{:.3} X{:.3}: not more than rapid_cut_tol {cut_tol} mm, so not a crash; a rapid should clear the stock",
            c.depth_mm,
            c.area_mm2,
            c.z,
            2.0 * c.r
        ),
    }));
    for (seg, message) in &sim.warnings {
        let span = tp.segments.get(*seg).map(|s| s.span).unwrap_or_default();
        warnings.push(Diagnostic {
            line: span.line,
            column: span.column,
            code: "LS-STOCK".into(),
            message: message.clone(),
        });
    }
    // alarms and warnings listed up to a cap; the count of the rest is the last warning
    warnings.truncate(MAX_LISTED);
    for (what, n) in [
        ("alarms", tp.alarms.len()),
        (
            "warnings",
            tp.warnings.len() + rapid_cuts.len() + sim.warnings.len(),
        ),
    ] {
        if n > MAX_LISTED {
            warnings.push(Diagnostic {
                line: 0,
                column: 0,
                code: "LS-LIST-CAPPED".into(),
                message: format!(
                    "{n} {what}: the {MAX_LISTED} first are listed, {} more are not",
                    n - MAX_LISTED
                ),
            });
        }
    }
    Report {
        program: program_name.to_string(),
        title: tp.title.clone(),
        control: format!(
            "{} — {}",
            loaded.machine.control.key(),
            loaded.machine.control.title()
        ),
        stock: StockInfo {
            description: blank.description.clone(),
            shapes: blank.shapes.iter().map(shape).collect(),
        },
        final_part: sim.final_shapes.iter().map(shape).collect(),
        // filled last by `add_toolpath`, from the segments themselves
        toolpath: vec![],
        rapid_cuts,
        alarms: tp
            .alarms
            .iter()
            .take(MAX_LISTED)
            .map(|d| diagnostic(loaded, d))
            .collect(),
        warnings,
        // every tool of the moves in order of first use, with its time
        tools: times
            .per_tool
            .iter()
            .map(|&(t, secs)| {
                // "T01 · 32.6 s · turning …": the time before the long description
                let line = tool_line(tools, t);
                match line.split_once(' ') {
                    Some((num, rest)) => format!("{num} · {secs:.1} s · {rest}"),
                    None => format!("{line} · {secs:.1} s"),
                }
            })
            .collect(),
        removed_area_mm2: sim.removed_area,
        removed_volume_mm3: sim.removed_volume,
        segments: tp.segments.len(),
        rapid_segments: facts.rapid_segments,
        cycle_time_s: times.total,
        tolerance_mm: tol,
        grooves: tp
            .intended
            .iter()
            .filter(|i| i.kind == expander::IntendedKind::Groove)
            .map(|i| {
                let ring: Vec<[f64; 2]> = i.points.iter().map(|p| [p.z, p.r]).collect();
                render::Groove {
                    line: i.span.line,
                    deviation_mm: stock::groove_deviation(&ring, &sim.final_shapes),
                    ring,
                }
            })
            .collect(),
        variables: tp.variables.clone(),
        line_counts: tp.line_counts.clone(),
        tool_list: tool_list(tools, times, &tp.tool_offsets),
        ..Report::default()
    }
}

/// Most gouges (and leftovers) listed in a report; the count of the rest is a warning.
pub(crate) const MAX_LISTED: usize = 1_000;

/// The deviation findings: gouges (with the first line whose sweep made them), leftovers
/// (and where the largest is thickest), the intended shapes drawn dashed, and the summary.
pub(crate) fn add_deviation(
    report: &mut Report,
    loaded: &Loaded,
    intents: &[stock::Intent],
    deviation: Option<&stock::Deviation>,
) {
    // Closed rings as they are; an open path is drawn out and back.
    let intended: Vec<stock::Shape> = intents
        .iter()
        .flat_map(|i| i.outline.iter())
        .map(|(line, closed)| {
            let mut outer = line.clone();
            if !closed {
                outer.extend(line.iter().rev().skip(1).take(line.len().saturating_sub(2)));
            }
            stock::Shape {
                outer,
                holes: vec![],
            }
        })
        .collect();
    report.intended = intended.iter().map(shape).collect();
    let Some(d) = deviation else { return };
    let segs = &loaded.toolpath.segments;
    for (what, n) in [("gouges", d.gouges.len()), ("leftovers", d.leftovers.len())] {
        if n > MAX_LISTED {
            report.warnings.push(render::Diagnostic {
                line: 0,
                column: 0,
                code: "LS-FINDINGS-CAPPED".into(),
                message: format!(
                    "{n} {what}: the {MAX_LISTED} first are listed, {} more are not",
                    n - MAX_LISTED
                ),
            });
        }
    }
    for c in d.later_cuts.iter().take(MAX_LISTED) {
        let Some(seg) = c.made_by.and_then(|i| segs.get(i)) else {
            continue;
        };
        report.warnings.push(render::Diagnostic {
            line: seg.span.line,
            column: seg.span.column,
            code: "LS-LATER-CUT".into(),
            message: format!(
                "T{:02} cuts {:.3} mm² ({:.3} mm deep, at Z{:.3} X{:.3}) inside a contour another tool finished before: read as this operation's own cut (a groove, hole or relief), not a gouge (Interpretation; --target judges it against the drawing)",
                seg.tool,
                c.area,
                c.depth,
                c.at[0],
                2.0 * c.at[1]
            ),
        });
    }
    report.gouges = d
        .gouges
        .iter()
        .take(MAX_LISTED)
        .map(|g| render::Gouge {
            line: g
                .made_by
                .and_then(|i| segs.get(i))
                .map_or(0, |s| s.span.line),
            z: g.at[0],
            r: g.at[1],
            area_mm2: g.area,
            depth_mm: g.depth,
        })
        .collect();
    report.gouge_shapes = d
        .gouges
        .iter()
        .take(MAX_LISTED)
        .map(|g| shape(&g.shape))
        .collect();
    let leftovers = &d.leftovers[..d.leftovers.len().min(MAX_LISTED)];
    // the detail view looks where the largest leftover is deepest: the depth the summary
    // gives, measured to the same boundary (the intended part's, walls a profile drops
    // included)
    report.leftover_spot = leftovers
        .iter()
        .enumerate()
        .filter(|(_, l)| l.at.iter().chain(&l.nearest).all(|v| v.is_finite()))
        .max_by(|a, b| a.1.area.total_cmp(&b.1.area))
        .map(|(i, l)| {
            let measured = l.depth.is_finite();
            render::LeftoverSpot {
                leftover: i,
                centre: [
                    (l.at[0] + l.nearest[0]) / 2.0,
                    (l.at[1] + l.nearest[1]) / 2.0,
                ],
                thickness: measured.then_some(l.depth),
                measure: measured.then_some([l.at, l.nearest]),
            }
        });
    report.leftovers = leftovers.iter().map(|l| shape(&l.shape)).collect();
    report.deviation = Some(render::Deviation {
        overcut_area_mm2: d.overcut_area(),
        undercut_area_mm2: d.undercut_area(),
        max_overcut_mm: d.max_overcut(),
        max_undercut_mm: d.max_undercut(),
    });
}

/// The threads, checked in the final section (`stock::threads`): the diameter reached
/// against the programmed final X, or against `target`'s surface over the thread when a
/// `--target` is given (a target draws a thread at its minor diameter, OD, or major, ID).
/// A thread deeper than expected by more than `--tol` fails the run like a gouge (part
/// material removed); one too shallow is a warning (like a leftover). Both are warnings
/// `LS-THREAD-DEPTH` at the thread's line. `before`: the stock each thread cut into, by its
/// first move, where it was kept: the depth is measured only where that stock came up to
/// the root (a relief groove cut deeper before is not the thread's depth).
pub(crate) fn add_threads(
    report: &mut Report,
    loaded: &Loaded,
    sim: &stock::Simulation,
    target: Option<&[stock::Shape]>,
    before: &[(usize, Vec<stock::Shape>)],
    passes: &stock::ThreadPasses,
) {
    let shapes = &sim.final_shapes;
    for t in passes.measure(&loaded.toolpath.segments, shapes) {
        if t.wrong_side {
            let (side, toward, other) = match t.surface {
                stock::Surface::Outer => ("an OD", "outward (an inside thread)", "id"),
                stock::Surface::Bore => ("an ID", "inward (an outside thread)", "od"),
            };
            report.alarms.push(render::Diagnostic {
                line: t.span.line,
                column: t.span.column,
                code: "LS-THREAD-SIDE".into(),
                message: format!(
                    "the thread passes go deeper {toward} but the threading tool is {side} insert: its body sweeps through the part; give the tool `side = \"{other}\"` in the tool table"
                ),
            });
        }
        let cut_into = before
            .iter()
            .find(|(k, _)| *k == t.first_move)
            .map(|(_, s)| s.as_slice());
        let achieved = t.achieved_x(shapes, cut_into);
        let form = t.form(shapes);
        let (z0, z1) = t.z_span();
        let sign = match t.surface {
            stock::Surface::Outer => 1.0,
            stock::Surface::Bore => -1.0,
        };
        // the least gap between the section and what it should be (negative: deeper)
        let (gap, expected) = match target {
            Some(part) => {
                let gap =
                    stock::least_gap(shapes, stock::Reference::Shapes(part), z0, z1, t.surface);
                (gap, achieved.zip(gap).map(|(a, g)| a - sign * 2.0 * g))
            }
            None => (achieved.map(|a| sign * (a - t.x()) / 2.0), Some(t.x())),
        };
        let depth_error = gap.map(|g| -g);
        if let Some(e) = depth_error.filter(|e| e.abs() > report.tolerance_mm) {
            report.warnings.push(render::Diagnostic {
                line: t.span.line,
                column: t.span.column,
                code: "LS-THREAD-DEPTH".into(),
                message: format!(
                    "thread depth error: the thread is cut {:.3} mm too {}{}",
                    e.abs(),
                    if e > 0.0 { "deep" } else { "shallow" },
                    match (achieved, expected) {
                        (Some(a), Some(x)) => format!(" (X{a:.3} reached, X{x:.3} expected)"),
                        _ => String::new(),
                    },
                ),
            });
        }
        report.threads.push(render::ThreadCheck {
            line: t.span.line,
            inside: t.surface == stock::Surface::Bore,
            lead_mm: t.lead,
            starts: t.starts,
            x_mm: t.x(),
            expected_x_mm: expected,
            pass_depths_mm: t.pass_depths.clone(),
            achieved_x_mm: achieved,
            depth_error_mm: depth_error,
            pitch_diameter_mm: form.map(|f| f.pitch_diameter),
            included_angle_deg: form.and_then(|f| f.included_angle),
            z_start_mm: z0,
            z_end_mm: z1,
        });
    }
}

/// How many snapshots (besides the blank and the final part).
const SNAPSHOTS: usize = 30;
/// How many for programs over 5 000 moves, where each is a union of all the removal's
/// tiles (the 10⁵-move cutting zig-zag: 29 of them added 3.2 s to a 4.1 s run).
const SNAPSHOTS_LONG: usize = 10;

/// Move counts after which the simulation keeps the stock for the HTML report's move
/// slider (taken in the simulation's one pass: exactly at these counts up to 5 000 moves,
/// at the removal's epoch ends nearest after them beyond; `stock::Simulation::snapshots`).
pub(crate) fn snapshot_marks(moves: usize) -> Vec<usize> {
    if moves == 0 {
        return vec![];
    }
    let count = if moves > stock::SNAPSHOT_EXACT_MAX_MOVES {
        SNAPSHOTS_LONG
    } else {
        SNAPSHOTS
    };
    let mut marks: Vec<usize> = (1..count)
        .map(|i| i * moves / count)
        .filter(|&k| k > 0 && k < moves)
        .collect();
    marks.dedup();
    marks
}

/// The stock part-way through the run for the HTML report: the blank, the snapshots the
/// simulation took at [`snapshot_marks`], and the final part.
pub(crate) fn snapshots(
    blank: &stock::Blank,
    moves: usize,
    sim: &stock::Simulation,
) -> Vec<render::Snapshot> {
    if moves == 0 {
        return vec![];
    }
    let mut out = vec![render::Snapshot {
        after_move: 0,
        shapes: blank.shapes.iter().map(shape).collect(),
    }];
    out.extend(sim.snapshots.iter().map(|(k, shapes)| render::Snapshot {
        after_move: *k,
        shapes: shapes.iter().map(shape).collect(),
    }));
    out.push(render::Snapshot {
        after_move: moves,
        shapes: sim.final_shapes.iter().map(shape).collect(),
    });
    out
}
