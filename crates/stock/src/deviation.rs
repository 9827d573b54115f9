//! The final part against the intended one: gouges (part material that is gone) and
//! leftovers (material that should be gone), each with its area, depth, position and the
//! moves whose sweeps made it (spec/simulation.md, "The intended shape").

use crate::overlay::BoolOp;
use crate::{area, boolean, Outline, Shape, ToolTable};
use expander::Segment;
use geom::distance::EdgeIndex;
use geom::flat::{clip_convex, clip_to_hull, convex_hull, dist, lerp, pts, sweep_convex, P};
use geom::{ring, Rect};

/// What the part should be, and where that statement holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Intent {
    /// The intended part material.
    pub part: Vec<Shape>,
    /// Where the comparison applies (a G75.1 groove's box, a finishing shape's Z span);
    /// outside it the program may do what it likes.
    pub zone: Vec<Shape>,
    /// The intended boundary as drawn in the report: (points, closed ring or open path).
    pub outline: Vec<(Vec<[f64; 2]>, bool)>,
    /// For a contour the program cuts: the tool that cuts it and the index of its first
    /// move. What feed moves of another tool cut from then on inside its zone is that
    /// operation's own (a groove in a finished diameter, a drilled core, a thread relief):
    /// no gouge of this contour (**Interpretation**, [`Deviation::later_cuts`]). `None`
    /// (a `--target` drawing, a G75.1 groove): every cut is judged.
    pub owner: Option<(u32, usize)>,
}

/// The side toward which an open intended path is closed: where the part lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Toward {
    MinusR,
    PlusR,
    MinusZ,
    PlusZ,
}

/// Half the size of the world a zone or a closing edge may reach, mm.
const FAR: f64 = 1e5;

fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
    Shape {
        outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
        holes: vec![],
    }
}

impl Intent {
    /// `--target`: the whole intended part, compared everywhere.
    pub fn target(part: Vec<Shape>) -> Self {
        let outline = part
            .iter()
            .flat_map(|s| std::iter::once(s.outer.clone()).chain(s.holes.iter().cloned()))
            .map(|ring| (ring, true))
            .collect();
        Self {
            part,
            zone: vec![rect(-FAR, FAR, -FAR, FAR)],
            outline,
            owner: None,
        }
    }

    /// A G75.1 groove (a closed ring of material that must go): compared within the
    /// groove's bounding box grown along Z by the groove's depth on both sides (a groove cut
    /// a blade width off, or a flank gouged, shows there), where everything but the groove
    /// must stay. Material above the mouth is not the groove's business.
    pub fn groove(ring: &[[f64; 2]]) -> Self {
        let (lo, hi) = bbox(ring);
        let grow = (hi[1] - lo[1]).max(1.0);
        let zone = vec![rect(lo[0] - grow, hi[0] + grow, lo[1] - grow, hi[1])];
        let groove = boolean(
            &[Shape {
                outer: ring.to_vec(),
                holes: vec![],
            }],
            &[],
            BoolOp::Union,
        );
        Self {
            part: boolean(&zone, &groove, BoolOp::Difference),
            zone,
            outline: vec![(ring.to_vec(), true)],
            owner: None,
        }
    }

    /// A G70–G73 finishing shape: `path[0]` is the start point A, `path[1..]` the shape
    /// B..C. The part lies on the side away from A (spec): below the shape when A is above
    /// it (OD), above it when A is below (ID), left of it when A is to its right (facing).
    /// The comparison is limited to the shape's Z span (its X span for facing).
    ///
    /// Only the profile bounds the part (spec, "The intended shape"); `stock` is the stock
    /// when the cycle began, and what the shape runs through before it first touches that
    /// stock, and after it last leaves it, is approach and retract ([`in_contact`]).
    pub fn finishing(path: &[[f64; 2]], stock: &[Shape]) -> Option<Self> {
        let (a, shape) = path.split_first()?;
        let (lo, hi) = bbox(shape);
        let toward = if a[1] >= hi[1] - 1e-9 {
            Toward::MinusR
        } else if a[1] <= lo[1] + 1e-9 {
            Toward::PlusR
        } else if a[0] >= hi[0] - 1e-9 {
            Toward::MinusZ
        } else {
            return None;
        };
        Self::open_path(&in_contact(shape, stock), toward)
    }

    /// A contour cut under G41/G42: the part lies on the side of the path away from the
    /// tool (`part_on_left` of the direction of travel for G42). The region is closed
    /// toward the side the path's normals on the part side point to on average (below for
    /// OD turning, above for ID boring, left for facing); the comparison is limited to the
    /// path's Z span (its X span when closed along Z). As for a finishing shape, approach
    /// and retract are no part (`stock`: when the contour began), also when deciding the
    /// side: a retract off the last diameter would otherwise turn an OD contour into a face.
    pub fn compensated(path: &[[f64; 2]], part_on_left: bool, stock: &[Shape]) -> Option<Self> {
        let path = in_contact(path, stock);
        let mut n = [0.0, 0.0];
        for w in path.windows(2) {
            let d = [w[1][0] - w[0][0], w[1][1] - w[0][1]];
            let left = [-d[1], d[0]];
            let s = if part_on_left { 1.0 } else { -1.0 };
            n = [n[0] + s * left[0], n[1] + s * left[1]];
        }
        let toward = if n[1].abs() >= n[0].abs() {
            if n[1] < 0.0 {
                Toward::MinusR
            } else {
                Toward::PlusR
            }
        } else if n[0] < 0.0 {
            Toward::MinusZ
        } else {
            Toward::PlusZ
        };
        Self::open_path(&path, toward)
    }

