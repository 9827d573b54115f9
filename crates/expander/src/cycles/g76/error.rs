//! What can be wrong with a G76 block or its planning: the kinds, their alarm codes, messages
//! and help, and the word each points at.

use super::{At, MAX_PASSES};
use crate::{Diagnostic, Span};

/// What is wrong with a G76.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum G76ErrorKind {
    /// `G76 P(pitch) … J … H …`: LinuxCNC/Mach G76, a different dialect (§4.5).
    LinuxCnc,
    /// A block that reads as a second block (F, or one-block K/D) without X/Z/U/W.
    NoEndPoint,
    /// A required word is absent.
    Missing {
        /// What the word gives.
        what: &'static str,
    },
    /// A least-increment word written with a decimal point (language.md).
    DecimalPoint {
        /// mm per increment.
        mm_per_unit: f64,
    },
    /// First-block P is not six digits mm rr aa (negative, fractional, > 999999).
    PDigits {
        /// The value written.
        value: f64,
    },
    /// m = 0 (first-block P digits 1–2, or the profile).
    NoFinishingPass,
    /// a not in {0, 29, 30, 55, 60, 80} (two-block) or A outside 0–120 (one-block).
    ToolAngle {
        /// The angle.
        a: f64,
        /// The one-block form (0–120) rather than the two-block list.
        one_block: bool,
    },
    /// One-block P not 1–4.
    InfeedType {
        /// The value written.
        value: f64,
    },
    /// One-block Q not a whole number 0–360000 (0.001°).
    StartAngle {
        /// The value written.
        value: f64,
    },
    /// k ≤ 0.
    Height {
        /// k, mm.
        k: f64,
    },
    /// Δd ≤ 0.
    FirstDepth {
        /// Δd, mm.
        dd: f64,
    },
    /// Haas: both F and E give the lead.
    LeadTwice,
    /// L ≤ 0.
    Lead {
        /// L, mm.
        lead: f64,
    },
    /// Δdmin < 0.
    MinDepth {
        /// Δdmin, mm.
        dmin: f64,
    },
    /// d < 0 or d ≥ k: no depth is left for the rough passes.
    Allowance {
        /// d, mm.
        d: f64,
        /// k, mm.
        k: f64,
    },
    /// The chamfer angle is not strictly between 0° and 90°.
    ChamferAngle {
        /// Degrees from Z.
        angle: f64,
    },
    /// The thread has no Z travel (Za = Z).
    NoZTravel,
    /// γ = r·L/10 is not shorter than the thread's Z travel.
    ChamferTooLong {
        /// γ, mm.
        gamma: f64,
        /// |Za − Z|, mm.
        travel: f64,
    },
    /// No radial travel: the start point is on the end point's diameter, so the cycle
    /// cannot tell an OD thread from an ID one, nor retract.
    NoRadialTravel,
    /// |i| > |U/2| with i and U/2 of opposite signs.
    Taper {
        /// i, mm.
        i: f64,
        /// U/2, mm.
        half_u: f64,
    },
    /// More passes than [`MAX_PASSES`].
    TooManyPasses {
        /// About how many the words ask for.
        estimate: f64,
    },
}

/// An alarm of a G76, with the word at fault.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct G76Error {
    /// What is wrong.
    pub(crate) kind: G76ErrorKind,
    /// The word at fault: its letter and, when a word gave the value, its span (`None`: point
    /// at the G76 word). `None` entirely: the block as a whole (no end point, `LinuxCNC` form).
    pub(crate) at: Option<At>,
}

impl G76Error {
    pub(super) fn new(kind: G76ErrorKind, at: At) -> Self {
        Self { kind, at: Some(at) }
    }

    /// The span to show: the faulty word's, else `fallback` (the G76 word).
    pub(crate) fn span(&self, fallback: Span) -> Span {
        self.at.and_then(|a| a.span).unwrap_or(fallback)
    }

