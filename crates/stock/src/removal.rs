//! Material removal: final = blank − ⋃ sweeps, with rapid crashes as exact events.
//!
//! How it stays fast for 10⁶ moves (measured figures in `PERFORMANCE.md`):
//! - every boolean runs in `i_overlay`'s integer core on one fixed grid (see `overlay.rs`);
//! - the stock is cut into Z strips, each its own small polygon set, so a boolean call
//!   only sees the stock near the move; strips are independent, so they run in parallel;
//! - within a strip, sweeps are subtracted in batches of [`BATCH`]: one call removes the
//!   union of the batch (no sweep-by-sweep subtraction from an ever-growing polygon, no
//!   single giant call with k² tool-tool intersections); a sweep that one in the batch
//!   covers where the tile has stock is left out, and one that covers those takes their
//!   place ([`SimOptions::cover`]: a roughing's passes then make one call per tile and
//!   epoch);
//! - sweeps that cannot touch a subtree's stock box (box overlap, then a separating axis)
//!   never descend into it, and those that miss a tile's stock (air cuts) never reach a
//!   boolean call;
//! - collinear overlapping feeds (pecks) were already merged into one sweep, as were
//!   chains of nearly collinear short feeds (within [`SimOptions::merge_tol`]), and short
//!   paths of feeds are swept as one ring ([`SimOptions::feed_paths`]);
//! - in long programs, passes that repeat the one before moved by a tiny step are one
//!   sweep ([`SimOptions::pass_groups`], the `pass_group` module).
//!
//! Crashes: a rapid whose box meets a strip's stock box flushes that strip's batch (so
//! the stock is exactly the stock after every earlier move) and intersects its sweep with
//! it; the overlaps of all strips add up to the crash area.

use crate::overlay::{
    convex_contains, convex_covers_in_box, orient, point_in_ring, segments_meet, winds, Engine,
    Grid, IBox, IPt, IShapes,
};
use crate::ring_air;
use crate::snapshot::Snapshots;
use crate::sweep::{Item, Poly, SweepBuilder, Sweeps};
use crate::{area, revolved_volume, Blank, Shape, ToolTable};
use expander::{Motion, Segment};
use geom::distance::point_segment;
use geom::flat::{pts, P};
use geom::{ring, Pt, Rect};
use std::sync::atomic::{AtomicU32, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Smallest overlap (mm²) between a rapid's sweep and the stock that counts as a crash.
/// The threshold actually used for a rapid is the larger of this and 2 × grid step × the
/// sweep's perimeter, the biggest sliver rounding to the grid can create along an edge the
/// rapid shares with an earlier cut (a few 10⁻⁵ mm² for a 100 mm bar: ~0.1 nm grid step).
pub const CRASH_MIN_AREA: f64 = 1e-6;

/// Sweeps subtracted per boolean call in a tile. Consecutive sweeps overlap pairwise, so a
/// call's cost grows with k². Chosen with [`MAX_TILE_VERTICES`] on the stock bench at 10⁵
/// moves (roughing / taper / G73, s, tile 64): batch 2 0.97 / 0.85 / 3.53, 3 1.04 / 0.92 /
/// 3.86, 4 1.03 / 0.93 / 4.14; 8 and 16 took 1.8 and 23 s on the roughing (its passes lie
/// 0.00013 mm apart: the splitter meets nearly coincident edges k² times). With 256-vertex
/// tiles, 4 had been best on the tiny moves of the pipeline bench (4.42 / 3.89·10⁹
/// instructions for 2 / 4); the whole 10⁶-move contour run is the same with 2 (`farm-bench`
/// A/B 1.00), the 10⁶ grooving run 0.90.
const BATCH: usize = 2;
/// Target width of a Z strip, mm (strips are the units of parallel work; complex stock is
/// split further into tiles).
const STRIP_WIDTH: f64 = 30.0;
/// Upper bound on the number of strips.
const MAX_STRIPS: usize = 64;
/// A tile whose stock has more vertices than this is split in two. Smaller tiles make each
/// boolean call smaller and the tree deeper: stock bench at 10⁵ moves, batch 2 (roughing /
/// taper / G73 / contour, s): 256 1.41 / 0.93 / 4.55 / 0.024 (batch 4), 96 1.15 / 0.87 /
/// 3.77 / 0.028, 64 0.97 / 0.85 / 3.53 / 0.029, 48 0.96 / 0.82 / 3.46 / 0.037.
const MAX_TILE_VERTICES: usize = 64;
/// Smallest tile side, mm.
const MIN_TILE: f64 = 0.001;
/// Segments handled between two progress reports (also bounds the sweeps held in memory).
const EPOCH: usize = 32_768;

/// Options of a removal run.
#[derive(Debug, Clone, PartialEq)]
pub struct SimOptions {
    /// Chord tolerance for arcs, mm (default 0.001).
    pub chord_tol: f64,
    /// Chains of short feed moves (same tool, no rapid in between, never turning back) are
    /// swept as one straight move while every programmed point lies within this distance
    /// of it, mm (default 0.0005; capped at `chord_tol`; 0 or not finite: only exactly
    /// collinear feeds merge). The final part then differs from the unmerged result by at
    /// most this much wherever it was cut (see the `sweep` module). Arcs take part with
    /// their chord when it lies within `chord_tol − merge_tol` of them.
    pub merge_tol: f64,
    /// Consecutive feeds of one tool (each starting where the last ended, no rapid in
    /// between, a tool without a body to probe) are swept as one path of up to 128
    /// vertices: one ring, the exact Minkowski sum of the outline with the polyline
    /// (default true). Exact either way; false sweeps each (merged) move on its own.
    pub feed_paths: bool,
    /// A ring (a path or chorded arc swept as one, see `feed_paths`) is told apart from a
    /// tile's or subtree's stock box by its edges, a few box tests for most of them
    /// (default true). Exact either way; false tries every tile its box overlaps with the
    /// ring's full edge test (the behaviour before round 6 of PERFORMANCE.md).
    pub ring_air: bool,
    /// A sweep that a sweep already waiting in a tile's batch covers there (inside the
    /// tile's stock box) stays out of the batch, and a sweep takes out of the batch those it
    /// covers (default true): the passes of a roughing, each lowering a flat top, then make
    /// one boolean call per tile and epoch instead of one per pass. Exact either way; false
    /// sends every sweep that touches a tile's stock to its boolean call.
    pub cover: bool,
    /// Repeated passes (each the last moved by at most `merge_tol`, every vertex on its own
    /// line) are cut as the one region they sweep together, within `merge_tol / 2` of their
    /// union (default true; see the `pass_group` module). Only in programs of more than
    /// [`crate::snapshot::EXACT_MAX_MOVES`] moves: shorter ones are cut pass by pass, so
    /// their snapshots stay exact. False cuts every pass on its own.
    pub pass_groups: bool,
    /// Move counts after which the stock is wanted (see [`Simulation::snapshots`]), taken
    /// in the same pass. Counts of 0 or of all the moves and more are ignored: those are
    /// the blank and [`Simulation::final_shapes`].
    pub snapshot_after: Vec<usize>,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            chord_tol: 0.001,
            merge_tol: 0.0005,
            feed_paths: true,
            ring_air: true,
            cover: true,
            pass_groups: true,
            snapshot_after: Vec::new(),
        }
    }
}

/// A rapid move whose sweep overlapped the stock present at that moment, or a move (at any
/// speed) whose tool body met stock.
#[derive(Debug, Clone, PartialEq)]
pub struct Crash {
    /// Index of the move in the input slice.
    pub segment: usize,
    /// The non-cutting body that met stock ("holder", "boring bar", …); `None` for a
    /// rapid's cutting outline.
    pub body: Option<&'static str>,
    /// (z, r) where it first meets stock: the point of the overlap nearest the rapid's start.
    pub at: [f64; 2],
    /// Area of stock the rapid's sweep overlapped, mm².
    pub area: f64,
    /// Depth of the cut: the thickness of the overlapped stock measured normal to the
    /// move (a rapid that scrapes a 0.07 mm wedge has depth 0.07), mm.
    pub depth: f64,
}

/// The result of a removal run.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    /// The part after every move.
    pub final_shapes: Vec<Shape>,
    /// Rapids through stock, in program order.
    pub crashes: Vec<Crash>,
    /// Area of the half section removed, mm².
    pub removed_area: f64,
    /// Volume removed (solid of revolution), mm³.
    pub removed_volume: f64,
    /// (first segment index, message): skipped moves, defaulted tools.
    pub warnings: Vec<(usize, String)>,
    /// (move count k, the stock after the first k moves) for each count asked for in
    /// [`SimOptions::snapshot_after`], ascending. A merged chain of feeds still open at k
    /// is cut up to its last move so far; the run itself goes on unchanged. Programs of more
    /// than 5 000 moves get them at the removal's epoch ends instead: k is then the first
    /// count at or after the one asked for where all tiles are flushed (one snapshot for
    /// several counts when they fall in one epoch).
    pub snapshots: Vec<(usize, Vec<Shape>)>,
}

