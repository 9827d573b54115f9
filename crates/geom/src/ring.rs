//! Closed rings of points (the last point joins the first; it is not repeated).
//!
//! Area, moments, containment and hulls come from geo; a ring converts with
//! [`to_polygon`]. The integer-grid areas of the removal stay in `stock::overlay`
//! (exact i128 arithmetic on `i_overlay`'s grid).

use crate::{Pt, Rect};
use geo::{Area, Centroid, Contains, ConvexHull, Coord, LineString, Polygon};

/// The ring as a geo polygon without holes.
pub fn to_polygon(ring: &[Pt]) -> Polygon<f64> {
    Polygon::new(to_line_string(ring), vec![])
}

/// The points as a geo line string (not closed).
pub fn to_line_string(points: &[Pt]) -> LineString<f64> {
    LineString::new(points.iter().map(|&p| Coord::from(p)).collect())
}

/// The exterior ring of a geo polygon, without the repeated closing point.
pub fn from_polygon(poly: &Polygon<f64>) -> Vec<Pt> {
    let mut pts: Vec<Pt> = poly.exterior().coords().map(|&c| Pt::from(c)).collect();
    if pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    pts
}

/// Signed area, positive when the ring runs counter-clockwise.
pub fn signed_area(ring: &[Pt]) -> f64 {
    to_polygon(ring).signed_area()
}

/// ∫ r dA over the ring, signed like [`signed_area`]: its centroid's r times its signed
/// area. 2π times it is the volume the ring sweeps turning about the axis (Pappus).
pub fn first_moment_r(ring: &[Pt]) -> f64 {
    let poly = to_polygon(ring);
    let a = poly.signed_area();
    match poly.centroid() {
        Some(c) if a != 0.0 => c.y() * a,
        _ => 0.0,
    }
}

/// `p` strictly inside the ring (a point on its border is not).
pub fn contains(ring: &[Pt], p: Pt) -> bool {
    to_polygon(ring).contains(&geo::Point::from(Coord::from(p)))
}

/// Convex hull of some points, counter-clockwise, without collinear points; non-finite
/// points are ignored. Fewer than three distinct points come back as they are (sorted).
pub fn convex_hull(points: &[Pt]) -> Vec<Pt> {
    let finite: Vec<Coord<f64>> = points
        .iter()
        .filter(|p| p.is_finite())
        .map(|&p| Coord::from(p))
        .collect();
    let hull = geo::MultiPoint::from(finite).convex_hull();
    let mut pts = from_polygon(&hull);
    if pts.len() < 3 {
        pts.sort_by(|a, b| a.z.total_cmp(&b.z).then(a.r.total_cmp(&b.r)));
        pts.dedup();
    }
    pts
}

/// The ring's finite points with repeated (closer than 1e-9 mm) neighbours and a
/// repeated closing point dropped; `None` when fewer than three remain. Rings handed over
/// by cycles and reports may repeat points; measures and drawings need distinct corners.
pub fn cleaned(ring: &[Pt]) -> Option<Vec<Pt>> {
    let mut out: Vec<Pt> = Vec::with_capacity(ring.len());
    for &p in ring {
        if !p.is_finite() || out.last().is_some_and(|q| q.dist(p) < 1e-9) {
            continue;
        }
        out.push(p);
    }
    while out.len() > 1 && out[0].dist(out[out.len() - 1]) < 1e-9 {
        out.pop();
    }
    (out.len() >= 3).then_some(out)
}

/// Box of the ring's points.
pub fn bounds(ring: &[Pt]) -> Rect {
    Rect::of(ring.iter().copied())
}

