//! Which part of a turning insert touches a point: its nose, its leading edge or its
//! trailing edge (spec/simulation.md, "Tools": the leading edge leaves the cutting corner at
//! 180° − κr from +Z, the trailing edge at 180° − κr − ε, for tip 3; tips 2, 4, 1 mirror it).

use geom::flat::P;
use stock::{Insert, Tool};

/// A part of a turning insert's outline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Part {
    Nose,
    Leading,
    Trailing,
}

/// The facts of a turning insert the causes speak of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Facts {
    pub(crate) insert: Insert,
    pub(crate) nose_radius: f64,
    pub(crate) tip: u8,
    /// Entering angle κr, degrees.
    pub(crate) entering: f64,
    /// Included angle ε, degrees.
    pub(crate) included: f64,
    pub(crate) edge: f64,
}

impl Facts {
    /// A turning tool's facts (tips 0–4, 9: the ones with a leading and a trailing edge
    /// along Z); `None` for other tools.
    pub(crate) fn of(tool: &Tool) -> Option<Self> {
        match *tool {
            Tool::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            } if insert != Insert::R && matches!(tip, 0..=4 | 9) => Some(Self {
                insert,
                nose_radius,
                tip,
                entering: entering_angle,
                included: insert.included_angle(),
                edge,
            }),
            _ => None,
        }
    }

    /// The trailing edge's clearance: the steepest flank it can descend, degrees
    /// (180 − κr − ε: 32° for a 55° insert on a 93° holder).
    pub(crate) fn trailing_clearance(&self) -> f64 {
        180.0 - self.entering - self.included
    }

    /// How far the leading edge leans back from a square shoulder, degrees (κr − 90).
    pub(crate) fn leading_lean(&self) -> f64 {
        self.entering - 90.0
    }

    /// The part of the insert nearest to `q`, a point on its outline relative to the
    /// reference point, as mounted on the front post.
    pub(crate) fn part_at(&self, q: P) -> Part {
        // into the tip-3 frame
        let q = match self.tip {
            2 => [q[0], -q[1]],
            4 => [-q[0], q[1]],
            1 => [-q[0], -q[1]],
            _ => q,
        };
        let r = self.nose_radius.max(0.0);
        let c = if matches!(self.tip, 0 | 9) {
            [0.0, 0.0]
        } else {
            [r, r]
        };
        let dir = |deg: f64| {
            let a = deg.to_radians();
            [a.cos(), a.sin()]
        };
        let (a1, a2) = (180.0 - self.entering, 180.0 - self.entering - self.included);
        let edge = |a: f64, normal: f64| {
            let n = dir(normal);
            let t = [c[0] + r * n[0], c[1] + r * n[1]];
            let u = dir(a);
            segment_distance(q, t, [t[0] + u[0] * self.edge, t[1] + u[1] * self.edge])
        };
        let leading = edge(a1, a1 + 90.0);
        let trailing = edge(a2, a2 - 90.0);
        let v = [q[0] - c[0], q[1] - c[1]];
        let on_arc = {
            let ang = v[1].atan2(v[0]).to_degrees();
            let from = a1 + 90.0;
            let span = 180.0 - self.included;
            (ang - from).rem_euclid(360.0) <= span
        };
        let nose = if on_arc {
            (v[0].hypot(v[1]) - r).abs()
        } else {
            f64::INFINITY
        };
        // an edge wins a tie: where the nose meets an edge the edge decides
        if nose + 1e-9 < leading.min(trailing) {
            Part::Nose
        } else if trailing <= leading {
            Part::Trailing
        } else {
            Part::Leading
        }
    }
}

/// Distance from `q` to the segment `a b`.
pub(crate) fn segment_distance(q: P, a: P, b: P) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((q[0] - a[0]) * d[0] + (q[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (q[0] - a[0] - t * d[0]).hypot(q[1] - a[1] - t * d[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sharp D 55° insert on a 93° holder, tip 3: its trailing edge leaves the corner at
    /// 32° (toward +Z, up), its leading edge at 87° (nearly straight up); its clearance is
    /// 32°. A 0.4 nose: the point under the nose centre (r, 0) is on the nose.
    #[test]
    fn parts_of_a_d55_insert_by_hand() {
        let mut f = Facts {
            insert: Insert::D,
            nose_radius: 0.0,
            tip: 3,
            entering: 93.0,
            included: 55.0,
            edge: 11.0,
        };
        assert!((f.trailing_clearance() - 32.0).abs() < 1e-12);
        assert!((f.leading_lean() - 3.0).abs() < 1e-12);
        let at = |deg: f64, l: f64| {
            let a = f64::to_radians(deg);
            [l * a.cos(), l * a.sin()]
        };
        assert_eq!(f.part_at(at(32.0, 5.0)), Part::Trailing);
        assert_eq!(f.part_at(at(87.0, 5.0)), Part::Leading);
        // tip 4 mirrors it in Z: the trailing edge goes toward −Z
        f.tip = 4;
        assert_eq!(
            f.part_at([-at(32.0, 5.0)[0], at(32.0, 5.0)[1]]),
            Part::Trailing
        );
        f.tip = 3;
        f.nose_radius = 0.4;
        assert_eq!(f.part_at([0.4, 0.0]), Part::Nose);
    }
}
