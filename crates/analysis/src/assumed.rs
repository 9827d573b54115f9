//! Findings from assumed tools (spec/simulation.md, "Findings from assumed tools"): a
//! finding that depends on the extent of an outline the table does not state (a tool with
//! no entry, an insert whose size is assumed) is a *possible* finding — the warning
//! `LS-ASSUMED-TOOL`, no effect on the verdict. What holds for the tool's reference point
//! alone stays certain: the programmed path entering uncut stock at rapid (or the
//! workholding), or entering the intended part.
//!
//! The reference point's path is tested exactly against the regions: the parameters where
//! it crosses their edges cut it into pieces, each wholly inside or outside.

use crate::note::Note;
use expander::{Motion, Segment};
use geom::flat::P;
use stock::{float_sweep, move_path, Mounted, Mounts, Outline, Shape, ToolTable};

/// Most findings of guessed tools tested for certainty in one run: each test is a pass over
/// the moves before it; the findings after these stay possible (a program with that many is
/// broken anyway, and the first ones say where).
pub(crate) const MAX_TESTED: usize = 64;

/// Shorter stretches of the path inside a region do not count as entering it, mm.
const ENTERS: f64 = 1e-3;
/// How far outside an earlier move's sweep a point still counts as swept, mm (float noise
/// of a path that runs along the sweep's own edge).
const ON_EDGE: f64 = 1e-7;

/// Whether the outline that cuts `seg` is a guess: its size is not stated by the table.
pub(crate) fn guessed(tools: &ToolTable, seg: &Segment) -> bool {
    !tools.size_stated(seg.tool, seg.hint)
}

/// `seg`'s reference path as the section sees it (folded to r ≥ 0, as the removal folds
/// the move), chord by chord.
fn section_chords(seg: &Segment, chord_tol: f64) -> Vec<[P; 2]> {
    let below = seg.from.r + seg.to.r < 0.0;
    let path: Vec<P> = move_path(seg, chord_tol)
        .into_iter()
        .map(|p| if below { [p[0], -p[1]] } else { p })
        .collect();
    path.windows(2).map(|w| [w[0], w[1]]).collect()
}

/// The edges of a shape set, binned along Z: a chord meets only the edges of the bins its
/// Z span covers, and a point's vertical ray only those of its own bin (a gouge along a
/// G73's contour has thousands of edges, and every pass's chords ask).
pub(crate) struct Region {
    edges: Vec<[P; 2]>,
    z0: f64,
    dz: f64,
    bins: Vec<Vec<u32>>,
}

impl Region {
    pub(crate) fn new(shapes: &[Shape]) -> Self {
        let edges: Vec<[P; 2]> = shapes
            .iter()
            .flat_map(|s| std::iter::once(&s.outer).chain(&s.holes))
            .flat_map(|ring| (0..ring.len()).map(move |k| [ring[k], ring[(k + 1) % ring.len()]]))
            .collect();
        let (z0, z1) = edges
            .iter()
            .flatten()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[0]), hi.max(p[0]))
            });
        let n = (edges.len() / 4).clamp(1, 4096);
        let dz = ((z1 - z0) / n as f64).max(1e-9);
        let mut r = Self {
            edges,
            z0,
            dz,
            bins: vec![Vec::new(); n],
        };
        for (k, [u, v]) in r.edges.iter().enumerate() {
            for b in r.bin_range(u[0].min(v[0]), u[0].max(v[0])) {
                r.bins[b].push(k as u32);
            }
        }
        r
    }

    /// The bins a Z span covers (empty outside the set's Z extent).
    fn bin_range(&self, lo: f64, hi: f64) -> std::ops::Range<usize> {
        let n = self.bins.len();
        if !(hi >= self.z0 && lo <= self.z0 + self.dz * n as f64) {
            return 0..0;
        }
        let at = |z: f64| (((z - self.z0) / self.dz).floor().max(0.0) as usize).min(n - 1);
        at(lo)..at(hi) + 1
    }

    /// How far `p` is from the set's edges, up to `within` (only the edges of the bins
    /// within that distance along Z are looked at).
    pub(crate) fn depth_at(&self, p: P, within: f64) -> f64 {
        let mut best = within;
        for b in self.bin_range(p[0] - within, p[0] + within) {
            for &k in &self.bins[b] {
                let [u, v] = self.edges[k as usize];
                best = best.min(geom::flat::segment_distance(p, u, v));
            }
        }
        best
    }

    /// Even-odd containment: the crossings of the ray from `p` toward +r.
    pub(crate) fn contains(&self, p: P) -> bool {
        let mut c = false;
        for b in self.bin_range(p[0], p[0]) {
            for &k in &self.bins[b] {
                let [u, v] = self.edges[k as usize];
                if (u[0] > p[0]) != (v[0] > p[0])
                    && p[1] < u[1] + (p[0] - u[0]) * (v[1] - u[1]) / (v[0] - u[0])
                {
                    c = !c;
                }
            }
        }
        c
    }

    /// The parameter intervals (0 at `a`, 1 at `b`) of the chord inside the set.
    pub(crate) fn inside(&self, a: P, b: P) -> Vec<(f64, f64)> {
        let mut ts = vec![0.0, 1.0];
        let mut seen = Vec::new();
        for bin in self.bin_range(a[0].min(b[0]), a[0].max(b[0])) {
            for &k in &self.bins[bin] {
                if seen.contains(&k) {
                    continue;
                }
                seen.push(k);
                let [p, q] = self.edges[k as usize];
                if let Some(t) = crossing(a, b, p, q) {
                    ts.push(t);
                }
            }
        }
        ts.sort_by(f64::total_cmp);
        ts.dedup();
        let at = |t: f64| [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
        ts.windows(2)
            .filter(|w| w[1] > w[0] && self.contains(at((w[0] + w[1]) / 2.0)))
            .map(|w| (w[0], w[1]))
            .collect()
    }
}

