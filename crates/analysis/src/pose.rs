//! Where the tool was when it crashed: the report draws the tool's outline (cutting outline
//! and body) at the first point of its move where the part that hit reaches the crash's
//! contact point, so a machinist sees what met what.

use expander::{Segment, ToolHint};
use geom::flat::{convex_hull, P};
use stock::{chord_sweeps, move_path, Mounted, Outline, ToolTable};

/// Bisection steps along the move (2⁻⁴⁰ of its length).
const STEPS: usize = 40;
/// How near the contact point a swept outline must come to count as reaching it, mm.
const NEAR: f64 = 1e-6;

/// The tool of move `seg` placed where its part `body` (its cutting outline when `None`,
/// else the body of that name) first reaches `at` (a crash's contact point in the
/// section, r ≥ 0), as convex parts in the section (mirrored to r ≥ 0 when the tool is
/// below the axis there): the cutting outline's parts, then the body's. `rear`: the tools
/// on a rear post ([`stock::rear_tools`]). Empty for a move with no finite coordinates.
pub fn tool_at_crash(
    tools: &ToolTable,
    seg: &Segment,
    rear: &[u32],
    at: [f64; 2],
    body: Option<&str>,
    chord_tol: f64,
) -> Vec<Vec<[f64; 2]>> {
    let m = Mounted::new(tools, seg.tool, seg.hint, rear.contains(&seg.tool));
    let Some(p) = first_reach(m.part(body), seg, at, chord_tol, NEAR) else {
        return Vec::new();
    };
    let below = p[1] < 0.0;
    let place = |part: &Vec<P>| -> Vec<P> {
        let placed: Vec<P> = part
            .iter()
            .map(|v| {
                let (z, r) = (v[0] + p[0], v[1] + p[1]);
                [z, if below { -r } else { r }]
            })
            .collect();
        convex_hull(&placed)
    };
    m.edge
        .parts
        .iter()
        .chain(m.body.iter().flat_map(|b| b.outline.parts.iter()))
        .map(place)
        .collect()
}

