//! The air tests of a ring: a path of feeds or a chorded arc swept as one ring (the
//! convolution cycle of [`geom::flat::sweep_chain`]), whose non-zero winding is the sweep.
//!
//! A ring is not convex, so the separating-axis test that tells a hull from a tile's stock
//! box does not apply. Without a test of its own, every tile and tree node that the ring's
//! box overlaps got the ring's exact edge test against its stock, each pass: on a stock made
//! dense by many passes (the `g73` bench pattern, an R20 arc over a sawtooth of slivers)
//! that was quadratic. Here a ring's edges are taken [`RUN`] at a time with the box of each
//! run, so that a box far from most of the ring is told apart by a few box tests: a closed
//! box shares no point with the ring's closed region exactly when no edge meets the box and
//! one point of the box winds zero (a box that meets no edge lies in one face of the ring's
//! arrangement, where the winding number is constant). Exact integer tests, no tolerance.

use crate::overlay::{orient, segments_meet, winding_step, winds, IBox, IPt, IShapes};

/// Edges of a ring under one run box (measured on the `g73` bench pattern: see
/// PERFORMANCE.md, round 6).
pub(crate) const RUN: usize = 8;

/// Appends the boxes of the ring's edges, [`RUN`] consecutive edges a box (edge `i` runs
/// from vertex `i` to vertex `i + 1`; the last edge closes the ring).
pub(crate) fn run_boxes(ring: &[IPt], out: &mut Vec<IBox>) {
    let n = ring.len();
    let mut i = 0;
    while i < n {
        let end = (i + RUN).min(n);
        out.push(IBox::of((i..=end).map(|k| ring[k % n])));
        i = end;
    }
}

/// The edges `(p, q)` of `ring` under the run boxes that overlap `b`.
fn edges_near<'a>(
    ring: &'a [IPt],
    runs: &'a [IBox],
    b: &'a IBox,
) -> impl Iterator<Item = (IPt, IPt)> + 'a {
    let n = ring.len();
    runs.iter()
        .enumerate()
        .filter(move |(_, rb)| rb.overlaps(b))
        .flat_map(move |(j, _)| (j * RUN..((j + 1) * RUN).min(n)).map(move |k| (k, (k + 1) % n)))
        .map(move |(k, l)| (ring[k], ring[l]))
}

/// True when the closed segment `[p, q]` shares a point with the closed box `b` (exact: the
/// boxes overlap and the segment's line has corners of `b` on both sides or on it).
fn segment_meets_box(p: IPt, q: IPt, b: &IBox) -> bool {
    if !IBox::of_segment(p, q).overlaps(b) {
        return false;
    }
    let sides = b.corners().map(|c| orient(p, q, c));
    !(sides.iter().all(|&s| s < 0) || sides.iter().all(|&s| s > 0))
}

/// True when the ring's region (the closure of its points of non-zero winding) shares no
/// point with the closed box `b`; `runs` are the ring's [`run_boxes`].
pub(crate) fn misses(ring: &[IPt], runs: &[IBox], b: &IBox) -> bool {
    !edges_near(ring, runs, b).any(|(p, q)| segment_meets_box(p, q, b))
        && !winds_by_runs(IPt::new(b.min[0], b.min[1]), ring, runs)
}

/// [`winds`] with the run boxes: only edges that cross the horizontal ray from `p` to +z
/// count, so a run whose box does not reach it (its r range misses `p`'s, or it lies
/// wholly at or left of `p`) is skipped.
fn winds_by_runs(p: IPt, ring: &[IPt], runs: &[IBox]) -> bool {
    let n = ring.len();
    let mut w = 0i32;
    for (j, rb) in runs.iter().enumerate() {
        if rb.min[1] > p.y || rb.max[1] <= p.y || rb.max[0] <= p.x {
            continue;
        }
        for k in j * RUN..((j + 1) * RUN).min(n) {
            w += winding_step(p, ring[k], ring[(k + 1) % n]);
        }
    }
    w != 0
}

