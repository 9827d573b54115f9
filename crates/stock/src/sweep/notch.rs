//! How far the sweep of a convex outline between two stamps lies from the two stamps: the
//! depth of the notches that sweeping a thread's repeated passes as one fills.

use geom::flat::{dist, lerp, segment_distance, P};

/// An upper bound of the Hausdorff distance between `poly ⊕ [0, w]` (their hull) and
/// `poly ∪ (poly + w)` for a convex counter-clockwise `poly`: how far any point the hull
/// adds lies from both stamps, never more than `|w| / 2`.
///
/// The hull adds two notches, one where each of its edges parallel to `w` joins the
/// stamps, from a vertex `v` of `poly` to `v + w`. The boundaries of the two stamps meet
/// in that notch at `x`; the chords `v x` and `(v + w) x` lie in the stamps (convex), and
/// the notch in the triangle `v, v + w, x` they close with the hull's edge. A point of the
/// triangle is no further from the stamps than from the nearer chord, and that distance
/// grows along every ray from `x`: its largest value lies on the edge, where the distances
/// to the chords (one rising from 0 at `v`, the other falling to 0 at `v + w`) are equal.
/// Where no `x` is found (an edge of `poly` parallel to `w`, the boundaries overlapping),
/// `|w| / 2` stands: every point of the hull is `s + t·w` with `s` in `poly`, `t ∈ [0, 1]`.
pub(super) fn notch_depth(poly: &[P], w: P) -> f64 {
    let n = poly.len();
    let half = dist([0.0, 0.0], w) / 2.0;
    if half == 0.0 || n < 3 {
        return 0.0;
    }
    // an edge faces forward when its outward normal has a positive component along w
    let front = |i: usize| {
        let (a, b) = (poly[i % n], poly[(i + 1) % n]);
        w[0] * (b[1] - a[1]) - w[1] * (b[0] - a[0]) > 0.0
    };
    let mut worst: f64 = 0.0;
    for i in 0..n {
        let (fin, fout) = (front(i + n - 1), front(i));
        if fin != fout {
            // back to front at v: the hull runs v → v + w, with the stamp's forward chain
            // from v and the moved stamp's backward chain from v + w on its inner side;
            // front to back: the other way round
            let dir = if fout { 1 } else { -1 };
            let depth = side_depth(poly, i, w, dir).unwrap_or(half);
            worst = worst.max(depth);
        }
    }
    worst.min(half)
}

/// The notch at vertex `i` of `poly` (see [`notch_depth`]): `poly`'s boundary walked from
/// it in direction `dir` (±1) against `poly + w`'s walked from `i + w` the other way; their
/// first crossing closes the triangle. `None` when they do not cross properly.
fn side_depth(poly: &[P], i: usize, w: P, dir: isize) -> Option<f64> {
    let n = poly.len() as isize;
    let at = |k: isize| poly[(i as isize + k).rem_euclid(n) as usize];
    let moved = |k: isize| {
        let p = at(k);
        [p[0] + w[0], p[1] + w[1]]
    };
    let (v, vw) = (at(0), moved(0));
    let x = (0..n).find_map(|k| {
        let (a, b) = (at(dir * k), at(dir * (k + 1)));
        (0..n).find_map(|m| crossing(a, b, moved(-dir * m), moved(-dir * (m + 1))))
    })?;
    // bisection for where the distances from the hull's edge to the two chords are equal:
    // the first rises from 0 at v, the second falls to 0 at v + w (distances to convex
    // sets along a line are convex)
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let t = (lo + hi) / 2.0;
        let q = lerp(v, vw, t);
        if segment_distance(q, v, x) < segment_distance(q, vw, x) {
            lo = t;
        } else {
            hi = t;
        }
    }
    let q = lerp(v, vw, hi);
    Some(segment_distance(q, v, x).max(segment_distance(lerp(v, vw, lo), vw, x)))
}

