//! The intents a program defines for itself (its finishing shapes, grooves and compensated
//! contours), where the thread moves' own teeth are left out of every intent, and the
//! stock snapshots reading them needs.

use super::{Intent, Stages};
use crate::Intents;
use expander::{IntendedKind, Motion, Segment, Toolpath};
use stock::{boolean, BoolOp, Shape, ToolTable};

/// The stock after `k` moves where the run kept it (`None` where it did not).
type KeptAt<'a> = dyn Fn(usize) -> Option<Vec<Shape>> + 'a;

/// The intents the run is judged against: `intents`' drawing, else the shapes the program
/// defines for itself, each read against the stock when its cycle began (`stock_at(k)`: the
/// stock after `k` moves). What the thread moves cut between their deepest pass and the
/// top of the tool's flanks is the thread's own business (spec/simulation.md: "its teeth
/// are cut to this form"): no other intent speaks where the thread found stock
/// ([`thread_own`]; `kept_at(k)`: the stock after `k` moves where the run kept it).
pub(crate) fn read(
    intents: &Intents,
    toolpath: &Toolpath,
    tools: &ToolTable,
    (stock_at, kept_at): (&dyn Fn(usize) -> Vec<Shape>, &KeptAt<'_>),
) -> Vec<Intent> {
    let mut read = match intents {
        Intents::Target(part) => vec![Intent::target(part.clone())],
        Intents::Program => own(toolpath, tools, stock_at),
    };
    if read.is_empty() {
        return read;
    }
    let threads = thread_own(&toolpath.segments, tools, kept_at);
    if !threads.is_empty() {
        for i in &mut read {
            i.zone = boolean(&i.zone, &threads, BoolOp::Difference);
        }
    }
    read
}

/// Each thread's band ([`thread_bands`]) where stock stood when the thread began: what a
/// turning tool had already taken there is that tool's cut, judged as before (README,
/// Interpretation: other turning tools are judged on their own cuts). A skim 0.4 mm under
/// the crest, then a thread cut into it, was hidden by the whole band: the part was
/// reported clean (field run 8, C). A thread whose starting stock the run did not keep
/// (past the first [`MAX_STOCK_MARKS`] / 2) keeps its whole band.
fn thread_own(segments: &[Segment], tools: &ToolTable, kept_at: &KeptAt<'_>) -> Vec<Shape> {
    let starts = crate::measure::ThreadPasses::of(segments, tools).starts();
    let mut own = vec![];
    for (k, &start) in starts.iter().enumerate() {
        let end = starts.get(k + 1).copied().unwrap_or(segments.len());
        let band = bands_of(&segments[start..end], tools);
        if band.is_empty() {
            continue;
        }
        match kept_at(start) {
            Some(stock) => own.extend(boolean(&band, &stock, BoolOp::Intersection)),
            None => own.extend(band),
        }
    }
    // thread moves outside the threads found (a lone pass) keep their bands whole
    let first = starts.first().copied().unwrap_or(segments.len());
    own.extend(bands_of(&segments[..first], tools));
    if own.is_empty() {
        return own;
    }
    boolean(&own, &[], BoolOp::Union)
}

/// The bands of the thread moves among `segments` ([`thread_bands`]), not joined.
fn bands_of(segments: &[Segment], tools: &ToolTable) -> Vec<Shape> {
    segments
        .iter()
        .filter(|s| s.motion == Motion::Thread)
        .filter_map(|s| band(s, tools))
        .collect()
}

/// Where thread moves cut their teeth: above each pass (below, for a tool whose body lies
/// below its tip) up to the height where the tool's flanks reach their full width, over
/// the pass's Z span grown by that width. A pass below the axis is seen mirrored.
pub(crate) fn thread_bands(segments: &[Segment], tools: &ToolTable) -> Vec<Shape> {
    let bands = bands_of(segments, tools);
    if bands.is_empty() {
        return bands;
    }
    boolean(&bands, &[], BoolOp::Union)
}

/// The band of one thread move ([`thread_bands`]).
fn band(s: &Segment, tools: &ToolTable) -> Option<Shape> {
    const FAR: f64 = 1e5;
    let outline = tools.outline_for(s.tool, s.hint).0;
    let (lo, hi) = outline.bbox()?;
    let up = hi[1] >= -lo[1];
    let w = lo[0].abs().max(hi[0].abs());
    // the flank height: the least |r| at which the outline is as wide as it gets
    let h = outline
        .parts
        .iter()
        .flatten()
        .filter(|p| p[0].abs() >= w - 1e-9)
        .map(|p| p[1].abs())
        .fold(FAR, f64::min);
    let h = if up { h } else { -h };
    let (a, b) = if s.from.z <= s.to.z {
        (s.from, s.to)
    } else {
        (s.to, s.from)
    };
    let (ra, rb) = if a.r + b.r < 0.0 {
        (-a.r, -b.r)
    } else {
        (a.r, b.r)
    };
    Some(Shape {
        outer: vec![
            [a.z - w, ra],
            [b.z + w, rb],
            [b.z + w, rb + h],
            [a.z - w, ra + h],
        ],
        holes: vec![],
    })
}

/// The shapes the program defines for itself, in program order, those a later contour
/// overcuts left out ([`overcut_later`]).
fn own(
    toolpath: &Toolpath,
    tools: &ToolTable,
    stock_at: &dyn Fn(usize) -> Vec<Shape>,
) -> Vec<Intent> {
    let intended = &toolpath.intended;
    let segments = &toolpath.segments;
    let (blank, finished) = (stock_at(0), stock_at(usize::MAX));
    intended
        .iter()
        .enumerate()
        .filter(|(k, i)| !overcut_later(intended, *k, i))
        .map(|(_, i)| i)
        .filter_map(|i| {
            // a shape programmed below the axis (a rear post) is seen mirrored in the
            // section, where its sides swap
            let below = i.points.iter().map(|p| p.r).sum::<f64>() < 0.0;
            let pts: Vec<[f64; 2]> = i
                .points
                .iter()
                .map(|p| [p.z, if below { -p.r } else { p.r }])
                .collect();
            // the tool that finishes the contour, from where its first cycle began (a G71's
            // roughing before the G70): later feeds of other tools are theirs
            let comp = match i.kind {
                IntendedKind::Compensated { part_on_left } => Some(super::Comp {
                    part_on_left,
                    wrong_side: wrong_side(i, segments, tools),
                }),
                _ => None,
            };
            let owner = segments.get(i.after_move).map(|s| super::Owner {
                tool: s.tool,
                began: i.began,
                finish: i.after_move,
                comp,
            });
            let contour = |intent: Option<Intent>| intent.map(|x| Intent { owner, ..x });
            // read against the stock where its cycle began; a contour wholly in the air
            // there (a guessed tool's roughing cut the wall on the wrong side, another tool
            // cut deeper) against the blank, rather than dropped
            let read = |began: &[Shape]| {
                let stages = Stages {
                    began,
                    finished: &finished,
                    blank: &blank,
                };
                match i.kind {
                    IntendedKind::Groove => Some(Intent::groove(&pts)),
                    IntendedKind::FinishingContour => Intent::finishing(&pts, &stages),
                    IntendedKind::Compensated { part_on_left } => {
                        // the side the tool's stated tip gives wins over a G41/G42 that
                        // contradicts it (LS-COMP-SIDE)
                        let wrong = comp.is_some_and(|c| c.wrong_side);
                        Intent::compensated(&pts, (part_on_left != below) != wrong, &stages)
                    }
                }
            };
            let intent = read(&stock_at(i.after_move))
                .filter(|it| !it.part.is_empty())
                .or_else(|| read(&blank));
            if i.kind == IntendedKind::Groove {
                intent
            } else {
                contour(intent)
            }
        })
        .collect()
}

/// Whether the compensated contour `i` keeps the part on the other side than its tool's
/// stated tip says (an ID tip 1, 2 or 6 keeps the part outside its path, an OD tip 3, 4 or
/// 8 inside): G42 along a bore, G41 along an OD toward the chuck. The control offsets the
/// nose into the part; the part is the path's other side (field run 8, I: a bore under
/// G42 was CLEAN with the bore 1.6 mm larger, an OD under G41 a gouge blamed on its
/// roughing). Front post only (a rear post's tips are not sorted out here).
fn wrong_side(i: &expander::Intended, segments: &[Segment], tools: &ToolTable) -> bool {
    let IntendedKind::Compensated { part_on_left } = i.kind else {
        return false;
    };
    let Some(seg) = segments.get(i.after_move) else {
        return false;
    };
    if !tools.tip_stated(seg.tool) || i.points.iter().any(|p| p.r < 0.0) {
        return false;
    }
    let inside_tool = match tools.get(seg.tool) {
        Some(stock::Tool::Turning { tip: 1 | 2 | 6, .. }) => true,
        Some(stock::Tool::Turning { tip: 3 | 4 | 8, .. }) => false,
        _ => return false,
    };
    let outward = stock::outward_travel(&i.points, part_on_left);
    const CLEAR: f64 = 1.0;
    (inside_tool && outward < -CLEAR) || (!inside_tool && outward > CLEAR)
}

/// The warning LS-COMP-SIDE for each contour cut under G41/G42 on the other side than its
/// tool's stated tip gives ([`wrong_side`]).
pub(crate) fn comp_side_notes(toolpath: &Toolpath, tools: &ToolTable) -> Vec<crate::Note> {
    toolpath
        .intended
        .iter()
        .filter(|i| wrong_side(i, &toolpath.segments, tools))
        .filter_map(|i| {
            let seg = toolpath.segments.get(i.after_move)?;
            let IntendedKind::Compensated { part_on_left } = i.kind else {
                return None;
            };
            let (code, other) = super::Comp {
                part_on_left,
                wrong_side: true,
            }
            .codes();
            Some(crate::Note {
                span: i.span,
                code: "LS-COMP-SIDE",
                message: format!(
                    "{code} keeps T{:02}'s nose on the part's side: its tip says the part lies on the other side of this contour, so the nose is offset into it (write {other}); the contour is read with the part on the tip's side",
                    seg.tool
                ),
            })
        })
        .take(crate::MAX_LISTED)
        .collect()
}

/// A contour cut under G41/G42 is an intent only when it is the last pass over its stretch
/// of surface (spec/simulation.md, "The intended shape": roughing passes are not intents,
/// compensated or not): it is dropped when a later compensated contour with the part on the
/// same side covers an overlapping Z span.
fn overcut_later(all: &[expander::Intended], k: usize, i: &expander::Intended) -> bool {
    let IntendedKind::Compensated { part_on_left } = i.kind else {
        return false;
    };
    let span = |i: &expander::Intended| {
        i.points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.z), hi.max(p.z))
            })
    };
    let (lo, hi) = span(i);
    all[k + 1..].iter().any(|later| {
        let (a, b) = span(later);
        later.kind == (IntendedKind::Compensated { part_on_left }) && a < hi - 1e-6 && b > lo + 1e-6
    })
}

