//! Measures on shape sets: area, volume of revolution, symmetric difference, Hausdorff.

use crate::geom::{pts, P};
use crate::overlay::{boolean, BoolOp};
use crate::Shape;
use geom::distance::point_segment;
use geom::{ring, Pt, Rect};

/// Area in mm² of a shape set (outer areas minus hole areas, whatever the ring orientation).
pub fn area(shapes: &[Shape]) -> f64 {
    shapes
        .iter()
        .map(|s| {
            ring::signed_area(&pts(&s.outer)).abs()
                - s.holes
                    .iter()
                    .map(|h| ring::signed_area(&pts(h)).abs())
                    .sum::<f64>()
        })
        .sum()
}

/// Volume in mm³ of the solid of revolution of a shape set about the Z axis (Pappus:
/// 2π ∫ r dA). Shapes are expected at r ≥ 0.
pub fn revolved_volume(shapes: &[Shape]) -> f64 {
    let moment = |r: &Vec<P>| {
        let r = pts(r);
        ring::first_moment_r(&r) * ring::signed_area(&r).signum()
    };
    let m: f64 = shapes
        .iter()
        .map(|s| moment(&s.outer) - s.holes.iter().map(moment).sum::<f64>())
        .sum();
    std::f64::consts::TAU * m
}

/// Area in mm² of (a − b) ∪ (b − a).
pub fn symmetric_difference_area(a: &[Shape], b: &[Shape]) -> f64 {
    area(&boolean(a, b, BoolOp::Xor))
}

/// Hausdorff distance between the boundaries of `a` and `b`, mm.
///
/// Distances are exact point-to-segment distances from sample points of one boundary to
/// the edges of the other, both ways. Every edge is sampled at its vertices and at a
/// spacing h = max(total boundary length × 10⁻⁶, 10⁻⁵ mm), so the result d satisfies
/// d ≤ H ≤ d + h/2 (the distance to a set is 1-Lipschitz). 0 when both sets are empty,
/// infinity when only one is.
pub fn hausdorff(a: &[Shape], b: &[Shape]) -> f64 {
    let (ea, eb) = (edges(a), edges(b));
    match (ea.is_empty(), eb.is_empty()) {
        (true, true) => return 0.0,
        (true, false) | (false, true) => return f64::INFINITY,
        _ => {}
    }
    let len: f64 = ea
        .iter()
        .chain(eb.iter())
        .map(|(p, q)| (q[0] - p[0]).hypot(q[1] - p[1]))
        .sum();
    let h = (len * 1e-6).max(1e-5);
    directed(&ea, &eb, h).max(directed(&eb, &ea, h))
}

fn edges(shapes: &[Shape]) -> Vec<(P, P)> {
    let mut out = Vec::new();
    for s in shapes {
        for r in std::iter::once(&s.outer).chain(s.holes.iter()) {
            if r.iter().any(|p| !(p[0].is_finite() && p[1].is_finite())) {
                continue;
            }
            for i in 0..r.len() {
                out.push((r[i], r[(i + 1) % r.len()]));
            }
        }
    }
    out
}

/// sup over sample points of `from` of the distance to the edges of `to`.
fn directed(from: &[(P, P)], to: &[(P, P)], h: f64) -> f64 {
    let index = SegIndex::new(to);
    let mut worst: f64 = 0.0;
    for &(p, q) in from {
        let len = (q[0] - p[0]).hypot(q[1] - p[1]);
        let n = ((len / h).ceil() as usize).clamp(1, 10_000_000);
        for i in 0..n {
            let t = i as f64 / n as f64;
            let s = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            // the sample cannot raise the maximum when it is closer than `worst`: the
            // index search stops as soon as it proves that
            worst = worst.max(index.nearest(s, worst));
        }
    }
    worst
}

/// A uniform grid over segments for nearest-segment queries.
struct SegIndex<'a> {
    segs: &'a [(P, P)],
    origin: P,
    cell: f64,
    nx: i64,
    ny: i64,
    cells: Vec<Vec<u32>>,
}

impl<'a> SegIndex<'a> {
    fn new(segs: &'a [(P, P)]) -> Self {
        let rect = Rect::of(segs.iter().flat_map(|&(p, q)| [Pt::from(p), Pt::from(q)]));
        let w = rect.width().max(1e-9);
        let hgt = rect.height().max(1e-9);
        let n = (segs.len() as f64).max(1.0);
        let cell = ((w * hgt / n).sqrt()).max(w.max(hgt) / 4096.0).max(1e-9);
        let nx = ((w / cell).ceil() as i64).clamp(1, 4096);
        let ny = ((hgt / cell).ceil() as i64).clamp(1, 4096);
        let mut cells = vec![Vec::new(); (nx * ny) as usize];
        for (k, (p, q)) in segs.iter().enumerate() {
            let c = |v: f64, o: f64, m: i64| (((v - o) / cell).floor() as i64).clamp(0, m - 1);
            let (x0, x1) = (
                c(p[0].min(q[0]), rect.min.z, nx),
                c(p[0].max(q[0]), rect.min.z, nx),
            );
            let (y0, y1) = (
                c(p[1].min(q[1]), rect.min.r, ny),
                c(p[1].max(q[1]), rect.min.r, ny),
            );
            for ix in x0..=x1 {
                for iy in y0..=y1 {
                    cells[(ix * ny + iy) as usize].push(k as u32);
                }
            }
        }
        Self {
            segs,
            origin: rect.min.to_array(),
            cell,
            nx,
            ny,
            cells,
        }
    }

