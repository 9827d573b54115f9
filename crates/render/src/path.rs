//! SVG path data in mm, written by hand (f64, enough decimals for sub-micron detail),
//! thinned to what the picture can show.

use foldhash::{HashSet, HashSetExt};
use std::fmt::Write as _;
use std::hash::BuildHasher as _;

use crate::report::{PathKind, PathLine, Shape};
use crate::scale::Bbox;
use crate::text::num;

/// Points closer than this (px) to the previous kept point are dropped.
pub(crate) const MIN_PX: f64 = 0.3;

/// Decimals for shape coordinates (mm): 1 nm.
const SHAPE_DECIMALS: usize = 6;
/// Decimals for toolpath coordinates (mm): 0.1 µm, sub-micron and compact.
const PATH_DECIMALS: usize = 4;

fn dist2(a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dz, dr) = (a[0] - b[0], a[1] - b[1]);
    dz * dz + dr * dr
}

fn finite(p: &[f64; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// A ring's finite points, dropping those within `md` (mm) of the previous kept one (and,
/// as the closing edge may also be tiny, trailing ones within `md` of the first).
pub(crate) fn thin_ring(pts: &[[f64; 2]], md: f64) -> Vec<[f64; 2]> {
    let md2 = md * md;
    let mut kept: Vec<[f64; 2]> = Vec::with_capacity(pts.len().min(4096));
    for p in pts.iter().filter(|p| finite(p)) {
        match kept.last() {
            Some(l) if dist2(*l, *p) <= md2 => {}
            _ => kept.push(*p),
        }
    }
    while kept.len() > 3 && dist2(kept[0], kept[kept.len() - 1]) <= md2 {
        kept.pop();
    }
    if md > 0.0 && kept.len() > COLLAPSE_RUN {
        kept = collapse_runs(&kept, md, 0);
        kept = collapse_runs(&kept, md, 1);
    }
    kept
}

/// A run of more consecutive points than this in one column is collapsed.
const COLLAPSE_RUN: usize = 4;

/// Min/max decimation (as for waveforms): where more than [`COLLAPSE_RUN`] consecutive
/// points fall in one column `md` wide across `axis` (0: columns of equal z, 1: rows of equal
/// r) and the run turns back along the column, only the run's first, lowest, highest and
/// last points are kept, in path order (a monotone run — an arc near its tangent — is left
/// as it is, so ordinary parts draw exactly as before). The
/// run's edges stay inside the column, so the path crosses every level between its lowest
/// and highest point there: every dropped point is within `md` of the kept path and every
/// kept edge within `md` of the dropped ones. A sawtooth of 50 000 sub-pixel teeth becomes
/// four points a column, drawn the same (a band filled and stroked top to bottom).
fn collapse_runs(pts: &[[f64; 2]], md: f64, axis: usize) -> Vec<[f64; 2]> {
    let other = 1 - axis;
    let column = |p: &[f64; 2]| (p[axis] / md).floor();
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(pts.len());
    let mut i = 0;
    while i < pts.len() {
        let c = column(&pts[i]);
        let mut j = i + 1;
        while j < pts.len() && column(&pts[j]) == c {
            j += 1;
        }
        let run = &pts[i..j];
        let monotone = |up: bool| {
            run.windows(2)
                .all(|w| (w[1][other] >= w[0][other]) == up || w[1][other] == w[0][other])
        };
        if run.len() > COLLAPSE_RUN && !monotone(true) && !monotone(false) {
            let (mut lo, mut hi) = (0, 0);
            for (k, p) in run.iter().enumerate() {
                if p[other] < run[lo][other] {
                    lo = k;
                }
                if p[other] > run[hi][other] {
                    hi = k;
                }
            }
            let mut keep = [0, lo, hi, run.len() - 1];
            keep.sort_unstable();
            for (n, &k) in keep.iter().enumerate() {
                if n == 0 || k != keep[n - 1] {
                    out.push(run[k]);
                }
            }
        } else {
            out.extend_from_slice(run);
        }
        i = j;
    }
    out
}

fn push_pt(d: &mut String, cmd: char, p: [f64; 2], decimals: usize) {
    // Writing to a String cannot fail.
    let _ = write!(d, "{cmd}{},{}", num(p[0], decimals), num(p[1], decimals));
}

/// Append one closed ring, dropping vertices closer than `min_dist` (mm) to the previous
/// kept one; rings that collapse below three vertices are smaller than a pixel and skipped.
fn ring(d: &mut String, pts: &[[f64; 2]], min_dist: f64) {
    ring_or(d, pts, min_dist, false);
}

/// [`ring`]; with `keep_tiny`, a ring that collapses is written unthinned instead of
/// skipped (a gouge or leftover smaller than a pixel must still show as a dot).
fn ring_or(d: &mut String, pts: &[[f64; 2]], min_dist: f64, keep_tiny: bool) {
    let kept = thin_ring(pts, min_dist);
    if kept.len() < 3 {
        if keep_tiny {
            let all: Vec<[f64; 2]> = pts.iter().copied().filter(finite).collect();
            if all.len() >= 3 {
                for (i, p) in all.iter().enumerate() {
                    push_pt(d, if i == 0 { 'M' } else { 'L' }, *p, SHAPE_DECIMALS);
                }
                d.push('Z');
            }
        }
        return;
    }
    for (i, p) in kept.iter().enumerate() {
        push_pt(d, if i == 0 { 'M' } else { 'L' }, *p, SHAPE_DECIMALS);
    }
    d.push('Z');
}

/// Path data for shapes with holes (draw with `fill-rule="evenodd"`).
pub(crate) fn shapes_d(shapes: &[Shape], min_dist: f64) -> String {
    let mut d = String::new();
    for s in shapes {
        ring(&mut d, &s.outer, min_dist);
        for h in &s.holes {
            ring(&mut d, h, min_dist);
        }
    }
    d
}

/// Path data for gouges or leftovers: as [`shapes_d`], but an outer ring smaller than
/// `min_dist` is kept (unthinned) rather than dropped, so its outline shows as a dot.
pub(crate) fn deviation_d(shapes: &[Shape], min_dist: f64) -> String {
    let mut d = String::new();
    for s in shapes {
        ring_or(&mut d, &s.outer, min_dist, true);
        for h in &s.holes {
            ring(&mut d, h, min_dist);
        }
    }
    d
}

/// The toolpath as one path per kind, thinned.
#[derive(Debug, Default)]
pub(crate) struct ToolpathD {
    /// Path data of rapids.
    pub(crate) rapid: String,
    /// Path data of feeds.
    pub(crate) feed: String,
    /// Path data of threading moves.
    pub(crate) thread: String,
    /// Points written in total.
    pub(crate) points: usize,
    /// 1 when every distinct segment was drawn; k when only every k-th was.
    pub(crate) stride: usize,
}

impl ToolpathD {
    /// Whether whole segments were dropped to respect the point cap.
    pub(crate) fn thinned(&self) -> bool {
        self.stride > 1
    }
}

/// One kind's path data, simplified as it is written: a run of points is drawn as one
/// straight line from its first point (the anchor) while every point of the run lies within
/// `md` of that line (the line's direction stays in the cone each point allows, the
/// intersection of which is `window`), and points within `md` of the anchor are dropped. One
/// pass, constant work a point: 50 passes of a 2 000-move roughing at 0.45 px a move drew
/// 54 050 points, stroked point by point by the PNG's rasteriser.
#[derive(Default)]
struct KindWriter {
    d: String,
    /// The last point written or pending: the start of the current run.
    anchor: Option<[f64; 2]>,
    /// A subpath start not yet written: only flushed once a line follows it.
    pending_move: Option<[f64; 2]>,
    /// The run's last point, not yet written: where its line ends so far.
    tail: Option<[f64; 2]>,
    /// Direction (rad) of the run's first point from the anchor; `window` is relative to it.
    base: f64,
    /// The directions from the anchor within which the line keeps every run point within
    /// `md`: the intersection of the points' cones.
    window: (f64, f64),
    /// The run's farthest distance from the anchor (a run turning back ends).
    reach: f64,
    points: usize,
    /// Write the path text; else only count the points it would have.
    write: bool,
}

impl KindWriter {
    /// Adds a move's points (`md`: the tolerance, mm): a move starting away from where the
    /// path stands (or after a non-finite point) starts a new subpath.
    fn line(&mut self, pts: &[[f64; 2]], md: f64) {
        for (i, p) in pts.iter().enumerate() {
            if !finite(p) {
                self.end_subpath();
                continue;
            }
            let at = self.tail.or(self.anchor);
            let near = at.is_some_and(|l| dist2(l, *p) <= md * md);
            if i == 0 && !near {
                // Discontinuous start: begin a new subpath lazily.
                self.end_subpath();
                self.pending_move = Some(*p);
                self.anchor = Some(*p);
            } else if !near {
                self.extend(*p, md);
            }
        }
    }

    /// Takes `p` into the run when the run's line can reach it and still pass within `md`
    /// of every point before; else writes the run's line and starts the next run at its end.
    fn extend(&mut self, p: [f64; 2], md: f64) {
        let Some(a) = self.anchor else {
            self.pending_move = Some(p);
            self.anchor = Some(p);
            return;
        };
        let d = dist2(a, p).sqrt();
        if d <= md {
            return;
        }
        let theta = (p[1] - a[1]).atan2(p[0] - a[0]);
        let w = (md / d).asin();
        if self.tail.is_none() {
            (self.base, self.window, self.reach) = (theta, (-w, w), d);
            self.tail = Some(p);
            return;
        }
        let rel = wrap(theta - self.base);
        if rel >= self.window.0 && rel <= self.window.1 && d >= self.reach - md {
            self.window = (self.window.0.max(rel - w), self.window.1.min(rel + w));
            self.reach = self.reach.max(d);
            self.tail = Some(p);
            return;
        }
        self.write_tail();
        self.extend(p, md);
    }

    /// Writes the run's line to its last point, which becomes the next run's anchor.
    fn write_tail(&mut self) {
        let Some(t) = self.tail.take() else {
            return;
        };
        if let Some(m) = self.pending_move.take() {
            if self.write {
                push_pt(&mut self.d, 'M', m, PATH_DECIMALS);
            }
            self.points += 1;
        }
        if self.write {
            push_pt(&mut self.d, 'L', t, PATH_DECIMALS);
        }
        self.points += 1;
        self.anchor = Some(t);
    }

    /// Ends the current subpath: its last run is written.
    fn end_subpath(&mut self) {
        self.write_tail();
        self.anchor = None;
        self.pending_move = None;
    }
}

/// An angle difference brought into (−π, π].
fn wrap(a: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    if a > PI {
        a - TAU
    } else if a <= -PI {
        a + TAU
    } else {
        a
    }
}

type Key = (u8, [i64; 6]);

/// Quantised identity of a segment: its kind, first, middle and last points on a grid of
/// `grid` mm, direction-independent, so re-cut moves (pecks, spring passes) draw once.
fn key(l: &PathLine, grid: f64) -> Option<Key> {
    let n = l.points.len();
    let q = |p: [f64; 2]| -> Option<[i64; 2]> {
        let a = (p[0] / grid).round();
        let b = (p[1] / grid).round();
        (a.is_finite() && b.is_finite() && a.abs() < 9e15 && b.abs() < 9e15)
            .then_some([a as i64, b as i64])
    };
    let a = q(*l.points.first()?)?;
    let m = q(l.points[n / 2])?;
    let b = q(l.points[n - 1])?;
    let (a, b) = if a <= b { (a, b) } else { (b, a) };
    let kind = match l.kind {
        PathKind::Rapid => 0,
        PathKind::Feed => 1,
        PathKind::Thread => 2,
    };
    Some((kind, [a[0], a[1], m[0], m[1], b[0], b[1]]))
}

/// The segments a view draws: those touching `window`, each re-cut move (same kind and
/// quantised points, see [`key`]) once. Independent of the stride, so found once.
fn candidates<'a>(lines: &'a [PathLine], min_dist: f64, window: &Bbox) -> Vec<&'a PathLine> {
    // the keys' 64-bit hashes stand for them (8 bytes a move instead of 56: a table of 10⁵
    // keys was 10 % of a 10⁵-move report); two moves whose hashes meet by chance (about
    // n² / 2⁶⁵: 3·10⁻¹⁰ for 10⁵ moves) would draw once
    let state = foldhash::fast::FixedState::with_seed(0);
    let mut seen: HashSet<u64> = HashSet::with_capacity(lines.len());
    lines
        .iter()
        .filter(|l| {
            if l.points.is_empty() {
                return false;
            }
            let mut b = Bbox::EMPTY;
            for p in l.points.iter() {
                b.add(*p);
            }
            b.overlaps(window) && key(l, min_dist).is_none_or(|k| seen.insert(state.hash_one(k)))
        })
        .collect()
}

