//! The geometry of `LinuxCNC`'s G70/G71/G72 (docs/linuxcnc.md "G70, G71, G72"; [G] "G70",
//! "G71 G72"; `interp_g7x.cc`): the profile the O-sub Q traced (its moves read as lines
//! and arcs, a G0 as a G1), with the fillets (A) and chamfers (C) written at its corners;
//! the profile kept at a distance (`add_distance`: a true offset toward the cycle's start
//! point, not FANUC's translation); the profile without its pockets (G7x.1); and G70's
//! passes. The roughing layers are FANUC's (`g71_g72::linuxcnc_rough`).

use super::contour::{FinishingShape, ShapeElement, ShapeModes};
use super::Move;
use crate::tnrc::{self, Nose, Side};
use crate::{Diagnostic, Pt, Segment, Span};

/// A fillet (A, `chamfer` false) or chamfer (C) of `size` written on the block whose move
/// is profile element `after` (counted from the first move of the O-sub).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Corner {
    pub(crate) after: usize,
    pub(crate) chamfer: bool,
    pub(crate) size: f64,
    pub(crate) span: Span,
}

/// Arcs are flattened to this sagitta where a polyline is needed (G7x.1), mm.
const SAGITTA: f64 = 1e-4;

fn element(from: Pt, to: Pt, arc: Option<crate::Arc>, span: Span) -> ShapeElement {
    ShapeElement {
        from,
        to,
        arc,
        rapid: false,
        feed: None,
        modes: ShapeModes::default(),
        span,
    }
}

/// The profile of a cycle `code` (canonical) at `span` starting at `start`: the moves the
/// O-sub made (from `start`), their corners applied. Fewer than two moves is an alarm.
pub(crate) fn profile(
    (code, span): (i32, Span),
    start: Pt,
    moves: &[Segment],
    corners: &[Corner],
) -> Result<FinishingShape, Diagnostic> {
    let mut elements: Vec<ShapeElement> = moves
        .iter()
        .map(|s| element(s.from, s.to, s.arc, s.span))
        .collect();
    if elements.len() < 2 {
        return Err(Diagnostic::new(
            span,
            "LS-G7X-PROFILE",
            "the profile of the O-sub Q has fewer than two moves",
            "the O-sub traces the part's profile with G0/G1/G2/G3 moves from the cycle's start point",
        ));
    }
    let mut sorted = corners.to_vec();
    sorted.sort_by_key(|c| std::cmp::Reverse(c.after));
    for c in sorted {
        add_corner(&mut elements, c)?;
    }
    Ok(FinishingShape {
        cycle: code,
        start,
        ns_span: elements[0].span,
        elements,
        span,
        ns_moves: (true, true),
        ns_index: 0,
        comp: None,
        comp_from: 0,
        nf_index: 0,
        notes: vec![],
    })
}

/// Put corner `c` between element `c.after` and the next: both lines (`LinuxCNC` rounds any
/// corner; latsim only between two lines).
fn add_corner(elements: &mut Vec<ShapeElement>, c: Corner) -> Result<(), Diagnostic> {
    let what = if c.chamfer { "chamfer C" } else { "fillet A" };
    let k = c.after;
    let (Some(a), Some(b)) = (elements.get(k), elements.get(k + 1)) else {
        return Err(Diagnostic::new(
            c.span,
            "LS-G7X-PROFILE",
            format!("a {what} on the profile's last move: no corner follows"),
            "write A or C on a move that another move follows",
        ));
    };
    if a.arc.is_some() || b.arc.is_some() {
        return Err(Diagnostic::new(
            c.span,
            "LS-NOT-IMPLEMENTED",
            format!("a {what} next to an arc in a G7x profile is not simulated by latsim"),
            "write the corner's arc or chamfer as moves of its own",
        ));
    }
    let p = a.to;
    let (d1, d2) = ((a.to - a.from).unit(), (b.to - b.from).unit());
    let turn = d1.cross(d2);
    let deflection = turn.atan2(d1.dot(d2)).abs();
    if deflection < 1e-9 {
        return Ok(());
    }
    let t = c.size * (deflection / 2.0).tan();
    if c.size <= 0.0 || t > a.from.dist(p) + 1e-9 || t > p.dist(b.to) + 1e-9 {
        return Err(Diagnostic::new(
            c.span,
            "LS-G7X-PROFILE",
            format!("the {what}{} does not fit the corner's moves", c.size),
            "give a smaller size",
        ));
    }
    let (t1, t2) = (p - d1 * t, p + d2 * t);
    let arc = (!c.chamfer).then(|| {
        let normal = if turn > 0.0 { d1.perp() } else { -d1.perp() };
        crate::Arc {
            center: t1 + normal * c.size,
            ccw: turn > 0.0,
        }
    });
    elements[k].to = t1;
    elements[k + 1].from = t2;
    elements.insert(k + 1, element(t1, t2, arc, c.span));
    Ok(())
}

