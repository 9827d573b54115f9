//! Emission: sweeps swept along paths, stamped, carved or grouped, folded into the section,
//! clipped to the envelope and stored on the grid with what the removal's tests read.

use super::run::Run;
use super::{Item, SweepBuilder};
use crate::outline::{Outline, PastAxis};
use crate::overlay::{inscribed_box, ring_perimeter, IBox};
use crate::pass_group::{Lane, Offer, PassGroups};
use crate::Shape;
use expander::{Motion, Segment};
use geom::flat::{bounds, clip_convex, minkowski, pts, sweep_chain, sweep_convex, P};
use std::sync::atomic::AtomicU32;
use std::sync::Arc;

/// Convex polygons of at least this many vertices get an inscribed box ([`super::Poly::core`]).
const CORE_FROM: usize = 8;

/// Polygons in mm.
type Polygons = Vec<Vec<P>>;

/// The move a sweep comes from, as the removal reads it.
#[derive(Clone, Copy)]
pub(super) struct Origin {
    /// The move's index.
    idx: usize,
    /// A rapid (or a body's probe, measured like one): its overlap with the stock is a crash.
    rapid: bool,
    /// It runs below the axis: its contact point and normal are mirrored into the section.
    below: bool,
}

impl Origin {
    /// A cut of move `idx` (no crash test of its own).
    pub(super) fn cut(idx: usize) -> Self {
        Self {
            idx,
            rapid: false,
            below: false,
        }
    }

    /// Move `idx`, `seg`: a crash test when `seg` is a rapid.
    pub(super) fn of(idx: usize, seg: &Segment) -> Self {
        Self {
            rapid: seg.motion == Motion::Rapid,
            ..Self::probe(idx, seg)
        }
    }

    /// A probe along move `idx`, `seg`, measured like a rapid.
    pub(super) fn probe(idx: usize, seg: &Segment) -> Self {
        Self {
            idx,
            rapid: true,
            below: seg.from.r + seg.to.r < 0.0,
        }
    }
}

/// What a polygon added to the sweeps is.
#[derive(Clone, Copy, PartialEq)]
enum PolyKind {
    /// Convex (a hull or a stamp), with an inscribed box when it has many vertices.
    Hull,
    /// Convex, without an inscribed box: a carved rapid's whole sweep, which is cut only
    /// where its pieces meet stock (rarely), and whose box cost the builder 20 %.
    BareHull,
    /// A chain sweep's ring, whose positive winding is the sweep (see [`sweep_chain`]).
    Ring,
}