/// Where the chord `a → b` crosses the edge `p → q`, as a parameter of the chord.
fn crossing(a: P, b: P, p: P, q: P) -> Option<f64> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let e = [q[0] - p[0], q[1] - p[1]];
    let den = d[0] * e[1] - d[1] * e[0];
    if den == 0.0 {
        return None;
    }
    let w = [p[0] - a[0], p[1] - a[1]];
    let t = (w[0] * e[1] - w[1] * e[0]) / den;
    let u = (w[0] * d[1] - w[1] * d[0]) / den;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then_some(t)
}

/// The parameter interval of the chord `a → b` inside the convex polygon `poly` (either
/// orientation; Cyrus–Beck).
fn in_convex(a: P, b: P, poly: &[P]) -> Option<(f64, f64)> {
    let n = poly.len();
    if n < 3 {
        return None;
    }
    let sign = {
        let twice: f64 = (0..n)
            .map(|k| {
                let (u, v) = (poly[k], poly[(k + 1) % n]);
                u[0] * v[1] - v[0] * u[1]
            })
            .sum();
        twice.signum()
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let d = [b[0] - a[0], b[1] - a[1]];
    for k in 0..n {
        let (u, v) = (poly[k], poly[(k + 1) % n]);
        // inside: sign · cross(v − u, x − u) ≥ 0 along x = a + t d
        let e = [v[0] - u[0], v[1] - u[1]];
        // a path along the polygon's edge (a tip retracting along the wall it just swept)
        // is inside: the polygon grown by ON_EDGE
        let grow = ON_EDGE * e[0].hypot(e[1]);
        let at0 = sign * (e[0] * (a[1] - u[1]) - e[1] * (a[0] - u[0])) + grow;
        let slope = sign * (e[0] * d[1] - e[1] * d[0]);
        if slope == 0.0 {
            if at0 < 0.0 {
                return None;
            }
        } else if slope > 0.0 {
            lo = lo.max(-at0 / slope);
        } else {
            hi = hi.min(-at0 / slope);
        }
        if lo >= hi {
            return None;
        }
    }
    Some((lo, hi))
}

/// The parts of `spans` (parameter intervals of a chord) not covered by `cover`.
fn uncovered(spans: &[(f64, f64)], cover: &mut [(f64, f64)]) -> Vec<(f64, f64)> {
    cover.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut left = Vec::new();
    for &(s0, s1) in spans {
        let mut at = s0;
        for &(c0, c1) in cover.iter() {
            if c1 <= at || c0 >= s1 {
                continue;
            }
            if c0 > at {
                left.push((at, c0));
            }
            at = at.max(c1);
        }
        if s1 > at {
            left.push((at, s1));
        }
    }
    left
}

/// The outlines an earlier move may have cut with (`m`: its tool as mounted): the edge and
/// the body as mounted when the table states the tool, or at least its nose and the way it
/// points (an insert whose size is assumed: a bigger one cuts on the same side); for a
/// feed of a tool the table says nothing of (`unknown_feed`: a default stands in, no nose
/// stated), the default's edge and, where a bore may be (`bore`, [`bore_possible`]), its
/// mirror across the path (an OD insert or a boring bar: a T word alone does not tell which). The stock such a feed leaves is a guess too: the default OD
/// insert fed along a bore leaves the wall a boring bar would have cut, and a rapid back
/// through that wall is no certain crash; a rapid into the bar beyond a shoulder either
/// would have left stays certain. (A rapid cuts nothing in a sound program: it keeps its
/// outline.)
fn may_have_cut(m: &Mounted, unknown_feed: bool, bore: bool) -> Vec<Outline> {
    if !unknown_feed || !bore {
        return [Some(&*m.edge), m.body.as_ref().map(|b| &b.outline)]
            .into_iter()
            .flatten()
            .cloned()
            .collect();
    }
    let mirrored = Outline {
        parts: m
            .edge
            .parts
            .iter()
            .map(|part| part.iter().rev().map(|p| [p[0], -p[1]]).collect())
            .collect(),
        past_axis: m.edge.past_axis,
    };
    vec![(*m.edge).clone(), mirrored]
}

/// Whether a tool the table says nothing of may have worked inside a bore before move `i`:
/// the blank is a tube, or an earlier feed ran along the axis into it (a drill, or a bore's
/// first pass on centre). A boring bar enters through a bore (simulation.md, "ID tools are
/// carried along Z"): in a solid bar nothing has drilled, every feed is an OD tool's, and
/// the mirror image of the default insert (a boring bar) cannot have cut below its path
/// (field run 10, B1: a blade's rapid 0.5 mm into the fillet a G02 left stayed "possible").
fn bore_possible(segments: &[Segment], i: usize, blank: &[Shape]) -> bool {
    let pts = || blank.iter().flat_map(|s| s.outer.iter());
    let tube = pts().map(|p| p[1].abs()).fold(f64::INFINITY, f64::min) > ON_AXIS;
    let face = pts().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max);
    tube || segments[..i].iter().any(|s| {
        s.motion == Motion::Feed
            && s.from.r.abs().max(s.to.r.abs()) <= ON_AXIS
            && s.to.z < s.from.z
            && s.to.z < face
    })
}

