//! Small plane-geometry helpers on `[f64; 2]` points (z, r).

/// A point (z, r) in mm.
pub(crate) type P = [f64; 2];

/// Twice the signed area of a ring (positive when counter-clockwise).
pub(crate) fn signed_area2(ring: &[P]) -> f64 {
    let n = ring.len();
    let mut s = 0.0;
    for i in 0..n {
        let a = ring[i];
        let b = ring[(i + 1) % n];
        s += a[0] * b[1] - b[0] * a[1];
    }
    s
}

/// ∫ r dA over a ring (signed like [`signed_area2`]); 2π times it is the volume of revolution.
pub(crate) fn first_moment_r(ring: &[P]) -> f64 {
    let n = ring.len();
    let mut s = 0.0;
    for i in 0..n {
        let a = ring[i];
        let b = ring[(i + 1) % n];
        s += (a[0] * b[1] - b[0] * a[1]) * (a[1] + b[1]);
    }
    s / 6.0
}

fn cross(o: P, a: P, b: P) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// Convex hull, counter-clockwise, without collinear points (Andrew's monotone chain).
/// Non-finite points are ignored.
pub(crate) fn convex_hull(points: &[P]) -> Vec<P> {
    let mut pts: Vec<P> = points
        .iter()
        .copied()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .collect();
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let mut hull: Vec<P> = Vec::with_capacity(pts.len() + 1);
    for &p in &pts {
        while hull.len() >= 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        hull.push(p);
    }
    // the upper chain may not eat into the lower one
    let lower = hull.len() + 1;
    for &p in pts.iter().rev().skip(1) {
        while hull.len() >= lower && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        hull.push(p);
    }
    hull.pop();
    hull
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
pub(crate) fn convex_parts(ring: &[P]) -> Vec<Vec<P>> {
    let mut ring: Vec<P> = ring.to_vec();
    if signed_area2(&ring) < 0.0 {
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

/// An axis-aligned box; empty when `min > max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rect {
    pub(crate) min: P,
    pub(crate) max: P,
}

impl Rect {
    /// The empty box (the identity of [`Rect::add`]).
    pub(crate) const EMPTY: Self = Self {
        min: [f64::INFINITY; 2],
        max: [f64::NEG_INFINITY; 2],
    };

    /// Grows the box to include `p`.
    pub(crate) fn add(&mut self, p: P) {
        self.min = [self.min[0].min(p[0]), self.min[1].min(p[1])];
        self.max = [self.max[0].max(p[0]), self.max[1].max(p[1])];
    }

    /// Box of some points.
    pub(crate) fn of<'a>(pts: impl IntoIterator<Item = &'a P>) -> Self {
        let mut r = Self::EMPTY;
        for p in pts {
            r.add(*p);
        }
        r
    }

    /// True when nothing was added.
    pub(crate) fn is_empty(&self) -> bool {
        !(self.min[0] <= self.max[0] && self.min[1] <= self.max[1])
    }

    /// The box grown by `m` on every side.
    pub(crate) fn grown(&self, m: f64) -> Self {
        Self {
            min: [self.min[0] - m, self.min[1] - m],
            max: [self.max[0] + m, self.max[1] + m],
        }
    }

    /// Width or height, whichever is larger.
    pub(crate) fn size(&self) -> f64 {
        (self.max[0] - self.min[0]).max(self.max[1] - self.min[1])
    }
}

/// Clips a convex polygon to a box (Sutherland–Hodgman); the result stays convex.
pub(crate) fn clip_convex(poly: &[P], rect: &Rect) -> Vec<P> {
    let mut cur: Vec<P> = poly.to_vec();
    // (axis, bound, keep when coordinate >= bound)
    let planes = [
        (0, rect.min[0], true),
        (0, rect.max[0], false),
        (1, rect.min[1], true),
        (1, rect.max[1], false),
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

/// Distance from `p` to the segment `[a, b]` and the nearest point on it.
pub(crate) fn point_segment(p: P, a: P, b: P) -> (f64, P) {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = [a[0] + t * d[0], a[1] + t * d[1]];
    ((p[0] - q[0]).hypot(p[1] - q[1]), q)
}

/// Even-odd point-in-ring test.
pub(crate) fn point_in_ring(p: P, ring: &[P]) -> bool {
    let n = ring.len();
    let mut inside = false;
    for i in 0..n {
        let a = ring[i];
        let b = ring[(i + 1) % n];
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let z = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < z {
                inside = !inside;
            }
        }
    }
    inside
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
        assert!((signed_area2(&h) - 2.0).abs() < 1e-12);
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
        assert!((signed_area2(&s) - signed_area2(&h)).abs() < 1e-12);
        let s = sweep_convex(&sq, [-3.0, 0.0]);
        assert!((signed_area2(&s) - 8.0).abs() < 1e-12);
    }

    #[test]
    fn clip_keeps_the_inside_part() {
        let sq = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let c = clip_convex(
            &sq,
            &Rect {
                min: [1.0, -1.0],
                max: [2.0, 2.0],
            },
        );
        assert!((signed_area2(&c) / 2.0 - 2.0).abs() < 1e-12);
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
        let total: f64 = parts.iter().map(|p| signed_area2(p) / 2.0).sum();
        assert!((total - 3.0).abs() < 1e-12);
        assert!(parts.iter().all(|p| is_convex(p) && signed_area2(p) > 0.0));
    }
}
