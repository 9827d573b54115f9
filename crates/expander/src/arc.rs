//! Circular interpolation: the centre from R or from I/K, with the controller's checks.

use crate::{Diagnostic, Pt, Span};
use gcode::Word;

/// Why an arc cannot be made.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ArcError {
    /// R is shorter than half the chord by more than the tolerance.
    RadiusTooSmall {
        /// Programmed R.
        r: f64,
        /// Half the chord, the least R that reaches.
        half_chord: f64,
    },
    /// R form with start = end: the centre is undefined.
    FullCircleWithR,
    /// R ≤ 0.
    NonPositiveRadius,
    /// I/K: the end point is not on the circle through the start.
    EndNotOnCircle {
        /// Radius at the start.
        r_start: f64,
        /// Radius at the end.
        r_end: f64,
    },
}

/// An end radius may differ from the start radius by this much (mm) …
const END_TOL_MM: f64 = 0.005;
/// … or this fraction of the radius, whichever is larger (spec: alarm when both are exceeded).
const END_TOL_REL: f64 = 0.001;

/// Centre of an arc of radius `r` (≤ 180°) from `from` to `to`.
/// Counter-clockwise arcs of at most a half turn have their centre left of the chord.
pub(crate) fn centre_from_radius(from: Pt, to: Pt, r: f64, ccw: bool) -> Result<Pt, ArcError> {
    if r <= 0.0 {
        return Err(ArcError::NonPositiveRadius);
    }
    let (dz, dr) = (to.z - from.z, to.r - from.r);
    let chord = dz.hypot(dr);
    if chord < 1e-9 {
        return Err(ArcError::FullCircleWithR);
    }
    let half = chord / 2.0;
    let deficit = half - r;
    if deficit > END_TOL_MM.max(END_TOL_REL * r) {
        return Err(ArcError::RadiusTooSmall {
            r,
            half_chord: half,
        });
    }
    // Within tolerance of a half circle: the centre is the midpoint.
    let d = (r * r - half * half).max(0.0).sqrt();
    let (nz, nr) = (-dr / chord, dz / chord); // left normal of the chord
    let side = if ccw { 1.0 } else { -1.0 };
    Ok(Pt::new(
        (from.z + to.z) / 2.0 + side * d * nz,
        (from.r + to.r) / 2.0 + side * d * nr,
    ))
}

/// Check an I/K centre: the end must lie on the circle through the start.
pub(crate) fn check_centre(from: Pt, to: Pt, centre: Pt) -> Result<(), ArcError> {
    let (r_start, r_end) = (centre.dist(from), centre.dist(to));
    let diff = (r_start - r_end).abs();
    if diff > END_TOL_MM && diff > END_TOL_REL * r_start {
        return Err(ArcError::EndNotOnCircle { r_start, r_end });
    }
    if r_start < 1e-9 {
        return Err(ArcError::NonPositiveRadius);
    }
    Ok(())
}

/// The arc words of one G02/G03 block, as read: R, or the centre offsets I (radius) and K.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct ArcWords<'b> {
    /// R, the radius.
    pub(crate) r: Option<&'b Word>,
    /// I, the centre's radial offset from the start.
    pub(crate) i: Option<&'b Word>,
    /// K, the centre's axial offset from the start.
    pub(crate) k: Option<&'b Word>,
}