/// The move counts after which [`read`] wants the stock (to take them in the removal pass,
/// `stock::SimOptions::snapshot_after`): one per contour that stays an intent. Only
/// programs of up to [`MAX_MOVES_FOR_MARKS`] moves get them, at most [`MAX_STOCK_MARKS`];
/// other contours are read against the final part (which has at most less material than
/// the stock of their cycle: a lead-in in front of either is dropped).
pub fn stock_marks(toolpath: &Toolpath) -> Vec<usize> {
    let intended = &toolpath.intended;
    if toolpath.segments.len() > MAX_MOVES_FOR_MARKS {
        return vec![];
    }
    let mut marks: Vec<usize> = intended
        .iter()
        .enumerate()
        .filter(|(k, i)| i.kind != IntendedKind::Groove && !overcut_later(intended, *k, i))
        .map(|(_, i)| i.after_move)
        .collect();
    marks.sort_unstable();
    marks.dedup();
    marks.truncate(MAX_STOCK_MARKS);
    marks
}

/// The move counts after which the threads want the stock exactly, whatever the program's
/// length (`stock::SimOptions::snapshot_exact`): each thread's first move (what it cuts
/// into, `Thread::achieved_x`) and the end of its last pass (the thread as it cut itself,
/// before a later tool deburrs it: a thread's verdict must not depend on how many moves
/// come before it), for the first [`MAX_STOCK_MARKS`] / 2 threads; later ones are
/// measured in the final part.
pub fn thread_marks(toolpath: &Toolpath, tools: &ToolTable) -> Vec<usize> {
    let segments = &toolpath.segments;
    marks_of_threads(&crate::measure::ThreadPasses::of(segments, tools), segments)
}

/// [`thread_marks`] of the threads' `passes` found in `segments`.
pub(crate) fn marks_of_threads(
    passes: &crate::measure::ThreadPasses,
    segments: &[expander::Segment],
) -> Vec<usize> {
    passes
        .starts()
        .into_iter()
        .zip(passes.ends(segments))
        .take(MAX_STOCK_MARKS / 2)
        .flat_map(|(start, end)| [start, end])
        .collect()
}

/// Most stock snapshots taken for reading contours, and for threads.
const MAX_STOCK_MARKS: usize = 64;
/// Programs longer than this read their intents against the final part.
const MAX_MOVES_FOR_MARKS: usize = 5_000;
