//! The single integration point with `i_overlay`: every boolean operation of the crate goes
//! through here, so the rest of the code speaks only [`Shape`] and these integer aliases.
//!
//! Removal runs in `i_overlay`'s integer core on ONE fixed grid (a `FloatPointAdapter`
//! built once over the machine envelope): the stock is converted to integers once, every
//! boolean call works on exact integer points, and nothing is re-snapped between calls, so
//! the stock cannot drift however many operations it goes through.

use crate::geom::P;
use crate::Shape;
use geom::Rect;
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay::{Overlay, ShapeType};
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::core::solver::Solver;
use i_overlay::float::overlay::FloatOverlay;
use i_overlay::i_float::adapter::FloatPointAdapter;
use i_overlay::i_float::float::rect::FloatRect;
use i_overlay::i_float::int::point::IntPoint;

/// A grid point.
pub(crate) type IPt = IntPoint<i32>;
/// A shape on the grid: outer ring first (counter-clockwise), then its holes (clockwise).
pub(crate) type IShape = Vec<Vec<IPt>>;
/// Several shapes on the grid.
pub(crate) type IShapes = Vec<IShape>;

/// The fixed snapping grid of one run.
pub(crate) struct Grid {
    adapter: FloatPointAdapter<[f64; 2], i32>,
    rect: Rect,
}

impl Grid {
    /// A grid covering `rect` (finite, non-empty) with the conservative 29-bit budget.
    pub(crate) fn new(rect: Rect) -> Self {
        let fr = FloatRect {
            min_x: rect.min.z,
            max_x: rect.max.z,
            min_y: rect.min.r,
            max_y: rect.max.r,
        };
        Self {
            adapter: FloatPointAdapter::new_conservative(fr),
            rect,
        }
    }

    /// Size of one grid step in mm.
    pub(crate) fn step(&self) -> f64 {
        self.adapter.inv_scale()
    }

    /// Snaps a point (clamped into the grid's rectangle first, so it can never overflow).
    pub(crate) fn to_int(&self, p: P) -> IPt {
        let q = [
            p[0].clamp(self.rect.min.z, self.rect.max.z),
            p[1].clamp(self.rect.min.r, self.rect.max.r),
        ];
        let q = if q[0].is_nan() || q[1].is_nan() {
            self.rect.min.to_array()
        } else {
            q
        };
        self.adapter.float_to_int(&q)
    }

    /// The grid box of the corners of `rect` (each snapped like [`Grid::to_int`]).
    pub(crate) fn box_to_int(&self, rect: &Rect) -> IBox {
        let (lo, hi) = (self.to_int(rect.min.into()), self.to_int(rect.max.into()));
        IBox {
            min: [lo.x, lo.y],
            max: [hi.x, hi.y],
        }
    }

    /// Back to mm.
    pub(crate) fn to_float(&self, p: IPt) -> P {
        self.adapter.int_to_float(&p)
    }

    /// Shapes onto the grid.
    pub(crate) fn shapes_to_int(&self, shapes: &[Shape]) -> IShapes {
        shapes
            .iter()
            .map(|s| {
                std::iter::once(&s.outer)
                    .chain(s.holes.iter())
                    .map(|r| r.iter().map(|&p| self.to_int(p)).collect())
                    .collect()
            })
            .collect()
    }

    /// Shapes back to mm.
    pub(crate) fn shapes_to_float(&self, shapes: &IShapes) -> Vec<Shape> {
        shapes
            .iter()
            .filter(|s| !s.is_empty())
            .map(|s| {
                let mut rings = s
                    .iter()
                    .map(|r| r.iter().map(|&p| self.to_float(p)).collect::<Vec<P>>());
                let outer = rings.next().unwrap_or_default();
                Shape {
                    outer,
                    holes: rings.collect(),
                }
            })
            .collect()
    }

    /// Area in mm² of shapes on the grid (exact integer shoelace, then scaled).
    pub(crate) fn area(&self, shapes: &IShapes) -> f64 {
        let s = self.step();
        shapes
            .iter()
            .flatten()
            .map(|r| ring_area2(r) as f64)
            .sum::<f64>()
            * 0.5
            * s
            * s
    }
}