/// The profile kept `distance` away, on the side of the cycle's start point: the moves
/// after the first offset as a nose of that radius would run (spec/tnrc.md's offset: arcs
/// round the outside corners), the first move ending at the offset start.
pub(crate) fn at_distance(
    shape: &FinishingShape,
    distance: f64,
) -> Result<FinishingShape, Diagnostic> {
    if distance.abs() < 1e-12 {
        return Ok(shape.clone());
    }
    let (b, c) = (shape.b(), shape.c());
    let side = if (c - b).cross(shape.start - b) > 0.0 {
        Side::Left
    } else {
        Side::Right
    };
    let (side, r) = if distance > 0.0 {
        (side, distance)
    } else {
        let other = if side == Side::Left {
            Side::Right
        } else {
            Side::Left
        };
        (other, -distance)
    };
    let mut section: Vec<Segment> = shape
        .elements
        .iter()
        .map(ShapeElement::as_segment)
        .collect();
    let last = shape.elements[shape.elements.len() - 1];
    let along = if last.arc.is_none() {
        (last.to - last.from).unit()
    } else {
        (c - b).unit()
    };
    let mut cancel = last.as_segment();
    cancel.from = c;
    cancel.to = c + along;
    cancel.arc = None;
    section.push(cancel);
    let done = tnrc::compensate(&section, side, Nose { radius: r, tip: 0 });
    if let Some(a) = done.alarms.into_iter().next() {
        return Err(a);
    }
    let n = done.segments.len();
    let mut out = shape.clone();
    out.elements = done.segments[..n - 1]
        .iter()
        .map(|s| element(s.from, s.to, s.arc, s.span))
        .collect();
    out.elements[0].from = shape.start;
    Ok(out)
}

/// The profile without its pockets (G7x.1): after the first move, wherever the profile
/// would go back into the material (deeper, along the cycle's infeed: X for G71, Z for
/// G72, than the shallowest level it has reached since B), a straight bridge at that level
/// instead, to where the profile comes back to it.
/// Arcs are flattened (0.1 µm).
pub(crate) fn without_pockets(shape: &FinishingShape, g72: bool) -> FinishingShape {
    let a = shape.start;
    let b = shape.b();
    let infeed = |p: Pt| if g72 { p.z - a.z } else { p.r - a.r };
    let sv = infeed(b).signum();
    let depth = |p: Pt| sv * infeed(p);
    let mut pts: Vec<(Pt, Span)> = vec![(b, shape.elements[0].span)];
    for e in &shape.elements[1..] {
        for p in e.as_segment().polyline(SAGITTA).into_iter().skip(1) {
            pts.push((p, e.span));
        }
    }
    let mut out = shape.clone();
    out.elements.truncate(1);
    let mut level = depth(b);
    let mut at = b;
    let mut level_from: Option<Pt> = None;
    for w in pts.windows(2) {
        let ((p, _), (q, span)) = (w[0], w[1]);
        let (dp, dq) = (depth(p), depth(q));
        match level_from {
            None if dq <= level + 1e-12 => {
                out.elements.push(element(at, q, None, span));
                at = q;
                level = level.min(dq);
            }
            None => {
                // the profile goes deeper again (a pocket): bridge from here
                level_from = Some(at);
            }
            Some(_) if dq <= level + 1e-12 => {
                // back at the level: where the move crosses it, then on
                let t = (level - dp) / (dq - dp);
                let cross = p + (q - p) * t;
                out.elements.push(element(at, cross, None, span));
                out.elements.push(element(cross, q, None, span));
                at = q;
                level_from = None;
            }
            Some(_) => {}
        }
    }
    if level_from.is_some() {
        let (last, span) = pts[pts.len() - 1];
        let end = if g72 {
            Pt::new(at.z, last.r)
        } else {
            Pt::new(last.z, at.r)
        };
        out.elements.push(element(at, end, None, span));
    }
    out.elements.retain(|e| e.from.dist(e.to) > 1e-12);
    out
}