    /// Distance from `p` to the nearest segment; may stop early with any value ≤ `enough`
    /// once the true distance is known to be at most `enough`.
    fn nearest(&self, p: P, enough: f64) -> f64 {
        let cx = ((p[0] - self.origin[0]) / self.cell)
            .floor()
            .clamp(-1e12, 1e12) as i64;
        let cy = ((p[1] - self.origin[1]) / self.cell)
            .floor()
            .clamp(-1e12, 1e12) as i64;
        let outside = [cx - (self.nx - 1), -cx, cy - (self.ny - 1), -cy]
            .into_iter()
            .max()
            .unwrap_or(0)
            .max(0);
        let mut best = f64::INFINITY;
        let mut k = outside;
        let kmax = outside + self.nx + self.ny + 2;
        while k <= kmax {
            let mut visit = |ix: i64, iy: i64| {
                if ix >= 0 && ix < self.nx && iy >= 0 && iy < self.ny {
                    for &s in &self.cells[(ix * self.ny + iy) as usize] {
                        let (a, b) = self.segs[s as usize];
                        best = best.min(point_segment(p.into(), a.into(), b.into()).0);
                    }
                }
            };
            if k == 0 {
                visit(cx, cy);
            } else {
                for ix in (cx - k)..=(cx + k) {
                    if ix >= 0 && ix < self.nx {
                        visit(ix, cy - k);
                        visit(ix, cy + k);
                    }
                }
                for iy in (cy - k + 1)..=(cy + k - 1) {
                    if iy >= 0 && iy < self.ny {
                        visit(cx - k, iy);
                        visit(cx + k, iy);
                    }
                }
            }
            // everything in later rings is at least k cells away
            if best <= k as f64 * self.cell || best <= enough {
                break;
            }
            k += 1;
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(z0: f64, r0: f64, s: f64) -> Shape {
        Shape {
            outer: vec![[z0, r0], [z0 + s, r0], [z0 + s, r0 + s], [z0, r0 + s]],
            holes: vec![],
        }
    }

    #[test]
    fn areas_and_symmetric_difference_of_known_squares() {
        let a = [square(0.0, 0.0, 2.0)];
        let b = [square(1.0, 0.0, 2.0)];
        assert!((area(&a) - 4.0).abs() < 1e-12);
        // overlap 1 x 2 = 2, so each keeps 2 of its own: 4
        assert!((symmetric_difference_area(&a, &b) - 4.0).abs() < 1e-9);
        assert!(symmetric_difference_area(&a, &a) < 1e-12);
        let mut holed = square(0.0, 0.0, 4.0);
        holed
            .holes
            .push(vec![[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]]);
        assert!((area(&[holed]) - 15.0).abs() < 1e-12);
    }

    #[test]
    fn volume_of_a_bar_is_pi_r2_l() {
        let bar = [square(-10.0, 0.0, 10.0)];
        assert!((revolved_volume(&bar) - std::f64::consts::PI * 100.0 * 10.0).abs() < 1e-9);
    }

    #[test]
    fn hausdorff_of_known_squares() {
        let a = [square(0.0, 0.0, 2.0)];
        // shifted by 0.5 in z: every boundary point is within 0.5 of the other
        let b = [square(0.5, 0.0, 2.0)];
        assert!((hausdorff(&a, &b) - 0.5).abs() < 1e-9);
        // a square inside a bigger one: the far corner of the big one is sqrt(2)*1 away
        let big = [square(-1.0, -1.0, 4.0)];
        assert!((hausdorff(&a, &big) - 2f64.sqrt()).abs() < 1e-9);
        // the middle of a long edge counts, not only the vertices
        let long = [Shape {
            outer: vec![[0.0, 0.0], [10.0, 0.0], [10.0, 1.0], [0.0, 1.0]],
            holes: vec![],
        }];
        let dented = [Shape {
            outer: vec![[0.0, 0.0], [10.0, 0.0], [10.0, 1.0], [5.0, 0.7], [0.0, 1.0]],
            holes: vec![],
        }];
        assert!((hausdorff(&long, &dented) - 0.3).abs() < 1e-5);
        assert_eq!(hausdorff(&[], &[]), 0.0);
        assert!(hausdorff(&a, &[]).is_infinite());
    }
}
