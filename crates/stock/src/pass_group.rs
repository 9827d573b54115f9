//! Passes merged into one sweep: the repeated passes of a long roughing, each the last
//! moved by the same small step, cut as the region they sweep together.
//!
//! A roughing cycle with a tiny depth of cut, a G73 of thousands of passes or CAM's
//! contour-parallel output repeats a *pass* — a few feed paths between rapids — each time
//! moved by a step much smaller than the tool. Cut one by one, every pass leaves a new
//! sliver (and a new notch where it ends) that the boolean engine must split: the cost of
//! a pass stays that of a real feature, 10⁶ moves take seconds (`PERFORMANCE.md`).
//!
//! Here the feed paths of such passes are *lanes*: lane `c` of pass `n` is its first path
//! `f` with every vertex moved by `n · w_i`, each step `|w_i|` at most the merge tolerance
//! `δ`. A lane of one segment sweeps, over passes `0..=N`, within the convex region
//! `outline part ⊕ hull(a, b, b + N w_b, a + N w_a)`; a longer lane (a translate: every
//! `w_i` equal) within `part ⊕ [0, N w] ⊕ f`, swept as one ring. Error: a point of that
//! region lies on the ruled strip between two consecutive passes' paths (moved by its
//! part's point), within `max |w_i| / 2 ≤ δ / 2` of one of them, so the final part moves by
//! at most `δ / 2` where the group cut (notches thinner than that between passes vanish).
//! Only exact paths take part (no chain merged within `δ`: the two errors would add up).
//!
//! The group's sweep is emitted when it closes, after the rapids between its passes. A
//! rapid must meet the stock as it is after the passes before it, which the removal's stock
//! still holds at that point: so each rapid is first *carved*, the regions the group has
//! swept so far taken out of its sweep (convex pieces, [`geom::flat::minus_convex`]). What
//! it then meets of the stock is what it meets of the true stock, up to the notches between
//! the passes (at most `δ / 2` thick: a rapid retracing the cut can miss such a sliver, the
//! caveat of merged chains in [`crate::sweep`]); it never meets material the group removed,
//! so a group adds no false crash. Where its pieces do meet stock (a crash), the rapid cuts
//! its whole sweep, as it would pass by pass: cutting only the pieces left slivers of a grid
//! step between them and the group's later cut. A ring lane carves segment by segment (each segment's
//! region is convex). Where a rapid cannot be carved (below the axis, or into too many
//! pieces), the group closes first and the rapid meets the cut stock.
//!
//! Why our own Minkowski sum and convex difference ([`geom::flat::minkowski`],
//! [`geom::flat::minus_convex`]): geo, `parry2d` and `i_overlay` have no Minkowski sum of
//! polygons (the edge merge of two convex ones is 30 lines), and carving a rapid with
//! `i_overlay`'s difference would be a boolean call a rapid, ~147 000 instructions each on the
//! stock bench (`PERFORMANCE.md`), where cutting a convex piece by a few convex regions
//! costs a few thousand.

use crate::outline::Outline;
use geom::flat::{bounds, convex_hull, minkowski, minus_convex, sweep_chain, sweep_convex, P};
use geom::{Pt, Rect};
use std::collections::VecDeque;
use std::sync::Arc;

/// Most lanes (feed paths) one pass may hold.
const MAX_LANES: usize = 16;
/// How far a pass's vertex may lie from where its lane's first path and step put it, mm:
/// programmed positions a cycle computed (float rounding of `k · step`, far below this).
const LINEAR_TOL: f64 = 1e-6;
/// Pieces of a carved rapid smaller than this (mm²) are rounding slivers, left out: a
/// crash needs [`crate::CRASH_MIN_AREA`] = 10⁻⁶ mm² or more.
const TINY_AREA: f64 = 1e-10;
/// Most convex pieces a carved rapid may leave; more closes the group instead.
const MAX_PIECES: usize = 256;

/// A feed path as the builder offers it.
#[derive(Clone, Copy)]
struct Path<'a> {
    outline: &'a Arc<Outline>,
    pts: &'a [P],
    seg: usize,
}

/// A feed path emitted on its own, kept while a group may still start from it.
struct Recorded {
    outline: Arc<Outline>,
    pts: Vec<P>,
    /// Its first point (kept beside: compared with every path offered).
    first: P,
}

