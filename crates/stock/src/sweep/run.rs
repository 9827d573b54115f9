//! Runs and paths of feeds.
//!
//! Consecutive collinear feeds that overlap (pecks re-cutting the same line) merge into one
//! sweep, exactly: the union of the sweeps of a convex part along two overlapping collinear
//! intervals is its sweep along their union. Consecutive feeds of a tool without a body
//! (each starting where the last ended) form a path, swept as one ring per convex part: the
//! convolution cycle of [`geom::flat::sweep_chain`], whose non-zero region is exactly the
//! Minkowski sum with the whole polyline. A path is bounded ([`MAX_PATH`] vertices, the
//! tool's outline size in length, [`MAX_TURN`] of turning) so that its ring stays small and
//! local: one ring instead of many hulls that overlap their neighbours, which the boolean
//! engine would have to split against each other.
//!
//! # Merging nearly collinear feeds (bounded error)
//!
//! A chain of short feeds (CAM output: 0.05 mm G01 moves along a curve) is merged into one
//! straight move from its first start to its last end while every programmed point in
//! between lies within `δ = merge_tol` (default 0.0005 mm, half the default chord
//! tolerance) of that chord, every move of the chain advances along the chord (a move that
//! turns back ends the run) and the chord is no longer than the tool's outline (so a merged
//! sweep is no bigger than the ones it replaces, and the tiles' air tests stay selective).
//! Rapids and threads are never merged and end the run; a rapid is only dropped when it lies
//! inside an *exact* run, so crash tests always see every rapid against the simulated stock.
//!
//! Why the error is at most `δ` (Hausdorff distance between the merged and the unmerged
//! union of sweeps, hence between the cut boundaries they leave): the sweep of a convex
//! part `A` along a path `C` is the Minkowski sum `A ⊕ C`, and the sweep of a non-convex
//! outline is the union of those of its convex parts. Let `P` be the chain (a polyline from
//! `a` to `b`) and `S = [a, b]` the chord. Every vertex of `P` is within `δ` of `S`, and the
//! `δ`-neighbourhood of a segment is convex, so all of `P` is within `δ` of `S`. Conversely,
//! every point `s` of `S` is within `δ` of `P`: `P` runs from one side of the line through `s`
//! perpendicular to `S` to the other, so it crosses that line, at a point within `δ` of the
//! chord's line, i.e. of `s`. So `H(P, S) ≤ δ`, and for any set `A`,
//! `H(A ⊕ P, A ⊕ S) ≤ H(P, S) ≤ δ` (move each path point by ≤ δ and the translated copy of
//! `A` moves by the same vector). A union of sets each moved by ≤ δ in Hausdorff distance
//! is moved by ≤ δ, so the removed region, and the boundary of the stock where it was cut,
//! move by at most `δ`; as with chording arcs, features thinner than `δ` may appear or
//! vanish there. The stock a later rapid is tested against is that merged stock, so a rapid
//! that retraces a merged chain can meet a sliver at most `δ` thick that the chain's true
//! sweep would have cut (a crash of area ≤ `δ` × its length in contact), or miss one as
//! thin; rapids away from the cut (retracts) cannot: the merged run ends at the same
//! programmed point. An arc whose single chord is within `chord_tol − δ` of it joins such
//! chains as that chord, so the total deviation stays within `chord_tol`.

use super::emit::Origin;
use super::SweepBuilder;
use expander::{Motion, Segment, ToolHint};
use geom::flat::{dist, P};
use std::sync::Arc;

/// Distance under which points count as on the same line when merging moves, mm.
const COLLINEAR_TOL: f64 = 1e-9;
/// Most programmed points one merged run of nearly collinear feeds may hold (each new move
/// re-checks them all, so this bounds the work per move).
const MAX_CHAIN: usize = 256;
/// Most vertices of a path of feeds swept as one ring.
const MAX_PATH: usize = 128;
/// Most total turning of a path of feeds swept as one ring, radians: a staircase of
/// 0.001 mm steps under G42 (`found/hostile-exit1`) made rings whose outline loops, one a
/// corner, all overlapped (minutes instead of 10 s).
const MAX_TURN: f64 = std::f64::consts::FRAC_PI_2;

