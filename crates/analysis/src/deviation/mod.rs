//! The final part against the intended one: gouges (part material that is gone) and
//! leftovers (material that should be gone), each with its area, depth, position and the
//! moves whose sweeps made it (spec/simulation.md, "The intended shape").

mod blame;
mod features;
pub(crate) use blame::moves_over;
#[cfg(test)]
mod tests;

use crate::intent::{rect, Intent, FAR};
use expander::Segment;
use geom::distance::EdgeIndex;
use geom::flat::{clip_convex, dist, lerp, pts, P};
use geom::{ring, Rect};
use stock::{area, boolean, BoolOp, Mounts, Shape, ToolTable};

/// One connected region where the part differs from the intent.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// The region.
    pub shape: Shape,
    /// Its area, mm².
    pub area: f64,
    /// Largest distance of the region from the intended boundary, mm.
    pub depth: f64,
    /// The deepest point, (z, r).
    pub at: [f64; 2],
    /// The point of the intended part's boundary nearest `at` (its depth is measured to
    /// it); `at` itself when the comparison has no boundary.
    pub nearest: [f64; 2],
    /// The first segment whose tool sweep overlaps the region (gouges only): the move that
    /// made it, named in the report.
    pub made_by: Option<usize>,
    /// A possible finding (spec/simulation.md, "Findings from assumed tools"): the move
    /// that made it cuts with an outline the table does not state, and the tool's
    /// reference point alone does not enter the region. No effect on the verdict.
    pub assumed: bool,
    /// Why it happened ([`crate::diagnose`]); `None` before the diagnosis.
    pub cause: Option<crate::Cause>,
    /// How to fix it, checked by simulating the fix; `None` when none was found.
    pub remedy: Option<crate::Remedy>,
}

/// Gouges and leftovers beyond the tolerance.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Deviation {
    /// Overcuts: part material removed.
    pub gouges: Vec<Finding>,
    /// Undercuts: material left that should be gone.
    pub leftovers: Vec<Finding>,
    /// Part material a later operation of another tool cut on purpose (see
    /// [`Intent::owner`]): not gouges; the report names them.
    pub later_cuts: Vec<Finding>,
}

impl Deviation {
    /// Total overcut area, mm².
    pub fn overcut_area(&self) -> f64 {
        self.gouges.iter().map(|f| f.area).sum()
    }
    /// Total undercut area, mm².
    pub fn undercut_area(&self) -> f64 {
        self.leftovers.iter().map(|f| f.area).sum()
    }
    /// Deepest gouge, mm (0 when none).
    pub fn max_overcut(&self) -> f64 {
        self.gouges.iter().map(|f| f.depth).fold(0.0, f64::max)
    }
    /// Thickest leftover, mm (0 when none).
    pub fn max_undercut(&self) -> f64 {
        self.leftovers.iter().map(|f| f.depth).fold(0.0, f64::max)
    }
}