/// An integer bounding box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct IBox {
    pub(crate) min: [i32; 2],
    pub(crate) max: [i32; 2],
}

impl IBox {
    /// Contains nothing.
    pub(crate) const EMPTY: Self = Self {
        min: [i32::MAX; 2],
        max: [i32::MIN; 2],
    };

    /// Grows the box to contain `p`.
    pub(crate) fn add(&mut self, p: IPt) {
        self.min = [self.min[0].min(p.x), self.min[1].min(p.y)];
        self.max = [self.max[0].max(p.x), self.max[1].max(p.y)];
    }

    /// The box of some points (EMPTY for none).
    pub(crate) fn of(points: impl IntoIterator<Item = IPt>) -> Self {
        let mut b = Self::EMPTY;
        for p in points {
            b.add(p);
        }
        b
    }

    /// Box of the segment `[a, b]`.
    pub(crate) fn of_segment(a: IPt, b: IPt) -> Self {
        Self {
            min: [a.x.min(b.x), a.y.min(b.y)],
            max: [a.x.max(b.x), a.y.max(b.y)],
        }
    }

    /// The four corners, counter-clockwise from the lower left.
    pub(crate) fn corners(&self) -> [IPt; 4] {
        [
            IPt::new(self.min[0], self.min[1]),
            IPt::new(self.max[0], self.min[1]),
            IPt::new(self.max[0], self.max[1]),
            IPt::new(self.min[0], self.max[1]),
        ]
    }

    /// True when the boxes share at least a point.
    pub(crate) fn overlaps(&self, o: &Self) -> bool {
        self.min[0] <= o.max[0]
            && o.min[0] <= self.max[0]
            && self.min[1] <= o.max[1]
            && o.min[1] <= self.max[1]
    }
}

/// Twice the signed area of a grid ring, exact. This stays next to `i_overlay` rather than
/// in the `geom` kernel: it is exact integer (i128) arithmetic on the grid, which a float
/// area would round.
pub(crate) fn ring_area2(r: &[IPt]) -> i128 {
    let n = r.len();
    (0..n)
        .map(|i| {
            let (a, b) = (r[i], r[(i + 1) % n]);
            i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y)
        })
        .sum()
}

/// Perimeter of a grid ring in grid steps.
pub(crate) fn ring_perimeter(ring: &[IPt]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|k| {
            let (p, q) = (ring[k], ring[(k + 1) % n]);
            f64::from(q.x - p.x).hypot(f64::from(q.y - p.y))
        })
        .sum()
}

/// Exact orientation of `c` against the directed line `a → b`: 1 left, -1 right, 0 on it.
/// Differences are taken in i64 and products in i128: a tile box may reach the ends of the
/// i32 grid (an OD threading insert's body swept across a bore overflowed the i32 difference).
pub(crate) fn orient(a: IPt, b: IPt, c: IPt) -> i64 {
    let d = |p: i32, q: i32| i128::from(i64::from(p) - i64::from(q));
    let v = d(b.x, a.x) * d(c.y, a.y) - d(b.y, a.y) * d(c.x, a.x);
    v.signum() as i64
}

/// True when every point of `inner` is inside or on the convex counter-clockwise `outer`.
pub(crate) fn convex_contains(outer: &[IPt], inner: &[IPt]) -> bool {
    let n = outer.len();
    n >= 3
        && (0..n).all(|i| {
            let (a, b) = (outer[i], outer[(i + 1) % n]);
            let (ex, ey) = (i64::from(b.x - a.x), i64::from(b.y - a.y));
            inner
                .iter()
                .all(|p| ex * i64::from(p.y - a.y) - ey * i64::from(p.x - a.x) >= 0)
        })
}

/// Closed segments [a, b] and [c, d] share a point.
pub(crate) fn segments_meet(a: IPt, b: IPt, c: IPt, d: IPt) -> bool {
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    if o1 * o2 > 0 {
        // [c, d] lies strictly on one side of the line through a and b (the usual case for
        // a box overlap: half the orientation tests)
        return false;
    }
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    let on = |p: IPt, q: IPt, r: IPt| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    (o1 == 0 && on(a, b, c))
        || (o2 == 0 && on(a, b, d))
        || (o3 == 0 && on(c, d, a))
        || (o4 == 0 && on(c, d, b))
}

