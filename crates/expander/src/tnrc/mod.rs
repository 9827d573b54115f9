//! Tool nose radius compensation G41/G42 (spec/tnrc.md, seed 004).
//!
//! The program moves the imaginary tip along the contour. Under G41/G42 the nose centre
//! moves along the contour offset by the nose radius r to the left/right of travel, and the
//! segments we emit move the imaginary tip = nose centre + the tip vector of the imaginary
//! tip number. One scheme, applied consistently (FANUC type A):
//! - start-up: the start-up block (G00/G01) ends at its programmed end plus r times the
//!   normal of the *next* block at its start;
//! - cancel: the cancel block starts at the previous block's end plus r times that block's
//!   normal there, and ends at its programmed (uncompensated) end point;
//! - inside corners: the intersection of the two offset elements;
//! - outside corners: an arc of radius r about the programmed corner (the nose rolls round
//!   the corner and stays on the contour);
//! - an offset element that would run backwards after trimming (radius too large for an
//!   inside corner or a short element), or a concave arc smaller than the nose, is
//!   interference: an alarm at that block, and the path is still emitted as computed so
//!   the report shows the overcut it would cause.

use crate::{Arc, Diagnostic, Pt, Segment};

mod section;

/// Which side of the contour the tool keeps, looking along the direction of travel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Side {
    /// G41.
    Left,
    /// G42.
    Right,
}

/// The nose of a tool offset: radius and imaginary tip number (FANUC numbering).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Nose {
    /// Nose radius, mm.
    pub radius: f64,
    /// Imaginary tip number 0–9.
    pub tip: u8,
}

impl Nose {
    /// The vector from the nose centre to the imaginary tip, (z, r) (spec/tnrc.md table).
    pub(crate) fn tip_vector(&self) -> Pt {
        let r = self.radius;
        match self.tip {
            1 => Pt::new(r, r),
            2 => Pt::new(-r, r),
            3 => Pt::new(-r, -r),
            4 => Pt::new(r, -r),
            5 => Pt::new(r, 0.0),
            6 => Pt::new(0.0, r),
            7 => Pt::new(-r, 0.0),
            8 => Pt::new(0.0, -r),
            _ => Pt::new(0.0, 0.0),
        }
    }
}

/// Unit tangent of a segment at its start (`at_end` false) or end.
fn tangent(s: &Segment, at_end: bool) -> Pt {
    match s.arc {
        None => (s.to - s.from).unit(),
        Some(a) => {
            let p = if at_end { s.to } else { s.from };
            let radial = (p - a.center).unit();
            // counter-clockwise: tangent is the radial vector turned +90°
            if a.ccw {
                Pt::new(-radial.r, radial.z)
            } else {
                Pt::new(radial.r, -radial.z)
            }
        }
    }
}

/// Unit normal toward the tool's side of a travel direction.
fn normal(side: Side, t: Pt) -> Pt {
    match side {
        Side::Left => Pt::new(-t.r, t.z),
        Side::Right => Pt::new(t.r, -t.z),
    }
}

/// An offset element: the programmed element moved r to the tool's side.
#[derive(Debug, Clone, Copy)]
enum Offset {
    Line { p: Pt, d: Pt },
    Circle { c: Pt, radius: f64, ccw: bool },
}

fn offset_of(s: &Segment, side: Side, r: f64) -> Offset {
    match s.arc {
        None => {
            let d = tangent(s, false);
            Offset::Line {
                p: (s.from + (normal(side, d) * r)),
                d,
            }
        }
        Some(a) => {
            let rad = a.center.dist(s.from);
            // The left of a counter-clockwise arc is toward its centre.
            let inward = (side == Side::Left) == a.ccw;
            Offset::Circle {
                c: a.center,
                radius: if inward { rad - r } else { rad + r },
                ccw: a.ccw,
            }
        }
    }
}

