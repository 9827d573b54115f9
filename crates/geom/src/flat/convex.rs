//! Hulls and convex parts of rings.

use super::{cross, pts, P};
use crate::{ring, Pt};

/// Convex hull through the kernel ([`crate::ring::convex_hull`]), on `[f64; 2]` points.
pub fn convex_hull(points: &[P]) -> Vec<P> {
    ring::convex_hull(&pts(points))
        .into_iter()
        .map(Pt::to_array)
        .collect()
}

/// True when the ring is convex (either orientation, collinear points allowed).
pub fn is_convex(ring: &[P]) -> bool {
    let n = ring.len();
    if n < 4 {
        return true;
    }
    let (mut pos, mut neg) = (false, false);
    for i in 0..n {
        let c = cross(ring[i], ring[(i + 1) % n], ring[(i + 2) % n]);
        pos |= c > 0.0;
        neg |= c < 0.0;
    }
    !(pos && neg)
}

/// Splits a simple ring into convex parts, each counter-clockwise: the ring itself when it
/// is convex, else the triangles of an ear-clipping triangulation.
pub fn convex_parts(outline: &[P]) -> Vec<Vec<P>> {
    let mut ring: Vec<P> = outline.to_vec();
    if ring::signed_area(&pts(&ring)) < 0.0 {
        ring.reverse();
    }
    if is_convex(&ring) {
        return vec![convex_hull(&ring)];
    }
    let mut idx: Vec<usize> = (0..ring.len()).collect();
    let mut parts = Vec::new();
    let mut guard = 0;
    while idx.len() > 3 && guard < 10 * ring.len() {
        guard += 1;
        let n = idx.len();
        let ear = (0..n).find(|&i| {
            let (a, b, c) = (
                ring[idx[(i + n - 1) % n]],
                ring[idx[i]],
                ring[idx[(i + 1) % n]],
            );
            cross(a, b, c) > 0.0
                && idx.iter().all(|&j| {
                    let p = ring[j];
                    p == a
                        || p == b
                        || p == c
                        || !(cross(a, b, p) >= 0.0
                            && cross(b, c, p) >= 0.0
                            && cross(c, a, p) >= 0.0)
                })
        });
        let Some(i) = ear else { break };
        parts.push(vec![
            ring[idx[(i + n - 1) % n]],
            ring[idx[i]],
            ring[idx[(i + 1) % n]],
        ]);
        idx.remove(i);
    }
    if idx.len() >= 3 {
        parts.push(convex_hull(
            &idx.iter().map(|&i| ring[i]).collect::<Vec<_>>(),
        ));
    }
    parts
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flat::tests::L_SHAPE;

    #[test]
    fn hull_of_square_with_inner_point_is_ccw_square() {
        let h = convex_hull(&[
            [0.0, 0.0],
            [1.0, 1.0],
            [0.5, 0.5],
            [1.0, 0.0],
            [0.0, 1.0],
            [0.5, 0.0],
        ]);
        assert_eq!(h.len(), 4);
        assert!((2.0 * ring::signed_area(&pts(&h)) - 2.0).abs() < 1e-12);
    }

    #[test]
    fn l_shape_splits_into_convex_parts_of_the_same_area() {
        let l = L_SHAPE;
        let parts = convex_parts(&l);
        assert!(parts.len() > 1);
        let total: f64 = parts
            .iter()
            .map(|p| 2.0 * ring::signed_area(&pts(p)) / 2.0)
            .sum();
        assert!((total - 3.0).abs() < 1e-12);
        assert!(parts
            .iter()
            .all(|p| is_convex(p) && 2.0 * ring::signed_area(&pts(p)) > 0.0));
    }
}
