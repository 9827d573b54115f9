//! Tiles: a Z strip's stock split into a tree of rectangles, each with its own small polygon
//! set, that sweeps descend only where they may touch stock.

use super::batch::{Batch, Trimmed, BATCH};
use super::crash::Fragment;
use crate::budget::{RunMemory, CHECK_EVERY};
use crate::overlay::{
    convex_contains, drop_grid_kinks, orient, point_in_ring, right_of, segments_meet, winds,
    Engine, Grid, IBox, IPt, IShapes,
};
use crate::ring_air;
use crate::sweep::{Item, Sweeps};
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};

/// A tile whose stock has more vertices than this is split in two. Smaller tiles make each
/// boolean call smaller and the tree deeper: 64 was the fastest with batches of
/// [`BATCH`] (the stock bench at 10⁵ moves; PERFORMANCE.md, "Batch and tile sizes").
const MAX_TILE_VERTICES: usize = 64;
/// A vertex of a tile's stock within this many grid steps of the segment between its
/// neighbours is dropped after each boolean call ([`drop_grid_kinks`]).
const KINK: i64 = 1;
/// Smallest tile side, mm.
pub(super) const MIN_TILE: f64 = 0.001;

/// A rectangle of the stock with its own small polygon set.
pub(super) struct Tile {
    /// Its rectangle.
    rect: IBox,
    /// The stock in it.
    stock: IShapes,
    /// The box of `stock`.
    bbox: IBox,
    /// Vertex count of `stock`.
    verts: usize,
}

/// A Z strip, split further (in two, along its longer side) wherever its stock gets
/// complex, so that no boolean call sees more than about [`MAX_TILE_VERTICES`] of stock.
/// A split node keeps its children's rectangles and the boxes of their stock (as of their
/// last flush: the stock only shrinks, so a sweep that misses a box misses the stock under
/// it), so a sweep that cannot touch a subtree's stock never descends into it.
pub(super) enum Node {
    Leaf(Tile),
    Split(Box<[Self; 2]>, [IBox; 2], [IBox; 2]),
}

impl Tile {
    /// Subtracts the batch from the stock in one boolean call.
    fn flush(&mut self, batch: &mut Batch, engine: &mut Engine, ctx: &Ctx, calls: &mut u32) {
        if batch.len() == 0 {
            return;
        }
        *calls += 1;
        if calls.is_multiple_of(CHECK_EVERY) {
            ctx.look_at_memory();
        }
        self.stock = engine.difference(&self.stock, batch.iter());
        drop_grid_kinks(&mut self.stock, KINK, &self.rect);
        self.bbox = IBox::of_shapes(&self.stock);
        self.verts = self.stock.iter().flatten().map(Vec::len).sum();
        batch.clear();
    }

    pub(super) fn new(rect: IBox, stock: IShapes) -> Self {
        let verts = stock.iter().flatten().map(Vec::len).sum();
        Self {
            rect,
            bbox: IBox::of_shapes(&stock),
            stock,
            verts,
        }
    }

