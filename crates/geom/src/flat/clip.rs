//! Clipping: a convex polygon minus another, rings cut to a box or to a convex hull.

use super::{cross, P};
use crate::Rect;

/// The parts of the convex polygon `p` outside the convex counter-clockwise polygon `h`,
/// as convex pieces (none when `h` covers `p`; pieces of area ≤ `tiny` are left out): the
/// part beyond each edge of `h` in turn, the rest kept for the next edge.
pub fn minus_convex(p: &[P], h: &[P], tiny: f64) -> Vec<Vec<P>> {
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
pub fn clip_convex(poly: &[P], rect: &Rect) -> Vec<P> {
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
/// with the subject's sign — what the deviation analysis needs to tell whether a convex sweep
/// overlaps a region without a boolean.
pub fn clip_to_hull(poly: &[P], hull: &[P]) -> Vec<P> {
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
    use crate::flat::{pts, tests::L_SHAPE};
    use crate::{ring, Pt};

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
    fn clip_keeps_the_inside_part() {
        let sq = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let c = clip_convex(&sq, &Rect::new(Pt::new(1.0, -1.0), Pt::new(2.0, 2.0)));
        assert!((2.0 * ring::signed_area(&pts(&c)) / 2.0 - 2.0).abs() < 1e-12);
    }
}
