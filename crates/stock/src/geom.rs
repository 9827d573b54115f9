//! The removal's own plane geometry on `[f64; 2]` points (z, r): convex parts, sweeps of a
//! convex polygon, clipping to a box. Area, hulls, containment, distances and boxes come
//! from the `geom` kernel.

use geom::{orient, ring, Pt, Rect};

/// A point (z, r) in mm.
pub(crate) type P = [f64; 2];

/// Points as kernel points.
pub(crate) fn pts(ring: &[P]) -> Vec<Pt> {
    ring.iter().map(|&p| Pt::from(p)).collect()
}

/// Convex hull through the kernel ([`geom::ring::convex_hull`]), on `[f64; 2]` points.
pub(crate) fn convex_hull(points: &[P]) -> Vec<P> {
    ring::convex_hull(&pts(points))
        .into_iter()
        .map(Pt::to_array)
        .collect()
}

fn cross(o: P, a: P, b: P) -> f64 {
    orient(o.into(), a.into(), b.into())
}

/// True when the ring is convex (either orientation, collinear points allowed).
pub(crate) fn is_convex(ring: &[P]) -> bool {
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
pub(crate) fn convex_parts(outline: &[P]) -> Vec<Vec<P>> {
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

/// The Minkowski sum of a convex counter-clockwise polygon with the segment `[0, d]`:
/// the area the polygon sweeps when translated by `d`. Linear time.
pub(crate) fn sweep_convex(poly: &[P], d: P) -> Vec<P> {
    let n = poly.len();
    let mut out = Vec::with_capacity(n + 2);
    if n == 0 {
        return out;
    }
    // an edge faces forward when its outward normal has a positive component along d
    let front = |i: usize| {
        let a = poly[i];
        let b = poly[(i + 1) % n];
        d[0] * (b[1] - a[1]) - d[1] * (b[0] - a[0]) > 0.0
    };
    let moved = |p: P| [p[0] + d[0], p[1] + d[1]];
    for (i, &p) in poly.iter().enumerate() {
        let (fin, fout) = (front((i + n - 1) % n), front(i));
        match (fin, fout) {
            (false, false) => out.push(p),
            (true, true) => out.push(moved(p)),
            (false, true) => {
                out.push(p);
                out.push(moved(p));
            }
            (true, false) => {
                out.push(moved(p));
                out.push(p);
            }
        }
    }
    out
}

/// Clips a convex polygon to a box (Sutherland–Hodgman); the result stays convex.
pub(crate) fn clip_convex(poly: &[P], rect: &Rect) -> Vec<P> {
    let mut cur: Vec<P> = poly.to_vec();
    // (axis, bound, keep when coordinate >= bound)
    let planes = [
        (0, rect.min.z, true),
        (0, rect.max.z, false),
        (1, rect.min.r, true),
        (1, rect.max.r, false),
    ];
    for (axis, bound, ge) in planes {
        if cur.is_empty() {
            break;
        }
        let inside = |p: &P| {
            if ge {
                p[axis] >= bound
            } else {
                p[axis] <= bound
            }
        };
        if cur.iter().all(inside) {
            continue;
        }
        let mut next = Vec::with_capacity(cur.len() + 2);
        for i in 0..cur.len() {
            let a = cur[i];
            let b = cur[(i + 1) % cur.len()];
            let (ia, ib) = (inside(&a), inside(&b));
            if ia {
                next.push(a);
            }
            if ia != ib {
                let t = (bound - a[axis]) / (b[axis] - a[axis]);
                let mut q = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                q[axis] = bound;
                next.push(q);
            }
        }
        cur = next;
    }
    cur
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn sweep_of_unit_square_is_the_long_rectangle() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let s = sweep_convex(&sq, [5.0, 2.0]);
        let h = convex_hull(
            &[
                sq.to_vec(),
                sq.iter().map(|p| [p[0] + 5.0, p[1] + 2.0]).collect(),
            ]
            .concat(),
        );
        assert!(
            (2.0 * ring::signed_area(&pts(&s)) - 2.0 * ring::signed_area(&pts(&h))).abs() < 1e-12
        );
        let s = sweep_convex(&sq, [-3.0, 0.0]);
        assert!((2.0 * ring::signed_area(&pts(&s)) - 8.0).abs() < 1e-12);
    }

    #[test]
    fn clip_keeps_the_inside_part() {
        let sq = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let c = clip_convex(&sq, &Rect::new(Pt::new(1.0, -1.0), Pt::new(2.0, 2.0)));
        assert!((2.0 * ring::signed_area(&pts(&c)) / 2.0 - 2.0).abs() < 1e-12);
    }

    #[test]
    fn l_shape_splits_into_convex_parts_of_the_same_area() {
        let l = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
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
