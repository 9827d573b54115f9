//! The tool table (`--tools F`): T numbers mapped to real tool outlines.

use crate::error::{from_toml, line_col};
use crate::outline::{self, InsertBody, Outline};
use crate::StockError;
use expander::ToolHint;
use serde::Deserialize;
use toml::Spanned;

/// ISO insert shape letter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Insert {
    /// Rhombic 80°.
    C,
    /// Rhombic 55°.
    D,
    /// Triangular 60°.
    T,
    /// Rhombic 35°.
    V,
    /// Trigon 80° (modelled as an isosceles triangle with an 80° cutting corner).
    W,
    /// Square 90°.
    S,
    /// Round, of radius `nose_radius`.
    R,
}

impl Insert {
    /// From the ISO letter (either case).
    pub fn from_letter(s: &str) -> Option<Self> {
        Some(match s.to_ascii_uppercase().as_str() {
            "C" => Self::C,
            "D" => Self::D,
            "T" => Self::T,
            "V" => Self::V,
            "W" => Self::W,
            "S" => Self::S,
            "R" => Self::R,
            _ => return None,
        })
    }

    /// Included angle ε in degrees (360 for a round insert).
    pub fn included_angle(self) -> f64 {
        match self {
            Self::C | Self::W => 80.0,
            Self::D => 55.0,
            Self::T => 60.0,
            Self::V => 35.0,
            Self::S => 90.0,
            Self::R => 360.0,
        }
    }

    fn body(self) -> InsertBody {
        match self {
            Self::C | Self::D | Self::V | Self::S => InsertBody::Rhombic,
            Self::T | Self::W => InsertBody::Triangle,
            Self::R => InsertBody::Round,
        }
    }

    fn letter(self) -> char {
        match self {
            Self::C => 'C',
            Self::D => 'D',
            Self::T => 'T',
            Self::V => 'V',
            Self::W => 'W',
            Self::S => 'S',
            Self::R => 'R',
        }
    }
}

/// An axis direction in the tool table (`"+z"`, `"-z"`, `"+x"`, `"-x"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AxisDir {
    /// +Z
    PlusZ,
    /// −Z
    MinusZ,
    /// +X
    PlusX,
    /// −X
    MinusX,
}

impl AxisDir {
    /// From the table text.
    pub fn parse(s: &str) -> Option<Self> {
        Some(match s.trim().to_ascii_lowercase().as_str() {
            "+z" | "z" => Self::PlusZ,
            "-z" => Self::MinusZ,
            "+x" | "x" => Self::PlusX,
            "-x" => Self::MinusX,
            _ => return None,
        })
    }

    /// Unit vector in (z, r).
    pub fn unit(self) -> [f64; 2] {
        match self {
            Self::PlusZ => [1.0, 0.0],
            Self::MinusZ => [-1.0, 0.0],
            Self::PlusX => [0.0, 1.0],
            Self::MinusX => [0.0, -1.0],
        }
    }

    fn is_z(self) -> bool {
        matches!(self, Self::PlusZ | Self::MinusZ)
    }

    fn text(self) -> &'static str {
        match self {
            Self::PlusZ => "+z",
            Self::MinusZ => "-z",
            Self::PlusX => "+x",
            Self::MinusX => "-x",
        }
    }
}

/// One tool, with every default filled in.
#[derive(Debug, Clone, PartialEq)]
pub enum Tool {
    /// A turning (or boring) insert.
    Turning {
        /// ISO shape letter (default D, 55°).
        insert: Insert,
        /// Nose radius, mm (default 0.4).
        nose_radius: f64,
        /// Imaginary tip number 0–9 (default 3).
        tip: u8,
        /// Holder entering angle κr, degrees (default 93).
        entering_angle: f64,
        /// Cutting edge length, mm (default 11).
        edge: f64,
    },
    /// A grooving (parting) blade.
    Grooving {
        /// Blade width, mm (default 3).
        width: f64,
        /// Direction the width spans from the reference corner (default +z).
        width_dir: AxisDir,
        /// Direction the blade body runs from the cutting edge (default +x, OD).
        shank_dir: AxisDir,
        /// Blade length, mm (default 20).
        reach: f64,
        /// Radius of both cutting-edge corners, mm (default 0).
        corner_radius: f64,
    },
    /// A drill on the spindle axis.
    Drill {
        /// Diameter, mm (required).
        diameter: f64,
        /// Point angle, degrees (default 118).
        point_angle: f64,
        /// Length of the body, mm (default 60).
        reach: f64,
    },
    /// An OD threading insert pointing −X.
    Threading {
        /// Thread angle, degrees (default 60).
        angle: f64,
        /// Width of the tip flat, mm (default 0).
        tip_flat: f64,
    },
}

