//! Crashes: the overlap of a rapid's (or a body's) sweep with the stock, seen by each strip
//! as a fragment, added up over the strips.

use crate::overlay::{Grid, IShapes};
use crate::sweep::Item;
use geom::distance::point_segment;
use geom::flat::P;
use geom::{ring, Pt};

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

/// Part of a crash seen by one strip.
pub(super) struct Fragment {
    /// The move.
    seg: usize,
    /// Its body, for a body's probe.
    body: Option<&'static str>,
    /// Overlap area above which the move's cuts are a crash ([`crate::sweep::Item::eps`]).
    eps: f64,
    /// The overlap's area in this strip, mm².
    area: f64,
    /// Distance of `at` from the move's start.
    dist: f64,
    /// The overlap's point nearest the move's start.
    at: P,
    /// The overlap's extent along the move's normal: (least, largest) projection.
    across: (f64, f64),
}

impl Fragment {
    /// The fragment of the move `it` whose sweep overlapped this strip's stock in
    /// `overlap`, of area `area` mm².
    pub(super) fn of(it: &Item, overlap: &IShapes, area: f64, grid: &Grid) -> Self {
        let (dist, at) = nearest(grid, overlap, it.start);
        Self {
            seg: it.seg,
            body: it.body,
            eps: it.eps,
            area,
            dist,
            at,
            across: across(grid, overlap, it.dir),
        }
    }
}

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

/// Point of `shapes` nearest to `p` (p itself when inside) and its distance.
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

/// Adds up the overlaps each strip saw for a rapid; the contact point is the one nearest
/// the rapid's start over all strips.
pub(super) fn merge_fragments(mut frags: Vec<Fragment>) -> Vec<Crash> {
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