/// One feed path of the repeated pass, over the passes absorbed so far.
pub(crate) struct Lane {
    pub(crate) outline: Arc<Outline>,
    /// Its path in the group's first pass.
    pub(crate) first: Vec<P>,
    /// The step of each vertex from one pass to the next.
    pub(crate) step: Vec<P>,
    /// Passes absorbed (at least one).
    pub(crate) count: usize,
    /// The last segment of its last pass.
    pub(crate) seg: usize,
    /// The outline's box (min, max) about its reference point.
    extent: (P, P),
}

impl Lane {
    /// The path of pass `n` (0 is the first).
    fn path_at(&self, n: usize) -> impl Iterator<Item = P> + '_ {
        let k = n as f64;
        self.first
            .iter()
            .zip(&self.step)
            .map(move |(p, w)| [p[0] + k * w[0], p[1] + k * w[1]])
    }

    /// Whether `path` is this lane's next pass.
    fn next_is(&self, path: &Path) -> bool {
        Arc::ptr_eq(&self.outline, path.outline)
            && path.pts.len() == self.first.len()
            && self.path_at(self.count).zip(path.pts).all(|(e, p)| {
                (e[0] - p[0]).abs() <= LINEAR_TOL && (e[1] - p[1]).abs() <= LINEAR_TOL
            })
    }

    /// The steps from `from` to `to` when `to` may continue it as a lane: same outline,
    /// same vertex count, every step within `limit`, one common step for a path of more
    /// than one segment.
    fn steps(from: &Recorded, to: &Path, limit: f64) -> Option<Vec<P>> {
        if !Arc::ptr_eq(&from.outline, to.outline) || from.pts.len() != to.pts.len() {
            return None;
        }
        let step = |k: usize| {
            let (a, b) = (from.pts[k], to.pts[k]);
            [b[0] - a[0], b[1] - a[1]]
        };
        // (squared lengths: most recent paths are far from this one, told at the first
        // vertex, and a square root there for every path was 2 % of a grooving run)
        let far = |w: P| w[0] * w[0] + w[1] * w[1] > limit * limit;
        let w0 = step(0);
        if far(w0) {
            return None;
        }
        let mut common = true;
        for k in 1..from.pts.len() {
            let w = step(k);
            if far(w) {
                return None;
            }
            common &= (w[0] - w0[0]).abs() <= LINEAR_TOL && (w[1] - w0[1]).abs() <= LINEAR_TOL;
        }
        // a segment whose ends step apart sweeps a trapezoid, not twisted: longer than the
        // steps (its hull is then the strip the passes rule)
        let (a, b) = (to.pts[0], to.pts[to.pts.len() - 1]);
        let ruled = to.pts.len() == 2 && (b[0] - a[0]).hypot(b[1] - a[1]) > 2.0 * limit;
        (common || ruled).then(|| (0..from.pts.len()).map(step).collect())
    }

    fn new(path: Path, step: Vec<P>) -> Option<Self> {
        let extent = path.outline.bbox()?;
        let lane = Self {
            outline: Arc::clone(path.outline),
            first: path.pts.to_vec(),
            step,
            count: 1,
            seg: path.seg,
            extent,
        };
        lane.above_axis(0).then_some(lane)
    }

    /// Whether pass `n` stays above the axis (a carved rapid is measured in the folded
    /// section, the regions are not).
    fn above_axis(&self, n: usize) -> bool {
        self.reach(self.path_at(n)).min.r >= 0.0
    }

    /// The box of the outline placed at each of `points`.
    fn reach(&self, points: impl IntoIterator<Item = P>) -> Rect {
        let (lo, hi) = self.extent;
        let mut r = Rect::EMPTY;
        for p in points {
            r.add(Pt::new(p[0] + lo[0], p[1] + lo[1]));
            r.add(Pt::new(p[0] + hi[0], p[1] + hi[1]));
        }
        r
    }

    /// The box of its region so far: the outline about its first and last paths (every
    /// vertex moves on a line in between).
    fn bbox(&self) -> Rect {
        self.reach(
            self.first
                .iter()
                .copied()
                .chain(self.path_at(self.count - 1)),
        )
    }

    /// The sweep of the passes so far: convex polygons (a lane of one segment) or rings.
    pub(crate) fn sweep(&self) -> (Vec<Vec<P>>, bool) {
        if self.first.len() == 2 {
            (self.regions(0).collect(), true)
        } else {
            let n = (self.count - 1) as f64;
            let w = [self.step[0][0] * n, self.step[0][1] * n];
            let rings = self
                .outline
                .parts
                .iter()
                .map(|part| sweep_chain(&sweep_convex(part, w), &self.first))
                .collect();
            (rings, false)
        }
    }

    /// The region segment `i` of the path sweeps over the passes so far, one convex
    /// polygon per outline part: `part ⊕ hull(a, b, b + N w_b, a + N w_a)`.
    fn regions(&self, i: usize) -> impl Iterator<Item = Vec<P>> + '_ {
        let quad = self.quad(i);
        let quad = convex_hull(&quad);
        self.outline
            .parts
            .iter()
            .map(move |part| minkowski(part, &quad))
    }

    /// The corners `a, b, b + N w_b, a + N w_a` of segment `i` over the passes so far.
    fn quad(&self, i: usize) -> [P; 4] {
        let n = (self.count - 1) as f64;
        let (a, b) = (self.first[i], self.first[i + 1]);
        let (wa, wb) = (self.step[i], self.step[i + 1]);
        [
            a,
            b,
            [b[0] + n * wb[0], b[1] + n * wb[1]],
            [a[0] + n * wa[0], a[1] + n * wa[1]],
        ]
    }

    /// `pieces` (convex) with this lane's regions so far taken out; `None` when they
    /// would be more than [`MAX_PIECES`]. Only segments whose region's box meets the
    /// pieces are looked at (a ring lane of an arc has a hundred).
    fn carve(&self, mut pieces: Vec<Vec<P>>) -> Option<Vec<Vec<P>>> {
        for i in 0..self.first.len() - 1 {
            if !bounds(pieces.iter().flatten()).intersects(&self.reach(self.quad(i))) {
                continue;
            }
            for region in self.regions(i) {
                pieces = pieces
                    .iter()
                    .flat_map(|p| minus_convex(p, &region, TINY_AREA))
                    .collect();
                if pieces.is_empty() {
                    return Some(pieces);
                }
                if pieces.len() > MAX_PIECES {
                    return None;
                }
            }
        }
        Some(pieces)
    }
}

