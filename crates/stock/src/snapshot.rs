//! Stock snapshots part-way through a removal run, taken in the run's one pass.
//!
//! The removal itself works in epochs over tiles and batches its cuts; cutting at the
//! snapshot counts inside it would change where batches end and so the last bits of the
//! final part. Up to [`EXACT_MAX_MOVES`] moves, snapshots therefore keep their own copy of
//! the stock and cut into it the same sweeps, in order, stopping at each count asked for
//! (the intended shapes read the stock exactly where a cycle began). The copy is held in Z
//! strips of tiles like the removal's and cut the way the removal cuts ([`Strips`]): each
//! range of sweeps meets only the tiles it reaches, with their air tests and batches (one
//! boolean call of the whole stock against every sweep of a range, 30 ranges, took 60 % of
//! an HTML run of 1 000 small arcs). A snapshot is the union of the copy's tiles: it
//! differs from one boolean call by where edges were rounded at tile sides and batch
//! ends, a few grid steps. Longer programs get their snapshots at the removal's own epoch
//! ends instead, where every tile is flushed: the union of the tiles' stock, at the first
//! epoch end at or after each count asked for, labelled with the moves it holds.

/// Longest program whose snapshots are taken exactly at their counts.
pub const EXACT_MAX_MOVES: usize = 5_000;

use crate::overlay::{Engine, Grid, IShapes};
use crate::removal::{SimOptions, Strips};
use crate::sweep::{SweepBuilder, Sweeps};

/// The snapshot counts still to come, the snapshot stock and the snapshots taken.
pub(crate) struct Snapshots {
    /// Exact at the counts (a second cut), or at epoch ends.
    exact: bool,
    marks: std::iter::Peekable<std::vec::IntoIter<usize>>,
    /// The blank, until [`Snapshots::tile`] puts it in strips (exact snapshots only).
    stock: IShapes,
    /// The snapshots' own copy of the stock, cut up to the last count reached.
    strips: Option<Strips>,
    /// Counts reached in the current epoch: (count, number of the epoch's sweeps emitted by
    /// then, the sweep of the merged run still open then).
    reached: Vec<(usize, usize, Sweeps)>,
    /// (move count, stock after that many moves), ascending.
    pub(crate) out: Vec<(usize, IShapes)>,
}

impl Snapshots {
    /// Snapshots after each of `marks` moves (those in `1..moves`), from `stock`: exact
    /// when `moves` is at most [`EXACT_MAX_MOVES`], else at epoch ends
    /// ([`Snapshots::at_epoch_end`]).
    pub(crate) fn new(marks: &[usize], moves: usize, stock: &IShapes) -> Self {
        let mut m: Vec<usize> = marks
            .iter()
            .copied()
            .filter(|&k| k > 0 && k < moves)
            .collect();
        m.sort_unstable();
        m.dedup();
        let exact = moves <= EXACT_MAX_MOVES;
        Self {
            exact,
            stock: if m.is_empty() || !exact {
                Vec::new()
            } else {
                stock.clone()
            },
            marks: m.into_iter().peekable(),
            strips: None,
            reached: Vec::new(),
            out: Vec::new(),
        }
    }

    /// Puts the snapshots' copy of the stock into strips (`strips` of the blank's stock),
    /// when snapshots are taken exactly and any are asked for.
    pub(crate) fn tile(&mut self, strips: impl FnOnce(&IShapes) -> Strips) {
        if !self.stock.is_empty() {
            self.strips = Some(strips(&std::mem::take(&mut self.stock)));
        }
    }

    /// Whether the snapshots are taken exactly at their counts (a short program) rather
    /// than at epoch ends.
    pub(crate) fn exact(&self) -> bool {
        self.exact
    }

    /// Called after `moves` moves were pushed into `builder`: at a snapshot count, notes how
    /// far the builder got and the sweep of its open run.
    pub(crate) fn after_push(&mut self, moves: usize, builder: &mut SweepBuilder) {
        if self.exact && self.marks.next_if_eq(&moves).is_some() {
            let emitted = builder.emitted();
            self.reached.push((moves, emitted, builder.peek_run()));
        }
    }

    /// Called with the sweeps the builder emitted this epoch: cuts them into the snapshots'
    /// copy of the stock and takes the snapshots reached.
    pub(crate) fn epoch(
        &mut self,
        sweeps: &Sweeps,
        run: (&Grid, &SimOptions),
        engine: &mut Engine,
    ) {
        let Some(strips) = self.strips.as_ref().filter(|_| self.exact) else {
            return;
        };
        let mut applied = 0;
        for (k, emitted, open) in std::mem::take(&mut self.reached) {
            strips.cut_items(sweeps, applied..emitted, run, engine);
            applied = emitted;
            let stock = strips.stock(engine);
            let snap = if open.items.is_empty() {
                stock
            } else {
                let polys = open
                    .items
                    .iter()
                    .filter(|it| it.body.is_none())
                    .flat_map(|it| open.polys_of(it));
                engine.difference(&stock, polys)
            };
            self.out.push((k, snap));
        }
        if self.marks.peek().is_some() {
            strips.cut_items(sweeps, applied..sweeps.items.len(), run, engine);
        }
    }

