//! A point or vector in the (z, r) half plane.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

/// A point (or a vector) in the half plane: `z` axial (mm), `r` radius (mm) = X / 2.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pt {
    /// Axial coordinate, mm.
    pub z: f64,
    /// Radius, mm (X / 2).
    pub r: f64,
}

impl Pt {
    /// The origin (or the zero vector).
    pub const ZERO: Self = Self { z: 0.0, r: 0.0 };

    /// A point from axial coordinate and radius.
    pub const fn new(z: f64, r: f64) -> Self {
        Self { z, r }
    }
    /// The unit vector at `angle` radians from +Z toward +r.
    pub fn from_angle(angle: f64) -> Self {
        Self::new(angle.cos(), angle.sin())
    }
    /// Euclidean distance to `other`.
    pub fn dist(self, other: Self) -> f64 {
        (self.z - other.z).hypot(self.r - other.r)
    }
    /// Length of the vector.
    pub fn len(self) -> f64 {
        self.z.hypot(self.r)
    }
    /// Squared length of the vector.
    pub fn len2(self) -> f64 {
        self.z * self.z + self.r * self.r
    }
    /// Dot product.
    pub fn dot(self, o: Self) -> f64 {
        self.z * o.z + self.r * o.r
    }
    /// Cross product (z-component of the 3D cross): positive when `o` is counter-clockwise
    /// of `self`.
    pub fn cross(self, o: Self) -> f64 {
        self.z * o.r - self.r * o.z
    }
    /// The vector turned a quarter counter-clockwise (its left normal).
    pub fn perp(self) -> Self {
        Self::new(-self.r, self.z)
    }
    /// The vector scaled to length 1 (zero stays zero).
    pub fn unit(self) -> Self {
        let l = self.len();
        if l > 0.0 {
            self / l
        } else {
            self
        }
    }
    /// Angle of the vector from +Z, radians in (−π, π].
    pub fn angle(self) -> f64 {
        self.r.atan2(self.z)
    }
    /// The point a fraction `t` of the way to `o`.
    pub fn lerp(self, o: Self, t: f64) -> Self {
        self + (o - self) * t
    }
    /// Both coordinates finite.
    pub fn is_finite(self) -> bool {
        self.z.is_finite() && self.r.is_finite()
    }
    /// As an array `[z, r]`.
    pub const fn to_array(self) -> [f64; 2] {
        [self.z, self.r]
    }
}

/// Orientation of `c` against the directed line `a → b`: positive when `c` is left of it.
pub fn orient(a: Pt, b: Pt, c: Pt) -> f64 {
    (b - a).cross(c - a)
}

impl From<[f64; 2]> for Pt {
    fn from(p: [f64; 2]) -> Self {
        Self::new(p[0], p[1])
    }
}
impl From<Pt> for [f64; 2] {
    fn from(p: Pt) -> Self {
        [p.z, p.r]
    }
}
impl From<Pt> for geo::Coord<f64> {
    fn from(p: Pt) -> Self {
        Self { x: p.z, y: p.r }
    }
}
impl From<geo::Coord<f64>> for Pt {
    fn from(c: geo::Coord<f64>) -> Self {
        Self::new(c.x, c.y)
    }
}

impl Add for Pt {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::new(self.z + o.z, self.r + o.r)
    }
}
impl AddAssign for Pt {
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl Sub for Pt {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::new(self.z - o.z, self.r - o.r)
    }
}
impl SubAssign for Pt {
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
impl Neg for Pt {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.z, -self.r)
    }
}
impl Mul<f64> for Pt {
    type Output = Self;
    fn mul(self, k: f64) -> Self {
        Self::new(self.z * k, self.r * k)
    }
}
impl Div<f64> for Pt {
    type Output = Self;
    fn div(self, k: f64) -> Self {
        Self::new(self.z / k, self.r / k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_and_products() {
        let a = Pt::new(3.0, 4.0);
        assert_eq!(a.len(), 5.0);
        assert_eq!(a + Pt::new(1.0, 1.0), Pt::new(4.0, 5.0));
        assert_eq!(a * 2.0 - a, a);
        assert_eq!(a.dot(Pt::new(1.0, 0.0)), 3.0);
        assert_eq!(Pt::new(1.0, 0.0).cross(Pt::new(0.0, 1.0)), 1.0);
        assert_eq!(Pt::new(1.0, 0.0).perp(), Pt::new(0.0, 1.0));
        assert!(orient(Pt::ZERO, Pt::new(1.0, 0.0), Pt::new(0.5, 1.0)) > 0.0);
        assert!((a.unit().len() - 1.0).abs() < 1e-15);
    }
}