impl SweepBuilder<'_> {
    /// Emits the probe of move `idx`'s `body` along it, held until the open run's sweep is
    /// out (it must meet the stock as it is after the cut).
    pub(super) fn hold_probe(&mut self, idx: usize, seg: &Segment, body: &crate::Body) {
        let path = crate::mounted::move_path(seg, self.tol);
        let done = std::mem::take(&mut self.out);
        // swept and measured like a rapid (convex hulls, the crash rule's depth), then
        // marked as the body's probe
        self.emit_path(Origin::probe(idx, seg), &body.outline, &path);
        if let Some(it) = self.out.items.last_mut() {
            it.rapid = false;
            it.body = Some(body.name);
        }
        let probe = std::mem::replace(&mut self.out, done);
        self.held.append(probe);
    }

    /// Emits the held body probes.
    pub(super) fn release_bodies(&mut self) {
        if !self.held.items.is_empty() {
            let held = std::mem::take(&mut self.held);
            self.out.append(held);
        }
    }

    /// The sweep of `outline` along `path`: one ring per convex part for a chorded path,
    /// hulls for a straight move; a rapid across an open pass group is carved by it.
    pub(super) fn emit_path(&mut self, from: Origin, outline: &Outline, path: &[P]) {
        if self.groups.as_ref().is_some_and(PassGroups::is_open) {
            if from.rapid && path.len() == 2 && self.emit_carved(from, outline, path) {
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
                self.add(&ring, PolyKind::Ring, outline.past_axis);
            }
        } else {
            self.emit_hulls(outline, path);
        }
        let end = path[path.len() - 1];
        self.end(
            item,
            from,
            start,
            unit([end[0] - start[0], end[1] - start[1]]),
        );
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
                self.add(&poly, PolyKind::Hull, outline.past_axis);
            }
        }
    }

    /// The outline stamped at each of `at`, one sweep of move `idx` (a thread pass). When
    /// the move repeats earlier passes whose run began at `first` (see
    /// [`super::thread::ThreadStamps::repeats`]), each stamp is swept from there instead:
    /// `outline ⊕ [first, at]`, the region the run's stamps cover with the notches between
    /// them filled (a chorded nose moved by 0.0005 mm leaves a notch of 10⁻⁵ mm on each
    /// flank, every pass: thousands of vertices for the tiles to split on), within
    /// `merge_tol / 5` of them (see `thread_step`). Each pass's sweep then covers the one
    /// before it, so a tile keeps one of them in its batch, not one boolean call every two
    /// passes.
    pub(super) fn emit_stamps(
        &mut self,
        idx: usize,
        outline: &Outline,
        (at, first): (&[P], Option<&[P]>),
        start: P,
    ) {
        self.close_group();
        let item = self.begin();
        for (i, p) in at.iter().enumerate() {
            for part in &outline.parts {
                let moved = |at: P| -> Vec<P> {
                    part.iter().map(|v| [v[0] + at[0], v[1] + at[1]]).collect()
                };
                let poly: Vec<P> = match first {
                    Some(first) => {
                        let from = first[i];
                        sweep_convex(&moved(from), [p[0] - from[0], p[1] - from[1]])
                    }
                    None => moved(*p),
                };
                self.add(&poly, PolyKind::Hull, outline.past_axis);
            }
        }
        self.end(item, Origin::cut(idx), start, [0.0, 0.0]);
    }

    /// The sweep of a straight feed (move `idx`, from `start` along `dir`) that repeats
    /// earlier passes: the outline's convex parts swept over the convex `region` the
    /// passes' segments rule (see [`super::repeat`]), one convex polygon each.
    pub(super) fn emit_ruled(&mut self, idx: usize, outline: &Outline, region: &[P], dir: (P, P)) {
        self.close_group();
        let item = self.begin();
        for part in &outline.parts {
            self.add(&minkowski(part, region), PolyKind::Hull, outline.past_axis);
        }
        self.end(item, Origin::cut(idx), dir.0, dir.1);
    }

    /// Offers a run's path to the pass groups: true when the open group took it; else the
    /// group, if it closed, has been emitted.
    pub(super) fn offer_to_group(
        &mut self,
        exact: bool,
        outline: &Arc<Outline>,
        run: &Run,
    ) -> bool {
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
    pub(super) fn close_group(&mut self) {
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
            let kind = if convex {
                PolyKind::Hull
            } else {
                PolyKind::Ring
            };
            for p in &polys {
                self.add(p, kind, lane.outline.past_axis);
            }
        }
        self.end(item, Origin::cut(seg), start, [0.0, 0.0]);
    }

    /// Emits a rapid's straight sweep with the open group's regions carved out of it (see
    /// [`crate::pass_group`]); false, emitting nothing, when it cannot be carved.
    fn emit_carved(&mut self, from: Origin, outline: &Outline, path: &[P]) -> bool {
        let (a, b) = (path[0], path[1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let Some((whole, pieces)) = self.carve(outline, a, d) else {
            return false;
        };
        if pieces.is_empty() {
            // wholly inside what the group cut: air, and the group's sweep cuts it
            return true;
        }
        // it cuts its whole sweep (the group's sweep would cut the rest, but pieces cut
        // apart from it leave slivers of a grid step between them) and is tested for a
        // crash with its pieces
        let item = self.begin();
        for p in &whole {
            self.add(p, PolyKind::BareHull, outline.past_axis);
        }
        let cut = self.out.polys.len() as u32;
        for p in &pieces {
            self.add(p, PolyKind::Hull, outline.past_axis);
        }
        let count = self.out.items.len();
        self.end(item, from, a, unit(d));
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

    /// The sweep of each convex part of `outline` from `a` along `d`, clipped to the clip
    /// box, and its pieces outside the open group's regions; `None` when it cannot be
    /// carved (it reaches below the axis, or falls into too many pieces).
    fn carve(&self, outline: &Outline, a: P, d: P) -> Option<(Polygons, Polygons)> {
        let clip = self.clip;
        let groups = self.groups.as_ref()?;
        let (mut whole, mut pieces) = (Vec::new(), Vec::new());
        for part in &outline.parts {
            let placed: Vec<P> = part.iter().map(|v| [v[0] + a[0], v[1] + a[1]]).collect();
            let poly = sweep_convex(&placed, d);
            let reach = bounds(&poly);
            if reach.min.r < 0.0 {
                return None;
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
            pieces.extend(groups.carve(&poly)?);
            whole.push(poly);
        }
        Some((whole, pieces))
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
            self.add(&ring, PolyKind::Ring, PastAxis::Fold);
        }
        let start = pieces
            .first()
            .and_then(|s| s.outer.first().copied())
            .unwrap_or_default();
        self.end(item, Origin::cut(idx), start, [0.0, 0.0]);
    }

    /// Where the next sweep's polygons start.
    fn begin(&self) -> u32 {
        self.out.polys.len() as u32
    }

    /// Adds a polygon folded into the section (its part below the axis mirrored, or left
    /// out for an outline whose size is assumed: `past`; the clipping keeps a ring's
    /// winding numbers, so chain rings fold like hulls).
    fn add(&mut self, poly: &[P], kind: PolyKind, past: PastAxis) {
        if poly.iter().any(|p| p[1] < 0.0) {
            for part in crate::section::fold(poly, past) {
                self.add_section_poly(&part, kind);
            }
        } else {
            self.add_section_poly(poly, kind);
        }
    }

    /// Adds a polygon of the section, clipped to the envelope, with its boxes.
    fn add_section_poly(&mut self, poly: &[P], kind: PolyKind) {
        let quick = bounds(poly);
        let clip = &self.clip;
        let inside = clip.contains(quick.min) && clip.contains(quick.max);
        let clipped;
        let poly = if inside {
            poly
        } else {
            if quick.max.z < clip.min.z
                || quick.min.z > clip.max.z
                || quick.max.r < clip.min.r
                || quick.min.r > clip.max.r
            {
                return;
            }
            clipped = clip_convex(poly, clip);
            &clipped[..]
        };
        if poly.len() < 3 {
            return;
        }
        let convex = kind != PolyKind::Ring;
        let out = &mut self.out;
        let start = out.pts.len() as u32;
        let grid = self.grid;
        out.pts.extend(poly.iter().map(|&p| grid.to_int(p)));
        out.polys.push(start..out.pts.len() as u32);
        out.convex.push(convex);
        let b = out.run_boxes.len() as u32;
        if !convex {
            crate::ring_air::run_boxes(&out.pts[start as usize..], &mut out.run_boxes);
        }
        out.runs.push(b..out.run_boxes.len() as u32);
        let added = &out.pts[start as usize..];
        out.boxes.push(IBox::of(added.iter().copied()));
        // a core saves edge tests: a polygon of a few edges (a blade's peck) has few to save,
        // and its core would cost more than they (wobble 10⁵: +7 % instructions)
        out.cores
            .push(if kind == PolyKind::Hull && added.len() >= CORE_FROM {
                inscribed_box(added)
            } else {
                IBox::EMPTY
            });
        out.hints.push(AtomicU32::new(0));
    }

    /// Ends the sweep whose polygons start at `first`, as a move `from` starting at `start`
    /// in the direction `dir`; nothing when it has no polygon (wholly outside the envelope:
    /// air).
    fn end(&mut self, first: u32, from: Origin, start: P, dir: P) {
        let last = self.out.polys.len() as u32;
        if last == first {
            return;
        }
        // a rapid's contact point and normal as the section sees them
        let (start, dir) = if from.rapid && from.below {
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
            seg: from.idx,
            rapid: from.rapid,
            body: None,
            polys: first..last,
            probe: 0..0,
            bbox,
            start,
            eps,
            dir,
        });
    }
}

/// The unit vector of `d` (zero for a zero vector).
pub(super) fn unit(d: P) -> P {
    let len = d[0].hypot(d[1]);
    if len > 0.0 {
        [d[0] / len, d[1] / len]
    } else {
        [0.0, 0.0]
    }
}