    /// The part bounded by an open path and closed far away `toward` one side.
    fn open_path(shape: &[[f64; 2]], toward: Toward) -> Option<Self> {
        let (first, last) = (*shape.first()?, *shape.last()?);
        if shape.len() < 2 {
            return None;
        }
        let (lo, hi) = bbox(shape);
        let mut ring = shape.to_vec();
        let zone = match toward {
            Toward::MinusR | Toward::PlusR => {
                let r = if toward == Toward::MinusR { -FAR } else { FAR };
                ring.extend([[last[0], r], [first[0], r]]);
                rect(lo[0], hi[0], -FAR, FAR)
            }
            Toward::MinusZ | Toward::PlusZ => {
                let z = if toward == Toward::MinusZ { -FAR } else { FAR };
                ring.extend([[z, last[1]], [z, first[1]]]);
                rect(-FAR, FAR, lo[1], hi[1])
            }
        };
        let part = boolean(
            &[Shape {
                outer: ring,
                holes: vec![],
            }],
            &[],
            BoolOp::Union,
        );
        Some(Self {
            part,
            zone: vec![zone],
            outline: vec![(shape.to_vec(), false)],
            owner: None,
        })
    }
}

/// How near a path must come to the stock to touch it, mm: a path run on the stock's
/// surface (a G70 after roughing to size) touches it; one in the air a rapid's clearance
/// away does not.
const CONTACT: f64 = 1e-3;

/// The stretch of `path` that is profile (spec/simulation.md, "The intended shape": approach
/// and retract are no part), judged against `stock`, the stock when the path began:
/// - leading segments that do not touch the stock (a lead-in along Z to a faced front, an
///   approach along the chamfer's own line) are dropped; when none was, the first segment
///   starts where it first touches the stock (a diameter reached straight from the
///   approach starts at the stock's front), else at its programmed vertex (a face marked by
///   `G01 Z0` stays at Z0, so a face cut too deep before is still found);
/// - trailing moves off the last diameter that end beyond the stock's radial extent are
///   dropped (also where they cut the corner on the way), and trailing segments that no
///   longer touch the stock, and the end of the last one past its last contact.
///
/// A segment touches where its band of ±[`CONTACT`] meets the stock. Empty when the path
/// never touches the stock.
fn in_contact(path: &[P], stock: &[Shape]) -> Vec<P> {
    // the first segment that touches (the ones before are dropped at once, not one by one)
    let mut first = 0;
    let mut start = None;
    while first + 1 < path.len() {
        let (a, b) = (path[first], path[first + 1]);
        if let Some((t, _)) =
            contact(a, b, stock).filter(|(t, _)| (1.0 - t) * dist(a, b) > 2.0 * CONTACT)
        {
            start = Some(t);
            break;
        }
        first += 1;
    }
    let mut s = path[first..].to_vec();
    if let Some(t) = start {
        if first == 0 && t * dist(s[0], s[1]) > CONTACT {
            s[0] = lerp(s[0], s[1], t);
        }
    }
    let all: Vec<P> = stock.iter().flat_map(|m| m.outer.clone()).collect();
    if all.is_empty() {
        return vec![];
    }
    let (lo, hi) = bbox(&all);
    const EPS: f64 = 1e-6;
    while s.len() > 2 {
        let (p, q) = (s[s.len() - 2], s[s.len() - 1]);
        let off = (q[1] > p[1] + EPS && q[1] >= hi[1] - EPS)
            || (q[1] < p[1] - EPS && q[1] <= lo[1] + EPS);
        if !off {
            break;
        }
        s.pop();
    }
    while s.len() >= 2 {
        let (a, b) = (s[s.len() - 2], s[s.len() - 1]);
        match contact(a, b, stock) {
            Some((_, t)) if t * dist(a, b) > 2.0 * CONTACT => {
                if (1.0 - t) * dist(a, b) > CONTACT {
                    let last = s.len() - 1;
                    s[last] = lerp(a, b, t);
                }
                break;
            }
            _ => {
                s.pop();
            }
        }
    }
    if s.len() < 2 {
        s.clear();
    }
    s
}