/// Intersections of two offset elements.
fn intersect(a: Offset, b: Offset) -> Vec<Pt> {
    match (a, b) {
        (Offset::Line { p, d }, Offset::Line { p: q, d: e }) => {
            let den = d.cross(e);
            if den.abs() < 1e-12 {
                return vec![];
            }
            let t = ((q - p).cross(e)) / den;
            vec![(p + (d * t))]
        }
        (Offset::Line { p, d }, Offset::Circle { c, radius, .. })
        | (Offset::Circle { c, radius, .. }, Offset::Line { p, d }) => {
            let f = p - c;
            let bq = f.dot(d);
            let cq = (f.dot(f)) - radius * radius;
            let disc = bq * bq - cq;
            if disc < 0.0 {
                return vec![];
            }
            let s = disc.sqrt();
            vec![(p + (d * (-bq - s))), (p + (d * (-bq + s)))]
        }
        (
            Offset::Circle {
                c: c1, radius: r1, ..
            },
            Offset::Circle {
                c: c2, radius: r2, ..
            },
        ) => {
            let dv = c2 - c1;
            let dd = dv.z.hypot(dv.r);
            if dd < 1e-12 || dd > r1 + r2 || dd < (r1 - r2).abs() {
                return vec![];
            }
            let a = (r1 * r1 - r2 * r2 + dd * dd) / (2.0 * dd);
            let h = (r1 * r1 - a * a).max(0.0).sqrt();
            let m = c1 + (dv * (a / dd));
            let n = Pt::new(-dv.r / dd, dv.z / dd);
            vec![(m + (n * h)), (m + (n * (-h)))]
        }
    }
}

/// Position of `p` along an offset element, in the element's direction of travel from `from`
/// (a length for lines, an angle for arcs), used to detect elements that run backwards.
fn progress(o: Offset, from: Pt, p: Pt) -> f64 {
    match o {
        Offset::Line { d, .. } => (p - from).dot(d),
        Offset::Circle { c, ccw, .. } => {
            let a0 = (from.r - c.r).atan2(from.z - c.z);
            let a1 = (p.r - c.r).atan2(p.z - c.z);
            let mut t = a1 - a0;
            if !ccw {
                t = -t;
            }
            let tau = std::f64::consts::TAU;
            t.rem_euclid(tau)
        }
    }
}

/// Two elements whose perpendicular points at the joint are closer than this (mm) join
/// smoothly: the arc end-point tolerance of `arc.rs`.
const TANGENT_TOL_MM: f64 = 0.005;

/// The result of compensating one section.
pub(crate) struct Compensated {
    /// Segments moving the imaginary tip.
    pub(crate) segments: Vec<Segment>,
    /// Interference alarms (the path is still emitted).
    pub(crate) alarms: Vec<Diagnostic>,
}

/// Compensate one section: `section[0]` is the start-up move, and the last move is the
/// cancel move when `cancelled` (else the section simply ends compensated at the last
/// move's perpendicular point, which is what "the last motion before G40 is the cancel
/// block" means for a section with no following motion: the last move ends uncompensated).
pub(crate) fn compensate(section: &[Segment], side: Side, nose: Nose) -> Compensated {
    let mut out = Compensated {
        segments: vec![],
        alarms: vec![],
    };
    let r = nose.radius;
    // A section with only one move does not compensate (seed 004).
    if section.len() < 2 || r <= 0.0 {
        out.segments.extend_from_slice(section);
        return out;
    }
    let first = &section[0];
    let last = section.len() - 1;
    // Elements 1..last are compensated; 0 is the start-up, `last` the cancel.
    let body = &section[1..last];
    // A contour below the axis is cut from a rear post, where the tip number reads the same
    // as on the front (spec/tnrc.md): in program X the tip vector is its mirror.
    let rear = body.iter().map(|s| s.from.r + s.to.r).sum::<f64>() < 0.0;
    let tip = nose.tip_vector();
    let tip = if rear { Pt::new(tip.z, -tip.r) } else { tip };

    if body.is_empty() {
        // Start-up straight into cancel: the nose touches nothing in between.
        out.segments.extend_from_slice(section);
        return out;
    }

    let path = Path {
        body,
        offsets: body.iter().map(|s| offset_of(s, side, r)).collect(),
        side,
        r,
        tip,
    };
    // Start-up: ends perpendicular to the next block's start (type A).
    let mut cur = path.perp(0, false);
    out.segments.push(Segment {
        to: cur + tip,
        arc: None,
        ..*first
    });
    for i in 0..body.len() {
        cur = path.element(i, cur, &mut out);
    }
    // Cancel: from the perpendicular point to the programmed end.
    let cancel = &section[last];
    out.segments.push(Segment {
        from: cur + tip,
        arc: None,
        ..*cancel
    });
    out
}