/// Compare `final_shapes` (the simulated part, cut from `blank`) with the intents. Regions
/// whose depth does not exceed `tol` are dropped (chord and grid noise); the rest are
/// findings. Gouges get the segments whose tool sweep overlaps them.
pub fn deviation(
    blank: &[Shape],
    final_shapes: &[Shape],
    intents: &[Intent],
    tol: f64,
    segments: &[Segment],
    tools: &ToolTable,
    chord_tol: f64,
) -> Deviation {
    let mut out = Deviation::default();
    if intents.is_empty() {
        return out;
    }
    // P is the blank intersected with what every intent keeps: within its zone its part,
    // outside its zone anything (an OD contour says nothing about the bore an ID contour
    // finishes: spec/simulation.md, "The intended shape"). The comparison holds where at
    // least one intent speaks.
    //
    // Everything compared lies in the blank (the final part is cut from it), so the intents
    // are clipped to the blank's box first: the booleans' grid is fitted to their inputs,
    // and an intent closed FAR away made it ~0.4 µm, coarser than a fine blank's detail
    // (a 100 000-vertex sawtooth of 0.0016 mm teeth snapped to near-collinear edges that
    // took the splitter seconds) — within the blank's box it is ~1000 times finer.
    let world_box = Rect::of(blank.iter().flat_map(|s| pts(&s.outer))).grown(1.0);
    if world_box.is_empty() {
        return out;
    }
    let world = vec![rect(
        world_box.min.z,
        world_box.max.z,
        world_box.min.r,
        world_box.max.r,
    )];
    let mut part = blank.to_vec();
    let mut zone: Vec<Shape> = vec![];
    for intent in intents {
        let intent_zone = clip_to_box(&intent.zone, &world_box);
        let elsewhere = boolean(&world, &intent_zone, BoolOp::Difference);
        let keeps = boolean(
            &clip_to_box(&intent.part, &world_box),
            &elsewhere,
            BoolOp::Union,
        );
        part = boolean(&part, &keeps, BoolOp::Intersection);
        zone = boolean(&zone, &intent_zone, BoolOp::Union);
    }
    let should_stay = boolean(&part, &zone, BoolOp::Intersection);
    let final_zone = boolean(final_shapes, &zone, BoolOp::Intersection);
    let gone = boolean(&should_stay, final_shapes, BoolOp::Difference);
    let left = boolean(&final_zone, &part, BoolOp::Difference);
    let mut mounts = Mounts::new(tools, stock::rear_tools(segments));
    // what the feature cuts swept of it is judged apart, made by them (against a drawing,
    // `--target`, every cut is judged as it is: no feature is any operation's own)
    let featured = if intents.iter().any(|i| i.owner.is_some()) {
        features::sweeps(&gone, segments, tools, &mut mounts, chord_tol)
    } else {
        vec![]
    };
    let (plain, by_features) = if featured.is_empty() {
        (gone, vec![])
    } else {
        (
            boolean(&gone, &featured, BoolOp::Difference),
            boolean(&gone, &featured, BoolOp::Intersection),
        )
    };
    let depth_in = faced(&part, &zone, final_shapes, &world_box);
    let mut plain = findings(plain, &depth_in, tol);
    let mut by_features = findings(by_features, &depth_in, tol);
    blame::blame(&mut plain, segments, &mut mounts, chord_tol, &|_| true);
    let feature = |s: &Segment| crate::sweeps::cuts_features(s, tools);
    blame::blame(&mut by_features, segments, &mut mounts, chord_tol, &feature);
    out.gouges = plain;
    out.gouges.append(&mut by_features);
    // the thread bands (what a thread cut of them is left out of every zone: its own
    // form) are stated too
    let bands = std::cell::OnceCell::new();
    let band_edges = || {
        bands.get_or_init(|| {
            let shapes = crate::intent::program::thread_bands(segments, tools);
            outline_index(shapes.iter().map(|s| (&s.outer, true)))
        })
    };
    if !out.gouges.is_empty() {
        let stated = stated_surfaces(intents, &world_box);
        out.gouges
            .retain(|g| on_stated_surface(g, &stated, tol) || meets(g, band_edges(), tol));
    }
    out.leftovers = findings(left, &part, tol);
    let (later, gouges): (Vec<Finding>, Vec<Finding>) = std::mem::take(&mut out.gouges)
        .into_iter()
        .partition(|g| cut_later(g, intents, segments, tools, &world_box));
    out.gouges = gouges;
    out.later_cuts = later;
    // a tool the table says nothing of may be a drill or a blade: what it cuts inside a
    // contour another tool finished before may be its own hole or groove
    for g in &mut out.gouges {
        if g.made_by.is_some_and(|i| {
            tools.get(segments[i].tool).is_none()
                && segments[i].motion != expander::Motion::Rapid
                && in_later_contour(g, intents, (i, &segments[i]), &world_box, true)
        }) {
            g.assumed = true;
        }
    }
    // the reference point makes a gouge certain where it enters what an intent keeps; in
    // no intent's zone (a thread's teeth, the bar beyond a contour) the part is anything
    mark_assumed(
        &mut out.gouges,
        &should_stay,
        segments,
        &mut mounts,
        chord_tol,
    );
    out
}

