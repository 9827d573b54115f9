//! Where a leftover is thickest: the largest leftover region (by area) and its thickest
//! place, measured as the distance from the leftover's boundary to the intended shape's
//! boundary (the leftover lies between the final part's edge and the intended edge, so
//! its farthest boundary point from the intended edge is where most material is left).

use crate::Shape;
use geom::distance::point_segment;
use geom::{ring, Pt, Rect};

/// Cap on point-to-segment distance evaluations (points are sampled with a stride above
/// it), so a finely chorded profile stays fast.
const MAX_EVALS: usize = 20_000_000;

/// The thickest place of the largest leftover.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeftoverSpot {
    /// Which leftover (index into the list measured): the largest by area.
    pub leftover: usize,
    /// The thickness: the leftover's boundary point farthest from the intended boundary,
    /// the nearest intended point to it, and their distance (mm); `None` when no intended
    /// shape is known.
    pub thickest: Option<([f64; 2], [f64; 2], f64)>,
    /// A point to look at, `[z, r]`: midway along the thickness, or (without an intended
    /// shape) the leftover's vertex nearest the middle of its box.
    pub centre: [f64; 2],
}

/// The thickest place of the largest of `leftovers` (by area) against the `intended`
/// shapes' boundary; `None` when no leftover has an area or a finite point.
pub fn leftover_spot(leftovers: &[Shape], intended: &[Shape]) -> Option<LeftoverSpot> {
    let (index, shape) = leftovers
        .iter()
        .enumerate()
        .map(|(i, s)| (i, s, shape_area(s)))
        .filter(|(_, _, a)| *a > 0.0)
        .max_by(|a, b| a.2.total_cmp(&b.2))
        .map(|(i, s, _)| (i, s))?;
    let pts = samples(shape);
    if pts.is_empty() {
        return None;
    }
    let segs = segments(intended);
    if segs.is_empty() {
        // No intended edge to measure from: the vertex nearest the box's middle.
        let mid = Rect::of(pts.iter().copied()).center();
        let centre = *pts
            .iter()
            .min_by(|a, b| (**a - mid).len2().total_cmp(&(**b - mid).len2()))?;
        return Some(LeftoverSpot {
            leftover: index,
            thickest: None,
            centre: centre.to_array(),
        });
    }
    let stride = (pts.len() * segs.len()).div_ceil(MAX_EVALS).max(1);
    let mut best: Option<(Pt, Pt, f64)> = None;
    for &p in pts.iter().step_by(stride) {
        let (d, q) = segs
            .iter()
            .map(|&(a, b)| point_segment(p, a, b))
            .min_by(|a, b| a.0.total_cmp(&b.0))?;
        if d.is_finite() && best.is_none_or(|b| d > b.2) {
            best = Some((p, q, d));
        }
    }
    let (p, q, d) = best?;
    Some(LeftoverSpot {
        leftover: index,
        thickest: Some((p.to_array(), q.to_array(), d)),
        centre: [(p.z + q.z) / 2.0, (p.r + q.r) / 2.0],
    })
}

/// Area of a shape (outer ring less its holes, mm²); rings with a non-finite point count 0.
fn shape_area(s: &Shape) -> f64 {
    let ring_area = |r: &[[f64; 2]]| {
        let a = ring::signed_area(&r.iter().map(|&p| Pt::from(p)).collect::<Vec<_>>()).abs();
        if a.is_finite() {
            a
        } else {
            0.0
        }
    };
    let holes: f64 = s.holes.iter().map(|h| ring_area(h)).sum();
    (ring_area(&s.outer) - holes).max(0.0)
}

/// The finite points of each ring (outer and holes) of the shapes.
fn finite_rings(shapes: &[Shape]) -> impl Iterator<Item = Vec<Pt>> + '_ {
    shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(&s.holes))
        .map(|r| {
            r.iter()
                .map(|&p| Pt::from(p))
                .filter(|p| p.is_finite())
                .collect()
        })
}

/// The edges of all rings of some shapes (closing edges included).
fn segments(shapes: &[Shape]) -> Vec<(Pt, Pt)> {
    let mut out = Vec::new();
    for pts in finite_rings(shapes).filter(|r| r.len() >= 2) {
        for i in 0..pts.len() {
            out.push((pts[i], pts[(i + 1) % pts.len()]));
        }
    }
    out
}

/// The leftover's boundary points to measure from: its vertices and edge midpoints.
fn samples(s: &Shape) -> Vec<Pt> {
    let mut out = Vec::new();
    for pts in finite_rings(std::slice::from_ref(s)) {
        for i in 0..pts.len() {
            let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
            out.push(p);
            out.push(Pt::new((p.z + q.z) / 2.0, (p.r + q.r) / 2.0));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sq(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
        Shape {
            outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
            holes: vec![],
        }
    }

    #[test]
    fn area_and_largest() {
        let mut s = sq(0.0, 10.0, 0.0, 2.0);
        assert!((shape_area(&s) - 20.0).abs() < 1e-12);
        s.holes
            .push(vec![[1.0, 0.5], [1.0, 1.5], [2.0, 1.5], [2.0, 0.5]]);
        assert!((shape_area(&s) - 19.0).abs() < 1e-12);
        let leftovers = [sq(0.0, 1.0, 0.0, 1.0), s, sq(5.0, 6.0, 0.0, 3.0)];
        assert_eq!(leftover_spot(&leftovers, &[]).unwrap().leftover, 1);
        assert_eq!(leftover_spot(&[], &[]), None);
        assert_eq!(leftover_spot(&[sq(0.0, 0.0, 0.0, 1.0)], &[]), None);
    }

    #[test]
    fn thickest_place_of_a_band_is_at_a_shoulder_edge() {
        // Intended: a shoulder at Z-30 from r20 up to r30; the part left 0.25 mm big.
        let intended = Shape {
            outer: vec![
                [-100.0, 0.0],
                [0.0, 0.0],
                [0.0, 20.0],
                [-30.0, 20.0],
                [-30.0, 30.0],
                [-100.0, 30.0],
            ],
            holes: vec![],
        };
        let band = Shape {
            outer: vec![
                [0.0, 20.0],
                [0.0, 20.25],
                [-29.75, 20.25],
                [-29.75, 30.25],
                [-100.0, 30.25],
                [-100.0, 30.0],
                [-30.0, 30.0],
                [-30.0, 20.0],
            ],
            holes: vec![],
        };
        let s = leftover_spot(std::slice::from_ref(&band), &[intended]).unwrap();
        let t = s.thickest.unwrap().2;
        assert!((t - 0.25 * 2f64.sqrt()).abs() < 1e-9, "{t}");
        // Around the shoulder's outer edge (Z-30 r30), where the band turns the corner.
        assert!((s.centre[0] + 29.875).abs() < 1e-9 && (s.centre[1] - 30.125).abs() < 1e-9);
        // Without an intended shape: a vertex near the middle of the box, no thickness.
        let s = leftover_spot(&[band], &[]).unwrap();
        assert_eq!(s.thickest, None);
        let c = s.centre;
        assert!(
            (-100.0..=0.0).contains(&c[0]) && (20.0..=30.25).contains(&c[1]),
            "{c:?}"
        );
    }
}
