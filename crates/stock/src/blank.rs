//! The blank: the stock before the first cut.

use crate::{overlay, profile, Shape, StockError};

/// The raw material, a polygon set in (z, r).
#[derive(Debug, Clone, PartialEq)]
pub struct Blank {
    /// The blank's section (usually one shape).
    pub shapes: Vec<Shape>,
    /// Human description for reports, e.g. "Ø125 × 110 bar, face at Z0".
    pub description: String,
}

impl Blank {
    /// A bar of `diameter` × `length`, right face at `face_z`, extending to `face_z - length`;
    /// `bore` is the inner diameter of a tube, or `None` for solid bar.
    pub fn bar(
        diameter: f64,
        length: f64,
        face_z: f64,
        bore: Option<f64>,
    ) -> Result<Self, StockError> {
        let finite = |v: f64| v.is_finite() && v.abs() < 1e9;
        if !(finite(diameter) && diameter > 0.0) {
            return Err(StockError::Blank(format!(
                "diameter {diameter} must be a positive number"
            )));
        }
        if !(finite(length) && length > 0.0) {
            return Err(StockError::Blank(format!(
                "length {length} must be a positive number"
            )));
        }
        if !finite(face_z) {
            return Err(StockError::Blank(format!(
                "face position Z{face_z} is not a number"
            )));
        }
        let inner = match bore {
            None => 0.0,
            Some(b) if finite(b) && b >= 0.0 && b < diameter => b / 2.0,
            Some(b) => {
                return Err(StockError::Blank(format!(
                    "bore Ø{b} must be at least 0 and less than the diameter Ø{diameter}"
                )))
            }
        };
        let (z0, z1, r1) = (face_z - length, face_z, diameter / 2.0);
        let outer = vec![[z0, inner], [z1, inner], [z1, r1], [z0, r1]];
        let bore_text = match bore {
            Some(b) if b > 0.0 => format!(", bore Ø{}", fmt_num(b)),
            _ => String::new(),
        };
        Ok(Self {
            shapes: vec![Shape {
                outer,
                holes: Vec::new(),
            }],
            description: format!(
                "Ø{} × {} bar{}, face at Z{}",
                fmt_num(diameter),
                fmt_num(length),
                bore_text,
                fmt_num(face_z)
            ),
        })
    }

    /// Parses "125x110" (also "125X110", "125×110", "Ø125x110") into (diameter, length).
    pub fn parse_dims(s: &str) -> Result<(f64, f64), StockError> {
        let err = |m: &str| StockError::Dims {
            text: s.to_string(),
            message: m.to_string(),
        };
        let t = s.trim();
        let t = t
            .strip_prefix('Ø')
            .or_else(|| t.strip_prefix('ø'))
            .unwrap_or(t)
            .trim();
        let mut it = t.split(['x', 'X', '×']);
        let (Some(d), Some(l), None) = (it.next(), it.next(), it.next()) else {
            return Err(err("expected DIAMETERxLENGTH"));
        };
        let num = |v: &str, what: &str| -> Result<f64, StockError> {
            let n: f64 = v
                .trim()
                .parse()
                .map_err(|_| err(&format!("the {what} `{}` is not a number", v.trim())))?;
            if n.is_finite() && n > 0.0 {
                Ok(n)
            } else {
                Err(err(&format!("the {what} must be positive")))
            }
        };
        Ok((num(d, "diameter")?, num(l, "length")?))
    }

    /// A blank from the profile TOML of the simulation spec (see [`profile_from_toml`]).
    ///
    /// [`profile_from_toml`]: crate::profile_from_toml
    pub fn from_profile_toml(text: &str, chord_tol: f64) -> Result<Self, StockError> {
        let shapes = profile::profile_from_toml(text, chord_tol)?;
        let r = geom::Rect::of(shapes.iter().flat_map(|s| geom::flat::pts(&s.outer)));
        Ok(Self {
            description: format!(
                "profile Z{}..Z{}, up to Ø{}",
                fmt_num(r.min.z),
                fmt_num(r.max.z),
                fmt_num(2.0 * r.max.r)
            ),
            shapes,
        })
    }

    /// A blank from any polygon rings (any orientation; overlaps merge by non-zero fill).
    pub fn from_rings(rings: &[Vec<[f64; 2]>], description: &str) -> Self {
        Self {
            shapes: overlay::clean(rings),
            description: description.to_string(),
        }
    }
}

/// Shortest decimal text for a dimension (no trailing zeros).
pub(crate) fn fmt_num(v: f64) -> String {
    let s = format!("{:.4}", v);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::area;

    #[test]
    fn tube_has_the_bore_as_its_lower_edge() {
        let b = Blank::bar(125.0, 110.0, 0.0, Some(40.0)).unwrap();
        let o = &b.shapes[0].outer;
        assert!(o
            .iter()
            .all(|p| p[1] >= 20.0 - 1e-12 && p[1] <= 62.5 + 1e-12));
        assert!(o.iter().all(|p| p[0] >= -110.0 && p[0] <= 0.0));
        assert!((area(&b.shapes) - 110.0 * (62.5 - 20.0)).abs() < 1e-9);
        assert!(b.description.contains("bore Ø40"), "{}", b.description);
    }

    #[test]
    fn bad_bars_are_errors() {
        assert!(Blank::bar(-1.0, 10.0, 0.0, None).is_err());
        assert!(Blank::bar(10.0, f64::NAN, 0.0, None).is_err());
        assert!(Blank::bar(10.0, 10.0, 0.0, Some(12.0)).is_err());
        assert!(Blank::bar(10.0, 10.0, f64::INFINITY, None).is_err());
    }

    #[test]
    fn dims_accept_the_usual_spellings() {
        assert_eq!(Blank::parse_dims("125x110").unwrap(), (125.0, 110.0));
        assert_eq!(Blank::parse_dims("125X110").unwrap(), (125.0, 110.0));
        assert_eq!(Blank::parse_dims("Ø125x110.5").unwrap(), (125.0, 110.5));
        assert!(Blank::parse_dims("125").is_err());
        assert!(Blank::parse_dims("ax3").is_err());
        assert!(Blank::parse_dims("0x3").is_err());
    }
}
