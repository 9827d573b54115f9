//! Workholding: the chuck (body, hard or soft jaws, gripped length) and the tailstock centre,
//! as the machine profile's `[chuck]` and `[tailstock]` tables or `latsim run --chuck` give
//! them. Plain numbers in program coordinates (z, x = diameter); `stock::Fixture` turns them
//! into obstacles against the blank.
//!
//! ```toml
//! [chuck]
//! grip = 20.0         # length of the blank held in the jaws, mm (required)
//! face = -80.0        # Z of the chuck face; default: the blank's left end
//! jaw = 25.0          # hard jaws' height above the gripped diameter, mm
//! od = 200.0          # chuck body diameter; default: the jaws' outer diameter + 40
//! depth = 100.0       # chuck body length behind the face, mm
//! soft_jaw = [[0, 40], [20, 40], [20, 120], [0, 120]] # soft jaws instead: [dz, x] from the face
//! [tailstock]
//! tip = 2.0           # Z of the centre's point (a 60° cone)
//! quill = 40.0        # quill diameter, mm
//! length = 150.0      # quill length behind the cone, mm
//! ```

use toml::Spanned;

/// Default radial height of hard jaws above the gripped diameter, mm.
pub(crate) const DEFAULT_JAW: f64 = 25.0;
/// Default chuck body length behind the face, mm.
pub(crate) const DEFAULT_DEPTH: f64 = 100.0;
/// Default quill diameter of the tailstock, mm.
pub(crate) const DEFAULT_QUILL: f64 = 40.0;
/// Default quill length behind the centre's cone, mm.
pub(crate) const DEFAULT_QUILL_LENGTH: f64 = 150.0;
/// Largest length or coordinate accepted, mm (no lathe travels 10 m).
const MAX_MM: f64 = 10_000.0;

/// The chuck: a body behind its face and jaws gripping the blank over `grip`.
#[derive(Debug, Clone, PartialEq)]
pub struct Chuck {
    /// Z of the chuck face; `None`: the blank's left end (stick-out = blank length − grip).
    pub face: Option<f64>,
    /// Length of the blank held by the jaws, from the face toward +Z, mm.
    pub grip: f64,
    /// Radial height of the hard jaws above the gripped diameter, mm.
    pub jaw: f64,
    /// Chuck body diameter, mm; `None`: the jaws' outer diameter + 40.
    pub od: Option<f64>,
    /// Chuck body length behind the face, mm.
    pub depth: f64,
    /// Soft jaws: a closed outline of `[dz, x]` points (dz from the face toward +Z, x a
    /// diameter) drawn in place of the hard jaws.
    pub soft_jaw: Option<Vec<[f64; 2]>>,
}

/// The tailstock centre: a 60° cone with its point at `tip` on the axis, then the quill.
#[derive(Debug, Clone, PartialEq)]
pub struct Tailstock {
    /// Z of the centre's point.
    pub tip: f64,
    /// Quill diameter, mm (the cone widens to it).
    pub quill: f64,
    /// Quill length toward +Z behind the cone, mm.
    pub length: f64,
}

/// Chuck and tailstock; both `None`: nothing is checked (the default).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Workholding {
    /// The chuck, when given.
    pub chuck: Option<Chuck>,
    /// The tailstock centre, when given (engaged).
    pub tailstock: Option<Tailstock>,
}

/// The `[chuck]` table.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ChuckFile {
    grip: Spanned<f64>,
    face: Option<Spanned<f64>>,
    jaw: Option<Spanned<f64>>,
    od: Option<Spanned<f64>>,
    depth: Option<Spanned<f64>>,
    soft_jaw: Option<Spanned<Vec<[f64; 2]>>>,
}

/// The `[tailstock]` table.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct TailstockFile {
    tip: Spanned<f64>,
    quill: Option<Spanned<f64>>,
    length: Option<Spanned<f64>>,
}

/// A file holding only `[chuck]` and `[tailstock]` (`--chuck FILE`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct WorkholdingFile {
    chuck: Option<ChuckFile>,
    tailstock: Option<TailstockFile>,
}

