//! Batches: the sweeps a tile subtracts in its next boolean call, each trimmed to the tile's
//! stock box, leaving out those another one covers there.

use crate::overlay::{convex_covers_in_box, orient, IBox, IPt};
use crate::ring_air;
use crate::sweep::{Item, Poly, Sweeps};

/// Sweeps subtracted per boolean call in a tile. Consecutive sweeps overlap pairwise, so a
/// call's cost grows with k²: 2 was the fastest with tiles of [`super::tile::MAX_TILE_VERTICES`]
/// (the stock bench at 10⁵ moves, the 10⁶ contour and grooving runs; PERFORMANCE.md, "Batch
/// and tile sizes").
pub(super) const BATCH: usize = 2;

/// Polygons trimmed to a box (see [`trim_to_box`]), stored flat.
#[derive(Default)]
pub(super) struct Trimmed {
    pts: Vec<IPt>,
    rings: Vec<std::ops::Range<usize>>,
    /// Per ring: whether it came from a convex polygon ([`Poly::convex`]), and that
    /// polygon's [`Poly::core`].
    kinds: Vec<(bool, IBox)>,
    /// Rings (not convex) are trimmed with the tests of [`trim_to_box`] for rings
    /// ([`SimOptions::ring_air`]).
    pub(super) ring_air: bool,
}

/// A trimmed ring with what its polygon was ([`Trimmed::kinds`]).
#[derive(Clone, Copy)]
pub(super) struct Ring<'a> {
    pub(super) pts: &'a [IPt],
    pub(super) convex: bool,
    pub(super) core: IBox,
}

impl Trimmed {
    pub(super) fn clear(&mut self) {
        self.pts.clear();
        self.rings.clear();
        self.kinds.clear();
    }

    /// Appends every polygon of the sweep `it`, trimmed to `b`.
    pub(super) fn push_sweep(&mut self, sweeps: &Sweeps, it: &Item, b: &IBox) {
        for p in sweeps.parts_of(it) {
            self.push(p, b);
        }
    }

    /// Appends the polygons a rapid's crash test reads ([`Item::probe`]), trimmed to `b`.
    pub(super) fn push_probe(&mut self, sweeps: &Sweeps, it: &Item, b: &IBox) {
        for p in sweeps.probe_parts_of(it) {
            self.push(p, b);
        }
    }

    /// Appends `poly` trimmed to `b` (nothing when its overlap with `b` has no area).
    pub(super) fn push(&mut self, poly: Poly, b: &IBox) {
        let start = self.pts.len();
        if self.ring_air && !poly.convex {
            // a run strictly on one outer side of `b` keeps its first vertex only: the
            // closed triangles of the vertices dropped lie on that side (see trim_to_box)
            let n = poly.pts.len();
            let verts = poly.runs.iter().enumerate().flat_map(|(j, rb)| {
                let (lo, hi) = (j * ring_air::RUN, ((j + 1) * ring_air::RUN).min(n));
                let away = !rb.overlaps(b);
                poly.pts[lo..if away { lo + 1 } else { hi }].iter().copied()
            });
            trim_to_box(verts, b, &mut self.pts, true);
        } else {
            trim_to_box(poly.pts.iter().copied(), b, &mut self.pts, false);
        }
        if self.pts.len() > start {
            self.rings.push(start..self.pts.len());
            self.kinds.push((poly.convex, poly.core));
        }
    }

    pub(super) fn iter(&self) -> impl Iterator<Item = &[IPt]> + Clone {
        self.rings.iter().map(|r| &self.pts[r.clone()])
    }

    /// Every ring with its kind.
    pub(super) fn rings(&self) -> impl Iterator<Item = Ring<'_>> + Clone {
        self.ranged(0..self.rings.len())
    }

    /// The rings of `from` with their kinds.
    fn ranged(&self, from: std::ops::Range<usize>) -> impl Iterator<Item = Ring<'_>> + Clone {
        self.rings[from.clone()]
            .iter()
            .zip(&self.kinds[from])
            .map(|(r, &(convex, core))| Ring {
                pts: &self.pts[r.clone()],
                convex,
                core,
            })
    }

    /// Appends the rings of `other`.
    fn extend_from(&mut self, other: &Self) {
        let base = self.pts.len();
        self.pts.extend_from_slice(&other.pts);
        self.rings
            .extend(other.rings.iter().map(|r| r.start + base..r.end + base));
        self.kinds.extend_from_slice(&other.kinds);
    }
}

/// The sweeps of a tile waiting for its next boolean call, each trimmed to the tile's stock
/// box (its part in any box inside that one is the sweep's, so the box later sweeps are
/// tested against may shrink while the batch waits).
#[derive(Default)]
pub(super) struct Batch {
    /// Per sweep still in the batch: the range of its rings in `rings`.
    kept: Vec<std::ops::Range<usize>>,
    rings: Trimmed,
}

