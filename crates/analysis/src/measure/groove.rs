//! How far the final part strays from a G75.1 groove the program defines: the number the
//! groove's detail view shows in its title.

use geom::distance::point_segment;
use geom::{ring, Pt, Rect};
use stock::Shape;

/// Cap on ring samples.
const MAX_SAMPLES: usize = 2000;
/// Cap on part boundary edges considered (beyond it: no number, the measure would be slow).
const MAX_EDGES: usize = 400_000;

/// The largest distance between the groove `ring` and the `part`'s boundary, in mm;
/// `None` when it cannot be measured (fewer than three distinct finite corners, no finite
/// part boundary near the groove, or a part too large to measure quickly).
///
/// Method: the ring is sampled along each edge (every 1/200 of the groove's larger size,
/// at most 2000 samples, vertices included) and each sample's distance to the part's
/// boundary (edges near the groove's box) is taken; the largest is the deviation. Samples
/// on the groove's mouth are skipped: those whose point a quarter of the groove's smaller
/// size outside the ring (along the edge's outward normal) is not inside the part — there
/// the groove opens into air, and the part has no boundary to meet. So leftovers in the
/// groove and floors or flanks cut too deep (by less than that quarter size) count; a
/// narrow dig between samples, or one deeper than the quarter size, may not (the gouge
/// findings report those). Sampling makes this a close lower bound.
pub fn groove_deviation(ring: &[[f64; 2]], part: &[Shape]) -> Option<f64> {
    let ring = ring::cleaned(&ring.iter().map(|&p| Pt::from(p)).collect::<Vec<_>>())?;
    let b = ring::bounds(&ring);
    let size = b.size();
    let near = b.grown(size.max(1e-3));
    let mut edges: Vec<(Pt, Pt)> = Vec::new();
    for r in part_rings(part) {
        let n = r.len();
        for i in 0..n {
            let (a, c) = (r[i], r[(i + 1) % n]);
            if a.is_finite() && c.is_finite() && Rect::of([a, c]).intersects(&near) {
                edges.push((a, c));
            }
        }
    }
    if edges.is_empty() || edges.len() > MAX_EDGES {
        return None;
    }
    let n = ring.len();
    let perimeter: f64 = (0..n).map(|i| ring[i].dist(ring[(i + 1) % n])).sum();
    let step = (size / 200.0).max(perimeter / MAX_SAMPLES as f64).max(1e-9);
    // Outward = away from the ring's inside: right of the direction for a
    // counter-clockwise ring, left for a clockwise one.
    let sign = if ring::signed_area(&ring) >= 0.0 {
        1.0
    } else {
        -1.0
    };
    let rings: Vec<Vec<Pt>> = part_rings(part).collect();
    // Even-odd over all rings of the part.
    let inside = |p: Pt| rings.iter().filter(|r| ring::contains(r, p)).count() % 2 == 1;
    let probe = 0.25 * b.width().min(b.height()).max(1e-3);
    let mut worst: Option<f64> = None;
    for i in 0..n {
        let (a, c) = (ring[i], ring[(i + 1) % n]);
        let len = a.dist(c);
        if len <= 0.0 {
            continue;
        }
        let normal = Pt::new(sign * (c.r - a.r) / len, -sign * (c.z - a.z) / len);
        let k = (len / step).ceil().max(1.0) as usize;
        for j in 0..=k {
            let t = j as f64 / k as f64;
            let p = Pt::new(a.z + t * (c.z - a.z), a.r + t * (c.r - a.r));
            if !inside(Pt::new(p.z + probe * normal.z, p.r + probe * normal.r)) {
                continue;
            }
            let d = edges
                .iter()
                .map(|&(e0, e1)| point_segment(p, e0, e1).0)
                .fold(f64::INFINITY, f64::min);
            if d.is_finite() {
                worst = Some(worst.map_or(d, |w: f64| w.max(d)));
            }
        }
    }
    worst
}

/// Every ring (outer and holes) of the shapes, as points.
fn part_rings(part: &[Shape]) -> impl Iterator<Item = Vec<Pt>> + '_ {
    part.iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .map(|r| r.iter().map(|&p| Pt::from(p)).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trapezoid() -> Vec<[f64; 2]> {
        vec![[30.0, 25.0], [20.0, 15.0], [10.0, 15.0], [-7.32, 25.0]]
    }

    fn bar_minus(groove: &[[f64; 2]]) -> Vec<Shape> {
        let mut outer = vec![[-40.0, 0.0], [40.0, 0.0], [40.0, 25.0]];
        outer.extend(groove.iter().copied());
        outer.push([-40.0, 25.0]);
        vec![Shape {
            outer,
            holes: vec![],
        }]
    }

    #[test]
    fn deviation_of_exact_cut_leftover_and_deep_floor() {
        let r = trapezoid();
        let d = groove_deviation(&r, &bar_minus(&r)).unwrap();
        assert!(d < 1e-9, "{d}");
        // Floor left 0.3 mm high: a leftover.
        let high = [[30.0, 25.0], [20.3, 15.3], [9.9, 15.3], [-7.32, 25.0]];
        let d = groove_deviation(&r, &bar_minus(&high)).unwrap();
        assert!((d - 0.3).abs() < 0.02, "{d}");
        // Floor cut 0.2 mm deep: a gouge.
        let deep = [[30.0, 25.0], [19.8, 14.8], [10.1, 14.8], [-7.32, 25.0]];
        let d = groove_deviation(&r, &bar_minus(&deep)).unwrap();
        assert!((d - 0.2).abs() < 0.02, "{d}");
        assert!(groove_deviation(&r, &[]).is_none());
        assert!(groove_deviation(&r[..2], &bar_minus(&r)).is_none());
    }
}
