//! Where to zoom on a leftover: the largest leftover region (by area) and its thickest
//! place, measured as the distance from the leftover's boundary to the intended shape's
//! boundary (the leftover lies between the final part's edge and the intended edge, so
//! its farthest boundary point from the intended edge is where most material is left).

use crate::report::{Report, Shape};
use crate::scale::Bbox;
use geom::distance::point_segment;
use geom::{ring, Pt};

/// Cap on point-to-segment distance evaluations per leftover (points are sampled with a
/// stride above it), so a finely chorded profile stays fast.
const MAX_EVALS: usize = 20_000_000;

/// The place to show of one leftover region.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Spot {
    /// Centre of the view, `[z, r]`: midway between the leftover's farthest point and
    /// the nearest intended point (or a leftover vertex when no intended shape is known).
    pub(crate) centre: [f64; 2],
    /// The leftover's thickness there, mm (`None` when no intended shape is known).
    pub(crate) thickness: Option<f64>,
    /// Where the thickness is measured: from the leftover's farthest point to the
    /// nearest intended point (`None` when no intended shape is known).
    pub(crate) measure: Option<[[f64; 2]; 2]>,
}

/// Area of a ring (absolute, the `geom` kernel's); 0 for rings with non-finite points.
fn ring_area(ring: &[[f64; 2]]) -> f64 {
    let pts: Vec<Pt> = ring.iter().map(|&p| Pt::from(p)).collect();
    let a = ring::signed_area(&pts).abs();
    if a.is_finite() {
        a
    } else {
        0.0
    }
}

/// Area of a shape: outer ring less its holes, mm².
pub(crate) fn area(s: &Shape) -> f64 {
    let holes: f64 = s.holes.iter().map(|h| ring_area(h)).sum();
    (ring_area(&s.outer) - holes).max(0.0)
}

/// The largest leftover by area, if any has an area.
pub(crate) fn largest(report: &Report) -> Option<&Shape> {
    report
        .leftovers
        .iter()
        .map(|s| (s, area(s)))
        .filter(|(_, a)| *a > 0.0)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(s, _)| s)
}

fn finite(p: &[f64; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// The segments of all rings of some shapes (closing edges included).
fn segments(shapes: &[Shape]) -> Vec<([f64; 2], [f64; 2])> {
    let mut out = Vec::new();
    for s in shapes {
        for ring in std::iter::once(&s.outer).chain(&s.holes) {
            let pts: Vec<[f64; 2]> = ring.iter().copied().filter(finite).collect();
            if pts.len() < 2 {
                continue;
            }
            for i in 0..pts.len() {
                out.push((pts[i], pts[(i + 1) % pts.len()]));
            }
        }
    }
    out
}

/// The leftover's boundary points to measure from: its vertices and edge midpoints.
fn samples(s: &Shape) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    for ring in std::iter::once(&s.outer).chain(&s.holes) {
        let pts: Vec<[f64; 2]> = ring.iter().copied().filter(finite).collect();
        for i in 0..pts.len() {
            let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
            out.push(p);
            out.push([(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0]);
        }
    }
    out
}

/// The thickest place of `leftover` against the `intended` shapes' boundary; `None`
/// when the leftover has no finite point.
pub(crate) fn thickest(leftover: &Shape, intended: &[Shape]) -> Option<Spot> {
    let pts = samples(leftover);
    if pts.is_empty() {
        return None;
    }
    let segs = segments(intended);
    if segs.is_empty() {
        // No intended edge to measure from: the vertex nearest the box's middle.
        let mut b = Bbox::EMPTY;
        for p in &pts {
            b.add(*p);
        }
        let mid = [(b.zmin + b.zmax) / 2.0, (b.rmin + b.rmax) / 2.0];
        let d2 = |p: &[f64; 2]| (p[0] - mid[0]).powi(2) + (p[1] - mid[1]).powi(2);
        let centre = *pts.iter().min_by(|a, b| d2(a).total_cmp(&d2(b)))?;
        return Some(Spot {
            centre,
            thickness: None,
            measure: None,
        });
    }
    let stride = (pts.len() * segs.len()).div_ceil(MAX_EVALS).max(1);
    let mut best: Option<([f64; 2], [f64; 2], f64)> = None;
    for &p in pts.iter().step_by(stride) {
        let (d, q) = segs
            .iter()
            .map(|&(a, b)| point_segment(p.into(), a.into(), b.into()))
            .min_by(|a, b| a.0.total_cmp(&b.0))?;
        if d.is_finite() && best.is_none_or(|b| d > b.2) {
            best = Some((p, q.to_array(), d));
        }
    }
    let (p, q, d) = best?;
    Some(Spot {
        centre: [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0],
        thickness: Some(d),
        measure: Some([p, q]),
    })
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
        assert!((area(&s) - 20.0).abs() < 1e-12);
        s.holes
            .push(vec![[1.0, 0.5], [1.0, 1.5], [2.0, 1.5], [2.0, 0.5]]);
        assert!((area(&s) - 19.0).abs() < 1e-12);
        let r = Report {
            leftovers: vec![sq(0.0, 1.0, 0.0, 1.0), s.clone(), sq(5.0, 6.0, 0.0, 3.0)],
            ..Report::default()
        };
        assert_eq!(largest(&r), Some(&s));
        assert_eq!(largest(&Report::default()), None);
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
        let s = thickest(&band, &[intended]).unwrap();
        let t = s.thickness.unwrap();
        assert!((t - 0.25 * 2f64.sqrt()).abs() < 1e-9, "{t}");
        // Around the shoulder's outer edge (Z-30 r30), where the band turns the corner.
        assert!((s.centre[0] + 29.875).abs() < 1e-9 && (s.centre[1] - 30.125).abs() < 1e-9);
        // Without an intended shape: a vertex near the middle of the box, no thickness.
        let s = thickest(&band, &[]).unwrap();
        assert_eq!(s.thickness, None);
        let c = s.centre;
        assert!(
            (-100.0..=0.0).contains(&c[0]) && (20.0..=30.25).contains(&c[1]),
            "{c:?}"
        );
    }
}