    /// Processes `list` in order; returns the index of the first item not processed when
    /// the tile grew too complex and must split first.
    fn process(&mut self, list: &[u32], ctx: &Ctx, worker: &mut Worker) -> Option<usize> {
        let sweeps = ctx.sweeps;
        let Worker {
            engine,
            frags,
            batch,
            trim,
            runs,
            calls,
        } = worker;
        trim.ring_air = ctx.ring_air;
        // a box of the stock as it will be after the batch: smaller than the stock's box
        // when a core of the batch spans that (the stock outside it is the batch's to
        // cut); trimming and covering keep to the box of the stock as it is
        let mut reach = self.bbox;
        for (k, &i) in list.iter().enumerate() {
            if ctx.stopped() {
                break;
            }
            if self.verts > MAX_TILE_VERTICES && batch.len() == 0 && self.splittable(ctx) {
                return Some(k);
            }
            let it = &sweeps.items[i as usize];
            // air in this tile: the stock only shrinks, so missing the stock of the last
            // flush (less the batch's cores) means missing the stock of this moment
            if misses_box(ctx, it, &reach) {
                continue;
            }
            trim.clear();
            // a carved rapid: in the air where its pieces are (the rest is the group's)
            trim.push_probe(sweeps, it, &self.bbox);
            if !trim.rings().any(|r| {
                if r.convex || !ctx.ring_air {
                    touches(r.pts, r.convex, &self.stock, &reach)
                } else {
                    ring_air::touches(r.pts, &self.stock, &reach, runs)
                }
            }) {
                continue;
            }
            if it.body.is_some() {
                // a probe: the stock after every earlier cut (this move's own included)
                self.flush(batch, engine, ctx, calls);
                reach = self.bbox;
                self.probe(it, ctx, engine, frags, trim);
                continue;
            }
            let covered = ctx.cover && batch.covers(trim, &self.bbox);
            if it.rapid && !covered {
                self.flush(batch, engine, ctx, calls);
                reach = self.bbox;
                let met = self.probe(it, ctx, engine, frags, trim);
                if !it.probe.is_empty() {
                    // probed with its carved pieces: where they meet stock it cuts its
                    // whole sweep (cutting the pieces alone would leave slivers between
                    // them and the group's later cut); where not, it leaves the rest to
                    // the group (no boolean for a rapid in the air the group cut)
                    if !met {
                        continue;
                    }
                    trim.clear();
                    trim.push_sweep(sweeps, it, &self.bbox);
                }
            }
            if covered {
                continue;
            }
            batch.push(trim, &self.bbox, ctx.cover);
            for r in trim.rings() {
                reach = reach.outside(&r.core);
            }
            if batch.len() >= BATCH {
                self.flush(batch, engine, ctx, calls);
                reach = self.bbox;
            }
        }
        self.flush(batch, engine, ctx, calls);
        None
    }

    /// Intersects the sweep `it` (its [`Item::probe`] polygons) with the (flushed) stock
    /// and keeps the overlap as a crash fragment; leaves `trim` holding those polygons
    /// trimmed to a box of the stock. True when they overlap the stock.
    fn probe(
        &self,
        it: &Item,
        ctx: &Ctx,
        engine: &mut Engine,
        frags: &mut Vec<Fragment>,
        trim: &mut Trimmed,
    ) -> bool {
        if !it.bbox.overlaps(&self.bbox) {
            return false;
        }
        trim.clear();
        trim.push_probe(ctx.sweeps, it, &self.bbox);
        let overlap = engine.intersection(&self.stock, trim.iter());
        let a = ctx.grid.area(&overlap);
        if a > 0.0 {
            frags.push(Fragment::of(it, &overlap, a, ctx.grid));
        }
        a > 0.0
    }

    fn splittable(&self, ctx: &Ctx) -> bool {
        let size = i64::from(self.rect.max[0] - self.rect.min[0])
            .max(i64::from(self.rect.max[1] - self.rect.min[1]));
        size > ctx.min_tile
    }

    /// The two halves of the tile along its longer side (its batch must be empty). Where
    /// it splits depends on the tile alone, not on the stock at that moment: the seams of
    /// the final part (a grid point where an edge crossed a tile's side) are then the same
    /// however the moves are batched (two tools that cut alike give the same report).
    fn split(self, engine: &mut Engine) -> Node {
        let r = self.rect;
        let halves = if r.max[0] - r.min[0] >= r.max[1] - r.min[1] {
            let mid = ((i64::from(r.min[0]) + i64::from(r.max[0])) / 2) as i32;
            [
                IBox {
                    min: r.min,
                    max: [mid, r.max[1]],
                },
                IBox {
                    min: [mid, r.min[1]],
                    max: r.max,
                },
            ]
        } else {
            let mid = ((i64::from(r.min[1]) + i64::from(r.max[1])) / 2) as i32;
            [
                IBox {
                    min: r.min,
                    max: [r.max[0], mid],
                },
                IBox {
                    min: [r.min[0], mid],
                    max: r.max,
                },
            ]
        };
        let child = |b: IBox, engine: &mut Engine| {
            let ring = b.corners();
            Node::Leaf(Self::new(b, engine.intersection(&self.stock, [&ring[..]])))
        };
        let a = child(halves[0], engine);
        let b = child(halves[1], engine);
        let boxes = [a.stock_box(), b.stock_box()];
        Node::Split(Box::new([a, b]), halves, boxes)
    }
}

