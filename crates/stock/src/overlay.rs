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

/// Twice the signed area of a grid ring, exact.
pub(crate) fn ring_area2(r: &[IPt]) -> i128 {
    let n = r.len();
    (0..n)
        .map(|i| {
            let (a, b) = (r[i], r[(i + 1) % n]);
            i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y)
        })
        .sum()
}

/// A reusable boolean engine (keeps its buffers between calls).
pub(crate) struct Engine {
    ov: Overlay<i32>,
}

impl Engine {
    /// A fresh engine.
    pub(crate) fn new() -> Self {
        Self {
            ov: Overlay::new(256),
        }
    }

    fn run<'a>(
        &mut self,
        subj: &IShapes,
        clips: impl IntoIterator<Item = &'a [IPt]>,
        rule: OverlayRule,
    ) -> IShapes {
        self.ov.clear();
        self.ov.add_source(subj, ShapeType::Subject);
        for c in clips {
            self.ov.add_contour(c, ShapeType::Clip);
        }
        self.ov.overlay(rule, FillRule::NonZero)
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
        self.ov.clear();
        for p in parts {
            self.ov.add_source(p, ShapeType::Subject);
        }
        self.ov.overlay(OverlayRule::Subject, FillRule::NonZero)
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
    to_shapes(FloatOverlay::with_subj(&rings).overlay(OverlayRule::Subject, FillRule::NonZero))
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
    to_shapes(FloatOverlay::with_subj_and_clip(&a, &b).overlay(rule, FillRule::NonZero))
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
