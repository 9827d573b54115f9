//! The kernel's convex-polygon algorithms on `[f64; 2]` points `[z, r]`, the form the
//! removal engine and the sections store their rings in: convex parts, sweeps of a convex
//! polygon along a move, Minkowski sums, convex differences, clipping to a box or a hull.
//! Area, hulls, containment, distances and boxes come from the [`Pt`] kernel above.
//!
//! Why a second point form: a section's rings are read and written by the boolean engine
//! (through `[f64; 2]`) many millions of times in a long run; these routines work on them
//! in place instead of copying every ring into [`Pt`]s and back.

mod clip;
mod convex;
mod sweep;

pub use clip::{clip_convex, clip_to_hull, minus_convex};
pub use convex::{convex_hull, convex_parts, is_convex};
pub use sweep::{minkowski, sweep_chain, sweep_convex};

use crate::{orient, Pt, Rect};

/// A point `[z, r]` in mm.
pub type P = [f64; 2];

/// Distance between two points.
pub fn dist(a: P, b: P) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// Distance from `q` to the segment `a b`.
pub fn segment_distance(q: P, a: P, b: P) -> f64 {
    let t = segment_param(q, a, b);
    (q[0] - a[0] - t * (b[0] - a[0])).hypot(q[1] - a[1] - t * (b[1] - a[1]))
}

/// Where on the segment `a b` the point nearest `q` lies: 0 at `a`, 1 at `b` (0 for a
/// segment of no length).
pub fn segment_param(q: P, a: P, b: P) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    if len2 > 0.0 {
        (((q[0] - a[0]) * d[0] + (q[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// The point a fraction `t` of the way from `a` to `b`.
pub fn lerp(a: P, b: P, t: f64) -> P {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
}

/// Points as kernel points.
pub fn pts(ring: &[P]) -> Vec<Pt> {
    ring.iter().map(|&p| Pt::from(p)).collect()
}

/// The box of some points (no copy of them, unlike `Rect::of(pts(..))`).
pub fn bounds<'a>(points: impl IntoIterator<Item = &'a P>) -> Rect {
    let mut r = Rect::EMPTY;
    for &p in points {
        r.add(Pt::new(p[0], p[1]));
    }
    r
}

/// Orientation of `b` against the directed line `o → a`: positive when left of it.
fn cross(o: P, a: P, b: P) -> f64 {
    orient(o.into(), a.into(), b.into())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::P;

    /// An L of area 3: the unit squares at (0,0), (1,0) and (0,1).
    pub(crate) const L_SHAPE: [P; 6] = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];
}
