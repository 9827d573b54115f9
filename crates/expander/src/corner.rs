//! Direct drawing dimensions on G01 (spec/dialects.md §6.5): `,A a` gives a line's angle
//! instead of one end coordinate; `,C c` replaces the corner at
//! a line's end point, between it and the next G01 line, by a chamfer whose ends are `c`
//! from the corner along each line; `,R r` by an arc of radius `r` tangent to both. The
//! geometry and the words, for the interpreter (`interp/corner.rs`) and the finishing
//! shapes of G70–G73 (`cycles/contour.rs`).

use crate::{Arc, Diagnostic, Pt, Span};
use gcode::Word;

/// What replaces the corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum CornerKind {
    /// `,C c`: a straight chamfer, `c` from the corner along each line.
    Chamfer(f64),
    /// `,R r`: a tangent arc of radius `r`.
    Round(f64),
}

/// Where the corner piece starts and ends, and its arc (`None`: a chamfer).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CornerPiece {
    pub(crate) start: Pt,
    pub(crate) end: Pt,
    pub(crate) arc: Option<Arc>,
}

/// The piece replacing the corner `b` between the lines `a -> b` and `b -> c`; `Err` says
/// why there is none.
fn piece(a: Pt, b: Pt, c: Pt, kind: CornerKind) -> Result<CornerPiece, String> {
    let (len1, len2) = (a.dist(b), b.dist(c));
    let (u1, u2) = ((b - a).unit(), (c - b).unit());
    let turn = u1.cross(u2);
    if turn.abs() < 1e-9 {
        return Err(if u1.dot(u2) > 0.0 {
            "the two lines are in line: there is no corner".into()
        } else {
            "the next line goes straight back: there is no corner".into()
        });
    }
    let (d, what) = match kind {
        CornerKind::Chamfer(c) => (c, "chamfer"),
        // the tangent points are r·tan(θ/2) from the corner, θ the angle turned
        CornerKind::Round(r) => (r * (turn.atan2(u1.dot(u2)).abs() / 2.0).tan(), "round"),
    };
    if d > len1 + 1e-9 || d > len2 + 1e-9 {
        return Err(format!(
            "the {what} needs {d:.4} mm of each line, but the lines are {len1:.4} and {len2:.4} mm long"
        ));
    }
    let (start, end) = (b - u1 * d, b + u2 * d);
    let arc = match kind {
        CornerKind::Chamfer(_) => None,
        CornerKind::Round(r) => {
            // the centre is on the inside of the turn: left of the first line on a left turn
            let normal = if turn > 0.0 { u1.perp() } else { -u1.perp() };
            Some(Arc {
                center: start + normal * r,
                ccw: turn > 0.0,
            })
        }
    };
    Ok(CornerPiece { start, end, arc })
}

/// What a G01 asks for its end corner: the piece, its word, and for system A's plain form
/// the sign the next move's direction must have.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ask {
    pub(crate) kind: CornerKind,
    pub(crate) word: Span,
    pub(crate) toward: Option<f64>,
}

/// The corner a G01 block asks for with its words (already taken from the block): `comma`
/// its `,C` and `,R`, `plain` its system-A `C` and `R` (none unless the profile reads them);
/// an error for two corner words, or for a size that is not one. `unit`: mm per unit.
pub(crate) fn ask(
    comma: [Option<&Word>; 2],
    plain: [Option<&Word>; 2],
    unit: f64,
) -> Result<Option<Ask>, Diagnostic> {
    let mut words = comma
        .iter()
        .chain(&plain)
        .zip([false, true, false, true])
        .filter_map(|(w, round)| w.map(|w| (w, round)));
    let Some((w, round)) = words.next() else {
        return Ok(None);
    };
    if let Some((second, _)) = words.next() {
        return Err(Diagnostic::new(
            second.span,
            "LS-CORNER",
            format!(
                "both {} and {} on one block ({} at {})",
                gcode::address(w.letter),
                gcode::address(second.letter),
                gcode::address(w.letter),
                w.span
            ),
            "a corner is either chamfered or rounded, by one word: keep one",
        ));
    }
    let is_plain = !w.letter.is_ascii_lowercase();
    // a plain word's sign is the next move's direction, its size the value's magnitude
    let size = if is_plain { w.value.abs() } else { w.value } * unit;
    if !(size.is_finite() && size > 0.0) {
        return Err(Diagnostic::new(
            w.span,
            "LS-CORNER",
            format!("{}{} is not a size", gcode::address(w.letter), w.value),
            if is_plain {
                "give the chamfer or radius with the sign of the next move's direction, e.g. C-1. or R2."
            } else {
                "give the chamfer or radius in mm (inch under G20), greater than 0"
            },
        ));
    }
    Ok(Some(Ask {
        kind: if round {
            CornerKind::Round(size)
        } else {
            CornerKind::Chamfer(size)
        },
        word: w.span,
        toward: is_plain.then(|| w.value.signum()),
    }))
}