/// Where the reference point of move `seg` is (as programmed, not folded) when `outline`,
/// swept along the move, first reaches `at` (a point of the section, r ≥ 0, or its mirror:
/// sweeps are folded); `None` for a move with no finite coordinates, or when `at` is not
/// reached at all (within `near`) by the end of the move.
pub(crate) fn first_reach(
    outline: &Outline,
    seg: &Segment,
    at: P,
    chord_tol: f64,
    near: f64,
) -> Option<P> {
    let path = move_path(seg, chord_tol);
    if path.iter().flatten().any(|v| !v.is_finite()) {
        return None;
    }
    let reaches = |t: f64| {
        let sub = prefix(&path, t);
        [at, [at[0], -at[1]]]
            .iter()
            .any(|&q| swept_near(outline, &sub, q, near))
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    if reaches(0.0) {
        hi = 0.0;
    } else if !reaches(1.0) {
        return None;
    } else {
        for _ in 0..STEPS {
            let mid = 0.5 * (lo + hi);
            if reaches(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
    }
    let sub = prefix(&path, hi);
    Some(sub[sub.len() - 1])
}

/// The outline of each move's tool as mounted, for drawing the tool as it moves: the
/// distinct outlines (cutting outline's parts, body's parts, relative to the reference
/// point) and, for each run of moves with the same one, (index of its first move, index
/// of the outline). `rear`: the tools on a rear post ([`stock::rear_tools`]).
#[allow(clippy::type_complexity)]
pub fn tool_outlines(
    tools: &ToolTable,
    segments: &[Segment],
    rear: &[u32],
) -> (
    Vec<(Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>)>,
    Vec<(usize, usize)>,
) {
    let mut outlines: Vec<(Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>)> = Vec::new();
    let mut runs: Vec<(usize, usize)> = Vec::new();
    let mut last: Option<(u32, ToolHint)> = None;
    for (i, s) in segments.iter().enumerate() {
        if last == Some((s.tool, s.hint)) {
            continue;
        }
        last = Some((s.tool, s.hint));
        let m = Mounted::new(tools, s.tool, s.hint, rear.contains(&s.tool));
        let o = (
            m.edge.parts.clone(),
            m.body.map(|b| b.outline.parts).unwrap_or_default(),
        );
        let k = outlines.iter().position(|x| *x == o).unwrap_or_else(|| {
            outlines.push(o);
            outlines.len() - 1
        });
        if runs.last().is_none_or(|r| r.1 != k) {
            runs.push((i, k));
        }
    }
    (outlines, runs)
}

/// The path's first fraction `t` of its length (at least its start point).
fn prefix(path: &[P], t: f64) -> Vec<P> {
    let lens: Vec<f64> = path
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .collect();
    let total: f64 = lens.iter().sum();
    let mut left = t.clamp(0.0, 1.0) * total;
    let mut out = vec![path[0]];
    for (w, &l) in path.windows(2).zip(&lens) {
        if left >= l {
            out.push(w[1]);
            left -= l;
            continue;
        }
        let f = if l > 0.0 { left / l } else { 0.0 };
        out.push([
            w[0][0] + f * (w[1][0] - w[0][0]),
            w[0][1] + f * (w[1][1] - w[0][1]),
        ]);
        break;
    }
    out
}

/// Whether the sweep of `outline` along `path` comes within `near` of `q`.
fn swept_near(outline: &Outline, path: &[P], q: P, near: f64) -> bool {
    chord_sweeps(outline, path).any(|hull| inside_convex(&hull, q, near))
}

/// `q` inside the counter-clockwise convex polygon or within `near` of its edges.
fn inside_convex(poly: &[P], q: P, near: f64) -> bool {
    let n = poly.len();
    if n < 3 {
        return poly
            .iter()
            .any(|p| (p[0] - q[0]).hypot(p[1] - q[1]) <= near);
    }
    (0..n).all(|i| {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        let cross = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
        len == 0.0 || cross >= -near * len
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use expander::{FeedId, Motion, Pt, Span};

    #[test]
    fn a_blade_stops_where_it_first_touches() {
        // a 3 mm blade (z 0…3 from its reference corner, 20 mm up) with its holder beyond
        // the reach; a rapid along -Z at r 5 meets the point (0, 5.5) when its left side,
        // at the reference point's Z, gets there: reference at Z0
        let tools = ToolTable::from_toml(
            "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\nreach = 20.0\n",
        )
        .unwrap();
        let seg = Segment {
            motion: Motion::Rapid,
            from: Pt::new(10.0, 5.0),
            to: Pt::new(-10.0, 5.0),
            arc: None,
            tool: 1,
            hint: ToolHint::Table,
            lead: 0.0,
            thread_phase: 0.0,
            feed: FeedId::default(),
            span: Span::default(),
        };
        let parts = tool_at_crash(&tools, &seg, &[], [0.0, 5.5], None, 0.001);
        assert_eq!(parts.len(), 2, "blade and holder");
        let (lo, hi) = Outline {
            parts: vec![parts[0].clone()],
            ..Outline::default()
        }
        .bbox()
        .unwrap();
        assert!(
            lo[0].abs() < 1e-6 && (hi[0] - 3.0).abs() < 1e-6,
            "{lo:?} {hi:?}"
        );
        assert!((lo[1] - 5.0).abs() < 1e-9 && (hi[1] - 25.0).abs() < 1e-9);
        // the holder's part met (0, 26): it starts 2 mm left of the blade, so the
        // reference stops at Z2
        let parts = tool_at_crash(&tools, &seg, &[], [0.0, 26.0], Some("blade holder"), 0.001);
        let zmin = parts[1].iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        assert!(zmin.abs() < 1e-6, "{parts:?}");
        let zref = parts[0].iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        assert!((zref - 2.0).abs() < 1e-6);
    }
}
