//! The removal's own plane geometry on `[f64; 2]` points (z, r): convex parts, sweeps of a
//! convex polygon, clipping to a box. Area, hulls, containment, distances and boxes come
//! from the `geom` kernel.

use geom::{orient, ring, Pt, Rect};

/// A point (z, r) in mm.
pub(crate) type P = [f64; 2];

/// Distance between two points.
pub(crate) fn dist(a: P, b: P) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// The point a fraction `t` of the way from `a` to `b`.
pub(crate) fn lerp(a: P, b: P, t: f64) -> P {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
}

/// Points as kernel points.
pub(crate) fn pts(ring: &[P]) -> Vec<Pt> {
    ring.iter().map(|&p| Pt::from(p)).collect()
}

/// The box of some points (no copy of them, unlike `Rect::of(pts(..))`).
pub(crate) fn bounds<'a>(points: impl IntoIterator<Item = &'a P>) -> Rect {
    let mut r = Rect::EMPTY;
    for &p in points {
        r.add(Pt::new(p[0], p[1]));
    }
    r
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

/// The sweep of a convex counter-clockwise polygon `a` along the polyline `path` (at least
/// two points, `a` placed with its reference at each point): a ring whose points of
/// positive winding number are exactly the Minkowski sum `a ⊕ path`, the union of the
/// hulls [`sweep_convex`] gives chord by chord.
///
/// It is the convolution cycle of `a` with the path traversed forward and back (a
/// degenerate polygon, "counter-clockwise" as the limit of a thin one around the path):
/// each path edge is traced by the vertex of `a` extreme along the edge's right normal,
/// and at each turn the vertices of `a` between the two extremes are inserted, walking
/// `a` forward on a left turn and backward on a right turn; the two ends turn left by
/// 180° (the caps). Guibas, Ramshaw and Stolfi's kinetic framework gives the winding
/// numbers: 1 inside the sum, 2 in the small loops on the inner side of turns, 0 outside,
/// never negative — so the non-zero fill of every boolean call reads it as the sum. Why:
/// a chorded arc of k chords, swept chord by chord, hands the boolean engine k hulls of
/// the whole outline that all overlap their neighbours (k·m edges and crossings near
/// every corner); this ring has about 4k + m edges and only the inner loops' crossings.
pub(crate) fn sweep_chain(a: &[P], path: &[P]) -> Vec<P> {
    let m = a.len();
    let n = path.len();
    if m == 0 || n < 2 {
        return Vec::new();
    }
    // the degenerate polygon: forward along the path, then back
    let b: Vec<P> = path
        .iter()
        .chain(path[1..n - 1].iter().rev())
        .copied()
        .collect();
    let k = b.len();
    let dir = |i: usize| {
        let (p, q) = (b[i], b[(i + 1) % k]);
        [q[0] - p[0], q[1] - p[1]]
    };
    let dot = |v: P, w: P| v[0] * w[0] + v[1] * w[1];
    let right = |d: P| [d[1], -d[0]];
    let step = |i: usize, fwd: bool| if fwd { (i + 1) % m } else { (i + m - 1) % m };
    // from support vertex i, walk while the extreme along `nrm` strictly improves
    let walk = |mut i: usize, nrm: P, fwd: bool, out: &mut Vec<usize>| {
        for _ in 0..m {
            let j = step(i, fwd);
            let e = [a[j][0] - a[i][0], a[j][1] - a[i][1]];
            if dot(e, nrm) <= 0.0 {
                break;
            }
            i = j;
            out.push(i);
        }
        i
    };
    let n0 = right(dir(0));
    let mut s = (0..m)
        .max_by(|&x, &y| dot(a[x], n0).total_cmp(&dot(a[y], n0)))
        .unwrap_or(0);
    let mut out: Vec<P> = Vec::with_capacity(4 * k + 2 * m);
    let at = |i: usize, q: P| [a[i][0] + q[0], a[i][1] + q[1]];
    let mut visited = Vec::new();
    for e in 0..k {
        let (d, dn) = (dir(e), dir((e + 1) % k));
        let q = b[(e + 1) % k];
        out.push(at(s, b[e]));
        out.push(at(s, q));
        let cross = d[0] * dn[1] - d[1] * dn[0];
        let left = cross > 0.0 || (cross == 0.0 && dot(d, dn) < 0.0);
        let (nrm, nrm_next) = (right(d), right(dn));
        visited.clear();
        if dot(d, dn) < 0.0 {
            // more than 90°: through the normal halfway, so each walk turns < 180°
            let mid = if left {
                [-nrm[1], nrm[0]]
            } else {
                [nrm[1], -nrm[0]]
            };
            s = walk(s, mid, left, &mut visited);
        }
        s = walk(s, nrm_next, left, &mut visited);
        out.extend(visited.iter().map(|&i| at(i, q)));
    }
    out.dedup();
    if out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
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

/// The Minkowski sum of two convex counter-clockwise polygons (either may be a point or a
/// segment: one or two points): their edges merged by angle from both lowest vertices.
/// Linear time.
pub(crate) fn minkowski(a: &[P], b: &[P]) -> Vec<P> {
    let (a, b) = if a.len() < b.len() { (b, a) } else { (a, b) };
    let shift = |poly: &[P], d: P| poly.iter().map(|p| [p[0] + d[0], p[1] + d[1]]).collect();
    match b.len() {
        0 => return Vec::new(),
        1 => return shift(a, b[0]),
        2 => return sweep_convex(&shift(a, b[0]), [b[1][0] - b[0][0], b[1][1] - b[0][1]]),
        _ => {}
    }
    let lowest = |p: &[P]| {
        (0..p.len())
            .min_by(|&i, &j| {
                p[i][1]
                    .total_cmp(&p[j][1])
                    .then(p[i][0].total_cmp(&p[j][0]))
            })
            .unwrap_or(0)
    };
    let (n, m) = (a.len(), b.len());
    let (i0, j0) = (lowest(a), lowest(b));
    let edge = |p: &[P], k: usize| {
        let (u, v) = (p[k % p.len()], p[(k + 1) % p.len()]);
        [v[0] - u[0], v[1] - u[1]]
    };
    let mut out = Vec::with_capacity(n + m);
    let (mut i, mut j) = (0, 0);
    while i < n || j < m {
        let (p, q) = (a[(i0 + i) % n], b[(j0 + j) % m]);
        out.push([p[0] + q[0], p[1] + q[1]]);
        let turn = if i >= n {
            -1.0
        } else if j >= m {
            1.0
        } else {
            let (ea, eb) = (edge(a, i0 + i), edge(b, j0 + j));
            ea[0] * eb[1] - ea[1] * eb[0]
        };
        if turn >= 0.0 && i < n {
            i += 1;
        }
        if turn <= 0.0 && j < m {
            j += 1;
        }
    }
    out
}

/// The parts of the convex polygon `p` outside the convex counter-clockwise polygon `h`,
/// as convex pieces (none when `h` covers `p`; pieces of area ≤ `tiny` are left out): the
/// part beyond each edge of `h` in turn, the rest kept for the next edge.
pub(crate) fn minus_convex(p: &[P], h: &[P], tiny: f64) -> Vec<Vec<P>> {
    let n = h.len();
    if n < 3 {
        return vec![p.to_vec()];
    }
    // apart (an edge of either separates them): `p` stays whole, not cut along the lines of
    // `h`'s edges (a rapid crossing a lane of a hundred chords fell into 25 000 pieces)
    let m = p.len();
    let apart = (0..n).any(|i| p.iter().all(|x| cross(h[i], h[(i + 1) % n], *x) <= 0.0))
        || (0..m).any(|j| h.iter().all(|x| cross(p[j], p[(j + 1) % m], *x) <= 0.0));
    if apart {
        return vec![p.to_vec()];
    }
    let mut out = Vec::new();
    // the part not yet found outside, borrowed until the first cut
    let mut rest = std::borrow::Cow::Borrowed(p);
    let mut side = Vec::with_capacity(p.len() + 8);
    for i in 0..n {
        let (a, b) = (h[i], h[(i + 1) % n]);
        side.clear();
        side.extend(rest.iter().map(|x| cross(a, b, *x)));
        if side.iter().all(|&s| s >= 0.0) {
            continue;
        }
        if side.iter().all(|&s| s <= 0.0) {
            // wholly beyond this edge: the rest is outside `h`
            out.push(rest.into_owned());
            return out;
        }
        let (inner, outer) = split_by_sides(&rest, &side);
        if shoelace(&outer).abs() > tiny {
            out.push(outer);
        }
        rest = std::borrow::Cow::Owned(inner);
    }
    out
}

/// Signed area of a ring (counter-clockwise positive), without a copy of its points.
fn shoelace(r: &[P]) -> f64 {
    let n = r.len();
    (0..n)
        .map(|i| {
            let (a, b) = (r[i], r[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        / 2.0
}

/// A convex polygon cut by a line, given each vertex's signed side: the parts on the
/// non-negative and the non-positive side (crossings in both).
fn split_by_sides(poly: &[P], side: &[f64]) -> (Vec<P>, Vec<P>) {
    let (mut pos, mut neg) = (Vec::with_capacity(poly.len() + 2), Vec::with_capacity(8));
    for j in 0..poly.len() {
        let k = (j + 1) % poly.len();
        let (p, sp, sq) = (poly[j], side[j], side[k]);
        if sp >= 0.0 {
            pos.push(p);
        }
        if sp <= 0.0 {
            neg.push(p);
        }
        if (sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0) {
            let t = sp / (sp - sq);
            let q = poly[k];
            let x = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            pos.push(x);
            neg.push(x);
        }
    }
    (pos, neg)
}

/// Clips a polygon to a box (Sutherland–Hodgman): a convex one stays convex; any ring keeps
/// the winding number of every point inside the box (the chain sweeps rely on that). Points
/// made on a side of the box lie exactly on it.
pub(crate) fn clip_convex(poly: &[P], rect: &Rect) -> Vec<P> {
    // (axis, bound, keep when coordinate >= bound)
    let planes = [
        (0, rect.min.z, true),
        (0, rect.max.z, false),
        (1, rect.min.r, true),
        (1, rect.max.r, false),
    ];
    let mut cur: Vec<P> = poly.to_vec();
    for (axis, bound, ge) in planes {
        let side = |p: &P| if ge { p[axis] - bound } else { bound - p[axis] };
        cur = clip_half_plane(cur, side, Some((axis, bound)));
    }
    cur
}

/// The part of a ring inside a convex counter-clockwise `hull` (Sutherland–Hodgman against
/// each of its edges). The subject may be any simple ring, either orientation: the result
/// may hold zero-width bridges but its signed area is exactly that of the intersection,
/// with the subject's sign — what [`crate::deviation`] needs to tell whether a convex sweep
/// overlaps a region without a boolean.
pub(crate) fn clip_to_hull(poly: &[P], hull: &[P]) -> Vec<P> {
    let n = hull.len();
    let mut cur: Vec<P> = poly.to_vec();
    for i in 0..n {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        cur = clip_half_plane(cur, |p: &P| cross(a, b, *p), None);
    }
    cur
}

/// One Sutherland–Hodgman step: the points of `poly` where `side` ≥ 0, with the crossings
/// of its edges; `snap` puts a crossing exactly on an axis-parallel line (axis, value).
fn clip_half_plane(poly: Vec<P>, side: impl Fn(&P) -> f64, snap: Option<(usize, f64)>) -> Vec<P> {
    if poly.iter().all(|p| side(p) >= 0.0) {
        return poly;
    }
    let mut next = Vec::with_capacity(poly.len() + 2);
    for j in 0..poly.len() {
        let (p, q) = (poly[j], poly[(j + 1) % poly.len()]);
        let (sp, sq) = (side(&p), side(&q));
        if sp >= 0.0 {
            next.push(p);
        }
        if (sp >= 0.0) != (sq >= 0.0) {
            let t = sp / (sp - sq);
            let mut x = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            if let Some((axis, value)) = snap {
                x[axis] = value;
            }
            next.push(x);
        }
    }
    next
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An L of area 3: the unit squares at (0,0), (1,0) and (0,1).
    const L_SHAPE: [P; 6] = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];

    /// An L-shaped ring (area 3) against a unit square hull at the notch corner, and a
    /// triangle: the clipped areas by hand.
    #[test]
    fn clip_to_hull_areas_by_hand() {
        let signed = |r: &[P]| ring::signed_area(&pts(r));
        let l = L_SHAPE;
        let sq = [[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]];
        // the square over the L's notch: three quarters of it lie in the L
        assert!((signed(&clip_to_hull(&l, &sq)) - 0.75).abs() < 1e-12);
        // clockwise subject: the sign follows it
        let mut cw = l.to_vec();
        cw.reverse();
        assert!((signed(&clip_to_hull(&cw, &sq)) + 0.75).abs() < 1e-12);
        // the triangle (0,0) (2,0) (0,2) lies wholly in the L (its points with x, y > 1
        // have x + y > 2): its own area
        let tri = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        assert!((signed(&clip_to_hull(&l, &tri)) - 2.0).abs() < 1e-12);
        // far away: nothing
        let far = [[10.0, 10.0], [11.0, 10.0], [11.0, 11.0]];
        assert!(clip_to_hull(&l, &far).is_empty());
    }

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

    /// The chain sweep's ring fills (non-zero) exactly the union of the per-chord hulls,
    /// and no point has a negative winding number: arcs of both turning directions, an S
    /// curve, a half circle (turns up to 180° in total) and a polyline with sharp corners,
    /// with a 35° insert whose nose is chorded (a convex part of many vertices).
    #[test]
    fn chain_sweep_is_the_union_of_the_chord_hulls() {
        let nose = 0.4;
        let mut insert: Vec<P> = (0..=14)
            .map(|k| {
                let t = (-90.0 + 145.0 * f64::from(k) / 14.0_f64).to_radians();
                [nose * t.cos() - 0.3, nose * t.sin() + nose]
            })
            .collect();
        insert.push([4.0, 2.5]);
        let insert = convex_hull(&insert);
        let arc = |c: P, r: f64, a0: f64, a1: f64, n: usize| -> Vec<P> {
            (0..=n)
                .map(|k| {
                    let t = (a0 + (a1 - a0) * k as f64 / n as f64).to_radians();
                    [c[0] + r * t.cos(), c[1] + r * t.sin()]
                })
                .collect()
        };
        let mut s_curve = arc([0.0, 10.0], 0.5, 0.0, 180.0, 25);
        s_curve.extend(arc([-1.0, 10.0], 0.5, 0.0, -180.0, 25).into_iter().skip(1));
        let paths = [
            arc([0.0, 10.0], 5.0, 0.0, 90.0, 40),
            arc([0.0, 10.0], 5.0, 90.0, 0.0, 40),
            arc([0.0, 10.0], 0.5, 180.0, 0.0, 25),
            s_curve,
            vec![
                [0.0, 10.0],
                [-5.0, 10.0],
                [-5.0, 6.0],
                [-9.0, 12.0],
                [-2.0, 13.0],
            ],
        ];
        for (i, path) in paths.iter().enumerate() {
            let ring = sweep_chain(&insert, path);
            let hulls: Vec<Vec<P>> = path
                .windows(2)
                .map(|w| {
                    let moved: Vec<P> = insert
                        .iter()
                        .map(|v| [v[0] + w[0][0], v[1] + w[0][1]])
                        .collect();
                    sweep_convex(&moved, [w[1][0] - w[0][0], w[1][1] - w[0][1]])
                })
                .collect();
            let union = crate::overlay::clean(&hulls);
            let chain = crate::overlay::clean(std::slice::from_ref(&ring));
            let xor = crate::symmetric_difference_area(&union, &chain);
            assert!(xor < 1e-6, "path {i}: symmetric difference {xor} mm²");
            // arcs turn a little at each vertex: about four points per chord plus the caps
            assert!(
                i == 4 || ring.len() < path.len() * 4 + 2 * insert.len(),
                "path {i}: {} points",
                ring.len()
            );
            // winding numbers: never negative on a grid of sample points
            let r = Rect::of(pts(&ring));
            for a in 0..60 {
                for b in 0..60 {
                    let p = [
                        r.min.z + (r.max.z - r.min.z) * (f64::from(a) + 0.37) / 60.0,
                        r.min.r + (r.max.r - r.min.r) * (f64::from(b) + 0.61) / 60.0,
                    ];
                    assert!(winding(&ring, p) >= 0, "path {i}: winding < 0 at {p:?}");
                }
            }
        }
    }

    fn winding(ring: &[P], p: P) -> i32 {
        let mut w = 0;
        for i in 0..ring.len() {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            let side = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
            if a[1] <= p[1] && b[1] > p[1] && side > 0.0 {
                w += 1;
            } else if a[1] > p[1] && b[1] <= p[1] && side < 0.0 {
                w -= 1;
            }
        }
        w
    }

    #[test]
    fn clip_keeps_the_inside_part() {
        let sq = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let c = clip_convex(&sq, &Rect::new(Pt::new(1.0, -1.0), Pt::new(2.0, 2.0)));
        assert!((2.0 * ring::signed_area(&pts(&c)) / 2.0 - 2.0).abs() < 1e-12);
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
