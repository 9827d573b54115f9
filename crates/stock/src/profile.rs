//! The profile TOML (blank `--stock-file` and intended part `--target`):
//! program coordinates (z, x = diameter), straight and circular edges, closed automatically.

use crate::error::{from_toml, line_col};
use crate::{overlay, Shape, StockError};
use expander::Pt;
use serde::Deserialize;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawProfile {
    start: Spanned<[f64; 2]>,
    path: Vec<Spanned<RawStep>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawStep {
    to: [f64; 2],
    r: Option<f64>,
    dir: Option<String>,
}

const HELP: &str = "a profile is `start = [z, x]` and `path = [{ to = [z, x] }, { to = [z, x], r = R, dir = \"cw\" | \"ccw\" }, ...]`, x as diameter";

/// Parses a profile TOML into shapes in (z, r), chording arcs within `chord_tol` mm
/// (0.001 when `chord_tol` is not a positive number).
///
/// `start = [z, x]` then `path` entries `{ to = [z, x] }` (straight edge) or
/// `{ to = [z, x], r = R, dir = "cw" | "ccw" }` (arc of radius R, as G02/G03 would cut it;
/// a negative R takes the arc longer than 180°, as in G-code). The path closes back to
/// `start` by itself. x is a diameter and must not be negative.
pub fn profile_from_toml(text: &str, chord_tol: f64) -> Result<Vec<Shape>, StockError> {
    let tol = if chord_tol.is_finite() && chord_tol > 0.0 {
        chord_tol
    } else {
        0.001
    };
    let raw: RawProfile = toml::from_str(text).map_err(|e| from_toml("profile", text, &e, HELP))?;
    let r = Reading { text };
    let start = r.point(*raw.start.get_ref(), raw.start.span())?;
    let mut ring = vec![[start.z, start.r]];
    let mut cur = start;
    for step in &raw.path {
        cur = r.step(step, cur, tol, &mut ring)?;
    }
    r.closed(ring, raw.start.span())
}

type Span = std::ops::Range<usize>;

/// The profile's text, for the line and column of an error.
struct Reading<'a> {
    text: &'a str,
}

impl Reading<'_> {
    fn at(&self, span: Span, message: String, help: &str) -> StockError {
        let (line, column) = line_col(self.text, span.start);
        StockError::Toml {
            file: "profile",
            line,
            column,
            message,
            help: help.to_string(),
        }
    }

    /// A point `[z, x]` a lathe can hold, x a diameter, as (z, r).
    fn point(&self, p: [f64; 2], span: Span) -> Result<Pt, StockError> {
        if !(p[0].is_finite() && p[1].is_finite() && p[0].abs() <= 1e4 && p[1].abs() <= 2e4) {
            return Err(self.at(
                span,
                format!(
                    "point [{}, {}] is not a coordinate a lathe can hold (|z| ≤ 10 m, x ≤ 20 m)",
                    p[0], p[1]
                ),
                HELP,
            ));
        }
        if p[1] < 0.0 {
            return Err(self.at(
                span,
                format!("x = {} is below the axis", p[1]),
                "x is a diameter: it cannot be negative",
            ));
        }
        Ok(Pt::new(p[0], p[1] / 2.0))
    }

    /// One entry of `path` from `cur`: its points pushed onto `ring` (an arc's chords
    /// within `tol`); where it ends.
    fn step(
        &self,
        step: &Spanned<RawStep>,
        cur: Pt,
        tol: f64,
        ring: &mut Vec<[f64; 2]>,
    ) -> Result<Pt, StockError> {
        let span = step.span();
        let s = step.get_ref();
        let to = self.point(s.to, span.clone())?;
        let ccw = match (s.r, s.dir.as_deref()) {
            (None, None) => {
                ring.push([to.z, to.r]);
                return Ok(to);
            }
            (Some(_), Some("ccw" | "CCW")) => true,
            (Some(_), Some("cw" | "CW")) => false,
            (Some(_), Some(other)) => {
                let message = format!("dir = \"{other}\" is neither \"cw\" nor \"ccw\"");
                return Err(self.at(span, message, HELP));
            }
            (Some(_), None) => {
                let message = "an arc needs `dir` (\"cw\" or \"ccw\")".into();
                return Err(self.at(span, message, HELP));
            }
            (None, Some(_)) => {
                let message = "`dir` without `r`: an arc needs its radius".into();
                return Err(self.at(span, message, HELP));
            }
        };
        let r = s.r.unwrap_or_default();
        let center = arc_center(cur, to, r, ccw).ok_or_else(|| {
            self.at(
                span.clone(),
                format!(
                    "no arc of radius {r} joins the two points (they are {:.4} mm apart)",
                    cur.dist(to)
                ),
                "the radius must be at least half the distance between the end points",
            )
        })?;
        let g = |p: Pt| geom::Pt::new(p.z, p.r);
        let arc = geom::arc::Arc::between(g(cur), g(to), g(center), ccw);
        // the floor G-code arcs are chorded with
        let pts = arc.flatten(tol.max(1e-6));
        // the chords' inner points, then the programmed end point exactly
        ring.extend(pts[1..pts.len() - 1].iter().map(|p| p.to_array()));
        ring.push([to.z, to.r]);
        Ok(to)
    }

    /// The region the closed `ring` encloses; an error at `start` when it crosses itself
    /// or encloses nothing.
    fn closed(&self, ring: Vec<[f64; 2]>, start: Span) -> Result<Vec<Shape>, StockError> {
        const UNCROSS: &str = "list the points once around the outline, without crossing an edge";
        // A crossing found by the kernel's sweep first: a tangled outline of 10⁵ points
        // would make the boolean engine split every one of its crossings before the test
        // below.
        let outline = geom::flat::pts(&ring);
        if let Some(x) = geom::ring::self_intersection(&outline) {
            let message = format!(
                "the outline crosses itself near Z{:.4} X{:.4}",
                x.z,
                2.0 * x.r
            );
            return Err(self.at(start, message, UNCROSS));
        }
        let signed = geom::ring::signed_area(&outline).abs();
        let shapes = overlay::clean(&[ring]);
        let area = crate::area(&shapes);
        // A simple outline encloses what its signed area says; one that crosses itself (a
        // bowtie) has lobes that cancel in the signed area but not in the region.
        if (area - signed).abs() > 1e-6 * area.max(1.0) + 1e-6 {
            let message = format!(
                "the outline crosses itself: its lobes enclose {area:.4} mm² but wind to {signed:.4} mm²"
            );
            return Err(self.at(start, message, UNCROSS));
        }
        if area <= 0.0 {
            return Err(self.at(start, "the profile encloses no area".into(), HELP));
        }
        Ok(shapes)
    }
}

