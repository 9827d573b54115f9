//! Sweeps: the area a tool outline covers during one move, as convex polygons on the grid.
//!
//! The sweep of a convex part along a straight move is the convex hull of the part at both
//! ends (a Minkowski sum with the move); arcs are chorded and each chord swept; thread
//! moves stamp the outline once per lead. Consecutive collinear feeds that overlap (pecks
//! re-cutting the same line) merge into one sweep, exactly: the union of the sweeps of a
//! convex part along two overlapping collinear intervals is its sweep along their union.
//!
//! Consecutive feeds of a tool without a body (each starting where the last ended) form a
//! path, swept as one ring per convex part: the convolution cycle of [`sweep_chain`], whose
//! non-zero region is exactly the Minkowski sum with the whole polyline. A path is bounded
//! (128 vertices, the tool's outline size in length, 90° of turning) so that its ring stays
//! small and local: one ring instead of many hulls that overlap their neighbours, which
//! the boolean engine would have to split against each other.
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

use crate::mounted::{move_path, Mounted, Mounts};
use crate::outline::{Outline, PastAxis};
use crate::overlay::{inscribed_box, ring_perimeter, Grid, IBox, IPt};
use crate::pass_group::{Lane, Offer, PassGroups};
use crate::tools::hint_key;
use crate::{Shape, ToolTable};
use expander::{Motion, Segment, ToolHint};
use geom::flat::{bounds, clip_convex, dist, pts, sweep_chain, sweep_convex, P};
use geom::Rect;
use std::ops::Range;
use std::sync::atomic::AtomicU32;
use std::sync::Arc;

/// Most stamps one thread move may make before it is swept continuously instead, with a
/// warning (a real thread has a few hundred: 200 mm at 0.5 mm lead is 400; stamps that all
/// overlap their neighbours cost the boolean engine about k², so 4 000 took 10 s).
pub(crate) const MAX_THREAD_STAMPS: usize = 2_000;
/// Distance under which points count as on the same line when merging moves, mm.
const COLLINEAR_TOL: f64 = 1e-9;
/// Most programmed points one merged run of nearly collinear feeds may hold (each new move
/// re-checks them all, so this bounds the work per move).
const MAX_CHAIN: usize = 256;
/// Convex polygons of at least this many vertices get an inscribed box ([`Poly::core`]).
const CORE_FROM: usize = 8;
/// Most vertices of a path of feeds swept as one ring.
const MAX_PATH: usize = 128;
/// Most total turning of a path of feeds swept as one ring, radians: a staircase of
/// 0.001 mm steps under G42 (`found/hostile-exit1`) made rings whose outline loops, one a
/// corner, all overlapped (minutes instead of 10 s).
const MAX_TURN: f64 = std::f64::consts::FRAC_PI_2;

/// One unit of removal: the sweep of one move (or of a merged run of collinear feeds).
#[derive(Debug, Clone)]
pub(crate) struct Item {
    /// Index of the (last) segment this sweep comes from.
    pub(crate) seg: usize,
    /// A rapid: its overlap with the stock is a crash.
    pub(crate) rapid: bool,
    /// The sweep of a tool's non-cutting body (named): a probe that never removes
    /// material; any overlap with the stock is a crash.
    pub(crate) body: Option<&'static str>,
    /// Its polygons, indices into [`Sweeps::polys`].
    pub(crate) polys: Range<u32>,
    /// The polygons a rapid's crash test reads, when not `polys` (empty): a rapid between
    /// the passes of a group is carved by what they cut ([`crate::pass_group`]) but cuts
    /// its whole sweep, so that no sliver is left between its pieces and the group's sweep.
    pub(crate) probe: Range<u32>,
    /// Bounding box of all its polygons.
    pub(crate) bbox: IBox,
    /// Reference point at the start of the move (for the crash contact point).
    pub(crate) start: P,
    /// Overlap area above which a rapid is a crash, mm².
    pub(crate) eps: f64,
    /// Unit direction of the move (zero for a stamp set), to measure a rapid cut's depth
    /// normal to it.
    pub(crate) dir: P,
}

