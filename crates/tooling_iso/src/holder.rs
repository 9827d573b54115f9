//! ISO 5608 external turning holder designations (`"PCLNR 2525M12"`, `"SVJBR 2525M16"`)
//! and ISO 6261-style boring bars (`"S20R-SCLCR09"`).

use crate::insert::Shape;
use crate::IsoError;

/// The expected form, shown in every holder error.
pub const HOLDER_FORM: &str = "expected an ISO 5608 holder like \"PCLNR 2525M12\" (clamping, insert shape, style, clearance, hand; shank height and width, length letter, insert size) or a boring bar like \"S20R-SCLCR09\"";

/// Hand of a holder (position 5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hand {
    /// Right hand: cuts toward the chuck (−Z) on a conventional lathe.
    R,
    /// Left hand: cuts away from the chuck (+Z).
    L,
    /// Neutral.
    N,
}

/// A holder style (position 3): entering angle κr (ISO 3002-1, between the main edge and the
/// feed direction) and whether it is an end-cutting (facing) style.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Style {
    /// The letter.
    pub letter: char,
    /// Entering angle κr, degrees.
    pub entering_angle: f64,
    /// The main edge faces (feed along X) rather than turns.
    pub end_cutting: bool,
}

impl Style {
    /// Lead angle (the ANSI habit): 90° − κr.
    pub fn lead_angle(&self) -> f64 {
        90.0 - self.entering_angle
    }
}

/// The style letters with their κr. Sources: Sumitomo Electric general catalogue 2019-2020,
/// "Holders External, Cutting Edge Position Dimension" (A 90, B 75, D 45, E 60, F 90 end,
/// G 90 offset, J 93, K 75 end, L 95, N 63, S 45, T 60, Y 85 end); Q 107.5, R 75 and
/// V 72.5 are the common catalogue values (not found in a fetched page: see the report).
pub const STYLES: [Style; 16] = [
    st('A', 90.0, false),
    st('B', 75.0, false),
    st('D', 45.0, false),
    st('E', 60.0, false),
    st('F', 90.0, true),
    st('G', 90.0, false),
    st('J', 93.0, false),
    st('K', 75.0, true),
    st('L', 95.0, false),
    st('N', 63.0, false),
    st('Q', 107.5, false),
    st('R', 75.0, false),
    st('S', 45.0, false),
    st('T', 60.0, false),
    st('V', 72.5, false),
    st('Y', 85.0, true),
];

const fn st(letter: char, entering_angle: f64, end_cutting: bool) -> Style {
    Style {
        letter,
        entering_angle,
        end_cutting,
    }
}

/// Holder length letters (position 8), mm (ISO 5608 table; G 90 and W 450).
pub const LENGTHS: [(char, f64); 22] = [
    ('A', 32.0),
    ('B', 40.0),
    ('C', 50.0),
    ('D', 60.0),
    ('E', 70.0),
    ('F', 80.0),
    ('G', 90.0),
    ('H', 100.0),
    ('J', 110.0),
    ('K', 125.0),
    ('L', 140.0),
    ('M', 150.0),
    ('N', 160.0),
    ('P', 170.0),
    ('Q', 180.0),
    ('R', 200.0),
    ('S', 250.0),
    ('T', 300.0),
    ('U', 350.0),
    ('V', 400.0),
    ('W', 450.0),
    ('Y', 500.0),
];

const CLAMPS: &str = "CDMPSW";

/// The shank: a rectangle for external holders, a round bar for boring bars.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shank {
    /// External holder: height h × width b, mm.
    Square {
        /// Height h, mm.
        height: f64,
        /// Width b, mm.
        width: f64,
    },
    /// Boring bar of this diameter, mm, and bar type letter (S steel, A steel with coolant,
    /// E carbide, F damped carbide).
    Bar {
        /// Diameter, mm.
        diameter: f64,
        /// Bar type letter.
        kind: char,
    },
}

/// Facts from a holder designation.
#[derive(Debug, Clone, PartialEq)]
pub struct Holder {
    /// The designation as given (trimmed).
    pub designation: String,
    /// Clamping letter (C top clamp, D double, M top and hole, P lever, S screw, W wedge).
    pub clamping: char,
    /// Insert shape the pocket takes.
    pub shape: Shape,
    /// Style: entering angle.
    pub style: Style,
    /// Clearance letter of the insert it takes.
    pub clearance: char,
    /// Hand.
    pub hand: Hand,
    /// Shank section.
    pub shank: Shank,
    /// Overall length, mm (`None` for "-": the ISO 5610 preferred length).
    pub length: Option<f64>,
    /// Insert size digits (edge length in whole mm).
    pub insert_size: u32,
    /// Anything after, trimmed.
    pub suffix: String,
}

fn err(text: &str, problem: impl Into<String>) -> IsoError {
    IsoError::Holder {
        designation: text.to_string(),
        problem: problem.into(),
    }
}

