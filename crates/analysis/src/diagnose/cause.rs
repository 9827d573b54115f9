//! The cause of a crash, a gouge or a leftover, from the geometry.

use super::insert::{Facts, Part};
use crate::deviation::Finding;
use crate::findings::{Cause, CauseKind, Crash};
use crate::{Intent, Settings};
use expander::{Motion, Segment};
use geom::flat::{segment_distance, P};
use stock::{Mounts, Tool};

/// How near a move's sweep must come to a gouge's deepest point to have reached it, mm (the
/// removal's grid and chords put the region's edge within this of the float sweep).
const REACH: f64 = 1e-3;

/// Most moves after the one that made a gouge looked at for the one that reached its
/// deepest point.
const MAX_LOOKED_AT: usize = 20_000;

/// A program's X (a diameter) and Z, as a machinist reads them.
fn place(p: P) -> String {
    format!("Z{:.3} X{:.3}", p[0], 2.0 * p[1])
}

/// The tool that cuts `seg`, as the table (or its default) has it.
fn tool_of(seg: &Segment, s: &Settings) -> Tool {
    let t = if seg.tool == 0 {
        s.tools.numbers().first().copied().unwrap_or(0)
    } else {
        seg.tool
    };
    s.tools.tool_or_default(t).clone()
}

/// The cause of a crash: the workholding, the tool's body, or a rapid into uncut stock
/// (with the stock's edge it met: the face, or a diameter).
pub(crate) fn crash(c: &Crash, segments: &[Segment], s: &Settings, rear: &[u32]) -> Cause {
    let seg = &segments[c.segment];
    let part = c.body.unwrap_or("cutting edge");
    let numbers = vec![("depth_mm", c.depth), ("area_mm2", c.area)];
    if let Some(o) = c.obstacle {
        return Cause {
            kind: CauseKind::Workholding,
            text: format!(
                "the tool's {part} enters the {o} at {} ({:.3} mm)",
                place(c.at),
                c.depth
            ),
            numbers,
        };
    }
    if let Some(body) = c.body {
        return Cause {
            kind: CauseKind::Body,
            text: format!(
                "the {body} reaches what the edge does not: it meets stock at {}, {:.3} mm deep ({})",
                place(c.at),
                c.depth,
                s.tools.describe(seg.tool)
            ),
            numbers,
        };
    }
    if let Some(text) = past_the_axis(c, seg, s, rear) {
        return Cause {
            kind: CauseKind::Rapid,
            text,
            numbers,
        };
    }
    let what = if seg.motion == Motion::Rapid {
        "a rapid"
    } else {
        "the move"
    };
    Cause {
        kind: CauseKind::Rapid,
        text: format!(
            "{what} from {} to {} runs into uncut stock: it meets {} at {}, {:.3} mm deep",
            place([seg.from.z, seg.from.r]),
            place([seg.to.z, seg.to.r]),
            stock_edge(c.at, s),
            place(c.at),
            c.depth
        ),
        numbers,
    }
}

