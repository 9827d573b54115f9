//! The single integration point with `i_overlay`: every boolean operation of the crate goes
//! through here, so the rest of the code speaks only [`Shape`] and these integer aliases.
//!
//! Removal runs in `i_overlay`'s integer core on ONE fixed grid (a `FloatPointAdapter`
//! built once over the machine envelope): the stock is converted to integers once, every
//! boolean call works on exact integer points, and nothing is re-snapped between calls, so
//! the stock cannot drift however many operations it goes through.

use crate::Shape;
use geom::flat::P;
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

    /// True when the box holds no point.
    pub(crate) fn is_empty(&self) -> bool {
        self.min[0] > self.max[0] || self.min[1] > self.max[1]
    }

    /// True when the boxes share at least a point.
    pub(crate) fn overlaps(&self, o: &Self) -> bool {
        self.min[0] <= o.max[0]
            && o.min[0] <= self.max[0]
            && self.min[1] <= o.max[1]
            && o.min[1] <= self.max[1]
    }

    /// The box of some shapes' outer rings (EMPTY for none).
    pub(crate) fn of_shapes(shapes: &IShapes) -> Self {
        Self::of(shapes.iter().filter_map(|s| s.first()).flatten().copied())
    }

    /// `self ∩ b` (empty when they miss each other: min above max).
    pub(crate) fn intersection(&self, b: &Self) -> Self {
        Self {
            min: [self.min[0].max(b.min[0]), self.min[1].max(b.min[1])],
            max: [self.max[0].min(b.max[0]), self.max[1].min(b.max[1])],
        }
    }

    /// True when this box contains `inner`.
    pub(crate) fn contains(&self, inner: &Self) -> bool {
        self.min[0] <= inner.min[0]
            && self.min[1] <= inner.min[1]
            && self.max[0] >= inner.max[0]
            && self.max[1] >= inner.max[1]
    }

    /// A box that holds this one less the box `core` (this box itself unless `core` spans
    /// it across one axis and reaches past one end along the other).
    pub(crate) fn outside(self, core: &Self) -> Self {
        let b = self;
        let mut out = b;
        for axis in 0..2 {
            let other = 1 - axis;
            if core.is_empty() || core.min[other] > b.min[other] || core.max[other] < b.max[other] {
                continue;
            }
            if core.max[axis] >= b.max[axis] {
                out.max[axis] = out.max[axis].min(core.min[axis].max(b.min[axis]));
            }
            if core.min[axis] <= b.min[axis] {
                out.min[axis] = out.min[axis].max(core.max[axis].min(b.max[axis]));
            }
        }
        out
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

/// True when `c` lies strictly right of the directed line `p → q`, exactly: the
/// determinant in f64 (differences of i32 are exact, the products round by at most
/// 2⁻⁵³ of their size), the exact [`orient`] only when it is too close to zero to tell.
pub(crate) fn right_of(p: IPt, q: IPt, c: IPt) -> bool {
    let d = |a: i32, b: i32| f64::from(a) - f64::from(b);
    let (l, r) = (d(q.x, p.x) * d(c.y, p.y), d(q.y, p.y) * d(c.x, p.x));
    let det = l - r;
    let bound = (l.abs() + r.abs()) * 1e-15;
    if det < -bound {
        true
    } else if det > bound {
        false
    } else {
        orient(p, q, c) < 0
    }
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

/// A large axis-aligned box inside the convex counter-clockwise `poly` (EMPTY when none was
/// found): a box that meets it meets the polygon, with no edge to test. The largest of the
/// boxes spanned by two of four horizontal chords (at the bottom, a third and two thirds
/// up, and the top; by convexity the polygon holds the hull of two chords, so the overlap
/// of their Z ranges between their heights), shrunk by a grid step, and kept only when its
/// corners pass the exact test of every edge (which a polygon that snapping left a little
/// reflex may fail). One pass over the edges: it is built for most sweep polygons.
pub(crate) fn inscribed_box(poly: &[IPt]) -> IBox {
    const LEVELS: usize = 4;
    let n = poly.len();
    let b = IBox::of(poly.iter().copied());
    if n < 3 || b.max[1] - b.min[1] < 4 || b.max[0] - b.min[0] < 4 {
        return IBox::EMPTY;
    }
    let (lo, hi) = (f64::from(b.min[1]), f64::from(b.max[1]));
    let ys: [f64; LEVELS] =
        std::array::from_fn(|k| (lo + (hi - lo) * k as f64 / (LEVELS - 1) as f64).round());
    // the chord at each height: the least and largest x of the polygon there
    let mut chords = [(f64::INFINITY, f64::NEG_INFINITY); LEVELS];
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        let (py, qy) = (f64::from(p.y), f64::from(q.y));
        let (px, qx) = (f64::from(p.x), f64::from(q.x));
        for (&y, c) in ys.iter().zip(chords.iter_mut()) {
            if (py - y) * (qy - y) > 0.0 {
                continue;
            }
            let (l, r) = if py == qy {
                (px.min(qx), px.max(qx))
            } else {
                let x = px + (y - py) * (qx - px) / (qy - py);
                (x, x)
            };
            *c = (c.0.min(l), c.1.max(r));
        }
    }
    let mut best = (0.0, IBox::EMPTY);
    for i in 0..LEVELS {
        for j in i + 1..LEVELS {
            // shrunk a step from every side (the chords are rounded)
            let x0 = chords[i].0.max(chords[j].0).ceil() + 1.0;
            let x1 = chords[i].1.min(chords[j].1).floor() - 1.0;
            let (y0, y1) = (ys[i] + 1.0, ys[j] - 1.0);
            let area = (x1 - x0) * (y1 - y0);
            if x1 > x0 && y1 > y0 && area > best.0 {
                let c = IBox {
                    min: [x0 as i32, y0 as i32],
                    max: [x1 as i32, y1 as i32],
                };
                best = (area, c);
            }
        }
    }
    if best.1.is_empty() || !convex_contains(poly, &best.1.corners()) {
        return IBox::EMPTY;
    }
    best.1
}

/// True when the part of the polygon `inner` inside the box `b` lies inside or on the
/// convex counter-clockwise `outer` (closed sets; either may reach outside `b`). Exact: the
/// corners of the hull of `inner ∩ b` are among `inner`'s vertices in `b`, `b`'s corners
/// inside `inner`, and the points where `inner`'s edges cross `b`'s sides (rational: tested
/// with the denominator multiplied out, in i128); a point passes when it lies on or left of
/// every edge of `outer`, and the points that do make a convex set inside `outer` (all of
/// it when `outer` is convex; its kernel when grid snapping left it a little reflex).
pub(crate) fn convex_covers_in_box(outer: &[IPt], inner: &[IPt], b: &IBox) -> bool {
    if outer.len() < 3 {
        return false;
    }
    let w = |v: i32| i128::from(v);
    // `(x, y)` = `(xn / d, yn / d)` with `d > 0` inside or on `outer`
    let holds = |xn: i128, yn: i128, d: i128| {
        (0..outer.len()).all(|i| {
            let (a, e) = (outer[i], outer[(i + 1) % outer.len()]);
            let (ex, ey) = (w(e.x) - w(a.x), w(e.y) - w(a.y));
            ex * (yn - w(a.y) * d) - ey * (xn - w(a.x) * d) >= 0
        })
    };
    let in_box = |p: IPt| p.x >= b.min[0] && p.x <= b.max[0] && p.y >= b.min[1] && p.y <= b.max[1];
    if inner
        .iter()
        .any(|&p| in_box(p) && !holds(w(p.x), w(p.y), 1))
    {
        return false;
    }
    if inner.len() >= 3
        && b.corners()
            .iter()
            .any(|&c| point_in_ring(c, inner) && !holds(w(c.x), w(c.y), 1))
    {
        return false;
    }
    // the crossings of each edge with the lines of the box's sides, where they lie on a side
    (0..inner.len()).all(|i| {
        let (p, q) = (inner[i], inner[(i + 1) % inner.len()]);
        // axis 0: the sides x = const, the crossing's y from the edge; axis 1 the other way
        [0usize, 1].iter().all(|&axis| {
            let (pa, qa) = if axis == 0 { (p.x, q.x) } else { (p.y, q.y) };
            let (po, qo) = if axis == 0 { (p.y, q.y) } else { (p.x, q.x) };
            let d = w(qa) - w(pa);
            [b.min[axis], b.max[axis]].iter().all(|&line| {
                if d == 0 || line < pa.min(qa) || line > pa.max(qa) {
                    return true;
                }
                // the other coordinate: po + (qo - po)(line - pa) / d, over a positive d
                let (num, den) = ((w(qo) - w(po)) * (w(line) - w(pa)), d);
                let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
                let other = w(po) * den + num;
                let (lo, hi) = (w(b.min[1 - axis]) * den, w(b.max[1 - axis]) * den);
                if other < lo || other > hi {
                    return true;
                }
                let line = w(line) * den;
                if axis == 0 {
                    holds(line, other, den)
                } else {
                    holds(other, line, den)
                }
            })
        })
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

/// Drops the vertices of `shapes` that lie within `tol` grid steps of the segment between
/// their neighbours (projecting inside it) when no other vertex lies in the triangle they
/// make with them: the kinks grid rounding leaves where the edges of many passes run along
/// one line (a G76's flank infeed puts every pass's tip on the thread's leading flank: an
/// 891-pass thread kept 21 735 such vertices, and every pass's boolean call met them all).
/// A ring keeps at least three vertices. No edge can cross a triangle that holds no vertex
/// (the rings do not cross each other), so the shapes stay valid; the region moves by at
/// most `tol` grid steps where a vertex went. Vertices on the sides of `frame` (a tile's
/// rectangle, where its neighbour's stock meets it) stay.
pub(crate) fn drop_grid_kinks(shapes: &mut IShapes, tol: i64, frame: &IBox) {
    let on_frame = |v: IPt| {
        v.x == frame.min[0] || v.x == frame.max[0] || v.y == frame.min[1] || v.y == frame.max[1]
    };
    let near_line = |a: IPt, v: IPt, c: IPt| {
        let w = |p: IPt, q: IPt| {
            (
                i128::from(q.x) - i128::from(p.x),
                i128::from(q.y) - i128::from(p.y),
            )
        };
        let (e, u, back) = (w(a, c), w(a, v), w(c, v));
        let len2 = e.0 * e.0 + e.1 * e.1;
        let cross = e.0 * u.1 - e.1 * u.0;
        let ahead = e.0 * u.0 + e.1 * u.1 > 0 && e.0 * back.0 + e.1 * back.1 < 0;
        len2 > 0 && ahead && cross * cross <= i128::from(tol * tol) * len2 && !on_frame(v)
    };
    let candidate = |r: &Vec<IPt>| {
        let n = r.len();
        n > 3 && (0..n).any(|k| near_line(r[(k + n - 1) % n], r[k], r[(k + 1) % n]))
    };
    if !shapes.iter().flatten().any(candidate) {
        return;
    }
    let all: Vec<IPt> = shapes.iter().flatten().flatten().copied().collect();
    let removable = |a: IPt, v: IPt, c: IPt| {
        if !near_line(a, v, c) {
            return false;
        }
        let b = IBox::of([a, v, c]);
        let inside = |p: IPt| {
            let (s1, s2, s3) = (orient(a, v, p), orient(v, c, p), orient(c, a, p));
            (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0)
        };
        !all.iter().any(|&p| {
            p != a && p != v && p != c && b.overlaps(&IBox::of_segment(p, p)) && inside(p)
        })
    };
    for ring in shapes.iter_mut().flatten().filter(|r| candidate(r)) {
        let mut out: Vec<IPt> = Vec::with_capacity(ring.len());
        for &v in ring.iter() {
            out.push(v);
            while out.len() >= 3 {
                let l = out.len();
                if removable(out[l - 3], out[l - 2], out[l - 1]) {
                    out.remove(l - 2);
                } else {
                    break;
                }
            }
        }
        // the wrap-around: the first and last vertices against each other
        loop {
            let n = out.len();
            if n < 4 {
                break;
            }
            if removable(out[n - 1], out[0], out[1]) {
                out.remove(0);
            } else if removable(out[n - 2], out[n - 1], out[0]) {
                out.pop();
            } else {
                break;
            }
        }
        if out.len() >= 3 {
            *ring = out;
        }
    }
}

/// A reusable boolean engine (keeps its buffers between calls).
pub(crate) struct Engine {
    ov: Overlay<i32>,
    /// For calls of [`FRAG_FROM`] points or more: `i_overlay`'s fragment splitter.
    frag: Overlay<i32>,
}

/// Calls with at least this many points use the fragment splitter: below 2 000 edges
/// `i_overlay`'s automatic choice splits edges pair by pair, which is slow when a batch's
/// sweeps run nearly along the stock's edges, and from 2 000 to 32 000 its tree splitter was
/// slow to join tiles (figures in PERFORMANCE.md, "The splitter's threshold"). Hence every
/// call, the unions and the float booleans of the measures included, chooses by
/// [`solver_for`].
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
pub fn clean(rings: &[Vec<P>]) -> Vec<Shape> {
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

/// Most shapes a union joins in one call; more are joined half by half (see [`boolean`]).
const UNION_CHUNK: usize = 64;

/// Float boolean between two shape sets on a grid fitted to both (for measures). A union of
/// more than [`UNION_CHUNK`] shapes is the union of its two halves' unions, each on a grid
/// fitted to it: the boolean engine splits every edge at every other edge's end along the
/// same line, so n overlapping bands with sides on one line (a thread's passes) made n²
/// pieces in one call (5 000 passes: 5 GB), where the halves' unions stay small.
pub(crate) fn boolean(a: &[Shape], b: &[Shape], rule: BoolOp) -> Vec<Shape> {
    let (a, b) = (finite_shapes(a), finite_shapes(b));
    if a.is_empty() && b.is_empty() {
        return Vec::new();
    }
    if rule == BoolOp::Union && a.len() + b.len() > UNION_CHUNK {
        let all: Vec<Vec<Vec<P>>> = a.into_iter().chain(b).collect();
        return to_shapes(union_by_halves(&all));
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

/// The union of `shapes` (finite), joined half by half down to [`UNION_CHUNK`] shapes a call.
fn union_by_halves(shapes: &[Vec<Vec<P>>]) -> Vec<Vec<Vec<P>>> {
    if shapes.len() <= UNION_CHUNK {
        let points = shapes.iter().flatten().map(Vec::len).sum();
        return FloatOverlay::with_subj_custom(shapes, Default::default(), solver_for(points))
            .overlay(OverlayRule::Subject, FillRule::NonZero);
    }
    let (left, right) = shapes.split_at(shapes.len() / 2);
    let (l, r) = (union_by_halves(left), union_by_halves(right));
    let points = [&l, &r].into_iter().flatten().flatten().map(Vec::len).sum();
    FloatOverlay::with_subj_and_clip_custom(&l, &r, Default::default(), solver_for(points))
        .overlay(OverlayRule::Union, FillRule::NonZero)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ring_air::tests::{box_within, Rng};

    /// A random convex counter-clockwise polygon on a coarse grid (touching and collinear
    /// cases are frequent), or fewer than three points.
    fn random_hull(rng: &mut Rng, span: i64) -> Vec<IPt> {
        let pts: Vec<P> = (0..6)
            .map(|_| [rng.next(span) as f64, rng.next(span) as f64])
            .collect();
        geom::flat::convex_hull(&pts)
            .iter()
            .map(|p| IPt::new(p[0] as i32, p[1] as i32))
            .collect()
    }

    /// A rational point `(x / d, y / d)`, `d > 0`.
    type Q = (i128, i128, i128);

    /// Sutherland–Hodgman in exact rationals: the convex `poly` clipped to the box.
    fn clip_exact(poly: &[IPt], b: &IBox) -> Vec<Q> {
        let mut out: Vec<Q> = poly
            .iter()
            .map(|p| (i128::from(p.x), i128::from(p.y), 1))
            .collect();
        // (axis, bound, keep when the coordinate is at least the bound)
        let planes = [
            (0, b.min[0], true),
            (0, b.max[0], false),
            (1, b.min[1], true),
            (1, b.max[1], false),
        ];
        for (axis, bound, keep_above) in planes {
            let coord = |q: &Q| if axis == 0 { q.0 } else { q.1 };
            // sign of (coordinate - bound), times d > 0
            let side = |q: &Q| {
                let v = coord(q) - i128::from(bound) * q.2;
                if keep_above {
                    v
                } else {
                    -v
                }
            };
            let input = std::mem::take(&mut out);
            for i in 0..input.len() {
                let (p, q) = (input[i], input[(i + 1) % input.len()]);
                let (sp, sq) = (side(&p), side(&q));
                if sp >= 0 {
                    out.push(p);
                }
                if (sp > 0 && sq < 0) || (sp < 0 && sq > 0) {
                    // p + t (q - p) with t = sp_true / (sp_true - sq_true); over the common
                    // denominator p.2 q.2 (sp_true = sp / p.2, sq_true = sq / q.2)
                    let (a, c) = (sp * q.2, sq * p.2); // t = a / (a - c)
                    let den = a - c;
                    let (den, a) = if den < 0 { (-den, -a) } else { (den, a) };
                    let x = p.0 * q.2 * den + (q.0 * p.2 - p.0 * q.2) * a;
                    let y = p.1 * q.2 * den + (q.1 * p.2 - p.1 * q.2) * a;
                    out.push((x, y, p.2 * q.2 * den));
                }
            }
        }
        out
    }

    /// Reference for `convex_covers_in_box`: every corner of `inner ∩ b` (exact) is on or
    /// left of every edge of `outer`.
    fn covers_reference(outer: &[IPt], inner: &[IPt], b: &IBox) -> bool {
        let n = outer.len();
        clip_exact(inner, b).iter().all(|&(x, y, d)| {
            (0..n).all(|i| {
                let (a, e) = (outer[i], outer[(i + 1) % n]);
                let (ex, ey) = (i128::from(e.x - a.x), i128::from(e.y - a.y));
                ex * (y - i128::from(a.y) * d) - ey * (x - i128::from(a.x) * d) >= 0
            })
        })
    }

    /// The box test by edge crossings agrees with clipping `inner` to the box exactly and
    /// testing the clip's corners, on hulls and boxes of a grid coarse enough that touching,
    /// collinear and degenerate cases are common (both answers occur often).
    #[test]
    fn covering_in_a_box_matches_the_exact_clip() {
        let mut rng = Rng(0x5eed_c0de_0001_2345);
        let (mut yes, mut no) = (0, 0);
        for _ in 0..40_000 {
            let (outer, inner) = (random_hull(&mut rng, 6), random_hull(&mut rng, 6));
            if outer.len() < 3 || inner.len() < 3 {
                continue;
            }
            let b = box_within(&mut rng, 6);
            let want = covers_reference(&outer, &inner, &b);
            assert_eq!(
                convex_covers_in_box(&outer, &inner, &b),
                want,
                "{outer:?} {inner:?} {b:?}"
            );
            if want {
                yes += 1;
            } else {
                no += 1;
            }
        }
        assert!(yes > 3_000 && no > 3_000, "{yes} covered, {no} not");
    }

    /// The inscribed box lies in the polygon (its corners pass the exact edge test) and,
    /// on a long swept hull like a roughing pass's, reaches down to a grid step above the
    /// bottom edge, where the stock lies.
    #[test]
    fn the_inscribed_box_lies_inside() {
        let mut rng = Rng(0x1b0c_5eed);
        let mut found = 0;
        for _ in 0..20_000 {
            let hull = random_hull(&mut rng, 1_000);
            if hull.len() < 3 {
                continue;
            }
            let c = inscribed_box(&hull);
            if c.is_empty() {
                continue;
            }
            found += 1;
            assert!(convex_contains(&hull, &c.corners()), "{hull:?} {c:?}");
        }
        assert!(found > 15_000, "{found}");
        // a notch from the top (a reflex vertex, as snapping may leave a hull): its chords
        // span the square, but no box of them lies in the kernel (the triangle under the
        // notch), so none is given
        let notched =
            [(0, 0), (100, 0), (100, 100), (50, 40), (0, 100)].map(|(x, y)| IPt::new(x, y));
        let c = inscribed_box(&notched);
        assert!(
            c.is_empty() || convex_contains(&notched, &c.corners()),
            "{c:?}"
        );
        // a pass: a 35° rhombus swept 100 000 steps along -z
        let rhombus = [
            [0.0, 0.0],
            [8000.0, 3000.0],
            [9000.0, 11000.0],
            [1000.0, 8000.0],
        ];
        let swept: Vec<IPt> = geom::flat::sweep_convex(&rhombus, [-100_000.0, 0.0])
            .iter()
            .map(|p| IPt::new(p[0] as i32, p[1] as i32))
            .collect();
        let c = inscribed_box(&swept);
        assert!(convex_contains(&swept, &c.corners()));
        assert_eq!(c.min[1], 1, "{c:?}");
        assert!(c.max[0] - c.min[0] > 90_000, "{c:?}");
    }

    /// (`geom::flat`'s chain sweep read by the boolean engine.)
    mod chain_sweep {
        use super::super::clean;
        use geom::flat::{convex_hull, pts, sweep_chain, sweep_convex, P};
        use geom::Rect;

        /// The chain sweep's ring fills (non-zero) exactly the union of the per-chord hulls,
        /// and no point has a negative winding number: arcs of both turning directions, an S
        /// curve, a half circle (turns up to 180° in total) and a polyline with sharp corners,
        /// with a 35° insert whose nose is chorded (a convex part of many vertices).
        #[test]
        fn chain_sweep_is_the_union_of_the_chord_hulls() {
            let nose = 0.4;
            let mut insert: Vec<P> = (0..=14)
                .map(|k| {
                    let t = (-90.0 + 145.0 * f64::from(k) / 14.0_f64).to_radians();
                    [nose * t.cos() - 0.3, nose * t.sin() + nose]
                })
                .collect();
            insert.push([4.0, 2.5]);
            let insert = convex_hull(&insert);
            let arc = |c: P, r: f64, a0: f64, a1: f64, n: usize| -> Vec<P> {
                (0..=n)
                    .map(|k| {
                        let t = (a0 + (a1 - a0) * k as f64 / n as f64).to_radians();
                        [c[0] + r * t.cos(), c[1] + r * t.sin()]
                    })
                    .collect()
            };
            let mut s_curve = arc([0.0, 10.0], 0.5, 0.0, 180.0, 25);
            s_curve.extend(arc([-1.0, 10.0], 0.5, 0.0, -180.0, 25).into_iter().skip(1));
            let paths = [
                arc([0.0, 10.0], 5.0, 0.0, 90.0, 40),
                arc([0.0, 10.0], 5.0, 90.0, 0.0, 40),
                arc([0.0, 10.0], 0.5, 180.0, 0.0, 25),
                s_curve,
                vec![
                    [0.0, 10.0],
                    [-5.0, 10.0],
                    [-5.0, 6.0],
                    [-9.0, 12.0],
                    [-2.0, 13.0],
                ],
            ];
            for (i, path) in paths.iter().enumerate() {
                let ring = sweep_chain(&insert, path);
                let hulls: Vec<Vec<P>> = path
                    .windows(2)
                    .map(|w| {
                        let moved: Vec<P> = insert
                            .iter()
                            .map(|v| [v[0] + w[0][0], v[1] + w[0][1]])
                            .collect();
                        sweep_convex(&moved, [w[1][0] - w[0][0], w[1][1] - w[0][1]])
                    })
                    .collect();
                let union = clean(&hulls);
                let chain = clean(std::slice::from_ref(&ring));
                let xor = crate::symmetric_difference_area(&union, &chain);
                assert!(xor < 1e-6, "path {i}: symmetric difference {xor} mm²");
                // arcs turn a little at each vertex: about four points per chord plus the caps
                assert!(
                    i == 4 || ring.len() < path.len() * 4 + 2 * insert.len(),
                    "path {i}: {} points",
                    ring.len()
                );
                // winding numbers: never negative on a grid of sample points
                let r = Rect::of(pts(&ring));
                for a in 0..60 {
                    for b in 0..60 {
                        let p = [
                            r.min.z + (r.max.z - r.min.z) * (f64::from(a) + 0.37) / 60.0,
                            r.min.r + (r.max.r - r.min.r) * (f64::from(b) + 0.61) / 60.0,
                        ];
                        assert!(winding(&ring, p) >= 0, "path {i}: winding < 0 at {p:?}");
                    }
                }
            }
        }

        fn winding(ring: &[P], p: P) -> i32 {
            let mut w = 0;
            for i in 0..ring.len() {
                let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
                let side = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
                if a[1] <= p[1] && b[1] > p[1] && side > 0.0 {
                    w += 1;
                } else if a[1] > p[1] && b[1] <= p[1] && side < 0.0 {
                    w -= 1;
                }
            }
            w
        }
    }

    /// What a box keeps when a core is cut out of it holds every unit cell of the box the
    /// core does not cover (what a cut leaves is the closure of such cells), and it shrinks
    /// when the core spans the box.
    #[test]
    fn the_box_outside_a_core_holds_what_the_cut_leaves() {
        let mut rng = Rng(0x0b0c_5eed_0042);
        let mut shrunk = 0;
        for _ in 0..20_000 {
            let (b, core) = (box_within(&mut rng, 5), box_within(&mut rng, 7));
            let out = b.outside(&core);
            // every unit cell of the box the core does not cover lies in what is kept
            for x in b.min[0]..b.max[0] {
                for y in b.min[1]..b.max[1] {
                    let cut =
                        core.min[0] <= x && x < core.max[0] && core.min[1] <= y && y < core.max[1];
                    let kept =
                        out.min[0] <= x && x < out.max[0] && out.min[1] <= y && y < out.max[1];
                    assert!(
                        cut || kept,
                        "{b:?} less {core:?} gave {out:?}: cell ({x}, {y})"
                    );
                }
            }
            shrunk += usize::from(out != b);
        }
        assert!(shrunk > 2_000, "{shrunk}");
    }

    /// A union of more shapes than one call joins (joined half by half) is the union: 2 000
    /// bands of a thread's passes, 0.0005 mm apart on sides of one line, join into the one
    /// rectangle they cover; 300 scattered unit squares (some overlapping) cover what the
    /// one-call union of each chunk covers, added up; a union with a clip set joins both.
    #[test]
    fn a_union_of_many_shapes_is_joined_by_halves() {
        let rect = |z0: f64, z1: f64, r0: f64, r1: f64| Shape {
            outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
            holes: vec![],
        };
        let bands: Vec<Shape> = (0..2000)
            .map(|k| {
                rect(
                    -18.0,
                    0.5,
                    8.0 - 0.0005 * f64::from(k),
                    9.0 - 0.0005 * f64::from(k),
                )
            })
            .collect();
        let u = boolean(&bands, &[], BoolOp::Union);
        assert_eq!(u.len(), 1);
        assert_eq!(u[0].outer.len(), 4, "{:?}", u[0].outer);
        let top = 9.0;
        let bottom = 8.0 - 0.0005 * 1999.0;
        assert!((crate::area(&u) - 18.5 * (top - bottom)).abs() < 1e-6);
        // scattered squares on a 20 x 20 lattice of pitch 0.9 (unit squares: neighbours
        // overlap by 0.1 along both axes): the area the inclusion–exclusion gives
        let squares: Vec<Shape> = (0..300)
            .map(|k| {
                let (i, j) = (f64::from(k % 20), f64::from(k / 20));
                rect(0.9 * i, 0.9 * i + 1.0, 0.9 * j, 0.9 * j + 1.0)
            })
            .collect();
        let u = boolean(&squares, &[], BoolOp::Union);
        let (w, h) = (0.9 * 19.0 + 1.0, 0.9 * 14.0 + 1.0);
        assert!(
            (crate::area(&u) - w * h).abs() < 1e-6,
            "{}",
            crate::area(&u)
        );
        let (a, b) = squares.split_at(100);
        let u2 = boolean(a, b, BoolOp::Union);
        assert!((crate::area(&u2) - w * h).abs() < 1e-6);
    }

    /// A kink of a grid step goes, one of two stays, one with a vertex of another ring in
    /// its triangle stays, and one on the frame stays; on random rings the dropped vertices
    /// move the region by less than a step a vertex (area within the triangles dropped) and
    /// no ring loses its orientation.
    #[test]
    fn grid_kinks_go_and_the_rings_stay_valid() {
        let p = |x: i32, y: i32| IPt::new(x, y);
        let frame = IBox {
            min: [-1000, -1000],
            max: [1000, 1000],
        };
        // a square whose bottom edge has a 1-step kink at (50, -1) and a 2-step one at (80, 2)
        let mut shapes: IShapes = vec![vec![vec![
            p(0, 0),
            p(50, -1),
            p(100, 0),
            p(100, 100),
            p(0, 100),
        ]]];
        drop_grid_kinks(&mut shapes, 1, &frame);
        assert_eq!(
            shapes[0][0],
            vec![p(0, 0), p(100, 0), p(100, 100), p(0, 100)]
        );
        let mut shapes: IShapes = vec![vec![vec![
            p(0, 0),
            p(80, 2),
            p(100, 0),
            p(100, 100),
            p(0, 100),
        ]]];
        drop_grid_kinks(&mut shapes, 1, &frame);
        assert_eq!(shapes[0][0].len(), 5, "two steps off the line: kept");
        // a hole's vertex in the kink's triangle keeps it
        let mut shapes: IShapes = vec![vec![
            vec![p(0, 0), p(50, -1), p(100, 0), p(100, 100), p(0, 100)],
            vec![p(50, 0), p(40, 10), p(60, 10)],
        ]];
        drop_grid_kinks(&mut shapes, 1, &frame);
        assert_eq!(shapes[0][0].len(), 5, "a vertex in the triangle: kept");
        // on the frame's side: kept
        let mut shapes: IShapes = vec![vec![vec![
            p(0, 0),
            p(50, -1),
            p(100, 0),
            p(100, 100),
            p(0, 100),
        ]]];
        let edge = IBox {
            min: [0, -1],
            max: [100, 100],
        };
        drop_grid_kinks(&mut shapes, 1, &edge);
        assert_eq!(shapes[0][0].len(), 5, "on the frame: kept");
        // random rings: 400-700 points round a circle of radius 10 000, jittered by up to two
        // steps (chords of ~100 steps: their sagitta is 0.1 step)
        let mut rng = Rng(0x5eed_0f1c_5eed);
        let mut dropped = 0;
        for _ in 0..40 {
            let n = 400 + rng.next(300).unsigned_abs() as usize;
            let ring: Vec<IPt> = (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n as f64;
                    let r = 10_000.0 + rng.next(2) as f64;
                    p((r * t.cos()).round() as i32, (r * t.sin()).round() as i32)
                })
                .collect();
            let before = ring_area2(&ring);
            let mut shapes: IShapes = vec![vec![ring.clone()]];
            drop_grid_kinks(&mut shapes, 1, &frame);
            let after = &shapes[0][0];
            assert!(after.len() >= 3 && after.iter().all(|q| ring.contains(q)));
            assert!(ring_area2(after) > 0, "orientation kept");
            // each dropped vertex takes a triangle of height <= 1 on its chord (<= 2 r)
            let gone = (ring.len() - after.len()) as i128;
            assert!(
                (before - ring_area2(after)).abs() <= gone * 2 * 20_002,
                "{ring:?}"
            );
            dropped += gone;
        }
        assert!(dropped > 0);
    }
}
