//! Moves past the axis (spec/simulation.md, "Tools past the axis"): the part is a solid of
//! revolution, so what a tool removes at negative X it removes at radius |X| / 2. The tool
//! is swept where it was programmed and the sweep is folded about the axis: its part below
//! the axis is mirrored into the section (a facing pass past the centre, a tool whose body
//! reaches across the axis, a move that crosses X0 all come out right).
//!
//! A tool's tip number reads the same on a rear post as on the front (spec/tnrc.md: an OD
//! tool is tip 3 on either), so a rear-post tool — one that works at negative X — is mounted
//! as the mirror of the table's picture.

use crate::outline::PastAxis;
use expander::{Motion, Segment};
use geom::flat::{clip_convex, P};
use geom::{Pt, Rect};

/// A convex polygon of a sweep folded into the section: its part at r ≥ 0 as it is, its part
/// at r ≤ 0 mirrored — or, for an outline whose size is assumed, only the part on its
/// tool's side of the axis (`past`, [`PastAxis`]) — each convex; empty parts left out.
pub(crate) fn fold(poly: &[P], past: PastAxis) -> Vec<Vec<P>> {
    if poly.iter().all(|p| p[1] >= 0.0) {
        return match past {
            PastAxis::DropAbove => Vec::new(),
            _ => vec![poly.to_vec()],
        };
    }
    const FAR: f64 = 1e12;
    let upper = Rect::new(Pt::new(-FAR, 0.0), Pt::new(FAR, FAR));
    let lower = Rect::new(Pt::new(-FAR, -FAR), Pt::new(FAR, 0.0));
    let above = match past {
        PastAxis::DropAbove => Vec::new(),
        _ => clip_convex(poly, &upper),
    };
    let mut below = match past {
        PastAxis::DropBelow => Vec::new(),
        _ => clip_convex(poly, &lower),
    };
    for p in &mut below {
        p[1] = -p[1];
    }
    below.reverse(); // mirroring reverses the orientation
                     // a part that only touches the axis is a line, not a polygon
    let twice_area = |p: &Vec<P>| {
        (0..p.len())
            .map(|i| {
                let (a, b) = (p[i], p[(i + 1) % p.len()]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>()
    };
    [above, below]
        .into_iter()
        .filter(|p| p.len() >= 3 && twice_area(p) > 1e-12)
        .collect()
}

/// The tools on a rear post: those whose cutting moves (feeds and threads) run longer at
/// negative X than at positive X. Their outline as mounted is the mirror of the table's.
pub fn rear_tools(segments: &[Segment]) -> Vec<u32> {
    let mut len: Vec<(u32, f64)> = Vec::new();
    for s in segments.iter().filter(|s| s.motion != Motion::Rapid) {
        let mid = (s.from.r + s.to.r) / 2.0;
        let l = if mid == 0.0 {
            0.0
        } else {
            s.from.dist(s.to).copysign(mid)
        };
        match len.iter_mut().find(|(t, _)| *t == s.tool) {
            Some((_, v)) => *v += l,
            None => len.push((s.tool, l)),
        }
    }
    len.into_iter()
        .filter(|&(_, l)| l < 0.0)
        .map(|(t, _)| t)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use expander::{FeedId, Span};
    use geom::flat::pts;

    fn seg(tool: u32, from: [f64; 2], to: [f64; 2]) -> Segment {
        Segment {
            motion: Motion::Feed,
            from: Pt::new(from[0], from[1]),
            to: Pt::new(to[0], to[1]),
            arc: None,
            tool,
            hint: expander::ToolHint::Table,
            lead: 0.0,
            thread_phase: 0.0,
            feed: FeedId::default(),
            span: Span::default(),
        }
    }

    #[test]
    fn a_polygon_across_the_axis_folds_into_two() {
        let square = [[0.0, -1.0], [2.0, -1.0], [2.0, 3.0], [0.0, 3.0]];
        let f = fold(&square, PastAxis::Fold);
        assert_eq!(f.len(), 2);
        // 2 × 3 above, 2 × 1 mirrored, both counter-clockwise
        let areas: Vec<f64> = f
            .iter()
            .map(|p| ::geom::ring::signed_area(&pts(p)))
            .collect();
        assert!(
            (areas[0] - 6.0).abs() < 1e-12 && (areas[1] - 2.0).abs() < 1e-12,
            "{areas:?}"
        );
        assert!(f[1].iter().all(|p| p[1] >= 0.0 && p[1] <= 1.0));
        let above = [[0.0, 1.0], [1.0, 1.0], [1.0, 2.0]];
        assert_eq!(fold(&above, PastAxis::Fold), vec![above.to_vec()]);
        // wholly below, touching the axis: only its mirror (no zero-area part on the axis)
        let below = [[0.0, -1.0], [1.0, -1.0], [1.0, 0.0], [0.0, 0.0]];
        let f = fold(&below, PastAxis::Fold);
        assert_eq!(f.len(), 1);
        assert!((::geom::ring::signed_area(&pts(&f[0])) - 1.0).abs() < 1e-12);
        // an outline whose size is assumed keeps only its part on its tool's side
        let f = fold(&square, PastAxis::DropBelow);
        assert_eq!(f.len(), 1);
        assert!((::geom::ring::signed_area(&pts(&f[0])) - 6.0).abs() < 1e-12);
        assert!(fold(&below, PastAxis::DropBelow).is_empty());
        let f = fold(&square, PastAxis::DropAbove);
        assert_eq!(f.len(), 1);
        assert!((::geom::ring::signed_area(&pts(&f[0])) - 2.0).abs() < 1e-12);
        assert!(fold(&above, PastAxis::DropAbove).is_empty());
    }

    #[test]
    fn a_tool_working_at_negative_x_is_on_the_rear_post() {
        let s = [
            seg(1, [0.0, 20.0], [-30.0, 20.0]),
            seg(2, [0.0, -18.0], [-25.0, -18.0]),
            seg(2, [-25.0, -18.0], [-25.0, 1.0]),
        ];
        assert_eq!(rear_tools(&s), vec![2]);
    }
}
