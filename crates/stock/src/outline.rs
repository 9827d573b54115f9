//! Tool outlines: closed polygons in (z, r) relative to the tool's reference point.
//!
//! Only the cutting insert (or blade, drill, threading insert) is modelled, not the holder
//! body: the insert is what touches the part in normal work, and a holder outline would
//! need dimensions the tool table does not carry.

use geom::arc::Arc;
use geom::flat::{convex_hull, convex_parts, pts, P};
use geom::{Pt, Rect};

/// Largest distance between a chorded nose and the true arc, mm.
pub(crate) const NOSE_CHORD_TOL: f64 = 0.001;

/// A tool outline as convex parts, each counter-clockwise, relative to the reference point
/// (the point the program moves).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Outline {
    /// Convex parts, counter-clockwise, relative to the reference point.
    pub parts: Vec<Vec<[f64; 2]>>,
    /// What becomes of the outline's part that reaches past the axis.
    pub past_axis: PastAxis,
}

/// What becomes of a tool outline's part beyond the axis (spec/simulation.md, "Tools past
/// the axis" and "Only stated geometry past the axis").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PastAxis {
    /// Folded into the section (mirrored): the part is a solid of revolution, so a tool
    /// point at distance d behind the axis meets the part where its radius exceeds d. For
    /// tools whose size the table states.
    #[default]
    Fold,
    /// Left out of the cut and of every crash test: the outline's size is a guess (a
    /// default insert or blade, an insert whose edge is not given), and a guess must not
    /// make a crash. A front-post tool keeps its part above the axis.
    DropBelow,
    /// The same for a rear-post tool (it works at negative X): its part below the axis is
    /// kept (mirrored into the section), the part above it left out.
    DropAbove,
}

impl Outline {
    /// An outline from one simple ring of any orientation, split into convex parts.
    pub fn from_ring(ring: &[[f64; 2]]) -> Self {
        Self {
            parts: convex_parts(ring)
                .into_iter()
                .filter(|p| p.len() >= 3)
                .collect(),
            past_axis: PastAxis::Fold,
        }
    }

    /// Bounding box as (min, max), or `None` for an empty outline.
    pub fn bbox(&self) -> Option<([f64; 2], [f64; 2])> {
        let r = Rect::of(self.parts.iter().flat_map(|p| pts(p)));
        (!r.is_empty()).then_some((r.min.into(), r.max.into()))
    }

    /// Largest distance of any outline point from the reference point.
    pub fn reach(&self) -> f64 {
        self.parts
            .iter()
            .flatten()
            .map(|p| p[0].hypot(p[1]))
            .fold(0.0, f64::max)
    }

    /// The outline mirrored about the axis (r -> -r): the same tool on the other side.
    pub fn mirrored(&self) -> Self {
        self.map(|p| [p[0], -p[1]])
    }

    fn map(&self, f: impl Fn(P) -> P) -> Self {
        Self {
            parts: self
                .parts
                .iter()
                .map(|part| convex_hull(&part.iter().map(|&p| f(p)).collect::<Vec<_>>()))
                .collect(),
            past_axis: self.past_axis,
        }
    }
}

/// Points of the arc of `radius` around `c` from angle `a0` over `sweep` radians, chords
/// within [`NOSE_CHORD_TOL`] of the arc.
fn arc_points(c: P, radius: f64, a0: f64, sweep: f64) -> Vec<P> {
    if radius <= 0.0 {
        return vec![c];
    }
    let arc = Arc {
        center: c.into(),
        radius,
        start: a0,
        sweep,
    };
    let mut pts: Vec<P> = arc
        .flatten(NOSE_CHORD_TOL)
        .into_iter()
        .map(Pt::to_array)
        .collect();
    // the extreme points along ±Z and ±X are where the part is measured: include them exactly
    let (lo, hi) = if sweep >= 0.0 {
        (a0, a0 + sweep)
    } else {
        (a0 + sweep, a0)
    };
    let quarter = std::f64::consts::FRAC_PI_2;
    let mut k = (lo / quarter).ceil();
    while k * quarter <= hi && pts.len() < 100_010 {
        let q =
            [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]][(k as i64).rem_euclid(4) as usize];
        pts.push([c[0] + radius * q[0], c[1] + radius * q[1]]);
        k += 1.0;
    }
    pts
}

fn dir(deg: f64) -> P {
    let a = deg.to_radians();
    [a.cos(), a.sin()]
}

/// The body of a turning insert, without its nose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum InsertBody {
    /// Parallelogram (C, D, V, S): edges of length `edge` along both edge directions.
    Rhombic,
    /// Isosceles triangle (T, W): two edges of length `edge` from the cutting corner.
    Triangle,
    /// Round insert: a disc of the nose radius.
    Round,
}

