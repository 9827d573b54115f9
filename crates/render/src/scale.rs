//! Bounding boxes, the mm -> px mapping with equal Z and X scale, and nice tick steps.

use crate::report::{PathLine, Shape};

/// An axis-aligned box in `[z, r]` mm; empty until a finite point is added.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bbox {
    pub(crate) zmin: f64,
    pub(crate) zmax: f64,
    pub(crate) rmin: f64,
    pub(crate) rmax: f64,
}

impl Bbox {
    /// The empty box.
    pub(crate) const EMPTY: Self = Self {
        zmin: f64::INFINITY,
        zmax: f64::NEG_INFINITY,
        rmin: f64::INFINITY,
        rmax: f64::NEG_INFINITY,
    };

    /// A box from its bounds.
    pub(crate) fn new(zmin: f64, zmax: f64, rmin: f64, rmax: f64) -> Self {
        Self {
            zmin,
            zmax,
            rmin,
            rmax,
        }
    }

    /// Whether no point was added.
    pub(crate) fn is_empty(&self) -> bool {
        !(self.zmin <= self.zmax && self.rmin <= self.rmax)
    }

    /// Grow to include `p`; non-finite points are ignored.
    pub(crate) fn add(&mut self, p: [f64; 2]) {
        if p[0].is_finite() && p[1].is_finite() {
            self.zmin = self.zmin.min(p[0]);
            self.zmax = self.zmax.max(p[0]);
            self.rmin = self.rmin.min(p[1]);
            self.rmax = self.rmax.max(p[1]);
        }
    }

    /// Union with another box.
    pub(crate) fn union(&self, o: &Self) -> Self {
        if o.is_empty() {
            return *self;
        }
        if self.is_empty() {
            return *o;
        }
        Self::new(
            self.zmin.min(o.zmin),
            self.zmax.max(o.zmax),
            self.rmin.min(o.rmin),
            self.rmax.max(o.rmax),
        )
    }

    /// Intersection (may be empty).
    pub(crate) fn intersect(&self, o: &Self) -> Self {
        Self::new(
            self.zmin.max(o.zmin),
            self.zmax.min(o.zmax),
            self.rmin.max(o.rmin),
            self.rmax.min(o.rmax),
        )
    }

    /// Grown by `m` on every side.
    pub(crate) fn grow(&self, m: f64) -> Self {
        Self::new(self.zmin - m, self.zmax + m, self.rmin - m, self.rmax + m)
    }

    /// Width along Z.
    pub(crate) fn w(&self) -> f64 {
        self.zmax - self.zmin
    }

    /// Height along r.
    pub(crate) fn h(&self) -> f64 {
        self.rmax - self.rmin
    }

    /// Whether `o` lies within this box.
    #[cfg(test)]
    pub(crate) fn contains(&self, o: &Self) -> bool {
        o.is_empty()
            || (o.zmin >= self.zmin
                && o.zmax <= self.zmax
                && o.rmin >= self.rmin
                && o.rmax <= self.rmax)
    }

    /// Whether the boxes overlap.
    pub(crate) fn overlaps(&self, o: &Self) -> bool {
        !self.is_empty()
            && !o.is_empty()
            && self.zmin <= o.zmax
            && o.zmin <= self.zmax
            && self.rmin <= o.rmax
            && o.rmin <= self.rmax
    }

    /// Box of some shapes (outer rings suffice: holes lie inside).
    pub(crate) fn of_shapes(shapes: &[Shape]) -> Self {
        let mut b = Self::EMPTY;
        for s in shapes {
            for p in &s.outer {
                b.add(*p);
            }
        }
        b
    }

    /// Box of a toolpath.
    pub(crate) fn of_path(path: &[PathLine]) -> Self {
        let mut b = Self::EMPTY;
        for l in path {
            for p in l.points.iter() {
                b.add(*p);
            }
        }
        b
    }
}

/// A mapping from mm `[z, r]` to px, equal scale on both axes, r up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct View {
    /// The visible mm window (fills the px rectangle exactly).
    pub(crate) mm: Bbox,
    /// Pixel rectangle: left, top, width, height.
    pub(crate) px: [f64; 4],
    /// px per mm.
    pub(crate) s: f64,
}