/// A run of merged feeds swept as the one segment a -> b: either exact (collinear feeds,
/// `mid` empty) or a chain of nearly collinear feeds whose programmed points `mid` lie
/// within the merge tolerance of `[a, b]` (see the module documentation).
#[derive(Clone)]
pub(super) struct Run {
    pub(super) tool: u32,
    pub(super) hint: ToolHint,
    /// The outline is the table's mirror (see [`crate::section`]).
    pub(super) flip: bool,
    pub(super) a: P,
    pub(super) b: P,
    pub(super) last: usize,
    /// Programmed points strictly between `a` and `b` of a merged chain, in order.
    pub(super) mid: Vec<P>,
    /// Longest chord a chain may have: the size of the tool's outline, mm.
    pub(super) max_len: f64,
    /// Earlier vertices of a feed path swept as one ring with this run (see
    /// [`SweepBuilder::push_arc_feed`]): the path is `path`, then `a`, then `b`.
    pub(super) path: Vec<P>,
    /// Length of `path` up to `a`, mm.
    pub(super) path_len: f64,
    /// Total turning of the path up to `a` (radians): the ring inserts outline vertices at
    /// every turn, and the loops of sharp turns overlap each other.
    pub(super) turn: f64,
    /// A chain merged within the merge tolerance lies in `path` (not the programmed points).
    pub(super) approx: bool,
}

impl Run {
    /// Line parameters of p and q, when both lie on the run's line.
    fn params(&self, p: P, q: P) -> Option<(f64, f64, f64)> {
        let d = [self.b[0] - self.a[0], self.b[1] - self.a[1]];
        let len = d[0].hypot(d[1]);
        if len <= COLLINEAR_TOL {
            return None;
        }
        let u = [d[0] / len, d[1] / len];
        let off = |x: P| u[0] * (x[1] - self.a[1]) - u[1] * (x[0] - self.a[0]);
        let along = |x: P| u[0] * (x[0] - self.a[0]) + u[1] * (x[1] - self.a[1]);
        (off(p).abs() <= COLLINEAR_TOL && off(q).abs() <= COLLINEAR_TOL)
            .then(|| (along(p), along(q), len))
    }

    /// Extends the run by the feed p -> q when it is collinear and overlaps.
    fn try_extend(&mut self, p: P, q: P) -> bool {
        let near = |x: P, y: P| (x[0] - y[0]).hypot(x[1] - y[1]) <= COLLINEAR_TOL;
        if near(self.a, self.b) {
            // a run of one point merges with any move through that point's start
            if near(p, self.a) {
                (self.a, self.b) = (p, q);
                return true;
            }
            return false;
        }
        let Some((tp, tq, len)) = self.params(p, q) else {
            return false;
        };
        let (lo, hi) = (tp.min(tq), tp.max(tq));
        if lo > len + COLLINEAR_TOL || hi < -COLLINEAR_TOL {
            return false;
        }
        let u = [(self.b[0] - self.a[0]) / len, (self.b[1] - self.a[1]) / len];
        let (nlo, nhi) = (lo.min(0.0), hi.max(len));
        let a = self.a;
        self.a = [a[0] + u[0] * nlo, a[1] + u[1] * nlo];
        self.b = [a[0] + u[0] * nhi, a[1] + u[1] * nhi];
        true
    }

    /// Extends the run by the feed p -> q, which must start at the run's end, when the new
    /// chord `[a, q]` passes within `tol` of every programmed point of the chain (`mid` and
    /// the old end), every move advances along it, and it is no longer than `max_len`.
    /// An exact run counts as the single move `a -> b` (its sweep is that move's sweep).
    fn try_chain(&mut self, p: P, q: P, tol: f64) -> bool {
        let dist = |x: P, y: P| (x[0] - y[0]).hypot(x[1] - y[1]);
        if tol <= 0.0 || self.mid.len() >= MAX_CHAIN || dist(p, self.b) > COLLINEAR_TOL {
            return false;
        }
        let d = [q[0] - self.a[0], q[1] - self.a[1]];
        let len = d[0].hypot(d[1]);
        if !(len > COLLINEAR_TOL && len <= self.max_len) {
            return false;
        }
        // every move goes forward along the chord: no reversal inside a merged run
        let mut prev = self.a;
        for &x in self.mid.iter().chain([self.b, q].iter()) {
            if (x[0] - prev[0]) * d[0] + (x[1] - prev[1]) * d[1] <= 0.0 {
                return false;
            }
            prev = x;
        }
        // Every point projects strictly inside [a, q] (the test above), so its distance to
        // the chord is |cross| / len: no square root per point (`hypot` was a third of the
        // removal of 10⁶ contour-parallel moves).
        let (a, b) = (self.a, self.b);
        let limit = tol * len;
        let off = |x: &P| ((x[0] - a[0]) * d[1] - (x[1] - a[1]) * d[0]).abs();
        if self
            .mid
            .iter()
            .chain(std::iter::once(&b))
            .any(|x| off(x) > limit)
        {
            return false;
        }
        self.mid.push(b);
        self.b = q;
        true
    }

