//! The kinds of tool the table knows, with every default filled in, and their one-line
//! descriptions.

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

    /// The ISO shape letter (`C`, `D`, …).
    pub fn letter(self) -> char {
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

    pub(super) fn is_z(self) -> bool {
        matches!(self, Self::PlusZ | Self::MinusZ)
    }

    pub(super) fn text(self) -> &'static str {
        match self {
            Self::PlusZ => "+z",
            Self::MinusZ => "-z",
            Self::PlusX => "+x",
            Self::MinusX => "-x",
        }
    }
}

/// A grooving (parting) blade, every default filled in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroovingBlade {
    /// Blade width, mm (default 3).
    pub width: f64,
    /// Direction the width spans from the reference corner (default +z).
    pub width_dir: AxisDir,
    /// Direction the blade body runs from the cutting edge (default +x, OD).
    pub shank_dir: AxisDir,
    /// Blade length, mm (default 20).
    pub reach: f64,
    /// Radius of both cutting-edge corners, mm (default 0).
    pub corner_radius: f64,
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
    Grooving(GroovingBlade),
    /// A drill on the spindle axis.
    Drill {
        /// Diameter, mm (required).
        diameter: f64,
        /// Point angle, degrees (default 118).
        point_angle: f64,
        /// Length of the body, mm (default 60).
        reach: f64,
    },
    /// A threading insert: OD pointing −X, ID (a boring bar) pointing +X.
    Threading {
        /// Thread angle, degrees (default 60).
        angle: f64,
        /// Width of the tip flat, mm (default 0).
        tip_flat: f64,
        /// Outside or inside thread (`side = "od" | "id"`, default od).
        side: ThreadSide,
    },
}

/// The side a threading insert cuts: OD (body toward +X, the tip cuts inward) or ID (body
/// toward −X, in the bore: the tip cuts outward).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ThreadSide {
    /// Outside thread: the insert points −X.
    Od,
    /// Inside thread: the insert points +X.
    Id,
}

impl Tool {
    /// The documented default when the table has no entry: a 55° insert (D), nose r 0.4,
    /// tip 3, on a 93° holder, 11 mm edge.
    /// Its nose is the interpreter's default nose ([`toolfacts::Nose::DEFAULT`]).
    pub const DEFAULT: Self = Self::Turning {
        insert: Insert::D,
        nose_radius: toolfacts::Nose::DEFAULT.radius,
        tip: toolfacts::Nose::DEFAULT.tip,
        entering_angle: 93.0,
        edge: 11.0,
    };

    /// The default G74/G75 blade: 3 mm wide, referenced at its left corner, OD, 20 mm reach.
    pub const DEFAULT_BLADE: Self = Self::Grooving(GroovingBlade {
        width: 3.0,
        width_dir: AxisDir::PlusZ,
        shank_dir: AxisDir::PlusX,
        reach: 20.0,
        corner_radius: 0.0,
    });

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
            Self::Grooving(b) => format!(
                "grooving {} mm, width {}, shank {}, reach {}{}",
                n(b.width),
                b.width_dir.text(),
                b.shank_dir.text(),
                n(b.reach),
                if b.corner_radius > 0.0 {
                    format!(", corners r{}", n(b.corner_radius))
                } else {
                    String::new()
                }
            ),
            Self::Drill {
                diameter,
                point_angle,
                ..
            } => format!("drill Ø{}, {}° point", n(diameter), n(point_angle)),
            Self::Threading {
                angle,
                tip_flat,
                side,
            } => {
                format!(
                    "threading {}{}°{}",
                    if side == ThreadSide::Id { "ID " } else { "" },
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

    /// The tool as `[[tool]]` fields (TOML, without `t`), every size stated: what reads back
    /// as this tool (a remedy's tool, re-run in a table).
    pub fn toml_fields(&self) -> String {
        match *self {
            Self::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            } => format!(
                "kind = \"turning\"\ninsert = \"{}\"\nnose_radius = {nose_radius:?}\ntip = {tip}\nentering_angle = {entering_angle:?}\nedge = {edge:?}\n",
                insert.letter()
            ),
            Self::Grooving(b) => format!(
                "kind = \"grooving\"\nwidth = {:?}\nwidth_dir = \"{}\"\nshank_dir = \"{}\"\nreach = {:?}\ncorner_radius = {:?}\n",
                b.width,
                b.width_dir.text(),
                b.shank_dir.text(),
                b.reach,
                b.corner_radius
            ),
            Self::Drill {
                diameter,
                point_angle,
                reach,
            } => format!(
                "kind = \"drill\"\ndiameter = {diameter:?}\npoint_angle = {point_angle:?}\nreach = {reach:?}\n"
            ),
            Self::Threading {
                angle,
                tip_flat,
                side,
            } => format!(
                "kind = \"threading\"\nangle = {angle:?}\ntip_flat = {tip_flat:?}\nside = \"{}\"\n",
                if side == ThreadSide::Id { "id" } else { "od" }
            ),
        }
    }
}