impl Tool {
    /// The documented default when the table has no entry: a 55° insert (D), nose r 0.4,
    /// tip 3, on a 93° holder, 11 mm edge.
    pub const DEFAULT: Self = Self::Turning {
        insert: Insert::D,
        nose_radius: 0.4,
        tip: 3,
        entering_angle: 93.0,
        edge: 11.0,
    };

    /// The default G74/G75 blade: 3 mm wide, referenced at its left corner, OD, 20 mm reach.
    pub const DEFAULT_BLADE: Self = Self::Grooving {
        width: 3.0,
        width_dir: AxisDir::PlusZ,
        shank_dir: AxisDir::PlusX,
        reach: 20.0,
        corner_radius: 0.0,
    };

    /// The outline relative to the reference point (see [`Outline`]).
    pub fn outline(&self) -> Outline {
        match *self {
            Self::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            } => outline::turning(
                insert.body(),
                insert.included_angle(),
                nose_radius,
                tip,
                entering_angle,
                edge,
            ),
            Self::Grooving {
                width,
                width_dir,
                shank_dir,
                reach,
                corner_radius,
            } => outline::grooving(
                width,
                width_dir.unit(),
                shank_dir.unit(),
                reach,
                corner_radius,
            ),
            Self::Drill {
                diameter,
                point_angle,
                reach,
            } => outline::drill(diameter, point_angle, reach),
            Self::Threading { angle, tip_flat } => outline::threading(angle, tip_flat),
        }
    }

    /// One human line, e.g. "turning V 35°, r0.4, tip 3, κr 93°".
    pub fn describe(&self) -> String {
        use crate::blank::fmt_num as n;
        match *self {
            Self::Turning {
                insert: Insert::R,
                nose_radius,
                tip,
                ..
            } => {
                format!("turning R round, r{}, tip {tip}", n(nose_radius))
            }
            Self::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                ..
            } => format!(
                "turning {} {}°, r{}, tip {tip}, κr {}°",
                insert.letter(),
                n(insert.included_angle()),
                n(nose_radius),
                n(entering_angle)
            ),
            Self::Grooving {
                width,
                width_dir,
                shank_dir,
                reach,
                corner_radius,
            } => format!(
                "grooving {} mm, width {}, shank {}, reach {}{}",
                n(width),
                width_dir.text(),
                shank_dir.text(),
                n(reach),
                if corner_radius > 0.0 {
                    format!(", corners r{}", n(corner_radius))
                } else {
                    String::new()
                }
            ),
            Self::Drill {
                diameter,
                point_angle,
                ..
            } => format!("drill Ø{}, {}° point", n(diameter), n(point_angle)),
            Self::Threading { angle, tip_flat } => {
                format!(
                    "threading {}°{}",
                    n(angle),
                    if tip_flat > 0.0 {
                        format!(", flat {}", n(tip_flat))
                    } else {
                        String::new()
                    }
                )
            }
        }
    }
}