/// What every tile needs to know about the run and the epoch.
pub(super) struct Ctx<'a> {
    pub(super) grid: &'a Grid,
    /// Tiles no smaller than this (grid units) are never split.
    pub(super) min_tile: i64,
    /// The epoch's sweeps.
    pub(super) sweeps: &'a Sweeps,
    /// Rings get their exact air tests ([`super::SimOptions::ring_air`]).
    pub(super) ring_air: bool,
    /// Batches leave out what they cover ([`super::SimOptions::cover`]).
    pub(super) cover: bool,
    /// The run's memory budget ([`super::SimOptions::max_memory`]).
    pub(super) budget: Option<&'a RunMemory>,
    /// Set when the process went over the budget: every worker stops.
    pub(super) stop: &'a AtomicBool,
}

impl Ctx<'_> {
    /// Sets [`Ctx::stop`] when the process holds more than the budget and this run is the
    /// one to stop.
    fn look_at_memory(&self) {
        if self.budget.is_some_and(|b| b.over().is_some()) {
            self.stop.store(true, Ordering::Relaxed);
        }
    }

    /// Whether the workers stop (the run went over its memory budget).
    pub(super) fn stopped(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }
}

/// What one worker thread writes to: its boolean engine, the rapid cuts it found, and its
/// scratch space.
pub(super) struct Worker<'e> {
    pub(super) engine: &'e mut Engine,
    /// The rapid cuts found.
    pub(super) frags: Vec<Fragment>,
    /// The tile at hand's sweeps waiting for a boolean call (empty between tiles).
    pub(super) batch: Batch,
    /// The sweep at hand trimmed to the tile.
    pub(super) trim: Trimmed,
    /// Run boxes of a ring ([`ring_air::touches`]).
    pub(super) runs: Vec<IBox>,
    /// Boolean calls made (the memory is looked at every [`CHECK_EVERY`]).
    pub(super) calls: u32,
}

impl Node {
    pub(super) fn process(&mut self, list: &[u32], ctx: &Ctx, worker: &mut Worker) {
        match self {
            Self::Leaf(tile) => {
                let Some(rest) = tile.process(list, ctx, worker) else {
                    return;
                };
                let tile = std::mem::replace(tile, Tile::new(IBox::EMPTY, Vec::new()));
                *self = tile.split(worker.engine);
                self.process(&list[rest..], ctx, worker);
            }
            Self::Split(children, rects, boxes) => {
                for ((child, rect), sb) in children.iter_mut().zip(rects.iter()).zip(&mut *boxes) {
                    if ctx.stopped() {
                        break;
                    }
                    let sub: Vec<u32> = list
                        .iter()
                        .copied()
                        .filter(|&i| {
                            let it = &ctx.sweeps.items[i as usize];
                            it.bbox.overlaps(rect) && !misses_box(ctx, it, sb)
                        })
                        .collect();
                    if !sub.is_empty() {
                        child.process(&sub, ctx, worker);
                        *sb = child.stock_box();
                    }
                }
                // a child cut empty stays empty: the node is its sibling (one level less
                // for every later sweep to descend)
                if let Some(k) = boxes.iter().position(IBox::is_empty) {
                    let [a, b] = std::mem::replace(
                        children.as_mut(),
                        [
                            Self::Leaf(Tile::new(IBox::EMPTY, Vec::new())),
                            Self::Leaf(Tile::new(IBox::EMPTY, Vec::new())),
                        ],
                    );
                    *self = if k == 0 { b } else { a };
                }
            }
        }
    }

    /// The box of the stock under this node (as of the last flushes).
    fn stock_box(&self) -> IBox {
        match self {
            Self::Leaf(tile) => tile.bbox,
            Self::Split(_, _, [a, b]) => {
                let mut u = *a;
                for p in b.corners() {
                    if b.min[0] <= b.max[0] {
                        u.add(p);
                    }
                }
                u
            }
        }
    }

    /// Whether any stock lies right of `x` (grid units): a move to the axis with nothing
    /// beyond it (a face to the centre) parts nothing off.
    pub(super) fn has_stock_right_of(&self, x: i32) -> bool {
        match self {
            Self::Leaf(tile) => {
                !tile.stock.is_empty()
                    && tile.bbox.max[0] > x
                    && tile.stock.iter().flatten().flatten().any(|p| p.x > x)
            }
            Self::Split(children, ..) => {
                children[0].has_stock_right_of(x) || children[1].has_stock_right_of(x)
            }
        }
    }