/// A list of sweeps with their polygons stored flat.
#[derive(Debug, Default)]
pub(crate) struct Sweeps {
    pts: Vec<IPt>,
    polys: Vec<Range<u32>>,
    /// Per polygon: convex (a hull or a stamp), else a chain sweep's ring whose positive
    /// winding is the sweep (see [`sweep_chain`]); convexity shortcuts skip those.
    convex: Vec<bool>,
    /// Per polygon: its run boxes in `run_boxes` (a ring's, see [`crate::ring_air`]; none for a
    /// convex polygon).
    runs: Vec<Range<u32>>,
    run_boxes: Vec<IBox>,
    /// Per polygon: its bounding box.
    boxes: Vec<IBox>,
    /// Per polygon: a box inside it ([`Poly::core`]).
    cores: Vec<IBox>,
    /// Per polygon: the edge that last told it apart from a box ([`Poly::hint`]).
    hints: Vec<AtomicU32>,
    /// The sweeps, in program order.
    pub(crate) items: Vec<Item>,
}

impl Sweeps {
    /// Appends the sweeps of `other` after these.
    fn append(&mut self, other: Self) {
        let (dp, dq) = (self.pts.len() as u32, self.polys.len() as u32);
        let db = self.run_boxes.len() as u32;
        self.pts.extend(other.pts);
        self.polys
            .extend(other.polys.into_iter().map(|r| r.start + dp..r.end + dp));
        self.convex.extend(other.convex);
        self.runs
            .extend(other.runs.into_iter().map(|r| r.start + db..r.end + db));
        self.run_boxes.extend(other.run_boxes);
        self.boxes.extend(other.boxes);
        self.cores.extend(other.cores);
        self.hints.extend(other.hints);
        self.items.extend(other.items.into_iter().map(|mut it| {
            it.polys = it.polys.start + dq..it.polys.end + dq;
            if !it.probe.is_empty() {
                it.probe = it.probe.start + dq..it.probe.end + dq;
            }
            it
        }));
    }

    /// The polygons of one item.
    pub(crate) fn polys_of(&self, it: &Item) -> impl Iterator<Item = &[IPt]> + Clone {
        self.polys[it.polys.start as usize..it.polys.end as usize]
            .iter()
            .map(|r| &self.pts[r.start as usize..r.end as usize])
    }

    /// The polygons of one item with what the air tests know of each ([`Poly`]).
    pub(crate) fn parts_of(&self, it: &Item) -> impl Iterator<Item = Poly<'_>> + Clone {
        self.parts_in(it.polys.clone())
    }

    /// The polygons a rapid's crash test reads ([`Item::probe`]).
    pub(crate) fn probe_parts_of(&self, it: &Item) -> impl Iterator<Item = Poly<'_>> + Clone {
        self.parts_in(if it.probe.is_empty() {
            it.polys.clone()
        } else {
            it.probe.clone()
        })
    }

    fn parts_in(&self, polys: Range<u32>) -> impl Iterator<Item = Poly<'_>> + Clone {
        (polys.start as usize..polys.end as usize).map(|k| {
            let (p, b) = (&self.polys[k], &self.runs[k]);
            Poly {
                pts: &self.pts[p.start as usize..p.end as usize],
                convex: self.convex[k],
                runs: &self.run_boxes[b.start as usize..b.end as usize],
                bbox: self.boxes[k],
                core: self.cores[k],
                hint: &self.hints[k],
            }
        })
    }
}

/// One polygon of a sweep, as the removal's tests read it.
#[derive(Clone, Copy)]
pub(crate) struct Poly<'a> {
    /// Its vertices.
    pub(crate) pts: &'a [IPt],
    /// A hull or a stamp; else a chain sweep's ring whose positive winding is the sweep
    /// (see [`sweep_chain`]).
    pub(crate) convex: bool,
    /// A ring's run boxes ([`crate::ring_air`]; none for a convex polygon).
    pub(crate) runs: &'a [IBox],
    /// Its bounding box.
    pub(crate) bbox: IBox,
    /// A large box inside a convex polygon ([`inscribed_box`]; EMPTY for a ring): a tile's
    /// stock box that meets it meets the sweep, and what it holds the sweep covers, both
    /// without an edge test (a long pass meets the boxes of every tile along its bottom).
    pub(crate) core: IBox,
    /// The edge of a convex polygon that last had a box wholly outside it: a sweep meets
    /// the boxes of a tile tree in order, and neighbouring boxes are mostly told apart by
    /// the same edge, so this one is tried first. Only a hint (any value is safe), shared by
    /// the threads that walk the strips.
    pub(crate) hint: &'a AtomicU32,
}

