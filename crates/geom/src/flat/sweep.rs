//! Sweeps of convex polygons along moves, and Minkowski sums.

use super::P;

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
pub fn sweep_chain(a: &[P], path: &[P]) -> Vec<P> {
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
pub fn sweep_convex(poly: &[P], d: P) -> Vec<P> {
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
pub fn minkowski(a: &[P], b: &[P]) -> Vec<P> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flat::{convex_hull, pts};
    use crate::ring;

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
}