    /// The vertices of the stock under this node and its leaves.
    pub(super) fn census(&self) -> (usize, usize) {
        match self {
            Self::Leaf(tile) => (tile.verts, 1),
            Self::Split(children, ..) => {
                let (a, b) = (children[0].census(), children[1].census());
                (a.0 + b.0, a.1 + b.1)
            }
        }
    }

    /// A copy of the stock of every leaf, with the leaf's box (for a snapshot).
    pub(super) fn gather(&self, out: &mut Vec<(IBox, IShapes)>) {
        match self {
            Self::Leaf(tile) => out.push((tile.rect, tile.stock.clone())),
            Self::Split(children, ..) => {
                children[0].gather(out);
                children[1].gather(out);
            }
        }
    }

    /// The stock of every leaf with the leaf's box, the tree taken apart.
    pub(super) fn collect(self, out: &mut Vec<(IBox, IShapes)>) {
        match self {
            Self::Leaf(tile) => out.push((tile.rect, tile.stock)),
            Self::Split(children, ..) => {
                let [a, b] = *children;
                a.collect(out);
                b.collect(out);
            }
        }
    }
}

/// True when no polygon of the sweep `it` can share a point with the box `b`: its box
/// misses `b`, or (for a convex polygon) one of its edges has all of `b` strictly on its
/// right (a separating axis), or (for a ring) no edge meets `b` and `b` lies outside it
/// ([`ring_air::misses`]). Exact; one orientation test an edge of a hull, against the corner
/// of `b` farthest left of it; box tests first for a ring's edges. Cheap enough to run on
/// every tile and tree node a sweep's box overlaps (a long pass's box covers hundreds of a
/// shoulder's tiles that it misses).
fn misses_box(ctx: &Ctx, it: &Item, b: &IBox) -> bool {
    if !it.bbox.overlaps(b) {
        return true;
    }
    ctx.sweeps.parts_of(it).all(|poly| {
        if !poly.bbox.overlaps(b) {
            return true;
        }
        if poly.core.overlaps(b) {
            return false;
        }
        if poly.convex {
            separated(poly.pts, poly.hint, b)
        } else {
            ctx.ring_air && ring_air::misses(poly.pts, poly.runs, b)
        }
    })
}

/// True when an edge of the convex counter-clockwise polygon has every corner of `b`
/// strictly on its right; the edge of its hint first, which it then holds.
fn separated(pts: &[IPt], hint: &AtomicU32, b: &IBox) -> bool {
    let n = pts.len();
    let apart = |p: IPt, q: IPt| {
        // the corner maximising cross(q - p, c - p): largest y when the edge runs to +x,
        // smallest x when it runs to +y
        let c = IPt::new(
            if q.y > p.y { b.min[0] } else { b.max[0] },
            if q.x > p.x { b.max[1] } else { b.min[1] },
        );
        right_of(p, q, c)
    };
    let edge = |i: usize| (pts[i], pts[if i + 1 == n { 0 } else { i + 1 }]);
    let first = hint.load(Ordering::Relaxed) as usize;
    if first < n {
        let (p, q) = edge(first);
        if apart(p, q) {
            return true;
        }
    }
    // every edge in order (the last closes the ring), without a division per edge
    let found = pts
        .windows(2)
        .map(|w| (w[0], w[1]))
        .chain(pts.last().zip(pts.first()).map(|(&p, &q)| (p, q)))
        .position(|(p, q)| apart(p, q));
    match found {
        Some(i) => {
            hint.store(i as u32, Ordering::Relaxed);
            true
        }
        None => false,
    }
}

