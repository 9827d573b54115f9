//! Stock snapshots part-way through a removal run, taken in the run's one pass.
//!
//! The removal itself works in epochs over tiles and batches its cuts; cutting at the
//! snapshot counts inside it would change where batches end and so the last bits of the
//! final part. Up to [`EXACT_MAX_MOVES`] moves, snapshots therefore keep their own copy of
//! the stock and cut into it the same sweeps, in order, stopping at each count asked for
//! (the intended shapes read the stock exactly where a cycle began). That doubles the
//! cutting, so longer programs get their snapshots at the removal's own epoch ends instead,
//! where every tile is flushed: the union of the tiles' stock, at the first epoch end at or
//! after each count asked for, labelled with the moves it holds.

/// Longest program whose snapshots are taken exactly at their counts.
pub const EXACT_MAX_MOVES: usize = 5_000;

use crate::overlay::{Engine, IShapes};
use crate::sweep::{SweepBuilder, Sweeps};

/// The snapshot counts still to come, the snapshot stock and the snapshots taken.
pub(crate) struct Snapshots {
    /// Exact at the counts (a second cut), or at epoch ends.
    exact: bool,
    marks: std::iter::Peekable<std::vec::IntoIter<usize>>,
    stock: IShapes,
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
            reached: Vec::new(),
            out: Vec::new(),
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

    /// Called with the sweeps the builder emitted this epoch: cuts them into the snapshot
    /// stock and takes the snapshots reached.
    pub(crate) fn epoch(&mut self, sweeps: &Sweeps, engine: &mut Engine) {
        if !self.exact {
            return;
        }
        let mut applied = 0;
        for (k, emitted, open) in std::mem::take(&mut self.reached) {
            self.cut(sweeps, applied..emitted, engine);
            applied = emitted;
            let snap = if open.items.is_empty() {
                self.stock.clone()
            } else {
                let polys = open
                    .items
                    .iter()
                    .filter(|it| it.body.is_none())
                    .flat_map(|it| open.polys_of(it));
                engine.difference(&self.stock, polys)
            };
            self.out.push((k, snap));
        }
        if self.marks.peek().is_some() {
            self.cut(sweeps, applied..sweeps.items.len(), engine);
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
        let vertices: usize = std::iter::once(&self.stock)
            .chain(self.out.iter().map(|(_, s)| s))
            .flatten()
            .flatten()
            .map(Vec::len)
            .sum();
        (vertices * std::mem::size_of::<crate::overlay::IPt>()) as u64
    }

    fn cut(&mut self, sweeps: &Sweeps, items: std::ops::Range<usize>, engine: &mut Engine) {
        if items.is_empty() {
            return;
        }
        let polys = sweeps.items[items]
            .iter()
            .filter(|it| it.body.is_none())
            .flat_map(|it| sweeps.polys_of(it));
        self.stock = engine.difference(&self.stock, polys);
    }
}