/// The intended part a gouge's depth is measured in: `part` without the stock in front of
/// the foremost zone that the final part has faced off. In front of the zones the part is
/// "anything", the blank; a face cut 0.2 too deep then read as deep as the face stock it
/// took along (0.7 with 0.5 of it, and a false "nose not compensated"; field run 4, 5e).
/// Behind the front (the bar past a contour's end, a hole drilled on past it) the part
/// goes on into the blank as before.
fn faced(part: &[Shape], zone: &[Shape], final_shapes: &[Shape], world: &Rect) -> Vec<Shape> {
    let front = zone
        .iter()
        .flat_map(|s| pts(&s.outer))
        .map(|p| p.z)
        .fold(f64::NEG_INFINITY, f64::max);
    if !front.is_finite() || front >= world.max.z {
        return part.to_vec();
    }
    let ahead = vec![rect(front, world.max.z, world.min.r, world.max.r)];
    // only the final part ahead of the front takes part (a long part's section is not cut
    // whole for a face)
    let box_ahead = Rect::new(
        geom::Pt::new(front, world.min.r),
        geom::Pt::new(world.max.z, world.max.r),
    );
    let faced_off = boolean(
        &ahead,
        &clip_to_box(final_shapes, &box_ahead),
        BoolOp::Difference,
    );
    if area(&faced_off) <= 0.0 {
        return part.to_vec();
    }
    boolean(part, &faced_off, BoolOp::Difference)
}

/// Marks the gouges made by a guessed tool that only its assumed extent explains as
/// possible (the first [`crate::assumed::MAX_TESTED`] of them are tested, the rest stay
/// possible).
fn mark_assumed(
    gouges: &mut [Finding],
    part: &[Shape],
    segments: &[Segment],
    mounts: &mut Mounts,
    chord_tol: f64,
) {
    let guessed: Vec<usize> = (0..gouges.len())
        .filter(|&g| {
            !gouges[g].assumed
                && gouges[g]
                    .made_by
                    .is_some_and(|i| crate::assumed::guessed(mounts.tools(), &segments[i]))
        })
        .collect();
    let tested = &guessed[..guessed.len().min(crate::assumed::MAX_TESTED)];
    let regions: Vec<&Shape> = tested.iter().map(|&g| &gouges[g].shape).collect();
    let from: Vec<usize> = tested
        .iter()
        .map(|&g| gouges[g].made_by.unwrap_or(0))
        .collect();
    let certain = blame::certain(&regions, &from, part, segments, mounts, chord_tol);
    for (k, &g) in guessed.iter().enumerate() {
        gouges[g].assumed = !certain.get(k).copied().unwrap_or(false);
    }
}

/// Whether the gouge `g` was made by a feed move of a blade, drill or threading tool other
/// than the contour's, after every contour that claims its place began ([`Intent::owner`]):
/// the later operation's own cut (a groove, a hole, a relief). A turning tool's cut into a
/// finished contour stays a gouge.
fn cut_later(
    g: &Finding,
    intents: &[Intent],
    segments: &[Segment],
    tools: &ToolTable,
    world: &Rect,
) -> bool {
    let Some(seg) = g.made_by.and_then(|i| segments.get(i).map(|s| (i, s))) else {
        return false;
    };
    let (i, seg) = seg;
    if !crate::sweeps::cuts_features(seg, tools) {
        return false;
    }
    in_later_contour(g, intents, (i, seg), world, false)
}