/// A run of merged feeds swept as the one segment a -> b: either exact (collinear feeds,
/// `mid` empty) or a chain of nearly collinear feeds whose programmed points `mid` lie
/// within the merge tolerance of `[a, b]` (see the module documentation).
#[derive(Clone)]
struct Run {
    tool: u32,
    hint: ToolHint,
    /// The outline is the table's mirror (see [`crate::section`]).
    flip: bool,
    a: P,
    b: P,
    last: usize,
    /// Programmed points strictly between `a` and `b` of a merged chain, in order.
    mid: Vec<P>,
    /// Longest chord a chain may have: the size of the tool's outline, mm.
    max_len: f64,
    /// Earlier vertices of a feed path swept as one ring with this run (see
    /// [`SweepBuilder::push_cut`]): the path is `path`, then `a`, then `b`.
    path: Vec<P>,
    /// Length of `path` up to `a`, mm.
    path_len: f64,
    /// Total turning of the path up to `a` (radians): the ring inserts outline vertices at
    /// every turn, and the loops of sharp turns overlap each other.
    turn: f64,
    /// A chain merged within the merge tolerance lies in `path` (not the programmed points).
    approx: bool,
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

/// Turns segments into sweeps on the grid, in order.
pub(crate) struct SweepBuilder<'a> {
    grid: &'a Grid,
    clip: Rect,
    /// Each move's tool as mounted.
    mounts: Mounts<'a>,
    /// The tools (and hints) whose defaulted outline was warned of.
    warned: Vec<(u32, u8, u64)>,
    tol: f64,
    /// Largest deviation of a merged chain of feeds from the programmed points, mm (0: only
    /// exact merging).
    merge_tol: f64,
    /// Sweep consecutive feeds as one path (see [`crate::SimOptions::feed_paths`]).
    feed_paths: bool,
    run: Option<Run>,
    /// Body sweeps of the moves of the open run: emitted after the run's own sweep, so
    /// that they meet the stock as it is after the cut.
    held: Sweeps,
    /// The segment being pushed runs below the axis.
    below: bool,
    scratch: Vec<P>,
    /// The segment being pushed is a thread move whose pass the next one continues (a
    /// pull-out chamfer): no stamp at its end, the next one's stamps go on a lead apart.
    next_continues: bool,
    /// After such a move: where it ended and where the next stamp falls from there, as a
    /// fraction of the lead.
    thread_carry: Option<(P, f64)>,
    /// Repeated passes merged into one sweep (see [`crate::pass_group`]); `None`: off.
    groups: Option<PassGroups>,
    /// The polygons added now get no core: a carved rapid's whole sweep, which is cut only
    /// where its pieces meet stock (rarely), and whose core cost the builder 20 %.
    coreless: bool,
    /// (first segment index, message) for skipped moves and defaulted tools.
    pub(crate) warnings: Vec<(usize, String)>,
    /// The sweeps built so far.
    pub(crate) out: Sweeps,
}

impl<'a> SweepBuilder<'a> {
    /// A builder that clips sweeps to `clip` (which must lie inside the grid's rectangle),
    /// chording arcs within `chord_tol` and merging chains of feeds within `merge_tol`
    /// (at most `chord_tol`; 0 merges only exactly collinear feeds).
    pub(crate) fn new(
        grid: &'a Grid,
        clip: Rect,
        tools: &'a ToolTable,
        chord_tol: f64,
        merge_tol: f64,
    ) -> Self {
        Self {
            grid,
            clip,
            mounts: Mounts::new(tools, Vec::new()),
            warned: Vec::new(),
            tol: chord_tol,
            merge_tol: merge_tol.clamp(0.0, chord_tol),
            feed_paths: true,
            run: None,
            held: Sweeps::default(),
            below: false,
            scratch: Vec::new(),
            next_continues: false,
            thread_carry: None,
            groups: None,
            coreless: false,
            warnings: Vec::new(),
            out: Sweeps::default(),
        }
    }

    /// Whether consecutive feeds are swept as one path ([`crate::SimOptions::feed_paths`]).
    pub(crate) fn set_feed_paths(&mut self, on: bool) {
        self.feed_paths = on;
    }

    /// Whether repeated passes are merged into one sweep ([`crate::pass_group`]; only with
    /// a merge tolerance, their step's limit).
    pub(crate) fn set_pass_groups(&mut self, on: bool) {
        self.groups = (on && self.merge_tol > 0.0).then(|| PassGroups::new(self.merge_tol));
    }