/// What [`PassGroups::offer`] did with a feed path.
pub(crate) enum Offer {
    /// Taken into the open group: nothing to emit now.
    Absorbed,
    /// Emit it as usual (after the lanes of a group that closed, when given).
    Emit(Option<Vec<Lane>>),
}

/// The recent feed paths and the open group.
pub(crate) struct PassGroups {
    /// Largest step between passes, mm (the merge tolerance).
    limit: f64,
    /// Feed paths emitted one by one since the last group (the pass a group would repeat).
    recent: VecDeque<Recorded>,
    /// Where in `recent` the group's pass starts.
    base: usize,
    lanes: Vec<Lane>,
    /// All lanes of the pass are known (its second pass in the group has begun).
    fixed: bool,
    /// The lane the next path should continue.
    cursor: usize,
}

impl PassGroups {
    pub(crate) fn new(limit: f64) -> Self {
        Self {
            limit,
            recent: VecDeque::new(),
            base: 0,
            lanes: Vec::new(),
            fixed: false,
            cursor: 0,
        }
    }

    pub(crate) fn is_open(&self) -> bool {
        !self.lanes.is_empty()
    }

    /// Ends the open group: its lanes, to be emitted as one sweep now.
    pub(crate) fn close(&mut self) -> Option<Vec<Lane>> {
        self.recent.clear();
        self.fixed = false;
        self.cursor = 0;
        (!self.lanes.is_empty()).then(|| std::mem::take(&mut self.lanes))
    }

    /// A feed path about to be emitted (an exact path of a tool without a body, ending at
    /// segment `seg`): taken into the group when it continues its lane, or it starts a
    /// group with the recent path it repeats, or it is emitted (closing the group).
    pub(crate) fn offer(&mut self, outline: &Arc<Outline>, pts: &[P], seg: usize) -> Offer {
        let path = Path { outline, pts, seg };
        if self.is_open() {
            if self.absorb(&path) {
                return Offer::Absorbed;
            }
            let closed = self.close();
            self.record(path);
            return Offer::Emit(closed);
        }
        // a group starts where a recent path repeats with a small step
        let limit = self.limit;
        let p0 = pts.first().copied().unwrap_or_default();
        let start = self
            .recent
            .iter()
            .enumerate()
            .filter(|(_, q)| {
                // told apart by their first points, most of them
                (q.first[0] - p0[0]).abs() <= limit && (q.first[1] - p0[1]).abs() <= limit
            })
            .find_map(|(k, q)| Lane::steps(q, &path, limit).map(|w| (k, w)));
        if let Some((k, step)) = start {
            if let Some(lane) = Lane::new(path, step) {
                self.base = k;
                self.lanes.push(lane);
                self.cursor = 1;
                return Offer::Absorbed;
            }
        }
        self.record(path);
        Offer::Emit(None)
    }