/// The compensated body of a section: its elements, their offsets, the side, the nose
/// radius and the tip vector (the programmed point's offset from the nose centre).
struct Path<'s> {
    body: &'s [Segment],
    offsets: Vec<Offset>,
    side: Side,
    r: f64,
    tip: Pt,
}

impl Path<'_> {
    /// The perpendicular point at the start (or end) of element `i`.
    fn perp(&self, i: usize, at_end: bool) -> Pt {
        let s = &self.body[i];
        let p = if at_end { s.to } else { s.from };
        p + (normal(self.side, tangent(s, at_end)) * self.r)
    }

    /// Compensate element `i` from `cur`: its offset move, and at an outside corner the
    /// roll round the programmed corner point. Where the nose centre is after it.
    fn element(&self, i: usize, cur: Pt, out: &mut Compensated) -> Pt {
        let s = &self.body[i];
        let o = self.offsets[i];
        let tip = self.tip;
        if let Offset::Circle { radius, .. } = o {
            if radius <= 1e-9 {
                out.alarms.push(interference(
                    s,
                    "the concave arc is smaller than the nose radius",
                ));
            }
        }
        let (end, corner_arc) = self.joint(i, &mut out.alarms);
        // The element must still run forward from `cur` to `end`.
        if !runs_forward(o, cur, end, self.perp(i, false), self.perp(i, true)) {
            out.alarms.push(interference(s, "the nose radius is too large for this element: the offset path would run backwards"));
        }
        let arc = match (s.arc, o) {
            (Some(a), Offset::Circle { c, .. }) => Some(Arc {
                center: (c + tip),
                ccw: a.ccw,
            }),
            _ => None,
        };
        if cur.dist(end) > 1e-12 {
            out.segments.push(Segment {
                from: cur + tip,
                to: end + tip,
                arc,
                ..*s
            });
        }
        let Some((a, b)) = corner_arc else {
            return end;
        };
        // Roll round the outside corner about the programmed corner point.
        if a.dist(b) > 1e-12 {
            let corner = s.to;
            let ccw = self.side == Side::Right;
            out.segments.push(Segment {
                from: a + tip,
                to: b + tip,
                arc: Some(Arc {
                    center: (corner + tip),
                    ccw,
                }),
                ..*s
            });
        }
        b
    }

    /// Where element `i` ends: the joint with the next one (the offsets' intersection at an
    /// inside corner, the perpendicular point at an outside one, which the corner arc then
    /// leaves from its end to the next start), or perpendicular at the end of the last.
    fn joint(&self, i: usize, alarms: &mut Vec<Diagnostic>) -> (Pt, Option<(Pt, Pt)>) {
        let s = &self.body[i];
        if i + 1 >= self.body.len() {
            return (self.perp(i, true), None);
        }
        let t1 = tangent(s, true);
        let t2 = tangent(&self.body[i + 1], false);
        let turn = t1.cross(t2);
        // Tangency within the control's tolerance is tangency: programs carry 3-decimal
        // coordinates, so a "tangent" arc end is off by a few µm and its tangent by
        // ~0.001 rad. Where the two perpendicular points are closer than the arc end
        // tolerance, the joint is smooth (an inside corner that small has offset paths
        // that meet far away or not at all: a false PS041).
        let smooth = turn.abs() * self.r < TANGENT_TOL_MM && t1.dot(t2) > 0.0;
        let outside = !smooth
            && ((t1.dot(t2)) < 0.0 && turn.abs() < 1e-9
                || (self.side == Side::Left) == (turn < 0.0));
        if smooth {
            return (self.perp(i + 1, false), None);
        }
        if outside {
            return (
                self.perp(i, true),
                Some((self.perp(i, true), self.perp(i + 1, false))),
            );
        }
        let near = self.perp(i, true);
        let end = match intersect(self.offsets[i], self.offsets[i + 1])
            .into_iter()
            .min_by(|a, b| a.dist(near).total_cmp(&b.dist(near)))
        {
            Some(p) => p,
            None => {
                alarms.push(interference(
                    s,
                    "the offset paths of this block and the next do not meet",
                ));
                near
            }
        };
        (end, None)
    }
}

