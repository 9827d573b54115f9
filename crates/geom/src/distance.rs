//! Distances: point to segment, point to polyline (parry2d-f64's BVH), Hausdorff.

use crate::Pt;
use parry2d_f64::math::Vector;
use parry2d_f64::query::PointQuery;
use parry2d_f64::shape::Polyline;

/// Distance from `p` to the segment `[a, b]` and the nearest point on it.
pub fn point_segment(p: Pt, a: Pt, b: Pt) -> (f64, Pt) {
    let d = b - a;
    let len2 = d.len2();
    let t = if len2 > 0.0 {
        ((p - a).dot(d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = a + d * t;
    (p.dist(q), q)
}

/// Many nearest-point queries against one set of edges: parry2d-f64's polyline with its
/// bounding-volume tree (built once, each query logarithmic).
pub struct EdgeIndex {
    shape: Option<Polyline>,
}

impl EdgeIndex {
    /// An index over edges `(a, b)` (open polylines and closed rings alike).
    pub fn new(edges: impl IntoIterator<Item = (Pt, Pt)>) -> Self {
        let mut vertices = Vec::new();
        let mut indices = Vec::new();
        for (a, b) in edges {
            let i = vertices.len() as u32;
            vertices.push(Vector::new(a.z, a.r));
            vertices.push(Vector::new(b.z, b.r));
            indices.push([i, i + 1]);
        }
        let shape = (!indices.is_empty()).then(|| Polyline::new(vertices, Some(indices)));
        Self { shape }
    }
    /// The index over the edges of closed rings.
    pub fn of_rings<'a>(rings: impl IntoIterator<Item = &'a [Pt]>) -> Self {
        Self::new(rings.into_iter().flat_map(|ring| {
            let n = ring.len();
            (0..n).map(move |i| (ring[i], ring[(i + 1) % n]))
        }))
    }
    /// The nearest point on any edge and its distance; `None` without edges.
    pub fn nearest(&self, p: Pt) -> Option<(f64, Pt)> {
        let shape = self.shape.as_ref()?;
        let proj = shape.project_local_point(Vector::new(p.z, p.r), false);
        let q = Pt::new(proj.point.x, proj.point.y);
        Some((p.dist(q), q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_distance_clamps_to_the_ends() {
        let (d, q) = point_segment(Pt::new(5.0, 1.0), Pt::ZERO, Pt::new(2.0, 0.0));
        assert!((d - 10f64.sqrt()).abs() < 1e-12);
        assert_eq!(q, Pt::new(2.0, 0.0));
        let (d, _) = point_segment(Pt::new(1.0, 3.0), Pt::ZERO, Pt::new(2.0, 0.0));
        assert!((d - 3.0).abs() < 1e-12);
    }

    #[test]
    fn edge_index_finds_the_nearest_edge() {
        let sq = [
            Pt::new(0.0, 0.0),
            Pt::new(4.0, 0.0),
            Pt::new(4.0, 4.0),
            Pt::new(0.0, 4.0),
        ];
        let idx = EdgeIndex::of_rings([&sq[..]]);
        let (d, q) = idx.nearest(Pt::new(1.0, 1.5)).unwrap();
        assert!((d - 1.0).abs() < 1e-12);
        assert!(q.dist(Pt::new(0.0, 1.5)) < 1e-12);
        let (d, _) = idx.nearest(Pt::new(7.0, 8.0)).unwrap();
        assert!((d - 5.0).abs() < 1e-12);
        assert!(EdgeIndex::new([]).nearest(Pt::ZERO).is_none());
    }
}