/// Whether every contour that claims the place of `g` (at least one) was finished by
/// another tool than move `i`'s and began before `i` ([`Intent::owner`]), or claims it
/// only as the core under an OD profile ([`core_hole`]). `own_later`: a contour of move
/// `i`'s own tool that begins after it does not count (for a tool the table says nothing
/// of, whose finding then is only possible: a part-off's plunge before its own chamfer
/// under G42; field run 5, C).
fn in_later_contour(
    g: &Finding,
    intents: &[Intent],
    (i, seg): (usize, &Segment),
    world: &Rect,
    own_later: bool,
) -> bool {
    let region = std::slice::from_ref(&g.shape);
    let claiming = intents.iter().filter(|intent| {
        let zone = clip_to_box(&intent.zone, world);
        area(&boolean(region, &zone, BoolOp::Intersection)) > 1e-9
    });
    let mut any = false;
    for intent in claiming {
        match intent.owner {
            Some(o) if o.tool != seg.tool && (i >= o.began || core_hole(g, intent)) => {
                any = true;
            }
            Some(o) if own_later && o.tool == seg.tool && o.began > i => {}
            _ => return false,
        }
    }
    any
}

/// Whether gouge `g` meets a surface an intent states: it comes within `tol` of the
/// outline of an intent whose zone it lies in. A contour states the surface it finishes,
/// not the part's other side (spec/simulation.md, "each constrains only its own side"): a
/// bush whose only contour is its bore, its OD turned by G90, lost "2.2 mm" of an OD no
/// contour states to a bore contour that claims the wall out to any radius (field run 7,
/// A; its mirror, a bore opened by G90 under an OD contour, too). Material gone from the
/// part where no stated surface is, is not judged (**Interpretation**,
/// docs/field-rules.md §21).
fn on_stated_surface(g: &Finding, stated: &[Stated], tol: f64) -> bool {
    let region = Rect::of(pts(&g.shape.outer));
    stated.iter().any(|s| {
        let overlaps = s.zones.iter().any(|b| {
            b.min.z.max(region.min.z) < b.max.z.min(region.max.z) - 1e-9
                && b.min.r.max(region.min.r) < b.max.r.min(region.max.r) - 1e-9
        });
        overlaps && meets(g, &s.outline, tol)
    })
}

/// Where an intent states a surface: the boxes of its zone (within the world's box) and
/// the edges of its outline.
struct Stated {
    zones: Vec<Rect>,
    outline: EdgeIndex,
}

/// Each intent's [`Stated`], made once for all the gouges.
fn stated_surfaces(intents: &[Intent], world: &Rect) -> Vec<Stated> {
    intents
        .iter()
        .map(|intent| Stated {
            zones: clip_to_box(&intent.zone, world)
                .iter()
                .map(|z| Rect::of(pts(&z.outer)))
                .collect(),
            outline: outline_index(intent.outline.iter().map(|(l, c)| (l, *c))),
        })
        .collect()
}

/// Whether a vertex of `g` lies within `tol` of an edge of `edges`.
fn meets(g: &Finding, edges: &EdgeIndex, tol: f64) -> bool {
    std::iter::once(&g.shape.outer)
        .chain(&g.shape.holes)
        .flatten()
        .any(|&p| edges.nearest(p.into()).is_some_and(|(d, _)| d <= tol))
}

/// The edges of `lines` (a path and whether it is closed): an open path stays open (a
/// closing edge would cross the part).
fn outline_index<'a>(lines: impl Iterator<Item = (&'a Vec<P>, bool)>) -> EdgeIndex {
    EdgeIndex::new(lines.flat_map(|(line, closed)| {
        let n = line.len();
        let edges = if closed { n } else { n.saturating_sub(1) };
        (0..edges).map(move |i| {
            let (a, b) = (line[i], line[(i + 1) % n]);
            (geom::Pt::new(a[0], a[1]), geom::Pt::new(b[0], b[1]))
        })
    }))
}

