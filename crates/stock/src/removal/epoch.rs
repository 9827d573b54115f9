//! Epochs: the program is cut a slice of moves at a time into the stock's Z strips, the
//! next slice's sweeps built while the workers cut this one's; an epoch ends at a part-off,
//! and the pieces that fell are erased from what comes after.

use super::batch::{Batch, Trimmed};
use super::crash::Fragment;
use super::tile::{Ctx, Node, Tile, Worker, MIN_TILE};
use super::SimOptions;
use crate::budget::{size, OverBudget, RunMemory};
use crate::overlay::{Engine, Grid, IBox, IPt, IShape, IShapes};
use crate::snapshot::Snapshots;
use crate::sweep::{SweepBuilder, Sweeps};
use crate::{Shape, ToolTable};
use expander::{Motion, Segment};
use geom::Rect;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Target width of a Z strip, mm (strips are the units of parallel work; complex stock is
/// split further into tiles).
const STRIP_WIDTH: f64 = 30.0;
/// Upper bound on the number of strips.
const MAX_STRIPS: usize = 64;
/// Segments handled between two progress reports (also bounds the sweeps held in memory).
const EPOCH: usize = 32_768;
/// About how many epochs a program short enough for exact snapshots is cut in: the first
/// epoch's sweeps are built before any cutting starts, each later one's beside the cutting.
const EXACT_EPOCHS: usize = 4;
/// Most part-offs after which the stock is looked at for pieces that fell.
const MAX_SEPARATION_CHECKS: usize = 1_000;

/// The stock of a run: Z strips, each a tree of tiles, cut by `threads` workers.
pub(crate) struct Strips {
    /// The strips' Z bounds (grid units), one more than the strips.
    bounds: Vec<i32>,
    nodes: Vec<Mutex<Node>>,
    /// Tiles no smaller than this (grid units) are never split.
    min_tile: i64,
    threads: usize,
    /// The bar's left end (grid units), where the chuck holds it.
    left_end: i32,
}

impl Strips {
    /// The blank's `stock` in strips across the clip box `clip` (`bb`: the blank's box).
    pub(crate) fn new(
        grid: &Grid,
        clip: &Rect,
        bb: &Rect,
        stock: &IShapes,
        engine: &mut Engine,
    ) -> Self {
        let IBox {
            min: [x0, y0],
            max: [x1, y1],
        } = grid.box_to_int(clip);
        let n_strips = ((clip.width() / STRIP_WIDTH).ceil() as usize).clamp(1, MAX_STRIPS);
        let bounds: Vec<i32> = (0..=n_strips)
            .map(|k| {
                (i64::from(x0) + (i64::from(x1) - i64::from(x0)) * k as i64 / n_strips as i64)
                    as i32
            })
            .collect();
        let nodes = (0..n_strips)
            .map(|k| {
                let tile = IBox {
                    min: [bounds[k], y0],
                    max: [bounds[k + 1], y1],
                };
                let part = engine.intersection(stock, [&tile.corners()[..]]);
                Mutex::new(Node::Leaf(Tile::new(tile, part)))
            })
            .collect();
        let threads = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(n_strips);
        Self {
            bounds,
            nodes,
            min_tile: (MIN_TILE / grid.step()) as i64,
            threads,
            left_end: grid.box_to_int(bb).min[0],
        }
    }

    /// For each strip, the sweeps whose box reaches into it.
    fn lists(&self, sweeps: &Sweeps) -> Vec<Vec<u32>> {
        let bounds = &self.bounds;
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

    /// Cuts an epoch's sweeps into the strips (`lists[k]`: the sweeps that reach strip `k`),
    /// the workers taking strips in turn; the calling thread first does `meanwhile`
    /// (building the next epoch), then joins them. Each strip ends its batches at the
    /// epoch's `stops` and, where a snapshot is wanted, keeps a copy of its tiles there, so
    /// no strip waits for another at a stop. Returns the rapid cuts found and, for each
    /// stop whose snapshot is wanted, the tiles of every strip there.
    fn cut(
        &self,
        (lists, stops): (&[Vec<u32>], &[Stop]),
        ctx: &Ctx,
        engine: &mut Engine,
        meanwhile: impl FnOnce(),
    ) -> (Vec<Fragment>, Vec<Vec<(IBox, IShapes)>>) {
        let next_strip = AtomicUsize::new(0);
        let n = self.nodes.len();
        let wanted = stops.iter().filter(|s| s.wanted).count();
        // [wanted stop][strip]: each filled once, by the worker that takes the strip
        let kept: Vec<Mutex<Vec<(IBox, IShapes)>>> =
            (0..wanted * n).map(|_| Mutex::default()).collect();
        let work = |engine: &mut Engine| {
            let mut worker = Worker {
                engine,
                frags: Vec::new(),
                batch: Batch::default(),
                trim: Trimmed::default(),
                runs: Vec::new(),
                calls: 0,
            };
            loop {
                let k = next_strip.fetch_add(1, Ordering::Relaxed);
                if k >= n {
                    break;
                }
                let list = &lists[k];
                if list.is_empty() && wanted == 0 {
                    continue;
                }
                // a poisoned lock only means another worker panicked; its data is still whole
                let mut strip = self.nodes[k].lock().unwrap_or_else(|e| e.into_inner());
                let mut from = 0;
                let mut w = 0;
                for stop in stops {
                    let to = from + list[from..].partition_point(|&i| (i as usize) < stop.items);
                    if to > from {
                        strip.process(&list[from..to], ctx, &mut worker);
                    }
                    from = to;
                    if stop.wanted {
                        let mut tiles = Vec::new();
                        strip.gather(&mut tiles);
                        *kept[w * n + k].lock().unwrap_or_else(|e| e.into_inner()) = tiles;
                        w += 1;
                    }
                }
                if from < list.len() {
                    strip.process(&list[from..], ctx, &mut worker);
                }
            }
            worker.frags
        };
        // A worker thread costs tens of µs; an epoch of few sweeps is still worth one: chained
        // runs make 10⁵ contour moves a few hundred sweeps, which under the old bar of 256
        // were cut on this thread after the next epoch was built, not beside it.
        let total: usize = lists.iter().map(Vec::len).sum();
        let frags = if self.threads <= 1 || total == 0 {
            meanwhile();
            work(engine)
        } else {
            self.cut_beside(work, engine, meanwhile)
        };
        let mut kept = kept
            .into_iter()
            .map(|m| m.into_inner().unwrap_or_else(|e| e.into_inner()));
        let tiles = (0..wanted)
            .map(|_| kept.by_ref().take(n).flatten().collect())
            .collect();
        (frags, tiles)
    }

    /// Runs `work` on the worker threads and, after `meanwhile`, on the calling thread.
    fn cut_beside(
        &self,
        work: impl Fn(&mut Engine) -> Vec<Fragment> + Sync,
        engine: &mut Engine,
        meanwhile: impl FnOnce(),
    ) -> Vec<Fragment> {
        std::thread::scope(|s| {
            let handles: Vec<_> = (1..self.threads)
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

    /// The stock as it stands: every strip's tiles joined.
    pub(crate) fn stock(&self, engine: &mut Engine) -> IShapes {
        let mut tiles = Vec::new();
        for m in &self.nodes {
            m.lock()
                .unwrap_or_else(|e| e.into_inner())
                .gather(&mut tiles);
        }
        joined(&tiles, engine)
    }

    /// The vertices of the stock and the tiles holding them.
    pub(crate) fn census(&self) -> (usize, usize) {
        self.nodes.iter().fold((0, 0), |(v, t), m| {
            let (nv, nt) = m.lock().unwrap_or_else(|e| e.into_inner()).census();
            (v + nv, t + nt)
        })
    }

    /// Whether any stock lies right of `x` (grid units).
    fn has_stock_right_of(&self, x: i32) -> bool {
        self.nodes.iter().any(|m| {
            m.lock()
                .unwrap_or_else(|e| e.into_inner())
                .has_stock_right_of(x)
        })
    }

    /// The stock of every tile with the tile's box, the strips taken apart.
    pub(super) fn into_parts(self) -> Vec<(IBox, IShapes)> {
        let mut parts = Vec::new();
        for m in self.nodes {
            m.into_inner()
                .unwrap_or_else(|e| e.into_inner())
                .collect(&mut parts);
        }
        parts
    }
}

/// The union of the tiles' stock: stitched along the tile sides where they meet as cut
/// tiles do, else by the boolean union (a debug build checks the stitch against it).
pub(crate) fn joined(tiles: &[(IBox, IShapes)], engine: &mut Engine) -> IShapes {
    let union = |engine: &mut Engine| {
        let parts: Vec<IShapes> = tiles.iter().map(|(_, s)| s.clone()).collect();
        engine.union(&parts)
    };
    match super::stitch::stitch(tiles) {
        Some(stitched) => {
            debug_assert!(
                stitched == union(engine),
                "the stitch differs from the union"
            );
            stitched
        }
        None => union(engine),
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
    /// The stops in the epoch and at its end ([`crate::snapshot::stops`]), ascending.
    stops: Vec<Stop>,
}

/// A stop in an epoch: every strip ends its batches there (so that every report of a run
/// reads the same part) and keeps its tiles when a snapshot is wanted there.
struct Stop {
    /// Moves done at the stop.
    moves: usize,
    /// The epoch's sweeps built by then.
    items: usize,
    /// A snapshot is wanted there.
    wanted: bool,
    /// The sweep so far of a merged run of feeds still open there, when a snapshot is
    /// wanted (its cut comes when it ends: the snapshot is the stock less it).
    open: Option<Sweeps>,
}

impl Epoch {
    /// The moves whose cuts are all in the tiles once this epoch is cut (`before`: those of
    /// the epochs before): a merged run still open is not, its sweep comes when it ends.
    fn cut_moves(&self, before: usize) -> usize {
        if !self.open_run {
            return self.end;
        }
        self.sweeps
            .items
            .iter()
            .filter(|it| it.body.is_none())
            .map(|it| it.seg + 1)
            .max()
            .unwrap_or(before)
    }
}

/// What cutting the epochs found besides the stock.
#[derive(Default)]
pub(super) struct Cuts {
    /// Every strip's rapid cuts.
    pub(super) fragments: Vec<Fragment>,
    /// Pieces parted off the held bar: (moves done when they fell, the pieces).
    pub(super) fallen: Vec<(usize, IShapes)>,
    /// (move, message).
    pub(super) warnings: Vec<(usize, String)>,
    /// The run went over its memory budget: it stopped there.
    pub(super) over_budget: Option<OverBudget>,
}

/// What builds the epochs' sweeps in program order: the sweep builder, the snapshot counts
/// it passes, and the program.
pub(super) struct Epochs<'a> {
    pub(super) builder: SweepBuilder<'a>,
    pub(super) snapshots: Snapshots,
    segments: &'a [Segment],
    tools: &'a ToolTable,
    /// The blank's bore radius (a blade parts off there).
    bore: f64,
    /// The widest hole opened along Z so far (a drill's edge, a bore an ID tool turned):
    /// a blade reaching it may part a ring off into it (field run 7, B).
    hole: f64,
    /// Most moves an epoch holds.
    len: usize,
    /// Move counts where the strips end their batches (`snapshot::stops`), ascending.
    stops: Vec<usize>,
    /// Part-offs after which the stock was looked at for pieces that fell.
    checks: usize,
}

impl<'a> Epochs<'a> {
    /// The epochs of `segments` over the blank `shapes` (on `grid`), sweeps clipped
    /// to `clip`.
    pub(super) fn new(
        grid: &'a Grid,
        clip: Rect,
        tools: &'a ToolTable,
        segments: &'a [Segment],
        opts: &SimOptions,
        shapes: &[Shape],
    ) -> Self {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        let tol = if positive(opts.chord_tol) {
            opts.chord_tol
        } else {
            0.001
        };
        let merge_tol = if positive(opts.merge_tol) {
            opts.merge_tol
        } else {
            0.0
        };
        let mut builder = SweepBuilder::new(grid, clip, tools, tol, merge_tol);
        builder.set_rear(crate::section::rear_tools(segments));
        builder.set_feed_paths(opts.feed_paths);
        let snapshots = Snapshots::new(&opts.snapshot_after, &opts.snapshot_exact, segments.len());
        // a group's passes are one sweep: only where snapshots are not taken move by move
        builder.set_pass_groups(opts.pass_groups && !snapshots.exact());
        Self {
            builder,
            // programs whose snapshots come from epoch ends get about 30 epochs (depending
            // only on the program's length, so every report of a run reads the same removal);
            // shorter ones a few, ending at stops
            len: if snapshots.exact() {
                segments.len().div_ceil(EXACT_EPOCHS).max(1)
            } else {
                (segments.len() / 30).clamp(1024, EPOCH)
            },
            stops: crate::snapshot::stops(
                &opts.snapshot_after,
                &opts.snapshot_exact,
                segments.len(),
            ),
            snapshots,
            segments,
            tools,
            bore: bore(shapes),
            hole: 0.0,
            checks: 0,
        }
    }

    /// Cuts every epoch into `strips`, calling `progress` with the moves done after each.
    pub(super) fn cut_all(
        &mut self,
        strips: &Strips,
        (grid, engine): (&Grid, &mut Engine),
        opts: &SimOptions,
        progress: &mut dyn FnMut(usize),
    ) -> Cuts {
        let moves = self.segments.len();
        let mut cuts = Cuts::default();
        // moves whose cuts are all in the tiles at the last epoch end
        let mut cut_moves = 0;
        let stop = AtomicBool::new(false);
        // the snapshots of the last epoch's stops, joined beside the next epoch's cutting
        let mut pending = Vec::new();
        let mut side = Engine::new();
        let mut next = Some(self.build(0, None));
        while let Some(mut ep) = next.take() {
            let lists = strips.lists(&ep.sweeps);
            // the next epoch's sweeps are built while the workers cut this one's, unless this
            // one ends with a part-off (the stock is looked at first: pieces that fell are
            // erased from what comes after)
            let ahead = !ep.parting && ep.end < moves;
            let ctx = Ctx {
                grid,
                min_tile: strips.min_tile,
                sweeps: &ep.sweeps,
                ring_air: opts.ring_air,
                cover: opts.cover,
                budget: opts.max_memory.as_ref(),
                stop: &stop,
            };
            let (mut found, kept) = strips.cut((&lists, &ep.stops), &ctx, engine, || {
                if ahead {
                    next = Some(self.build(ep.end, None));
                }
                self.snapshots
                    .at_stops(std::mem::take(&mut pending), 1, &mut side);
            });
            cuts.fragments.append(&mut found);
            if let Some(memory) = &opts.max_memory {
                let over = self.over_budget(memory, (&ctx, strips), &ep, &cuts, cut_moves);
                if let Some(over) = over {
                    cuts.over_budget = Some(over);
                    progress(moves);
                    break;
                }
            }
            let wanted = std::mem::take(&mut ep.stops)
                .into_iter()
                .filter(|s| s.wanted);
            let taken = wanted.zip(kept).map(|(s, tiles)| (s.moves, tiles, s.open));
            pending.extend(taken);
            cut_moves = ep.cut_moves(cut_moves);
            // (at the last epoch end the stock is the final part, which the caller has anyway)
            if ep.end < moves {
                self.snapshots
                    .at_epoch_end(cut_moves, || strips.stock(engine));
            }
            let fallen = if ep.parting && ep.end < moves {
                self.fallen_at(ep.end, strips, (grid, engine), &mut cuts)
            } else {
                None
            };
            progress(ep.end);
            if next.is_none() && ep.end < moves {
                next = Some(self.build(ep.end, fallen));
            }
        }
        if cuts.over_budget.is_none() {
            self.snapshots.at_stops(pending, strips.threads, engine);
        }
        cuts
    }

    /// The run went over its budget (a worker saw it, or the run's thread sees it now): how
    /// far it got (`cut_moves` before this epoch when a worker stopped it midway) and what
    /// grew. First tells the batch's ledger what this run holds.
    fn over_budget(
        &self,
        memory: &RunMemory,
        (ctx, strips): (&Ctx, &Strips),
        ep: &Epoch,
        cuts: &Cuts,
        cut_moves: usize,
    ) -> Option<OverBudget> {
        let parts = self.holdings(strips, &ep.sweeps, cuts);
        let total: u64 = parts.iter().map(|p| p.0).sum();
        memory.holds(total);
        let held = memory
            .over()
            .or_else(|| ctx.stopped().then(|| memory.held()))?;
        let moves = if ctx.stopped() { cut_moves } else { ep.end };
        Some(OverBudget {
            budget: memory.budget(),
            held,
            moves,
            what: what_grew(parts, held),
        })
    }

    /// What the run holds that grows with its input: the moves, the stock's outline, the
    /// epoch's sweeps, the snapshots, the rapid cuts' pieces (bytes, in words).
    fn holdings(&self, strips: &Strips, sweeps: &Sweeps, cuts: &Cuts) -> [(u64, String); 5] {
        let (vertices, tiles) = strips.census();
        let bytes = |n: usize, each: usize| (n * each) as u64;
        let frags = cuts.fragments.len();
        let moves = self.segments.len();
        [
            (
                bytes(moves, std::mem::size_of::<Segment>()),
                format!("the program's {moves} moves"),
            ),
            (
                bytes(vertices, std::mem::size_of::<IPt>()),
                format!("the stock's outline, {vertices} vertices in {tiles} tiles"),
            ),
            (sweeps.bytes(), "this epoch's sweeps".to_string()),
            (self.snapshots.bytes(), "the stock snapshots".to_string()),
            (
                bytes(frags, std::mem::size_of::<Fragment>()),
                format!("{frags} pieces of rapid cuts"),
            ),
        ]
    }

    /// After a part-off ending at move `end`: the pieces that fell (kept in `cuts`), as the
    /// (move, section shapes) the builder erases; none when the blade has no stock beyond
    /// it (a face to the centre parts nothing off) or no piece fell.
    fn fallen_at(
        &mut self,
        end: usize,
        strips: &Strips,
        (grid, engine): (&Grid, &mut Engine),
        cuts: &mut Cuts,
    ) -> Option<(usize, Vec<Shape>)> {
        let seg = &self.segments[end - 1];
        if !strips.has_stock_right_of(grid.to_int([seg.from.z.max(seg.to.z), 0.0]).x) {
            return None;
        }
        self.checks += 1;
        if self.checks == MAX_SEPARATION_CHECKS {
            cuts.warnings.push((
                end - 1,
                format!("{MAX_SEPARATION_CHECKS} part-offs: pieces parted off after this move stay in the stock"),
            ));
        }
        let off = fallen_pieces(strips.stock(engine), strips.left_end)?;
        let erase = (end - 1, grid.shapes_to_float(&off));
        cuts.fallen.push((end, off));
        Some(erase)
    }

    /// Builds the sweeps of the epoch starting at move `start` (ended at the first part-off
    /// while part-offs are looked at), after erasing the pieces `fallen` from what later
    /// sweeps see.
    fn build(&mut self, start: usize, fallen: Option<(usize, Vec<Shape>)>) -> Epoch {
        let (segments, tools, bore) = (self.segments, self.tools, self.bore);
        let looking = self.checks < MAX_SEPARATION_CHECKS;
        let mut end = (start + self.len).min(segments.len());
        if self.snapshots.exact() {
            // ends at a stop, where every strip ends its batches anyway
            end = self.stops[self.stops.partition_point(|&k| k < end)..]
                .first()
                .map_or(segments.len(), |&k| k.min(segments.len()));
        }
        // a part-off may leave a piece: its epoch ends with it, so that the stock can be
        // looked at before the next move
        let mut hole = self.hole;
        let parting_at = segments[start..end].iter().position(|s| {
            let parts = looking && parts_off(s, tools, bore.max(hole));
            hole = hole.max(opened(s, tools));
            parts
        });
        self.hole = hole;
        if let Some(k) = parting_at {
            end = start + k + 1;
        }
        if let Some((idx, pieces)) = fallen {
            self.builder.erase(idx, &pieces);
        }
        let mut stops = Vec::new();
        let mut next_stop = self.stops.partition_point(|&k| k <= start);
        for (k, seg) in segments[start..end].iter().enumerate() {
            self.builder
                .push(start + k, seg, segments.get(start + k + 1));
            let done = start + k + 1;
            if done < end && self.stops.get(next_stop) == Some(&done) {
                stops.push(self.stop(done));
                next_stop += 1;
            }
        }
        let parting = parting_at.is_some();
        if end == segments.len() || parting {
            self.builder.flush_run();
        }
        if self.stops.get(next_stop) == Some(&end) {
            stops.push(self.stop(end));
        }
        Epoch {
            end,
            parting,
            sweeps: self.builder.take(),
            open_run: self.builder.has_open_run(),
            stops,
        }
    }

    /// The stop after `moves` moves, the sweeps of those moves built.
    fn stop(&mut self, moves: usize) -> Stop {
        let wanted = self.snapshots.wanted(moves);
        let open = (wanted && self.builder.has_open_run()).then(|| self.builder.peek_run());
        Stop {
            moves,
            items: self.builder.count_at_stop(),
            wanted,
            open,
        }
    }
}

/// A tube's bore radius, 0 for a bar: a blade parts a tube off when it reaches the bore,
/// not the axis.
fn bore(shapes: &[Shape]) -> f64 {
    shapes
        .iter()
        .flat_map(|s| s.outer.iter().chain(s.holes.iter().flatten()))
        .map(|p| p[1])
        .fold(f64::INFINITY, f64::min)
        .max(0.0)
}

/// A part-off: a feed of a blade (a grooving tool, or a grooving cycle's) inward to the
/// axis or into a bore (`bore`: the blank's inner radius, or a hole opened since); it may leave a
/// piece that no longer reaches the held bar. (A turning tool facing to the centre leaves,
/// between passes, only a pip at the axis that its next pass cuts: no part.)
fn parts_off(seg: &Segment, tools: &ToolTable, bore: f64) -> bool {
    seg.motion == Motion::Feed
        && seg.to.r <= bore + 1e-9
        && seg.from.r > seg.to.r
        && tools.blade_cuts(seg)
}

/// How far out feed `s` opens the part from the inside when it runs along Z: a drill's
/// edge, an ID turning tool's reference point (the bore it turns); 0 for other moves.
fn opened(s: &Segment, tools: &ToolTable) -> f64 {
    if s.motion != Motion::Feed || (s.to.z - s.from.z).abs() <= (s.to.r - s.from.r).abs() {
        return 0.0;
    }
    let r = s.from.r.abs().max(s.to.r.abs());
    match tools.tool_or_default(s.tool) {
        crate::Tool::Drill { diameter, .. } => r + diameter / 2.0,
        crate::Tool::Turning { tip: 1 | 2 | 6, .. } => r,
        _ => 0.0,
    }
}

/// The pieces of `stock` that no longer reach the bar's left end `left_end` (grid units),
/// where the chuck holds it: parted off, fallen. None while the held bar is the only piece,
/// or when no piece reaches the left end (nothing to tell held from fallen).
fn fallen_pieces(stock: IShapes, left_end: i32) -> Option<IShapes> {
    let held = |s: &IShape| {
        s.first()
            .is_some_and(|outer| outer.iter().any(|p| p.x <= left_end + 1))
    };
    if stock.len() < 2 || !stock.iter().any(held) {
        return None;
    }
    let off: IShapes = stock.into_iter().filter(|s| !held(s)).collect();
    (!off.is_empty()).then_some(off)
}

/// What grew, in words: the run's holdings largest first, and whether they are most of
/// what the process held (`held` bytes) or the rest was held elsewhere.
fn what_grew(mut parts: [(u64, String); 5], held: u64) -> String {
    parts.sort_by_key(|p| std::cmp::Reverse(p.0));
    let total: u64 = parts.iter().map(|p| p.0).sum();
    let list: Vec<String> = parts
        .iter()
        .filter(|p| p.0 >= 1024)
        .take(3)
        .map(|(bytes, what)| format!("{what} ({})", size(*bytes)))
        .collect();
    let list = if list.is_empty() {
        vec!["nothing over 1 KiB".to_string()]
    } else {
        list
    };
    if total * 2 >= held {
        format!("what grew is this run's {}", list.join(", "))
    } else {
        format!(
            "this run's removal held {} of it ({}); the rest is held by the reading of the program, other programs of the batch or the process itself",
            size(total),
            list.join(", ")
        )
    }
}