    fn record(&mut self, path: Path) {
        // the oldest one's vector is reused
        let mut pts = if self.recent.len() == MAX_LANES {
            self.recent.pop_front().map(|r| r.pts).unwrap_or_default()
        } else {
            Vec::new()
        };
        pts.clear();
        pts.extend_from_slice(path.pts);
        self.recent.push_back(Recorded {
            outline: Arc::clone(path.outline),
            first: path.pts.first().copied().unwrap_or_default(),
            pts,
        });
    }

    /// Takes `path` into the open group as its expected lane's next pass.
    fn absorb(&mut self, path: &Path) -> bool {
        if !self.fixed {
            // the group's first pass: a lane for each path of the pass it repeats
            let k = self.base + self.lanes.len();
            if let Some(step) = self
                .recent
                .get(k)
                .and_then(|q| Lane::steps(q, path, self.limit))
            {
                if self.lanes.len() < MAX_LANES {
                    if let Some(lane) = Lane::new(*path, step) {
                        self.lanes.push(lane);
                        self.cursor = self.lanes.len();
                        return true;
                    }
                }
                return false;
            }
            if !self.lanes[0].next_is(path) {
                return false;
            }
            self.fixed = true;
            self.cursor = 0;
        }
        let c = self.cursor;
        let lane = &mut self.lanes[c];
        if !lane.next_is(path) || !lane.above_axis(lane.count) {
            return false;
        }
        lane.count += 1;
        lane.seg = path.seg;
        self.cursor = (c + 1) % self.lanes.len();
        true
    }

    /// The convex `poly` (a rapid's sweep) with the group's regions so far taken out, as
    /// convex pieces; `None` when they get too many: close the group first.
    pub(crate) fn carve(&self, poly: &[P]) -> Option<Vec<Vec<P>>> {
        let mut pieces = vec![poly.to_vec()];
        for lane in &self.lanes {
            if pieces.is_empty() {
                break;
            }
            if bounds(pieces.iter().flatten()).intersects(&lane.bbox()) {
                pieces = lane.carve(pieces)?;
            }
        }
        Some(pieces)
    }
}

#[cfg(test)]
mod tests {
    use crate::overlay::Grid;
    use crate::removal::tests::{seg, v35};
    use crate::sweep::SweepBuilder;
    use crate::{
        hausdorff, simulate, symmetric_difference_area, Blank, SimOptions, Simulation, Tool,
        ToolTable,
    };
    use expander::{Motion, Pt, Segment};
    use geom::flat::{clip_to_hull, convex_hull, minkowski, minus_convex, pts, P};
    use geom::ring::signed_area;

    fn area(p: &[P]) -> f64 {
        signed_area(&pts(p))
    }