/// The piece for the corner `ask` of the line `a -> b`, against the next line `b -> c`: a
/// plain corner's 90° and sign checked first; `line` is the asking block's, for the alarm.
pub(crate) fn make(a: Pt, b: Pt, c: Pt, ask: &Ask, line: u32) -> Result<CornerPiece, Diagnostic> {
    if let Some(sign) = ask.toward {
        plain_fits(a, b, c, sign, ask.word, line)?;
    }
    piece(a, b, c, ask.kind).map_err(|why| {
        Diagnostic::new(
            ask.word,
            "LS-CORNER",
            format!("the corner at the end of line {line} cannot be made: {why}"),
            "make the chamfer or radius smaller, or the lines longer",
        )
    })
}

/// The alarm for a corner word on a G01 that does not move.
pub(crate) fn standing_still(word: Span) -> Diagnostic {
    Diagnostic::new(
        word,
        "LS-CORNER",
        "a chamfer or round on a G01 that does not move",
        "put the corner word on the line that ends at the corner",
    )
}

/// The alarm for a corner still waiting when `what` comes instead of a G01 line.
pub(crate) fn without_line(word: Span, line: u32, what: &str) -> Diagnostic {
    Diagnostic::new(
        word,
        "LS-CORNER",
        format!("the chamfer or round at the end of line {line} needs a G01 line next, but {what}"),
        "follow a block with ,C or ,R by the G01 line of the corner's other side",
    )
}

/// The end of a G01 given one coordinate and `,A a` (spec/dialects.md §6.5): the line leaves
/// `from` at `a` degrees from +Z, counter-clockwise in the drawing (X up), and ends where it
/// reaches the coordinate given (`given`: X, Z); `to` holds that coordinate.
pub(crate) fn line_at_angle(
    from: Pt,
    to: Pt,
    w: &gcode::Word,
    given: (bool, bool),
) -> Result<Pt, Diagnostic> {
    let a = w.value.to_radians();
    let (dz, dr) = (a.cos(), a.sin());
    match given {
        (true, false) => {
            // X given: run along the angle until the radius is reached
            if dr.abs() < 1e-9 || (to.r - from.r) * dr < 0.0 {
                return Err(angle_alarm(
                    w,
                    "the line at this angle never reaches the X given",
                ));
            }
            let t = (to.r - from.r) / dr;
            Ok(Pt::new(from.z + t * dz, to.r))
        }
        (false, true) => {
            if dz.abs() < 1e-9 || (to.z - from.z) * dz < 0.0 {
                return Err(angle_alarm(
                    w,
                    "the line at this angle never reaches the Z given",
                ));
            }
            let t = (to.z - from.z) / dz;
            Ok(Pt::new(to.z, from.r + t * dr))
        }
        (true, true) => Err(angle_alarm(
            w,
            "a line's angle stands with one coordinate: its X (or U) or its Z (or W), not both",
        )),
        (false, false) => Err(angle_alarm(
            w,
            "a line's angle needs its X (or U) or its Z (or W)",
        )),
    }
}

fn angle_alarm(w: &gcode::Word, message: &str) -> Diagnostic {
    Diagnostic::new(
        w.span,
        "LS-ANGLE",
        format!("{message} (,A{})", w.value),
        "give ,A (degrees from +Z, counter-clockwise) with exactly one end coordinate",
    )
}

