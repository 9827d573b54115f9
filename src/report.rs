//! The findings as the render crate's plain `Report`: a mapping, no rule. What a run
//! concludes is `analysis`'; here it is only put into the report's words and units.

use crate::input::Loaded;
use analysis::{Findings, MAX_LISTED};
use expander::{Motion, Segment, Span};
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

/// What the report is made of besides the findings.
pub(crate) struct Run<'a> {
    pub(crate) loaded: &'a Loaded,
    pub(crate) name: &'a str,
    pub(crate) blank: &'a stock::Blank,
    pub(crate) tools: &'a stock::ToolTable,
    pub(crate) sim: &'a stock::Simulation,
    pub(crate) fixture: Option<&'a analysis::Fixture>,
    pub(crate) tol: f64,
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
            description: tools.tool_or_default(t).describe(),
            designation: tools.designation(t).map(str::to_string),
            assumed: !tools.size_stated(t, expander::ToolHint::Table),
            in_table: tools.get(t).is_some(),
            from_moves: tools.taken_from_moves(t),
            time_s: secs,
            cut_time_s: cut(t),
        })
        .collect()
}

/// Everything a finished run shows, but the toolpath ([`add_toolpath`]) and the player's
/// snapshots ([`snapshots`]).
pub(crate) fn report(run: &Run, findings: &Findings) -> Report {
    let mut report = summary(run, findings);
    add_crashes(&mut report, run, findings);
    add_deviation(&mut report, run.loaded, findings);
    add_threads(&mut report, findings);
    report.verdict = verdict(findings.verdict);
    report
}

fn verdict(v: analysis::Verdict) -> render::Verdict {
    match v {
        analysis::Verdict::Clean => render::Verdict::Clean,
        analysis::Verdict::Alarm => render::Verdict::Alarm,
        analysis::Verdict::Crash => render::Verdict::Crash,
        analysis::Verdict::Gouge => render::Verdict::Gouge,
    }
}

/// A note of the analysis at its place in the program.
fn note(n: &analysis::Note) -> Diagnostic {
    Diagnostic {
        line: n.span.line,
        column: n.span.column,
        code: n.code.into(),
        message: n.message.clone(),
    }
}

/// A cause of the analysis in the report's words.
fn cause(c: &analysis::Cause) -> render::Cause {
    render::Cause {
        kind: c.kind.word().to_string(),
        text: c.text.clone(),
        numbers: c
            .numbers
            .iter()
            .map(|(k, v)| ((*k).to_string(), *v))
            .collect(),
    }
}

/// A checked remedy of the analysis in the report's words.
fn remedy(r: &analysis::Remedy) -> render::Remedy {
    render::Remedy {
        text: r.text.clone(),
        tool: r.tool.clone(),
        line: r.line,
        edit: r.edit.clone(),
        verified: r.verified,
        ghost: r.ghost.clone(),
    }
}

/// A crash (or scrape) of the analysis at its move's line.
fn crash(segments: &[Segment], c: &analysis::Crash) -> Crash {
    let span: Span = segments[c.segment].span;
    Crash {
        line: span.line,
        column: span.column,
        z: c.at[0],
        r: c.at[1],
        area_mm2: c.area,
        depth_mm: c.depth,
        body: c.body.map(str::to_string),
        obstacle: c.obstacle.map(str::to_string),
        tool: c.tool.clone(),
        assumed: c.assumed,
        cause: c.cause.as_ref().map(cause),
        remedy: c.remedy.as_ref().map(remedy),
    }
}

