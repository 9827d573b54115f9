//! Which move made a gouge: the first whose tool sweep overlaps it.

use super::Finding;
use expander::Segment;
use geom::flat::{clip_to_hull, pts, P};
use geom::{ring, Rect};
use stock::{area, boolean, float_sweep, move_path, BoolOp, Mounts, Shape};

/// For every gouge, the first segment whose tool sweep overlaps it by more than a sliver.
/// Each segment's sweep is built once and tried on the gouges still unnamed whose box it
/// meets; the search ends when every gouge is named. (A mutated facing program of 11 030
/// moves whose holder rubs on most of them took 19.8 s when every gouge built every sweep
/// again and asked a boolean; a 3 000-pass G73 over small arcs asked for every pass.)
/// Moves past the axis are folded into the section as the removal folds them
/// (`stock::float_sweep`), each tool as mounted (`mounts`: rear-post tools mirrored).
/// Only the moves `maker` accepts are looked at.
pub(super) fn blame(
    gouges: &mut [Finding],
    segments: &[Segment],
    mounts: &mut Mounts,
    chord_tol: f64,
    maker: &dyn Fn(&Segment) -> bool,
) {
    let boxes: Vec<Rect> = gouges
        .iter()
        .map(|g| Rect::of(pts(&g.shape.outer)))
        .collect();
    let mut unnamed: Vec<usize> = (0..gouges.len()).collect();
    for (i, seg) in segments.iter().enumerate() {
        if unnamed.is_empty() {
            break;
        }
        if !maker(seg) {
            continue;
        }
        let mounted = mounts.of(seg);
        let outline = &mounted.edge;
        let near: Vec<usize> = unnamed
            .iter()
            .copied()
            .filter(|&g| crate::sweeps::may_sweep_over(&boxes[g], seg, outline))
            .collect();
        if near.is_empty() {
            continue;
        }
        let sweep = float_sweep(outline, &move_path(seg, chord_tol));
        for g in near {
            if overlaps(
                &gouges[g].shape,
                &boxes[g],
                &sweep,
                edge_sliver(&gouges[g].shape),
            ) && thicker_than(&gouges[g].shape, &sweep, chord_tol)
            {
                gouges[g].made_by = Some(i);
                unnamed.retain(|&u| u != g);
            }
        }
    }
}

/// Which of `regions` (gouges of guessed tools) do not depend on what the table leaves out
/// (spec/simulation.md, "Findings from assumed tools"): those the stated core of a guessed
/// tool (`stock::Mounted::core`: an insert's nose, a blade's tip) sweeps over on some move,
/// or where the reference path enters the intended `part` ([`crate::assumed`]). One pass
/// over the moves for all of them; each move's path and core sweep made once, where a
/// region's box is near. `from[g]`: the move that made region `g` (the first whose sweep
/// overlaps it): no move before it can have entered it.
pub(crate) fn certain(
    regions: &[&Shape],
    from: &[usize],
    part: &[Shape],
    segments: &[Segment],
    mounts: &mut Mounts,
    chord_tol: f64,
) -> Vec<bool> {
    let part = crate::assumed::Region::new(part);
    let boxes: Vec<Rect> = regions.iter().map(|r| Rect::of(pts(&r.outer))).collect();
    let indexes: Vec<crate::assumed::Region> = regions
        .iter()
        .map(|r| crate::assumed::Region::new(std::slice::from_ref(*r)))
        .collect();
    let mut certain = vec![false; regions.len()];
    let mut open: Vec<usize> = (0..regions.len()).collect();
    let first = from.iter().copied().min().unwrap_or(0);
    for (i, seg) in segments.iter().enumerate().skip(first) {
        if open.is_empty() {
            break;
        }
        if !crate::assumed::guessed(mounts.tools(), seg) {
            continue;
        }
        let m = mounts.of(seg);
        let reach = crate::assumed::path_box(seg);
        let near: Vec<usize> = open
            .iter()
            .copied()
            .filter(|&g| {
                i >= from[g]
                    && (reach.intersects(&boxes[g])
                        || m.core
                            .as_deref()
                            .is_some_and(|c| crate::sweeps::may_sweep_over(&boxes[g], seg, c)))
            })
            .collect();
        if near.is_empty() {
            continue;
        }
        let path = move_path(seg, chord_tol);
        let core = m.core.as_deref().map(|c| float_sweep(c, &path));
        for g in near {
            let by_core = core
                .as_ref()
                .is_some_and(|sweep| overlaps(regions[g], &boxes[g], sweep, SLIVER));
            if by_core || crate::assumed::path_enters_part_at(seg, &part, &indexes[g], chord_tol) {
                certain[g] = true;
                open.retain(|&o| o != g);
            }
        }
    }
    certain
}

/// The least overlap that makes a move the maker of `region`: 10⁻⁶ mm times its perimeter
/// (at least [`SLIVER`]). A sweep that only runs along the region's edge overlaps it by the
/// booleans' rounding there (a grid step, ~10⁻⁷ mm, along the edge): the facing pass along
/// the face above a drilled hole was named the hole's maker, or not, with the bar's length.
pub(super) fn edge_sliver(region: &Shape) -> f64 {
    (1e-6 * super::perimeter(region)).max(SLIVER)
}