impl ArcWords<'_> {
    /// The alarm for arc words in a block with no end point; `None` when there are none.
    pub(crate) fn without_end_point(&self) -> Option<Diagnostic> {
        self.r.or(self.i).or(self.k).map(|w| {
            Diagnostic::new(
                w.span,
                "LS-ARC",
                "arc data without an end point",
                "give the arc's end point with X/U and Z/W",
            )
        })
    }

    /// The centre of the arc from `from` to `to` (mm per input unit `unit`), with the
    /// controller's alarms; `span` is the block's, for an arc with neither R nor I/K.
    pub(crate) fn centre(
        &self,
        from: Pt,
        to: Pt,
        ccw: bool,
        unit: f64,
        span: Span,
    ) -> Result<Pt, Diagnostic> {
        match (self.r, self.i, self.k) {
            (Some(r), None, None) => {
                centre_from_radius(from, to, r.value * unit, ccw).map_err(|e| alarm(r.span, e))
            }
            (None, None, None) => Err(Diagnostic::new(
                span,
                "LS-ARC",
                "G02/G03 without R or I/K",
                "give the radius R, or the centre offset I (radius) and K",
            )),
            (Some(r), _, _) => Err(Diagnostic::new(
                r.span,
                "LS-ARC",
                "arc given both R and I/K",
                "give either R or I/K, not both",
            )),
            (None, i, k) => {
                let c = Pt::new(
                    from.z + k.map_or(0.0, |k| k.value * unit),
                    from.r + i.map_or(0.0, |i| i.value * unit),
                );
                let span = i.or(k).map_or(span, |w| w.span);
                check_centre(from, to, c).map_err(|e| alarm(span, e))?;
                Ok(c)
            }
        }
    }
}

/// The controller alarm (PS020) for an arc that cannot be made, at the word at fault.
fn alarm(span: Span, e: ArcError) -> Diagnostic {
    match e {
        ArcError::RadiusTooSmall { r, half_chord } => Diagnostic::new(
            span,
            "PS020",
            format!("arc radius R{r} is too small to reach the end point (at least {half_chord:.3} needed)"),
            "check the end point and the radius: R must be at least half the distance between start and end",
        ),
        ArcError::FullCircleWithR => Diagnostic::new(span, "PS020", "arc with R whose end point equals its start", "a full circle needs I/K, not R"),
        ArcError::NonPositiveRadius => Diagnostic::new(span, "PS020", "arc radius must be positive", "arcs over 180° are not possible with R on this lathe; use I/K or split the arc"),
        ArcError::EndNotOnCircle { r_start, r_end } => Diagnostic::new(
            span,
            "PS020",
            format!("arc end point is not on the circle: radius {r_start:.4} at the start, {r_end:.4} at the end"),
            "correct I/K (I is a radius value) or the end point",
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_004_dome_is_centred_on_the_axis_line() {
        // G03 X30 Z-10 R10 from (Z0, X10): centre (Z-10, X10) i.e. r = 5.
        let c = centre_from_radius(Pt::new(0.0, 5.0), Pt::new(-10.0, 15.0), 10.0, true).unwrap();
        assert!(
            (c.z + 10.0).abs() < 1e-9 && (c.r - 5.0).abs() < 1e-9,
            "{c:?}"
        );
    }

    #[test]
    fn seed_003_concave_fillet() {
        // G02 X160 W-20 R20 from Φ120 at Z-50: centre (Z-50, Φ160) = r 80.
        let c =
            centre_from_radius(Pt::new(-50.0, 60.0), Pt::new(-70.0, 80.0), 20.0, false).unwrap();
        assert!(
            (c.z + 50.0).abs() < 1e-9 && (c.r - 80.0).abs() < 1e-9,
            "{c:?}"
        );
    }

    #[test]
    fn radius_too_small() {
        let e = centre_from_radius(Pt::new(0.0, 0.0), Pt::new(-10.0, 0.0), 4.0, true).unwrap_err();
        assert!(matches!(e, ArcError::RadiusTooSmall { .. }));
        // a rounding-sized deficit is accepted as a half circle
        assert!(centre_from_radius(Pt::new(0.0, 0.0), Pt::new(-10.0, 0.0), 4.999, true).is_ok());
    }

    #[test]
    fn ik_end_tolerance() {
        let from = Pt::new(0.0, 10.0);
        let c = Pt::new(0.0, 0.0);
        assert!(check_centre(from, Pt::new(10.004, 0.0), c).is_ok());
        assert!(check_centre(from, Pt::new(10.02, 0.0), c).is_err());
    }
}