/// System A's plain corner (`C±i` / `R±r` without a comma) stands between perpendicular
/// moves `a -> b -> c`, one along Z and one along X, and its sign is the direction of the
/// second (spec/dialects.md §6.5); `word` and `line` place the alarm.
fn plain_fits(a: Pt, b: Pt, c: Pt, sign: f64, word: Span, line: u32) -> Result<(), Diagnostic> {
    const EPS: f64 = 1e-9;
    let (u1, u2) = (b - a, c - b);
    let next = if u1.r.abs() < EPS && u2.z.abs() < EPS {
        ("X", u2.r)
    } else if u1.z.abs() < EPS && u2.r.abs() < EPS {
        ("Z", u2.z)
    } else {
        return Err(Diagnostic::new(
            word,
            "LS-CORNER",
            format!(
                "a corner without a comma (line {line}) stands between a Z and an X move at 90°"
            ),
            "write ,C / ,R for corners at other angles (g01_cr = \"comma\")",
        ));
    };
    if next.1 * sign <= 0.0 {
        return Err(Diagnostic::new(
            word,
            "LS-CORNER",
            format!(
                "the corner's sign says the next move goes toward {}{}, but it goes the other way",
                if sign > 0.0 { "+" } else { "-" },
                next.0
            ),
            "the sign of C or R is the direction of the move after the corner",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Pt, b: Pt) -> bool {
        a.dist(b) < 1e-12
    }

    /// Up X20 → X30 at Z0, then along −Z: `,C1.` cuts the corner (Z0, r15) from (0, 14) to
    /// (−1, 15).
    #[test]
    fn a_chamfer_is_c_from_the_corner_along_each_line() {
        let p = piece(
            Pt::new(0.0, 10.0),
            Pt::new(0.0, 15.0),
            Pt::new(-20.0, 15.0),
            CornerKind::Chamfer(1.0),
        )
        .unwrap();
        assert!(close(p.start, Pt::new(0.0, 14.0)) && close(p.end, Pt::new(-1.0, 15.0)));
        assert_eq!(p.arc, None);
    }

    /// Along −Z at r15 into a shoulder up to r20 at Z−20: `,R2.` is the fillet from
    /// (−18, 15) to (−20, 17) about (−18, 17), clockwise (a right turn); a 60° turn puts
    /// the tangent points r·tan 30° from the corner.
    #[test]
    fn a_round_is_tangent_to_both_lines() {
        let p = piece(
            Pt::new(-1.0, 15.0),
            Pt::new(-20.0, 15.0),
            Pt::new(-20.0, 20.0),
            CornerKind::Round(2.0),
        )
        .unwrap();
        assert!(close(p.start, Pt::new(-18.0, 15.0)) && close(p.end, Pt::new(-20.0, 17.0)));
        let arc = p.arc.unwrap();
        assert!(close(arc.center, Pt::new(-18.0, 17.0)) && !arc.ccw);
        // a left turn of 60°: (0,0) → (10,0) → (10 + 5, 5√3)
        let c = Pt::new(15.0, 5.0 * 3f64.sqrt());
        let p = piece(
            Pt::new(0.0, 0.0),
            Pt::new(10.0, 0.0),
            c,
            CornerKind::Round(3.0),
        )
        .unwrap();
        let t = 3.0 * (30f64.to_radians()).tan();
        assert!(close(p.start, Pt::new(10.0 - t, 0.0)));
        assert!(close(
            p.end,
            Pt::new(10.0, 0.0) + (c - Pt::new(10.0, 0.0)).unit() * t
        ));
        let arc = p.arc.unwrap();
        assert!(arc.ccw && close(arc.center, Pt::new(10.0 - t, 3.0)));
        assert!((arc.center.dist(p.end) - 3.0).abs() < 1e-12);
    }

    #[test]
    fn no_corner_no_piece() {
        let (a, b) = (Pt::new(0.0, 10.0), Pt::new(-5.0, 10.0));
        for (c, kind, why) in [
            (Pt::new(-9.0, 10.0), CornerKind::Chamfer(1.0), "in line"),
            (Pt::new(3.0, 10.0), CornerKind::Round(1.0), "straight back"),
            (Pt::new(-5.0, 10.5), CornerKind::Chamfer(1.0), "lines are"),
            (Pt::new(-5.0, 20.0), CornerKind::Chamfer(6.0), "lines are"),
        ] {
            let e = piece(a, b, c, kind).unwrap_err();
            assert!(e.contains(why), "{e}");
        }
    }
}