    /// True when the move p -> q lies within the run (its sweep is inside the run's sweep).
    fn contains(&self, p: P, q: P) -> bool {
        match self.params(p, q) {
            Some((tp, tq, len)) => {
                tp.min(tq) >= -COLLINEAR_TOL && tp.max(tq) <= len + COLLINEAR_TOL
            }
            None => {
                let near = |x: P| (x[0] - self.a[0]).hypot(x[1] - self.a[1]) <= COLLINEAR_TOL;
                near(self.b) && near(p) && near(q)
            }
        }
    }
}

/// The angle between two directions, radians (0 when either is zero).
fn angle(u: P, v: P) -> f64 {
    let cross = u[0] * v[1] - u[1] * v[0];
    let dot = u[0] * v[0] + u[1] * v[1];
    cross.abs().atan2(dot)
}

impl SweepBuilder<'_> {
    /// Takes the straight move `seg` (number `idx`, `flip`: a rear-post tool) into the runs:
    /// a feed merges with the open run, continues its path or opens a run of its own; a
    /// rapid inside an exact run's sweep is dropped. False when it is left to be emitted on
    /// its own (a rapid; the open run then ended).
    pub(super) fn push_straight(&mut self, idx: usize, seg: &Segment, flip: bool) -> bool {
        let (p, q) = ([seg.from.z, seg.from.r], [seg.to.z, seg.to.r]);
        let merge_tol = self.merge_tol;
        if let Some(run) = &mut self.run {
            if run.tool == seg.tool && run.hint == seg.hint && run.flip == flip {
                match seg.motion {
                    Motion::Feed
                        if (run.mid.is_empty() && run.try_extend(p, q))
                            || run.try_chain(p, q, merge_tol) =>
                    {
                        run.last = idx;
                        return true;
                    }
                    // inside the sweep of feeds just made: it meets no stock, removes
                    // nothing (only for exact runs: a merged chain is not the true sweep)
                    Motion::Rapid if run.mid.is_empty() && run.contains(p, q) => return true,
                    _ => {}
                }
            }
        }
        // a feed that goes on from where the run ended (same tool, no body to probe after
        // each move) continues one polyline path, swept as one ring
        let path = if seg.motion == Motion::Feed {
            self.continued_path(seg, flip, p, dist(p, q), ([q[0] - p[0], q[1] - p[1]], 0.0))
        } else {
            None
        };
        if path.is_none() {
            self.flush_run();
        }
        if seg.motion != Motion::Feed {
            return false;
        }
        self.open_run(seg, flip, idx, (p, q), path.unwrap_or_default());
        true
    }

    /// Takes the arc feed `seg` (number `idx`) into the runs: its chords join the open
    /// run's path (or start one), and it leaves a run of one point at its end for the feeds
    /// after it. False when it is left to be emitted on its own (no paths of feeds, or a
    /// tool with a body; the open run then ended).
    pub(super) fn push_arc_feed(&mut self, idx: usize, seg: &Segment, flip: bool) -> bool {
        let p = [seg.from.z, seg.from.r];
        let chords: Vec<P> = seg
            .polyline(self.tol)
            .iter()
            .map(|pt| [pt.z, pt.r])
            .collect();
        let arc_len = chords.windows(2).map(|w| dist(w[0], w[1])).sum();
        let dirs: Vec<P> = chords
            .windows(2)
            .map(|w| [w[1][0] - w[0][0], w[1][1] - w[0][1]])
            .collect();
        // an arc's equal chords each turn by the same angle: one atan2, not one a chord
        // (they were a tenth of a 10⁶-move G73's removal)
        let arc_turn = match dirs.as_slice() {
            [d0, d1, ..] => angle(*d0, *d1) * (dirs.len() - 1) as f64,
            _ => 0.0,
        };
        let first = dirs.first().copied().unwrap_or([0.0, 0.0]);
        let path = self
            .continued_path(seg, flip, p, arc_len, (first, arc_turn))
            .or_else(|| {
                self.flush_run();
                let starts = self.feed_paths && self.with_body(seg.tool, seg.hint).is_none();
                starts.then(|| (Vec::new(), 0.0, 0.0, false))
            });
        let Some((mut path, len, turn, approx)) = path else {
            return false;
        };
        for v in chords {
            if path.last() != Some(&v) {
                path.push(v);
            }
        }
        let Some(end) = path.pop() else {
            return false;
        };
        let so_far = (path, len + arc_len, turn + arc_turn, approx);
        self.open_run(seg, flip, idx, (end, end), so_far);
        if self
            .run
            .as_ref()
            .is_some_and(|r| r.path_len > r.max_len || r.turn > MAX_TURN)
        {
            self.flush_run(); // as long as the tool, or turning: no feed joins it
        }
        true
    }

    /// Opens a run of the feed `seg` along `a -> b`, after the path vertices `path`.
    fn open_run(
        &mut self,
        seg: &Segment,
        flip: bool,
        idx: usize,
        (a, b): (P, P),
        (path, path_len, turn, approx): (Vec<P>, f64, f64, bool),
    ) {
        let outline = Arc::clone(&self.edge(seg.tool, seg.hint, idx).edge);
        let max_len = outline
            .bbox()
            .map_or(0.0, |(lo, hi)| (hi[0] - lo[0]).max(hi[1] - lo[1]));
        self.run = Some(Run {
            tool: seg.tool,
            hint: seg.hint,
            flip,
            a,
            b,
            last: idx,
            mid: Vec::new(),
            max_len,
            path,
            path_len,
            turn,
            approx,
        });
    }

    /// When the feed `seg` (starting at `p`, `len` mm long) continues the open run's path:
    /// the run is taken and its path vertices up to `p` returned, with their length. Only
    /// for a tool without a body (a body's probe must see the stock right after its own
    /// move), up to [`MAX_PATH`] vertices and a path no longer than the tool's outline is
    /// wide (a ring has no separating-axis test: a long one would reach every tile along
    /// it, where the hulls of long moves are told apart from the stock one by one).
    fn continued_path(
        &mut self,
        seg: &Segment,
        flip: bool,
        p: P,
        len: f64,
        (first, inner_turn): (P, f64),
    ) -> Option<(Vec<P>, f64, f64, bool)> {
        let run = self.run.as_ref()?;
        let same = run.tool == seg.tool && run.hint == seg.hint && run.flip == flip;
        let near = dist(p, run.b) <= COLLINEAR_TOL;
        let path_len = run.path_len + dist(run.a, run.b);
        // the direction the path ends with: its last move, or the last chord of an arc
        let last = if dist(run.a, run.b) > COLLINEAR_TOL {
            Some([run.b[0] - run.a[0], run.b[1] - run.a[1]])
        } else {
            run.path.last().map(|v| [run.a[0] - v[0], run.a[1] - v[1]])
        };
        let turn = run.turn + last.map_or(0.0, |d| angle(d, first)) + inner_turn;
        if !self.feed_paths
            || !same
            || !near
            || run.path.len() + 2 > MAX_PATH
            || path_len + len > run.max_len
            || turn > MAX_TURN
        {
            return None;
        }
        if self.with_body(seg.tool, seg.hint).is_some() {
            return None;
        }
        let run = self.run.take()?;
        let approx = run.approx || !run.mid.is_empty();
        let mut path = run.path;
        for v in [run.a, run.b, p] {
            if path.last() != Some(&v) {
                path.push(v);
            }
        }
        path.pop(); // p is the new run's `a`
        Some((path, path_len, turn - inner_turn, approx))
    }

    /// Ends the current merged run, emitting its sweep (or giving it to the pass group).
    pub(super) fn emit_run(&mut self) {
        if let Some(mut run) = self.run.take() {
            let outline = Arc::clone(&self.edge(run.tool, run.hint, run.last).edge);
            for v in [run.a, run.b] {
                if run.path.last() != Some(&v) {
                    run.path.push(v);
                }
            }
            if run.path.len() == 1 {
                run.path.push(run.b);
            }
            let exact = !run.approx && run.mid.is_empty();
            if self.offer_to_group(exact, &outline, &run) {
                return;
            }
            if exact && !run.flip && self.emit_repeated_feed(&outline, &run) {
                return;
            }
            self.emit_path(Origin::cut(run.last), &outline, &run.path);
        }
    }
}