/// A turning insert outline.
///
/// `included` ε and `entering` κr in degrees. For tip 3 the leading edge leaves the
/// cutting corner at 180° − κr from +Z and the trailing edge at 180° − κr − ε; the nose is
/// the arc of `nose_radius` tangent to both; the reference point is the imaginary tip
/// (nose centre + (−r, −r)). Tips 2, 4, 1 mirror tip 3 in r, z, both; tips 5–8 point the
/// bisector along +Z, +X, −Z, −X (reference: nose centre + r along that axis); tips 0 and 9
/// keep the tip-3 orientation with the reference at the nose centre.
pub(crate) fn turning(
    body: InsertBody,
    included: f64,
    nose_radius: f64,
    tip: u8,
    entering: f64,
    edge: f64,
) -> Outline {
    let r = nose_radius.max(0.0);
    if body == InsertBody::Round {
        let c = match tip {
            1 => [-r, -r],
            2 => [r, -r],
            3 => [r, r],
            4 => [-r, r],
            5 => [-r, 0.0],
            6 => [0.0, -r],
            7 => [r, 0.0],
            8 => [0.0, r],
            _ => [0.0, 0.0],
        };
        let pts = arc_points(c, r.max(1e-3), 0.0, std::f64::consts::TAU);
        return Outline {
            parts: vec![convex_hull(&pts)],
            past_axis: PastAxis::Fold,
        };
    }
    // (direction of the leading edge, of the trailing edge) from the cutting corner
    let axis_tip: Option<P> = match tip {
        5 => Some([1.0, 0.0]),
        6 => Some([0.0, 1.0]),
        7 => Some([-1.0, 0.0]),
        8 => Some([0.0, -1.0]),
        _ => None,
    };
    let (a1, a2) = match axis_tip {
        Some(t) => {
            let back = (-t[1]).atan2(-t[0]).to_degrees();
            (back + included / 2.0, back - included / 2.0)
        }
        None => (180.0 - entering, 180.0 - entering - included),
    };
    let (u1, u2) = (dir(a1), dir(a2));
    let half = (included / 2.0).to_radians();
    let b = dir((a1 + a2) / 2.0);
    let c = [b[0] * r / half.sin(), b[1] * r / half.sin()];
    // the nose turns around the outside, through the direction opposite the bisector
    let n1 = (a1 + 90.0).to_radians();
    let mut pts = arc_points(c, r, n1, (180.0 - included).to_radians());
    let e = edge.max(r / half.tan() + 1e-6);
    let far1 = [u1[0] * e, u1[1] * e];
    let far2 = [u2[0] * e, u2[1] * e];
    pts.push(far1);
    pts.push(far2);
    if body == InsertBody::Rhombic {
        pts.push([far1[0] + far2[0], far1[1] + far2[1]]);
    }
    let reference = match (axis_tip, tip) {
        (Some(t), _) => [c[0] + r * t[0], c[1] + r * t[1]],
        (None, 0 | 9) => c,
        (None, _) => [c[0] - r, c[1] - r],
    };
    let tip3 = Outline {
        parts: vec![convex_hull(
            &pts.iter()
                .map(|p| [p[0] - reference[0], p[1] - reference[1]])
                .collect::<Vec<_>>(),
        )],
        past_axis: PastAxis::Fold,
    };
    match tip {
        2 => tip3.map(|p| [p[0], -p[1]]),
        4 => tip3.map(|p| [-p[0], p[1]]),
        1 => tip3.map(|p| [-p[0], -p[1]]),
        _ => tip3,
    }
}

/// A grooving blade: `width` along `width_axis` (a unit axis vector), body of length `reach`
/// along `shank_axis`; the reference is the corner at the cutting edge where the width
/// starts; the two cutting-edge corners are rounded with `corner_radius`.
pub(crate) fn grooving(
    width: f64,
    width_axis: P,
    shank_axis: P,
    reach: f64,
    corner_radius: f64,
) -> Outline {
    let rho = corner_radius.clamp(0.0, width / 2.0);
    // local (w, s) coordinates: w across the blade, s along the shank
    let mut local = arc_points(
        [rho, rho],
        rho,
        std::f64::consts::PI,
        std::f64::consts::FRAC_PI_2,
    );
    local.extend(arc_points(
        [width - rho, rho],
        rho,
        1.5 * std::f64::consts::PI,
        std::f64::consts::FRAC_PI_2,
    ));
    local.push([width, reach]);
    local.push([0.0, reach]);
    let pts: Vec<P> = local
        .iter()
        .map(|&[w, s]| {
            [
                w * width_axis[0] + s * shank_axis[0],
                w * width_axis[1] + s * shank_axis[1],
            ]
        })
        .collect();
    Outline {
        parts: vec![convex_hull(&pts)],
        past_axis: PastAxis::Fold,
    }
}