    /// Tools on a rear post ([`crate::section::rear_tools`]).
    pub(crate) fn set_rear(&mut self, rear: Vec<u32>) {
        self.mounts = Mounts::new(self.mounts.tools(), rear);
    }

    /// Tool `t` under `hint` as mounted, for its cutting outline: warns once per tool (and
    /// hint) when a default stands in, at move `idx`.
    fn edge(&mut self, t: u32, hint: ToolHint, idx: usize) -> Arc<Mounted> {
        let m = self.mounts.get(t, hint);
        if let Some(w) = &m.warning {
            let key = hint_key(t, hint);
            if !self.warned.contains(&key) {
                self.warned.push(key);
                self.warnings.push((idx, w.clone()));
            }
        }
        m
    }

    /// Tool `t` under `hint` as mounted, when it has a body.
    fn with_body(&mut self, t: u32, hint: ToolHint) -> Option<Arc<Mounted>> {
        Some(self.mounts.get(t, hint)).filter(|m| m.body.is_some())
    }

    /// [`SweepBuilder::push`], told the segment after it: a thread move that the next one
    /// continues (its pull-out chamfer, one pass) is stamped as one pass with it.
    pub(crate) fn push_before(&mut self, idx: usize, seg: &Segment, next: Option<&Segment>) {
        self.next_continues = seg.motion == Motion::Thread
            && next
                .is_some_and(|n| n.motion == Motion::Thread && n.arc.is_none() && n.from == seg.to);
        self.push(idx, seg);
        self.next_continues = false;
    }

    /// Adds segment number `idx`: the sweep of its cutting outline, then the probe of its
    /// body (held while a merged run is open: it follows the run's sweep).
    pub(crate) fn push(&mut self, idx: usize, seg: &Segment) {
        let body = self.with_body(seg.tool, seg.hint);
        if body.is_some() {
            // its probes must meet the stock the group's passes cut
            self.close_group();
        }
        if self.push_cut(idx, seg) {
            let Some(body) = body.as_ref().and_then(|m| m.body.as_ref()) else {
                return;
            };
            let path = move_path(seg, self.tol);
            let done = std::mem::take(&mut self.out);
            // swept and measured like a rapid (convex hulls, the crash rule's depth), then
            // marked as the body's probe
            self.emit_path(idx, true, &body.outline, &path);
            if let Some(it) = self.out.items.last_mut() {
                it.rapid = false;
                it.body = Some(body.name);
            }
            let probe = std::mem::replace(&mut self.out, done);
            self.held.append(probe);
        }
        if self.run.is_none() {
            self.release_bodies();
        }
    }

    /// Emits the held body probes.
    fn release_bodies(&mut self) {
        if !self.held.items.is_empty() {
            let held = std::mem::take(&mut self.held);
            self.out.append(held);
        }
    }