/// The cause of a crash made by the far side of a stated tool: the edge, where its point
/// passes, reaches no radius as large as the contact's, and reaches past the axis as far
/// (the section folds it onto the wall opposite). A DNMG 11 on a bar in a Ø16 hole: "a rapid
/// at X16 meets stock at Ø17.9" sent the programmer to a coordinate that is right (field run
/// 10, B4); the tool is too big for the bore.
fn past_the_axis(c: &Crash, seg: &Segment, s: &Settings, rear: &[u32]) -> Option<String> {
    const SLACK: f64 = 0.01;
    let m = stock::Mounted::new(s.tools, seg.tool, seg.hint, rear.contains(&seg.tool));
    let (a, b) = ([seg.from.z, seg.from.r], [seg.to.z, seg.to.r]);
    let r = geom::flat::lerp(a, b, geom::flat::segment_param(c.at, a, b))[1];
    // a front tool whose size is stated (a guessed outline is left out past the axis)
    if r < 0.0 || m.edge.past_axis != stock::PastAxis::Fold {
        return None;
    }
    let drs = m.edge.parts.iter().flatten().map(|p| p[1]);
    let (lo, hi) = drs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    let past = -(r + lo);
    if !(r + hi + SLACK < c.at[1] && past + SLACK >= c.at[1]) {
        return None;
    }
    // what to change first: the picture's detail shows the first 70 characters. A tool
    // that spans the bore (less a millimetre of play) is too big for it; a smaller one only
    // runs too near the axis (review 1128h, #3: a Φ10 bar retracting toward the centre of
    // a Ø16 hole was told to be smaller)
    let (span, wall) = (hi - lo, c.at[1]);
    let tool = s.tools.describe(seg.tool);
    let tool = tool.split_once(' ').map_or("", |x| x.1);
    let reach = format!(
        "from its point at Ø{:.3} it reaches {past:.1} mm past the axis, and its far side meets the wall opposite at Ø{:.3}, {:.3} mm deep",
        2.0 * r,
        2.0 * wall,
        c.depth
    );
    Some(if span > 2.0 * wall - BORE_PLAY {
        format!(
            "T{:02} is too big for the bore here: {reach} ({tool}; a smaller insert or bar, or a bigger bore first)",
            seg.tool
        )
    } else {
        format!(
            "T{:02} runs too near the axis here: {reach} ({tool}, {span:.1} mm across: keep its point above Ø{:.1})",
            seg.tool,
            2.0 * (-lo - wall)
        )
    })
}

/// Play a tool needs across a bore, mm: one that spans more of it is too big for it.
const BORE_PLAY: f64 = 1.0;

/// Which edge of the blank a point lies on: its face, or a diameter.
fn stock_edge(at: P, s: &Settings) -> String {
    let face = s
        .blank
        .shapes
        .iter()
        .flat_map(|sh| sh.outer.iter())
        .map(|p| p[0])
        .fold(f64::NEG_INFINITY, f64::max);
    if (at[0] - face).abs() < 1e-3 {
        format!("the face at Z{face:.3}")
    } else {
        format!("the stock at Ø{:.3}", 2.0 * at[1])
    }
}

/// The cause of a gouge: another tool's cut into a finished contour, the programmed point
/// going into the part, or the part of the turning insert that reached it.
pub(crate) fn gouge(
    g: &Finding,
    (intents, comp_starts): (&[Intent], &[usize]),
    segments: &[Segment],
    s: &Settings,
    mounts: &mut Mounts,
) -> Option<Cause> {
    let i = g.made_by?;
    let seg = &segments[i];
    if let Some((owner, from)) = other_owner(g, intents, seg, i) {
        return Some(Cause {
            kind: CauseKind::OtherTool,
            text: format!(
                "T{:02} (line {}) cuts into the contour T{owner:02} finished (from line {})",
                seg.tool,
                seg.span.line,
                segments.get(from).map_or(0, |f| f.span.line)
            ),
            numbers: vec![("depth_mm", g.depth)],
        });
    }
    if let Some(cause) = offset_into_part(g, intents, segments, i, s) {
        return Some(cause);
    }
    let radius = Facts::of(&tool_of(seg, s)).map_or(0.0, |f| f.nose_radius);
    if let Some(j) = program_enters(g, intents, segments, i, radius) {
        return Some(Cause {
            kind: CauseKind::Program,
            text: format!(
                "line {} moves the tool's reference point into the part: the programmed path itself cuts {:.3} mm below the intended surface",
                segments[j].span.line, g.depth
            ),
            numbers: vec![("depth_mm", g.depth)],
        });
    }
    // the move whose sweep reaches the deepest point (the one that made the region may
    // only have touched its edge, a compensation corner's arc; a later tool may have cut it
    // deeper, a finishing pass with a bigger nose)
    let (j, p) = (i..segments.len())
        .take(MAX_LOOKED_AT)
        .filter(|&j| segments[j].motion != Motion::Rapid)
        .find_map(|j| {
            let m = mounts.of(&segments[j]);
            let near = crate::assumed::path_box(&segments[j]);
            let bb = m.bbox();
            let reach = bb.max.z.abs().max(bb.min.z.abs()) + bb.max.r.abs().max(bb.min.r.abs());
            if !near.grown(reach + REACH).contains(geom::Pt::from(g.at)) {
                return None;
            }
            crate::pose::first_reach(&m.edge, &segments[j], g.at, crate::CHORD_TOL, REACH)
                .map(|p| (j, p))
        })?;
    let seg = &segments[j];
    let facts = Facts::of(&tool_of(seg, s))?;
    // the deepest point relative to the reference, as mounted on the front post
    let below = p[1] < 0.0;
    let at = if below { [g.at[0], -g.at[1]] } else { g.at };
    let mut q = [at[0] - p[0], at[1] - p[1]];
    if mounts.is_rear(seg.tool) {
        q[1] = -q[1];
    }
    Some(match facts.part_at(q) {
        Part::Trailing => trailing(g, intents, &facts, seg),
        Part::Leading => leading(g, intents, &facts, seg),
        Part::Nose => match part_beside(intents, seg, facts.nose_radius.max(0.05)) {
            Beside::Both => Cause {
                kind: CauseKind::Program,
                text: format!(
                    "line {} moves the tool's reference point through the part: the programmed path itself cuts {:.3} mm below the intended surface",
                    seg.span.line, g.depth
                ),
                numbers: vec![("depth_mm", g.depth)],
            },
            side => startup(g, comp_starts, &facts, segments, j)
                .unwrap_or_else(|| nose(g, &facts, seg, segments, (i, side))),
        },
    })
}