/// A drill of `diameter` with `point_angle` (degrees), point at the reference on the axis,
/// body toward +z for `reach` mm; kept symmetric about the axis.
pub(crate) fn drill(diameter: f64, point_angle: f64, reach: f64) -> Outline {
    let rad = diameter / 2.0;
    let h = rad / (point_angle / 2.0).to_radians().tan();
    let len = reach.max(h + 1e-6);
    Outline {
        parts: vec![convex_hull(&[
            [0.0, 0.0],
            [h, rad],
            [len, rad],
            [len, -rad],
            [h, -rad],
        ])],
        past_axis: PastAxis::Fold,
    }
}

/// Height of a threading insert's profile (flanks at the thread angle), mm.
pub(crate) const THREAD_PROFILE_HEIGHT: f64 = 3.0;
/// Height of the insert body above the profile (parallel sides), mm.
pub(crate) const THREAD_BODY_HEIGHT: f64 = 12.0;

/// A threading insert: reference at the middle of its tip flat, flanks at ±angle/2 from the
/// X axis for [`THREAD_PROFILE_HEIGHT`], then a body with parallel sides up to
/// [`THREAD_BODY_HEIGHT`] more; toward +X (an OD insert pointing −X), or mirrored toward −X
/// when `inside` (an ID insert in the bore pointing +X).
pub(crate) fn threading(angle: f64, tip_flat: f64, inside: bool) -> Outline {
    let f = tip_flat / 2.0;
    let w = f + THREAD_PROFILE_HEIGHT * (angle / 2.0).to_radians().tan();
    let top = THREAD_PROFILE_HEIGHT + THREAD_BODY_HEIGHT;
    let pts = [
        [-f, 0.0],
        [f, 0.0],
        [w, THREAD_PROFILE_HEIGHT],
        [w, top],
        [-w, top],
        [-w, THREAD_PROFILE_HEIGHT],
    ]
    .map(|[z, r]| if inside { [z, -r] } else { [z, r] });
    Outline {
        parts: vec![convex_hull(&pts)],
        past_axis: PastAxis::Fold,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn edge_angles(o: &Outline) -> Vec<(f64, f64)> {
        let p = &o.parts[0];
        (0..p.len())
            .map(|i| {
                let (a, b) = (p[i], p[(i + 1) % p.len()]);
                let d = [b[0] - a[0], b[1] - a[1]];
                (
                    d[1].atan2(d[0]).to_degrees().rem_euclid(360.0),
                    d[0].hypot(d[1]),
                )
            })
            .collect()
    }

    #[test]
    fn tip3_35deg_insert_has_its_edges_at_87_and_52_degrees() {
        let o = turning(InsertBody::Rhombic, 35.0, 0.4, 3, 93.0, 11.0);
        let edges = edge_angles(&o);
        // CCW walk: the trailing edge runs away from the nose at 52°, the leading edge
        // comes back down toward the nose, i.e. along 87° + 180°
        let long = |deg: f64| {
            edges
                .iter()
                .any(|&(a, l)| l > 5.0 && (a - deg).abs() < 1e-6)
        };
        assert!(long(52.0), "{edges:?}");
        assert!(long(267.0), "{edges:?}");
        // the insert lies up and to the right of its imaginary tip, touching both tangents
        let (min, _) = o.bbox().unwrap();
        assert!(min[0].abs() < 1e-12 && min[1].abs() < 1e-12, "{min:?}");
        assert!(o.parts[0].iter().all(|p| p[0] >= -1e-9 && p[1] >= -1e-9));
    }

    #[test]
    fn nose_is_a_true_arc_of_the_nose_radius() {
        let r = 0.8;
        let o = turning(InsertBody::Rhombic, 55.0, r, 3, 93.0, 11.0);
        // nose centre of tip 3 is at (r, r) from the imaginary tip
        let near: Vec<f64> = o.parts[0]
            .iter()
            .map(|p| (p[0] - r).hypot(p[1] - r))
            .filter(|d| *d < r + 0.01)
            .collect();
        assert!(near.len() > 10, "{near:?}");
        assert!(near.iter().all(|d| (d - r).abs() < 1e-9), "{near:?}");
        // consecutive nose points are close enough for a 0.001 mm chord error
        let step = 2.0 * (2.0 * r * NOSE_CHORD_TOL).sqrt();
        let nose: Vec<&P> = o.parts[0]
            .iter()
            .filter(|p| ((p[0] - r).hypot(p[1] - r) - r).abs() < 1e-9)
            .collect();
        // walking the hull cyclically, the only long jump between nose points is across the body
        let n = nose.len();
        let gaps = (0..n).filter(|&i| {
            let (a, b) = (nose[i], nose[(i + 1) % n]);
            (a[0] - b[0]).hypot(a[1] - b[1]) > step + 1e-9
        });
        assert_eq!(gaps.count(), 1);
    }

    #[test]
    fn tips_mirror_and_rotate_as_the_table_says() {
        let quadrant = |tip: u8| {
            let o = turning(InsertBody::Rhombic, 55.0, 0.4, tip, 93.0, 11.0);
            let (min, max) = o.bbox().unwrap();
            let c = [(min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0];
            (c[0].signum(), c[1].signum())
        };
        // tip direction from nose centre (tnrc.md); the body lies on the opposite side
        assert_eq!(quadrant(3), (1.0, 1.0));
        assert_eq!(quadrant(2), (1.0, -1.0));
        assert_eq!(quadrant(4), (-1.0, 1.0));
        assert_eq!(quadrant(1), (-1.0, -1.0));
        let axis = |tip: u8| {
            let o = turning(InsertBody::Rhombic, 55.0, 0.4, tip, 93.0, 11.0);
            let (min, max) = o.bbox().unwrap();
            (min, max)
        };
        let (min5, _) = axis(5);
        assert!(min5[0] < -5.0 && axis(5).1[0].abs() < 1e-9);
        assert!(axis(6).1[1].abs() < 1e-9 && axis(6).0[1] < -5.0);
        assert!(axis(7).0[0].abs() < 1e-9 && axis(7).1[0] > 5.0);
        assert!(axis(8).0[1].abs() < 1e-9 && axis(8).1[1] > 5.0);
        // tip 0/9: reference at the nose centre, so the tip-3 outline shifted by (r, r)
        let t3 = turning(InsertBody::Rhombic, 55.0, 0.4, 3, 93.0, 11.0)
            .bbox()
            .unwrap();
        for tip in [0, 9] {
            let t = turning(InsertBody::Rhombic, 55.0, 0.4, tip, 93.0, 11.0)
                .bbox()
                .unwrap();
            assert!(
                (t.0[0] - (t3.0[0] - 0.4)).abs() < 1e-9 && (t.0[1] - (t3.0[1] - 0.4)).abs() < 1e-9
            );
        }
        // tips 1, 2, 4 are exact mirrors of tip 3
        let t3 = turning(InsertBody::Rhombic, 55.0, 0.4, 3, 93.0, 11.0).parts[0].clone();
        let t1 = turning(InsertBody::Rhombic, 55.0, 0.4, 1, 93.0, 11.0).parts[0].clone();
        assert!(t3.iter().all(|p| t1
            .iter()
            .any(|q| (q[0] + p[0]).abs() < 1e-12 && (q[1] + p[1]).abs() < 1e-12)));
    }

    #[test]
    fn seed_002_blade_is_the_expected_rectangle() {
        let o = grooving(3.0, [1.0, 0.0], [0.0, 1.0], 20.0, 0.0);
        assert_eq!(o.bbox().unwrap(), ([0.0, 0.0], [3.0, 20.0]));
        assert!((geom::ring::signed_area(&pts(&o.parts[0])) - 60.0).abs() < 1e-12);
    }

    #[test]
    fn drill_and_thread_tool_shapes() {
        let d = drill(10.0, 118.0, 60.0);
        let (min, max) = d.bbox().unwrap();
        assert_eq!((min[0], max[0], min[1], max[1]), (0.0, 60.0, -5.0, 5.0));
        let t = threading(60.0, 0.0, false);
        let p = &t.parts[0];
        assert!(p.contains(&[0.0, 0.0]) || p.iter().any(|q| q[1] == 0.0 && q[0].abs() < 1e-12));
        let (min, max) = t.bbox().unwrap();
        assert!((max[0] - 3.0 * 30f64.to_radians().tan()).abs() < 1e-12 && min[1] == 0.0);
        assert_eq!(max[1], 15.0);
        // the ID insert is its mirror: tip at the reference, body toward −X
        let (min, max) = threading(60.0, 0.0, true).bbox().unwrap();
        assert_eq!((min[1], max[1]), (-15.0, 0.0));
        assert!((max[0] - 3.0 * 30f64.to_radians().tan()).abs() < 1e-12);
    }
}