impl Batch {
    pub(super) fn len(&self) -> usize {
        self.kept.len()
    }

    pub(super) fn clear(&mut self) {
        self.kept.clear();
        self.rings.clear();
    }

    /// The rings of every sweep in the batch.
    pub(super) fn iter(&self) -> impl Iterator<Item = &[IPt]> {
        self.kept
            .iter()
            .flat_map(|r| self.rings.ranged(r.clone()).map(|ring| ring.pts))
    }

    /// True when the sweeps of the batch cover the sweep trimmed into `t` wherever the stock
    /// may be (inside `b`, its box; see [`covered`]). Then `stock − (batch ∪ t) = stock −
    /// batch`, and for a rapid, its overlap with the stock after the batch is empty.
    pub(super) fn covers(&self, t: &Trimmed, b: &IBox) -> bool {
        let all = self.kept.iter().flat_map(|r| self.rings.ranged(r.clone()));
        covered(t.rings(), all, b)
    }

    /// Adds the sweep trimmed into `t`, dropping (with `cover`) the sweeps of the batch it
    /// covers (the passes of a roughing or a zig-zag, each lowering a flat top, cover the
    /// last one there; nearly coincident edges in one call cost the splitter pairwise).
    pub(super) fn push(&mut self, t: &Trimmed, b: &IBox, cover: bool) {
        let rings = &self.rings;
        if cover {
            self.kept
                .retain(|r| !covered(rings.ranged(r.clone()), t.rings(), b));
        }
        let first = self.rings.rings.len();
        self.rings.extend_from(t);
        self.kept.push(first..self.rings.rings.len());
    }
}

/// True when every ring of `inner` is convex and, inside `b`, lies in one convex ring of
/// `outer`: then `inner ∩ b ⊆ outer`. Exact: the box of `inner ∩ b` inside the core of an
/// outer polygon, else [`convex_covers_in_box`] after a test of the outer ring's box.
fn covered<'a>(
    mut inner: impl Iterator<Item = Ring<'a>>,
    outer: impl Iterator<Item = Ring<'a>> + Clone,
    b: &IBox,
) -> bool {
    inner.all(|p| {
        let need = IBox::of(p.pts.iter().copied()).intersection(b);
        p.convex
            && outer.clone().any(|o| {
                o.convex
                    && (o.core.contains(&need)
                        || IBox::of(o.pts.iter().copied()).contains(&need)
                            && convex_covers_in_box(o.pts, p.pts, b))
            })
    })
}

