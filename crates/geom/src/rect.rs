//! Axis-aligned boxes.

use crate::Pt;

/// An axis-aligned box in (z, r); empty when `min > max` on either axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Lower corner (least z, least r).
    pub min: Pt,
    /// Upper corner.
    pub max: Pt,
}

impl Rect {
    /// The empty box (the identity of [`Rect::add`] and [`Rect::union`]).
    pub const EMPTY: Self = Self {
        min: Pt::new(f64::INFINITY, f64::INFINITY),
        max: Pt::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
    };

    /// The box with these corners.
    pub const fn new(min: Pt, max: Pt) -> Self {
        Self { min, max }
    }
    /// Grows the box to include `p`.
    pub fn add(&mut self, p: Pt) {
        self.min = Pt::new(self.min.z.min(p.z), self.min.r.min(p.r));
        self.max = Pt::new(self.max.z.max(p.z), self.max.r.max(p.r));
    }
    /// Box of some points ([`Rect::EMPTY`] for none).
    pub fn of(pts: impl IntoIterator<Item = Pt>) -> Self {
        let mut r = Self::EMPTY;
        for p in pts {
            r.add(p);
        }
        r
    }
    /// True when nothing was added.
    pub fn is_empty(&self) -> bool {
        !(self.min.z <= self.max.z && self.min.r <= self.max.r)
    }
    /// The smallest box holding both.
    pub fn union(&self, o: &Self) -> Self {
        Self::new(
            Pt::new(self.min.z.min(o.min.z), self.min.r.min(o.min.r)),
            Pt::new(self.max.z.max(o.max.z), self.max.r.max(o.max.r)),
        )
    }
    /// The box grown by `m` on every side.
    pub fn grown(&self, m: f64) -> Self {
        Self::new(self.min - Pt::new(m, m), self.max + Pt::new(m, m))
    }
    /// Extent along z.
    pub fn width(&self) -> f64 {
        self.max.z - self.min.z
    }
    /// Extent along r.
    pub fn height(&self) -> f64 {
        self.max.r - self.min.r
    }
    /// Width or height, whichever is larger.
    pub fn size(&self) -> f64 {
        self.width().max(self.height())
    }
    /// The centre point.
    pub fn center(&self) -> Pt {
        (self.min + self.max) / 2.0
    }
    /// `p` inside or on the border.
    pub fn contains(&self, p: Pt) -> bool {
        self.min.z <= p.z && p.z <= self.max.z && self.min.r <= p.r && p.r <= self.max.r
    }
    /// The boxes share at least a point.
    pub fn intersects(&self, o: &Self) -> bool {
        self.min.z <= o.max.z
            && o.min.z <= self.max.z
            && self.min.r <= o.max.r
            && o.min.r <= self.max.r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_grow_and_meet() {
        let mut b = Rect::EMPTY;
        assert!(b.is_empty());
        b.add(Pt::new(1.0, 2.0));
        b.add(Pt::new(-1.0, 5.0));
        assert_eq!(b, Rect::new(Pt::new(-1.0, 2.0), Pt::new(1.0, 5.0)));
        assert_eq!(b.size(), 3.0);
        assert!(b.contains(Pt::new(0.0, 3.0)));
        assert!(!b.intersects(&Rect::new(Pt::new(2.0, 0.0), Pt::new(3.0, 1.0))));
        assert!(b.intersects(&b.grown(1.0)));
    }
}