/// A rectangle of the stock with its own small polygon set.
struct Tile {
    rect: IBox,
    stock: IShapes,
    bbox: IBox,
    /// Vertex count of `stock`.
    verts: usize,
}

/// A Z strip, split further (in two, along its longer side) wherever its stock gets
/// complex, so that no boolean call sees more than about [`MAX_TILE_VERTICES`] of stock.
/// A split node keeps its children's rectangles and the boxes of their stock (as of their
/// last flush: the stock only shrinks, so a sweep that misses a box misses the stock under
/// it), so a sweep that cannot touch a subtree's stock never descends into it.
enum Node {
    Leaf(Tile),
    Split(Box<[Self; 2]>, [IBox; 2], [IBox; 2]),
}

/// Part of a crash seen by one strip.
struct Fragment {
    seg: usize,
    body: Option<&'static str>,
    eps: f64,
    area: f64,
    dist: f64,
    at: P,
    /// The overlap's extent along the move's normal: (least, largest) projection.
    across: (f64, f64),
}

fn bbox_of(shapes: &IShapes) -> IBox {
    IBox::of(shapes.iter().filter_map(|s| s.first()).flatten().copied())
}

/// Polygons trimmed to a box (see [`trim_to_box`]), stored flat.
#[derive(Default)]
struct Trimmed {
    pts: Vec<IPt>,
    rings: Vec<std::ops::Range<usize>>,
    /// Per ring: whether it came from a convex polygon ([`Poly::convex`]), and that
    /// polygon's [`Poly::core`].
    kinds: Vec<(bool, IBox)>,
    /// Rings (not convex) are trimmed with the tests of [`trim_to_box`] for rings
    /// ([`SimOptions::ring_air`]).
    ring_air: bool,
}

/// A trimmed ring with what its polygon was ([`Trimmed::kinds`]).
#[derive(Clone, Copy)]
struct Ring<'a> {
    pts: &'a [IPt],
    convex: bool,
    core: IBox,
}

impl Trimmed {
    fn clear(&mut self) {
        self.pts.clear();
        self.rings.clear();
        self.kinds.clear();
    }

    /// Appends every polygon of the sweep `it`, trimmed to `b`.
    fn push_sweep(&mut self, sweeps: &Sweeps, it: &Item, b: &IBox) {
        for p in sweeps.parts_of(it) {
            self.push(p, b);
        }
    }

    /// Appends the polygons a rapid's crash test reads ([`Item::probe`]), trimmed to `b`.
    fn push_probe(&mut self, sweeps: &Sweeps, it: &Item, b: &IBox) {
        for p in sweeps.probe_parts_of(it) {
            self.push(p, b);
        }
    }

