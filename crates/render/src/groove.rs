//! Geometry of a groove detail view: the ring cleaned up, its principal corners, and
//! where the corner labels go. How far the final part strays from the groove is measured
//! by the simulator (`stock::groove_deviation`) and handed over in the report.

use crate::scale::Bbox;
use geom::{ring, Pt};

/// A ring vertex is a principal corner when the outline turns there by more than this.
const CORNER_TURN_DEG: f64 = 20.0;
/// At most this many corner labels per groove.
pub(crate) const MAX_CORNER_LABELS: usize = 6;

/// The ring's distinct finite corners (the `geom` kernel's cleaning); `None` when fewer
/// than three remain.
pub(crate) fn clean_ring(ring: &[[f64; 2]]) -> Option<Vec<[f64; 2]>> {
    let pts: Vec<Pt> = ring.iter().map(|&p| Pt::from(p)).collect();
    Some(ring::cleaned(&pts)?.iter().map(|p| p.to_array()).collect())
}

/// Bounding box of a ring.
pub(crate) fn ring_box(ring: &[[f64; 2]]) -> Bbox {
    let mut b = Bbox::EMPTY;
    for p in ring {
        b.add(*p);
    }
    b
}

/// Indices of the ring's principal corners: vertices where the direction turns by more
/// than 20°, in ring order; when there are more than six, the six sharpest.
pub(crate) fn corners(ring: &[[f64; 2]]) -> Vec<usize> {
    let n = ring.len();
    let mut turns: Vec<(usize, f64)> = (0..n)
        .filter_map(|i| {
            let (a, p, b) = (ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
            let (u, v) = ([p[0] - a[0], p[1] - a[1]], [b[0] - p[0], b[1] - p[1]]);
            let cross = u[0] * v[1] - u[1] * v[0];
            let dot = u[0] * v[0] + u[1] * v[1];
            let turn = cross.abs().atan2(dot).to_degrees();
            (turn > CORNER_TURN_DEG).then_some((i, turn))
        })
        .collect();
    if turns.len() > MAX_CORNER_LABELS {
        turns.sort_by(|x, y| y.1.total_cmp(&x.1).then(x.0.cmp(&y.0)));
        turns.truncate(MAX_CORNER_LABELS);
    }
    let mut idx: Vec<usize> = turns.into_iter().map(|t| t.0).collect();
    idx.sort_unstable();
    idx
}

/// A corner label: `P1 Z30.00 Φ50.00` (program coordinates, Φ = diameter = 2r).
pub(crate) fn corner_label(k: usize, p: [f64; 2]) -> String {
    format!("P{k} Z{} Φ{}", f2(p[0]), f2(2.0 * p[1]))
}

/// Two decimals, never `-0.00`.
fn f2(v: f64) -> String {
    let s = format!("{v:.2}");
    if s == "-0.00" {
        "0.00".to_string()
    } else {
        s
    }
}

/// The deviation as shown in a title: rounded up to 0.001 mm, at least 0.001.
pub(crate) fn shown_deviation(d: f64) -> f64 {
    ((d * 1000.0 - 1e-6).ceil() / 1000.0).max(0.001)
}

/// A px box: left, top, right, bottom.
pub(crate) type PxBox = [f64; 4];

fn boxes_overlap(a: &PxBox, b: &PxBox) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Whether the px segment `a`–`b` meets the box (Liang–Barsky clipping).
fn seg_hits_box(a: [f64; 2], b: [f64; 2], r: &PxBox) -> bool {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a[0] - r[0]),
        (dx, r[2] - a[0]),
        (-dy, a[1] - r[1]),
        (dy, r[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

/// Place one label per corner (px points `at`, label sizes `size` = [w, h]) inside
/// `frame` (left, top, right, bottom): each label goes to one of eight places around its
/// corner, preferring the side away from the ring's centre `centre` and places that
/// cross no ring edge (`ring` in px); labels never overlap each other, cover another
/// corner, or leave the frame. A label with no free place gets `None` (left out).
pub(crate) fn place_labels(
    at: &[[f64; 2]],
    size: &[[f64; 2]],
    centre: [f64; 2],
    ring: &[[f64; 2]],
    frame: PxBox,
) -> Vec<Option<PxBox>> {
    const GAP: f64 = 5.0;
    let mut placed: Vec<PxBox> = Vec::new();
    let mut out = Vec::with_capacity(at.len());
    for (i, (&[x, y], &[w, h])) in at.iter().zip(size).enumerate() {
        let out_dir = {
            let (dx, dy) = (x - centre[0], y - centre[1]);
            let l = dx.hypot(dy);
            if l > 1e-9 {
                [dx / l, dy / l]
            } else {
                [0.0, -1.0]
            }
        };
        // (box, direction of the box from the corner)
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let candidates = [
            ([x + GAP, y - GAP - h, x + GAP + w, y - GAP], [s, -s]),
            ([x - GAP - w, y - GAP - h, x - GAP, y - GAP], [-s, -s]),
            ([x + GAP, y + GAP, x + GAP + w, y + GAP + h], [s, s]),
            ([x - GAP - w, y + GAP, x - GAP, y + GAP + h], [-s, s]),
            (
                [x + GAP + 2.0, y - h / 2.0, x + GAP + 2.0 + w, y + h / 2.0],
                [1.0, 0.0],
            ),
            (
                [x - GAP - 2.0 - w, y - h / 2.0, x - GAP - 2.0, y + h / 2.0],
                [-1.0, 0.0],
            ),
            (
                [x - w / 2.0, y - GAP - 2.0 - h, x + w / 2.0, y - GAP - 2.0],
                [0.0, -1.0],
            ),
            (
                [x - w / 2.0, y + GAP + 2.0, x + w / 2.0, y + GAP + 2.0 + h],
                [0.0, 1.0],
            ),
        ];
        let n = ring.len();
        let best = candidates
            .iter()
            .filter(|(b, _)| {
                b[0] >= frame[0] && b[1] >= frame[1] && b[2] <= frame[2] && b[3] <= frame[3]
            })
            .filter(|(b, _)| !placed.iter().any(|p| boxes_overlap(p, b)))
            .filter(|(b, _)| {
                !at.iter().enumerate().any(|(j, q)| {
                    j != i && boxes_overlap(b, &[q[0] - 4.0, q[1] - 4.0, q[0] + 4.0, q[1] + 4.0])
                })
            })
            .map(|(b, d)| {
                let crossings = (0..n)
                    .filter(|&k| seg_hits_box(ring[k], ring[(k + 1) % n], b))
                    .count();
                let away = 1.0 - (d[0] * out_dir[0] + d[1] * out_dir[1]);
                (crossings as f64 * 4.0 + away, *b)
            })
            .min_by(|p, q| p.0.total_cmp(&q.0))
            .map(|(_, b)| b);
        if let Some(b) = best {
            placed.push(b);
        }
        out.push(best);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trapezoid() -> Vec<[f64; 2]> {
        vec![[30.0, 25.0], [20.0, 15.0], [10.0, 15.0], [-7.32, 25.0]]
    }

    #[test]
    fn trapezoid_has_four_corners_and_labels() {
        let r = trapezoid();
        assert_eq!(corners(&r), vec![0, 1, 2, 3]);
        assert_eq!(corner_label(1, r[0]), "P1 Z30.00 Φ50.00");
        assert_eq!(corner_label(4, r[3]), "P4 Z-7.32 Φ50.00");
    }

    #[test]
    fn gentle_turns_are_not_corners_and_at_most_six() {
        // A 64-gon: every turn is 5.6°.
        let circle: Vec<[f64; 2]> = (0..64)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 64.0;
                [a.cos(), a.sin()]
            })
            .collect();
        assert!(corners(&circle).is_empty());
        // A star with 10 sharp corners keeps six.
        let star: Vec<[f64; 2]> = (0..10)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / 10.0;
                let r = if i % 2 == 0 { 1.0 } else { 0.4 };
                [r * a.cos(), r * a.sin()]
            })
            .collect();
        assert_eq!(corners(&star).len(), 6);
    }

    #[test]
    fn shown_deviation_rounds_up_to_a_micron() {
        assert_eq!(shown_deviation(1e-12), 0.001);
        assert_eq!(shown_deviation(0.2 + 1e-12), 0.2);
        assert_eq!(shown_deviation(0.2004), 0.201);
    }

    #[test]
    fn labels_stay_in_frame_and_apart() {
        let at = [[300.0, 20.0], [200.0, 120.0], [100.0, 120.0], [10.0, 20.0]];
        let size = [[110.0, 15.0]; 4];
        let ring = at.to_vec();
        let frame = [0.0, 0.0, 320.0, 160.0];
        let boxes = place_labels(&at, &size, [150.0, 70.0], &ring, frame);
        let boxes: Vec<PxBox> = boxes.into_iter().map(|b| b.expect("placed")).collect();
        for (i, b) in boxes.iter().enumerate() {
            assert!(b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= 320.0 && b[3] <= 160.0);
            for c in &boxes[i + 1..] {
                assert!(!boxes_overlap(b, c));
            }
        }
    }
}