/// Where the intended part lies beside a move.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Beside {
    Left,
    Right,
    /// On both sides: the path runs through the part (a hand chamfer across a finished
    /// corner), which no compensation explains.
    Both,
    Unknown,
}

/// Where the intended part lies beside `seg`: probed `off` mm either side of the middle of
/// its path (the side of the part, not of the gouge, says G41 or G42: an edge break cut
/// across a finished corner leaves the gouge on the other side of the path).
fn part_beside(intents: &[Intent], seg: &Segment, off: f64) -> Beside {
    let path = stock::move_path(seg, 1e-3);
    let k = path.len() / 2;
    let (a, b) = (path[k.saturating_sub(1)], path[k.min(path.len() - 1)]);
    let (dz, dr) = (b[0] - a[0], b[1] - a[1]);
    let len = dz.hypot(dr);
    if len <= 0.0 {
        return Beside::Unknown;
    }
    let mid = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
    // the left of travel in (z, r)
    let n = [-dr / len * off, dz / len * off];
    let inside = |p: P| {
        intents
            .iter()
            .any(|it| crate::assumed::Region::new(&it.part).contains(p))
    };
    match (
        inside([mid[0] + n[0], mid[1] + n[1]]),
        inside([mid[0] - n[0], mid[1] - n[1]]),
    ) {
        (true, true) => Beside::Both,
        (true, false) => Beside::Left,
        (false, true) => Beside::Right,
        (false, false) => Beside::Unknown,
    }
}