    /// Appends `poly` trimmed to `b` (nothing when its overlap with `b` has no area).
    fn push(&mut self, poly: Poly, b: &IBox) {
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

    fn iter(&self) -> impl Iterator<Item = &[IPt]> + Clone {
        self.rings.iter().map(|r| &self.pts[r.clone()])
    }

    /// Every ring with its kind.
    fn rings(&self) -> impl Iterator<Item = Ring<'_>> + Clone {
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
struct Batch {
    /// Per sweep still in the batch: the range of its rings in `rings`.
    kept: Vec<std::ops::Range<usize>>,
    rings: Trimmed,
}

impl Batch {
    fn len(&self) -> usize {
        self.kept.len()
    }

    fn clear(&mut self) {
        self.kept.clear();
        self.rings.clear();
    }

    /// The rings of every sweep in the batch.
    fn iter(&self) -> impl Iterator<Item = &[IPt]> {
        self.kept
            .iter()
            .flat_map(|r| self.rings.ranged(r.clone()).map(|ring| ring.pts))
    }

    /// True when the sweeps of the batch cover the sweep trimmed into `t` wherever the stock
    /// may be (inside `b`, its box; see [`covered`]). Then `stock − (batch ∪ t) = stock −
    /// batch`, and for a rapid, its overlap with the stock after the batch is empty.
    fn covers(&self, t: &Trimmed, b: &IBox) -> bool {
        let all = self.kept.iter().flat_map(|r| self.rings.ranged(r.clone()));
        covered(t.rings(), all, b)
    }

    /// Adds the sweep trimmed into `t`, dropping (with `cover`) the sweeps of the batch it
    /// covers (the passes of a roughing or a zig-zag, each lowering a flat top, cover the
    /// last one there; nearly coincident edges in one call cost the splitter pairwise).
    fn push(&mut self, t: &Trimmed, b: &IBox, cover: bool) {
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
        let need = clamp_box(IBox::of(p.pts.iter().copied()), b);
        p.convex
            && outer.clone().any(|o| {
                o.convex
                    && (contains_box(&o.core, &need)
                        || contains_box(&IBox::of(o.pts.iter().copied()), &need)
                            && convex_covers_in_box(o.pts, p.pts, b))
            })
    })
}

/// A box that holds `b` less the box `core` (`b` itself unless `core` spans `b` across one
/// axis and reaches past one end along the other).
fn outside_core(b: IBox, core: &IBox) -> IBox {
    let mut out = b;
    for axis in 0..2 {
        let other = 1 - axis;
        if core.is_empty() || core.min[other] > b.min[other] || core.max[other] < b.max[other] {
            continue;
        }
        if core.max[axis] >= b.max[axis] {
            out.max[axis] = out.max[axis].min(core.min[axis].max(b.min[axis]));
        }
        if core.min[axis] <= b.min[axis] {
            out.min[axis] = out.min[axis].max(core.max[axis].min(b.max[axis]));
        }
    }
    out
}

/// `a ∩ b` (empty when they miss each other: min above max).
fn clamp_box(a: IBox, b: &IBox) -> IBox {
    IBox {
        min: [a.min[0].max(b.min[0]), a.min[1].max(b.min[1])],
        max: [a.max[0].min(b.max[0]), a.max[1].min(b.max[1])],
    }
}

/// True when `outer` contains `inner`.
fn contains_box(outer: &IBox, inner: &IBox) -> bool {
    outer.min[0] <= inner.min[0]
        && outer.min[1] <= inner.min[1]
        && outer.max[0] >= inner.max[0]
        && outer.max[1] >= inner.max[1]
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

impl Tile {
    /// Subtracts the batch from the stock in one boolean call.
    fn flush(&mut self, batch: &mut Batch, engine: &mut Engine) {
        if batch.len() == 0 {
            return;
        }
        self.stock = engine.difference(&self.stock, batch.iter());
        self.bbox = bbox_of(&self.stock);
        self.verts = self.stock.iter().flatten().map(Vec::len).sum();
        batch.clear();
    }

    fn new(rect: IBox, stock: IShapes) -> Self {
        let verts = stock.iter().flatten().map(Vec::len).sum();
        Self {
            rect,
            bbox: bbox_of(&stock),
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
        } = worker;
        trim.ring_air = ctx.ring_air;
        // a box of the stock as it will be after the batch: smaller than the stock's box
        // when a core of the batch spans that (the stock outside it is the batch's to
        // cut); trimming and covering keep to the box of the stock as it is
        let mut reach = self.bbox;
        for (k, &i) in list.iter().enumerate() {
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
                self.flush(batch, engine);
                reach = self.bbox;
                self.probe(it, ctx, engine, frags, trim);
                continue;
            }
            let covered = ctx.cover && batch.covers(trim, &self.bbox);
            if it.rapid && !covered {
                self.flush(batch, engine);
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
                reach = outside_core(reach, &r.core);
            }
            if batch.len() >= BATCH {
                self.flush(batch, engine);
                reach = self.bbox;
            }
        }
        self.flush(batch, engine);
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
            let (dist, at) = nearest(ctx.grid, &overlap, it.start);
            frags.push(Fragment {
                seg: it.seg,
                body: it.body,
                eps: it.eps,
                area: a,
                dist,
                at,
                across: across(ctx.grid, &overlap, it.dir),
            });
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
struct Ctx<'a> {
    grid: &'a Grid,
    /// Tiles no smaller than this (grid units) are never split.
    min_tile: i64,
    /// The epoch's sweeps.
    sweeps: &'a Sweeps,
    /// Rings get their exact air tests ([`SimOptions::ring_air`]).
    ring_air: bool,
    /// Batches leave out what they cover ([`SimOptions::cover`]).
    cover: bool,
}

/// What one worker thread writes to: its boolean engine, the rapid cuts it found, and its
/// scratch space.
struct Worker<'e> {
    engine: &'e mut Engine,
    frags: Vec<Fragment>,
    /// The tile at hand's sweeps waiting for a boolean call (empty between tiles).
    batch: Batch,
    /// The sweep at hand trimmed to the tile.
    trim: Trimmed,
    /// Run boxes of a ring ([`ring_air::touches`]).
    runs: Vec<IBox>,
}

impl Node {
    fn process(&mut self, list: &[u32], ctx: &Ctx, worker: &mut Worker) {
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

    /// A copy of the stock of every leaf (for a snapshot).
    /// Whether any stock lies right of `x` (grid units): a move to the axis with nothing
    /// beyond it (a face to the centre) parts nothing off.
    fn has_stock_right_of(&self, x: i32) -> bool {
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

    fn gather(&self, out: &mut Vec<IShapes>) {
        match self {
            Self::Leaf(tile) => out.push(tile.stock.clone()),
            Self::Split(children, ..) => {
                children[0].gather(out);
                children[1].gather(out);
            }
        }
    }

    fn collect(self, out: &mut Vec<IShapes>) {
        match self {
            Self::Leaf(tile) => out.push(tile.stock),
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

/// True when `c` lies strictly right of the directed line `p → q`, exactly: the
/// determinant in f64 (differences of i32 are exact, the products round by at most
/// 2⁻⁵³ of their size), the exact [`orient`] only when it is too close to zero to tell.
fn right_of(p: IPt, q: IPt, c: IPt) -> bool {
    let d = |a: i32, b: i32| f64::from(a) - f64::from(b);
    let (l, r) = (d(q.x, p.x) * d(c.y, p.y), d(q.y, p.y) * d(c.x, p.x));
    let det = l - r;
    let bound = (l.abs() + r.abs()) * 1e-15;
    if det < -bound {
        true
    } else if det > bound {
        false
    } else {
        orient(p, q, c) < 0
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

/// Point of `shapes` nearest to `p` (p itself when inside) and its distance.
/// The least and largest projection of the region's points on the normal of `dir` (for a
/// zero direction, the region's larger extent along an axis).
fn across(grid: &Grid, shapes: &IShapes, dir: P) -> (f64, f64) {
    let n = if dir == [0.0, 0.0] {
        [1.0, 0.0]
    } else {
        [-dir[1], dir[0]]
    };
    let mut span = (f64::INFINITY, f64::NEG_INFINITY);
    for ring in shapes.iter().flatten() {
        for &q in ring {
            let p = grid.to_float(q);
            let t = p[0] * n[0] + p[1] * n[1];
            span = (span.0.min(t), span.1.max(t));
        }
    }
    span
}

fn nearest(grid: &Grid, shapes: &IShapes, p: P) -> (f64, P) {
    let mut best = (f64::INFINITY, p);
    for s in shapes {
        let rings: Vec<Vec<Pt>> = s
            .iter()
            .map(|r| r.iter().map(|&q| Pt::from(grid.to_float(q))).collect())
            .collect();
        let at = Pt::from(p);
        if let Some((outer, holes)) = rings.split_first() {
            if ring::contains(outer, at) && !holes.iter().any(|h| ring::contains(h, at)) {
                return (0.0, p);
            }
        }
        for r in &rings {
            for k in 0..r.len() {
                let (d, q) = point_segment(at, r[k], r[(k + 1) % r.len()]);
                if d < best.0 {
                    best = (d, q.to_array());
                }
            }
        }
    }
    best
}

/// Removes material: `blank` minus the sweep of every segment's tool outline, in order,
/// reporting rapids that run through stock as [`Crash`]es. `progress` is called now and
/// then with the number of segments processed. Never panics: moves with non-finite
/// coordinates are skipped with a warning.
pub fn simulate(
    blank: &Blank,
    tools: &ToolTable,
    segments: &[Segment],
    opts: &SimOptions,
    progress: &mut dyn FnMut(usize),
) -> Simulation {
    let tol = if opts.chord_tol.is_finite() && opts.chord_tol > 0.0 {
        opts.chord_tol
    } else {
        0.001
    };
    let mut warnings = Vec::new();
    let shapes: Vec<Shape> = blank
        .shapes
        .iter()
        .filter(|s| {
            s.outer
                .iter()
                .flat_map(|p| p.iter())
                .all(|v| v.is_finite() && v.abs() < 1e9)
        })
        .cloned()
        .collect();
    let bb = Rect::of(shapes.iter().flat_map(|s| pts(&s.outer)));
    if shapes.len() != blank.shapes.len() {
        warnings.push((
            0,
            "blank shapes with non-finite coordinates were ignored".to_string(),
        ));
    }
    if bb.is_empty() || area(&shapes) <= 0.0 {
        warnings.push((0, "the blank is empty: nothing to cut".to_string()));
        progress(segments.len());
        return Simulation {
            final_shapes: Vec::new(),
            crashes: Vec::new(),
            removed_area: 0.0,
            removed_volume: 0.0,
            warnings,
            snapshots: Vec::new(),
        };
    }

    // Sweeps are clipped to the blank's box plus a margin: outside it there is no stock
    // to remove, and clipping keeps huge coordinates from coarsening the grid.
    let margin = 1.0 + 1e-3 * bb.size();
    let clip = bb.grown(margin);
    let grid = Grid::new(bb.grown(2.0 * margin));
    let mut engine = Engine::new();
    let stock = grid.shapes_to_int(&shapes);

    let IBox {
        min: [x0, y0],
        max: [x1, y1],
    } = grid.box_to_int(&clip);
    let n_strips = ((clip.width() / STRIP_WIDTH).ceil() as usize).clamp(1, MAX_STRIPS);
    let bounds: Vec<i32> = (0..=n_strips)
        .map(|k| {
            (i64::from(x0) + (i64::from(x1) - i64::from(x0)) * k as i64 / n_strips as i64) as i32
        })
        .collect();
    let strips: Vec<Mutex<Node>> = (0..n_strips)
        .map(|k| {
            let (a, b) = (bounds[k], bounds[k + 1]);
            let tile = IBox {
                min: [a, y0],
                max: [b, y1],
            };
            let part = engine.intersection(&stock, [&tile.corners()[..]]);
            Mutex::new(Node::Leaf(Tile::new(tile, part)))
        })
        .collect();
    let min_tile = (MIN_TILE / grid.step()) as i64;
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(n_strips);
    let merge_tol = if opts.merge_tol.is_finite() && opts.merge_tol > 0.0 {
        opts.merge_tol
    } else {
        0.0
    };
    let mut builder = SweepBuilder::new(&grid, clip, tools, tol, merge_tol);
    builder.set_rear(crate::section::rear_tools(segments));
    builder.set_feed_paths(opts.feed_paths);
    let snapshots = Snapshots::new(&opts.snapshot_after, segments.len(), &stock);
    // a group's passes are one sweep: only where snapshots are not taken move by move
    builder.set_pass_groups(opts.pass_groups && !snapshots.exact());
    let mut fragments: Vec<Fragment> = Vec::new();
    // moves whose cuts are all in the tiles at the last epoch end (a merged run still open
    // is not: its sweep comes when it ends)
    let mut cut_moves = 0;
    // pieces parted off the held bar: (moves done when they fell, the pieces)
    let mut fallen: Vec<(usize, IShapes)> = Vec::new();
    let mut separation_checks = 0;
    let left_end = grid.box_to_int(&bb).min[0];
    // a tube's bore: a blade parts it off when it reaches the bore, not the axis
    let bore = shapes
        .iter()
        .flat_map(|s| s.outer.iter().chain(s.holes.iter().flatten()))
        .map(|p| p[1])
        .fold(f64::INFINITY, f64::min)
        .max(0.0);
    let mut epochs = Epochs {
        builder,
        // programs whose snapshots come from epoch ends get about 30 epochs (depending
        // only on the program's length, so every report of a run reads the same removal)
        len: if snapshots.exact() {
            EPOCH
        } else {
            (segments.len() / 30).clamp(1024, EPOCH)
        },
        snapshots,
        segments,
        tools,
        bore,
    };
    let mut next = Some(epochs.build(0, None, separation_checks < MAX_SEPARATION_CHECKS));
    while let Some(ep) = next.take() {
        let lists = strip_lists(&ep.sweeps, &bounds);
        // the next epoch's sweeps are built while the workers cut this one's, unless this
        // one ends with a part-off (the stock is looked at first: pieces that fell are
        // erased from what comes after) or the snapshots are exact (their counts are read
        // epoch by epoch; such programs fit one epoch anyway)
        let ahead = !ep.parting && ep.end < segments.len() && !epochs.snapshots.exact();
        let looking = separation_checks < MAX_SEPARATION_CHECKS;
        let ctx = Ctx {
            grid: &grid,
            min_tile,
            sweeps: &ep.sweeps,
            ring_air: opts.ring_air,
            cover: opts.cover,
        };
        let mut new_frags = cut_strips(&strips, &lists, &ctx, threads, &mut engine, || {
            if ahead {
                next = Some(epochs.build(ep.end, None, looking));
            }
        });
        fragments.append(&mut new_frags);
        epochs.snapshots.epoch(&ep.sweeps, &mut engine);
        cut_moves = if ep.open_run {
            ep.sweeps
                .items
                .iter()
                .filter(|it| it.body.is_none())
                .map(|it| it.seg + 1)
                .max()
                .unwrap_or(cut_moves)
        } else {
            ep.end
        };
        // (at the last epoch end the stock is the final part, which the caller has anyway)
        if ep.end < segments.len() {
            epochs
                .snapshots
                .at_epoch_end(cut_moves, || stock_of(&strips, &mut engine));
        }
        let beyond = |seg: &Segment| {
            let x = grid.to_int([seg.from.z.max(seg.to.z), 0.0]).x;
            strips.iter().any(|m| {
                m.lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .has_stock_right_of(x)
            })
        };
        let mut to_erase = None;
        if ep.parting && ep.end < segments.len() && beyond(&segments[ep.end - 1]) {
            separation_checks += 1;
            if separation_checks == MAX_SEPARATION_CHECKS {
                warnings.push((
                    ep.end - 1,
                    format!("{MAX_SEPARATION_CHECKS} part-offs: pieces parted off after this move stay in the stock"),
                ));
            }
            if let Some(off) = fallen_pieces(stock_of(&strips, &mut engine), left_end) {
                to_erase = Some((ep.end - 1, grid.shapes_to_float(&off)));
                fallen.push((ep.end, off));
            }
        }
        progress(ep.end);
        if next.is_none() && ep.end < segments.len() {
            let looking = separation_checks < MAX_SEPARATION_CHECKS;
            next = Some(epochs.build(ep.end, to_erase, looking));
        }
    }
    let mut parts: Vec<IShapes> = Vec::new();
    for m in strips {
        m.into_inner()
            .unwrap_or_else(|e| e.into_inner())
            .collect(&mut parts);
    }
    // the section shows the fallen pieces where they were parted off
    parts.extend(fallen.iter().map(|(_, f)| f.clone()));
    let final_int = engine.union(&parts);
    let final_shapes = grid.shapes_to_float(&final_int);
    let crashes = merge_fragments(fragments);
    warnings.extend(epochs.builder.warnings);
    warnings.sort_by_key(|w| w.0);
    let removed_area = area(&shapes) - area(&final_shapes);
    let removed_volume = revolved_volume(&shapes) - revolved_volume(&final_shapes);
    Simulation {
        final_shapes,
        crashes,
        removed_area,
        removed_volume,
        warnings,
        snapshots: epochs
            .snapshots
            .out
            .iter()
            .map(|(k, s)| {
                let before: Vec<&IShapes> = fallen
                    .iter()
                    .filter(|(at, _)| at < k)
                    .map(|(_, f)| f)
                    .collect();
                if before.is_empty() {
                    return (*k, grid.shapes_to_float(s));
                }
                let mut parts = vec![s.clone()];
                parts.extend(before.into_iter().cloned());
                (*k, grid.shapes_to_float(&engine.union(&parts)))
            })
            .collect(),
    }
}

/// One epoch's sweeps, built (possibly while the workers cut the epoch before).
struct Epoch {
    /// The epoch holds the moves up to this index.
    end: usize,
    /// It ends with a part-off: the stock is looked at for pieces that fell before the
    /// next epoch is built.
    parting: bool,
    sweeps: Sweeps,
    /// A merged run of feeds was still open at its end (its cut comes in a later epoch).
    open_run: bool,
}

/// What builds the epochs' sweeps in program order: the sweep builder, the snapshot counts
/// it passes, and the program.
struct Epochs<'a> {
    builder: SweepBuilder<'a>,
    snapshots: Snapshots,
    segments: &'a [Segment],
    tools: &'a ToolTable,
    /// The blank's bore radius (a blade parts off there).
    bore: f64,
    /// Most moves an epoch holds.
    len: usize,
}

impl Epochs<'_> {
    /// Builds the sweeps of the epoch starting at move `start` (ended at the first part-off
    /// while `looking`), after erasing the pieces `fallen` from what later sweeps see.
    fn build(&mut self, start: usize, fallen: Option<(usize, Vec<Shape>)>, looking: bool) -> Epoch {
        let (segments, tools, bore) = (self.segments, self.tools, self.bore);
        let mut end = (start + self.len).min(segments.len());
        // a part-off may leave a piece: its epoch ends with it, so that the stock can be
        // looked at before the next move
        if let Some(k) = segments[start..end]
            .iter()
            .position(|s| looking && parts_off(s, tools, bore))
        {
            end = start + k + 1;
        }
        if let Some((idx, pieces)) = fallen {
            self.builder.erase(idx, &pieces);
        }
        for (k, seg) in segments[start..end].iter().enumerate() {
            self.builder
                .push_before(start + k, seg, segments.get(start + k + 1));
            self.snapshots.after_push(start + k + 1, &mut self.builder);
        }
        let parting = end > start && looking && parts_off(&segments[end - 1], tools, bore);
        if end == segments.len() || parting {
            self.builder.flush_run();
        }
        Epoch {
            end,
            parting,
            sweeps: self.builder.take(),
            open_run: self.builder.has_open_run(),
        }
    }
}

/// Cuts an epoch's sweeps into the strips (`lists[k]`: the sweeps that reach strip `k`),
/// `threads` workers taking strips in turn; the calling thread first does `meanwhile`
/// (building the next epoch), then joins them. Returns the rapid cuts found.
fn cut_strips(
    strips: &[Mutex<Node>],
    lists: &[Vec<u32>],
    ctx: &Ctx,
    threads: usize,
    engine: &mut Engine,
    meanwhile: impl FnOnce(),
) -> Vec<Fragment> {
    let next_strip = AtomicUsize::new(0);
    let work = |engine: &mut Engine| {
        let mut worker = Worker {
            engine,
            frags: Vec::new(),
            batch: Batch::default(),
            trim: Trimmed::default(),
            runs: Vec::new(),
        };
        loop {
            let k = next_strip.fetch_add(1, Ordering::Relaxed);
            if k >= strips.len() {
                break;
            }
            if lists[k].is_empty() {
                continue;
            }
            // a poisoned lock only means another worker panicked; its data is still whole
            let mut strip = strips[k].lock().unwrap_or_else(|e| e.into_inner());
            strip.process(&lists[k], ctx, &mut worker);
        }
        worker.frags
    };
    let total: usize = lists.iter().map(Vec::len).sum();
    if threads <= 1 || total < 256 {
        meanwhile();
        return work(engine);
    }
    std::thread::scope(|s| {
        let handles: Vec<_> = (1..threads)
            .map(|_| s.spawn(|| work(&mut Engine::new())))
            .collect();
        meanwhile();
        let mut all = work(engine);
        for h in handles {
            // a worker that panicked lost its fragments; the strips stay consistent
            all.extend(h.join().unwrap_or_default());
        }
        all
    })
}

/// For each Z strip (between `bounds`), the sweeps whose box reaches into it.
fn strip_lists(sweeps: &Sweeps, bounds: &[i32]) -> Vec<Vec<u32>> {
    let n_strips = bounds.len() - 1;
    let mut lists: Vec<Vec<u32>> = vec![Vec::new(); n_strips];
    for (i, it) in sweeps.items.iter().enumerate() {
        let lo = bounds
            .partition_point(|&b| b <= it.bbox.min[0])
            .saturating_sub(1);
        let hi = bounds
            .partition_point(|&b| b < it.bbox.max[0])
            .min(n_strips);
        for list in &mut lists[lo..hi.max(lo + 1).min(n_strips)] {
            list.push(i as u32);
        }
    }
    lists
}

/// Most part-offs after which the stock is looked at for pieces that fell.
const MAX_SEPARATION_CHECKS: usize = 1_000;

/// A part-off: a feed of a blade (a grooving tool, or a grooving cycle's) inward to the
/// axis or into the blank's bore (`bore`: its inner radius, 0 for a bar); it may leave a
/// piece that no longer reaches the held bar. (A turning tool facing to the centre leaves,
/// between passes, only a pip at the axis that its next pass cuts: no part.)
fn parts_off(seg: &Segment, tools: &ToolTable, bore: f64) -> bool {
    seg.motion == Motion::Feed
        && seg.to.r <= bore + 1e-9
        && seg.from.r > seg.to.r
        && tools.blade_cuts(seg)
}

/// The stock as it stands: every strip's tiles joined.
fn stock_of(strips: &[Mutex<Node>], engine: &mut Engine) -> IShapes {
    let mut parts: Vec<IShapes> = Vec::new();
    for m in strips {
        m.lock()
            .unwrap_or_else(|e| e.into_inner())
            .gather(&mut parts);
    }
    engine.union(&parts)
}

/// The pieces of `stock` that no longer reach the bar's left end `left_end` (grid units),
/// where the chuck holds it: parted off, fallen. None while the held bar is the only piece,
/// or when no piece reaches the left end (nothing to tell held from fallen).
fn fallen_pieces(stock: IShapes, left_end: i32) -> Option<IShapes> {
    let held = |s: &crate::overlay::IShape| {
        s.first()
            .is_some_and(|outer| outer.iter().any(|p| p.x <= left_end + 1))
    };
    if stock.len() < 2 || !stock.iter().any(held) {
        return None;
    }
    let off: IShapes = stock.into_iter().filter(|s| !held(s)).collect();
    (!off.is_empty()).then_some(off)
}

/// Adds up the overlaps each strip saw for a rapid; the contact point is the one nearest
/// the rapid's start over all strips.
fn merge_fragments(mut frags: Vec<Fragment>) -> Vec<Crash> {
    frags.sort_by_key(|f| (f.seg, f.body));
    let mut out: Vec<Crash> = Vec::new();
    let mut i = 0;
    while i < frags.len() {
        let (seg, body) = (frags[i].seg, frags[i].body);
        let mut j = i;
        let (mut total, mut best) = (0.0, &frags[i]);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        while j < frags.len() && frags[j].seg == seg && frags[j].body == body {
            total += frags[j].area;
            lo = lo.min(frags[j].across.0);
            hi = hi.max(frags[j].across.1);
            if frags[j].dist < best.dist {
                best = &frags[j];
            }
            j += 1;
        }
        if total > frags[i].eps {
            out.push(Crash {
                segment: seg,
                body,
                at: best.at,
                area: total,
                depth: (hi - lo).max(0.0),
            });
        }
        i = j;
    }
    // One crash a move: a move whose cutting outline crashed reports that crash, not its
    // body's as well. And a body crash right after a crash continues it (the body is still
    // in the stock that crash put it in, e.g. a retract after a crashing plunge): reported
    // once, at the first move.
    let mut kept: Vec<Crash> = Vec::with_capacity(out.len());
    let mut last: Option<usize> = None;
    for c in out {
        let continues =
            c.body.is_some() && last.is_some_and(|p| p == c.segment || p + 1 == c.segment);
        last = Some(c.segment);
        if !continues {
            kept.push(c);
        }
    }
    kept
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::{hausdorff, symmetric_difference_area, Insert, Tool};
    use expander::{Arc, FeedId, Motion, Pt, Span};

    /// A move of tool 1 (shared with the other modules' tests).
    pub(crate) fn seg(motion: Motion, from: [f64; 2], to: [f64; 2]) -> Segment {
        Segment {
            motion,
            from: Pt::new(from[0], from[1]),
            to: Pt::new(to[0], to[1]),
            arc: None,
            tool: 1,
            hint: expander::ToolHint::Table,
            lead: 0.0,
            thread_phase: 0.0,
            feed: FeedId::default(),
            span: Span::default(),
        }
    }

    fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
        Shape {
            outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
            holes: vec![],
        }
    }

    fn run(blank: &Blank, tools: &ToolTable, segs: &[Segment]) -> Simulation {
        simulate(blank, tools, segs, &SimOptions::default(), &mut |_| {})
    }

    /// T1: a V 35° insert, r0.4, tip 3, 93° (shared with the other modules' tests).
    pub(crate) fn v35() -> ToolTable {
        ToolTable::from_tools(vec![(
            1,
            Tool::Turning {
                insert: Insert::V,
                nose_radius: 0.4,
                tip: 3,
                entering_angle: 93.0,
                edge: 11.0,
            },
        )])
    }

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

    #[test]
    fn straight_turning_pass_removes_exactly_the_rectangle() {
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let sim = run(
            &blank,
            &v35(),
            &[seg(Motion::Feed, [5.0, 20.0], [-115.0, 20.0])],
        );
        let expected = [rect(-110.0, 0.0, 0.0, 20.0)];
        let d = symmetric_difference_area(&sim.final_shapes, &expected);
        assert!(d < 1e-6 * 2200.0, "symmetric difference {d}");
        assert!(
            (sim.removed_area - 110.0 * 5.0).abs() < 1e-6,
            "{}",
            sim.removed_area
        );
        let pi = std::f64::consts::PI;
        assert!(
            (sim.removed_volume - pi * (625.0 - 400.0) * 110.0).abs() < 1e-3,
            "{}",
            sim.removed_volume
        );
        assert!(sim.crashes.is_empty());
    }

    #[test]
    fn arc_with_a_sharp_tool_gives_the_arc() {
        let tools = ToolTable::from_tools(vec![(
            1,
            Tool::Turning {
                insert: Insert::V,
                nose_radius: 0.0,
                tip: 3,
                entering_angle: 93.0,
                edge: 11.0,
            },
        )]);
        let blank = Blank::bar(40.0, 50.0, 0.0, None).unwrap();
        let mut arc = seg(Motion::Feed, [0.0, 10.0], [-10.0, 20.0]);
        arc.arc = Some(Arc {
            center: Pt::new(-10.0, 10.0),
            ccw: true,
        });
        let segs = [
            seg(Motion::Feed, [5.0, 10.0], [0.0, 10.0]),
            arc,
            seg(Motion::Feed, [-10.0, 20.0], [-12.0, 20.0]),
        ];
        let sim = run(&blank, &tools, &segs);
        // the intended dome, chorded 100 times finer than the simulation
        let mut outer = vec![[-50.0, 0.0], [0.0, 0.0]];
        outer.extend(arc.polyline(1e-5).iter().map(|p| [p.z, p.r]));
        outer.push([-50.0, 20.0]);
        let expected = [Shape {
            outer,
            holes: vec![],
        }];
        let h = hausdorff(&sim.final_shapes, &expected);
        assert!(h < 0.002, "hausdorff {h}");
        // and it is a real cut, not the blank
        assert!(sim.removed_area > 20.0, "{}", sim.removed_area);
    }

    #[test]
    fn rapid_into_the_stock_is_a_crash() {
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let segs = [
            seg(Motion::Rapid, [10.0, 30.0], [10.0, 20.0]),
            seg(Motion::Rapid, [10.0, 20.0], [-20.0, 20.0]),
            // back out along the same line: inside its own earlier sweep, no second crash
            seg(Motion::Rapid, [-20.0, 20.0], [10.0, 20.0]),
            // straight up from there would plough the sliver the 87° edge left: a crash
            seg(Motion::Rapid, [-20.0, 20.0], [-20.0, 40.0]),
        ];
        let sim = run(&blank, &v35(), &segs);
        assert_eq!(
            sim.crashes.iter().map(|c| c.segment).collect::<Vec<_>>(),
            vec![1, 3],
            "{:?}",
            sim.crashes
        );
        let c = &sim.crashes[0];
        assert_eq!(c.segment, 1);
        // it ploughed through r 20..25 over z -20..0 (less the sliver under the 87° edge)
        assert!(c.area > 99.0 && c.area <= 100.0, "{}", c.area);
        let total: f64 = sim.crashes.iter().map(|c| c.area).sum();
        assert!(
            (total - sim.removed_area).abs() < 1e-6,
            "{total} vs {}",
            sim.removed_area
        );
        assert!(
            (c.at[0] - 0.0).abs() < 1e-6 && (c.at[1] - 20.0).abs() < 1e-6,
            "{:?}",
            c.at
        );
    }

    #[test]
    fn rapid_in_air_is_not_a_crash() {
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let segs = [
            seg(Motion::Rapid, [10.0, 30.0], [-20.0, 30.0]),
            seg(Motion::Rapid, [-20.0, 30.0], [-20.0, 25.0]),
        ];
        let sim = run(&blank, &v35(), &segs);
        assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
        assert!(sim.removed_area.abs() < 1e-9);
    }

    #[test]
    fn rapid_through_material_cut_earlier_in_the_batch_is_not_a_crash() {
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let back = seg(Motion::Rapid, [-20.0, 22.0], [10.0, 22.0]);
        let segs = [
            seg(Motion::Feed, [10.0, 20.0], [-20.0, 20.0]),
            seg(Motion::Feed, [-20.0, 20.0], [-20.0, 22.0]),
            back,
        ];
        let sim = run(&blank, &v35(), &segs);
        assert!(sim.crashes.is_empty(), "{:?}", sim.crashes);
        // the same rapid without the feeds before it ploughs through stock
        let sim = run(&blank, &v35(), &[back]);
        assert_eq!(sim.crashes.len(), 1);
        assert_eq!(sim.crashes[0].segment, 0);
        // and a crash many batches later still carries its own index
        let mut many: Vec<Segment> = (0..100)
            .map(|_| seg(Motion::Rapid, [10.0, 40.0], [10.0, 45.0]))
            .collect();
        many.push(back);
        let sim = run(&blank, &v35(), &many);
        assert_eq!(
            sim.crashes.iter().map(|c| c.segment).collect::<Vec<_>>(),
            vec![100]
        );
    }

    #[test]
    fn thread_pass_stamps_one_tooth_per_lead() {
        let tools = ToolTable::from_tools(vec![(
            1,
            Tool::Threading {
                angle: 60.0,
                tip_flat: 0.0,
                side: crate::tools::ThreadSide::Od,
            },
        )]);
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let mut t = seg(Motion::Thread, [5.0, 24.0], [-30.0, 24.0]);
        t.lead = 2.0;
        let sim = run(&blank, &tools, &[t]);
        // stamps at z = 5, 3, ..., -29 and at the end -30; those at z <= -1 are in the bar
        let tooth = 30f64.to_radians().tan(); // 1 mm deep, 2 tan 30° wide: area tan 30°
        let overlap = (tooth - 0.5) * (tooth - 0.5) / tooth; // the last two teeth are 1 mm apart
        let expected = 16.0 * tooth - overlap;
        // grid rounding (~0.1 nm) along 37 mm of tooth flanks
        assert!(
            (sim.removed_area - expected).abs() < 1e-5,
            "{} vs {expected}",
            sim.removed_area
        );
    }

    #[test]
    fn grooving_hints_choose_the_blade() {
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let mut plunge = seg(Motion::Feed, [-10.0, 30.0], [-10.0, 20.0]);
        plunge.hint = expander::ToolHint::Grooving;
        let sim = run(&blank, &ToolTable::empty(), &[plunge]);
        // the default 3 mm blade, left corner referenced: a 3 x 5 groove at z -10..-7
        assert!(
            (sim.removed_area - 15.0).abs() < 1e-6,
            "{}",
            sim.removed_area
        );
        assert!(sim.warnings.iter().any(|(_, w)| w.contains("3 mm")));
        plunge.hint = expander::ToolHint::Blade {
            width: 4.0,
            toward_plus_z: false,
            shank_plus_x: true,
        };
        let sim = run(&blank, &ToolTable::empty(), &[plunge]);
        let expected = [
            rect(-110.0, -14.0, 0.0, 25.0),
            rect(-14.0, -10.0, 0.0, 20.0),
            rect(-10.0, 0.0, 0.0, 25.0),
        ];
        let expected = crate::boolean(&expected, &[], crate::BoolOp::Union);
        assert!(symmetric_difference_area(&sim.final_shapes, &expected) < 1e-6);
    }

    /// Number of cutting sweeps the builder makes of `segs` (with the defaults' chord tolerance),
    /// without paths of feeds.
    fn sweep_count(tools: &ToolTable, segs: &[Segment], merge_tol: f64) -> usize {
        let bb = Rect::new(geom::Pt::new(-200.0, -200.0), geom::Pt::new(200.0, 200.0));
        let grid = Grid::new(bb.grown(1.0));
        let mut b = SweepBuilder::new(&grid, bb, tools, 0.001, merge_tol);
        // merging alone (paths of feeds would make one sweep of every path)
        b.set_feed_paths(false);
        for (i, s) in segs.iter().enumerate() {
            b.push(i, s);
        }
        b.flush_run();
        // the cutting sweeps (each move also has its body's probe)
        b.take().items.iter().filter(|it| it.body.is_none()).count()
    }

    #[test]
    fn chains_of_tiny_feeds_merge_within_the_merge_tolerance() {
        let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
        // 1000 points on a gentle arc (radius 60 mm, centre below the axis), 0.02 mm apart,
        // chorded as tiny G01 moves: CAM output
        let (c, rad) = ([-20.0, -40.0], 60.0);
        let pts: Vec<[f64; 2]> = (0..1000)
            .map(|k| {
                let t = (90.0f64 - 10.0).to_radians() + 0.02 * k as f64 / rad;
                [c[0] + rad * t.cos(), c[1] + rad * t.sin()]
            })
            .collect();
        let mut segs = vec![
            seg(Motion::Rapid, [10.0, 30.0], [pts[0][0], 30.0]),
            seg(Motion::Feed, [pts[0][0], 30.0], pts[0]),
        ];
        segs.extend(pts.windows(2).map(|w| seg(Motion::Feed, w[0], w[1])));
        segs.push(seg(Motion::Feed, pts[999], [pts[999][0], 30.0]));
        segs.push(seg(Motion::Rapid, [pts[999][0], 30.0], [10.0, 30.0]));
        let merged = sweep_count(&v35(), &segs, 0.0005);
        let unmerged = sweep_count(&v35(), &segs, 0.0);
        assert_eq!(unmerged, 1003);
        // chords of 60 mm arcs within 0.0005 mm are ~0.49 mm long: ~25 moves each
        assert!(merged < 60, "{merged} sweeps");
        let sim = |merge_tol| {
            let opts = SimOptions {
                merge_tol,
                ..SimOptions::default()
            };
            simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
        };
        let (a, b) = (sim(0.0005), sim(0.0));
        assert!(a.crashes.is_empty() && b.crashes.is_empty());
        assert!(b.removed_area > 10.0, "{}", b.removed_area);
        let h = hausdorff(&a.final_shapes, &b.final_shapes);
        assert!(h <= 0.0005, "hausdorff {h}");
        assert!(h > 0.0, "the merged result is an approximation");
        // the default merges
        assert_eq!(SimOptions::default().merge_tol, 0.0005);
    }

    /// A path of feeds swept as one ring removes what the moves swept one by one remove:
    /// a wavy contour of 0.05 mm moves, two small arcs, sharp corners, a reversal and a
    /// 180° turn, in two passes, then a rapid that ploughs the stock left (the same crash
    /// either way).
    #[test]
    fn feed_paths_remove_exactly_what_the_single_moves_remove() {
        let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
        let wave = |z: f64| 20.0 + 1.5 * (z / 1.7).sin() + 0.4 * (z / 0.3).sin();
        let mut segs = Vec::new();
        for (pass, off) in [(0, 2.0), (1, 0.0)] {
            let n = 600;
            let pts: Vec<[f64; 2]> = (0..=n)
                .map(|k| {
                    let z = 1.0 - 31.0 * f64::from(k) / f64::from(n);
                    [z, wave(z.min(0.0)) + off]
                })
                .collect();
            segs.push(seg(Motion::Rapid, [5.0, 30.0], [pts[0][0], 30.0]));
            segs.push(seg(Motion::Feed, [pts[0][0], 30.0], pts[0]));
            segs.extend(pts.windows(2).map(|w| seg(Motion::Feed, w[0], w[1])));
            let last = pts[n as usize];
            // two R0.5 half circles (chorded arcs join the path), then a sharp corner, a
            // reversal back along the path and a 180° turn
            let end = [last[0] - 2.0, last[1]];
            for (k, ccw) in [(0.0, false), (1.0, true)] {
                let mut arc = seg(
                    Motion::Feed,
                    [last[0] - k, last[1]],
                    [last[0] - k - 1.0, last[1]],
                );
                arc.arc = Some(Arc {
                    center: Pt::new(last[0] - k - 0.5, last[1]),
                    ccw,
                });
                segs.push(arc);
            }
            segs.push(seg(Motion::Feed, end, [end[0], end[1] - 1.0]));
            segs.push(seg(
                Motion::Feed,
                [end[0], end[1] - 1.0],
                [end[0] + 2.0, end[1] - 1.0],
            ));
            segs.push(seg(
                Motion::Feed,
                [end[0] + 2.0, end[1] - 1.0],
                [end[0] + 1.0, end[1] - 1.0],
            ));
            segs.push(seg(
                Motion::Feed,
                [end[0] + 1.0, end[1] - 1.0],
                [end[0] + 1.0, 30.0],
            ));
            if pass == 1 {
                segs.push(seg(
                    Motion::Rapid,
                    [end[0] + 1.0, 30.0],
                    [end[0] - 3.0, 10.0],
                ));
            }
            segs.push(seg(Motion::Rapid, [end[0] + 1.0, 30.0], [5.0, 30.0]));
        }
        let sim = |feed_paths| {
            let opts = SimOptions {
                feed_paths,
                ..SimOptions::default()
            };
            simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
        };
        let (paths, single) = (sim(true), sim(false));
        assert!(single.removed_area > 100.0, "{}", single.removed_area);
        let xor = symmetric_difference_area(&paths.final_shapes, &single.final_shapes);
        assert!(xor < 1e-6, "symmetric difference {xor} mm²");
        let h = hausdorff(&paths.final_shapes, &single.final_shapes);
        assert!(h < 1e-6, "hausdorff {h}");
        let verdicts = |s: &Simulation| s.crashes.iter().map(|c| c.segment).collect::<Vec<_>>();
        assert_eq!(verdicts(&paths), verdicts(&single));
        assert_eq!(verdicts(&paths).len(), 1);
        assert!((paths.crashes[0].area - single.crashes[0].area).abs() < 1e-6);
        // and far fewer sweeps: one ring per path of up to 128 vertices
        let count = |on: bool| {
            let bb = Rect::new(geom::Pt::new(-200.0, -200.0), geom::Pt::new(200.0, 200.0));
            let grid = Grid::new(bb.grown(1.0));
            let tools = v35();
            let mut b = SweepBuilder::new(&grid, bb, &tools, 0.001, 0.0005);
            b.set_feed_paths(on);
            for (i, s) in segs.iter().enumerate() {
                b.push(i, s);
            }
            b.flush_run();
            b.take().items.len()
        };
        let (with, without) = (count(true), count(false));
        assert!(
            with * 5 < without,
            "{with} sweeps with paths, {without} without"
        );
    }

    #[test]
    fn snapshots_in_the_one_pass_match_the_prefix_runs() {
        let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
        // a chain of tiny feeds (merged across the snapshot counts) between two plain cuts
        let pts: Vec<[f64; 2]> = (0..400)
            .map(|k| [-2.0 - 0.02 * k as f64, 22.0 - 0.001 * k as f64])
            .collect();
        let mut segs = vec![
            seg(Motion::Rapid, [10.0, 30.0], [2.0, 23.0]),
            seg(Motion::Feed, [2.0, 23.0], [-30.0, 23.0]),
            seg(Motion::Rapid, [-30.0, 30.0], [pts[0][0], 30.0]),
            seg(Motion::Feed, [pts[0][0], 30.0], pts[0]),
        ];
        segs.extend(pts.windows(2).map(|w| seg(Motion::Feed, w[0], w[1])));
        segs.push(seg(Motion::Feed, pts[399], [pts[399][0], 30.0]));
        let marks = vec![1, 2, 100, 250, segs.len(), 0, 100];
        let opts = SimOptions {
            snapshot_after: marks,
            ..SimOptions::default()
        };
        let sim = simulate(&blank, &v35(), &segs, &opts, &mut |_| {});
        let counts: Vec<usize> = sim.snapshots.iter().map(|s| s.0).collect();
        assert_eq!(counts, [1, 2, 100, 250]);
        for (k, shapes) in &sim.snapshots {
            let prefix = run(&blank, &v35(), &segs[..*k]);
            let h = hausdorff(shapes, &prefix.final_shapes);
            assert!(h <= 0.0005, "after {k} moves: hausdorff {h}");
        }
        assert_eq!(sim.final_shapes, run(&blank, &v35(), &segs).final_shapes);
    }

    /// A part-off in the middle of a long program (epochs of 1 024 moves, the next one's
    /// sweeps built while the last is cut): the pin falls before any later epoch is built,
    /// so a rapid through its place three epochs later meets air, while a rapid into the
    /// bar at the end is a crash. Removed: a 3 mm groove 2 mm deep, the kerf to the axis
    /// and the crash's 3 × 5, 6 + 75 + 15 = 96 mm² (the fallen pin stays in the section).
    #[test]
    fn a_part_off_inside_a_long_program_drops_the_piece_for_later_epochs() {
        let blank = Blank::bar(50.0, 100.0, 0.0, None).unwrap();
        let blade = |motion, from, to| {
            let mut s = seg(motion, from, to);
            s.hint = expander::ToolHint::Grooving;
            s
        };
        let mut segs = vec![];
        for k in 1..=2_000 {
            let r = 24.0 - 0.0005 * f64::from(k);
            segs.push(blade(Motion::Feed, [-40.0, 26.0], [-40.0, r]));
            segs.push(blade(Motion::Rapid, [-40.0, r], [-40.0, 26.0]));
        }
        segs.push(blade(Motion::Rapid, [-40.0, 26.0], [-13.0, 26.0]));
        let part_off = segs.len();
        segs.push(blade(Motion::Feed, [-13.0, 26.0], [-13.0, 0.0]));
        segs.push(blade(Motion::Rapid, [-13.0, 0.0], [-13.0, 26.0]));
        for _ in 0..750 {
            segs.push(blade(Motion::Rapid, [-13.0, 26.0], [-60.0, 30.0]));
            segs.push(blade(Motion::Rapid, [-60.0, 30.0], [-13.0, 26.0]));
        }
        segs.push(blade(Motion::Rapid, [-13.0, 26.0], [-6.0, 26.0]));
        let through_pin = segs.len();
        segs.push(blade(Motion::Rapid, [-6.0, 26.0], [-6.0, 10.0]));
        segs.push(blade(Motion::Rapid, [-6.0, 10.0], [-6.0, 26.0]));
        segs.push(blade(Motion::Rapid, [-6.0, 26.0], [-70.0, 26.0]));
        segs.push(blade(Motion::Rapid, [-70.0, 26.0], [-70.0, 20.0]));
        assert!(part_off % 1_024 > 0 && through_pin / 1_024 > part_off / 1_024);
        let sim = run(&blank, &ToolTable::empty(), &segs);
        let crashed: Vec<usize> = sim.crashes.iter().map(|c| c.segment).collect();
        assert_eq!(crashed, vec![segs.len() - 1], "{:?}", sim.crashes);
        assert!(
            (sim.crashes[0].area - 15.0).abs() < 1e-6,
            "{:?}",
            sim.crashes
        );
        assert!(
            (sim.removed_area - 96.0).abs() < 1e-6,
            "{}",
            sim.removed_area
        );
    }

    /// A program of more than 5 000 moves gets its snapshots at epoch ends: 6 400 grooving
    /// pecks (3 mm blade-like V35 plunges stepped 0.01 mm, each followed by a retract) ask
    /// for two counts; each snapshot is labelled with the moves it holds (at or after the
    /// count asked for, before the end) and is the stock of that prefix run.
    #[test]
    fn a_long_program_gets_its_snapshots_at_epoch_ends() {
        let blank = Blank::bar(50.0, 100.0, 0.0, None).unwrap();
        let mut segs = vec![];
        for k in 0..3_200 {
            let z = -1.0 - 0.01 * f64::from(k);
            segs.push(seg(
                Motion::Feed,
                [z, 26.0],
                [z, 24.0 - 0.0001 * f64::from(k)],
            ));
            segs.push(seg(
                Motion::Rapid,
                [z, 24.0 - 0.0001 * f64::from(k)],
                [z - 0.01, 26.0],
            ));
        }
        let opts = SimOptions {
            snapshot_after: vec![1_000, 4_000],
            ..SimOptions::default()
        };
        let sim = simulate(&blank, &v35(), &segs, &opts, &mut |_| {});
        let counts: Vec<usize> = sim.snapshots.iter().map(|s| s.0).collect();
        assert_eq!(counts.len(), 2, "{counts:?}");
        assert!(
            counts[0] >= 1_000 && counts[1] >= 4_000 && counts[1] < segs.len(),
            "{counts:?}"
        );
        for (k, shapes) in &sim.snapshots {
            let prefix = run(&blank, &v35(), &segs[..*k]);
            let h = hausdorff(shapes, &prefix.final_shapes);
            assert!(h <= 0.0005, "after {k} moves: hausdorff {h}");
            assert!((area(shapes) - area(&prefix.final_shapes)).abs() < 1e-6);
        }
        // and the removal does not depend on whether snapshots were asked for
        assert_eq!(sim.final_shapes, run(&blank, &v35(), &segs).final_shapes);
    }

    #[test]
    fn zig_zags_and_reversals_are_not_merged() {
        // sideways zig-zag: every move advances along Z, but the points are 0.002 mm apart
        let zz: Vec<Segment> = (0..100)
            .map(|k| {
                let r = |k: i32| 20.0 + 0.002 * f64::from(k % 2);
                let (z0, z1) = (-0.05 * f64::from(k), -0.05 * f64::from(k + 1));
                seg(Motion::Feed, [z0, r(k)], [z1, r(k + 1)])
            })
            .collect();
        assert_eq!(sweep_count(&v35(), &zz, 0.0005), 100);
        // back and forth along almost the same line (0.0001 mm apart): each move reverses
        let back: Vec<Segment> = (0..100)
            .map(|k| {
                let z = |k: i32| -0.05 * f64::from(k % 2);
                let r = |k: i32| 20.0 + 0.0001 * f64::from(k);
                seg(Motion::Feed, [z(k), r(k)], [z(k + 1), r(k + 1)])
            })
            .collect();
        assert_eq!(sweep_count(&v35(), &back, 0.0005), 100);
        // a rapid in between always ends a merged run
        let mut with_rapid = vec![
            seg(Motion::Feed, [0.0, 20.0], [-0.05, 20.0001]),
            seg(Motion::Feed, [-0.05, 20.0001], [-0.1, 20.0]),
            seg(Motion::Rapid, [-0.1, 20.0], [-0.1, 20.0]),
        ];
        with_rapid.push(seg(Motion::Feed, [-0.1, 20.0], [-0.15, 20.0001]));
        assert_eq!(sweep_count(&v35(), &with_rapid, 0.0005), 3);
    }

    #[test]
    fn bad_input_is_skipped_with_a_warning_never_a_panic() {
        let blank = Blank::bar(50.0, 110.0, 0.0, None).unwrap();
        let mut arc = seg(Motion::Feed, [1e300, 0.0], [0.0, 1e300]);
        arc.arc = Some(Arc {
            center: Pt::new(f64::NAN, 0.0),
            ccw: false,
        });
        let mut thread = seg(Motion::Thread, [0.0, 24.0], [-1e6, 24.0]);
        thread.lead = 1e-9;
        let segs = [
            seg(Motion::Feed, [f64::NAN, 1.0], [0.0, 0.0]),
            seg(
                Motion::Rapid,
                [f64::INFINITY, 1.0],
                [0.0, f64::NEG_INFINITY],
            ),
            arc,
            seg(Motion::Feed, [1e11, 20.0], [-1e11, 20.0]),
            seg(Motion::Feed, [3.0, 3.0], [3.0, 3.0]),
            thread,
        ];
        let mut calls = Vec::new();
        let sim = simulate(
            &blank,
            &ToolTable::empty(),
            &segs,
            &SimOptions {
                chord_tol: -1.0,
                ..SimOptions::default()
            },
            &mut |n| calls.push(n),
        );
        assert!(sim.warnings.iter().any(|(i, _)| *i == 0));
        assert!(sim.warnings.iter().any(|(i, _)| *i == 1));
        assert!(sim.warnings.iter().any(|(i, _)| *i == 2));
        assert!(sim
            .warnings
            .iter()
            .any(|(i, w)| *i == 5 && w.contains("swept continuously")));
        // the huge pass still turned the whole bar down to r 20
        assert!(
            (area(&sim.final_shapes) - 110.0 * 20.0).abs() < 1e-6,
            "{}",
            area(&sim.final_shapes)
        );
        assert_eq!(calls.last(), Some(&segs.len()));
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
            let sb = bbox_of(&shapes);
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

    /// Arcs swept as rings over a tube with a sawtooth of 3 000 teeth (split into tiles
    /// about 1.2 mm long, many wholly inside an R10 arc's sweep without meeting one of its
    /// edges, others in its box but outside it): the removal with the rings' air tests
    /// equals the one without (every tile tried with the ring's full edge test), so no tile
    /// an arc cuts was skipped; then a rapid that crashes into what is left.
    /// Roughing passes (each lowering the flat top, so each covers the last there),
    /// rapids back over the cut, one rapid through material a pass in the same batch cut
    /// and one into stock: leaving covered sweeps out of the batches removes exactly what
    /// every boolean call removes, with the same crashes.
    #[test]
    fn covered_sweeps_left_out_remove_exactly_what_every_sweep_removes() {
        let blank = Blank::bar(50.0, 40.0, 0.0, None).unwrap();
        let mut segs = Vec::new();
        for k in 1..=40 {
            let r = 25.0 - 0.05 * f64::from(k);
            let zend = -30.0 + 0.1 * f64::from(k % 3);
            segs.push(seg(Motion::Rapid, [5.0, r + 0.55], [5.0, r]));
            segs.push(seg(Motion::Feed, [5.0, r], [zend, r]));
            segs.push(seg(Motion::Feed, [zend, r], [zend + 0.5, r + 0.5]));
            segs.push(seg(Motion::Rapid, [zend + 0.5, r + 0.5], [5.0, r + 0.5]));
        }
        // back through the last pass's cut, then down into the stock
        segs.push(seg(Motion::Rapid, [5.0, 23.1], [-20.0, 23.1]));
        segs.push(seg(Motion::Rapid, [-20.0, 23.1], [-20.0, 21.0]));
        let sim = |cover| {
            let opts = SimOptions {
                cover,
                ..SimOptions::default()
            };
            simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
        };
        let (with, without) = (sim(true), sim(false));
        assert!(without.removed_area > 50.0, "{}", without.removed_area);
        assert_eq!(same_cut(&with, &without), [segs.len() - 1]);
    }

    /// Asserts that two runs cut the same stock (symmetric difference and removed area
    /// within 10⁻⁹) with the same crashes (move and area); returns the crashes' moves.
    fn same_cut(a: &Simulation, b: &Simulation) -> Vec<usize> {
        let xor = symmetric_difference_area(&a.final_shapes, &b.final_shapes);
        assert!(xor < 1e-9, "symmetric difference {xor} mm²");
        assert!((a.removed_area - b.removed_area).abs() < 1e-9);
        let verdicts = |s: &Simulation| {
            s.crashes
                .iter()
                .map(|c| (c.segment, c.area))
                .collect::<Vec<_>>()
        };
        assert_eq!(verdicts(a), verdicts(b));
        a.crashes.iter().map(|c| c.segment).collect()
    }

    /// What a box keeps when a core is cut out of it holds every unit cell of the box the
    /// core does not cover (what a cut leaves is the closure of such cells), and it shrinks
    /// when the core spans the box.
    #[test]
    fn the_box_outside_a_core_holds_what_the_cut_leaves() {
        use crate::ring_air::tests::{box_within, Rng};
        let mut rng = Rng(0x0b0c_5eed_0042);
        let mut shrunk = 0;
        for _ in 0..20_000 {
            let (b, core) = (box_within(&mut rng, 5), box_within(&mut rng, 7));
            let out = outside_core(b, &core);
            // every unit cell of the box the core does not cover lies in what is kept
            for x in b.min[0]..b.max[0] {
                for y in b.min[1]..b.max[1] {
                    let cut =
                        core.min[0] <= x && x < core.max[0] && core.min[1] <= y && y < core.max[1];
                    let kept =
                        out.min[0] <= x && x < out.max[0] && out.min[1] <= y && y < out.max[1];
                    assert!(
                        cut || kept,
                        "{b:?} less {core:?} gave {out:?}: cell ({x}, {y})"
                    );
                }
            }
            shrunk += usize::from(out != b);
        }
        assert!(shrunk > 2_000, "{shrunk}");
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
            builder.push(i, &seg(Motion::Feed, [5.0, r], [z, r]));
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

    #[test]
    fn ring_air_tests_remove_exactly_what_every_tile_test_removes() {
        let mut outline = vec![[-30.0, 28.0], [0.0, 28.0]];
        outline.extend((0..=3000).map(|k| [-0.01 * f64::from(k), 30.0 + 0.02 * f64::from(k % 2)]));
        let blank = Blank::from_rings(&[outline], "sawtooth tube");
        let mut segs = Vec::new();
        for pass in 0..6 {
            let (z0, r0) = (-4.0 - 0.37 * f64::from(pass), 31.5 - 0.3 * f64::from(pass));
            segs.push(seg(Motion::Rapid, [5.0, 40.0], [z0, 40.0]));
            segs.push(seg(Motion::Feed, [z0, 40.0], [z0, r0]));
            // a lower R10 half circle, an upper R2.5 one, then out
            let mut a = seg(Motion::Feed, [z0, r0], [z0 - 20.0, r0]);
            a.arc = Some(Arc {
                center: Pt::new(z0 - 10.0, r0),
                ccw: false,
            });
            let mut b = seg(Motion::Feed, [z0 - 20.0, r0], [z0 - 25.0, r0]);
            b.arc = Some(Arc {
                center: Pt::new(z0 - 22.5, r0),
                ccw: true,
            });
            segs.extend([a, b]);
            segs.push(seg(Motion::Feed, [z0 - 25.0, r0], [z0 - 25.0, 40.0]));
        }
        segs.push(seg(Motion::Rapid, [5.0, 40.0], [-1.0, 29.0]));
        let sim = |ring_air| {
            let opts = SimOptions {
                ring_air,
                ..SimOptions::default()
            };
            simulate(&blank, &v35(), &segs, &opts, &mut |_| {})
        };
        let (with, without) = (sim(true), sim(false));
        assert!(without.removed_area > 40.0, "{}", without.removed_area);
        assert_eq!(same_cut(&with, &without).len(), 1);
    }
}
