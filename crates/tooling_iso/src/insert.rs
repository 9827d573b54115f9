//! ISO 1832 indexable insert designations: `"CNMG 120408"`, `"cnmg120408-pm"`, the inch
//! (ANSI B212.4) form `"CNMG 432"`, and the facts a tool outline needs.
//!
//! Reference positions read here: (1) shape, (2) normal clearance, (3) tolerance class,
//! (4) type (fixing and chip breaker), (5) size, (6) thickness, (7) corner (nose radius).
//! Anything after the nose code (edge condition, hand, a maker's chip-breaker after a `-`)
//! is kept as [`Insert::suffix`].

use crate::IsoError;

/// The expected form, shown in every insert error.
pub const INSERT_FORM: &str = "expected an ISO 1832 insert like \"CNMG 120408\" (shape, clearance, tolerance, type letters; size, thickness, nose radius codes) or the inch form \"CNMG 432\"";

/// Insert shape, ISO 1832 reference position (1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Hexagon, 120°.
    H,
    /// Octagon, 135°.
    O,
    /// Pentagon, 108°.
    P,
    /// Square, 90°.
    S,
    /// Triangle, 60°.
    T,
    /// Rhombic 80°.
    C,
    /// Rhombic 55°.
    D,
    /// Rhombic 75°.
    E,
    /// Rhombic 86°.
    M,
    /// Rhombic 35°.
    V,
    /// Trigon 80° (a hexagon of equal edges with alternating 80° and 160° corners).
    W,
    /// Rectangle, 90°.
    L,
    /// Parallelogram 85°.
    A,
    /// Parallelogram 82°.
    B,
    /// Parallelogram 55°.
    K,
    /// Round.
    R,
}

/// The body an insert shape has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Body {
    /// Equal edges, two acute corners (C, D, E, M, V) — S is the square case.
    Rhombic,
    /// Equilateral triangle (T).
    Triangle,
    /// Trigon (W).
    Trigon,
    /// Regular polygon with more than four corners (H, O, P).
    Polygon,
    /// Rectangle (L).
    Rectangle,
    /// Parallelogram with unequal edges (A, B, K).
    Parallelogram,
    /// Round (R).
    Round,
}

impl Shape {
    /// Every shape letter.
    pub const ALL: [Self; 16] = [
        Self::H,
        Self::O,
        Self::P,
        Self::S,
        Self::T,
        Self::C,
        Self::D,
        Self::E,
        Self::M,
        Self::V,
        Self::W,
        Self::L,
        Self::A,
        Self::B,
        Self::K,
        Self::R,
    ];

    /// From the letter (either case).
    pub fn from_letter(c: char) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|s| s.letter() == c.to_ascii_uppercase())
    }

    /// The ISO letter.
    pub fn letter(self) -> char {
        match self {
            Self::H => 'H',
            Self::O => 'O',
            Self::P => 'P',
            Self::S => 'S',
            Self::T => 'T',
            Self::C => 'C',
            Self::D => 'D',
            Self::E => 'E',
            Self::M => 'M',
            Self::V => 'V',
            Self::W => 'W',
            Self::L => 'L',
            Self::A => 'A',
            Self::B => 'B',
            Self::K => 'K',
            Self::R => 'R',
        }
    }

    /// Included (cutting corner) angle ε in degrees; 360 for round.
    pub fn included_angle(self) -> f64 {
        match self {
            Self::H => 120.0,
            Self::O => 135.0,
            Self::P => 108.0,
            Self::S | Self::L => 90.0,
            Self::T => 60.0,
            Self::C | Self::W => 80.0,
            Self::D | Self::K => 55.0,
            Self::E => 75.0,
            Self::M => 86.0,
            Self::V => 35.0,
            Self::A => 85.0,
            Self::B => 82.0,
            Self::R => 360.0,
        }
    }

    /// The body.
    pub fn body(self) -> Body {
        match self {
            Self::S | Self::C | Self::D | Self::E | Self::M | Self::V => Body::Rhombic,
            Self::T => Body::Triangle,
            Self::W => Body::Trigon,
            Self::H | Self::O | Self::P => Body::Polygon,
            Self::L => Body::Rectangle,
            Self::A | Self::B | Self::K => Body::Parallelogram,
            Self::R => Body::Round,
        }
    }

    /// Cutting edge length l from the inscribed circle d, by the shape's geometry; `None`
    /// where the inscribed circle does not fix it (L, A, B, K: two edge lengths).
    ///
    /// - rhombic (and square) with acute corner ε: the IC touches all four sides, the
    ///   distance between opposite sides is d = l·sin ε, so l = d / sin ε;
    /// - triangle: l = 2·√3·(d/2) = √3·d;
    /// - regular n-gon: l = d·tan(π/n);
    /// - trigon W (80°/160° corners, equal edges): from the centre, each edge's foot is d/2
    ///   away and the corners sit on 40° and 80° half angles, l = (d/2)(cot 40° + cot 80°);
    /// - round: the diameter.
    pub fn edge_from_ic(self, d: f64) -> Option<f64> {
        let deg = f64::to_radians;
        Some(match self.body() {
            Body::Rhombic => d / deg(self.included_angle()).sin(),
            Body::Triangle => 3f64.sqrt() * d,
            Body::Polygon => {
                let n = match self {
                    Self::H => 6.0,
                    Self::O => 8.0,
                    _ => 5.0,
                };
                d * (std::f64::consts::PI / n).tan()
            }
            Body::Trigon => d / 2.0 * (1.0 / deg(40.0).tan() + 1.0 / deg(80.0).tan()),
            Body::Round => d,
            Body::Rectangle | Body::Parallelogram => return None,
        })
    }

    /// Name, e.g. "rhombic 80°".
    pub fn describe(self) -> String {
        let a = self.included_angle();
        match self.body() {
            Body::Round => "round".into(),
            Body::Rhombic if self == Self::S => "square 90°".into(),
            Body::Rhombic => format!("rhombic {a}°"),
            Body::Triangle => "triangle 60°".into(),
            Body::Trigon => "trigon 80°".into(),
            Body::Polygon => format!("polygon {a}°"),
            Body::Rectangle => "rectangle 90°".into(),
            Body::Parallelogram => format!("parallelogram {a}°"),
        }
    }
}