/// Where the segment `a -> b` touches `stock`: the first and last parameter (0 at `a`, 1 at
/// `b`) where it is inside the stock, exactly where it crosses the stock's edges; where it
/// only runs along or grazes the stock, where its band of ±[`CONTACT`] meets it. `None`
/// when it misses.
fn contact(a: P, b: P, stock: &[Shape]) -> Option<(f64, f64)> {
    let len = dist(a, b);
    if len <= 0.0 {
        return None;
    }
    let span = |ts: &mut dyn Iterator<Item = f64>| {
        ts.fold(None, |acc: Option<(f64, f64)>, t| match acc {
            None => Some((t, t)),
            Some((lo, hi)) => Some((lo.min(t), hi.max(t))),
        })
    };
    // the segment itself: its ends inside, its crossings of the edges
    let inside = |p: P| stock.iter().any(|m| shape_contains(m, p));
    let d = [b[0] - a[0], b[1] - a[1]];
    let cross = |u: [f64; 2], v: [f64; 2]| u[0] * v[1] - u[1] * v[0];
    let mut ts: Vec<f64> = vec![];
    if inside(a) {
        ts.push(0.0);
    }
    if inside(b) {
        ts.push(1.0);
    }
    let (lo, hi) = (
        [a[0].min(b[0]), a[1].min(b[1])],
        [a[0].max(b[0]), a[1].max(b[1])],
    );
    for ring in stock
        .iter()
        .flat_map(|m| std::iter::once(&m.outer).chain(&m.holes))
    {
        for (k, &c) in ring.iter().enumerate() {
            let e = ring[(k + 1) % ring.len()];
            // an edge whose box misses the segment's cannot cross it
            if c[0].max(e[0]) < lo[0]
                || c[0].min(e[0]) > hi[0]
                || c[1].max(e[1]) < lo[1]
                || c[1].min(e[1]) > hi[1]
            {
                continue;
            }
            let f = [e[0] - c[0], e[1] - c[1]];
            let denom = cross(d, f);
            if denom.abs() < 1e-15 {
                continue;
            }
            let ca = [c[0] - a[0], c[1] - a[1]];
            let (t, u) = (cross(ca, f) / denom, cross(ca, d) / denom);
            if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
                ts.push(t);
            }
        }
    }
    let crossing = span(&mut ts.iter().copied());
    if let Some((lo, hi)) = crossing {
        // a real entry: the segment's own points inside between two parameters
        if hi > lo && inside(lerp(a, b, (lo + hi) / 2.0)) {
            return crossing;
        }
    }
    // along or near the stock: the band
    let u = [d[0] / len, d[1] / len];
    let n = [-u[1] * CONTACT, u[0] * CONTACT];
    let e = [u[0] * CONTACT, u[1] * CONTACT];
    let band = Shape {
        outer: vec![
            [a[0] - e[0] - n[0], a[1] - e[1] - n[1]],
            [b[0] + e[0] - n[0], b[1] + e[1] - n[1]],
            [b[0] + e[0] + n[0], b[1] + e[1] + n[1]],
            [a[0] - e[0] + n[0], a[1] - e[1] + n[1]],
        ],
        holes: vec![],
    };
    let hit = boolean(stock, &[band], BoolOp::Intersection);
    let t = |p: &P| (((p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1]) / len).clamp(0.0, 1.0);
    span(&mut hit.iter().flat_map(|h| h.outer.iter().map(t)))
}

/// Whether `p` is inside the shape (its outer ring and none of its holes), even-odd, on
/// the rings as they are (`geom::ring::contains` would copy the stock's rings to kernel
/// points for every point asked).
fn shape_contains(m: &Shape, p: P) -> bool {
    let crossings = |ring: &[P]| {
        let mut inside = false;
        for (k, &c) in ring.iter().enumerate() {
            let e = ring[(k + 1) % ring.len()];
            if (c[1] > p[1]) != (e[1] > p[1])
                && p[0] < c[0] + (p[1] - c[1]) * (e[0] - c[0]) / (e[1] - c[1])
            {
                inside = !inside;
            }
        }
        inside
    };
    crossings(&m.outer) && !m.holes.iter().any(|h| crossings(h))
}

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
    out.gouges = findings(gone, &part, tol);
    out.leftovers = findings(left, &part, tol);
    let rear = crate::section::rear_tools(segments);
    blame(&mut out.gouges, segments, tools, &rear, chord_tol);
    let (later, gouges): (Vec<Finding>, Vec<Finding>) = std::mem::take(&mut out.gouges)
        .into_iter()
        .partition(|g| cut_later(g, intents, segments, tools, &world_box));
    out.gouges = gouges;
    out.later_cuts = later;
    out
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
    let cuts_features = tools.blade_cuts(seg)
        || matches!(
            tools.get(seg.tool),
            Some(crate::Tool::Drill { .. } | crate::Tool::Threading { .. })
        );
    if seg.motion == expander::Motion::Rapid || !cuts_features {
        return false;
    }
    let region = std::slice::from_ref(&g.shape);
    let claiming = intents.iter().filter(|intent| {
        let zone = clip_to_box(&intent.zone, world);
        area(&boolean(region, &zone, BoolOp::Intersection)) > 1e-9
    });
    let mut any = false;
    for intent in claiming {
        match intent.owner {
            Some((tool, from)) if tool != seg.tool && i >= from => any = true,
            _ => return false,
        }
    }
    any
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

/// For every gouge, the first segment whose tool sweep overlaps it by more than a sliver.
/// Each segment's sweep is built once and tried on the gouges still unnamed whose box it
/// meets; the search ends when every gouge is named. (A mutated facing program of 11 030
/// moves whose holder rubs on most of them took 19.8 s when every gouge built every sweep
/// again and asked a boolean; a 3 000-pass G73 over small arcs asked for every pass.)
/// Moves past the axis are folded into the section as the removal folds them
/// ([`crate::section`]); `rear` are the rear-post tools (their outline mirrored).
fn blame(
    gouges: &mut [Finding],
    segments: &[Segment],
    tools: &ToolTable,
    rear: &[u32],
    chord_tol: f64,
) {
    let boxes: Vec<Rect> = gouges
        .iter()
        .map(|g| Rect::of(pts(&g.shape.outer)))
        .collect();
    let mut cache: OutlineCache = vec![];
    let mut unnamed: Vec<usize> = (0..gouges.len()).collect();
    for (i, seg) in segments.iter().enumerate() {
        if unnamed.is_empty() {
            break;
        }
        let outline = outline_cached(&mut cache, tools, seg, rear.contains(&seg.tool));
        let near: Vec<usize> = unnamed
            .iter()
            .copied()
            .filter(|&g| may_sweep_over(&boxes[g], seg, &outline))
            .collect();
        if near.is_empty() {
            continue;
        }
        let sweep = sweep_parts(seg, &outline, chord_tol);
        for g in near {
            if overlaps(&gouges[g].shape, &boxes[g], &sweep) {
                gouges[g].made_by = Some(i);
                unnamed.retain(|&u| u != g);
            }
        }
    }
}