/// A bad value: its byte range in the text (empty for the compact form) and the message.
pub(crate) type Bad = (std::ops::Range<usize>, String);

fn length(name: &str, v: Option<Spanned<f64>>, default: f64) -> Result<f64, Bad> {
    match v {
        None => Ok(default),
        Some(v) => {
            let x = *v.get_ref();
            if x.is_finite() && x > 0.0 && x <= MAX_MM {
                Ok(x)
            } else {
                Err((
                    v.span(),
                    format!("{name} must be a positive length up to {MAX_MM} mm, got {x}"),
                ))
            }
        }
    }
}

fn coord(name: &str, v: Spanned<f64>) -> Result<f64, Bad> {
    let x = *v.get_ref();
    if x.is_finite() && x.abs() <= MAX_MM {
        Ok(x)
    } else {
        Err((
            v.span(),
            format!("{name} must be a Z in mm within ±{MAX_MM}, got {x}"),
        ))
    }
}

impl ChuckFile {
    pub(crate) fn read(self) -> Result<Chuck, Bad> {
        let soft_jaw = match self.soft_jaw {
            None => None,
            Some(s) => {
                let span = s.span();
                let pts = s.into_inner();
                let ok = pts.len() >= 3
                    && pts.iter().all(|p| {
                        p.iter().all(|v| v.is_finite() && v.abs() <= MAX_MM) && p[1] >= 0.0
                    });
                if !ok {
                    return Err((
                        span,
                        "chuck.soft_jaw must be at least three [dz, x] points (dz from the chuck face, x a diameter ≥ 0)".into(),
                    ));
                }
                Some(pts)
            }
        };
        Ok(Chuck {
            grip: length("chuck.grip", Some(self.grip), 0.0)?,
            face: self.face.map(|f| coord("chuck.face", f)).transpose()?,
            jaw: length("chuck.jaw", self.jaw, DEFAULT_JAW)?,
            od: self
                .od
                .map(|v| length("chuck.od", Some(v), 0.0))
                .transpose()?,
            depth: length("chuck.depth", self.depth, DEFAULT_DEPTH)?,
            soft_jaw,
        })
    }
}

impl TailstockFile {
    pub(crate) fn read(self) -> Result<Tailstock, Bad> {
        Ok(Tailstock {
            tip: coord("tailstock.tip", self.tip)?,
            quill: length("tailstock.quill", self.quill, DEFAULT_QUILL)?,
            length: length("tailstock.length", self.length, DEFAULT_QUILL_LENGTH)?,
        })
    }
}

/// Workholding that could not be read: the message, and its 1-based line and column in
/// the file (0, 0 for the compact form).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct WorkholdingError {
    /// 1-based line (0: the compact form).
    pub line: u32,
    /// 1-based column.
    pub column: u32,
    /// What is wrong.
    pub message: String,
}

const COMPACT_KEYS: &str = "grip, face, jaw, od, depth, tail, quill, quill_length";