/// Normal clearance angle of ISO 1832 position (2), degrees; `None` for an unknown letter
/// (O, "other", gives `Some(None)`: a special clearance stated elsewhere).
pub fn clearance_angle(letter: char) -> Option<Option<f64>> {
    Some(Some(match letter {
        'A' => 3.0,
        'B' => 5.0,
        'C' => 7.0,
        'D' => 15.0,
        'E' => 20.0,
        'F' => 25.0,
        'G' => 30.0,
        'N' => 0.0,
        'P' => 11.0,
        'O' => return Some(None),
        _ => return None,
    }))
}

const TOLERANCE_CLASSES: &str = "ACEFGHJKLMNU";

/// What the type letter of position (4) says (fixing hole and chip breaker).
pub fn type_meaning(letter: char) -> Option<&'static str> {
    Some(match letter {
        'N' => "no hole, no chip breaker",
        'R' => "no hole, chip breaker on one face",
        'F' => "no hole, chip breakers on both faces",
        'A' => "cylindrical hole, no chip breaker",
        'M' => "cylindrical hole, chip breaker on one face",
        'G' => "cylindrical hole, chip breakers on both faces",
        'W' => "hole with one countersink (40-60°), no chip breaker",
        'T' => "hole with one countersink (40-60°), chip breaker on one face",
        'Q' => "hole with two countersinks (40-60°), no chip breaker",
        'U' => "hole with two countersinks (40-60°), chip breakers on both faces",
        'B' => "hole with one countersink (70-90°), no chip breaker",
        'H' => "hole with one countersink (70-90°), chip breaker on one face",
        'C' => "hole with two countersinks (70-90°), no chip breaker",
        'J' => "hole with two countersinks (70-90°), chip breakers on both faces",
        'X' => "special design",
        _ => return None,
    })
}

/// Whether the designation used metric codes or the inch form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Units {
    /// `CNMG 120408`: size = edge length in mm, thickness and nose radius in mm codes.
    Metric,
    /// `CNMG 432`: size in 1/8" of inscribed circle, thickness in 1/16", nose in 1/64".
    Inch,
}

/// Facts from an ISO 1832 insert designation.
#[derive(Debug, Clone, PartialEq)]
pub struct Insert {
    /// The designation as given (trimmed).
    pub designation: String,
    /// Shape (position 1).
    pub shape: Shape,
    /// Clearance letter (position 2).
    pub clearance: char,
    /// Normal clearance angle, degrees (`None` for O, special).
    pub clearance_angle: Option<f64>,
    /// Tolerance class letter (position 3).
    pub tolerance: char,
    /// Type letter: fixing and chip breaker (position 4).
    pub kind: char,
    /// Metric or inch codes.
    pub units: Units,
    /// The size code as written ("12", "4").
    pub size_code: String,
    /// Cutting edge length, mm (round: the diameter). Metric: derived from the standard
    /// inscribed circle when the shape allows, else the code's whole millimetres.
    pub edge_length: f64,
    /// Inscribed circle, mm, when known.
    pub inscribed_circle: Option<f64>,
    /// Thickness, mm.
    pub thickness: f64,
    /// Nose (corner) radius, mm (0 sharp).
    pub nose_radius: f64,
    /// Anything after the nose code (edge condition, hand, chip-breaker), trimmed.
    pub suffix: String,
}