/// Whether the ring and the shapes may share a point (touching counts), with the same
/// answer as testing every stock vertex for non-zero winding and every stock edge against
/// every ring edge: an edge of one meets an edge of the other, or a stock vertex winds
/// non-zero, or the ring lies inside a shape. Each stock ring needs one winding test
/// only: when no edge of a stock ring meets the ring, the stock ring lies in one face of
/// the ring's arrangement, where the winding number is constant. Stock edges are tried
/// only where their box meets the ring's, ring edges only under run boxes that meet the
/// stock edge's (`runs` is scratch space).
pub(crate) fn touches(
    ring: &[IPt],
    shapes: &IShapes,
    shapes_box: &IBox,
    runs: &mut Vec<IBox>,
) -> bool {
    let rb = IBox::of(ring.iter().copied());
    if !rb.overlaps(shapes_box) {
        return false;
    }
    runs.clear();
    run_boxes(ring, runs);
    for s in shapes {
        for stock in s {
            let m = stock.len();
            let mut wound = false;
            for k in 0..m {
                let (a, b) = (stock[k], stock[(k + 1) % m]);
                let eb = IBox::of_segment(a, b);
                if !eb.overlaps(&rb) {
                    continue;
                }
                if !wound {
                    wound = true;
                    if winds(a, ring) {
                        return true;
                    }
                }
                if edges_near(ring, runs, &eb)
                    .any(|(p, q)| IBox::of_segment(p, q).overlaps(&eb) && segments_meet(p, q, a, b))
                {
                    return true;
                }
            }
        }
        // the ring may lie wholly inside the shape
        if let (Some(outer), Some(&p)) = (s.first(), ring.first()) {
            if crate::overlay::point_in_ring(p, outer)
                && !s[1..].iter().any(|h| crate::overlay::point_in_ring(p, h))
            {
                return true;
            }
        }
    }
    false
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use geom::flat::{sweep_chain, P};

    /// A xorshift generator of integers in `-span..=span`.
    pub(crate) struct Rng(pub(crate) u64);

    impl Rng {
        pub(crate) fn next(&mut self, span: i64) -> i64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 % (2 * span as u64 + 1)) as i64 - span
        }
    }

    /// The convolution ring of a convex part along a path, on integer coordinates (every
    /// vertex of `sweep_chain` is a sum of integer points, so exact).
    pub(crate) fn int_ring(part: &[P], path: &[P]) -> Vec<IPt> {
        sweep_chain(part, path)
            .iter()
            .map(|p| IPt::new(p[0] as i32, p[1] as i32))
            .collect()
    }

    /// A random small ring: a random convex part (the hull of 5 points) along a random
    /// polyline, on a grid coarse enough that touching and collinear cases occur.
    pub(crate) fn random_ring(rng: &mut Rng) -> Vec<IPt> {
        let pts: Vec<P> = (0..5)
            .map(|_| [rng.next(4) as f64, rng.next(4) as f64])
            .collect();
        let part = geom::flat::convex_hull(&pts);
        let n = 2 + rng.next(3).unsigned_abs() as usize;
        let path: Vec<P> = (0..n)
            .map(|_| [rng.next(20) as f64, rng.next(20) as f64])
            .collect();
        if part.len() < 3 {
            return Vec::new();
        }
        int_ring(&part, &path)
    }

    pub(crate) fn random_box(rng: &mut Rng) -> IBox {
        let (a, b) = (rng.next(26) as i32, rng.next(26) as i32);
        let (w, h) = (rng.next(6).abs() as i32, rng.next(6).abs() as i32);
        IBox {
            min: [a, b],
            max: [a + w, b + h],
        }
    }

    /// A random box with its corners anywhere in `-span..=span`.
    pub(crate) fn box_within(rng: &mut Rng, span: i64) -> IBox {
        let (a, b, c, d) = (
            rng.next(span),
            rng.next(span),
            rng.next(span),
            rng.next(span),
        );
        IBox {
            min: [a.min(c) as i32, b.min(d) as i32],
            max: [a.max(c) as i32, b.max(d) as i32],
        }
    }

    fn runs_of(ring: &[IPt]) -> Vec<IBox> {
        let mut runs = Vec::new();
        run_boxes(ring, &mut runs);
        runs
    }

    /// Whether the ring's closed region meets the closed box, told another way: a ring
    /// vertex in the box, a ring edge crossing a side of the box, or a corner of the box
    /// inside the ring.
    fn meets(ring: &[IPt], b: &IBox) -> bool {
        let inside =
            |p: &IPt| p.x >= b.min[0] && p.x <= b.max[0] && p.y >= b.min[1] && p.y <= b.max[1];
        let c = b.corners();
        let n = ring.len();
        ring.iter().any(inside)
            || (0..n).any(|i| {
                (0..4).any(|s| segments_meet(ring[i], ring[(i + 1) % n], c[s], c[(s + 1) % 4]))
            })
            || winds(c[0], ring)
    }

    /// A ring whose box meets a box that its region does not (an L-shaped path: the box in
    /// the inner corner), one whose edges meet it, and one holding it wholly inside (no
    /// edge meets it: only the winding test tells).
    #[test]
    fn a_box_in_the_rings_box_is_told_by_its_edges_and_winding() {
        let square = [[-2.0, -2.0], [2.0, -2.0], [2.0, 2.0], [-2.0, 2.0]];
        let ring = int_ring(&square, &[[0.0, 0.0], [20.0, 0.0], [20.0, 20.0]]);
        let runs = runs_of(&ring);
        let rb = IBox::of(ring.iter().copied());
        let bx = |x0, y0, x1, y1| IBox {
            min: [x0, y0],
            max: [x1, y1],
        };
        let corner = bx(5, 5, 15, 15);
        assert!(rb.overlaps(&corner));
        assert!(misses(&ring, &runs, &corner));
        // on the arm's edge r = 2, touching counts
        assert!(!misses(&ring, &runs, &bx(5, 2, 15, 5)));
        assert!(misses(&ring, &runs, &bx(5, 3, 15, 5)));
        // wholly inside the arm: no edge meets it
        let inner = bx(5, -1, 6, 1);
        assert!(!ring
            .iter()
            .zip(ring.iter().cycle().skip(1))
            .any(|(&p, &q)| segment_meets_box(p, q, &inner)));
        assert!(!misses(&ring, &runs, &inner));
        for b in [corner, bx(5, 2, 15, 5), inner, bx(23, 23, 30, 30)] {
            assert_eq!(misses(&ring, &runs, &b), !meets(&ring, &b), "{b:?}");
        }
    }

    /// `misses` agrees with the independent test on random rings and boxes (both outcomes,
    /// and boxes inside a ring's box that it misses, occur).
    #[test]
    fn misses_matches_vertices_sides_and_winding() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let (mut missed, mut in_box_missed, mut total) = (0, 0, 0);
        for _ in 0..20_000 {
            let ring = random_ring(&mut rng);
            if ring.len() < 3 {
                continue;
            }
            let b = random_box(&mut rng);
            let m = misses(&ring, &runs_of(&ring), &b);
            assert_eq!(m, !meets(&ring, &b), "{ring:?} {b:?}");
            let rb = IBox::of(ring.iter().copied());
            missed += usize::from(m);
            in_box_missed += usize::from(m && rb.overlaps(&b));
            total += 1;
        }
        assert!(
            missed > total / 10 && missed < total * 9 / 10,
            "{missed} of {total}"
        );
        assert!(in_box_missed > total / 20, "{in_box_missed} of {total}");
    }

    /// `winds_by_runs` is `winds`, on every integer point around random rings.
    #[test]
    fn winding_by_runs_is_the_winding() {
        let mut rng = Rng(0x2545_f491_4f6c_dd1d);
        for _ in 0..300 {
            let ring = random_ring(&mut rng);
            if ring.len() < 3 {
                continue;
            }
            let runs = runs_of(&ring);
            for x in -26..=26 {
                for y in -26..=26 {
                    let p = IPt::new(x, y);
                    assert_eq!(winds_by_runs(p, &ring, &runs), winds(p, &ring), "{p:?}");
                }
            }
        }
    }
}