/// Even-odd test of a grid point against a grid ring, exact.
pub(crate) fn point_in_ring(p: IPt, ring: &[IPt]) -> bool {
    let n = ring.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            // x of the crossing, compared without division
            let lhs = i128::from(p.x - a.x) * i128::from(b.y - a.y);
            let rhs = i128::from(p.y - a.y) * i128::from(b.x - a.x);
            if (b.y > a.y && lhs < rhs) || (b.y < a.y && lhs > rhs) {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether `p` has a non-zero winding number around `ring` (any ring, self-crossing too;
/// exact). Points on the ring may go either way.
pub(crate) fn winds(p: IPt, ring: &[IPt]) -> bool {
    let n = ring.len();
    (0..n)
        .map(|i| winding_step(p, ring[i], ring[(i + 1) % n]))
        .sum::<i32>()
        != 0
}

/// What the edge `a → b` adds to the winding number of `p`: +1 crossing upward with `p` on
/// its left, −1 downward with `p` on its right, else 0 (exact, in i128).
pub(crate) fn winding_step(p: IPt, a: IPt, b: IPt) -> i32 {
    let d = |u: i32, v: i32| i128::from(i64::from(u) - i64::from(v));
    let side = || d(b.x, a.x) * d(p.y, a.y) - d(p.x, a.x) * d(b.y, a.y);
    if a.y <= p.y {
        i32::from(b.y > p.y && side() > 0)
    } else {
        -i32::from(b.y <= p.y && side() < 0)
    }
}

/// A reusable boolean engine (keeps its buffers between calls).
pub(crate) struct Engine {
    ov: Overlay<i32>,
    /// For calls of [`FRAG_FROM`] points or more: `i_overlay`'s fragment splitter.
    frag: Overlay<i32>,
}

/// Calls with at least this many points use the fragment splitter. `i_overlay`'s automatic
/// choice splits edges pair by pair (its list solver) below 2 000 edges; when a batch's
/// sweeps run nearly along the stock's edges (a 665-pass G73 over an R6 arc, passes
/// 0.009 mm apart, an insert in a PCLNR holder: 1 332 moves) that took 2.2 s in release,
/// the fragment splitter 0.38 s. Measured neutral elsewhere (stock bench at 10⁴ and 10⁵,
/// the 10⁵ zig-zag, O0006 r9999; same results bit for bit); 200 points was slower on the
/// zig-zag, 1 500 kept half the gain. From 2 000 to 32 000 edges the automatic choice is
/// its tree splitter, which took 513 ms to join the 274 tiles (20 691 points) of a
/// 2·10⁴-move cutting zig-zag; the fragment splitter 8 ms. Hence every call, the unions
/// and the float booleans of the measures included, chooses by [`solver_for`].
const FRAG_FROM: usize = 600;

/// The edge splitter for a call of `points` points (see [`FRAG_FROM`]). The fragment
/// solver also fills without the list strategy the automatic one uses below 8 000 segments;
/// both are exact integer arithmetic, the results the same.
fn solver_for(points: usize) -> Solver {
    if points >= FRAG_FROM {
        Solver::FRAG
    } else {
        Solver::AUTO
    }
}

impl Engine {
    /// A fresh engine.
    pub(crate) fn new() -> Self {
        Self {
            ov: Overlay::new(256),
            frag: Overlay::new_custom(256, Default::default(), Solver::FRAG),
        }
    }

    fn run<'a>(
        &mut self,
        subj: &IShapes,
        clips: impl IntoIterator<Item = &'a [IPt]>,
        rule: OverlayRule,
    ) -> IShapes {
        let clips: Vec<&[IPt]> = clips.into_iter().collect();
        let points = subj.iter().flatten().map(Vec::len).sum::<usize>()
            + clips.iter().map(|c| c.len()).sum::<usize>();
        let ov = self.overlay_for(points);
        ov.clear();
        ov.add_source(subj, ShapeType::Subject);
        for c in clips {
            ov.add_contour(c, ShapeType::Clip);
        }
        ov.overlay(rule, FillRule::NonZero)
    }

    /// `subj` minus the union of the `clips` rings (any orientation, overlapping allowed).
    pub(crate) fn difference<'a>(
        &mut self,
        subj: &IShapes,
        clips: impl IntoIterator<Item = &'a [IPt]>,
    ) -> IShapes {
        self.run(subj, clips, OverlayRule::Difference)
    }

    /// `subj` intersected with the union of the `clips` rings.
    pub(crate) fn intersection<'a>(
        &mut self,
        subj: &IShapes,
        clips: impl IntoIterator<Item = &'a [IPt]>,
    ) -> IShapes {
        self.run(subj, clips, OverlayRule::Intersect)
    }

    /// Union of several shape sets (shared edges between neighbours dissolve).
    pub(crate) fn union(&mut self, parts: &[IShapes]) -> IShapes {
        let points = parts.iter().flatten().flatten().map(Vec::len).sum();
        let ov = self.overlay_for(points);
        ov.clear();
        for p in parts {
            ov.add_source(p, ShapeType::Subject);
        }
        ov.overlay(OverlayRule::Subject, FillRule::NonZero)
    }

    /// The overlay (and so the splitter) for a call of `points` points.
    fn overlay_for(&mut self, points: usize) -> &mut Overlay<i32> {
        if points >= FRAG_FROM {
            &mut self.frag
        } else {
            &mut self.ov
        }
    }
}