/// Standard inscribed circles, mm: the inch series (ISO 1832 lists it first) then metric.
const IC_SERIES: [f64; 21] = [
    3.97, 4.76, 5.56, 6.35, 7.94, 9.525, 12.7, 15.875, 19.05, 25.4, 31.75, // inch based
    4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0, // metric
];

/// Metric thickness codes, ISO 1832 position (6), mm.
const THICKNESS: [(&str, f64); 11] = [
    ("01", 1.59),
    ("T1", 1.98),
    ("02", 2.38),
    ("T2", 2.78),
    ("03", 3.18),
    ("T3", 3.97),
    ("04", 4.76),
    ("05", 5.56),
    ("06", 6.35),
    ("07", 7.94),
    ("09", 9.52),
];

/// Metric nose radius codes that exist (ISO 1832 position 7: radius in tenths of a mm).
const NOSE_METRIC: [&str; 11] = [
    "00", "01", "02", "04", "08", "12", "16", "20", "24", "28", "32",
];
/// Inch nose radius digits (in 1/64"); 5 and 7 are not in the series.
const NOSE_INCH: [u32; 7] = [0, 1, 2, 3, 4, 6, 8];

/// The size digits of an edge length: the standard's tables give l to 0.1 mm (T with
/// d 6.35: l = 10.998, listed 11.0, code 11), then the decimals are cut off.
fn table_code(l: f64) -> f64 {
    (l * 10.0).round().div_euclid(10.0)
}

fn err(text: &str, problem: impl Into<String>) -> IsoError {
    IsoError::Insert {
        designation: text.to_string(),
        problem: problem.into(),
    }
}

impl Insert {
    /// Parses a designation: spaces and case do not matter; a maker's suffix after the nose
    /// code (`-PM`, `EN`, …) is kept.
    pub fn parse(text: &str) -> Result<Self, IsoError> {
        let (designation, s) = crate::normalized(text);
        if s.len() < 7 {
            return Err(err(
                text,
                format!(
                    "is {} characters without spaces, too short (at least 4 letters and 3 codes)",
                    s.len()
                ),
            ));
        }
        let shape = Shape::from_letter(s[0]).ok_or_else(|| {
            err(
                text,
                format!(
                    "'{}' is not an ISO shape letter (H O P S T C D E M V W L A B K R)",
                    s[0]
                ),
            )
        })?;
        let clearance_angle = clearance_angle(s[1]).ok_or_else(|| {
            err(
                text,
                format!("'{}' is not a clearance letter (A B C D E F G N P O)", s[1]),
            )
        })?;
        if !TOLERANCE_CLASSES.contains(s[2]) {
            return Err(err(
                text,
                format!(
                    "'{}' is not a tolerance class (A C E F G H J K L M N U)",
                    s[2]
                ),
            ));
        }
        if type_meaning(s[3]).is_none() {
            return Err(err(
                text,
                format!(
                    "'{}' is not a type letter (A B C F G H J M N Q R T U W X)",
                    s[3]
                ),
            ));
        }
        let rest: String = s[4..].iter().collect();
        let metric = rest.len() >= 6
            && rest.as_bytes()[..2].iter().all(u8::is_ascii_digit)
            && (rest.as_bytes()[2].is_ascii_digit() || rest.as_bytes()[2] == b'T')
            && rest.as_bytes()[3].is_ascii_digit()
            && (rest.as_bytes()[4].is_ascii_digit() || rest.as_bytes()[4] == b'M')
            && rest.as_bytes()[5].is_ascii_digit();
        let mut insert = Self {
            designation: designation.clone(),
            shape,
            clearance: s[1],
            clearance_angle,
            tolerance: s[2],
            kind: s[3],
            units: Units::Metric,
            size_code: String::new(),
            edge_length: 0.0,
            inscribed_circle: None,
            thickness: 0.0,
            nose_radius: 0.0,
            suffix: String::new(),
        };
        if metric {
            insert.metric_codes(text, &rest)?;
        } else {
            insert.inch_codes(text, &rest)?;
        }
        Ok(insert)
    }

