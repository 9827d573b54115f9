//! Where a contour touches the stock: approach and retract are no part of it.

use super::{bbox, Stages};
use geom::flat::{dist, lerp, P};
use stock::{boolean, BoolOp, Shape};

/// How near a path must come to the stock to touch it, mm: a path run on the stock's
/// surface (a G70 after roughing to size) touches it; one in the air a rapid's clearance
/// away does not.
const CONTACT: f64 = 1e-3;

/// The stretch of `path` that is profile (spec/simulation.md, "The intended shape": approach
/// and retract are no part), judged against `stages`, chiefly the stock when the path
/// began:
/// - leading segments that do not touch that stock are dropped (a lead-in along Z to a
///   faced front, an approach along the chamfer's own line), and so is a leading segment
///   along Z that ends at or in front of the finished part's front: a lead-in in front of
///   the face, also where it runs through face stock the program faces later;
/// - the first segment kept starts at its programmed vertex where the segment dropped
///   before it ran on the blank (a face marked by `G01 Z0` stays at Z0, so a face cut too
///   deep is still found); else (it is the first, or the moves before it were in the air,
///   as a CAM lead-in to an extended chamfer) where it first touches the stock, and not in
///   front of the finished part's front (what the program faces off later was never part
///   of a profile that states no face);
/// - trailing moves off the last diameter that end beyond the stock's radial extent are
///   dropped (also where they cut the corner on the way), and trailing segments that no
///   longer touch the stock, and the end of the last one past its last contact.
///
/// A segment touches where its band of ±[`CONTACT`] meets the stock. Empty when the path
/// never touches the stock.
pub(super) fn in_contact(path: &[P], stages: &Stages) -> Vec<P> {
    let stock = stages.began;
    let front = front_of(stages.finished);
    // the first segment that touches (the ones before are dropped at once, not one by one)
    let mut first = 0;
    let mut start = None;
    while first + 1 < path.len() {
        let (a, b) = (path[first], path[first + 1]);
        let touch = contact(a, b, stock).filter(|(t, _)| (1.0 - t) * dist(a, b) > 2.0 * CONTACT);
        if let (Some((t, _)), false) = (touch, lead_in_along_z(a, b, front)) {
            start = Some(t);
            break;
        }
        first += 1;
    }
    let mut s = path[first..].to_vec();
    if let Some(t) = start {
        let stated = first > 0 && runs_on(path[first - 1], path[first], stages.blank);
        let t = t.max(front.map_or(0.0, |f| crossing(s[0], s[1], f)));
        if !stated && t * dist(s[0], s[1]) > CONTACT {
            s[0] = lerp(s[0], s[1], t);
        }
    }
    let all: Vec<P> = stock.iter().flat_map(|m| m.outer.clone()).collect();
    if all.is_empty() {
        return vec![];
    }
    let (lo, hi) = bbox(&all);
    const EPS: f64 = 1e-6;
    while s.len() > 2 {
        let (p, q) = (s[s.len() - 2], s[s.len() - 1]);
        let off = (q[1] > p[1] + EPS && q[1] >= hi[1] - EPS)
            || (q[1] < p[1] - EPS && q[1] <= lo[1] + EPS);
        if !off {
            break;
        }
        s.pop();
    }
    while s.len() >= 2 {
        let (a, b) = (s[s.len() - 2], s[s.len() - 1]);
        match contact(a, b, stock) {
            Some((_, t)) if t * dist(a, b) > 2.0 * CONTACT => {
                if (1.0 - t) * dist(a, b) > CONTACT {
                    let last = s.len() - 1;
                    s[last] = lerp(a, b, t);
                }
                break;
            }
            _ => {
                s.pop();
            }
        }
    }
    if s.len() < 2 {
        s.clear();
    }
    s
}

/// The finished part's front (its largest Z), `None` when there is no part.
pub(super) fn front_of(finished: &[Shape]) -> Option<f64> {
    finished
        .iter()
        .flat_map(|m| m.outer.iter().map(|p| p[0]))
        .reduce(f64::max)
}

/// Whether `a -> b` runs along Z toward the chuck and ends at or in front of the finished
/// part's `front`: a lead-in to the face, not a diameter of the part.
fn lead_in_along_z(a: P, b: P, front: Option<f64>) -> bool {
    front.is_some_and(|f| (a[1] - b[1]).abs() <= 1e-9 && b[0] < a[0] && b[0] >= f - CONTACT)
}

/// Where `a -> b` crosses the finished part's `front` toward the chuck (0 where it starts
/// behind it).
fn crossing(a: P, b: P, front: f64) -> f64 {
    if a[0] > front + CONTACT && b[0] < front {
        (a[0] - front) / (a[0] - b[0])
    } else {
        0.0
    }
}