impl Workholding {
    /// Reads `--chuck`: the compact form `grip=20,jaw=15,face=-80,od=200,depth=100,tail=2,
    /// quill=40,quill_length=150` (`grip` required with any chuck key; `tail` makes the
    /// tailstock), or, when the text holds no `=`, nothing: see [`Workholding::from_toml`].
    pub fn from_compact(text: &str) -> Result<Self, WorkholdingError> {
        let err = |message: String| WorkholdingError {
            line: 0,
            column: 0,
            message,
        };
        let mut chuck_keys = String::new();
        let mut tail_keys = String::new();
        for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let Some((k, v)) = item.split_once('=') else {
                return Err(err(format!(
                    "--chuck: `{item}` is not key=value (keys: {COMPACT_KEYS})"
                )));
            };
            let (k, v) = (k.trim(), v.trim());
            let x: f64 = v
                .parse()
                .map_err(|_| err(format!("--chuck: {k}={v}: `{v}` is not a number")))?;
            let line = |key: &str| format!("{key} = {x:?}\n");
            match k {
                "grip" | "face" | "jaw" | "od" | "depth" => chuck_keys.push_str(&line(k)),
                "tail" => tail_keys.push_str(&line("tip")),
                "quill" => tail_keys.push_str(&line("quill")),
                "quill_length" => tail_keys.push_str(&line("length")),
                _ => {
                    return Err(err(format!(
                        "--chuck: unknown key `{k}` (keys: {COMPACT_KEYS})"
                    )))
                }
            }
        }
        let mut w = Self::default();
        if !chuck_keys.is_empty() {
            let c: ChuckFile = toml::from_str(&chuck_keys).map_err(|e| {
                err(format!(
                    "--chuck: {} (give grip=LENGTH)",
                    e.message().trim()
                ))
            })?;
            w.chuck = Some(c.read().map_err(|(_, m)| err(format!("--chuck: {m}")))?);
        }
        if !tail_keys.is_empty() {
            let t: TailstockFile = toml::from_str(&tail_keys).map_err(|e| {
                err(format!(
                    "--chuck: {} (give tail=Z for the tailstock)",
                    e.message().trim()
                ))
            })?;
            w.tailstock = Some(t.read().map_err(|(_, m)| err(format!("--chuck: {m}")))?);
        }
        Ok(w)
    }

    /// Reads a workholding file: `[chuck]` and `[tailstock]` tables with the machine
    /// profile's keys (see the module documentation).
    pub fn from_toml(text: &str) -> Result<Self, WorkholdingError> {
        let at = |span: std::ops::Range<usize>, message: String| {
            let (line, column) = crate::text_place::line_col(text, span.start);
            WorkholdingError {
                line,
                column,
                message,
            }
        };
        let f: WorkholdingFile = toml::from_str(text).map_err(|e| {
            let (line, column) = e
                .span()
                .map(|s| crate::text_place::line_col(text, s.start))
                .unwrap_or((0, 0));
            WorkholdingError {
                line,
                column,
                message: e.message().to_string(),
            }
        })?;
        Ok(Self {
            chuck: f
                .chuck
                .map(ChuckFile::read)
                .transpose()
                .map_err(|(s, m)| at(s, m))?,
            tailstock: f
                .tailstock
                .map(TailstockFile::read)
                .transpose()
                .map_err(|(s, m)| at(s, m))?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compact_form() {
        let w = Workholding::from_compact("grip=20, jaw=15,tail=2").unwrap();
        let c = w.chuck.unwrap();
        assert_eq!((c.grip, c.jaw, c.face, c.depth), (20.0, 15.0, None, 100.0));
        let t = w.tailstock.unwrap();
        assert_eq!((t.tip, t.quill, t.length), (2.0, 40.0, 150.0));
        assert!(Workholding::from_compact("jaw=15")
            .unwrap_err()
            .message
            .contains("grip"));
        assert!(Workholding::from_compact("grip=-2")
            .unwrap_err()
            .message
            .contains("chuck.grip"));
        assert!(Workholding::from_compact("grip=2,claw=3")
            .unwrap_err()
            .message
            .contains("unknown key `claw`"));
        assert!(Workholding::from_compact("grip=x").is_err());
        let w = Workholding::from_compact("tail=-1,quill=30").unwrap();
        assert!(w.chuck.is_none() && w.tailstock.unwrap().quill == 30.0);
    }

    #[test]
    fn file_form_with_places() {
        let w = Workholding::from_toml(
            "[chuck]\ngrip = 20\nsoft_jaw = [[0, 40], [20, 40], [20, 120]]\n[tailstock]\ntip = 3.5",
        )
        .unwrap();
        assert_eq!(w.chuck.unwrap().soft_jaw.unwrap().len(), 3);
        let e = Workholding::from_toml("[chuck]\ngrip = 20\nod = -4").unwrap_err();
        assert_eq!((e.line, e.column), (3, 6));
        let e = Workholding::from_toml("[chuck]\ngrip = 20\nsoft_jaw = [[0, 1]]").unwrap_err();
        assert_eq!(e.line, 3);
        let e = Workholding::from_toml("[tailstock]\nquill = 3").unwrap_err();
        assert!(e.message.contains("tip"), "{}", e.message);
    }
}