/// Whether the sweep of `seg` may reach the box `bb` (false only when it surely does not).
fn may_sweep_over(bb: &Rect, seg: &Segment, outline: &Outline) -> bool {
    let Some((lo, hi)) = outline.bbox() else {
        return false;
    };
    let (sz0, sz1) = (seg.from.z.min(seg.to.z), seg.from.z.max(seg.to.z));
    let (sr0, sr1) = (seg.from.r.min(seg.to.r), seg.from.r.max(seg.to.r));
    // arcs may bulge beyond their end points by up to their radius
    let bulge = seg.arc.map_or(0.0, |a| a.center.dist(seg.from));
    // (a sweep reaching below the axis is folded: only its Z range is known beforehand)
    let folded = sr0 + lo[1] - bulge < 0.0;
    !(sz1 + hi[0] + bulge < bb.min.z
        || sz0 + lo[0] - bulge > bb.max.z
        || (!folded && (sr1 + hi[1] + bulge < bb.min.r || sr0 + lo[1] - bulge > bb.max.r)))
}

/// The tool sweep of `seg` folded into the section, as convex counter-clockwise parts (one
/// per chord and outline part, each folded in up to two).
fn sweep_parts(seg: &Segment, outline: &Outline, chord_tol: f64) -> Vec<Vec<P>> {
    let path = seg.polyline(chord_tol);
    let mut sweep = vec![];
    for w in path.windows(2) {
        let d = [w[1].z - w[0].z, w[1].r - w[0].r];
        for part in &outline.parts {
            let at: Vec<P> = part
                .iter()
                .map(|p| [p[0] + w[0].z, p[1] + w[0].r])
                .collect();
            let ring = if d[0] == 0.0 && d[1] == 0.0 {
                convex_hull(&at)
            } else {
                sweep_convex(&at, d)
            };
            sweep.extend(crate::section::fold(&ring));
        }
    }
    sweep
}

/// Whether the union of the convex `sweep` parts overlaps `region` (box `bb`) by more than
/// 10⁻⁹ mm². Exact shortcuts first (a G73 of many passes asks this for every pass and gouge,
/// a holder that rubs for every move): a part whose box misses the region's adds nothing;
/// a part holding every vertex of the region holds all of it. Then each part's overlap is
/// measured by clipping the region's rings to it: one over the threshold decides, and when
/// even their sum is under it the union's is too. Only the rare case between asks the
/// boolean of the union.
fn overlaps(region: &Shape, bb: &Rect, sweep: &[Vec<P>]) -> bool {
    const SLIVER: f64 = 1e-9;
    let near: Vec<&Vec<P>> = sweep
        .iter()
        .filter(|s| Rect::of(pts(s)).intersects(bb))
        .collect();
    if near.is_empty() {
        return false;
    }
    if near.iter().any(|s| holds_all(s, &region.outer)) {
        return area(std::slice::from_ref(region)) > SLIVER;
    }
    let sign = ring::signed_area(&pts(&region.outer)).signum();
    let mut sum = 0.0;
    for s in &near {
        let a: f64 = std::iter::once(&region.outer)
            .chain(&region.holes)
            .map(|r| sign * ring::signed_area(&pts(&clip_to_hull(r, s))))
            .sum();
        if a > SLIVER {
            return true;
        }
        sum += a.max(0.0);
    }
    if sum <= SLIVER {
        return false;
    }
    let union: Vec<Shape> = near
        .into_iter()
        .map(|outer| Shape {
            outer: outer.clone(),
            holes: vec![],
        })
        .collect();
    area(&boolean(
        &union,
        std::slice::from_ref(region),
        BoolOp::Intersection,
    )) > SLIVER
}

/// Whether the convex ring `hull` (either orientation) holds every point of `ring`, its
/// boundary included.
fn holds_all(hull: &[P], ring: &[P]) -> bool {
    let n = hull.len();
    if n < 3 {
        return false;
    }
    let sign = ring::signed_area(&pts(hull)).signum();
    if sign == 0.0 {
        return false;
    }
    ring.iter().all(|p| {
        (0..n).all(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            let cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
            cross * sign >= 0.0
        })
    })
}

/// Box of a ring as (least, greatest) corner.
fn bbox(ring: &[P]) -> (P, P) {
    let r = Rect::of(pts(ring));
    (r.min.into(), r.max.into())
}

/// Outlines by (tool and hint key, mirrored).
type OutlineCache = Vec<(((u32, u8, u64), bool), Outline)>;

