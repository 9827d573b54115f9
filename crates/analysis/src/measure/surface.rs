//! The radius of a section's outside or bore at many Z at once, in one sweep along Z: each
//! edge is looked at only while it spans the Z asked, so a measure over every vertex of a
//! section costs n log n plus the crossings instead of n² (a thread over a G75 part of
//! thousands of notches took seconds per measure).

use super::thread::Surface;
use stock::Shape;

/// An edge of a ring: its ends in ring order and the Z it spans.
struct Edge {
    a: [f64; 2],
    b: [f64; 2],
    lo: f64,
    hi: f64,
}

impl Edge {
    /// The radius where the line Z = `z` (within `lo..=hi`) crosses this edge.
    fn radius_at(&self, z: f64) -> f64 {
        let (a, b) = (self.a, self.b);
        a[1] + (z - a[0]) / (b[0] - a[0]) * (b[1] - a[1])
    }
}

/// The edges of `shapes` that span some Z (not radial within 10⁻¹² mm), by their low Z.
fn edges(shapes: &[Shape]) -> Vec<Edge> {
    let mut edges: Vec<Edge> = shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flat_map(|ring| {
            (0..ring.len()).filter_map(move |i| {
                let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
                let (lo, hi) = (a[0].min(b[0]), a[0].max(b[0]));
                (hi - lo >= 1e-12).then_some(Edge { a, b, lo, hi })
            })
        })
        .collect();
    edges.sort_by(|e, f| e.lo.total_cmp(&f.lo));
    edges
}

/// The radius of `surface` at each of `zs` (in any order): where the line Z = z crosses the
/// section's boundaries, the largest crossing (outside) or the smallest (bore); `None`
/// where no material is.
pub(super) fn radii_at(shapes: &[Shape], zs: &[f64], surface: Surface) -> Vec<Option<f64>> {
    let edges = edges(shapes);
    let mut order: Vec<usize> = (0..zs.len()).collect();
    order.sort_by(|&i, &j| zs[i].total_cmp(&zs[j]));
    let mut out = vec![None; zs.len()];
    let (mut spanning, mut next): (Vec<&Edge>, usize) = (vec![], 0);
    for i in order {
        let z = zs[i];
        while next < edges.len() && edges[next].lo <= z {
            spanning.push(&edges[next]);
            next += 1;
        }
        // the Z asked only grow: an edge ending before this one is done with
        spanning.retain(|e| e.hi >= z);
        let crossings = spanning.iter().map(|e| e.radius_at(z));
        out[i] = match surface {
            Surface::Outer => crossings.reduce(f64::max),
            Surface::Bore => crossings.reduce(f64::min),
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A Φ20 tube with a Φ10 bore over Z −10..0, its outside stepped down to Φ16 over
    /// Z −4..−2 with slanted sides.
    fn stepped_tube() -> Vec<Shape> {
        vec![Shape {
            outer: vec![
                [0.0, 5.0],
                [0.0, 10.0],
                [-1.0, 10.0],
                [-2.0, 8.0],
                [-4.0, 8.0],
                [-5.0, 10.0],
                [-10.0, 10.0],
                [-10.0, 5.0],
            ],
            holes: vec![],
        }]
    }

    #[test]
    fn radii_are_the_hand_computed_ones_in_any_order_of_z() {
        let shapes = stepped_tube();
        let zs = [-3.0, -1.5, 0.5, -4.5, -10.0, -0.5];
        let outer = radii_at(&shapes, &zs, Surface::Outer);
        assert_eq!(
            outer,
            [
                Some(8.0),
                Some(9.0),
                None,
                Some(9.0),
                Some(10.0),
                Some(10.0)
            ]
        );
        let bore = radii_at(&shapes, &zs, Surface::Bore);
        assert_eq!(
            bore,
            [Some(5.0), Some(5.0), None, Some(5.0), Some(5.0), Some(5.0)]
        );
    }
}