/// The first move of the gouge's tool (from the one that made it) whose reference point goes
/// into the intended part near the gouge deeper than the nose radius `nose` (under
/// compensation the imaginary tip lies up to about the nose radius inside a wall it
/// follows: that is no programming error), or, on a move along Z or X, as deep as the
/// gouge itself.
fn program_enters(
    g: &Finding,
    intents: &[Intent],
    segments: &[Segment],
    i: usize,
    nose: f64,
) -> Option<usize> {
    let near = geom::Rect::of(g.shape.outer.iter().map(|&p| geom::Pt::from(p)))
        .grown(g.depth + nose + 1.0);
    let deeper = nose + 0.005;
    // along Z or X the imaginary tip runs on the surface its nose cuts, compensated or not:
    // a path there as deep as the gouge made all of it
    let straight_deeper = deeper.min(g.depth - 0.005).max(0.005);
    let parts: Vec<(crate::assumed::Region, crate::assumed::Region)> = intents
        .iter()
        .map(|it| {
            (
                crate::assumed::Region::new(&it.part),
                crate::assumed::Region::new(&it.zone),
            )
        })
        .collect();
    let tool = segments[i].tool;
    (i..segments.len())
        .take(MAX_LOOKED_AT)
        .take_while(|&j| segments[j].tool == tool)
        .find(|&j| {
            let seg = &segments[j];
            let along_axis = seg.arc.is_none()
                && ((seg.to.z - seg.from.z).abs() < 1e-9 || (seg.to.r - seg.from.r).abs() < 1e-9);
            let deeper = if along_axis { straight_deeper } else { deeper };
            parts.iter().any(|(part, zone)| {
                crate::assumed::inside_depths(seg, part, deeper, crate::CHORD_TOL)
                    .into_iter()
                    .any(|(p, d)| {
                        d >= deeper && zone.contains(p) && near.contains(geom::Pt::from(p))
                    })
            })
        })
}

/// The tool and first move of a contour that claims the gouge's place and was finished by
/// another tool than the one that made the gouge.
fn other_owner(g: &Finding, intents: &[Intent], seg: &Segment, i: usize) -> Option<(u32, usize)> {
    // the contour whose surface the gouge is measured from: another's zone may span it (an
    // OD contour's zone over a bore's gouge named the OD's tool, field run 9, C)
    intents
        .iter()
        .filter(|it| crate::assumed::Region::new(&it.zone).contains(g.at))
        .filter(|it| along_outline(it, g.nearest))
        .filter_map(|it| it.owner)
        .find(|o| o.tool != seg.tool && i >= o.finish)
        .map(|o| (o.tool, o.finish))
}

/// Every edge of the intended parts' outlines (a closed ring's closing edge too).
fn outline_edges(intents: &[Intent]) -> impl Iterator<Item = (P, P)> + '_ {
    intents
        .iter()
        .flat_map(|it| &it.outline)
        .flat_map(|(line, closed)| {
            let n = line.len();
            let edges = if *closed { n } else { n.saturating_sub(1) };
            (0..edges).map(move |k| (line[k], line[(k + 1) % n]))
        })
}

/// The steepness of the edge from `a` to `b`, degrees from the Z axis (0: a diameter, 90: a
/// face); `None` for an edge of no length.
fn steepness(a: P, b: P) -> Option<f64> {
    let (dz, dr) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
    (dz + dr > 0.0).then(|| dr.atan2(dz).to_degrees())
}

/// The steepness ([`steepness`]) of the intended part's boundary nearest `p`.
fn flank_deg(intents: &[Intent], p: P) -> Option<f64> {
    let mut best: Option<(f64, f64)> = None;
    for (a, b) in outline_edges(intents) {
        let d = segment_distance(p, a, b);
        if let Some(deg) = steepness(a, b).filter(|_| best.is_none_or(|(bd, _)| d < bd)) {
            best = Some((d, deg));
        }
    }
    best.map(|(_, deg)| deg)
}

/// The steepness ([`steepness`]) of the steepest edge of the intended part that the
/// region `shape` lies against: the flank a trailing edge could not descend. Its deepest
/// point is often nearest the diameter above the flank (a D insert's wedge under the
/// shoulder): that diameter is 0°, the flank 83°. `None` when the region touches no edge.
fn steepest_touched(intents: &[Intent], shape: &stock::Shape) -> Option<f64> {
    const TOUCH: f64 = 1e-3;
    let pts = &shape.outer;
    let bbox = geom::Rect::of(pts.iter().map(|&p| geom::Pt::from(p))).grown(TOUCH);
    outline_edges(intents)
        .filter(|&(a, b)| geom::Rect::of([geom::Pt::from(a), geom::Pt::from(b)]).intersects(&bbox))
        .filter(|&(a, b)| pts.iter().any(|&p| segment_distance(p, a, b) <= TOUCH))
        .filter_map(|(a, b)| steepness(a, b))
        .reduce(f64::max)
}