    /// Pseudo-random convex polygons (hulls of 2 to 9 points; one or two points too).
    fn polygons() -> Vec<Vec<P>> {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % 2001) as f64 / 100.0 - 10.0
        };
        (0..300)
            .map(|k| {
                let n = 1 + k % 9;
                let raw: Vec<P> = (0..n).map(|_| [next(), next()]).collect();
                if n <= 2 {
                    raw
                } else {
                    convex_hull(&raw)
                }
            })
            .collect()
    }

    /// The Minkowski sum by merged edges is the hull of all pairwise sums: same area, and
    /// every sum inside it.
    #[test]
    fn minkowski_sum_is_the_hull_of_the_pairwise_sums() {
        let polys = polygons();
        for w in polys.windows(2) {
            let (a, b) = (&w[0], &w[1]);
            if a.len() < 3 && b.len() < 3 {
                continue;
            }
            let sum = minkowski(a, b);
            let sums: Vec<P> = a
                .iter()
                .flat_map(|p| b.iter().map(move |q| [p[0] + q[0], p[1] + q[1]]))
                .collect();
            let hull = convex_hull(&sums);
            assert!(
                (area(&sum) - area(&hull)).abs() <= 1e-9 * area(&hull).max(1.0),
                "{a:?} ⊕ {b:?}: {} against {}",
                area(&sum),
                area(&hull)
            );
            assert!(area(&sum) > 0.0, "counter-clockwise");
        }
    }

    /// What `minus_convex` leaves plus what `h` covers of `p` is all of `p`, and no piece
    /// overlaps `h`.
    #[test]
    fn minus_convex_leaves_exactly_the_part_outside() {
        let polys: Vec<Vec<P>> = polygons().into_iter().filter(|p| p.len() >= 3).collect();
        let mut split = 0;
        for w in polys.windows(2) {
            let (p, h) = (&w[0], &w[1]);
            let pieces = minus_convex(p, h, 0.0);
            let inside = area(&clip_to_hull(p, h));
            let outside: f64 = pieces.iter().map(|q| area(q)).sum();
            assert!(
                (inside + outside - area(p)).abs() <= 1e-9 * area(p).max(1.0),
                "{inside} + {outside} ≠ {}",
                area(p)
            );
            for q in &pieces {
                assert!(area(&clip_to_hull(q, h)).abs() <= 1e-9 * area(p).max(1.0));
            }
            split += usize::from(pieces.len() > 1);
        }
        assert!(split > 10, "the cases cut pieces apart ({split})");
        // a square inside a bigger one leaves nothing; beside it, all of itself
        let sq = |x: f64, y: f64, s: f64| vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
        assert!(minus_convex(&sq(1.0, 1.0, 1.0), &sq(0.0, 0.0, 3.0), 0.0).is_empty());
        let beside = minus_convex(&sq(5.0, 0.0, 1.0), &sq(0.0, 0.0, 3.0), 0.0);
        assert_eq!(beside.len(), 1);
        assert!((area(&beside[0]) - 1.0).abs() < 1e-12);
    }

    /// Passes of a G90-like roughing on a Φ40 bar: every pass 0.0002 mm deeper (more than
    /// 5 000 moves, so that passes group), to a shoulder at Z-20, retracting at 45°;
    /// `detour(k, r)` gives the rapids that take pass `k` (at radius `r`) back to Z5.
    fn roughing(detour: impl Fn(usize, f64) -> Vec<P>) -> Vec<Segment> {
        let mut segs = Vec::new();
        let mut at = [5.0, 21.0];
        let mut go = |segs: &mut Vec<Segment>, m: Motion, to: P| {
            segs.push(seg(m, at, to));
            at = to;
        };
        for k in 1..=1300 {
            let r = 20.0 - 0.0002 * k as f64;
            go(&mut segs, Motion::Rapid, [5.0, r]);
            go(&mut segs, Motion::Feed, [-20.0, r]);
            go(&mut segs, Motion::Feed, [-19.5, r + 0.5]);
            for p in detour(k, r) {
                go(&mut segs, Motion::Rapid, p);
            }
            go(&mut segs, Motion::Rapid, [5.0, r + 0.5]);
        }
        segs
    }

    fn cut(segs: &[Segment], pass_groups: bool) -> Simulation {
        let blank = Blank::bar(40.0, 30.0, 0.0, None).expect("bar");
        let opts = SimOptions {
            pass_groups,
            ..SimOptions::default()
        };
        simulate(&blank, &v35(), segs, &opts, &mut |_| {})
    }

    /// The sweeps the builder makes of `segs` on the Φ40 bar's box: (cuts, rapids).
    fn sweeps(segs: &[Segment], pass_groups: bool) -> (usize, usize) {
        let clip = geom::Rect::new(geom::Pt::new(-31.0, -1.0), geom::Pt::new(1.2, 21.0));
        let grid = Grid::new(clip.grown(1.0));
        let tools = v35();
        let mut b = SweepBuilder::new(&grid, clip, &tools, 0.001, 0.0005);
        b.set_pass_groups(pass_groups);
        for (i, s) in segs.iter().enumerate() {
            b.push(i, s, None);
        }
        b.flush_run();
        let items = b.take().items;
        let rapids = items.iter().filter(|it| it.rapid).count();
        (items.len() - rapids, rapids)
    }

    /// 1 300 passes 0.0002 mm apart cut as groups: the part within `merge_tol / 2` of the
    /// pass-by-pass one (whose shoulder keeps a tooth of each pass, 10⁻⁵ mm high), the same
    /// area removed to 10⁻⁶ mm², no crash in either.
    #[test]
    fn grouped_passes_cut_the_part_within_half_the_merge_tolerance() {
        let segs = roughing(|_, _| Vec::new());
        let (grouped, single) = (cut(&segs, true), cut(&segs, false));
        let h = hausdorff(&grouped.final_shapes, &single.final_shapes);
        assert!(h <= 0.00025, "hausdorff {h}");
        let d = symmetric_difference_area(&grouped.final_shapes, &single.final_shapes);
        assert!(d < 1e-3, "symmetric difference {d} mm²");
        assert!((grouped.removed_area - single.removed_area).abs() < 1e-3);
        assert!(grouped.crashes.is_empty() && single.crashes.is_empty());
        // one sweep for the group (after the first pass's two), the rapids carved away
        // (each wholly inside what the passes before it cut), against a sweep per feed
        assert_eq!(sweeps(&segs, false), (2600, 1300));
        assert_eq!(sweeps(&segs, true), (3, 1));
    }

    /// A rapid back just above the floor the passes before it cut (0.0001 mm) meets no
    /// stock; the group's later cut is not yet in the removal's stock there, so without
    /// carving the group's regions out of the rapid it would be a false crash.
    #[test]
    fn a_rapid_over_the_floor_the_group_cut_is_no_crash() {
        let segs = roughing(|k, r| {
            if k == 700 {
                vec![[-15.0, r + 0.0001]]
            } else {
                Vec::new()
            }
        });
        let (grouped, single) = (cut(&segs, true), cut(&segs, false));
        assert!(single.crashes.is_empty(), "{:?}", single.crashes);
        assert!(grouped.crashes.is_empty(), "{:?}", grouped.crashes);
        assert!(sweeps(&segs, true).0 < 10);
    }

    /// A rapid that plunges 0.05 mm below the floor of its pass, into stock the later
    /// passes of the group cut, is the same crash with and without groups.
    #[test]
    fn a_rapid_into_what_later_passes_cut_is_the_same_crash() {
        let segs = roughing(|k, r| {
            if k == 700 {
                vec![[-10.0, r + 0.5], [-10.0, r - 0.05], [-10.0, r + 0.5]]
            } else {
                Vec::new()
            }
        });
        let (grouped, single) = (cut(&segs, true), cut(&segs, false));
        assert_eq!(single.crashes.len(), 1, "{:?}", single.crashes);
        assert_eq!(grouped.crashes.len(), 1, "{:?}", grouped.crashes);
        let (g, s) = (&grouped.crashes[0], &single.crashes[0]);
        assert_eq!(g.segment, s.segment);
        assert!(
            (g.area - s.area).abs() <= 1e-3 * s.area,
            "{} vs {}",
            g.area,
            s.area
        );
        assert!(
            (g.depth - s.depth).abs() <= 0.00025,
            "{} vs {}",
            g.depth,
            s.depth
        );
        assert!(sweeps(&segs, true).0 < 10);
    }

    /// The G73-like pattern of `passes` passes (straights, a taper, an R10 arc, out past
    /// the bar), moved by (0.2, 0.1) mm in all; in the pass `detour` names, a rapid from
    /// the arc's end plunges to a point 0.03 mm below that pass's floor, and back.
    fn g73_pattern(passes: usize, detour: Option<usize>) -> Vec<Segment> {
        let mut segs = Vec::new();
        let mut at = [10.0, 55.0];
        for k in 0..passes {
            let t = 1.0 - (k + 1) as f64 / passes as f64;
            let (dz, dr) = (0.2 * t, 0.1 * t);
            let mut go = |m: Motion, to: P| {
                segs.push(seg(m, at, to));
                at = to;
            };
            go(Motion::Rapid, [dz + 2.0, 20.0 + dr]);
            go(Motion::Feed, [dz, 20.0 + dr]);
            go(Motion::Feed, [dz - 10.0, 20.0 + dr]);
            go(Motion::Feed, [dz - 15.0, 30.0 + dr]);
            go(Motion::Feed, [dz - 25.0, 30.0 + dr]);
            let mut arc = seg(Motion::Feed, at, [dz - 35.0, 40.0 + dr]);
            arc.arc = Some(expander::Arc {
                center: Pt::new(dz - 35.0, 30.0 + dr),
                ccw: false,
            });
            segs.push(arc);
            at = [dz - 35.0, 40.0 + dr];
            let mut go = |m: Motion, to: P| {
                segs.push(seg(m, at, to));
                at = to;
            };
            if detour == Some(k) {
                go(Motion::Rapid, [dz - 24.0, 30.0 + dr - 0.03]);
                go(Motion::Rapid, [dz - 35.0, 40.0 + dr]);
            }
            go(Motion::Feed, [dz - 40.0, 52.0 + dr]);
            go(Motion::Rapid, [dz - 40.0, 55.0]);
            go(Motion::Rapid, [10.0, 55.0]);
        }
        segs
    }

    /// `segs` cut on a Φ100 bar with the default 55° insert, with and without groups.
    fn g73_cut(segs: &[Segment]) -> (Simulation, Simulation) {
        let blank = Blank::bar(100.0, 60.0, 0.0, None).expect("bar");
        let tools = ToolTable::from_tools(vec![(1, Tool::DEFAULT)]);
        let sim = |pass_groups| {
            let opts = SimOptions {
                pass_groups,
                ..SimOptions::default()
            };
            simulate(&blank, &tools, segs, &opts, &mut |_| {})
        };
        (sim(true), sim(false))
    }

    /// The G73-like pattern with a rapid from the arc's end into stock that later passes
    /// cut (and, with the tool's upper part, through the uncut bar above: 110 mm²), across
    /// the channel the group cut so far, carved by the arc's ring lane segment by segment:
    /// the same crash with and without groups (area within 10⁻³ mm²; not carved it is
    /// 0.012 mm² more), and no sliver left between the rapid's cut and the group's (the
    /// rapid cuts its whole sweep: cutting only its pieces left slivers 8.5 mm from the part).
    #[test]
    fn a_rapid_over_an_arc_lane_into_later_passes_is_the_same_crash() {
        let (grouped, single) = g73_cut(&g73_pattern(700, Some(350)));
        assert!(!single.crashes.is_empty());
        assert_eq!(
            grouped.crashes.len(),
            single.crashes.len(),
            "{:?}",
            grouped.crashes
        );
        for (g, s) in grouped.crashes.iter().zip(&single.crashes) {
            assert_eq!(g.segment, s.segment);
            assert!((g.area - s.area).abs() <= 1e-3, "{g:?} {s:?}");
            assert!((g.depth - s.depth).abs() <= 0.00025, "{g:?} {s:?}");
        }
        let h = hausdorff(&grouped.final_shapes, &single.final_shapes);
        assert!(h <= 0.00025, "hausdorff {h}");
    }

    /// A G73-like pattern (straights, a taper, an R10 arc, out past the bar; 700 passes
    /// moved by (0.2, 0.1) mm in all): the arc's chords make a ring lane. Grouped, the part
    /// is within `merge_tol / 2` of the pass-by-pass one, with a handful of sweeps.
    #[test]
    fn a_g73_pattern_with_an_arc_groups_within_half_the_merge_tolerance() {
        let passes = 700;
        let segs = g73_pattern(passes, None);
        assert!(segs.len() > crate::snapshot::EXACT_MAX_MOVES);
        let tools = ToolTable::from_tools(vec![(1, Tool::DEFAULT)]);
        let (grouped, single) = g73_cut(&segs);
        let h = hausdorff(&grouped.final_shapes, &single.final_shapes);
        assert!(h <= 0.00025, "hausdorff {h}");
        assert!((grouped.removed_area - single.removed_area).abs() < 1e-3);
        assert!(grouped.crashes.is_empty() && single.crashes.is_empty());
        let count = |pass_groups| {
            let clip = geom::Rect::new(geom::Pt::new(-61.0, -1.0), geom::Pt::new(1.2, 51.0));
            let grid = Grid::new(clip.grown(1.0));
            let mut b = SweepBuilder::new(&grid, clip, &tools, 0.001, 0.0005);
            b.set_pass_groups(pass_groups);
            for (i, s) in segs.iter().enumerate() {
                b.push(i, s, None);
            }
            b.flush_run();
            b.take().items.iter().filter(|it| !it.rapid).count()
        };
        let (few, many) = (count(true), count(false));
        assert!(many >= 5 * passes, "{many}");
        assert!(few <= 20, "{few}");
    }

    /// Pseudo-random roughings (bar, depth step up to the merge tolerance, shoulder or
    /// taper, retract) with rapids that plunge into the stock later passes cut and rapids
    /// that pass just over the floor: grouped, the same crashes (move, area, depth) as pass
    /// by pass, and the part within `merge_tol / 2`.
    #[test]
    fn random_roughings_keep_their_crashes_and_their_part() {
        let mut seed = 0x1234_5678_9abc_def1_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for case in 0..6 {
            let radius = 15.0 + 10.0 * next();
            let step = 0.0001 + 0.0004 * next();
            let zend0 = -10.0 - 15.0 * next();
            let taper = case % 2 == 1;
            let retract = 0.3 + 0.5 * next();
            let passes = 1300;
            let mut detours: Vec<(usize, u8, f64, f64)> = (0..4)
                .map(|k| {
                    let at = 50 + (next() * (passes - 100) as f64) as usize;
                    (at, (k % 2) as u8, next(), next())
                })
                .collect();
            detours.sort_by_key(|d| d.0);
            detours.dedup_by_key(|d| d.0);
            let mut segs = Vec::new();
            let mut at = [5.0, radius + 1.0];
            let mut go = |m: Motion, to: P| {
                segs.push(seg(m, at, to));
                at = to;
            };
            for k in 1..=passes {
                let r = radius - 0.05 - step * k as f64;
                let zend = if taper {
                    zend0 + 2.0 * step * k as f64
                } else {
                    zend0
                };
                go(Motion::Rapid, [5.0, r]);
                go(Motion::Feed, [zend, r]);
                go(Motion::Feed, [zend + retract, r + retract]);
                for &(_, kind, u, v) in detours.iter().filter(|d| d.0 == k) {
                    let z = zend + 2.0 + u * (-zend - 3.0);
                    if kind == 0 {
                        // a plunge 0.01-0.1 mm below this pass's floor: a crash
                        go(Motion::Rapid, [z, r + retract]);
                        go(Motion::Rapid, [z, r - 0.01 - 0.09 * v]);
                        go(Motion::Rapid, [z, r + retract]);
                    } else {
                        // down to 0.001-0.3 mm over the floor, then along it: no crash
                        go(Motion::Rapid, [z, r + 0.001 + 0.3 * v]);
                        go(Motion::Rapid, [-0.5, r + 0.001 + 0.3 * v]);
                    }
                }
                go(Motion::Rapid, [5.0, r + retract]);
            }
            let blank = Blank::bar(2.0 * radius, 40.0, 0.0, None).expect("bar");
            let sim = |pass_groups| {
                let opts = SimOptions {
                    pass_groups,
                    ..SimOptions::default()
                };
                simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
            };
            let (grouped, single) = (sim(true), sim(false));
            let plunges = detours.iter().filter(|d| d.1 == 0).count();
            assert_eq!(
                single.crashes.len(),
                plunges,
                "case {case}: {:?}",
                single.crashes
            );
            assert_eq!(
                grouped.crashes.len(),
                plunges,
                "case {case}: {:?}",
                grouped.crashes
            );
            for (g, s) in grouped.crashes.iter().zip(&single.crashes) {
                assert_eq!(g.segment, s.segment, "case {case}");
                assert!(
                    (g.area - s.area).abs() <= 1e-3 * s.area + 1e-5,
                    "case {case}: {g:?} {s:?}"
                );
                assert!(
                    (g.depth - s.depth).abs() <= 0.00025,
                    "case {case}: {g:?} {s:?}"
                );
            }
            let h = hausdorff(&grouped.final_shapes, &single.final_shapes);
            assert!(h <= 0.00025 + 1e-6, "case {case}: hausdorff {h}");
        }
    }

    /// A lane of one pass sweeps what that pass sweeps (its quad is a segment), and of
    /// three passes 0.0002 mm apart along r the segment's sweep grown by 0.0004 mm.
    #[test]
    fn a_lane_sweeps_its_passes_by_hand() {
        let tools = v35();
        let (outline, _) = tools.outline_for(1, expander::ToolHint::Table);
        let outline = std::sync::Arc::new(outline);
        let path = [[0.0, 10.0], [-20.0, 10.0]];
        let step = vec![[0.0, -0.0002], [0.0, -0.0002]];
        let lane = |count| super::Lane {
            outline: outline.clone(),
            first: path.to_vec(),
            step: step.clone(),
            count,
            seg: 0,
            extent: outline.bbox().expect("an outline"),
        };
        let single: f64 = outline
            .parts
            .iter()
            .map(|part| {
                let placed: Vec<P> = part
                    .iter()
                    .map(|v| [v[0] + path[0][0], v[1] + path[0][1]])
                    .collect();
                area(&geom::flat::sweep_convex(&placed, [-20.0, 0.0]))
            })
            .sum();
        let one: f64 = lane(1).regions(0).map(|r| area(&r)).sum();
        assert!((one - single).abs() < 1e-9, "{one} vs {single}");
        // three passes: a convex region moved 0.0004 mm along r grows by its width along z
        // (the 20 mm path plus the outline's width) times 0.0004 mm
        let three: f64 = lane(3).regions(0).map(|r| area(&r)).sum();
        let (lo, hi) = outline.bbox().expect("an outline");
        let width = 20.0 + (hi[0] - lo[0]);
        assert!(
            (three - single - width * 0.0004).abs() < 1e-9,
            "{three} vs {single}"
        );
    }
}