impl View {
    /// Fit `data` (non-empty, finite) into the px rectangle with equal scale, centred;
    /// the mm window is widened along one axis to fill the rectangle.
    pub(crate) fn fit(data: Bbox, px: [f64; 4]) -> Self {
        let data = if data.is_empty() {
            Bbox::new(-10.0, 10.0, -10.0, 10.0)
        } else {
            data
        };
        // Degenerate data (a single point or line) still gets a finite window.
        let w = data.w().max(1e-6);
        let h = data.h().max(1e-6);
        let s = (px[2] / w).min(px[3] / h);
        let (cz, cr) = ((data.zmin + data.zmax) / 2.0, (data.rmin + data.rmax) / 2.0);
        let (hw, hh) = (px[2] / s / 2.0, px[3] / s / 2.0);
        Self {
            mm: Bbox::new(cz - hw, cz + hw, cr - hh, cr + hh),
            px,
            s,
        }
    }

    /// The SVG transform mapping mm to px (`mirror`: r down, for the lower half).
    pub(crate) fn transform(&self, mirror: bool) -> String {
        let tx = self.px[0] - self.mm.zmin * self.s;
        let (sy, ty) = if mirror {
            (self.s, self.px[1] + self.mm.rmax * self.s)
        } else {
            (-self.s, self.px[1] + self.mm.rmax * self.s)
        };
        format!(
            "matrix({} 0 0 {} {} {})",
            crate::text::num(self.s, 9),
            crate::text::num(sy, 9),
            crate::text::num(tx, 6),
            crate::text::num(ty, 6)
        )
    }

    /// px x of a z.
    pub(crate) fn x(&self, z: f64) -> f64 {
        self.px[0] + (z - self.mm.zmin) * self.s
    }

    /// px y of an r.
    pub(crate) fn y(&self, r: f64) -> f64 {
        self.px[1] + (self.mm.rmax - r) * self.s
    }

    /// Right edge in px.
    pub(crate) fn right(&self) -> f64 {
        self.px[0] + self.px[2]
    }

    /// Bottom edge in px.
    pub(crate) fn bottom(&self) -> f64 {
        self.px[1] + self.px[3]
    }

    /// Whether a px point lies inside the rectangle.
    pub(crate) fn contains_px(&self, x: f64, y: f64) -> bool {
        x >= self.px[0] && x <= self.right() && y >= self.px[1] && y <= self.bottom()
    }
}

/// The smallest step of the form {1, 2, 5} × 10^k that is at least `min_step`.
pub(crate) fn nice_step(min_step: f64) -> f64 {
    if !(min_step.is_finite() && min_step > 0.0) {
        return 1.0;
    }
    let mag = 10f64.powf(min_step.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * mag >= min_step * (1.0 - 1e-9) {
            return m * mag;
        }
    }
    10.0 * mag
}

/// Decimals needed to print multiples of `step` exactly.
pub(crate) fn step_decimals(step: f64) -> usize {
    if step >= 1.0 {
        0
    } else {
        (-step.log10()).ceil().clamp(0.0, 9.0) as usize
    }
}

/// Multiples of `step` within `[lo, hi]`, at most 200 of them.
pub(crate) fn ticks(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite() && step > 0.0) || hi < lo {
        return Vec::new();
    }
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    if last - first > 200 {
        return Vec::new();
    }
    (first..=last).map(|i| i as f64 * step).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_steps() {
        assert_eq!(nice_step(7.0), 10.0);
        assert_eq!(nice_step(1.1), 2.0);
        assert_eq!(nice_step(3.0), 5.0);
        assert_eq!(nice_step(10.0), 10.0);
        assert!((nice_step(0.03) - 0.05).abs() < 1e-12);
        assert_eq!(nice_step(f64::NAN), 1.0);
        assert_eq!(step_decimals(0.05), 2);
        assert_eq!(ticks(-41.0, 44.0, 10.0).len(), 9);
    }

    #[test]
    fn fit_keeps_equal_scale_and_covers_data() {
        let data = Bbox::new(-40.0, 40.0, -25.0, 25.0);
        let v = View::fit(data, [0.0, 0.0, 800.0, 400.0]);
        assert!((v.mm.w() * v.s - 800.0).abs() < 1e-9);
        assert!((v.mm.h() * v.s - 400.0).abs() < 1e-9);
        assert!(v.mm.contains(&data));
        assert!((v.y(0.0) - 200.0).abs() < 1e-9);
        assert!((v.x(-40.0) - 80.0).abs() < 1e-9);
    }
}