    /// The stable diagnostic code.
    pub(crate) fn code(&self) -> &'static str {
        use G76ErrorKind as K;
        match self.kind {
            K::LinuxCnc => "LS-G76-LINUXCNC",
            K::NoEndPoint | K::Missing { .. } | K::LeadTwice => "LS-G76-WORD",
            K::DecimalPoint { .. } => "LS-INCREMENT",
            K::ChamferAngle { .. } => "LS-G76-CHAMFER-ANGLE",
            K::NoZTravel | K::ChamferTooLong { .. } => "LS-G76-CHAMFER",
            K::NoRadialTravel => "LS-G76-TRAVEL",
            K::Taper { .. } => "LS-G76-TAPER",
            K::TooManyPasses { .. } => "LS-G76-PASSES",
            K::PDigits { .. }
            | K::NoFinishingPass
            | K::ToolAngle { .. }
            | K::InfeedType { .. }
            | K::StartAngle { .. }
            | K::Height { .. }
            | K::FirstDepth { .. }
            | K::Lead { .. }
            | K::MinDepth { .. }
            | K::Allowance { .. } => "PS062",
        }
    }

    /// What happened.
    pub(crate) fn message(&self) -> String {
        use G76ErrorKind as K;
        let l = self.at.map_or('?', |a| a.letter);
        match self.kind {
            K::LinuxCnc => "LinuxCNC-style G76 (P pitch, J, H …) is not supported".into(),
            K::NoEndPoint => "G76 block with thread words but no end point X/Z (U/W)".into(),
            K::Missing { what } => format!("G76: {l} ({what}) is missing"),
            K::DecimalPoint { mm_per_unit } => format!(
                "{l} is in least input increments ({mm_per_unit} mm) and takes no decimal point"
            ),
            K::PDigits { value } => {
                format!("G76 first block P{value} is not six digits m m r r a a")
            }
            K::NoFinishingPass => "G76: m, the number of finishing passes, is 0".into(),
            K::ToolAngle { a, one_block: false } => {
                format!("G76 tool angle a = {a} is not one of 0, 29, 30, 55, 60, 80")
            }
            K::ToolAngle { a, one_block: true } => {
                format!("G76 A{a}: the tool angle must be a whole number 0 … 120")
            }
            K::InfeedType { value } => {
                format!("G76 P{value}: a one-block G76 takes P1 … P4 (infeed type)")
            }
            K::StartAngle { value } => {
                format!("G76 Q{value}: the start angle is a whole number 0 … 360000 (0.001°)")
            }
            K::Height { k } => format!("G76 thread height k = {k} mm is not positive"),
            K::FirstDepth { dd } => format!("G76 first depth Δd = {dd} mm is not positive"),
            K::LeadTwice => "G76: F and E both give the lead".into(),
            K::Lead { lead } => format!("G76 lead L = {lead} mm is not positive"),
            K::MinDepth { dmin } => format!("G76 minimum depth Δdmin = {dmin} mm is negative"),
            K::Allowance { d, k } if d < 0.0 => {
                format!("G76 finishing allowance d = {d} mm is negative (k = {k} mm)")
            }
            K::Allowance { d, k } => format!(
                "G76 finishing allowance d = {d} mm is not smaller than the thread height k = {k} mm"
            ),
            K::ChamferAngle { angle } => {
                format!("G76 chamfer angle {angle}° is not between 0° and 90°")
            }
            K::NoZTravel => "G76 end Z equals the start Z: the thread has no length".into(),
            K::ChamferTooLong { gamma, travel } => format!(
                "G76 pull-out chamfer γ = {gamma:.3} mm is not shorter than the thread's Z travel {travel:.3} mm"
            ),
            K::NoRadialTravel => {
                "G76 starts on the thread's end diameter: no radial travel, so neither the side (OD or ID) nor the retract is defined".into()
            }
            K::Taper { i, half_u } => format!(
                "G76 taper {l}{i} is larger than the X travel U/2 = {half_u:.3} with the opposite sign"
            ),
            K::TooManyPasses { estimate } => format!(
                "G76 would cut about {estimate:.0} passes (at most {MAX_PASSES})"
            ),
        }
    }

    /// What to change.
    pub(crate) fn help(&self) -> String {
        use G76ErrorKind as K;
        let l = self.at.map_or('?', |a| a.letter);
        match self.kind {
            K::LinuxCnc => "write the FANUC two-block G76 (P m r a Q R / X Z R P Q F) or the one-block form of the control (--control)".into(),
            K::NoEndPoint => "the second G76 block (or a one-block G76) needs the thread end point X(U) Z(W)".into(),
            K::Missing { .. } => format!("give {l}"),
            K::DecimalPoint { mm_per_unit } => format!(
                "write {l} as a whole number of increments, e.g. {l}{} for 1 mm",
                (1.0 / mm_per_unit).round()
            ),
            K::PDigits { .. } => "write P as m m r r a a, e.g. P021060: 2 finishing passes, chamfer 1.0 lead, 60° tool (the old 0T layout P01-0260 is not accepted)".into(),
            K::NoFinishingPass => "give at least one finishing pass: P01rraa".into(),
            K::ToolAngle { one_block: false, .. } => "the last two digits of P are the tool angle: 00, 29, 30, 55, 60 or 80".into(),
            K::ToolAngle { one_block: true, .. } => "write A as the included tool angle without a decimal point, e.g. A60".into(),
            K::InfeedType { .. } => "P1 one edge constant amount, P2 alternating constant amount, P3 one edge constant depth, P4 alternating constant depth; a two-block G76 height P with K/D in the same block mixes the two forms".into(),
            K::StartAngle { .. } => "write Q in 0.001° without a decimal point, e.g. Q180000 for 180°".into(),
            K::Height { .. } => format!("give the thread height (crest to root, radius) in {l}"),
            K::FirstDepth { .. } => format!("give the first depth of cut (radius) in {l}"),
            K::LeadTwice => "give the lead once, in F or in E".into(),
            K::Lead { .. } => "give the lead in F".into(),
            K::MinDepth { .. } => format!("{l} (minimum depth of cut) is unsigned"),
            K::Allowance { d, .. } if d >= 1.0 && d.fract() == 0.0 => format!(
                "the finishing allowance must be at least 0 and smaller than the thread height; latsim reads R{d} as {d} mm, as every number without a decimal point, where a FANUC reading such numbers in its least increment takes {} mm: write R{}",
                d / 1000.0,
                d / 1000.0
            ),
            K::Allowance { .. } => "the finishing allowance must be at least 0 and smaller than the thread height".into(),
            K::ChamferAngle { .. } => "set the chamfer angle (parameter 5131 / Haas setting 96) between 0° and 90°, 45° usually".into(),
            K::NoZTravel => "give the thread end Z away from the start point's Z".into(),
            K::ChamferTooLong { .. } => "reduce the chamfer (r digits of P, Haas setting 95 or M24) or start the thread further away".into(),
            K::NoRadialTravel => "start the cycle outside the thread (OD) or inside the bore (ID)".into(),
            K::Taper { .. } => "when the taper and U have different signs, |taper| must not exceed |U/2|; check the sign of the taper".into(),
            K::TooManyPasses { .. } => "give a larger first depth Δd or a minimum depth Δdmin".into(),
        }
    }

    /// The diagnostic, at the faulty word or else at `fallback` (the G76 word).
    pub(crate) fn diagnostic(&self, fallback: Span) -> Diagnostic {
        Diagnostic::new(
            self.span(fallback),
            self.code(),
            self.message(),
            self.help(),
        )
    }
}

impl std::fmt::Display for G76Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "[{}] {}", self.code(), self.message())
    }
}