/// A feed along Z within this radius of the axis drills, mm (an offset drill included,
/// field-rules §19).
const ON_AXIS: f64 = 1.0;

/// Whether `seg` is a feed of a tool whose size the table does not state.
fn guessed_feed(tools: &ToolTable, seg: &Segment) -> bool {
    seg.motion == Motion::Feed && guessed(tools, seg)
}

/// Whether move `i`'s reference path enters uncut stock deeper than `deeper_than`: the
/// blank less what the moves before it may have swept ([`may_have_cut`], folded into the
/// section as the removal folds them). Only the moves whose sweeps can reach the path are
/// looked at. A path that only grazes uncut stock (a G40 rapid along the 0.05 mm a roughing
/// left on a shoulder's face, field run 7, E) is a crash only by the size of the outline
/// around it: of a guessed tool, or of a drill whose size was guessed, no certain one.
pub(crate) fn enters_uncut(
    i: usize,
    (segments, tools): (&[Segment], &ToolTable),
    blank: &[Shape],
    mounts: &mut Mounts,
    (chord_tol, deeper_than): (f64, f64),
) -> bool {
    let bore = bore_possible(segments, i, blank);
    let blank = Region::new(blank);
    for [a, b] in section_chords(&segments[i], chord_tol) {
        let spans = blank.inside(a, b);
        if spans.is_empty() {
            continue;
        }
        let (lo, hi) = (
            [a[0].min(b[0]), a[1].min(b[1])],
            [a[0].max(b[0]), a[1].max(b[1])],
        );
        let mut cover = Vec::new();
        // every sweep near the chord: how deep a point of it lies in uncut stock
        let mut near = Vec::new();
        // an earlier feed of a tool the table says nothing of covers this chord
        let mut unknown_near = false;
        for seg in &segments[..i] {
            let m = mounts.of(seg);
            let unknown = guessed_feed(tools, seg) && m.core.is_none();
            let outlines = may_have_cut(&m, unknown, bore);
            let bb = geom::Rect::of(
                outlines
                    .iter()
                    .flat_map(|o| o.parts.iter().flatten())
                    .map(|&p| geom::Pt::from(p)),
            );
            let (sz, sr) = (seg.from.z.min(seg.to.z), seg.from.z.max(seg.to.z));
            let reach_r = seg.from.r.abs().max(seg.to.r.abs()) + bb.max.r.abs().max(bb.min.r.abs());
            let bulge = seg.arc.map_or(0.0, |c| c.center.dist(seg.from));
            if sz + bb.min.z - bulge > hi[0] || sr + bb.max.z + bulge < lo[0] {
                continue;
            }
            if reach_r + bulge < lo[1] {
                continue;
            }
            unknown_near |= unknown;
            let path = move_path(seg, chord_tol);
            for part in &outlines {
                if seg.motion == Motion::Thread {
                    continue; // a thread's stamps are the removal's; they cut the teeth only
                }
                for poly in float_sweep(part, &path) {
                    cover.extend(in_convex(a, b, &poly));
                    near.push(poly);
                }
            }
        }
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        let enters = if unknown_near { UNKNOWN_NOSE } else { ENTERS };
        let left = uncovered(&spans, &mut cover);
        if left.iter().map(|(s0, s1)| s1 - s0).sum::<f64>() * len <= enters {
            continue;
        }
        // how deep a point of the chord lies in the stock: to the blank's edge or the
        // nearest sweep's, whichever is nearer
        // (capped above the bar: only whether a point passes it counts; a bar of 0, a shop
        // that calls every rapid contact a crash, keeps any point inside certain)
        let depth = |p: P| {
            near.iter()
                .map(|poly| convex_distance(p, poly))
                .fold(blank.depth_at(p, 2.0 * deeper_than + ENTERS), f64::min)
        };
        let at = |t: f64| [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
        let step = (0.5 * deeper_than).max(DEPTH_STEP);
        let deep = left.iter().any(|&(s0, s1)| {
            let n = (((s1 - s0) * len / step).ceil() as usize).clamp(1, DEPTH_SAMPLES);
            (0..=n).any(|k| depth(at(s0 + (s1 - s0) * k as f64 / n as f64)) > deeper_than)
        });
        if deep {
            return true;
        }
    }
    false
}

/// The points of a stretch of a path in uncut stock looked at for its depth are half the
/// bar apart (a peak between two is within a quarter of the bar of one), at least this far
/// apart, mm, and at most [`DEPTH_SAMPLES`] of them.
const DEPTH_STEP: f64 = 0.01;
/// Most points of one stretch looked at (a 40 mm stretch at the 0.1 mm bar's 0.05).
const DEPTH_SAMPLES: usize = 800;

/// The distance from `p` (outside it) to the convex polygon `poly`.
fn convex_distance(p: P, poly: &[P]) -> f64 {
    (0..poly.len())
        .map(|k| geom::flat::segment_distance(p, poly[k], poly[(k + 1) % poly.len()]))
        .fold(f64::INFINITY, f64::min)
}

/// Near a feed of a tool the table says nothing of, a shorter stretch in uncut stock is no
/// entry, mm: the fillet a nose of unknown radius leaves in the corner where its feed
/// ended (up to the largest nose in common use, r0.8), which the imaginary tip, retracting
/// along the feed, passes through whatever the tool.
const UNKNOWN_NOSE: f64 = 0.8;

/// Whether the stated core of move `i`'s tool (`core`: an insert's nose, a blade's tip) cuts
/// uncut stock on that move: its sweep less the blank's outside and what the earlier moves
/// may have swept ([`may_have_cut`]; those whose boxes meet what is left of it in the blank)
/// has more than [`CORE_AREA`] left.
pub(crate) fn core_enters_uncut(
    i: usize,
    core: &Outline,
    (segments, tools): (&[Segment], &ToolTable),
    blank: &[Shape],
    mounts: &mut Mounts,
    chord_tol: f64,
) -> bool {
    let as_shapes = |polys: Vec<Vec<P>>| -> Vec<Shape> {
        polys
            .into_iter()
            .map(|outer| Shape {
                outer,
                holes: vec![],
            })
            .collect()
    };
    let swept = as_shapes(float_sweep(core, &move_path(&segments[i], chord_tol)));
    let inside = stock::boolean(&swept, blank, stock::BoolOp::Intersection);
    if stock::area(&inside) <= CORE_AREA {
        return false;
    }
    let bb = geom::Rect::of(
        inside
            .iter()
            .flat_map(|s| s.outer.iter().map(|&p| geom::Pt::from(p))),
    );
    let bore = bore_possible(segments, i, blank);
    let mut earlier = Vec::new();
    for seg in &segments[..i] {
        if seg.motion == Motion::Thread {
            continue;
        }
        let path = move_path(seg, chord_tol);
        let m = mounts.of(seg);
        for part in &may_have_cut(&m, guessed_feed(tools, seg) && m.core.is_none(), bore) {
            earlier.extend(float_sweep(part, &path).into_iter().filter(|poly| {
                geom::Rect::of(poly.iter().map(|&p| geom::Pt::from(p))).intersects(&bb)
            }));
        }
    }
    // the earlier sweeps joined first (half by half: many overlapping sweeps in one call
    // split every edge at every other's ends, a G75.1's pecks took gigabytes)
    let cover = stock::boolean(&as_shapes(earlier), &[], stock::BoolOp::Union);
    let uncut = stock::boolean(&inside, &cover, stock::BoolOp::Difference);
    stock::area(&uncut) > CORE_AREA
}

/// Less of a stated core's sweep in uncut stock is no crash of its own, mm².
const CORE_AREA: f64 = 1e-4;

/// The box of `seg`'s reference path as the section sees it (folded, arcs' bulge
/// included).
pub(crate) fn path_box(s: &Segment) -> geom::Rect {
    let b = geom::Rect::of([s.from, s.to]);
    let bulge = s.arc.map_or(0.0, |c| c.center.dist(s.from));
    geom::Rect::new(
        geom::Pt::new(b.min.z - bulge, 0.0),
        geom::Pt::new(b.max.z + bulge, b.max.r.abs().max(b.min.r.abs()) + bulge),
    )
}

/// Whether `seg`'s reference path enters `region` (a gouge: part material the intended part
/// keeps; a piece of workholding): more than [`ENTERS`] of it inside, reaching deeper than
/// [`ENTER_DEPTH`] from the region's edges (a path run along the edge, as a tip run on the
/// contour is, does not enter).
pub(crate) fn path_enters(seg: &Segment, region: &Region, chord_tol: f64) -> bool {
    section_chords(seg, chord_tol).into_iter().any(|[a, b]| {
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        region.inside(a, b).iter().any(|&(t0, t1)| {
            let mid = (t0 + t1) / 2.0;
            let p = [a[0] + (b[0] - a[0]) * mid, a[1] + (b[1] - a[1]) * mid];
            (t1 - t0) * len > ENTERS && region.depth_at(p, ENTER_DEPTH) >= ENTER_DEPTH
        })
    })
}

/// How near a gouge a point of the reference path that enters the intended part must lie
/// to have made it, mm: an imaginary tip stands off its nose's cut by r(√2 − 1), 0.25 mm
/// for a nose up to r0.6.
const NEAR_GOUGE: f64 = 0.25;

/// Whether `seg`'s reference path enters the intended `part` (deeper than [`ENTER_DEPTH`])
/// where it touches the gouge `region` (within [`NEAR_GOUGE`]): the programmed point itself
/// goes into the part there, whatever the tool. The path runs on the edge of what its tool
/// removed (a tip on a straight cut bounds the cut), so entering the gouge region itself
/// is not the test. Each stretch inside the part is looked at in up to 64 points.
pub(crate) fn path_enters_part_at(
    seg: &Segment,
    part: &Region,
    region: &Region,
    chord_tol: f64,
) -> bool {
    section_chords(seg, chord_tol).into_iter().any(|[a, b]| {
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        part.inside(a, b).into_iter().any(|(t0, t1)| {
            let n = (((t1 - t0) * len / 0.05).ceil() as usize).clamp(1, 64);
            (t1 - t0) * len > ENTERS
                && (0..=n).any(|k| {
                    let t = t0 + (t1 - t0) * k as f64 / n as f64;
                    let p = [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
                    part.depth_at(p, ENTER_DEPTH) >= ENTER_DEPTH
                        && (region.contains(p) || region.depth_at(p, NEAR_GOUGE) < NEAR_GOUGE)
                })
        })
    })
}

/// The places where `seg`'s reference path runs inside `region` (stretches longer than
/// [`ENTERS`]), each with its depth there (the distance to the region's edges, up to
/// `cap`): (midpoint, depth).
pub(crate) fn inside_depths(
    seg: &Segment,
    region: &Region,
    cap: f64,
    chord_tol: f64,
) -> Vec<(P, f64)> {
    let mut out = Vec::new();
    for [a, b] in section_chords(seg, chord_tol) {
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        for (t0, t1) in region.inside(a, b) {
            if (t1 - t0) * len > ENTERS {
                let mid = (t0 + t1) / 2.0;
                let p = [a[0] + (b[0] - a[0]) * mid, a[1] + (b[1] - a[1]) * mid];
                out.push((p, region.depth_at(p, cap)));
            }
        }
    }
    out
}

/// How deep into a region a path must reach to enter it, mm.
const ENTER_DEPTH: f64 = 0.005;

/// The warning of a possible finding (`what`: "gouge", "crash") `depth` mm deep made by
/// `seg`, naming the tool to state.
pub(crate) fn note(what: &str, depth: f64, seg: &Segment, tools: &ToolTable) -> Note {
    let t = if seg.tool == 0 {
        tools.numbers().first().copied().unwrap_or(0)
    } else {
        seg.tool
    };
    let tool = match tools.get(t) {
        // a tool taken for what its moves say (a threading insert, a drill), or the default
        None if tools.taken_from_moves(t) => {
            format!(
                "the {} it is taken for",
                tools.describe_for(seg.tool, seg.hint)
            )
        }
        None => format!("the default {}", tools.describe_for(seg.tool, seg.hint)),
        Some(_) => format!("as assumed ({})", tools.describe_for(seg.tool, seg.hint)),
    };
    Note {
        span: seg.span,
        code: "LS-ASSUMED-TOOL",
        message: format!(
            "possible {what} {depth:.3} mm deep at line {} if T{t:02} is {tool}: state T{t:02} in the tool table (its insert or blade size) to check; not counted in the verdict",
            seg.span.line
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(z0: f64, r0: f64, s: f64) -> Shape {
        Shape {
            outer: vec![[z0, r0], [z0 + s, r0], [z0 + s, r0 + s], [z0, r0 + s]],
            holes: vec![],
        }
    }

    /// A chord through a 10 × 10 square with a 2 × 2 hole: inside over 8 of its 20 mm;
    /// the Cyrus–Beck interval of a convex square; what a cover leaves.
    #[test]
    fn a_chord_inside_a_shape_with_a_hole() {
        let mut s = square(0.0, 0.0, 10.0);
        s.holes
            .push(vec![[4.0, 4.0], [4.0, 6.0], [6.0, 6.0], [6.0, 4.0]]);
        let spans = Region::new(&[s]).inside([-5.0, 5.0], [15.0, 5.0]);
        let total: f64 = spans.iter().map(|(a, b)| b - a).sum::<f64>() * 20.0;
        assert!((total - 8.0).abs() < 1e-12, "{spans:?}");
        let (lo, hi) =
            in_convex([-5.0, 5.0], [15.0, 5.0], &square(0.0, 0.0, 10.0).outer).expect("crosses");
        // (grown by ON_EDGE: 1e-7 mm of the 20 mm chord)
        assert!((lo - 0.25).abs() < 1e-8 && (hi - 0.75).abs() < 1e-8);
        assert!(in_convex([-5.0, 20.0], [15.0, 20.0], &square(0.0, 0.0, 10.0).outer).is_none());
        let left = uncovered(&spans, &mut [(0.2, 0.5)]);
        let length: f64 = left.iter().map(|(a, b)| b - a).sum::<f64>() * 20.0;
        // the cover takes the first 4 mm inside (t 0.25 … 0.45), the second 4 mm stay
        assert!((length - 4.0).abs() < 1e-12, "{left:?}");
    }
}