/// Centre of the arc of radius |r| from `a` to `b`, counter-clockwise when `ccw`; the short
/// arc for r > 0, the long one for r < 0 (G-code convention). None when no such arc exists.
pub(crate) fn arc_center(a: Pt, b: Pt, r: f64, ccw: bool) -> Option<Pt> {
    let (dz, dr) = (b.z - a.z, b.r - a.r);
    let len = dz.hypot(dr);
    let rad = r.abs();
    if !(len > 0.0 && rad.is_finite()) {
        return None;
    }
    let half = len / 2.0;
    // a hair of tolerance so a half circle given with rounded numbers still closes
    if rad < half * (1.0 - 1e-9) {
        return None;
    }
    let h = (rad * rad - half * half).max(0.0).sqrt();
    let left = (-dr / len, dz / len);
    // the short counter-clockwise arc has its centre on the left of a -> b
    let side = if ccw == (r > 0.0) { 1.0 } else { -1.0 };
    Some(Pt::new(
        a.z + dz / 2.0 + side * h * left.0,
        a.r + dr / 2.0 + side * h * left.1,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::area;

    const SPEC_EXAMPLE: &str = r#"
start = [0.0, 0.0]                                # [z, x]
path = [
  { to = [0.0, 30.0] },                           # straight edge
  { to = [-10.0, 50.0], r = 10.0, dir = "ccw" },  # arc, as G03 would cut it
  { to = [-60.0, 50.0] },
  { to = [-60.0, 0.0] },
]
"#;

    #[test]
    fn spec_example_area_matches_hand_computation() {
        let s = profile_from_toml(SPEC_EXAMPLE, 0.001).unwrap();
        // 60 x 25 rectangle minus the corner square 10 x 10 outside a quarter circle of R10
        let exact = 60.0 * 25.0 - (100.0 - std::f64::consts::PI * 100.0 / 4.0);
        let a = area(&s);
        // chords lie inside the arc: at most the sagitta (0.001) times the arc length short
        assert!(
            a <= exact + 1e-9 && exact - a < 0.001 * 16.0,
            "area {a} vs {exact}"
        );
        assert_eq!(s.len(), 1);
        // the dome bulges outward: (z, r) = (-10 + 10 cos45, 15 + 10 sin45) is on the boundary
        let p = [-10.0 + 10.0 * 0.5f64.sqrt(), 15.0 + 10.0 * 0.5f64.sqrt()];
        let d = s[0]
            .outer
            .iter()
            .map(|q| (q[0] - p[0]).hypot(q[1] - p[1]))
            .fold(f64::INFINITY, f64::min);
        assert!(d < 0.2, "{d}");
    }

    #[test]
    fn concave_cw_arc_removes_material() {
        let cw = SPEC_EXAMPLE.replace("\"ccw\"", "\"cw\"");
        let a = area(&profile_from_toml(&cw, 0.001).unwrap());
        // a cw arc of the same chord is the mirror: the quarter disc is cut out of the square
        let exact = 60.0 * 25.0 - 100.0 + (100.0 - std::f64::consts::PI * 100.0 / 4.0);
        assert!((a - exact).abs() < 0.02, "{a} vs {exact}");
    }

    #[test]
    fn errors_name_line_and_column() {
        let bad = "start = [0.0, 0.0]\npath = [\n  { to = [0.0, 30.0] },\n  { to = [-50.0, 50.0], r = 1.0, dir = \"ccw\" },\n]\n";
        match profile_from_toml(bad, 0.001) {
            Err(StockError::Toml { line, column, .. }) => assert_eq!((line, column), (4, 3)),
            other => panic!("{other:?}"),
        }
        match profile_from_toml(
            "start = [0.0, 0.0]\npath = [ { to = [1.0, 2.0], bulge = 1 } ]\n",
            0.001,
        ) {
            Err(StockError::Toml { line, message, .. }) => {
                assert_eq!(line, 2);
                assert!(message.contains("bulge"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        assert!(
            profile_from_toml("start = [0.0, 0.0]\npath = [ { to = [1.0, nan] } ]", 0.001).is_err()
        );
        assert!(
            profile_from_toml("start = [0.0, 0.0]\npath = [ { to = [1.0, 0.0] } ]", 0.001).is_err()
        );
    }
}