    /// At an epoch end (epoch mode): `stock()` is the stock holding the cuts of the first
    /// `moves` moves; it is taken once for all the counts asked for up to `moves`.
    pub(crate) fn at_epoch_end(&mut self, moves: usize, stock: impl FnOnce() -> IShapes) {
        let mut due = false;
        while !self.exact && self.marks.next_if(|&k| k <= moves).is_some() {
            due = true;
        }
        if due {
            self.out.push((moves, stock()));
        }
    }

    /// About how many bytes the snapshots' stock and the snapshots taken hold.
    pub(crate) fn bytes(&self) -> u64 {
        let copy = self.strips.as_ref().map_or(0, |s| s.census().0);
        let vertices: usize = std::iter::once(&self.stock)
            .chain(self.out.iter().map(|(_, s)| s))
            .flatten()
            .flatten()
            .map(Vec::len)
            .sum();
        ((vertices + copy) * std::mem::size_of::<crate::overlay::IPt>()) as u64
    }
}

#[cfg(test)]
mod tests {
    use crate::overlay::{Engine, Grid};
    use crate::removal::tests::{seg, v35};
    use crate::sweep::SweepBuilder;
    use crate::{area, hausdorff, simulate, Blank, Shape, SimOptions, ToolTable};
    use expander::{Arc, Motion, Pt, Segment};
    use geom::Rect;

    /// The stock after the first `k` moves of `segs` as one boolean call makes it: the blank
    /// less every sweep of those moves at once, on the grid and clip box the run uses; and
    /// that grid's step, mm.
    fn one_call(blank: &Blank, tools: &ToolTable, segs: &[Segment], k: usize) -> (Vec<Shape>, f64) {
        let bb = Rect::of(blank.shapes.iter().flat_map(|s| geom::flat::pts(&s.outer)));
        let margin = 1.0 + 1e-3 * bb.size();
        let grid = Grid::new(bb.grown(2.0 * margin));
        let mut builder = SweepBuilder::new(&grid, bb.grown(margin), tools, 0.001, 0.0005);
        builder.set_pass_groups(false);
        for (i, s) in segs[..k].iter().enumerate() {
            builder.push(i, s, segs.get(i + 1));
        }
        builder.flush_run();
        let sweeps = builder.take();
        let polys = sweeps
            .items
            .iter()
            .filter(|it| it.body.is_none())
            .flat_map(|it| sweeps.polys_of(it));
        let stock = grid.shapes_to_int(&blank.shapes);
        let exact = Engine::new().difference(&stock, polys);
        (grid.shapes_to_float(&exact), grid.step())
    }

    /// 80 R0.5 semicircles in a row along a Ø45 bar (the 1 000 small arcs, fewer),
    /// snapshots every 8 moves: each snapshot, cut into the snapshots' own tiled copy of the
    /// stock, lies within two grid steps of the blank less all the sweeps before its count
    /// in one boolean call (rounding at tile sides and batch ends), the same area within
    /// 10⁻⁷ mm².
    #[test]
    fn tiled_snapshots_of_small_arcs_stay_within_grid_steps_of_one_boolean_call() {
        let blank = Blank::bar(45.0, 100.0, 0.0, None).unwrap();
        let tools = v35();
        let mut segs = vec![
            seg(Motion::Rapid, [1.0, 21.0], [1.0, 20.5]),
            seg(Motion::Feed, [1.0, 20.5], [0.0, 20.0]),
        ];
        for k in 1..=80 {
            let (z0, z1) = (-f64::from(k - 1), -f64::from(k));
            let mut arc = seg(Motion::Feed, [z0, 20.0], [z1, 20.0]);
            arc.arc = Some(Arc {
                center: Pt::new(0.5 * (z0 + z1), 20.0),
                ccw: true,
            });
            segs.push(arc);
        }
        segs.push(seg(Motion::Rapid, [-80.0, 20.0], [-80.0, 24.0]));
        let marks: Vec<usize> = (1..11).map(|i| 8 * i).collect();
        let opts = SimOptions {
            snapshot_after: marks.clone(),
            ..SimOptions::default()
        };
        let sim = simulate(&blank, &tools, &segs, &opts, &mut |_| {});
        let counts: Vec<usize> = sim.snapshots.iter().map(|s| s.0).collect();
        assert_eq!(counts, marks);
        let mut worst: f64 = 0.0;
        for (k, shapes) in &sim.snapshots {
            let (exact, step) = one_call(&blank, &tools, &segs, *k);
            let h = hausdorff(shapes, &exact);
            worst = worst.max(h / step);
            assert!(
                h <= 2.0 * step,
                "after {k} moves: hausdorff {h}, grid {step}"
            );
            let da = (area(shapes) - area(&exact)).abs();
            assert!(da <= 1e-7, "after {k} moves: area {da}");
        }
        eprintln!("worst hausdorff {worst} grid steps");
        // and the cuts are real: each snapshot holds less than the one before
        let areas: Vec<f64> = sim.snapshots.iter().map(|(_, s)| area(s)).collect();
        assert!(areas.windows(2).all(|w| w[1] < w[0] - 0.1), "{areas:?}");
    }
}