/// G70's passes ([G] "G70"): pass k of `passes` (the last first) runs at distance
/// (k − 1)(d − e)/passes + e from the profile: a rapid to the start point, a rapid to the
/// profile's start, then the profile fed, arcs as arcs. The tool stays at the profile's end.
pub(crate) fn finishing_passes(
    shape: &FinishingShape,
    (d, e, passes): (f64, f64, u32),
) -> Result<Vec<Move>, Diagnostic> {
    let mut moves = vec![];
    for pass in (1..=passes).rev() {
        let distance = f64::from(pass - 1) * (d - e) / f64::from(passes) + e;
        let at = at_distance(shape, distance)?;
        moves.push(Move::rapid(shape.start));
        let mut first = Move::rapid(at.elements[0].to);
        first.span = Some(at.elements[0].span);
        moves.push(first);
        for el in &at.elements[1..] {
            let mut m = Move::feed(el.to);
            m.arc = el.arc;
            m.span = Some(el.span);
            moves.push(m);
        }
    }
    Ok(moves)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(from: (f64, f64), to: (f64, f64)) -> Segment {
        element(
            Pt::new(from.0, from.1),
            Pt::new(to.0, to.1),
            None,
            Span::default(),
        )
        .as_segment()
    }

    /// A 90° corner with fillet A2: tangent points 2 mm before and after it, the centre
    /// 2 mm inside; a chamfer C2 has the same end points.
    #[test]
    fn fillets_and_chamfers_meet_the_corner_moves_at_their_tangent_points() {
        let moves = [
            seg((0.0, 20.0), (0.0, 10.0)),
            seg((0.0, 10.0), (-10.0, 10.0)),
            seg((-10.0, 10.0), (-10.0, 20.0)),
        ];
        let corner = Corner {
            after: 0,
            chamfer: false,
            size: 2.0,
            span: Span::default(),
        };
        let s = profile((0, Span::default()), Pt::new(0.0, 20.0), &moves, &[corner]).unwrap();
        assert_eq!(s.elements.len(), 4);
        let near = |p: Pt, z: f64, r: f64| p.dist(Pt::new(z, r)) < 1e-12;
        assert!(near(s.elements[0].to, 0.0, 12.0), "{s:?}");
        assert!(near(s.elements[1].to, -2.0, 10.0), "{s:?}");
        let arc = s.elements[1].arc.unwrap();
        assert!(arc.center.dist(Pt::new(-2.0, 12.0)) < 1e-12, "{arc:?}");
        // down then toward -Z: a right turn (clockwise in z, r)
        assert!(!arc.ccw);
        let chamfer = Corner {
            chamfer: true,
            ..corner
        };
        let s = profile((0, Span::default()), Pt::new(0.0, 20.0), &moves, &[chamfer]).unwrap();
        assert_eq!(s.elements[1].arc, None);
        assert!(near(s.elements[1].from, 0.0, 12.0) && near(s.elements[1].to, -2.0, 10.0));
    }

    /// A step profile kept 0.5 away toward its start (outside): each line moves out by
    /// 0.5, the outside corner becomes an arc of 0.5.
    #[test]
    fn at_distance_offsets_toward_the_start_point() {
        // A (2, 15) → B (2, 5) → (-10, 5) → (-10, 8) → (-20, 8)
        let moves = [
            seg((2.0, 15.0), (2.0, 5.0)),
            seg((2.0, 5.0), (-10.0, 5.0)),
            seg((-10.0, 5.0), (-10.0, 8.0)),
            seg((-10.0, 8.0), (-20.0, 8.0)),
        ];
        let s = profile((0, Span::default()), Pt::new(2.0, 15.0), &moves, &[]).unwrap();
        let o = at_distance(&s, 0.5).unwrap();
        assert_eq!(o.elements[0].from, Pt::new(2.0, 15.0));
        assert!(
            o.elements[0].to.dist(Pt::new(2.0, 5.5)) < 1e-9,
            "{:?}",
            o.elements[0]
        );
        let last = o.elements.last().unwrap();
        assert!(last.to.dist(Pt::new(-20.0, 8.5)) < 1e-9, "{last:?}");
        // the inside corner at (-10, 5) becomes (-9.5, 5.5); the outside corner at (-10, 8)
        // an arc of 0.5 about it
        let ends: Vec<Pt> = o.elements.iter().map(|e| e.to).collect();
        assert!(ends[1].dist(Pt::new(-9.5, 5.5)) < 1e-9, "{ends:?}");
        assert!(ends[2].dist(Pt::new(-9.5, 8.0)) < 1e-9, "{ends:?}");
        let arc = o.elements[3].arc.expect("the outside corner's arc");
        assert!(
            arc.center.dist(Pt::new(-10.0, 8.0)) < 1e-9 && ends[3].dist(Pt::new(-10.0, 8.5)) < 1e-9
        );
    }

    /// A profile with a pocket: the bridge at the deepest level reached replaces it.
    #[test]
    fn without_pockets_bridges_at_the_deepest_level() {
        // G71 from A (5, 20): B (5, 4), out to r 10, down into a pocket at r 6, out to 12
        let moves = [
            seg((5.0, 20.0), (5.0, 4.0)),
            seg((5.0, 4.0), (0.0, 10.0)),
            seg((0.0, 10.0), (-4.0, 6.0)),
            seg((-4.0, 6.0), (-8.0, 12.0)),
        ];
        let s = profile((0, Span::default()), Pt::new(5.0, 20.0), &moves, &[]).unwrap();
        let e = without_pockets(&s, false);
        let ends: Vec<Pt> = e.elements.iter().map(|e| e.to).collect();
        // the pocket below r 10 is bridged from (0, 10) to where the last move climbs
        // back through r 10: z = -4 - 4·(4/6)
        let z = -4.0 - 4.0 * 4.0 / 6.0;
        assert_eq!(ends[..2], [Pt::new(5.0, 4.0), Pt::new(0.0, 10.0)]);
        assert!(ends[2].dist(Pt::new(z, 10.0)) < 1e-9, "{ends:?}");
        assert_eq!(ends[3], Pt::new(-8.0, 12.0));
    }
}