    /// Adds the cutting sweep of segment number `idx`, swept where it was programmed and
    /// folded about the axis ([`crate::section`]); false when the move was skipped.
    fn push_cut(&mut self, idx: usize, seg: &Segment) -> bool {
        let flip = self.mounts.is_rear(seg.tool);
        // a rapid measured in the section: mirrored when it runs below the axis
        self.below = seg.from.r + seg.to.r < 0.0;
        let finite = |v: f64| v.is_finite() && v.abs() < 1e12;
        let arc_ok = seg
            .arc
            .is_none_or(|a| finite(a.center.z) && finite(a.center.r));
        if !(finite(seg.from.z)
            && finite(seg.from.r)
            && finite(seg.to.z)
            && finite(seg.to.r)
            && arc_ok)
        {
            self.flush_run();
            self.warnings.push((
                idx,
                "a move with a non-finite or absurdly large coordinate was skipped".into(),
            ));
            return false;
        }
        let (p, q) = ([seg.from.z, seg.from.r], [seg.to.z, seg.to.r]);
        // an arc feed whose chord is within chord_tol - merge_tol of it joins chains as a chord
        let arc_budget = self.tol - self.merge_tol;
        let arc_as_chord = seg.arc.is_some()
            && seg.motion == Motion::Feed
            && self.merge_tol > 0.0
            && arc_budget > 0.0
            && seg.chord_count(arc_budget) == 1;
        if (seg.arc.is_none() || arc_as_chord) && seg.motion != Motion::Thread {
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
            // a feed that goes on from where the run ended (same tool, no body to probe
            // after each move) continues one polyline path, swept as one ring
            let path = if seg.motion == Motion::Feed {
                self.continued_path(seg, flip, p, dist(p, q), ([q[0] - p[0], q[1] - p[1]], 0.0))
            } else {
                None
            };
            if path.is_none() {
                self.flush_run();
            }
            if seg.motion == Motion::Feed {
                self.open_run(seg, flip, idx, (p, q), path.unwrap_or_default());
                return true;
            }
        } else {
            // an arc feed joins the path (or starts one) with its chords, and leaves a run
            // of one point at its end for the feeds after it
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
            let path = if seg.motion == Motion::Feed {
                self.continued_path(seg, flip, p, arc_len, (first, arc_turn))
            } else {
                None
            };
            let path = path.or_else(|| {
                self.flush_run();
                let starts = seg.motion == Motion::Feed
                    && seg.arc.is_some()
                    && self.feed_paths
                    && self.with_body(seg.tool, seg.hint).is_none();
                starts.then(|| (Vec::new(), 0.0, 0.0, false))
            });
            if let Some((mut path, len, turn, approx)) = path {
                for v in chords {
                    if path.last() != Some(&v) {
                        path.push(v);
                    }
                }
                if let Some(end) = path.pop() {
                    self.open_run(
                        seg,
                        flip,
                        idx,
                        (end, end),
                        (path, len + arc_len, turn + arc_turn, approx),
                    );
                    if self
                        .run
                        .as_ref()
                        .is_some_and(|r| r.path_len > r.max_len || r.turn > MAX_TURN)
                    {
                        self.flush_run(); // as long as the tool, or turning: no feed joins it
                    }
                    return true;
                }
            }
        }
        let mounted = self.edge(seg.tool, seg.hint, idx);
        let outline = &mounted.edge;
        let rapid = seg.motion == Motion::Rapid;
        if seg.motion == Motion::Thread {
            if let Some(stamps) = self.thread_stamps(idx, seg) {
                self.emit_stamps(idx, outline, &stamps, p);
                return true;
            }
        }
        let path: Vec<P> = seg
            .polyline(self.tol)
            .iter()
            .map(|pt| [pt.z, pt.r])
            .collect();
        self.emit_path(idx, rapid, outline, &path);
        true
    }