fn trailing(g: &Finding, intents: &[Intent], f: &Facts, seg: &Segment) -> Cause {
    let clearance = f.trailing_clearance();
    let flank = steepest_touched(intents, &g.shape)
        .or_else(|| flank_deg(intents, g.nearest))
        .unwrap_or(f64::NAN);
    Cause {
        kind: CauseKind::TrailingEdge,
        text: format!(
            "the trailing edge of the {} {}° insert on a {}° holder ({:.0}° clearance) cannot descend this {:.0}° flank: it cuts {:.3} mm into it (line {})",
            f.insert.letter(),
            f.included,
            f.entering,
            clearance,
            flank,
            g.depth,
            seg.span.line
        ),
        numbers: vec![
            ("flank_deg", flank),
            ("clearance_deg", clearance),
            ("depth_mm", g.depth),
        ],
    }
}

fn leading(g: &Finding, intents: &[Intent], f: &Facts, seg: &Segment) -> Cause {
    let lean = f.leading_lean();
    let wall = flank_deg(intents, g.nearest).map_or(f64::NAN, |d| 90.0 - d);
    Cause {
        kind: CauseKind::LeadingEdge,
        text: format!(
            "the leading edge of the {}° holder leans back {:.0}°: this wall leans back {:.0}°, and the edge cuts {:.3} mm into it (line {})",
            f.entering, lean, wall, g.depth, seg.span.line
        ),
        numbers: vec![
            ("wall_lean_deg", wall),
            ("holder_lean_deg", lean),
            ("depth_mm", g.depth),
        ],
    }
}

/// A gouge along a contour whose G41/G42 contradicts its tool's stated tip (LS-COMP-SIDE):
/// the programmed path lies on the surface, and the control offsets the nose into the part
/// (field run 8, I: a G41 OD finish said "the programmed path itself cuts 1.600 mm below
/// the intended surface").
fn offset_into_part(
    g: &Finding,
    intents: &[Intent],
    segments: &[Segment],
    i: usize,
    s: &Settings,
) -> Option<Cause> {
    let seg = &segments[i];
    let (owner, comp) = wrong_side_owner(g, intents, segments, i)?;
    let (code, other) = comp.codes();
    let radius = Facts::of(&tool_of(seg, s)).map_or(0.0, |f| f.nose_radius);
    Some(Cause {
        kind: CauseKind::Compensation,
        text: format!(
            "{code} from line {} offsets the r{radius} nose into the part: T{:02}'s tip puts the part on the other side of this contour (LS-COMP-SIDE), so the nose cuts {:.3} mm below the surface (write {other})",
            segments.get(owner.finish).map_or(seg.span.line, |f| f.span.line),
            seg.tool,
            g.depth
        ),
        numbers: vec![("nose_radius", radius), ("depth_mm", g.depth)],
    })
}

/// The contour `g` lies along whose G41/G42 contradicts its tool's stated tip, when move
/// `i` (its maker) is that tool's, from the contour's start on.
pub(super) fn wrong_side_owner(
    g: &Finding,
    intents: &[Intent],
    segments: &[Segment],
    i: usize,
) -> Option<(crate::Owner, crate::Comp)> {
    let seg = &segments[i];
    intents.iter().find_map(|it| {
        let o = it.owner?;
        let c = o.comp?;
        let along = along_outline(it, g.nearest);
        (c.wrong_side && o.tool == seg.tool && i >= o.finish && along).then_some((o, c))
    })
}

/// Whether `p` lies on `it`'s drawn outline (within 10⁻³ mm).
fn along_outline(it: &Intent, p: P) -> bool {
    outline_edges(std::slice::from_ref(it)).any(|(a, b)| segment_distance(p, a, b) <= 1e-3)
}