/// Rings with a non-finite point are dropped: the float adapter cannot place them.
fn finite_shapes(shapes: &[Shape]) -> Vec<Vec<Vec<P>>> {
    let ok = |r: &Vec<P>| r.len() >= 3 && r.iter().all(|p| p[0].is_finite() && p[1].is_finite());
    shapes
        .iter()
        .filter(|s| ok(&s.outer))
        .map(|s| {
            std::iter::once(&s.outer)
                .chain(s.holes.iter().filter(|h| ok(h)))
                .cloned()
                .collect()
        })
        .collect()
}

fn to_shapes(raw: Vec<Vec<Vec<P>>>) -> Vec<Shape> {
    raw.into_iter()
        .filter(|s| !s.is_empty())
        .map(|mut s| {
            let outer = s.remove(0);
            Shape { outer, holes: s }
        })
        .collect()
}

/// Normalises rings of any orientation (non-zero fill) into valid shapes: outer CCW, holes CW.
pub(crate) fn clean(rings: &[Vec<P>]) -> Vec<Shape> {
    let rings: Vec<Vec<P>> = rings
        .iter()
        .filter(|r| r.len() >= 3 && r.iter().all(|p| p[0].is_finite() && p[1].is_finite()))
        .cloned()
        .collect();
    if rings.is_empty() {
        return Vec::new();
    }
    let solver = solver_for(rings.iter().map(Vec::len).sum());
    to_shapes(
        FloatOverlay::with_subj_custom(&rings, Default::default(), solver)
            .overlay(OverlayRule::Subject, FillRule::NonZero),
    )
}

/// Float boolean between two shape sets on a grid fitted to both (for measures).
pub(crate) fn boolean(a: &[Shape], b: &[Shape], rule: BoolOp) -> Vec<Shape> {
    let (a, b) = (finite_shapes(a), finite_shapes(b));
    if a.is_empty() && b.is_empty() {
        return Vec::new();
    }
    let rule = match rule {
        BoolOp::Xor => OverlayRule::Xor,
        BoolOp::Difference => OverlayRule::Difference,
        BoolOp::Intersection => OverlayRule::Intersect,
        BoolOp::Union => OverlayRule::Union,
    };
    let points = [&a, &b].into_iter().flatten().flatten().map(Vec::len).sum();
    to_shapes(
        FloatOverlay::with_subj_and_clip_custom(&a, &b, Default::default(), solver_for(points))
            .overlay(rule, FillRule::NonZero),
    )
}

/// The boolean operations offered on float shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BoolOp {
    /// a ∪ b
    Union,
    /// a ∩ b
    Intersection,
    /// a − b
    Difference,
    /// (a − b) ∪ (b − a)
    Xor,
}