/// The outline that cuts `seg`, as the removal resolves it (tool number and hint; mirrored
/// about the axis when `flip`).
fn outline_cached(
    cache: &mut OutlineCache,
    tools: &ToolTable,
    seg: &Segment,
    flip: bool,
) -> Outline {
    let key = (crate::tools::hint_key(seg.tool, seg.hint), flip);
    if let Some((_, o)) = cache.iter().find(|(k, _)| *k == key) {
        return o.clone();
    }
    let o = tools.outline_for(seg.tool, seg.hint).0;
    let o = if flip { o.mirrored() } else { o };
    cache.push((key, o.clone()));
    o
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The deviation of `final_shapes` from `part` within one `zone`, at 0.01 mm, with no
    /// moves to blame.
    fn deviation_in(
        blank: &[Shape],
        final_shapes: &[Shape],
        part: Vec<Shape>,
        zone: Shape,
    ) -> Deviation {
        let intent = Intent {
            part,
            zone: vec![zone],
            outline: vec![],
            owner: None,
        };
        deviation(
            blank,
            final_shapes,
            &[intent],
            0.01,
            &[],
            &ToolTable::empty(),
            0.001,
        )
    }

    /// The clipping shortcut of [`overlaps`] against the boolean it replaces: a region with
    /// a hole (a 10 × 6 frame around a 6 × 2 hole) and convex parts slid across it on a
    /// grid, alone and in pairs, give the same answer.
    #[test]
    fn overlap_by_clipping_agrees_with_the_boolean() {
        let region = Shape {
            outer: vec![[0.0, 0.0], [10.0, 0.0], [10.0, 6.0], [0.0, 6.0]],
            holes: vec![vec![[2.0, 2.0], [2.0, 4.0], [8.0, 4.0], [8.0, 2.0]]],
        };
        let bb = Rect::of(pts(&region.outer));
        let tri = |z: f64, r: f64| vec![[z, r], [z + 1.5, r], [z + 0.5, r + 1.0]];
        let by_boolean = |parts: &[Vec<P>]| {
            let union: Vec<Shape> = parts
                .iter()
                .map(|o| Shape {
                    outer: o.clone(),
                    holes: vec![],
                })
                .collect();
            area(&boolean(
                &union,
                std::slice::from_ref(&region),
                BoolOp::Intersection,
            )) > 1e-9
        };
        let (mut hits, mut misses) = (0, 0);
        for i in -4..24 {
            for j in -4..14 {
                let (z, r) = (i as f64 * 0.5, j as f64 * 0.5);
                for parts in [vec![tri(z, r)], vec![tri(z, r), tri(z + 0.25, r - 0.75)]] {
                    let expect = by_boolean(&parts);
                    assert_eq!(overlaps(&region, &bb, &parts), expect, "at ({z}, {r})");
                    if expect {
                        hits += 1;
                    } else {
                        misses += 1;
                    }
                }
            }
        }
        // inside the hole, touching edges and far away all occur
        assert!(hits > 100 && misses > 100, "{hits} hits, {misses} misses");
    }

    /// A 1 mm wide step left 0.05 mm proud on a Φ30 shaft 200 mm long whose surface is
    /// everywhere else 0.0002 mm proud (chord-level noise): the two make one region of
    /// mean thickness 2·0.0898 / 400 ≈ 0.00045 mm, under the noise filter's tol / 10. The
    /// step is a real leftover and must be found; the sliver alone is not a finding.
    #[test]
    fn a_leftover_joined_to_a_long_sliver_is_still_found() {
        let blank = [rect(-200.0, 0.0, 0.0, 20.0)];
        let part = vec![rect(-200.0, 0.0, 0.0, 15.0)];
        let zone = rect(-200.0, 0.0, 0.0, 30.0);
        let sliver = rect(-200.0, 0.0, 0.0, 15.0002);
        let step = rect(-101.0, -100.0, 0.0, 15.05);
        let final_shapes = boolean(&[sliver.clone(), step], &[], BoolOp::Union);
        let d = deviation_in(&blank, &final_shapes, part.clone(), zone.clone());
        assert_eq!(d.leftovers.len(), 1, "{d:?}");
        let l = &d.leftovers[0];
        assert!((l.depth - 0.05).abs() < 1e-6, "{l:?}");
        // (the booleans snap to a grid of ~5·10⁻⁸ mm over the 200 mm blank)
        assert!((l.area - (200.0 * 0.0002 + 0.0498)).abs() < 1e-4, "{l:?}");
        // the sliver alone
        let d = deviation_in(&blank, &[sliver], part, zone);
        assert!(d.leftovers.is_empty() && d.gouges.is_empty(), "{d:?}");
    }

    #[test]
    fn gouge_and_leftover_with_depth() {
        let blank = [rect(-50.0, 0.0, 0.0, 20.0)];
        // intended: Φ30 (r 15) from Z0 to Z-20; the part: r 14.5 (0.5 deep gouge) from Z0 to
        // Z-10 and r 16 (1 mm leftover) from Z-10 to Z-20
        let part = [rect(-50.0, -20.0, 0.0, 20.0), rect(-20.0, 0.0, 0.0, 15.0)];
        let part = boolean(&part, &[], BoolOp::Union);
        let final_shapes = boolean(
            &[
                rect(-50.0, -20.0, 0.0, 20.0),
                rect(-10.0, 0.0, 0.0, 14.5),
                rect(-20.0, -10.0, 0.0, 16.0),
            ],
            &[],
            BoolOp::Union,
        );
        let zone = rect(-30.0, 10.0, 0.0, 30.0);
        let d = deviation_in(&blank, &final_shapes, part, zone);
        assert_eq!(d.gouges.len(), 1);
        assert_eq!(d.leftovers.len(), 1);
        assert!(
            (d.gouges[0].area - 5.0).abs() < 1e-6 && (d.gouges[0].depth - 0.5).abs() < 1e-6,
            "{:?}",
            d.gouges[0]
        );
        assert!(
            (d.leftovers[0].area - 10.0).abs() < 1e-6 && (d.leftovers[0].depth - 1.0).abs() < 1e-6
        );
        assert!((d.max_overcut() - 0.5).abs() < 1e-6 && (d.undercut_area() - 10.0).abs() < 1e-6);
    }

    #[test]
    fn groove_intent_wants_the_ring_gone_and_the_rest_kept() {
        let ring = [[-10.0, 20.0], [-10.0, 15.0], [-6.0, 15.0], [-6.0, 20.0]];
        let i = Intent::groove(&ring);
        // the zone grows 5 mm along Z both sides and 5 mm down: 14 × 10 box minus the 4 × 5 groove
        assert!(
            (area(&i.part) - (14.0 * 10.0 - 20.0)).abs() < 1e-9,
            "{}",
            area(&i.part)
        );
        let ring = [[-10.0, 20.0], [-8.0, 15.0], [-6.0, 15.0], [-4.0, 20.0]];
        let i = Intent::groove(&ring);
        assert!(
            (area(&i.part) - (16.0 * 10.0 - 20.0)).abs() < 1e-9,
            "{}",
            area(&i.part)
        );
    }

    #[test]
    fn finishing_shape_sides() {
        // OD: A above; the part is below the shape within its Z span
        let blank = [rect(-50.0, 0.0, 0.0, 25.0)];
        let od = Intent::finishing(
            &[[5.0, 30.0], [0.0, 10.0], [-10.0, 10.0], [-10.0, 20.0]],
            &blank,
        )
        .unwrap();
        let kept = boolean(&blank, &od.part, BoolOp::Intersection);
        let kept = boolean(&kept, &od.zone, BoolOp::Intersection);
        assert!((area(&kept) - 100.0).abs() < 1e-6, "{}", area(&kept));
        // ID: A below
        let id = Intent::finishing(&[[5.0, 5.0], [0.0, 12.0], [-10.0, 12.0]], &blank).unwrap();
        let kept = boolean(&blank, &id.part, BoolOp::Intersection);
        let kept = boolean(&kept, &id.zone, BoolOp::Intersection);
        assert!((area(&kept) - 130.0).abs() < 1e-6, "{}", area(&kept));
    }

    #[test]
    fn within_tolerance_and_outside_the_zone_is_not_a_finding() {
        let blank = [rect(-50.0, 0.0, 0.0, 20.0)];
        let part = vec![rect(-50.0, 0.0, 0.0, 15.0)];
        // 0.005 too deep everywhere, and a deep cut outside the zone
        let final_shapes = boolean(
            &[rect(-40.0, 0.0, 0.0, 14.995), rect(-50.0, -40.0, 0.0, 5.0)],
            &[],
            BoolOp::Union,
        );
        let zone = rect(-40.0, 0.0, 0.0, 30.0);
        let d = deviation_in(&blank, &final_shapes, part, zone);
        assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
    }

    fn zone_z(i: &Intent) -> (f64, f64) {
        let (lo, hi) = bbox(&i.zone[0].outer);
        (lo[0], hi[0])
    }

    /// Z spans equal to the overlay's grid (the contact points come out of a boolean).
    fn assert_span(got: (f64, f64), want: (f64, f64)) {
        assert!(
            (got.0 - want.0).abs() < 1e-6 && (got.1 - want.1).abs() < 1e-6,
            "{got:?} vs {want:?}"
        );
    }

    /// Issue 13 item 3: `N10 G00 X20` at Z2, `G01 Z0`, `Z-20`, `X30`, `Z-35`, `N20 X41` on a
    /// Φ40 blank whose face at Z1 was faced to Z0 before the cycle. The lead-in Z2 → Z0 runs
    /// in front of that stock: no part of the shape, which starts at Z0 (the profile's
    /// vertex). On the unfaced blank the lead-in runs through 1 mm of stock and claims it:
    /// facing it away afterwards is a gouge of 10 × 1 = 10 mm², 1 mm deep.
    #[test]
    fn a_lead_in_in_front_of_the_stock_is_no_part() {
        let path = [
            [2.0, 21.0],
            [2.0, 10.0],
            [0.0, 10.0],
            [-20.0, 10.0],
            [-20.0, 15.0],
            [-35.0, 15.0],
            [-35.0, 20.5],
        ];
        let blank = [rect(-60.0, 1.0, 0.0, 20.0)];
        let faced = [rect(-60.0, 0.0, 0.0, 20.0)];
        let finished = boolean(
            &[
                rect(-60.0, -35.0, 0.0, 20.0),
                rect(-35.0, -20.0, 0.0, 15.0),
                rect(-20.0, 0.0, 0.0, 10.0),
            ],
            &[],
            BoolOp::Union,
        );
        let run = |stock: &[Shape]| {
            let i = Intent::finishing(&path, stock).unwrap();
            let z = zone_z(&i);
            let d = deviation(
                &blank,
                &finished,
                &[i],
                0.01,
                &[],
                &ToolTable::empty(),
                0.001,
            );
            (z, d)
        };
        let (z, d) = run(&faced);
        assert_span(z, (-35.0, 0.0));
        assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
        let (z, d) = run(&blank);
        assert_span(z, (-35.0, 1.0));
        assert_eq!(d.gouges.len(), 1, "{d:?}");
        assert!((d.gouges[0].area - 10.0).abs() < 1e-6, "{:?}", d.gouges[0]);
        assert!((d.gouges[0].depth - 1.0).abs() < 1e-6, "{:?}", d.gouges[0]);
    }

    /// Item 3: a diameter reached straight from the approach (`G00 X20` at Z2, `G01 Z-20`)
    /// starts where the stock started (faced to Z0: no gouge in the faced slab); a retract
    /// off the last diameter (`X44 Z-36.5` from Φ30 at Z-35 on a Φ40 bar) is no part, so the
    /// corner it would cut off is no leftover.
    #[test]
    fn approach_and_retract_are_no_part() {
        let blank = [rect(-60.0, 1.0, 0.0, 20.0)];
        let faced = [rect(-60.0, 0.0, 0.0, 20.0)];
        let path = [
            [2.0, 23.0],
            [2.0, 10.0],
            [-20.0, 10.0],
            [-20.0, 15.0],
            [-35.0, 15.0],
            [-36.5, 22.0],
        ];
        let i = Intent::finishing(&path, &faced).unwrap();
        assert_span(zone_z(&i), (-35.0, 0.0));
        let finished = boolean(
            &[
                rect(-60.0, -35.0, 0.0, 20.0),
                rect(-35.0, -20.0, 0.0, 15.0),
                rect(-20.0, 0.0, 0.0, 10.0),
            ],
            &[],
            BoolOp::Union,
        );
        let d = deviation(
            &blank,
            &finished,
            &[i],
            0.01,
            &[],
            &ToolTable::empty(),
            0.001,
        );
        assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
        // on the unfaced blank the Φ20 diameter starts at the blank's face Z1
        let i = Intent::finishing(&path, &blank).unwrap();
        assert_span(zone_z(&i), (-35.0, 1.0));
        // a face gouged 1 mm too deep before a shape that marks its face (`G01 Z0`, `Z-20`)
        // is still found: the lead-in is dropped, the profile keeps its vertex at Z0
        let deep = [rect(-60.0, -1.0, 0.0, 20.0)];
        let marked = [
            [2.0, 21.0],
            [2.0, 10.0],
            [0.0, 10.0],
            [-20.0, 10.0],
            [-20.0, 15.0],
        ];
        let i = Intent::finishing(&marked, &deep).unwrap();
        assert_span(zone_z(&i), (-20.0, 0.0));
    }

    /// A back chamfer cut toward +Z under G41 along the chamfer's own line, coming in over a
    /// neck cut before (Φ60 flange Z0..−10, Φ40 neck behind): the path r = z + 39 from
    /// Z−12 to Z−7 touches the flange only from (−10, 29) to (−9, 30); the lead-in over the
    /// neck and the run-out above the flange are no part, so the neck is no gouge.
    #[test]
    fn a_lead_in_along_the_chamfer_line_is_no_part() {
        let stock = boolean(
            &[rect(-10.0, 0.0, 0.0, 30.0), rect(-60.0, -10.0, 0.0, 20.0)],
            &[],
            BoolOp::Union,
        );
        let i = Intent::compensated(&[[-12.0, 27.0], [-7.0, 32.0]], false, &stock).unwrap();
        assert_span(zone_z(&i), (-10.0, -9.0));
        let blank = [rect(-60.0, 0.0, 0.0, 30.0)];
        let finished = boolean(
            &[
                Shape {
                    outer: vec![
                        [-10.0, 0.0],
                        [0.0, 0.0],
                        [0.0, 30.0],
                        [-9.0, 30.0],
                        [-10.0, 29.0],
                    ],
                    holes: vec![],
                },
                rect(-60.0, -10.0, 0.0, 20.0),
            ],
            &[],
            BoolOp::Union,
        );
        let d = deviation(
            &blank,
            &finished,
            &[i],
            0.01,
            &[],
            &ToolTable::empty(),
            0.001,
        );
        assert!(d.gouges.is_empty() && d.leftovers.is_empty(), "{d:?}");
    }

    /// A chamfer under G42 from Z2 to Φ26 at Z−1, Z−2, then `X32.` off the Φ30 bar before the
    /// G40: the retract is no part, also in choosing the side (with it, the normals pointed
    /// toward −Z and the contour claimed Φ32 over the whole bar beyond Z−2).
    #[test]
    fn a_retract_off_the_last_diameter_does_not_turn_the_side() {
        let stock = boolean(
            &[rect(-90.0, 0.0, 0.0, 13.0), rect(-150.0, -90.0, 0.0, 15.0)],
            &[],
            BoolOp::Union,
        );
        let path = [[2.0, 10.0], [-1.0, 13.0], [-2.0, 13.0], [-2.0, 16.0]];
        let i = Intent::compensated(&path, true, &stock).unwrap();
        // OD: closed toward −r over the chamfer's Z span from the face
        assert_span(zone_z(&i), (-2.0, 0.0));
        let (lo, _) = bbox(&i.zone[0].outer);
        assert!(lo[1] < -1e4, "{:?}", i.zone);
    }

    /// A cut line from (−6, 10) to (0, 7) across the corner (0, 10) of a part [−10, 0] ×
    /// [0, 10]: the gouge is deepest where the corner's bisector meets the cut, (−2, 8), 2 mm
    /// from both edges; its vertices are on the part's edges and its cut edge's midpoint
    /// (−3, 8.5) is only 1.5 deep (what vertices and midpoints reported).
    #[test]
    fn a_gouge_is_as_deep_as_where_the_bisector_meets_the_cut() {
        let part = rect(-10.0, 0.0, 0.0, 10.0);
        let boundary = EdgeIndex::of_rings([pts(&part.outer)].iter().map(Vec::as_slice));
        let gouge = Shape {
            outer: vec![[-6.0, 10.0], [0.0, 7.0], [0.0, 10.0]],
            holes: vec![],
        };
        let (depth, at, _) = deepest(&gouge, &boundary, DEPTH_STEP);
        assert!((depth - 2.0).abs() < 1e-6, "{depth} at {at:?}");
        assert!(
            (at[0] + 2.0).abs() < 1e-5 && (at[1] - 8.0).abs() < 1e-5,
            "{at:?}"
        );
    }

    /// A sawtooth ring: teeth between r 12 and 14, `n` of them from Z0 to Z-20, on a body
    /// down to the axis.
    fn sawtooth(n: usize) -> Shape {
        let mut outer = vec![[-20.0, 0.0], [0.0, 0.0]];
        for k in 0..=2 * n {
            let z = -20.0 * k as f64 / (2 * n) as f64;
            outer.push([z, if k % 2 == 0 { 12.0 } else { 14.0 }]);
        }
        Shape {
            outer,
            holes: vec![],
        }
    }

    /// The comparison as it was before the intents were clipped to the blank's box (the
    /// world and the intents FAR away, so the grid is fitted to ±FAR).
    fn deviation_unclipped(blank: &[Shape], final_shapes: &[Shape], intent: &Intent) -> Deviation {
        let world = vec![rect(-FAR, FAR, -FAR, FAR)];
        let elsewhere = boolean(&world, &intent.zone, BoolOp::Difference);
        let keeps = boolean(&intent.part, &elsewhere, BoolOp::Union);
        let part = boolean(blank, &keeps, BoolOp::Intersection);
        let zone = boolean(&[], &intent.zone, BoolOp::Union);
        let should_stay = boolean(&part, &zone, BoolOp::Intersection);
        let final_zone = boolean(final_shapes, &zone, BoolOp::Intersection);
        let gone = boolean(&should_stay, final_shapes, BoolOp::Difference);
        let left = boolean(&final_zone, &part, BoolOp::Difference);
        Deviation {
            gouges: findings(gone, &part, 0.01),
            leftovers: findings(left, &part, 0.01),
            later_cuts: vec![],
        }
    }

    /// Issue 17: the intents are clipped to the blank's box before the booleans. On a
    /// sawtooth blank with a target Φ22 (r 11) OD part, closed far away, and a final part
    /// with a groove 0.5 mm into the target, gouge and leftovers are those of the unclipped
    /// comparison (to its coarser grid's precision).
    #[test]
    fn clipping_the_intents_to_the_blank_changes_no_finding() {
        let blank = vec![sawtooth(200)];
        let target = Intent::target(vec![rect(-FAR, FAR, 0.0, 11.0)]);
        let groove = rect(-12.0, -8.0, 10.5, 20.0);
        let final_shapes = boolean(&blank, &[groove], BoolOp::Difference);
        let new = deviation(
            &blank,
            &final_shapes,
            std::slice::from_ref(&target),
            0.01,
            &[],
            &ToolTable::empty(),
            0.001,
        );
        let old = deviation_unclipped(&blank, &final_shapes, &target);
        assert_eq!(new.gouges.len(), 1);
        assert_eq!(new.leftovers.len(), 2);
        assert_eq!(new.gouges.len(), old.gouges.len());
        assert_eq!(new.leftovers.len(), old.leftovers.len());
        // the gouge: 4 mm × 0.5 mm under the target surface
        assert!(
            (new.gouges[0].area - 2.0).abs() < 1e-6,
            "{:?}",
            new.gouges[0]
        );
        assert!((new.gouges[0].depth - 0.5).abs() < 1e-6);
        for (a, b) in new
            .gouges
            .iter()
            .chain(&new.leftovers)
            .zip(old.gouges.iter().chain(&old.leftovers))
        {
            assert!(
                (a.area - b.area).abs() < 1e-4 * b.area.max(1.0),
                "{} {}",
                a.area,
                b.area
            );
            assert!((a.depth - b.depth).abs() < 1e-3, "{} {}", a.depth, b.depth);
        }
        assert!((new.undercut_area() - old.undercut_area()).abs() < 1e-3);
    }

    /// The box clip keeps a concave ring's area inside the box (a ring leaving and
    /// re-entering the box is bridged along the box's side, enclosing nothing).
    #[test]
    fn box_clip_of_a_concave_ring_is_the_intersection() {
        let u = Shape {
            outer: vec![
                [0.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [7.0, 10.0],
                [7.0, 3.0],
                [3.0, 3.0],
                [3.0, 10.0],
                [0.0, 10.0],
            ],
            holes: vec![],
        };
        let bx = Rect::new(geom::Pt::new(-1.0, 5.0), geom::Pt::new(11.0, 20.0));
        let clipped = clip_to_box(std::slice::from_ref(&u), &bx);
        let exact = boolean(
            std::slice::from_ref(&u),
            &[rect(-1.0, 11.0, 5.0, 20.0)],
            BoolOp::Intersection,
        );
        let norm = boolean(&clipped, &[], BoolOp::Union);
        assert!((area(&norm) - 30.0).abs() < 1e-9, "{}", area(&norm));
        assert!((area(&exact) - 30.0).abs() < 1e-9);
        assert_eq!(norm.len(), 2, "two legs: {norm:?}");
    }
}