/// Whether an offset element still runs forward from `cur` to `end` (a joint made smooth
/// within `TANGENT_TOL_MM` may end that much past the element); `nominal_*`: its
/// perpendicular points.
fn runs_forward(o: Offset, cur: Pt, end: Pt, nominal_start: Pt, nominal_end: Pt) -> bool {
    match o {
        Offset::Line { .. } => progress(o, cur, end) > -TANGENT_TOL_MM,
        Offset::Circle { radius, .. } => {
            let slack = 1e-9 + TANGENT_TOL_MM / radius.max(TANGENT_TOL_MM);
            let full = progress(o, nominal_start, nominal_end);
            let a = progress(o, nominal_start, cur);
            let b = progress(o, nominal_start, end);
            let tau = std::f64::consts::TAU;
            let norm = |x: f64| if x > tau - slack { x - tau } else { x };
            let (a, b) = (norm(a), norm(b));
            b + slack >= a && b <= full.max(1e-12) + slack || full < 1e-12
        }
    }
}

fn interference(s: &Segment, what: &str) -> Diagnostic {
    Diagnostic::new(
        s.span,
        "PS041",
        format!("tool nose radius interference: {what}"),
        "use a tool with a smaller nose radius, or a larger inside radius / longer element in the contour",
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Motion, Span, ToolHint};

    fn line(from: Pt, to: Pt) -> Segment {
        Segment {
            motion: Motion::Feed,
            from,
            to,
            arc: None,
            tool: 1,
            hint: ToolHint::Table,
            lead: 0.0,
            thread_phase: 0.0,
            feed: crate::FeedId::default(),
            span: Span::default(),
        }
    }

    #[test]
    fn tip_vectors_follow_the_fanuc_table() {
        let n = |tip| Nose { radius: 1.0, tip }.tip_vector();
        assert_eq!(n(1), Pt::new(1.0, 1.0));
        assert_eq!(n(2), Pt::new(-1.0, 1.0));
        assert_eq!(n(3), Pt::new(-1.0, -1.0));
        assert_eq!(n(4), Pt::new(1.0, -1.0));
        assert_eq!(n(5), Pt::new(1.0, 0.0));
        assert_eq!(n(6), Pt::new(0.0, 1.0));
        assert_eq!(n(7), Pt::new(-1.0, 0.0));
        assert_eq!(n(8), Pt::new(0.0, -1.0));
        assert_eq!(n(0), Pt::new(0.0, 0.0));
        assert_eq!(n(9), Pt::new(0.0, 0.0));
    }

    #[test]
    fn od_turning_with_g42_puts_the_nose_above_the_contour() {
        // Start-up down to Z0 at r=5, turn along r=5 to Z-10, cancel up.
        let s = [
            line(Pt::new(5.0, 10.0), Pt::new(0.0, 10.0)),
            line(Pt::new(0.0, 10.0), Pt::new(-10.0, 10.0)),
            line(Pt::new(-10.0, 10.0), Pt::new(-10.0, 20.0)),
        ];
        let c = compensate(
            &s,
            Side::Right,
            Nose {
                radius: 1.0,
                tip: 0,
            },
        );
        assert!(c.alarms.is_empty());
        // moving −Z, the right side is +r: nose centre at r = 11, start-up ends at (0, 11)
        assert_eq!(c.segments[0].to, Pt::new(0.0, 11.0));
        assert_eq!(c.segments[1].to, Pt::new(-10.0, 11.0));
        assert_eq!(c.segments[2].from, Pt::new(-10.0, 11.0));
        // with tip 3 the imaginary tip is the nose centre − (1, 1): it runs on the contour
        let c = compensate(
            &s,
            Side::Right,
            Nose {
                radius: 1.0,
                tip: 3,
            },
        );
        assert_eq!(c.segments[1].from, Pt::new(-1.0, 10.0));
        assert_eq!(c.segments[1].to, Pt::new(-11.0, 10.0));
    }

    #[test]
    fn inside_corner_uses_the_intersection() {
        // Along r=10 toward −Z, then up a shoulder: an inside corner for G42 (tool above).
        let s = [
            line(Pt::new(5.0, 10.0), Pt::new(0.0, 10.0)),
            line(Pt::new(0.0, 10.0), Pt::new(-10.0, 10.0)),
            line(Pt::new(-10.0, 10.0), Pt::new(-10.0, 20.0)),
            line(Pt::new(-10.0, 20.0), Pt::new(-20.0, 20.0)),
        ];
        let c = compensate(
            &s,
            Side::Right,
            Nose {
                radius: 1.0,
                tip: 0,
            },
        );
        assert!(c.alarms.is_empty());
        // moving up +r at z=-10, the right side is +z: offset line z = -9; meets r = 11 at (-9, 11)
        assert_eq!(c.segments[1].to, Pt::new(-9.0, 11.0));
        assert_eq!(c.segments[2].from, Pt::new(-9.0, 11.0));
    }

    #[test]
    fn outside_corner_rolls_round_the_corner() {
        // Face down then turn: r=20 → r=10 at z=0 (moving −r), then along −Z: a left turn… for G42
        let s = [
            line(Pt::new(5.0, 25.0), Pt::new(0.0, 25.0)),
            line(Pt::new(0.0, 25.0), Pt::new(0.0, 10.0)),
            line(Pt::new(0.0, 10.0), Pt::new(-10.0, 10.0)),
            line(Pt::new(-10.0, 10.0), Pt::new(-10.0, 30.0)),
        ];
        // moving −r then −z: G41 (left of −r travel is +z … ) keeps the nose outside the corner
        let c = compensate(
            &s,
            Side::Left,
            Nose {
                radius: 1.0,
                tip: 0,
            },
        );
        assert!(c.alarms.is_empty(), "{:?}", c.alarms);
        let arc = c
            .segments
            .iter()
            .find(|s| s.arc.is_some())
            .expect("a corner arc");
        assert_eq!(arc.arc.unwrap().center, Pt::new(0.0, 10.0));
        assert!((arc.from.dist(Pt::new(0.0, 10.0)) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn short_element_is_interference() {
        // A 0.5 mm step between two inside corners with a 1 mm nose.
        let s = [
            line(Pt::new(5.0, 10.0), Pt::new(0.0, 10.0)),
            line(Pt::new(0.0, 10.0), Pt::new(-10.0, 10.0)),
            line(Pt::new(-10.0, 10.0), Pt::new(-10.0, 10.5)),
            line(Pt::new(-10.0, 10.5), Pt::new(-10.5, 10.5)),
            line(Pt::new(-10.5, 10.5), Pt::new(-10.5, 20.0)),
            line(Pt::new(-10.5, 20.0), Pt::new(-20.0, 20.0)),
        ];
        let c = compensate(
            &s,
            Side::Right,
            Nose {
                radius: 1.0,
                tip: 0,
            },
        );
        assert!(!c.alarms.is_empty());
        assert_eq!(c.alarms[0].code, "PS041");
    }
}