/// A nick the nose makes at the end of move `j` when that move starts a compensation
/// (`comp_starts`: a hand contour's or a G70's) and ends on the part: the control offsets
/// the nose along it, and on the way the nose cuts the corner it arrives at (field run 8,
/// J: an r0.8 nose from X26 Z2 onto the corner X30 Z0 under G42). The code is right; the
/// start-up is not: naming G41/G42 sent the programmer to the wrong fix.
fn startup(
    g: &Finding,
    comp_starts: &[usize],
    f: &Facts,
    segments: &[Segment],
    j: usize,
) -> Option<Cause> {
    let seg = &segments[j];
    let starts = comp_starts.binary_search(&j).is_ok();
    let end = [seg.to.z, seg.to.r.abs()];
    let at_end = geom::flat::dist([g.at[0], g.at[1].abs()], end) <= f.nose_radius + g.depth;
    (starts && at_end).then(|| Cause {
        kind: CauseKind::Compensation,
        text: format!(
            "the r{} nose cuts {:.3} mm into the part at line {}, the move that starts the compensation and ends on the part: the nose comes on along it and cuts the corner it arrives at (start the compensation on a move that ends clear of the part, then feed onto the contour)",
            f.nose_radius, g.depth, seg.span.line
        ),
        numbers: vec![("nose_radius", f.nose_radius), ("depth_mm", g.depth)],
    })
}

/// A gouge the nose made: its radius not compensated as this tool needs. The side the part
/// lies on, against the direction of travel, says G41 or G42.
fn nose(
    g: &Finding,
    f: &Facts,
    seg: &Segment,
    segments: &[Segment],
    (i, beside): (usize, Beside),
) -> Cause {
    let d = seg.to - seg.from;
    let side = d.z * (g.at[1] - seg.from.r) - d.r * (g.at[0] - seg.from.z);
    // the part on the left of travel puts the tool on the right: G42 (where the part lies
    // is probed; else the gouge is taken to lie on the part's side)
    let left = match beside {
        Beside::Left => true,
        Beside::Right => false,
        Beside::Both | Beside::Unknown => side > 0.0,
    };
    let code = if left { "G42" } else { "G41" };
    let first = (0..=i)
        .rev()
        .take_while(|&k| segments[k].tool == seg.tool && segments[k].motion != Motion::Rapid)
        .last()
        .map_or(seg.span.line, |k| segments[k].span.line);
    Cause {
        kind: CauseKind::Compensation,
        text: format!(
            "the r{} nose cuts {:.3} mm into the part at line {}: its radius is not compensated as this tool needs ({code} from line {first} with the offset's radius {} and tip {}, the tool's)",
            f.nose_radius, g.depth, seg.span.line, f.nose_radius, f.tip
        ),
        numbers: vec![("nose_radius", f.nose_radius), ("depth_mm", g.depth)],
    }
}

/// The cause of a leftover: the nose in an inside corner sharper than it, or no pass that
/// reaches it.
pub(crate) fn leftover(
    l: &Finding,
    intents: &[Intent],
    segments: &[Segment],
    s: &Settings,
) -> Cause {
    let nose = nose_last_near(l.nearest, l.depth, segments, s);
    let corner = at_corner(intents, l.nearest, nose);
    if nose > 0.0 && corner && l.depth <= nose * (1.0 - std::f64::consts::FRAC_1_SQRT_2) + 0.01 {
        return Cause {
            kind: CauseKind::Nose,
            text: format!(
                "the r{nose} nose cannot fill this inside corner sharper than its radius: {:.3} mm stays",
                l.depth
            ),
            numbers: vec![("nose_radius", nose), ("depth_mm", l.depth)],
        };
    }
    if nose > 0.0 && l.depth <= nose + 0.01 && on_slope(intents, l.nearest) {
        return Cause {
            kind: CauseKind::Compensation,
            text: format!(
                "the r{nose} nose leaves {:.3} mm on this slope: the tool's tip runs on the contour, its radius not compensated (G41/G42 with the offset's radius and tip)",
                l.depth
            ),
            numbers: vec![("nose_radius", nose), ("depth_mm", l.depth)],
        };
    }
    Cause {
        kind: CauseKind::Program,
        text: format!(
            "no pass reaches it: {:.3} mm² stays, {:.3} mm thick at {}",
            l.area,
            l.depth,
            place(l.at)
        ),
        numbers: vec![("area_mm2", l.area), ("depth_mm", l.depth)],
    }
}