fn two_digits(text: &str, s: &[char], at: usize, what: &str) -> Result<u32, IsoError> {
    match s.get(at..at + 2) {
        Some([a, b]) if a.is_ascii_digit() && b.is_ascii_digit() => {
            Ok(a.to_digit(10).unwrap_or(0) * 10 + b.to_digit(10).unwrap_or(0))
        }
        _ => Err(err(
            text,
            format!(
                "{what} needs two digits at character {} (\"{}\")",
                at + 1,
                s.get(at..)
                    .map(|r| r.iter().collect::<String>())
                    .unwrap_or_default()
            ),
        )),
    }
}

impl Holder {
    /// Parses an external holder or a boring bar (spaces and case do not matter).
    pub fn parse(text: &str) -> Result<Self, IsoError> {
        let (designation, s) = crate::normalized(text);
        let bar = s.first().is_some_and(|c| "SAEF".contains(*c))
            && s.get(1).is_some_and(char::is_ascii_digit);
        let ((clamping, shape, style, clearance, hand), shank, length, insert_size) = if bar {
            bar_parts(text, &s)?
        } else {
            external_parts(text, &s)?
        };
        Ok(Self {
            designation,
            clamping,
            shape,
            style,
            clearance,
            hand,
            shank,
            length,
            insert_size,
            suffix: s[12..]
                .iter()
                .collect::<String>()
                .trim_start_matches('-')
                .to_string(),
        })
    }

    /// A boring bar (internal tool).
    pub fn is_internal(&self) -> bool {
        matches!(self.shank, Shank::Bar { .. })
    }
}

fn length_letter(text: &str, c: char) -> Result<Option<f64>, IsoError> {
    if c == '-' {
        return Ok(None);
    }
    LENGTHS
        .iter()
        .find(|(l, _)| *l == c)
        .map(|&(_, mm)| Some(mm))
        .ok_or_else(|| {
            err(
                text,
                format!("'{c}' is not a length letter (A 32 … H 100, K 125, M 150, P 170, Q 180, R 200 … Y 500)"),
            )
        })
}

type Head = (char, Shape, Style, char, Hand);

/// What a designation's first 12 characters give: head, shank, length, insert size.
type Parts = (Head, Shank, Option<f64>, u32);

/// `PCLNR2525M12`: the head's five letters, shank height and width, length letter and
/// the insert size.
fn external_parts(text: &str, s: &[char]) -> Result<Parts, IsoError> {
    if s.len() < 12 {
        return Err(err(
            text,
            format!(
                "is {} characters without spaces, too short (12 needed: PCLNR2525M12)",
                s.len()
            ),
        ));
    }
    let head = head(text, &s[0..5])?;
    let height = two_digits(text, s, 5, "shank height")?;
    let width = two_digits(text, s, 7, "shank width")?;
    let shank = Shank::Square {
        height: f64::from(height),
        width: f64::from(width),
    };
    let length = length_letter(text, s[9])?;
    Ok((head, shank, length, two_digits(text, s, 10, "insert size")?))
}

/// `S20R-SCLCR09`: bar type, diameter, length letter, `-`, then the head as an external
/// holder's five letters and the insert size.
fn bar_parts(text: &str, s: &[char]) -> Result<Parts, IsoError> {
    let diameter = two_digits(text, s, 1, "bar diameter")?;
    let length = length_letter(text, *s.get(3).unwrap_or(&' '))?;
    if s.get(4) != Some(&'-') || s.len() < 12 {
        return Err(err(
            text,
            "a boring bar reads type, diameter, length letter, '-', five letters and the insert size (S20R-SCLCR09)",
        ));
    }
    let head = head(text, &s[5..10])?;
    let shank = Shank::Bar {
        diameter: f64::from(diameter),
        kind: s[0],
    };
    Ok((head, shank, length, two_digits(text, s, 10, "insert size")?))
}

fn head(text: &str, h: &[char]) -> Result<Head, IsoError> {
    if !CLAMPS.contains(h[0]) {
        return Err(err(
            text,
            format!("'{}' is not a clamping letter (C D M P S W)", h[0]),
        ));
    }
    let shape = Shape::from_letter(h[1])
        .ok_or_else(|| err(text, format!("'{}' is not an insert shape letter", h[1])))?;
    let style = STYLES
        .iter()
        .copied()
        .find(|s| s.letter == h[2])
        .ok_or_else(|| {
            let known: String = STYLES.iter().map(|s| s.letter).collect();
            err(
                text,
                format!("'{}' is not a holder style letter ({known})", h[2]),
            )
        })?;
    if crate::insert::clearance_angle(h[3]).is_none() {
        return Err(err(
            text,
            format!("'{}' is not a clearance letter (A B C D E F G N P O)", h[3]),
        ));
    }
    let hand = match h[4] {
        'R' => Hand::R,
        'L' => Hand::L,
        'N' => Hand::N,
        c => return Err(err(text, format!("'{c}' is not a hand (R, L or N)"))),
    };
    Ok((h[0], shape, style, h[3], hand))
}