/// Where the segments `a b` and `c d` cross, touching included; `None` when they miss or
/// are parallel.
fn crossing(a: P, b: P, c: P, d: P) -> Option<P> {
    let r = [b[0] - a[0], b[1] - a[1]];
    let s = [d[0] - c[0], d[1] - c[1]];
    let den = r[0] * s[1] - r[1] * s[0];
    if den == 0.0 {
        return None;
    }
    let ac = [c[0] - a[0], c[1] - a[1]];
    let t = (ac[0] * s[1] - ac[1] * s[0]) / den;
    let u = (ac[0] * r[1] - ac[1] * r[0]) / den;
    ((0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u)).then(|| lerp(a, b, t))
}

#[cfg(test)]
mod tests {
    use super::*;
    use geom::flat::sweep_convex;

    /// Distance from `q` to the convex counter-clockwise `poly` (0 inside).
    fn to_convex(q: P, poly: &[P]) -> f64 {
        let n = poly.len();
        let inside = (0..n).all(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) >= 0.0
        });
        if inside {
            return 0.0;
        }
        (0..n)
            .map(|i| segment_distance(q, poly[i], poly[(i + 1) % n]))
            .fold(f64::INFINITY, f64::min)
    }

    /// The farthest the hull's boundary lies from the two stamps, sampled: the notches'
    /// depth (their farthest points lie on it).
    fn sampled_depth(poly: &[P], w: P) -> f64 {
        let moved: Vec<P> = poly.iter().map(|p| [p[0] + w[0], p[1] + w[1]]).collect();
        let hull = sweep_convex(poly, w);
        let n = hull.len();
        (0..n)
            .flat_map(|i| (0..=400).map(move |k| (i, f64::from(k) / 400.0)))
            .map(|(i, t)| {
                let q = lerp(hull[i], hull[(i + 1) % n], t);
                to_convex(q, poly).min(to_convex(q, &moved))
            })
            .fold(0.0, f64::max)
    }

    /// A chorded round nose (r0.4, 16 chords a half circle) moved by up to 0.001 mm: the
    /// notches a chord's turn of 11° leaves are about |w|·11°/4 deep, a tenth of |w| / 2,
    /// bounded from above and closely.
    #[test]
    fn a_chorded_nose_moved_a_little_leaves_shallow_notches() {
        let nose: Vec<P> = (0..32)
            .map(|k| {
                let a = std::f64::consts::PI * f64::from(k) / 16.0 + 0.05;
                [0.4 * a.cos(), 0.4 * a.sin()]
            })
            .collect();
        for w in [
            [0.0, -0.0005],
            [0.0, 0.001],
            [0.0003, -0.0004],
            [-0.001, 0.0],
        ] {
            let (bound, seen) = (notch_depth(&nose, w), sampled_depth(&nose, w));
            assert!(seen <= bound + 1e-12, "{w:?}: {seen} > {bound}");
            assert!(
                bound <= seen * 1.01 + 1e-12,
                "{w:?}: {bound} far above {seen}"
            );
            assert!(bound < w[0].hypot(w[1]) / 20.0, "{w:?}: {bound}");
        }
    }

    /// Random convex polygons (hulls of random points) and steps: the bound is never below
    /// the sampled depth and never above |w| / 2, and mostly well below it.
    #[test]
    fn the_bound_holds_for_random_polygons_and_steps() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut rnd = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut below_half = 0;
        for _ in 0..200 {
            let cloud: Vec<geom::Pt> = (0..12)
                .map(|_| geom::Pt::new(rnd() * 2.0 - 1.0, rnd() * 2.0 - 1.0))
                .collect();
            let poly: Vec<P> = geom::ring::convex_hull(&cloud)
                .iter()
                .map(|p| [p.z, p.r])
                .collect();
            let scale = [0.001, 0.05, 0.5][(rnd() * 3.0) as usize % 3];
            let w = [(rnd() - 0.5) * scale, (rnd() - 0.5) * scale];
            let (bound, seen) = (notch_depth(&poly, w), sampled_depth(&poly, w));
            assert!(seen <= bound + 1e-12, "{poly:?} {w:?}: {seen} > {bound}");
            assert!(bound <= w[0].hypot(w[1]) / 2.0 + 1e-15);
            below_half += usize::from(bound < w[0].hypot(w[1]) * 0.45);
        }
        // the triangles, not the fallback, bound most of them
        assert!(below_half > 150, "{below_half} of 200 below |w| / 2");
    }
}