/// The tool table: T numbers to tools, in file order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToolTable {
    tools: Vec<(u32, Tool)>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTable {
    #[serde(default)]
    tool: Vec<Spanned<RawTool>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTool {
    t: u32,
    kind: String,
    insert: Option<String>,
    nose_radius: Option<f64>,
    tip: Option<i64>,
    entering_angle: Option<f64>,
    edge: Option<f64>,
    width: Option<f64>,
    width_dir: Option<String>,
    shank_dir: Option<String>,
    reach: Option<f64>,
    corner_radius: Option<f64>,
    diameter: Option<f64>,
    point_angle: Option<f64>,
    angle: Option<f64>,
    tip_flat: Option<f64>,
}

const HELP: &str = "each [[tool]] needs `t` and `kind` (turning | grooving | drill | threading) and only the fields of its kind";

impl ToolTable {
    /// A table with no entries: every tool gets the default.
    pub fn empty() -> Self {
        Self::default()
    }

    /// A table from explicit entries (T number, tool).
    pub fn from_tools(tools: Vec<(u32, Tool)>) -> Self {
        Self { tools }
    }

    /// Parses the `[[tool]]` TOML format of the simulation spec.
    pub fn from_toml(text: &str) -> Result<Self, StockError> {
        let raw: RawTable =
            toml::from_str(text).map_err(|e| from_toml("tool table", text, &e, HELP))?;
        let mut tools: Vec<(u32, Tool)> = Vec::new();
        for entry in &raw.tool {
            let (line, _) = line_col(text, entry.span().start);
            let raw = entry.get_ref();
            let tool = parse_tool(raw, line)?;
            if tools.iter().any(|(t, _)| *t == raw.t) {
                return Err(StockError::Tool {
                    t: raw.t,
                    field: "t",
                    message: "appears twice in the table".into(),
                    line,
                });
            }
            tools.push((raw.t, tool));
        }
        Ok(Self { tools })
    }

    /// The tool for number `t` (0 = no T word yet: the first entry), if the table has it.
    pub fn get(&self, t: u32) -> Option<&Tool> {
        if t == 0 {
            return self.tools.first().map(|(_, tool)| tool);
        }
        self.tools
            .iter()
            .find(|(n, _)| *n == t)
            .map(|(_, tool)| tool)
    }

    /// The T numbers in the table, in file order.
    pub fn numbers(&self) -> Vec<u32> {
        self.tools.iter().map(|(t, _)| *t).collect()
    }

    /// The outline for tool `t` (`tt` of `Tttoo`; 0 = no T word yet: the first entry).
    /// A missing entry or an empty table gives [`Tool::DEFAULT`] plus a warning text.
    pub fn outline(&self, t: u32) -> (Outline, Option<String>) {
        match self.get(t) {
            Some(tool) => (tool.outline(), None),
            None => {
                let why = if self.tools.is_empty() {
                    format!("no tool table: T{t:02} is taken as the default")
                } else {
                    format!("T{t:02} has no entry in the tool table: using the default")
                };
                (
                    Tool::DEFAULT.outline(),
                    Some(format!("{why} ({})", Tool::DEFAULT.describe())),
                )
            }
        }
    }

    /// One human line per tool, e.g. "T01 turning V 35°, r0.4, tip 3, κr 93°".
    pub fn describe(&self, t: u32) -> String {
        match self.get(t) {
            Some(tool) => format!("T{t:02} {}", tool.describe()),
            None => format!("T{t:02} {} (default)", Tool::DEFAULT.describe()),
        }
    }
}

fn parse_tool(raw: &RawTool, line: usize) -> Result<Tool, StockError> {
    let t = raw.t;
    let err = |field: &'static str, message: String| StockError::Tool {
        t,
        field,
        message,
        line,
    };
    // a positive (or non-negative) finite length or angle, with its default
    let num = |field: &'static str,
               v: Option<f64>,
               default: Option<f64>,
               min: f64,
               max: f64,
               zero_ok: bool| {
        let v = match (v, default) {
            (Some(v), _) => v,
            (None, Some(d)) => return Ok(d),
            (None, None) => return Err(err(field, "is required for this kind of tool".into())),
        };
        let ok = v.is_finite() && v <= max && if zero_ok { v >= min } else { v > min };
        if ok {
            Ok(v)
        } else {
            let bound = if zero_ok {
                format!("at least {min}")
            } else {
                format!("greater than {min}")
            };
            Err(err(
                field,
                format!("= {v} must be {bound} and at most {max}"),
            ))
        }
    };
    let fields: [(&'static str, bool); 14] = [
        ("insert", raw.insert.is_some()),
        ("nose_radius", raw.nose_radius.is_some()),
        ("tip", raw.tip.is_some()),
        ("entering_angle", raw.entering_angle.is_some()),
        ("edge", raw.edge.is_some()),
        ("width", raw.width.is_some()),
        ("width_dir", raw.width_dir.is_some()),
        ("shank_dir", raw.shank_dir.is_some()),
        ("reach", raw.reach.is_some()),
        ("corner_radius", raw.corner_radius.is_some()),
        ("diameter", raw.diameter.is_some()),
        ("point_angle", raw.point_angle.is_some()),
        ("angle", raw.angle.is_some()),
        ("tip_flat", raw.tip_flat.is_some()),
    ];
    let allowed: &[&str] = match raw.kind.as_str() {
        "turning" => &["insert", "nose_radius", "tip", "entering_angle", "edge"],
        "grooving" => &["width", "width_dir", "shank_dir", "reach", "corner_radius"],
        "drill" => &["diameter", "point_angle", "reach"],
        "threading" => &["angle", "tip_flat"],
        other => {
            return Err(err(
                "kind",
                format!("= \"{other}\" is not one of turning, grooving, drill, threading"),
            ));
        }
    };
    if let Some((field, _)) = fields.iter().find(|(f, set)| *set && !allowed.contains(f)) {
        return Err(err(field, format!("does not apply to a {} tool", raw.kind)));
    }
    Ok(match raw.kind.as_str() {
        "turning" => {
            let insert = match &raw.insert {
                None => Insert::D,
                Some(s) => Insert::from_letter(s).ok_or_else(|| {
                    err(
                        "insert",
                        format!("= \"{s}\" is not an ISO shape letter (C, D, T, V, W, S, R)"),
                    )
                })?,
            };
            let tip = match raw.tip {
                None => 3,
                Some(v @ 0..=9) => v as u8,
                Some(v) => {
                    return Err(err(
                        "tip",
                        format!("= {v} is not an imaginary tip number (0-9)"),
                    ))
                }
            };
            let nose_radius = num(
                "nose_radius",
                raw.nose_radius,
                Some(0.4),
                0.0,
                100.0,
                insert != Insert::R,
            )?;
            let entering_angle = num(
                "entering_angle",
                raw.entering_angle,
                Some(93.0),
                0.0,
                180.0,
                false,
            )?;
            let edge = num("edge", raw.edge, Some(11.0), 0.0, 1000.0, false)?;
            if insert != Insert::R && entering_angle + insert.included_angle() >= 180.0 {
                return Err(err("entering_angle", format!("= {entering_angle}: with a {}° insert the trailing edge would point into the part", insert.included_angle())));
            }
            Tool::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            }
        }
        "grooving" => {
            let dir = |field: &'static str, v: &Option<String>, d: AxisDir| match v {
                None => Ok(d),
                Some(s) => AxisDir::parse(s).ok_or_else(|| {
                    err(
                        field,
                        format!("= \"{s}\" is not one of \"+z\", \"-z\", \"+x\", \"-x\""),
                    )
                }),
            };
            let width = num("width", raw.width, Some(3.0), 0.0, 1000.0, false)?;
            let width_dir = dir("width_dir", &raw.width_dir, AxisDir::PlusZ)?;
            let default_shank = if width_dir.is_z() {
                AxisDir::PlusX
            } else {
                AxisDir::PlusZ
            };
            let shank_dir = dir("shank_dir", &raw.shank_dir, default_shank)?;
            if width_dir.is_z() == shank_dir.is_z() {
                return Err(err(
                    "shank_dir",
                    format!(
                        "= \"{}\" must be across the width direction \"{}\"",
                        shank_dir.text(),
                        width_dir.text()
                    ),
                ));
            }
            let reach = num("reach", raw.reach, Some(20.0), 0.0, 10000.0, false)?;
            let corner_radius = num(
                "corner_radius",
                raw.corner_radius,
                Some(0.0),
                0.0,
                width / 2.0,
                true,
            )?;
            Tool::Grooving {
                width,
                width_dir,
                shank_dir,
                reach,
                corner_radius,
            }
        }
        "drill" => Tool::Drill {
            diameter: num("diameter", raw.diameter, None, 0.0, 10000.0, false)?,
            point_angle: num(
                "point_angle",
                raw.point_angle,
                Some(118.0),
                0.0,
                180.0,
                false,
            )?,
            reach: num("reach", raw.reach, Some(60.0), 0.0, 10000.0, false)?,
        },
        _ => {
            let angle = num("angle", raw.angle, Some(60.0), 0.0, 170.0, false)?;
            Tool::Threading {
                angle,
                tip_flat: num("tip_flat", raw.tip_flat, Some(0.0), 0.0, 100.0, true)?,
            }
        }
    })
}