/// The title block, the blank and the final part, the alarms and warnings of the toolpath
/// and of the moves, the tools and times, the grooves.
fn summary(run: &Run, findings: &Findings) -> Report {
    let loaded = run.loaded;
    let tp = &loaded.toolpath;
    let times = &findings.facts.times;
    let sim = run.sim;
    Report {
        program: run.name.to_string(),
        title: tp.title.clone(),
        control: format!(
            "{} — {}",
            loaded.machine.control.key(),
            loaded.machine.control.title()
        ),
        encoding: loaded.encoding.to_string(),
        stock: StockInfo {
            description: run.blank.description.clone(),
            shapes: run.blank.shapes.iter().map(shape).collect(),
        },
        final_part: sim.final_shapes.iter().map(shape).collect(),
        // filled last by `add_toolpath`, from the segments themselves
        toolpath: vec![],
        rapid_cuts: findings
            .scrapes
            .iter()
            .map(|c| crash(&tp.segments, c))
            .collect(),
        alarms: tp
            .alarms
            .iter()
            .take(MAX_LISTED)
            .map(|d| diagnostic(loaded, d))
            .collect(),
        warnings: warnings(run, findings),
        tools: tool_times(run.tools, times),
        removed_area_mm2: sim.removed_area,
        removed_volume_mm3: sim.removed_volume,
        segments: tp.segments.len(),
        rapid_segments: findings.facts.rapid_segments,
        cycle_time_s: times.total,
        tolerance_mm: run.tol,
        grooves: findings
            .grooves
            .iter()
            .map(|g| render::Groove {
                line: g.span.line,
                ring: g.ring.clone(),
                deviation_mm: g.deviation_mm,
            })
            .collect(),
        variables: tp.variables.clone(),
        line_counts: tp.line_counts.clone(),
        tool_list: tool_list(run.tools, times, &tp.tool_offsets),
        ..Report::default()
    }
}

/// The warnings of the toolpath, of the analysis and of the removal, listed up to a cap;
/// the count of what is not listed (alarms too) is the last warning.
fn warnings(run: &Run, findings: &Findings) -> Vec<Diagnostic> {
    let loaded = run.loaded;
    let tp = &loaded.toolpath;
    let sim = run.sim;
    let mut warnings: Vec<Diagnostic> = tp.warnings.iter().map(|d| diagnostic(loaded, d)).collect();
    warnings.extend(findings.warnings.iter().map(note));
    for (seg, message) in &sim.warnings {
        let span = tp.segments.get(*seg).map(|s| s.span).unwrap_or_default();
        warnings.push(Diagnostic {
            line: span.line,
            column: span.column,
            code: "LS-STOCK".into(),
            message: message.clone(),
        });
    }
    warnings.truncate(MAX_LISTED);
    for (what, n) in [
        ("alarms", tp.alarms.len()),
        (
            "warnings",
            tp.warnings.len() + findings.warnings.len() + sim.warnings.len(),
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
    warnings
}

/// Every tool of the moves in order of first use, with its time: "T01 · 32.6 s · turning
/// …", the time before the long description.
fn tool_times(tools: &stock::ToolTable, times: &expander::timing::Times) -> Vec<String> {
    times
        .per_tool
        .iter()
        .map(|&(t, secs)| {
            let line = tool_line(tools, t);
            match line.split_once(' ') {
                Some((num, rest)) => format!("{num} · {secs:.1} s · {rest}"),
                None => format!("{line} · {secs:.1} s"),
            }
        })
        .collect()
}

/// The crashes (the first with the tool drawn where it hit), the workholding drawn, and
/// each move's tool outline for the HTML player.
fn add_crashes(report: &mut Report, run: &Run, findings: &Findings) {
    let loaded = run.loaded;
    let segments = &loaded.toolpath.segments;
    report.crashes = findings
        .crashes
        .iter()
        .map(|c| crash(segments, c))
        .collect();
    report.tool_outlines = findings
        .facts
        .outlines
        .iter()
        .map(|(edge, body)| render::ToolOutline {
            edge: edge.clone(),
            body: body.clone(),
        })
        .collect();
    report.tool_runs = findings.facts.runs.clone();
    let fixture = run.fixture;
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
            .any(|o| o.name == analysis::TAILSTOCK_CENTRE)
    }) {
        if let Some(moves) = tailstock_moves(loaded) {
            let _ = write!(report.stock.description, "; {moves}");
        }
    }
    // the picture shows the part at the end: a centre the program leaves retracted is drawn
    // retracted, and its label says so
    let retracted = loaded.toolpath.tailstock.last().is_some_and(|c| !c.1);
    report.fixture = fixture
        .iter()
        .flat_map(|f| f.obstacles.iter())
        .filter(|o| !o.cut_only)
        .map(|o| {
            if retracted && o.name == analysis::TAILSTOCK_CENTRE {
                render::Fixture {
                    name: format!("{} (retracted)", analysis::TAILSTOCK_CENTRE),
                    shapes: o
                        .shapes
                        .iter()
                        .map(|s| shape(&shifted(s, RETRACT_DRAWN)))
                        .collect(),
                }
            } else {
                render::Fixture {
                    name: o.name.to_string(),
                    shapes: o.shapes.iter().map(shape).collect(),
                }
            }
        })
        .collect();
}