/// Appends to `out` a polygon `t` with `t ∩ b == poly ∩ b` (as closed point sets, so any
/// boolean with shapes inside `b` gives the same result), made of a subset of `poly`'s
/// vertices. A vertex `k` (neighbours `a`, `c`) is dropped when `k` lies strictly right of
/// the chord `a → c` and all of `b` lies on or left of it: the winding number changes only
/// inside the open triangle `a k c`, which is then disjoint from `b`. Exact integer
/// orientation tests, valid for any ring (a grid-snapped hull may be slightly non-convex).
/// For a `ring` (a path's convolution cycle, whose loops and back-and-forth runs the rule
/// above keeps: an R20 arc's ring of 512 vertices kept ~150 against a 0.05 mm box), `k` is
/// also dropped when `a`, `k`, `c` lie strictly on one outer side of `b` (left of its least
/// z, …) or `k` strictly left of the chord and all of `b` strictly right of it: the closed
/// triangle is then disjoint from `b` (the same ring keeps 0–6 vertices).
/// Nothing is appended when fewer than three vertices are left (no area inside `b`).
fn trim_to_box(poly: impl Iterator<Item = IPt>, b: &IBox, out: &mut Vec<IPt>, ring: bool) {
    let corners = b.corners();
    let outside = |a: IPt, k: IPt, c: IPt| {
        let all = |f: &dyn Fn(IPt) -> bool| f(a) && f(k) && f(c);
        all(&|p| p.x < b.min[0])
            || all(&|p| p.x > b.max[0])
            || all(&|p| p.y < b.min[1])
            || all(&|p| p.y > b.max[1])
    };
    let removable = |a: IPt, k: IPt, c: IPt| {
        if ring && outside(a, k, c) {
            return true;
        }
        match orient(a, c, k) {
            o if o < 0 => corners.iter().all(|&q| orient(a, c, q) >= 0),
            o if o > 0 => ring && corners.iter().all(|&q| orient(a, c, q) < 0),
            _ => false,
        }
    };
    let start = out.len();
    for v in poly {
        out.push(v);
        while out.len() - start >= 3 {
            let l = out.len();
            if removable(out[l - 3], out[l - 2], out[l - 1]) {
                out.remove(l - 2);
            } else {
                break;
            }
        }
    }
    // the wrap-around: the first and last vertices against each other
    loop {
        let n = out.len() - start;
        if n < 3 {
            break;
        }
        let (first, last) = (start, out.len() - 1);
        if removable(out[last], out[first], out[first + 1]) {
            out.remove(first);
        } else if removable(out[last - 1], out[last], out[first]) {
            out.pop();
        } else {
            break;
        }
    }
    if out.len() - start < 3 {
        out.truncate(start);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::overlay::{segments_meet, winds, Grid};
    use crate::removal::tests::{seg, v35};
    use crate::sweep::SweepBuilder;
    use expander::Motion;
    use geom::Rect;
    use std::sync::atomic::AtomicU32;

    /// A ring trimmed to a box with the ring rules (whole runs outside first) winds as the
    /// ring does at every integer point inside the box off both rings' edges (on the box's
    /// sides the first rule's chords may run: a difference of no area), keeps a subset of
    /// its vertices, and keeps far fewer than the first rule alone.
    #[test]
    fn ring_trim_keeps_the_winding_inside_the_box() {
        use crate::ring_air::tests::{random_box, random_ring, Rng};
        let mut rng = Rng(0x0bad_cafe_dead_beef);
        let on_edge = |p: IPt, r: &[IPt]| {
            (0..r.len()).any(|i| segments_meet(r[i], r[(i + 1) % r.len()], p, p))
        };
        let (mut kept, mut kept_plain) = (0, 0);
        for _ in 0..3_000 {
            let ring = random_ring(&mut rng);
            if ring.len() < 3 {
                continue;
            }
            let b = random_box(&mut rng);
            let mut runs = Vec::new();
            ring_air::run_boxes(&ring, &mut runs);
            let mut trim = Trimmed {
                ring_air: true,
                ..Trimmed::default()
            };
            let hint = AtomicU32::new(0);
            let poly = Poly {
                pts: &ring,
                convex: false,
                runs: &runs,
                bbox: IBox::of(ring.iter().copied()),
                core: IBox::EMPTY,
                hint: &hint,
            };
            trim.push(poly, &b);
            let t: Vec<IPt> = trim.iter().next().map(<[IPt]>::to_vec).unwrap_or_default();
            assert!(t.iter().all(|p| ring.contains(p)));
            for x in b.min[0] + 1..b.max[0] {
                for y in b.min[1] + 1..b.max[1] {
                    let p = IPt::new(x, y);
                    if !on_edge(p, &ring) && !on_edge(p, &t) {
                        let wt = t.len() >= 3 && winds(p, &t);
                        assert_eq!(wt, winds(p, &ring), "{p:?} {ring:?} {b:?} -> {t:?}");
                    }
                }
            }
            let mut plain = Vec::new();
            trim_to_box(ring.iter().copied(), &b, &mut plain, false);
            kept += t.len();
            kept_plain += plain.len();
        }
        assert!(
            kept * 2 < kept_plain,
            "{kept} vertices kept, {kept_plain} without the ring rules"
        );
    }

    /// A lower pass covers the one above it inside the stock's box: it takes its place in
    /// the batch, and the higher one is then left out; a pass reaching further left is not
    /// covered by a shorter one.
    #[test]
    fn a_lower_pass_takes_the_place_of_the_one_above_in_the_batch() {
        let bb = Rect::new(geom::Pt::new(-60.0, -10.0), geom::Pt::new(20.0, 60.0));
        let grid = Grid::new(bb);
        let tools = v35();
        let mut builder = SweepBuilder::new(&grid, bb, &tools, 0.001, 0.0);
        let passes = [(20.0, -30.0), (19.9, -30.0), (19.8, -25.0)];
        for (i, &(r, z)) in passes.iter().enumerate() {
            builder.push(i, &seg(Motion::Feed, [5.0, r], [z, r]), None);
        }
        builder.flush_run();
        let sweeps = builder.take();
        assert_eq!(sweeps.items.len(), 3);
        // the stock's box: the bar down to the axis, up to the first pass's top
        let b = grid.box_to_int(&Rect::new(
            geom::Pt::new(-50.0, 0.0),
            geom::Pt::new(0.0, 20.05),
        ));
        let trimmed: Vec<Trimmed> = sweeps
            .items
            .iter()
            .map(|it| {
                let mut t = Trimmed::default();
                t.push_sweep(&sweeps, it, &b);
                t
            })
            .collect();
        let mut batch = Batch::default();
        batch.push(&trimmed[0], &b, true);
        assert!(!batch.covers(&trimmed[1], &b));
        batch.push(&trimmed[1], &b, true);
        assert_eq!(batch.len(), 1, "the lower pass replaces the upper");
        assert!(batch.covers(&trimmed[0], &b));
        // the shorter third pass, lower still, leaves the second's far end uncovered
        batch.push(&trimmed[2], &b, true);
        assert_eq!(batch.len(), 2);
        // without covering, every sweep stays
        let mut all = Batch::default();
        for t in &trimmed {
            all.push(t, &b, false);
        }
        assert_eq!(all.len(), 3);
    }
}