/// Whether `a -> b` runs on the blank, inside it or along its edge, over more than a
/// point: a stated surface (a face at Z0), not an approach that ends at the bar.
fn runs_on(a: P, b: P, blank: &[Shape]) -> bool {
    contact(a, b, blank).is_some_and(|(lo, hi)| (hi - lo) * dist(a, b) > 2.0 * CONTACT)
}

/// Where the segment `a -> b` touches `stock`: the first and last parameter (0 at `a`, 1 at
/// `b`) where it is inside the stock, exactly where it crosses the stock's edges; where it
/// only runs along or grazes the stock, where its band of ±[`CONTACT`] meets it. `None`
/// when it misses.
fn contact(a: P, b: P, stock: &[Shape]) -> Option<(f64, f64)> {
    let len = dist(a, b);
    if len <= 0.0 {
        return None;
    }
    let span = |ts: &mut dyn Iterator<Item = f64>| {
        ts.fold(None, |acc: Option<(f64, f64)>, t| match acc {
            None => Some((t, t)),
            Some((lo, hi)) => Some((lo.min(t), hi.max(t))),
        })
    };
    // the segment itself: its ends inside, its crossings of the edges
    let inside = |p: P| stock.iter().any(|m| shape_contains(m, p));
    let d = [b[0] - a[0], b[1] - a[1]];
    let cross = |u: [f64; 2], v: [f64; 2]| u[0] * v[1] - u[1] * v[0];
    let mut ts: Vec<f64> = vec![];
    if inside(a) {
        ts.push(0.0);
    }
    if inside(b) {
        ts.push(1.0);
    }
    let (lo, hi) = (
        [a[0].min(b[0]), a[1].min(b[1])],
        [a[0].max(b[0]), a[1].max(b[1])],
    );
    for ring in stock
        .iter()
        .flat_map(|m| std::iter::once(&m.outer).chain(&m.holes))
    {
        for (k, &c) in ring.iter().enumerate() {
            let e = ring[(k + 1) % ring.len()];
            // an edge whose box misses the segment's cannot cross it
            if c[0].max(e[0]) < lo[0]
                || c[0].min(e[0]) > hi[0]
                || c[1].max(e[1]) < lo[1]
                || c[1].min(e[1]) > hi[1]
            {
                continue;
            }
            let f = [e[0] - c[0], e[1] - c[1]];
            let denom = cross(d, f);
            if denom.abs() < 1e-15 {
                continue;
            }
            let ca = [c[0] - a[0], c[1] - a[1]];
            let (t, u) = (cross(ca, f) / denom, cross(ca, d) / denom);
            if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
                ts.push(t);
            }
        }
    }
    let crossing = span(&mut ts.iter().copied());
    if let Some((lo, hi)) = crossing {
        // a real entry: the segment's own points inside between two parameters
        if hi > lo && inside(lerp(a, b, (lo + hi) / 2.0)) {
            return crossing;
        }
    }
    // along or near the stock: the band
    let u = [d[0] / len, d[1] / len];
    let n = [-u[1] * CONTACT, u[0] * CONTACT];
    let e = [u[0] * CONTACT, u[1] * CONTACT];
    let band = Shape {
        outer: vec![
            [a[0] - e[0] - n[0], a[1] - e[1] - n[1]],
            [b[0] + e[0] - n[0], b[1] + e[1] - n[1]],
            [b[0] + e[0] + n[0], b[1] + e[1] + n[1]],
            [a[0] - e[0] + n[0], a[1] - e[1] + n[1]],
        ],
        holes: vec![],
    };
    let hit = boolean(stock, &[band], BoolOp::Intersection);
    let t = |p: &P| (((p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1]) / len).clamp(0.0, 1.0);
    span(&mut hit.iter().flat_map(|h| h.outer.iter().map(t)))
}

/// Whether `p` is inside the shape (its outer ring and none of its holes), even-odd, on
/// the rings as they are (`geom::ring::contains` would copy the stock's rings to kernel
/// points for every point asked).
fn shape_contains(m: &Shape, p: P) -> bool {
    let crossings = |ring: &[P]| {
        let mut inside = false;
        for (k, &c) in ring.iter().enumerate() {
            let e = ring[(k + 1) % ring.len()];
            if (c[1] > p[1]) != (e[1] > p[1])
                && p[0] < c[0] + (p[1] - c[1]) * (e[0] - c[0]) / (e[1] - c[1])
            {
                inside = !inside;
            }
        }
        inside
    };
    crossings(&m.outer) && !m.holes.iter().any(|h| crossings(h))
}