/// Whether `g` is a hole on the axis and `intent` claims it only as the core under its
/// profile: an OD contour's part runs down to the axis and states nothing of a centre hole
/// or a drilled core, drilled before it as well as after (face, centre drill, turn). An ID
/// contour's part stops at its bore: what a drill cuts of it is judged as before.
fn core_hole(g: &Finding, intent: &Intent) -> bool {
    const ON_AXIS: f64 = 1e-6;
    let reaches_axis = |ring: &[P]| ring.iter().any(|p| p[1] <= ON_AXIS);
    reaches_axis(&g.shape.outer) && intent.part.iter().any(|s| reaches_axis(&s.outer))
}

/// `shapes` cut to `bx` ring by ring (Sutherland–Hodgman against the box's four sides): the
/// same region within the box under the non-zero rule (a ring that leaves and re-enters the
/// box gets zero-width bridges along its sides, which enclose nothing), with every vertex
/// inside the box kept exactly as it was.
fn clip_to_box(shapes: &[Shape], bx: &Rect) -> Vec<Shape> {
    let ring = |r: &[P]| clip_convex(r, bx);
    shapes
        .iter()
        .filter_map(|s| {
            let outer = ring(&s.outer);
            (outer.len() >= 3).then(|| Shape {
                outer,
                holes: s
                    .holes
                    .iter()
                    .map(|h| ring(h))
                    .filter(|h| h.len() >= 3)
                    .collect(),
            })
        })
        .collect()
}

/// The components of `region` deeper than `tol` from the boundary of `part`. A region
/// thinner than a tenth of the tolerance (mean thickness 2·area / perimeter) both as a whole
/// and around its deepest point is boolean noise along a shared edge, not a finding, however
/// far it reaches: a mutated blank profile made 77 580 such "gouges" of 0.0000 mm². (Around
/// the deepest point too, because a real leftover joined to a long sliver of chord noise
/// is thin on average but not where it is deep.)
fn findings(region: Vec<Shape>, part: &[Shape], tol: f64) -> Vec<Finding> {
    let boundary = EdgeIndex::of_rings(
        part.iter()
            .flat_map(|s| std::iter::once(&s.outer).chain(&s.holes))
            .map(|r| pts(r))
            .collect::<Vec<_>>()
            .iter()
            .map(Vec::as_slice),
    );
    let step = DEPTH_STEP.max(region.iter().map(perimeter).sum::<f64>() / DEPTH_SAMPLES as f64);
    region
        .into_iter()
        .filter_map(|shape| {
            let a = area(std::slice::from_ref(&shape));
            let (depth, at, nearest) = deepest(&shape, &boundary, step);
            let deep_with_area = depth > tol && a > 0.0;
            if !deep_with_area {
                return None;
            }
            let thin =
                |s: &[Shape]| 2.0 * area(s) < 0.1 * tol * s.iter().map(perimeter).sum::<f64>();
            if thin(std::slice::from_ref(&shape)) {
                // the part within the depth (at least the tolerance) of the deepest point
                let h = depth.min(FAR);
                let near = Rect::new(
                    geom::Pt::new(at[0] - h, at[1] - h),
                    geom::Pt::new(at[0] + h, at[1] + h),
                );
                if thin(&clip_to_box(std::slice::from_ref(&shape), &near)) {
                    return None;
                }
            }
            Some(Finding {
                shape,
                area: a,
                depth,
                at,
                nearest,
                made_by: None,
                assumed: false,
                cause: None,
                remedy: None,
            })
        })
        .collect()
}

/// Length of all the rings of `shape`.
fn perimeter(shape: &Shape) -> f64 {
    std::iter::once(&shape.outer)
        .chain(&shape.holes)
        .map(|ring| {
            let n = ring.len();
            (0..n)
                .map(|i| dist(ring[i], ring[(i + 1) % n]))
                .sum::<f64>()
        })
        .sum()
}

/// Spacing of the points along a region's boundary where its depth is looked for, mm.
const DEPTH_STEP: f64 = 0.002;
/// Most such points for all the regions of one comparison (longer boundaries are looked at
/// more coarsely: a 600 000-point blank profile's noise regions otherwise took seconds).
const DEPTH_SAMPLES: usize = 200_000;