    /// Positions of the outline for a thread move: every lead from the start, and the end;
    /// `None` (with a warning) when the move must be swept continuously instead. A pass of
    /// several moves (a thread and its pull-out chamfer) is one pass: stamps every lead
    /// along all of it, at its start and its end only (the section sees the tool once a
    /// lead, also on the chamfer; the joint is no place it stops).
    fn thread_stamps(&mut self, idx: usize, seg: &Segment) -> Option<Vec<P>> {
        let (p, q) = ([seg.from.z, seg.from.r], [seg.to.z, seg.to.r]);
        let carried = self.thread_carry.take().filter(|(at, _)| *at == p);
        if seg.arc.is_some() {
            self.warnings
                .push((idx, "circular thread move: swept continuously".into()));
            return None;
        }
        // the lead is measured along the dominant axis (Z for straight and taper threads)
        let len = (q[0] - p[0]).abs().max((q[1] - p[1]).abs());
        if !(seg.lead.is_finite() && seg.lead > 0.0) {
            self.warnings.push((
                idx,
                format!("thread move with lead {}: swept continuously", seg.lead),
            ));
            return None;
        }
        if seg.lead <= self.tol {
            // The notches between stamps a lead apart are about lead·cot(flank angle) deep:
            // below the chord tolerance for any thread tool (flank half-angle ≥ 27°), so
            // the continuous sweep is the stamped section within the tolerance.
            self.warnings.push((
                idx,
                format!(
                    "thread lead {} mm is not more than the chord tolerance {} mm: swept continuously",
                    seg.lead, self.tol
                ),
            ));
            return None;
        }
        let n = (len / seg.lead).floor();
        if n > MAX_THREAD_STAMPS as f64 {
            self.warnings.push((
                idx,
                format!(
                    "thread move of {n} leads (more than {MAX_THREAD_STAMPS}): swept continuously"
                ),
            ));
            return None;
        }
        // The tool passes the section plane once a lead, shifted by the start angle
        // (multi-start Q): at from + (phase + k)·lead along the move; the start and end
        // points are where the tool enters and leaves the thread.
        let phase = carried.map_or(seg.thread_phase.rem_euclid(1.0), |(_, f)| f);
        let at = |s: f64| {
            let t = if len > 0.0 { s / len } else { 0.0 };
            [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
        };
        let mut pts: Vec<P> = Vec::new();
        if carried.is_none() {
            pts.push(p);
        }
        pts.extend(
            (0..=n as usize + 1)
                .map(|k| (phase + k as f64) * seg.lead)
                .filter(|&s| (s > 0.0 || (carried.is_some() && s >= 0.0)) && s < len)
                .map(at),
        );
        if self.next_continues {
            // the first stamp at or past the end, counted from there
            let k = (len / seg.lead - phase).ceil().max(0.0);
            self.thread_carry = Some((q, (phase + k - len / seg.lead).clamp(0.0, 1.0)));
        } else {
            pts.push(q);
        }
        Some(pts)
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

    /// Ends the current merged run, emitting its sweep and then its moves' body probes.
    pub(crate) fn flush_run(&mut self) {
        self.emit_run();
        self.release_bodies();
    }

    /// Ends the current merged run, emitting its sweep.
    fn emit_run(&mut self) {
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
            self.emit_path(run.last, false, &outline, &run.path);
        }
    }

    /// Offers a run's path to the pass groups: true when the open group took it; else the
    /// group, if it closed, has been emitted.
    fn offer_to_group(&mut self, exact: bool, outline: &Arc<Outline>, run: &Run) -> bool {
        if self.groups.is_none() {
            return false;
        }
        if !exact || self.with_body(run.tool, run.hint).is_some() {
            self.close_group();
            return false;
        }
        let Some(groups) = self.groups.as_mut() else {
            return false;
        };
        match groups.offer(outline, &run.path, run.last) {
            Offer::Absorbed => true,
            Offer::Emit(closed) => {
                if let Some(lanes) = closed {
                    self.emit_group(lanes);
                }
                false
            }
        }
    }

    /// Ends the open pass group, emitting its sweep.
    fn close_group(&mut self) {
        if let Some(lanes) = self.groups.as_mut().and_then(PassGroups::close) {
            self.emit_group(lanes);
        }
    }

    /// One sweep for a closed group's lanes, as a move of its last segment.
    fn emit_group(&mut self, lanes: Vec<Lane>) {
        let item = self.begin();
        let mut seg = 0;
        let start = lanes.first().map_or([0.0, 0.0], |l| l.first[0]);
        for lane in lanes {
            seg = seg.max(lane.seg);
            let (polys, convex) = lane.sweep();
            for p in &polys {
                self.add(p, convex, lane.outline.past_axis);
            }
        }
        self.end(item, seg, false, start, [0.0, 0.0]);
    }

    /// Emits a rapid's straight sweep with the open group's regions carved out of it (see
    /// [`crate::pass_group`]); false, emitting nothing, when it cannot be carved.
    fn emit_carved(&mut self, idx: usize, outline: &Outline, path: &[P]) -> bool {
        let (a, b) = (path[0], path[1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let clip = self.clip;
        let Some(groups) = self.groups.as_mut() else {
            return false;
        };
        let (mut whole, mut pieces) = (Vec::new(), Vec::new());
        for part in &outline.parts {
            let placed: Vec<P> = part.iter().map(|v| [v[0] + a[0], v[1] + a[1]]).collect();
            let poly = sweep_convex(&placed, d);
            let reach = bounds(&poly);
            if reach.min.r < 0.0 {
                return false;
            }
            if !reach.intersects(&clip) {
                continue;
            }
            // only its part inside the clip box is kept anyway: fewer pieces to carve
            let inside = clip.contains(reach.min) && clip.contains(reach.max);
            let poly = if inside {
                poly
            } else {
                clip_convex(&poly, &clip)
            };
            if poly.len() < 3 {
                continue;
            }
            match groups.carve(&poly) {
                Some(p) => pieces.extend(p),
                None => return false,
            }
            whole.push(poly);
        }
        if pieces.is_empty() {
            // wholly inside what the group cut: air, and the group's sweep cuts it
            return true;
        }
        // it cuts its whole sweep (the group's sweep would cut the rest, but pieces cut
        // apart from it leave slivers of a grid step between them) and is tested for a
        // crash with its pieces
        let item = self.begin();
        self.coreless = true;
        for p in &whole {
            self.add_poly(p, outline.past_axis);
        }
        self.coreless = false;
        let cut = self.out.polys.len() as u32;
        for p in &pieces {
            self.add_poly(p, outline.past_axis);
        }
        let len = d[0].hypot(d[1]);
        let dir = if len > 0.0 {
            [d[0] / len, d[1] / len]
        } else {
            [0.0, 0.0]
        };
        let count = self.out.items.len();
        self.end(item, idx, true, a, dir);
        if let Some(it) = self.out.items.get_mut(count) {
            if cut < it.polys.end {
                it.probe = cut..it.polys.end;
                it.polys = it.polys.start..cut;
            } else {
                // the pieces were all slivers the clipping dropped: no crash to find
                it.rapid = false;
            }
        }
        true
    }

    /// Whether a merged run of feeds is still open (its sweep not yet emitted).
    pub(crate) fn has_open_run(&self) -> bool {
        self.run.is_some()
    }

    /// Number of sweeps emitted since the last [`SweepBuilder::take`].
    pub(crate) fn emitted(&self) -> usize {
        self.out.items.len()
    }

    /// The sweep of the current merged run as [`SweepBuilder::flush_run`] would emit it,
    /// without ending the run (for snapshots part-way through).
    pub(crate) fn peek_run(&mut self) -> Sweeps {
        let Some(run) = self.run.clone() else {
            return Sweeps::default();
        };
        let done = std::mem::take(&mut self.out);
        let groups = self.groups.take();
        self.emit_run();
        self.groups = groups;
        self.run = Some(run);
        std::mem::replace(&mut self.out, done)
    }

    fn emit_path(&mut self, idx: usize, rapid: bool, outline: &Outline, path: &[P]) {
        if self.groups.as_ref().is_some_and(PassGroups::is_open) {
            if rapid && path.len() == 2 && self.emit_carved(idx, outline, path) {
                return;
            }
            self.close_group();
        }
        let start = path[0];
        let item = self.begin();
        if path.len() > 2 {
            // a chorded arc (a feed, or a body probed along one): one ring per convex part
            // instead of a hull per chord
            for part in &outline.parts {
                let ring = sweep_chain(part, path);
                self.add_ring(&ring, outline.past_axis);
            }
        } else {
            self.emit_hulls(outline, path);
        }
        let end = path[path.len() - 1];
        let (dz, dr) = (end[0] - start[0], end[1] - start[1]);
        let len = dz.hypot(dr);
        let dir = if len > 0.0 {
            [dz / len, dr / len]
        } else {
            [0.0, 0.0]
        };
        self.end(item, idx, rapid, start, dir);
    }

    /// The hull of each convex part along each straight piece of `path`.
    fn emit_hulls(&mut self, outline: &Outline, path: &[P]) {
        for w in path.windows(2) {
            let d = [w[1][0] - w[0][0], w[1][1] - w[0][1]];
            for part in &outline.parts {
                self.scratch.clear();
                self.scratch
                    .extend(part.iter().map(|v| [v[0] + w[0][0], v[1] + w[0][1]]));
                let poly = sweep_convex(&self.scratch, d);
                self.add_poly(&poly, outline.past_axis);
            }
        }
    }

    fn emit_stamps(&mut self, idx: usize, outline: &Outline, at: &[P], start: P) {
        self.close_group();
        let item = self.begin();
        for p in at {
            for part in &outline.parts {
                let poly: Vec<P> = part.iter().map(|v| [v[0] + p[0], v[1] + p[1]]).collect();
                self.add_poly(&poly, outline.past_axis);
            }
        }
        self.end(item, idx, false, start, [0.0, 0.0]);
    }

    fn begin(&self) -> (u32, f64) {
        (self.out.polys.len() as u32, 0.0)
    }

    /// Adds a convex polygon.
    fn add_poly(&mut self, poly: &[P], past: PastAxis) {
        self.add(poly, true, past);
    }

    /// Adds a chain sweep's ring (not convex; clipping keeps the winding number of every
    /// point inside the clip box, which is all the non-zero fill reads).
    fn add_ring(&mut self, ring: &[P], past: PastAxis) {
        self.add(ring, false, past);
    }

    /// Adds a polygon folded into the section (its part below the axis mirrored, or left
    /// out for an outline whose size is assumed: `past`; the clipping keeps a ring's
    /// winding numbers, so chain rings fold like hulls).
    fn add(&mut self, poly: &[P], convex: bool, past: PastAxis) {
        if poly.iter().any(|p| p[1] < 0.0) {
            for part in crate::section::fold(poly, past) {
                self.add_section_poly(&part, convex);
            }
        } else {
            self.add_section_poly(poly, convex);
        }
    }

    fn add_section_poly(&mut self, poly: &[P], convex: bool) {
        let quick = bounds(poly);
        let inside = self.clip.contains(quick.min) && self.clip.contains(quick.max);
        let clipped;
        let poly = if inside {
            poly
        } else {
            if quick.max.z < self.clip.min.z
                || quick.min.z > self.clip.max.z
                || quick.max.r < self.clip.min.r
                || quick.min.r > self.clip.max.r
            {
                return;
            }
            clipped = clip_convex(poly, &self.clip);
            &clipped[..]
        };
        if poly.len() < 3 {
            return;
        }
        let start = self.out.pts.len() as u32;
        let grid = self.grid;
        self.out.pts.extend(poly.iter().map(|&p| grid.to_int(p)));
        self.out.polys.push(start..self.out.pts.len() as u32);
        self.out.convex.push(convex);
        let b = self.out.run_boxes.len() as u32;
        if !convex {
            crate::ring_air::run_boxes(&self.out.pts[start as usize..], &mut self.out.run_boxes);
        }
        self.out.runs.push(b..self.out.run_boxes.len() as u32);
        let added = &self.out.pts[start as usize..];
        self.out.boxes.push(IBox::of(added.iter().copied()));
        // a core saves edge tests: a polygon of a few edges (a blade's peck) has few to save,
        // and its core would cost more than they (wobble 10⁵: +7 % instructions)
        self.out
            .cores
            .push(if convex && added.len() >= CORE_FROM && !self.coreless {
                inscribed_box(added)
            } else {
                IBox::EMPTY
            });
        self.out.hints.push(AtomicU32::new(0));
    }

    fn end(&mut self, (first, _): (u32, f64), idx: usize, rapid: bool, start: P, dir: P) {
        let last = self.out.polys.len() as u32;
        if last == first {
            return; // wholly outside the envelope: air
        }
        // a rapid's contact point and normal as the section sees them
        let (start, dir) = if rapid && self.below {
            ([start[0], -start[1]], [dir[0], -dir[1]])
        } else {
            (start, dir)
        };
        let mut bbox = IBox::EMPTY;
        let mut perimeter = 0.0;
        for r in &self.out.polys[first as usize..last as usize] {
            let ring = &self.out.pts[r.start as usize..r.end as usize];
            for &p in ring {
                bbox.add(p);
            }
            perimeter += ring_perimeter(ring);
        }
        perimeter *= self.grid.step();
        // rounding to the grid can open slivers of at most a grid step along any edge
        let eps = crate::CRASH_MIN_AREA.max(2.0 * self.grid.step() * perimeter);
        self.out.items.push(Item {
            seg: idx,
            rapid,
            body: None,
            polys: first..last,
            probe: 0..0,
            bbox,
            start,
            eps,
            dir,
        });
    }

    /// Removes `pieces` (section shapes) from the stock as a sweep of move `idx` that cuts
    /// nothing anyone reports: pieces a part-off separated from the held bar have fallen,
    /// and later moves through their place meet air.
    pub(crate) fn erase(&mut self, idx: usize, pieces: &[Shape]) {
        self.close_group();
        let item = self.begin();
        for s in pieces {
            // counter-clockwise, so that its winding is positive (what the removal reads)
            let mut ring = s.outer.clone();
            if geom::ring::signed_area(&pts(&ring)) < 0.0 {
                ring.reverse();
            }
            self.add_ring(&ring, PastAxis::Fold);
        }
        let start = pieces
            .first()
            .and_then(|s| s.outer.first().copied())
            .unwrap_or_default();
        self.end(item, idx, false, start, [0.0, 0.0]);
    }

    /// Takes the sweeps built so far (the current run, if any, stays open; a pass group
    /// closes).
    pub(crate) fn take(&mut self) -> Sweeps {
        self.close_group();
        std::mem::take(&mut self.out)
    }
}