/// Every `stride`-th candidate, thinned; only counted unless `write` (the path text of a
/// million moves is written once, for the stride finally chosen).
fn one_pass(cands: &[&PathLine], min_dist: f64, stride: usize, write: bool) -> ToolpathD {
    let mut w: [KindWriter; 3] = Default::default();
    for k in &mut w {
        k.write = write;
    }
    for l in cands.iter().step_by(stride) {
        let i = match l.kind {
            PathKind::Rapid => 0,
            PathKind::Feed => 1,
            PathKind::Thread => 2,
        };
        w[i].line(&l.points, min_dist);
    }
    for k in &mut w {
        k.end_subpath();
    }
    let [r, f, t] = w;
    ToolpathD {
        points: r.points + f.points + t.points,
        rapid: r.d,
        feed: f.d,
        thread: t.d,
        stride,
    }
}

/// Thin the toolpath for a view: only segments touching `window` (mm), duplicates drawn
/// once, each kind's path simplified so that every point lies within about `min_dist` (mm)
/// of the drawn line ([`KindWriter`]), and at most about `cap` points: beyond that only
/// every k-th segment is drawn.
pub(crate) fn toolpath_d(
    lines: &[PathLine],
    min_dist: f64,
    window: &Bbox,
    cap: usize,
) -> ToolpathD {
    let min_dist = if min_dist.is_finite() && min_dist > 0.0 {
        min_dist
    } else {
        1e-6
    };
    let cands = candidates(lines, min_dist, window);
    // drawn at once when that is likely to fit (simplified, the moves rarely give more
    // points than there are moves), else counted first
    if cands.len() <= cap {
        let all = one_pass(&cands, min_dist, 1, true);
        if all.points <= cap {
            return all;
        }
    }
    let mut stride = 1;
    let mut points = one_pass(&cands, min_dist, stride, false).points;
    let mut tries = 0;
    while points > cap && tries < 40 {
        let ratio = points as f64 / cap.max(1) as f64;
        stride = ((stride as f64 * ratio).ceil() as usize).max(stride + 1);
        points = one_pass(&cands, min_dist, stride, false).points;
        tries += 1;
    }
    one_pass(&cands, min_dist, stride, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(kind: PathKind, pts: &[[f64; 2]]) -> PathLine {
        PathLine {
            kind,
            line: 1,
            points: pts.to_vec().into(),
        }
    }

    #[test]
    fn consecutive_moves_merge_and_tiny_steps_drop() {
        let lines = vec![
            line(PathKind::Feed, &[[0.0, 10.0], [-1.0, 10.0]]),
            line(PathKind::Feed, &[[-1.0, 10.0], [-1.001, 10.0]]),
            line(PathKind::Feed, &[[-1.001, 10.0], [-5.0, 10.0]]),
            line(PathKind::Rapid, &[[-5.0, 10.0], [-5.0, 20.0]]),
        ];
        let w = Bbox::new(-100.0, 100.0, -100.0, 100.0);
        let t = toolpath_d(&lines, 0.01, &w, 1000);
        // the three feeds lie on one line: drawn as one
        assert_eq!(t.feed, "M0,10L-5,10");
        assert_eq!(t.rapid, "M-5,10L-5,20");
        assert_eq!(t.points, 4);
        assert!(!t.thinned());
    }

    #[test]
    fn repeated_moves_draw_once_and_cap_holds() {
        let mut lines = Vec::new();
        for i in 0..10_000 {
            let z = -(i as f64) * 0.5;
            lines.push(line(PathKind::Feed, &[[z, 20.0], [z, 10.0]]));
            lines.push(line(PathKind::Rapid, &[[z, 10.0], [z, 20.0]]));
            lines.push(line(PathKind::Feed, &[[z, 20.0], [z, 10.0]]));
        }
        let w = Bbox::new(-1e4, 1e4, -1e4, 1e4);
        let t = toolpath_d(&lines, 0.01, &w, 1_000);
        assert!(t.points <= 1_000, "{}", t.points);
        assert!(t.thinned());
    }

    /// Distance from `p` to the polyline `line`.
    fn to_polyline(p: [f64; 2], line: &[[f64; 2]]) -> f64 {
        line.windows(2)
            .map(|w| seg_dist(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min)
    }

    /// The points of one subpath of path data `M…L…`.
    fn parse_d(d: &str) -> Vec<[f64; 2]> {
        d.split(['M', 'L'])
            .filter(|t| !t.is_empty())
            .map(|t| {
                let (z, r) = t.split_once(',').unwrap();
                [z.parse().unwrap(), r.parse().unwrap()]
            })
            .collect()
    }

    /// 50 roughing passes of 2 000 feeds 0.05 mm long along a wave (R ≥ 5 mm), drawn at
    /// 0.03 mm a point: each pass keeps a few dozen points instead of a thousand, every
    /// programmed point lies within 1.5 × 0.03 mm of the drawn line and every drawn point
    /// on the path, and the corners where a pass starts and ends are kept.
    #[test]
    fn smooth_passes_draw_with_few_points_within_the_tolerance() {
        let md = 0.03;
        let profile = |z: f64, k: usize| 30.0 + k as f64 * 0.3 + 2.0 * (z / 5.0).sin();
        let mut lines = Vec::new();
        let mut all = Vec::new();
        for k in 0..50 {
            let pts: Vec<[f64; 2]> = (0..=2000)
                .map(|i| {
                    let z = -0.05 * i as f64;
                    [z, profile(z, k)]
                })
                .collect();
            for w in pts.windows(2) {
                lines.push(line(PathKind::Feed, w));
            }
            all.push(pts);
        }
        let w = Bbox::new(-1e3, 1e3, -1e3, 1e3);
        let t = toolpath_d(&lines, md, &w, 1_000_000);
        let subpaths: Vec<Vec<[f64; 2]>> = t
            .feed
            .split('M')
            .filter(|s| !s.is_empty())
            .map(parse_d)
            .collect();
        assert_eq!(subpaths.len(), 50);
        assert!(t.points < 50 * 80, "{} points", t.points);
        for (drawn, pts) in subpaths.iter().zip(&all) {
            assert_eq!(drawn[0], pts[0]);
            assert!(dist2(drawn[drawn.len() - 1], pts[2000]).sqrt() <= md);
            let worst = pts
                .iter()
                .map(|p| to_polyline(*p, drawn))
                .fold(0.0, f64::max);
            assert!(worst <= 1.5 * md, "a point {worst} mm off the drawn line");
            let off = drawn
                .iter()
                .map(|p| to_polyline(*p, pts))
                .fold(0.0, f64::max);
            assert!(off <= 1e-4, "a drawn point {off} mm off the path");
        }
    }

    /// A path that turns back on itself (a peck out and back along one line, then on) keeps
    /// the turning point: the line does not stop short of where the tool went.
    #[test]
    fn a_path_that_turns_back_keeps_its_turning_point() {
        let lines = vec![
            line(PathKind::Feed, &[[0.0, 10.0], [-3.0, 10.0]]),
            line(PathKind::Feed, &[[-3.0, 10.0], [-1.0, 10.0]]),
            line(PathKind::Feed, &[[-1.0, 10.0], [-1.0, 12.0]]),
        ];
        let w = Bbox::new(-100.0, 100.0, -100.0, 100.0);
        let t = toolpath_d(&lines, 0.01, &w, 1000);
        assert_eq!(t.feed, "M0,10L-3,10L-1,10L-1,12");
    }

    #[test]
    fn nan_points_do_not_leak() {
        let lines = vec![line(
            PathKind::Feed,
            &[[0.0, 1.0], [f64::NAN, 2.0], [3.0, 4.0], [5.0, 4.0]],
        )];
        let t = toolpath_d(&lines, 0.01, &Bbox::new(-9.0, 9.0, -9.0, 9.0), 100);
        assert!(!t.feed.contains("NaN"));
        assert_eq!(t.feed, "M3,4L5,4");
        let s = shapes_d(
            &[Shape {
                outer: vec![
                    [0.0, 0.0],
                    [f64::NAN, 1.0],
                    [1.0, 0.0],
                    [1.0, 1.0],
                    [0.0, 1.0],
                ],
                holes: vec![vec![[0.0, 0.0]]],
            }],
            1e-6,
        );
        assert_eq!(s, "M0,0L1,0L1,1L0,1Z");
    }

    /// Distance from `p` to the segment `a`–`b`.
    fn seg_dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
        let (dz, dr) = (b[0] - a[0], b[1] - a[1]);
        let l2 = dz * dz + dr * dr;
        let t = if l2 == 0.0 {
            0.0
        } else {
            (((p[0] - a[0]) * dz + (p[1] - a[1]) * dr) / l2).clamp(0.0, 1.0)
        };
        dist2(p, [a[0] + t * dz, a[1] + t * dr]).sqrt()
    }

    /// Largest distance from a point of `from` (vertices and edge samples) to the closed
    /// polyline `to`.
    fn one_way(from: &[[f64; 2]], to: &[[f64; 2]]) -> f64 {
        let n = from.len();
        let mut worst: f64 = 0.0;
        for i in 0..n {
            let (a, b) = (from[i], from[(i + 1) % n]);
            for k in 0..8 {
                let t = k as f64 / 8.0;
                let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                let d = (0..to.len())
                    .map(|j| seg_dist(p, to[j], to[(j + 1) % to.len()]))
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max(d);
            }
        }
        worst
    }

    /// Issue 17: a blank profile of 4 000 sub-pixel teeth (0.002 mm wide, 5 mm tall) on a
    /// 0.1 mm pixel keeps a few points per column, and the drawn ring stays within two
    /// collapse widths (0.6 px at `MIN_PX`) of the original both ways.
    #[test]
    fn sawtooth_collapses_to_the_picture_resolution() {
        let mut ring = vec![[-10.0, 0.0], [0.0, 0.0]];
        for k in 0..=8_000 {
            let z = -0.001 * k as f64;
            ring.push([z, if k % 2 == 0 { 40.0 } else { 45.0 }]);
        }
        ring.push([-10.0, 40.0]);
        let md = 0.03;
        let kept = thin_ring(&ring, md);
        assert!(kept.len() < 4 * (8.0 / md) as usize + 10, "{}", kept.len());
        let h = one_way(&ring, &kept).max(one_way(&kept, &ring));
        assert!(h <= 2.0 * md, "Hausdorff {h}");
        // a ring with no dense run is left as it was
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(thin_ring(&square, md), square.to_vec());
    }
}