/// The point of `shape` farthest from `boundary` (the intended part's edges), its distance
/// and the boundary point nearest it. The distance along a region edge peaks at its ends
/// or where the nearest boundary feature changes (a bisector crossing the edge, as where
/// a cut line passes a corner of the intended part), so every edge is looked at every
/// `step` ([`DEPTH_STEP`] unless the regions are long) and the best place refined to a
/// small fraction of that; the centroid
/// covers a region that reaches round a corner of the boundary. (Vertices and edge
/// midpoints alone missed the bisector: 1.043 reported for a 1.465 gouge.) Distances come
/// from parry2d-f64's edge tree (infinite without a boundary, the nearest point then the
/// point itself).
fn deepest(shape: &Shape, boundary: &EdgeIndex, step: f64) -> (f64, P, P) {
    let first = shape.outer.first().copied().unwrap_or([0.0, 0.0]);
    let mut best = (0.0, first, first);
    let rings: Vec<&Vec<P>> = std::iter::once(&shape.outer).chain(&shape.holes).collect();
    let depth_at = |p: P| {
        boundary
            .nearest(p.into())
            .map_or((f64::INFINITY, p), |(d, q)| (d, q.to_array()))
    };
    // (depth, point, nearest, edge ends, parameter, parameter step)
    let mut top: Option<(f64, P, P, P, P, f64, f64)> = None;
    for ring in &rings {
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let k = ((dist(a, b) / step).ceil() as usize).clamp(1, DEPTH_SAMPLES);
            for j in 0..k {
                let t = j as f64 / k as f64;
                let p = lerp(a, b, t);
                let (d, q) = depth_at(p);
                if top.is_none_or(|x| d > x.0) {
                    top = Some((d, p, q, a, b, t, 1.0 / k as f64));
                }
            }
        }
        if n > 0 {
            let c = ring.iter().fold([0.0, 0.0], |s, p| {
                [s[0] + p[0] / n as f64, s[1] + p[1] / n as f64]
            });
            if ring::contains(&pts(ring), c.into()) {
                let (d, q) = depth_at(c);
                if d > best.0 {
                    best = (d, c, q);
                }
            }
        }
    }
    if let Some((mut d, mut p, mut q, a, b, mut t, mut dt)) = top {
        // refine about the best sample of its edge
        for _ in 0..3 {
            let (lo, hi) = ((t - dt).max(0.0), (t + dt).min(1.0));
            for j in 0..=16 {
                let u = lo + (hi - lo) * j as f64 / 16.0;
                let x = lerp(a, b, u);
                let (dx, qx) = depth_at(x);
                if dx > d {
                    (d, p, q, t) = (dx, x, qx, u);
                }
            }
            dt /= 8.0;
        }
        if d > best.0 {
            best = (d, p, q);
        }
    }
    best
}

/// The warning of each cut a later operation made inside a finished contour (at most
/// [`crate::MAX_LISTED`]): read as that operation's own, not a gouge.
pub(crate) fn later_cut_notes(d: &Deviation, segments: &[Segment]) -> Vec<crate::Note> {
    d.later_cuts
        .iter()
        .take(crate::MAX_LISTED)
        .filter_map(|c| {
            let seg = c.made_by.and_then(|i| segments.get(i))?;
            Some(crate::Note {
                span: seg.span,
                code: "LS-LATER-CUT",
                message: format!(
                    "T{:02} cuts {:.3} mm² ({:.3} mm deep, at Z{:.3} X{:.3}) inside a contour another tool finishes: read as this operation's own cut (a groove, hole or relief), not a gouge (Interpretation; --target judges it against the drawing)",
                    seg.tool,
                    c.area,
                    c.depth,
                    c.at[0],
                    2.0 * c.at[1]
                ),
            })
        })
        .collect()
}