/// How far back along +Z a retracted tailstock centre is drawn, mm (the picture shows the
/// end of the run): a gap that shows it clear of the part, small enough that the centre and
/// its label stay in a view fitted to the part.
const RETRACT_DRAWN: f64 = 5.0;

/// `s` moved `dz` along Z.
fn shifted(s: &stock::Shape, dz: f64) -> stock::Shape {
    let mv = |ring: &Vec<[f64; 2]>| ring.iter().map(|p| [p[0] + dz, p[1]]).collect();
    stock::Shape {
        outer: mv(&s.outer),
        holes: s.holes.iter().map(mv).collect(),
    }
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

/// The deviation findings: gouges (with the first line whose sweep made them), leftovers
/// (and where the largest is thickest), the intended shapes drawn dashed, and the summary.
fn add_deviation(report: &mut Report, loaded: &Loaded, findings: &Findings) {
    report.intended = intended(findings);
    let Some(d) = &findings.deviation else {
        return;
    };
    let segs = &loaded.toolpath.segments;
    for (what, n) in [("gouges", d.gouges.len()), ("leftovers", d.leftovers.len())] {
        if n > MAX_LISTED {
            report.warnings.push(Diagnostic {
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
            assumed: g.assumed,
            cause: g.cause.as_ref().map(cause),
            remedy: g.remedy.as_ref().map(remedy),
        })
        .collect();
    report.gouge_shapes = d
        .gouges
        .iter()
        .take(MAX_LISTED)
        .map(|g| shape(&g.shape))
        .collect();
    add_leftovers(report, &d.leftovers[..d.leftovers.len().min(MAX_LISTED)]);
    report.deviation = Some(render::Deviation {
        overcut_area_mm2: d.overcut_area(),
        undercut_area_mm2: d.undercut_area(),
        max_overcut_mm: d.max_overcut(),
        max_undercut_mm: d.max_undercut(),
    });
}

/// The intended outlines as drawn: closed rings as they are, an open path out and back.
fn intended(findings: &Findings) -> Vec<Shape> {
    findings
        .intents
        .iter()
        .flat_map(|i| i.outline.iter())
        .map(|(line, closed)| {
            let mut outer = line.clone();
            if !closed {
                outer.extend(line.iter().rev().skip(1).take(line.len().saturating_sub(2)));
            }
            Shape {
                outer,
                holes: vec![],
            }
        })
        .collect()
}

/// The leftovers listed (their shapes, causes and the detail view's spot).
fn add_leftovers(report: &mut Report, leftovers: &[analysis::Finding]) {
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
    report.leftover_list = leftovers
        .iter()
        .map(|l| render::Leftover {
            z: l.at[0],
            r: l.at[1],
            area_mm2: l.area,
            depth_mm: l.depth,
            cause: l.cause.as_ref().map(cause),
        })
        .collect();
}

/// The threads as checked, with their alarms and the part's warnings (later cuts, thread
/// depths) after the deviation's.
fn add_threads(report: &mut Report, findings: &Findings) {
    report
        .warnings
        .extend(findings.part_warnings.iter().map(note));
    report.alarms.extend(findings.alarms.iter().map(note));
    report.threads = findings
        .threads
        .iter()
        .map(|t| render::ThreadCheck {
            line: t.span.line,
            inside: t.inside,
            lead_mm: t.lead_mm,
            starts: t.starts,
            x_mm: t.x_mm,
            expected_x_mm: t.expected_x_mm,
            pass_depths_mm: t.pass_depths_mm.clone(),
            achieved_x_mm: t.achieved_x_mm,
            depth_error_mm: t.depth_error_mm,
            pitch_diameter_mm: t.pitch_diameter_mm,
            included_angle_deg: t.included_angle_deg,
            z_start_mm: t.z_start_mm,
            z_end_mm: t.z_end_mm,
        })
        .collect();
}

/// The stock part-way through the run for the HTML report: the blank, the snapshots the
/// simulation took at `stock::player_marks`, and the final part.
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