/// A cache key for the outline of tool `t` under `hint`.
pub(crate) fn hint_key(t: u32, hint: ToolHint) -> (u32, u8, u64) {
    match hint {
        ToolHint::Table => (t, 0, 0),
        ToolHint::Grooving => (t, 1, 0),
        ToolHint::Blade {
            width,
            toward_plus_z,
            shank_plus_x,
        } => (
            t,
            2 + u8::from(toward_plus_z) + 2 * u8::from(shank_plus_x),
            width.to_bits(),
        ),
    }
}

impl ToolTable {
    /// The outline that cuts tool `t` when a cycle adds `hint` (spec/simulation.md, Tools):
    /// the table's entry; in a grooving cycle with no entry, the default 3 mm blade; for
    /// G75.1's I, a blade of the program's width (shank, reach and corner radius from the
    /// table's grooving entry, if any). The text is a warning when a default stands in.
    pub fn outline_for(&self, t: u32, hint: ToolHint) -> (Outline, Option<String>) {
        match hint {
            ToolHint::Table => self.outline(t),
            ToolHint::Grooving => match self.get(t) {
                Some(tool) => (tool.outline(), None),
                None => (
                    Tool::DEFAULT_BLADE.outline(),
                    Some(format!("T{t:02} has no entry in the tool table: the grooving cycle uses the default ({})", Tool::DEFAULT_BLADE.describe())),
                ),
            },
            ToolHint::Blade { width, toward_plus_z, shank_plus_x } => {
                let default_shank = if shank_plus_x { AxisDir::PlusX } else { AxisDir::MinusX };
                let (shank_dir, reach, corner_radius) = match self.get(t) {
                    Some(&Tool::Grooving { shank_dir, reach, corner_radius, .. }) => (shank_dir, reach, corner_radius),
                    _ => (default_shank, 20.0, 0.0),
                };
                if width.is_finite() && width > 0.0 && width < 1e4 {
                    let width_dir = if toward_plus_z { AxisDir::PlusZ } else { AxisDir::MinusZ };
                    let shank_dir = if matches!(shank_dir, AxisDir::PlusX | AxisDir::MinusX) { shank_dir } else { default_shank };
                    let tool = Tool::Grooving { width, width_dir, shank_dir, reach, corner_radius: corner_radius.min(width / 2.0) };
                    (tool.outline(), None)
                } else {
                    let (o, _) = self.outline(t);
                    (o, Some(format!("blade width {width} is not a positive length: T{t:02}'s outline is used")))
                }
            }
        }
    }
}

