//! Stock snapshots part-way through a removal run, taken in the run's one pass.
//!
//! The removal works in epochs over tiles and batches its cuts; where an epoch ends, every
//! tile is flushed and the stock is the union of the tiles. A program of up to
//! [`EXACT_MAX_MOVES`] moves therefore ends an epoch at each of its stops ([`stops`]): the
//! HTML player's counts ([`player_marks`], a function of the program's length alone) and
//! the counts the analysis asks for (where a cycle began, a function of the program), so
//! a snapshot there is the stock exactly after that many moves, and the removal ends its
//! batches at the same places whichever reports are written: every report of a run reads
//! the same part. (A second copy of the stock cut to the counts cost as much as the removal
//! itself: 95 of 317 ms on 1 000 small arcs.) Longer programs get their snapshots at the
//! removal's own epoch ends: the union of the tiles' stock, at the first epoch end at or
//! after each count asked for, labelled with the moves it holds.

/// Longest program whose snapshots are taken exactly at their counts.
pub const EXACT_MAX_MOVES: usize = 5_000;
/// How many snapshots the HTML player shows (besides the blank and the final part).
const PLAYER: usize = 30;
/// How many for programs over [`EXACT_MAX_MOVES`] moves, where each is a union of all the
/// removal's tiles (the 10⁵-move cutting zig-zag: 29 of them added 3.2 s to a 4.1 s run).
const PLAYER_LONG: usize = 10;

use crate::overlay::{Engine, IBox, IShapes};
use crate::removal::joined;
use crate::sweep::Sweeps;

/// What a stop whose snapshot is wanted kept: (moves done there, the tiles of every strip there, the
/// sweep so far of a merged run still open there).
pub(crate) type Kept = (usize, Vec<(IBox, IShapes)>, Option<Sweeps>);

/// Move counts after which the HTML player shows the stock (its move slider): evenly
/// spread over the program's `moves`.
pub fn player_marks(moves: usize) -> Vec<usize> {
    let count = if moves > EXACT_MAX_MOVES {
        PLAYER_LONG
    } else {
        PLAYER
    };
    let mut marks: Vec<usize> = (1..count)
        .map(|i| i * moves / count)
        .filter(|&k| k > 0 && k < moves)
        .collect();
    marks.dedup();
    marks
}

/// Where the removal of a program of `moves` moves ends its epochs besides its usual ends:
/// at the counts `exact` asks for whatever its length; for a program of up to
/// [`EXACT_MAX_MOVES`] moves also at the player's counts and at the counts `asked` (those
/// in `1..moves`), ascending.
pub(crate) fn stops(asked: &[usize], exact: &[usize], moves: usize) -> Vec<usize> {
    let mut stops = if moves > EXACT_MAX_MOVES {
        Vec::new()
    } else {
        let mut s = player_marks(moves);
        s.extend_from_slice(asked);
        s
    };
    stops.extend_from_slice(exact);
    stops.retain(|&k| k > 0 && k < moves);
    stops.sort_unstable();
    stops.dedup();
    stops
}

/// The snapshot counts still to come and the snapshots taken.
pub(crate) struct Snapshots {
    /// Exact at the counts (epochs end there), or at epoch ends.
    exact: bool,
    /// The counts asked for, ascending.
    marks: Vec<usize>,
    /// The counts taken exactly although the program is long (epochs end there), ascending.
    pinned: Vec<usize>,
    /// Counts before this index were served (epoch mode).
    served: usize,
    /// (move count, stock after that many moves), ascending.
    pub(crate) out: Vec<(usize, IShapes)>,
}