/// The first place a closed ring crosses or touches itself (neighbouring edges sharing
/// their joint excepted; overlapping collinear pieces count). A sweep over z with early
/// exit: edges are compared only with those whose z ranges overlap, so a simple outline of
/// 10⁵ points is checked in linear-ish time and a tangled one stops at its first crossing
/// (a boolean engine would first split every one of its crossings).
pub fn self_intersection(ring: &[Pt]) -> Option<Pt> {
    let n = ring.len();
    if n < 3 {
        return None;
    }
    // sort edges by their least z to prune: a sweep over z
    let mut edges: Vec<(f64, f64, usize)> = (0..n)
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            (a.z.min(b.z), a.z.max(b.z), i)
        })
        .collect();
    edges.sort_by(|x, y| x.0.total_cmp(&y.0));
    for (k, &(_, hi, i)) in edges.iter().enumerate() {
        for &(lo2, _, j) in &edges[k + 1..] {
            if lo2 > hi + 1e-12 {
                break;
            }
            let adjacent = (i + 1) % n == j || (j + 1) % n == i;
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            let (c, d) = (ring[j], ring[(j + 1) % n]);
            if adjacent {
                // neighbours share one end: only a fold back onto each other is a crossing
                let (p, q, o) = if (i + 1) % n == j {
                    (a, b, d)
                } else {
                    (c, d, b)
                };
                let (u, v) = (q - p, o - q);
                if u.cross(v).abs() <= 1e-12 * u.len() * v.len() && u.dot(v) < 0.0 {
                    return Some(q);
                }
                continue;
            }
            if let Some(x) = segments_cross(a, b, c, d) {
                return Some(x);
            }
        }
    }
    None
}

/// Where segments `ab` and `cd` cross or overlap (within a relative 1e-9), if they do.
fn segments_cross(a: Pt, b: Pt, c: Pt, d: Pt) -> Option<Pt> {
    let r = b - a;
    let s = d - c;
    let den = r.cross(s);
    if den.abs() < 1e-300 {
        // parallel: overlapping collinear pieces count as a crossing
        if (c - a).cross(r).abs() > 1e-12 * r.len().max(1.0) {
            return None;
        }
        let rr = r.len2();
        if rr == 0.0 {
            return None;
        }
        let t0 = (c - a).dot(r) / rr;
        let t1 = (d - a).dot(r) / rr;
        let (lo, hi) = (t0.min(t1), t0.max(t1));
        return (hi > 1e-9 && lo < 1.0 - 1e-9).then(|| a + r * lo.max(0.0));
    }
    let t = (c - a).cross(s) / den;
    let u = (c - a).cross(r) / den;
    let e = 1e-9;
    (t > -e && t < 1.0 + e && u > -e && u < 1.0 + e).then(|| a + r * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(s: f64) -> Vec<Pt> {
        vec![
            Pt::new(0.0, 0.0),
            Pt::new(s, 0.0),
            Pt::new(s, s),
            Pt::new(0.0, s),
        ]
    }

    #[test]
    fn area_moment_and_containment_of_a_square() {
        let sq = square(2.0);
        assert!((signed_area(&sq) - 4.0).abs() < 1e-12);
        let mut cw = sq.clone();
        cw.reverse();
        assert!((signed_area(&cw) + 4.0).abs() < 1e-12);
        // centroid r = 1, area 4: the moment is 4; revolved volume 2π·4 = π(2²)·2
        assert!((first_moment_r(&sq) - 4.0).abs() < 1e-12);
        assert!(contains(&sq, Pt::new(1.0, 1.0)));
        assert!(!contains(&sq, Pt::new(3.0, 1.0)));
    }

    #[test]
    fn cleaning_drops_repeats_and_non_finite_points() {
        let mut r = square(1.0);
        r.insert(1, Pt::new(1e-12, 0.0));
        r.insert(2, Pt::new(f64::NAN, 0.0));
        r.push(Pt::ZERO);
        assert_eq!(cleaned(&r), Some(square(1.0)));
        assert_eq!(cleaned(&[Pt::ZERO, Pt::new(1.0, 0.0), Pt::ZERO]), None);
    }

    #[test]
    fn hull_drops_inner_and_collinear_points() {
        let mut pts = square(1.0);
        pts.push(Pt::new(0.5, 0.5));
        pts.push(Pt::new(0.5, 0.0));
        pts.push(Pt::new(f64::NAN, 0.0));
        let h = convex_hull(&pts);
        assert_eq!(h.len(), 4);
        assert!((signed_area(&h) - 1.0).abs() < 1e-12);
    }
}