impl ToolTable {
    /// Nose radius and tip of every turning insert, by offset number (the table's `t`, as
    /// `T0101` pairs tool 01 with offset 01), for G41/G42; other kinds are `None`, for
    /// which compensation is ignored with a warning.
    pub fn noses(
        &self,
    ) -> std::collections::BTreeMap<u32, Result<expander::tnrc::Nose, &'static str>> {
        self.tools
            .iter()
            .map(|(t, tool)| {
                let nose = match tool {
                    Tool::Turning {
                        nose_radius, tip, ..
                    } => Ok(expander::tnrc::Nose {
                        radius: *nose_radius,
                        tip: *tip,
                    }),
                    Tool::Grooving { .. } => Err("grooving blade"),
                    Tool::Drill { .. } => Err("drill"),
                    Tool::Threading { .. } => Err("threading tool"),
                };
                (*t, nose)
            })
            .collect()
    }

    /// Every radial grooving blade by tool number: its width, and whether it extends toward
    /// +Z from its reference corner (G75.1 without I cuts with it).
    pub fn blades(&self) -> std::collections::BTreeMap<u32, (f64, bool)> {
        self.tools
            .iter()
            .filter_map(|(t, tool)| match tool {
                Tool::Grooving {
                    width, width_dir, ..
                } if matches!(width_dir, AxisDir::PlusZ | AxisDir::MinusZ) => {
                    Some((*t, (*width, *width_dir == AxisDir::PlusZ)))
                }
                _ => None,
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g75_1_blade_without_a_table_entry_faces_the_groove() {
        let t = ToolTable::empty();
        let od = ToolHint::Blade {
            width: 4.0,
            toward_plus_z: false,
            shank_plus_x: true,
        };
        let id = ToolHint::Blade {
            width: 4.0,
            toward_plus_z: false,
            shank_plus_x: false,
        };
        let (o, w) = t.outline_for(1, od);
        let (lo, hi) = o.bbox().unwrap();
        assert!(
            w.is_none() && lo[1] >= -1e-9 && hi[1] > 10.0 && (lo[0] + 4.0).abs() < 1e-9,
            "{lo:?} {hi:?}"
        );
        let (lo, hi) = t.outline_for(1, id).0.bbox().unwrap();
        assert!(
            hi[1] <= 1e-9 && lo[1] < -10.0,
            "an ID blade runs toward -X: {lo:?} {hi:?}"
        );
    }

    const SPEC_TABLE: &str = r#"
[[tool]]
t = 1                  # T0101 -> tool 1 (offset 01 turns on its nose radius for G41/G42)
kind = "turning"       # turning | grooving | drill | threading
insert = "V"           # ISO shape letter: C 80°, D 55°, T 60°, V 35°, W 80°, S 90°, R round
nose_radius = 0.4      # mm
tip = 3                # imaginary tip number 0-9 (tnrc.md)
entering_angle = 93    # holder lead angle in degrees (default 93)
edge = 11.0            # cutting edge length in mm (default 11)

[[tool]]
t = 2
kind = "grooving"
width = 3.0
width_dir = "+z"       # from the reference corner the blade spans +z: reference = left corner
shank_dir = "+x"       # the blade body runs from the cutting edge toward +x (OD); -x ID; +z face
reach = 20.0           # blade length in mm (default 20)
corner_radius = 0.0

[[tool]]
t = 3
kind = "drill"
diameter = 10.0
point_angle = 118
reach = 60.0

[[tool]]
t = 4
kind = "threading"
angle = 60
tip_flat = 0.0
"#;

    #[test]
    fn spec_table_parses_with_its_names() {
        let t = ToolTable::from_toml(SPEC_TABLE).unwrap();
        assert_eq!(t.numbers(), vec![1, 2, 3, 4]);
        assert_eq!(t.describe(1), "T01 turning V 35°, r0.4, tip 3, κr 93°");
        assert_eq!(t.describe(3), "T03 drill Ø10, 118° point");
        let (o, w) = t.outline(2);
        assert!(w.is_none());
        assert_eq!(o.bbox().unwrap(), ([0.0, 0.0], [3.0, 20.0]));
        // T0 before any T word: the first entry
        assert_eq!(t.outline(0).0, t.outline(1).0);
    }

    #[test]
    fn missing_tools_get_the_default_with_a_warning() {
        let (o, w) = ToolTable::empty().outline(7);
        assert_eq!(o, Tool::DEFAULT.outline());
        assert!(w.unwrap().contains("55°"));
        let t = ToolTable::from_toml(SPEC_TABLE).unwrap();
        assert!(t.outline(9).1.unwrap().contains("T09"));
    }

    #[test]
    fn bad_entries_name_tool_and_field() {
        let unknown = "[[tool]]\nt = 1\nkind = \"turning\"\nnose = 0.4\n";
        match ToolTable::from_toml(unknown) {
            Err(StockError::Toml { line, message, .. }) => {
                assert_eq!(line, 4);
                assert!(message.contains("nose"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        let cases = [
            ("kind = \"grooving\"\nwidth = -3.0", "width"),
            ("kind = \"turning\"\ntip = 10", "tip"),
            ("kind = \"turning\"\ninsert = \"Q\"", "insert"),
            ("kind = \"drill\"", "diameter"),
            ("kind = \"drill\"\ndiameter = 10.0\nwidth = 3.0", "width"),
            (
                "kind = \"grooving\"\nwidth_dir = \"+z\"\nshank_dir = \"-z\"",
                "shank_dir",
            ),
            ("kind = \"laser\"", "kind"),
        ];
        for (body, field) in cases {
            let text = format!("[[tool]]\nt = 5\n{body}\n");
            match ToolTable::from_toml(&text) {
                Err(StockError::Tool {
                    t, field: f, line, ..
                }) => {
                    assert_eq!((t, f, line), (5, field, 1), "{body}");
                }
                other => panic!("{body}: {other:?}"),
            }
        }
    }
}