impl Snapshots {
    /// Snapshots after each of `marks` moves (those in `1..moves`): exact when `moves` is
    /// at most [`EXACT_MAX_MOVES`] ([`Snapshots::at_stop`]), else at epoch ends
    /// ([`Snapshots::at_epoch_end`]); after each of `exact` moves exactly either way.
    pub(crate) fn new(marks: &[usize], exact: &[usize], moves: usize) -> Self {
        let counts = |ks: &mut dyn Iterator<Item = usize>| {
            let mut m: Vec<usize> = ks.filter(|&k| k > 0 && k < moves).collect();
            m.sort_unstable();
            m.dedup();
            m
        };
        let short = moves <= EXACT_MAX_MOVES;
        let (marks, pinned) = if short {
            (counts(&mut marks.iter().chain(exact).copied()), vec![])
        } else {
            (
                counts(&mut marks.iter().copied()),
                counts(&mut exact.iter().copied()),
            )
        };
        Self {
            exact: short,
            marks,
            pinned,
            served: 0,
            out: Vec::new(),
        }
    }

    /// Whether the snapshots are taken exactly at their counts (a short program) rather
    /// than at epoch ends.
    pub(crate) fn exact(&self) -> bool {
        self.exact
    }

    /// Whether a snapshot is wanted exactly after `moves` moves (exact mode, or pinned).
    pub(crate) fn wanted(&self, moves: usize) -> bool {
        (self.exact && self.marks.binary_search(&moves).is_ok())
            || self.pinned.binary_search(&moves).is_ok()
    }

    /// At the end of an epoch with stops where snapshots are wanted (exact mode, or pinned
    /// counts): for each, (moves done there, the tiles every strip had there, the sweep so
    /// far of a merged run still open there), takes the snapshot: the union of the tiles,
    /// less the open run's sweep (its cut comes when it ends). The unions are made on up to
    /// `threads` threads: 29 of them on 1 000 small arcs were 20 ms on one.
    pub(crate) fn at_stops(&mut self, stops: Vec<Kept>, threads: usize, engine: &mut Engine) {
        let take = |(moves, tiles, open): Kept, engine: &mut Engine| {
            let stock = joined(&tiles, engine);
            let snap = match open {
                Some(open) => {
                    let polys = open
                        .items
                        .iter()
                        .filter(|it| it.body.is_none())
                        .flat_map(|it| open.polys_of(it));
                    engine.difference(&stock, polys)
                }
                None => stock,
            };
            (moves, snap)
        };
        let threads = threads.clamp(1, stops.len().max(1));
        if threads == 1 {
            for stop in stops {
                let snap = take(stop, engine);
                self.out.push(snap);
            }
            return;
        }
        // stop m goes to thread m % threads; the calling thread takes the first share
        let mut shares: Vec<Vec<Kept>> = (0..threads).map(|_| Vec::new()).collect();
        for (m, stop) in stops.into_iter().enumerate() {
            shares[m % threads].push(stop);
        }
        let mut shares = shares.into_iter();
        let mine = shares.next().unwrap_or_default();
        let taken: Vec<Vec<(usize, IShapes)>> = std::thread::scope(|s| {
            let handles: Vec<_> = shares
                .map(|share| {
                    s.spawn(move || {
                        let mut engine = Engine::new();
                        share
                            .into_iter()
                            .map(|stop| take(stop, &mut engine))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            let mut all = vec![mine.into_iter().map(|stop| take(stop, engine)).collect()];
            // a thread that panicked lost its snapshots; the player shows the others
            all.extend(handles.into_iter().map(|h| h.join().unwrap_or_default()));
            all
        });
        let mut taken: Vec<(usize, IShapes)> = taken.into_iter().flatten().collect();
        taken.sort_by_key(|(k, _)| *k);
        self.out.extend(taken);
    }

    /// At an epoch end (epoch mode): `stock()` is the stock holding the cuts of the first
    /// `moves` moves; it is taken once for all the counts asked for up to `moves`.
    pub(crate) fn at_epoch_end(&mut self, moves: usize, stock: impl FnOnce() -> IShapes) {
        let due = self.marks[self.served..].partition_point(|&k| k <= moves);
        if !self.exact && due > 0 {
            self.served += due;
            self.out.push((moves, stock()));
        }
    }

    /// About how many bytes the snapshots taken hold.
    pub(crate) fn bytes(&self) -> u64 {
        let vertices: usize = self
            .out
            .iter()
            .flat_map(|(_, s)| s)
            .flatten()
            .map(Vec::len)
            .sum();
        (vertices * std::mem::size_of::<crate::overlay::IPt>()) as u64
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