/// Whether `p` lies within `within` of a vertex of an intended outline (an inside corner
/// of the part is a vertex of its drawn outline; a leftover the nose leaves there lies
/// within its radius of it).
/// The nose radius of the tool that last passed the corner `p`: the last feed move whose
/// reference path comes within twice its tool's nose radius and `depth` (and 0.05 mm) of
/// it. That nose left the corner's leftover (the largest nose of the program named a
/// roughing r0.8 for what a finishing r0.2 left); 0 when no feed comes that near.
fn nose_last_near(p: P, depth: f64, segments: &[Segment], s: &Settings) -> f64 {
    let largest = segments
        .iter()
        .filter(|seg| seg.motion != Motion::Rapid)
        .filter_map(|seg| Facts::of(&tool_of(seg, s)))
        .map(|f| f.nose_radius)
        .fold(0.0, f64::max);
    let margin = |r: f64| 2.0 * r + depth + 0.05;
    segments
        .iter()
        .rev()
        .filter(|seg| seg.motion != Motion::Rapid)
        .filter(|seg| box_distance(seg, p) <= margin(largest))
        .find_map(|seg| {
            let f = Facts::of(&tool_of(seg, s))?;
            let near = stock::move_path(seg, 1e-3)
                .windows(2)
                .any(|w| segment_distance(p, w[0], w[1]) <= margin(f.nose_radius));
            near.then_some(f.nose_radius)
        })
        .unwrap_or(0.0)
}

/// Distance from `p` to the box of `seg`'s path (arcs' bulge included), 0 inside.
fn box_distance(seg: &Segment, p: P) -> f64 {
    let bulge = seg.arc.map_or(0.0, |a| a.center.dist(seg.from));
    let (z0, z1) = (
        seg.from.z.min(seg.to.z) - bulge,
        seg.from.z.max(seg.to.z) + bulge,
    );
    let (r0, r1) = (
        seg.from.r.min(seg.to.r) - bulge,
        seg.from.r.max(seg.to.r) + bulge,
    );
    let dz = (z0 - p[0]).max(p[0] - z1).max(0.0);
    let dr = (r0 - p[1]).max(p[1] - r1).max(0.0);
    dz.hypot(dr)
}

/// Whether the intended boundary at `p` (an edge within 0.01 mm of it) is a slope: an edge
/// neither along Z nor along X (by more than a degree), where an uncompensated nose leaves
/// a band.
fn on_slope(intents: &[Intent], p: P) -> bool {
    let mut edges = intents
        .iter()
        .flat_map(|it| it.outline.iter())
        .flat_map(|(line, closed)| {
            let n = line.len();
            let count = if *closed { n } else { n.saturating_sub(1) };
            (0..count).map(move |k| (line[k], line[(k + 1) % n]))
        });
    edges.any(|(a, b)| {
        let angle = (b[1] - a[1]).atan2(b[0] - a[0]).abs().to_degrees();
        let off_axis = angle.min(180.0 - angle);
        segment_distance(p, a, b) <= 0.01 && off_axis > 1.0 && (90.0 - off_axis).abs() > 1.0
    })
}

fn at_corner(intents: &[Intent], p: P, within: f64) -> bool {
    intents
        .iter()
        .flat_map(|it| it.outline.iter())
        .any(|(line, _)| {
            line.iter()
                .any(|v| (v[0] - p[0]).hypot(v[1] - p[1]) <= within)
        })
}
