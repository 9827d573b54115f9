//! Sweeps: the area a tool outline covers during one move, as polygons on the grid.
//!
//! The sweep of a convex part along a straight move is the convex hull of the part at both
//! ends (a Minkowski sum with the move); arcs are chorded and their chords swept as one ring
//! ([`geom::flat::sweep_chain`]); thread moves stamp the outline once per lead
//! (`thread.rs`). Feeds merge into runs and paths (`run.rs`, with the bound on a merged
//! chain's error); repeated passes into one group ([`crate::pass_group`]); a thread pass or
//! a single feed that repeats an earlier one a little moved sweeps from where that run of
//! passes began (`repeat.rs`, the notches between passes bounded in `notch.rs`); `emit.rs`
//! folds, clips and stores what comes out.

mod emit;
mod notch;
mod repeat;
mod run;
mod thread;

use crate::mounted::{Mounted, Mounts};
use crate::overlay::{Grid, IBox, IPt};
use crate::pass_group::PassGroups;
use crate::tools::hint_key;
use crate::ToolTable;
use emit::Origin;
use expander::{Motion, Segment, ToolHint};
use geom::flat::P;
use geom::Rect;
use repeat::Repeats;
use run::Run;
use std::ops::Range;
use std::sync::atomic::AtomicU32;
use std::sync::Arc;
use thread::ThreadStamps;

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
    /// winding is the sweep (see [`geom::flat::sweep_chain`]); convexity shortcuts skip those.
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

    /// About how many bytes these sweeps hold.
    pub(crate) fn bytes(&self) -> u64 {
        let each = |n: usize, t: usize| (n * t) as u64;
        each(self.pts.len(), std::mem::size_of::<IPt>())
            + each(
                self.polys.len(),
                2 * std::mem::size_of::<IBox>() + 16 + 1 + 4,
            )
            + each(self.run_boxes.len(), std::mem::size_of::<IBox>())
            + each(self.items.len(), std::mem::size_of::<Item>())
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
    /// (see [`geom::flat::sweep_chain`]).
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
    scratch: Vec<P>,
    /// Where the stamps of a thread pass fall, carried from move to move.
    thread: ThreadStamps,
    /// Thread moves that repeat an earlier pass ([`repeat::Repeats`]).
    thread_runs: Repeats,
    /// Single straight feeds that repeat an earlier pass, in long programs.
    feed_runs: Repeats,
    /// Repeated passes merged into one sweep (see [`crate::pass_group`]); `None`: off.
    groups: Option<PassGroups>,
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
            scratch: Vec::new(),
            thread: ThreadStamps::default(),
            thread_runs: Repeats::default(),
            feed_runs: Repeats::default(),
            groups: None,
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
    /// hint) when a default stands in, at move `idx`, and once for the same words (a tool
    /// taken for a drill from its moves stands in under a grooving cycle's hint and without).
    fn edge(&mut self, t: u32, hint: ToolHint, idx: usize) -> Arc<Mounted> {
        let m = self.mounts.get(t, hint);
        if let Some(w) = &m.warning {
            let key = hint_key(t, hint);
            if !self.warned.contains(&key) {
                self.warned.push(key);
                if !self.warnings.iter().any(|(_, said)| said == w) {
                    self.warnings.push((idx, w.clone()));
                }
            }
        }
        m
    }

    /// Tool `t` under `hint` as mounted, when it has a body.
    fn with_body(&mut self, t: u32, hint: ToolHint) -> Option<Arc<Mounted>> {
        Some(self.mounts.get(t, hint)).filter(|m| m.body.is_some())
    }

    /// Adds segment number `idx`, followed by `next` (a thread move that the next one
    /// continues, its pull-out chamfer, is stamped as one pass with it): the sweep of its
    /// cutting outline, then the probe of its body (held while a merged run is open: it
    /// follows the run's sweep).
    pub(crate) fn push(&mut self, idx: usize, seg: &Segment, next: Option<&Segment>) {
        let body = self.with_body(seg.tool, seg.hint);
        if body.is_some() {
            // its probes must meet the stock the group's passes cut
            self.close_group();
        }
        if self.push_cut(idx, seg, thread::continued_by(seg, next)) {
            if let Some(body) = body.as_ref().and_then(|m| m.body.as_ref()) {
                self.hold_probe(idx, seg, body);
            } else {
                return;
            }
        }
        if self.run.is_none() {
            self.release_bodies();
        }
    }

    /// Adds the cutting sweep of segment number `idx` (`continues`: a thread pass the next
    /// move continues), swept where it was programmed and folded about the axis
    /// ([`crate::section`]); false when the move was skipped.
    fn push_cut(&mut self, idx: usize, seg: &Segment, continues: bool) -> bool {
        if !finite(seg) {
            self.flush_run();
            self.warnings.push((
                idx,
                "a move with a non-finite or absurdly large coordinate was skipped".into(),
            ));
            return false;
        }
        let flip = self.mounts.is_rear(seg.tool);
        let taken = if (seg.arc.is_none() || self.arc_as_chord(seg)) && seg.motion != Motion::Thread
        {
            self.push_straight(idx, seg, flip)
        } else if seg.motion == Motion::Feed {
            self.push_arc_feed(idx, seg, flip)
        } else {
            self.flush_run();
            false
        };
        if !taken {
            self.emit_move(idx, seg, continues);
        }
        true
    }

    /// Whether the arc feed `seg` joins chains as its chord: it lies within `chord_tol −
    /// merge_tol` of it.
    fn arc_as_chord(&self, seg: &Segment) -> bool {
        let arc_budget = self.tol - self.merge_tol;
        seg.arc.is_some()
            && seg.motion == Motion::Feed
            && self.merge_tol > 0.0
            && arc_budget > 0.0
            && seg.chord_count(arc_budget) == 1
    }

    /// Emits the sweep of move `idx` on its own: a thread's stamps (`continues`: the next
    /// move continues its pass), else the outline along the move.
    fn emit_move(&mut self, idx: usize, seg: &Segment, continues: bool) {
        let mounted = self.edge(seg.tool, seg.hint, idx);
        let outline = &mounted.edge;
        if seg.motion == Motion::Thread {
            let stamps = self
                .thread
                .stamps((idx, seg), self.tol, continues, &mut self.warnings);
            if let Some(stamps) = stamps {
                let key = hint_key(seg.tool, seg.hint);
                let accept = thread_step(&outline.parts, self.merge_tol);
                let first = self.thread_runs.repeats(key, &stamps, accept);
                let at = (&stamps[..], first.as_deref());
                self.emit_stamps(idx, outline, at, [seg.from.z, seg.from.r]);
                return;
            }
        }
        let path: Vec<P> = seg
            .polyline(self.tol)
            .iter()
            .map(|pt| [pt.z, pt.r])
            .collect();
        self.emit_path(Origin::of(idx, seg), outline, &path);
    }

    /// Ends the current merged run, emitting its sweep and then its moves' body probes.
    pub(crate) fn flush_run(&mut self) {
        self.emit_run();
        self.release_bodies();
    }

    /// Whether a merged run of feeds is still open (its sweep not yet emitted).
    pub(crate) fn has_open_run(&self) -> bool {
        self.run.is_some()
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

    /// How many sweeps are built so far, at a stop of the removal's batches: a pass group
    /// closes there, as at [`SweepBuilder::take`] (the current run, if any, stays open).
    pub(crate) fn count_at_stop(&mut self) -> usize {
        self.close_group();
        self.out.items.len()
    }

    /// Takes the sweeps built so far (the current run, if any, stays open; a pass group
    /// closes).
    pub(crate) fn take(&mut self) -> Sweeps {
        self.close_group();
        std::mem::take(&mut self.out)
    }
}

/// Which steps between a thread's passes (of a tool whose outline has the convex `parts`)
/// are swept as one ([`thread::ThreadStamps::repeats`]): up to `2·merge_tol` long (a step
/// of 0.001 mm: a G76's least depth of cut), filling notches at most `merge_tol / 5` deep
/// (10⁻⁴ mm by default; [`notch::notch_depth`]); none when `merge_tol` is 0. The last
/// step asked for is remembered: a pass's stamps all move alike.
fn thread_step(parts: &[Vec<P>], merge_tol: f64) -> impl FnMut(P) -> bool + '_ {
    let mut last: Option<(P, bool)> = None;
    move |w| {
        if let Some((_, ok)) = last.filter(|(seen, _)| *seen == w) {
            return ok;
        }
        // a step written as 0.002 mm on the diameter is 0.001 mm give or take 10⁻¹⁶
        let ok = merge_tol > 0.0
            && w[0].hypot(w[1]) <= 2.0 * merge_tol * (1.0 + 1e-9)
            && parts
                .iter()
                .all(|p| notch::notch_depth(p, w) <= merge_tol / 5.0);
        last = Some((w, ok));
        ok
    }
}

/// Whether every coordinate of the move is finite and not absurdly large (1 km and more).
fn finite(seg: &Segment) -> bool {
    let ok = |v: f64| v.is_finite() && v.abs() < 1e12;
    ok(seg.from.z)
        && ok(seg.from.r)
        && ok(seg.to.z)
        && ok(seg.to.r)
        && seg.arc.is_none_or(|a| ok(a.center.z) && ok(a.center.r))
}
