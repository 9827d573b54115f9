//! Circular arcs and the one routine that turns them into chords.

use crate::Pt;
use std::f64::consts::{PI, TAU};

/// Most chords one arc is ever cut into (a bound against absurd radii and tolerances).
pub const MAX_CHORDS: usize = 100_000;

/// A circular arc: centre, radius, start angle (radians from +Z toward +r) and signed
/// sweep (positive counter-clockwise as drawn with Z right and X up: G03).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc {
    /// Centre.
    pub center: Pt,
    /// Radius, mm.
    pub radius: f64,
    /// Start angle, radians.
    pub start: f64,
    /// Signed sweep, radians (positive counter-clockwise).
    pub sweep: f64,
}

impl Arc {
    /// The arc from `from` to `to` around `center`, counter-clockwise when `ccw`; start equal
    /// to end is a full circle. The radius is taken at the start.
    pub fn between(from: Pt, to: Pt, center: Pt, ccw: bool) -> Self {
        Self {
            center,
            radius: center.dist(from),
            start: (from - center).angle(),
            sweep: sweep_between(from, to, center, ccw),
        }
    }
    /// The point at angle `a`.
    pub fn at_angle(&self, a: f64) -> Pt {
        self.center + Pt::from_angle(a) * self.radius
    }
    /// The point a fraction `t` of the sweep along.
    pub fn at(&self, t: f64) -> Pt {
        self.at_angle(self.start + self.sweep * t)
    }
    /// Length of the arc.
    pub fn length(&self) -> f64 {
        self.radius * self.sweep.abs()
    }
    /// How many chords keep every chord within `tol` of the arc (see [`chord_count`]).
    pub fn chords(&self, tol: f64) -> usize {
        chord_count(self.radius, self.sweep, tol)
    }
    /// The `n + 1` points that cut the arc into `n` equal chords, start and end included.
    pub fn points(&self, n: usize) -> Vec<Pt> {
        let n = n.max(1);
        (0..=n).map(|i| self.at(i as f64 / n as f64)).collect()
    }
    /// The arc as chords within `tol` of it: [`Arc::points`] of [`Arc::chords`].
    pub fn flatten(&self, tol: f64) -> Vec<Pt> {
        self.points(self.chords(tol))
    }
}

/// Signed swept angle from `from` to `to` around `center`, positive counter-clockwise;
/// start equal to end sweeps a full turn (±2π).
pub fn sweep_between(from: Pt, to: Pt, center: Pt, ccw: bool) -> f64 {
    let a0 = (from - center).angle();
    let a1 = (to - center).angle();
    let mut d = a1 - a0;
    if ccw {
        while d <= 1e-12 {
            d += TAU;
        }
        while d > TAU + 1e-12 {
            d -= TAU;
        }
    } else {
        while d >= -1e-12 {
            d -= TAU;
        }
        while d < -TAU - 1e-12 {
            d += TAU;
        }
    }
    d
}

/// Number of equal chords for an arc of `radius` over `sweep` radians such that no chord
/// strays more than `tol` from the arc (sagitta `radius (1 − cos(θ/2)) ≤ tol`); a radius
/// within the tolerance takes half turns. At least 1, at most [`MAX_CHORDS`].
pub fn chord_count(radius: f64, sweep: f64, tol: f64) -> usize {
    let step = if radius <= tol {
        PI
    } else {
        2.0 * (1.0 - tol / radius).acos()
    };
    let n = (sweep.abs() / step).ceil();
    if n.is_finite() {
        (n as usize).clamp(1, MAX_CHORDS)
    } else {
        MAX_CHORDS
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_circle_chords_stay_within_the_tolerance() {
        let a = Arc::between(Pt::new(10.0, 0.0), Pt::new(0.0, 10.0), Pt::ZERO, true);
        assert!((a.sweep - PI / 2.0).abs() < 1e-12);
        let pts = a.flatten(0.001);
        assert!(pts.len() > 2);
        for w in pts.windows(2) {
            let mid = (w[0] + w[1]) / 2.0;
            assert!(10.0 - mid.len() <= 0.001 + 1e-12);
        }
        assert!(pts[0].dist(Pt::new(10.0, 0.0)) < 1e-12);
        assert!(pts.last().unwrap().dist(Pt::new(0.0, 10.0)) < 1e-12);
    }

    #[test]
    fn clockwise_and_full_circles() {
        let cw = sweep_between(Pt::new(10.0, 0.0), Pt::new(0.0, 10.0), Pt::ZERO, false);
        assert!((cw + 1.5 * PI).abs() < 1e-12);
        let full = sweep_between(Pt::new(1.0, 0.0), Pt::new(1.0, 0.0), Pt::ZERO, true);
        assert!((full - TAU).abs() < 1e-12);
        assert_eq!(chord_count(0.0005, PI, 0.001), 1);
        assert_eq!(chord_count(f64::INFINITY, PI, 0.001), MAX_CHORDS);
    }
}