/// Whether a polygon and shapes may share a point (touching counts): an edge of one
/// crosses an edge of the other, or a vertex of one lies in the other (for a chain sweep's
/// ring, `convex` false: a point of non-zero winding).
fn touches(poly: &[IPt], convex: bool, shapes: &IShapes, shapes_box: &IBox) -> bool {
    let pb = IBox::of(poly.iter().copied());
    let n = poly.len();
    if !pb.overlaps(shapes_box) {
        return false;
    }
    // separating axis: an edge of the convex polygon with the whole box outside it
    let corners = shapes_box.corners();
    if convex
        && (0..n).any(|i| {
            corners
                .iter()
                .all(|&c| orient(poly[i], poly[(i + 1) % n], c) < 0)
        })
    {
        return false;
    }
    for s in shapes {
        for ring in s {
            let m = ring.len();
            for k in 0..m {
                let (a, b) = (ring[k], ring[(k + 1) % m]);
                let eb = IBox::of_segment(a, b);
                if !eb.overlaps(&pb) {
                    continue;
                }
                if if convex {
                    convex_contains(poly, &[a])
                } else {
                    winds(a, poly)
                } {
                    return true;
                }
                if (0..n).any(|i| {
                    let (p, q) = (poly[i], poly[(i + 1) % n]);
                    // the boxes first: a long ring has few edges near any stock edge
                    IBox::of_segment(p, q).overlaps(&eb) && segments_meet(p, q, a, b)
                }) {
                    return true;
                }
            }
        }
        // the polygon may lie wholly inside the shape
        if let (Some(outer), Some(&p)) = (s.first(), poly.first()) {
            if point_in_ring(p, outer) && !s[1..].iter().any(|h| point_in_ring(p, h)) {
                return true;
            }
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The one-corner separating-axis test agrees with testing all four corners of the box
    /// (the rule `touches` used), and the float-filtered orientation with the exact one, on
    /// pseudo-random convex polygons and boxes, small and near the ends of the i32 grid.
    #[test]
    fn one_corner_separation_matches_the_four_corner_test() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = |span: i64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % (2 * span as u64 + 1)) as i64 - span
        };
        let (mut separated_count, mut total) = (0, 0);
        for round in 0..4000 {
            let span = if round % 2 == 0 {
                50
            } else {
                i64::from(i32::MAX)
            };
            let pts: Vec<[f64; 2]> = (0..6)
                .map(|_| [next(span) as f64, next(span) as f64])
                .collect();
            let hull: Vec<IPt> = geom::flat::convex_hull(&pts)
                .iter()
                .map(|p| IPt::new(p[0] as i32, p[1] as i32))
                .collect();
            let (a, b) = (next(span) as i32, next(span) as i32);
            let (c, d) = (next(span) as i32, next(span) as i32);
            let bx = IBox {
                min: [a.min(c), b.min(d)],
                max: [a.max(c), b.max(d)],
            };
            let n = hull.len();
            let four = (0..n).any(|i| {
                bx.corners()
                    .iter()
                    .all(|&q| orient(hull[i], hull[(i + 1) % n], q) < 0)
            });
            // twice: the second starts from the hint the first left
            let hint = AtomicU32::new(0);
            assert_eq!(separated(&hull, &hint, &bx), four, "{hull:?} {bx:?}");
            assert_eq!(separated(&hull, &hint, &bx), four, "{hull:?} {bx:?}");
            for &q in &bx.corners() {
                for i in 0..n {
                    let (p0, p1) = (hull[i], hull[(i + 1) % n]);
                    assert_eq!(right_of(p0, p1, q), orient(p0, p1, q) < 0);
                }
            }
            separated_count += usize::from(four);
            total += 1;
        }
        // both outcomes occur
        assert!(separated_count > total / 10 && separated_count < total * 9 / 10);
    }

    /// The ring's touch test (one winding test a stock ring, run boxes) answers as the
    /// edge-by-edge test did, on random rings and stock rings (touching and collinear
    /// cases included: small integer coordinates).
    #[test]
    fn ring_touches_matches_the_edge_by_edge_test() {
        use crate::ring_air::tests::{random_ring, Rng};
        let mut rng = Rng(0x1234_5678_9abc_def1);
        let (mut hits, mut total) = (0, 0);
        let mut runs = Vec::new();
        for _ in 0..20_000 {
            let ring = random_ring(&mut rng);
            if ring.len() < 3 {
                continue;
            }
            let shapes: IShapes = (0..1 + rng.next(1).unsigned_abs())
                .map(|_| {
                    let (x, y) = (rng.next(24) as i32, rng.next(24) as i32);
                    let outer: Vec<IPt> = (0..3 + rng.next(2).unsigned_abs())
                        .map(|_| IPt::new(x + rng.next(5) as i32, y + rng.next(5) as i32))
                        .collect();
                    vec![outer]
                })
                .collect();
            let sb = IBox::of_shapes(&shapes);
            let old = touches(&ring, false, &shapes, &sb);
            assert_eq!(
                ring_air::touches(&ring, &shapes, &sb, &mut runs),
                old,
                "{ring:?} {shapes:?}"
            );
            hits += usize::from(old);
            total += 1;
        }
        assert!(
            hits > total / 10 && hits < total * 9 / 10,
            "{hits} of {total}"
        );
    }
}