/// Whether the overlap of the convex `sweep` parts with `region` is thicker than `min`
/// (mm, 2·area/perimeter) in some piece. A finishing pass along a surface overlaps a gouge
/// that reaches that surface by the removal's discretisation only (a band 5·10⁻⁵ mm thick
/// along a finished Ø38.2, where a part-off slot at the shape's end joined it): on some
/// diameters that band was more than a sliver of area, and the G70's last move, not the
/// blade, was named the slot's maker.
fn thicker_than(region: &Shape, sweep: &[Vec<P>], min: f64) -> bool {
    let parts: Vec<Shape> = sweep
        .iter()
        .map(|p| Shape {
            outer: p.clone(),
            holes: vec![],
        })
        .collect();
    // the parts overlap one another: the boolean's non-zero rule joins them, as in `overlaps`
    boolean(&parts, std::slice::from_ref(region), BoolOp::Intersection)
        .iter()
        .any(|piece| 2.0 * area(std::slice::from_ref(piece)) > min * super::perimeter(piece))
}

/// Less overlap than this is no overlap, mm².
pub(super) const SLIVER: f64 = 1e-9;

/// Whether the union of the convex `sweep` parts overlaps `region` (box `bb`) by more than
/// `sliver` mm². Exact shortcuts first (a G73 of many passes asks this for every pass and gouge,
/// a holder that rubs for every move): a part whose box misses the region's adds nothing;
/// a part holding every vertex of the region holds all of it. Then each part's overlap is
/// measured by clipping the region's rings to it: one over the threshold decides, and when
/// even their sum is under it the union's is too. Only the rare case between asks the
/// boolean of the union.
pub(super) fn overlaps(region: &Shape, bb: &Rect, sweep: &[Vec<P>], sliver: f64) -> bool {
    let near: Vec<&Vec<P>> = sweep
        .iter()
        .filter(|s| Rect::of(pts(s)).intersects(bb))
        .collect();
    if near.is_empty() {
        return false;
    }
    if near.iter().any(|s| holds_all(s, &region.outer)) {
        return area(std::slice::from_ref(region)) > sliver;
    }
    let sign = ring::signed_area(&pts(&region.outer)).signum();
    let mut sum = 0.0;
    for s in &near {
        let a: f64 = std::iter::once(&region.outer)
            .chain(&region.holes)
            .map(|r| sign * ring::signed_area(&pts(&clip_to_hull(r, s))))
            .sum();
        if a > sliver {
            return true;
        }
        sum += a.max(0.0);
    }
    if sum <= sliver {
        return false;
    }
    let union: Vec<Shape> = near
        .into_iter()
        .map(|outer| Shape {
            outer: outer.clone(),
            holes: vec![],
        })
        .collect();
    area(&boolean(
        &union,
        std::slice::from_ref(region),
        BoolOp::Intersection,
    )) > sliver
}

/// Whether the convex ring `hull` (either orientation) holds every point of `ring`, its
/// boundary included.
fn holds_all(hull: &[P], ring: &[P]) -> bool {
    let n = hull.len();
    if n < 3 {
        return false;
    }
    let sign = ring::signed_area(&pts(hull)).signum();
    if sign == 0.0 {
        return false;
    }
    ring.iter().all(|p| {
        (0..n).all(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            let cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
            cross * sign >= 0.0
        })
    })
}

/// For each of `regions`, every move whose tool sweep overlaps it by more than a sliver, in
/// move order: the moves that made a region of `crate::diff` (the blame above stops at the
/// first). With `margin` > 0 each sweep is grown by it first (its Minkowski sum with a
/// square): the moves that ran within `margin` of a region, which left its edge where it
/// is. One pass over the moves; a move's sweep is built only when its box may reach one.
pub(crate) fn moves_over(
    regions: &[Shape],
    segments: &[Segment],
    mounts: &mut Mounts,
    chord_tol: f64,
    margin: f64,
) -> Vec<Vec<usize>> {
    let margin = margin.max(0.0);
    let boxes: Vec<Rect> = regions
        .iter()
        .map(|g| Rect::of(pts(&g.outer)).grown(margin))
        .collect();
    let mut out = vec![vec![]; regions.len()];
    for (i, seg) in segments.iter().enumerate() {
        let mounted = mounts.of(seg);
        let near: Vec<usize> = (0..regions.len())
            .filter(|&g| crate::sweeps::may_sweep_over(&boxes[g], seg, &mounted.edge))
            .collect();
        if near.is_empty() {
            continue;
        }
        let mut sweep = float_sweep(&mounted.edge, &move_path(seg, chord_tol));
        if margin > 0.0 {
            sweep = sweep.iter().map(|part| grown(part, margin)).collect();
        }
        for g in near {
            if overlaps(&regions[g], &boxes[g], &sweep, edge_sliver(&regions[g])) {
                out[g].push(i);
            }
        }
    }
    out
}

/// The convex `part` grown by `m` along both axes (its Minkowski sum with a square of side
/// 2·`m`): convex again.
fn grown(part: &[P], m: f64) -> Vec<P> {
    let corners: Vec<P> = part
        .iter()
        .flat_map(|p| {
            [
                [p[0] - m, p[1] - m],
                [p[0] + m, p[1] - m],
                [p[0] + m, p[1] + m],
                [p[0] - m, p[1] + m],
            ]
        })
        .collect();
    geom::flat::convex_hull(&corners)
}