    fn metric_codes(&mut self, text: &str, rest: &str) -> Result<(), IsoError> {
        let (size, thick, nose) = (&rest[0..2], &rest[2..4], &rest[4..6]);
        let code: f64 = size.parse().unwrap_or(0.0);
        if code < 1.0 {
            return Err(err(
                text,
                format!("size code \"{size}\" is not an edge length in mm"),
            ));
        }
        self.size_code = size.to_string();
        // The size digits are the edge length with its decimals cut off (round: the
        // diameter); the standard inscribed circle whose edge truncates to them is taken.
        match self.shape.body() {
            Body::Round => {
                self.edge_length = code;
                self.inscribed_circle = Some(code);
            }
            _ => match IC_SERIES
                .iter()
                .filter_map(|&d| Some((d, self.shape.edge_from_ic(d)?)))
                .find(|(_, l)| table_code(*l) == code)
            {
                Some((d, l)) => {
                    self.edge_length = l;
                    self.inscribed_circle = Some(d);
                }
                None => self.edge_length = code,
            },
        }
        self.thickness = match THICKNESS.iter().find(|(c, _)| *c == thick) {
            Some(&(_, t)) => t,
            None if thick.starts_with('T') => {
                return Err(err(
                    text,
                    format!(
                        "thickness code \"{thick}\" does not exist (T1 T2 T3, or whole mm like 04)"
                    ),
                ))
            }
            None => thick.parse().unwrap_or(0.0),
        };
        self.nose_radius = match nose {
            "M0" => 0.0, // round insert, metric: no corner
            n if NOSE_METRIC.contains(&n) => n.parse::<f64>().unwrap_or(0.0) / 10.0,
            n => {
                return Err(err(
                    text,
                    format!("nose radius code \"{n}\" does not exist (00 01 02 04 08 12 16 20 24 28 32, tenths of a mm)"),
                ))
            }
        };
        self.suffix = rest[6..].trim_start_matches('-').to_string();
        Ok(())
    }

    fn inch_codes(&mut self, text: &str, rest: &str) -> Result<(), IsoError> {
        // size, thickness and nose radius: one digit each, size and thickness may carry ".5"
        let mut chars = rest.char_indices().peekable();
        let mut fields = Vec::new();
        while fields.len() < 3 {
            let Some((i, c)) = chars.next() else { break };
            if !c.is_ascii_digit() {
                return Err(err(
                    text,
                    format!("'{c}' where a size, thickness or nose radius code was expected"),
                ));
            }
            let mut end = i + 1;
            if fields.len() < 2 && rest[end..].starts_with(".5") {
                chars.next();
                chars.next();
                end += 2;
            }
            fields.push((&rest[i..end], end));
        }
        if fields.len() < 3 {
            return Err(err(
                text,
                "needs three codes after the letters: size, thickness, nose radius",
            ));
        }
        let after = &rest[fields[2].1..];
        if after.starts_with(|c: char| c.is_ascii_digit()) {
            let digits = rest
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .count();
            return Err(err(
                text,
                format!("has {digits} code characters: metric needs 6 (size, thickness, nose: 120408), inch 3 (432)"),
            ));
        }
        let size: f64 = fields[0].0.parse().unwrap_or(0.0);
        let thick: f64 = fields[1].0.parse().unwrap_or(0.0);
        let nose: u32 = fields[2].0.parse().unwrap_or(99);
        if size <= 0.0 || thick <= 0.0 {
            return Err(err(text, "size and thickness codes must be positive"));
        }
        if !NOSE_INCH.contains(&nose) {
            return Err(err(
                text,
                format!(
                    "inch nose radius code \"{nose}\" does not exist (0 1 2 3 4 6 8, in 1/64\")"
                ),
            ));
        }
        const INCH: f64 = 25.4;
        let d = size / 8.0 * INCH;
        self.units = Units::Inch;
        self.size_code = fields[0].0.to_string();
        self.inscribed_circle = Some(d);
        self.edge_length = self.shape.edge_from_ic(d).unwrap_or(d);
        self.thickness = thick / 16.0 * INCH;
        self.nose_radius = f64::from(nose) / 64.0 * INCH;
        self.suffix = rest[fields[2].1..].trim_start_matches('-').to_string();
        Ok(())
    }

    /// Included angle ε, degrees.
    pub fn included_angle(&self) -> f64 {
        self.shape.included_angle()
    }

    /// The edge length in whole mm, as a holder's size digits name it.
    pub fn edge_code(&self) -> u32 {
        table_code(self.edge_length) as u32
    }
}
