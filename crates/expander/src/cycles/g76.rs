//! G76 — multiple threading cycle (spec/dialects.md §4, §3.5; spec/cycles.md "G92 / G32 / G76").
//!
//! A pure planner: words in, pass depths and moves out. It knows nothing of the interpreter;
//! the caller resolves the end point (X/U, Z/W with the work shift and G20), the F in force,
//! the profile's defaults and settings, and maps a [`G76Error`] to a diagnostic at its word.
//!
//! ```text
//! FANUC / GSK two-block:  G76 P(m)(r)(a) Q(Δdmin) R(d) ;
//!                         G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L) ;
//! Haas one-block:         G76 X(U) Z(W) K D [I] [A] [P1-4] [Q start angle] F(E) ;
//! FANUC FS15 one-block:   G76 X(U) Z(W) I K D A F P Q ;
//! ```
//!
//! Depth of pass n (§4.2), radius from the crest: hₙ* = Δd·√n ("constant amount", P1/P2 and
//! the two-block form) or n·Δd ("constant depth", P3/P4); an increment below Δdmin is raised
//! to Δdmin; the first hₙ* ≥ k − d is cut at k − d and ends the rough passes (that one may be
//! thinner than Δdmin); then m passes at k (the first removes d, the rest are spring passes).
//!
//! One pass at depth h, t = k − h (§4.3), for a start point A and end point E:
//! 1. rapid to (Za + s, rE + i + σt), σ = +1 OD (rA > rE), −1 ID;
//! 2. thread along the taper to Z = ZE + s (+ γ toward A when a chamfer is programmed);
//! 3. chamfer pull-out (still threading) to (ZE + s, rE + σt + σγ·tanθ), if γ = r·L/10 > 0;
//! 4. rapid out in X to rA; 5. rapid back in Z to Za.
//!
//! s is the one-flank infeed shift t·tan(a/2) toward A (the final passes have s = 0);
//! alternating infeed (P2/P4) flips its side pass by pass (**Interpretation**, §4.3).

use super::Move;
use crate::{Diagnostic, Motion, Pt, Span};
use gcode::Word;

/// Most passes one G76 may cut: a microscopic Δd is an error, not a hang.
pub(crate) const MAX_PASSES: usize = 10_000;
/// Tool angles the FANUC two-block P(a) digits accept (§4.4).
pub(crate) const TOOL_ANGLES: [u32; 6] = [0, 29, 30, 55, 60, 80];
/// Geometric tolerance, mm.
const EPS: f64 = 1e-9;

// ---------------------------------------------------------------------------------------------
// Parameters
// ---------------------------------------------------------------------------------------------

/// How the depth of each rough pass grows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum DepthLaw {
    /// Constant cutting amount: hₙ = Δd·√n (FANUC two-block, P1/P2).
    ConstantAmount,
    /// Constant depth of cut: hₙ = n·Δd (P3/P4).
    ConstantDepth,
}

/// Which flank leads the infeed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Edges {
    /// One flank: every pass start lies on the line at a/2 through the final root point.
    One,
    /// Alternating flanks: the shift flips side pass by pass (+ then −).
    Alternating,
}

/// Where a value came from: the word's letter, and its place when a word gave it (`None`:
/// a retained value without a word, a profile default or a machine setting; the caller
/// points at the G76 word then).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct At {
    /// The address letter the value belongs to.
    pub(crate) letter: char,
    /// The word's span, when a word gave the value.
    pub(crate) span: Option<Span>,
}

impl At {
    const fn letter(letter: char) -> Self {
        Self { letter, span: None }
    }
    fn word(letter: char, w: Option<&Word>) -> Self {
        Self {
            letter,
            span: w.map(|w| w.span),
        }
    }
}

/// The words each value of [`G76Params`] came from, for alarms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Sources {
    /// m (finishing passes).
    pub(crate) m: At,
    /// The chamfer length (r digits, or the Z word when a setting gives it).
    pub(crate) chamfer: At,
    /// The tool angle a / A.
    pub(crate) a: At,
    /// Δdmin.
    pub(crate) dmin: At,
    /// The finishing allowance d.
    pub(crate) d: At,
    /// X or U of the end point.
    pub(crate) x: At,
    /// Z or W of the end point.
    pub(crate) z: At,
    /// Taper i (R of the second block, I of the one-block form).
    pub(crate) i: At,
    /// Thread height k (P of the second block, K).
    pub(crate) k: At,
    /// First depth Δd (Q of the second block, D).
    pub(crate) dd: At,
    /// Lead (F, or Haas E).
    pub(crate) lead: At,
}

impl Sources {
    /// Letters of the FANUC two-block form, no spans.
    #[cfg_attr(not(test), allow(dead_code))] // the planner's tests build two-block sources
    pub(crate) const fn two_block() -> Self {
        Self {
            m: At::letter('P'),
            chamfer: At::letter('P'),
            a: At::letter('P'),
            dmin: At::letter('Q'),
            d: At::letter('R'),
            x: At::letter('X'),
            z: At::letter('Z'),
            i: At::letter('R'),
            k: At::letter('P'),
            dd: At::letter('Q'),
            lead: At::letter('F'),
        }
    }
    /// Letters of the one-block form, no spans. The settings (m, d, Δdmin, chamfer) have no
    /// word: the word they conflict with is named instead (K for d, D for Δdmin, Z for γ).
    pub(crate) const fn one_block() -> Self {
        Self {
            m: At::letter('P'),
            chamfer: At::letter('Z'),
            a: At::letter('A'),
            dmin: At::letter('D'),
            d: At::letter('K'),
            x: At::letter('X'),
            z: At::letter('Z'),
            i: At::letter('I'),
            k: At::letter('K'),
            dd: At::letter('D'),
            lead: At::letter('F'),
        }
    }
}

/// Everything one G76 needs, whichever form gave it. Lengths in mm, radius values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct G76Params {
    /// m: passes at full depth k (the first removes d, the others are spring passes).
    pub(crate) m: u32,
    /// Pull-out chamfer length in leads: r/10 (two-block), Haas setting 95 (0 under M24).
    pub(crate) chamfer_leads: f64,
    /// Chamfer angle from the Z axis, degrees (FANUC No. 5131, Haas setting 96; 45).
    pub(crate) chamfer_angle: f64,
    /// Included tool angle a, degrees: the infeed follows a/2.
    pub(crate) a: f64,
    /// Δdmin: minimum depth increment of a rough pass, radius.
    pub(crate) dmin: f64,
    /// d: finishing allowance, radius.
    pub(crate) d: f64,
    /// End point of the last pass (root at the thread end), G54 frame.
    pub(crate) end: Pt,
    /// i: taper, radius at the thread start minus radius at the end.
    pub(crate) i: f64,
    /// k: thread height, crest to root, radius.
    pub(crate) k: f64,
    /// Δd: depth of the first pass, radius.
    pub(crate) dd: f64,
    /// L: lead, mm per revolution.
    pub(crate) lead: f64,
    /// Depth law (P1–P4 of the one-block forms; constant amount otherwise).
    pub(crate) law: DepthLaw,
    /// One flank or alternating (P1–P4; one flank otherwise).
    pub(crate) edges: Edges,
    /// Thread start angle, degrees (Haas/FS15 Q; 0 in the two-block form). The caller
    /// shifts the stamped tool by L·q/360 along Z (§4.7); the moves do not carry it.
    pub(crate) start_angle: f64,
    /// Where each value came from.
    pub(crate) at: Sources,
}

/// The retained values of the two-block form's first block (modal; profile keys `g76_m`,
/// `g76_r`, `g76_a`, `g76_dmin`, `g76_d` until a first block sets them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FirstBlock {
    /// m: finishing passes, 1–99.
    pub(crate) m: u32,
    /// r: chamfer in tenths of the lead, 0–99.
    pub(crate) r: u32,
    /// a: tool angle, one of [`TOOL_ANGLES`].
    pub(crate) a: u32,
    /// Δdmin, mm (radius).
    pub(crate) dmin: f64,
    /// d, mm (radius).
    pub(crate) d: f64,
    /// Where P (m r a) was last written.
    pub(crate) p_at: Option<Span>,
    /// Where Q was last written.
    pub(crate) q_at: Option<Span>,
    /// Where R was last written.
    pub(crate) r_at: Option<Span>,
}

impl FirstBlock {
    /// Values from the profile (no word wrote them).
    pub(crate) const fn profile(m: u32, r: u32, a: u32, dmin: f64, d: f64) -> Self {
        Self {
            m,
            r,
            a,
            dmin,
            d,
            p_at: None,
            q_at: None,
            r_at: None,
        }
    }
}

impl Default for FirstBlock {
    /// The spec's profile defaults (§4.1, **Interpretation**): m 1, r 10, a 60, Δdmin 0.1, d 0.
    fn default() -> Self {
        Self::profile(1, 10, 60, 0.1, 0.0)
    }
}

/// Which one-block dialect is read (messages and unit of K/D).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Flavor {
    /// Haas: `G76 X Z K D [I] [A] [P] [Q] F(E)`, K/D/I calculator-type mm (§3.5).
    Haas,
    /// FANUC 10/11/15 format: `G76 X Z I K D A F P Q` (§4.5).
    Fs15,
}

/// What a one-block G76 takes from the machine rather than from words.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct OneBlockConfig {
    /// Dialect.
    pub(crate) flavor: Flavor,
    /// Passes at full depth: Haas 1; FS15 `g76_m` (No. 5142).
    pub(crate) m: u32,
    /// Finishing allowance d: Haas setting 86; FS15 `g76_d` (No. 5141).
    pub(crate) d: f64,
    /// Minimum cut Δdmin: Haas setting 99; FS15 `g76_dmin` (No. 5140).
    pub(crate) dmin: f64,
    /// Chamfer in leads: Haas setting 95 under M23, 0 under M24; FS15 `g76_r` / 10.
    pub(crate) chamfer_leads: f64,
    /// Chamfer angle from Z, degrees: Haas setting 96; FS15 No. 5131 (45).
    pub(crate) chamfer_angle: f64,
    /// Tool angle when A is absent: Haas 0 (radial, **Interpretation**); FS15 `g76_a`.
    pub(crate) a: f64,
    /// mm per unit of K and D when they are least-increment words; `None`: calculator-type
    /// mm (Haas, §3.1; FS15 by the same reading, **Interpretation**: §4.5 gives no unit).
    pub(crate) kd_mm_per_unit: Option<f64>,
}

impl OneBlockConfig {
    /// Haas: settings 86 (finish allowance), 99 (minimum cut), 95/96 (chamfer, only when
    /// `m23` — M23 in force), one pass at full depth.
    pub(crate) const fn haas(
        setting86: f64,
        setting99: f64,
        m23: bool,
        setting95: f64,
        setting96: f64,
    ) -> Self {
        Self {
            flavor: Flavor::Haas,
            m: 1,
            d: setting86,
            dmin: setting99,
            chamfer_leads: if m23 { setting95 } else { 0.0 },
            chamfer_angle: setting96,
            a: 0.0,
            kd_mm_per_unit: None,
        }
    }
    /// FANUC FS15 format: the parameters the two-block first block would set.
    pub(crate) fn fs15(first: &FirstBlock, chamfer_angle: f64) -> Self {
        Self {
            flavor: Flavor::Fs15,
            m: first.m,
            d: first.d,
            dmin: first.dmin,
            chamfer_leads: f64::from(first.r) / 10.0,
            chamfer_angle,
            a: f64::from(first.a),
            kd_mm_per_unit: None,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------------------------

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
    /// The radial travel |U/2| from A to the end point is not larger than the pull-out.
    RadialTravel {
        /// |U/2|, mm.
        half_u: f64,
        /// The pull-out's radial size γ·tanθ, mm.
        pull_out: f64,
    },
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
    fn new(kind: G76ErrorKind, at: At) -> Self {
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
            K::RadialTravel { .. } => "LS-G76-TRAVEL",
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
            K::RadialTravel { half_u, pull_out } => format!(
                "G76 radial travel |U/2| = {half_u:.3} mm is not larger than the pull-out {pull_out:.3} mm"
            ),
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
            K::Allowance { .. } => "the finishing allowance must be at least 0 and smaller than the thread height".into(),
            K::ChamferAngle { .. } => "set the chamfer angle (parameter 5131 / Haas setting 96) between 0° and 90°, 45° usually".into(),
            K::NoZTravel => "give the thread end Z away from the start point's Z".into(),
            K::ChamferTooLong { .. } => "reduce the chamfer (r digits of P, Haas setting 95 or M24) or start the thread further away".into(),
            K::RadialTravel { .. } => "start the cycle further outside the thread (OD) or inside the bore (ID), beyond the pull-out".into(),
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

// ---------------------------------------------------------------------------------------------
// Reading the words
// ---------------------------------------------------------------------------------------------

/// Which layout a G76 block is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Form {
    /// `G76 P(m r a) Q(Δdmin) R(d)`: only stores values.
    First,
    /// `G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)`.
    Second,
    /// `G76 X(U) Z(W) K D …` (Haas, FS15).
    OneBlock,
}

/// The layout of a G76 block. `get` looks a word up by letter without consuming it
/// (`Block::get`). J or H: `LinuxCNC`; K or D: one-block; X/Z/U/W: second block; F without an
/// end point: a second block missing it; else a first block. Whether the dialect admits the
/// form (`fs15_format`, `haas`, `gsk980`) is the caller's check.
pub(crate) fn classify<'w>(get: impl Fn(char) -> Option<&'w Word>) -> Result<Form, G76Error> {
    if let Some(w) = get('J').or_else(|| get('H')) {
        return Err(G76Error::new(
            G76ErrorKind::LinuxCnc,
            At::word(w.letter, Some(w)),
        ));
    }
    let end = ['X', 'Z', 'U', 'W'].iter().any(|&l| get(l).is_some());
    let one = get('K').is_some() || get('D').is_some();
    match (end, one) {
        (true, true) => Ok(Form::OneBlock),
        (true, false) => Ok(Form::Second),
        (false, true) => Err(G76Error {
            kind: G76ErrorKind::NoEndPoint,
            at: None,
        }),
        (false, false) if get('F').is_some() => Err(G76Error {
            kind: G76ErrorKind::NoEndPoint,
            at: None,
        }),
        (false, false) => Ok(Form::First),
    }
}

/// A least-increment word (no decimal point when `mm_per_unit` < 1) in mm.
fn increments(letter: char, w: Option<&Word>, mm_per_unit: f64) -> Result<Option<f64>, G76Error> {
    let Some(w) = w else { return Ok(None) };
    if mm_per_unit < 1.0 && w.has_point {
        return Err(G76Error::new(
            G76ErrorKind::DecimalPoint { mm_per_unit },
            At::word(letter, Some(w)),
        ));
    }
    Ok(Some(w.value * mm_per_unit))
}

/// Read `G76 P(m)(r)(a) Q(Δdmin) R(d)`. Absent words keep `prev` (the retained values).
/// `pq_mm`: mm per P/Q unit (`Machine::pq_mm`, times 25.4 under G20 for inch increments);
/// `unit`: 1, or 25.4 under G20, for R.
pub(crate) fn read_first<'w>(
    mut get: impl FnMut(char) -> Option<&'w Word>,
    prev: &FirstBlock,
    pq_mm: f64,
    unit: f64,
) -> Result<FirstBlock, G76Error> {
    let mut f = *prev;
    if let Some(p) = get('P') {
        let at = At::word('P', Some(p));
        let v = p.value;
        if p.has_point || v.fract() != 0.0 || !(0.0..=999_999.0).contains(&v) {
            return Err(G76Error::new(G76ErrorKind::PDigits { value: v }, at));
        }
        let v = v as u32;
        let (m, r, a) = (v / 10_000, v / 100 % 100, v % 100);
        if m == 0 {
            return Err(G76Error::new(G76ErrorKind::NoFinishingPass, at));
        }
        if !TOOL_ANGLES.contains(&a) {
            return Err(G76Error::new(
                G76ErrorKind::ToolAngle {
                    a: f64::from(a),
                    one_block: false,
                },
                at,
            ));
        }
        (f.m, f.r, f.a, f.p_at) = (m, r, a, Some(p.span));
    }
    if let Some(q) = get('Q') {
        let dmin = increments('Q', Some(q), pq_mm)?.unwrap_or(0.0);
        if dmin < 0.0 {
            return Err(G76Error::new(
                G76ErrorKind::MinDepth { dmin },
                At::word('Q', Some(q)),
            ));
        }
        (f.dmin, f.q_at) = (dmin, Some(q.span));
    }
    if let Some(r) = get('R') {
        (f.d, f.r_at) = (r.value * unit, Some(r.span));
    }
    Ok(f)
}

/// The lead: F (or Haas E) of the block, else the F in force (mm/rev, already in mm).
fn lead<'w>(
    f: Option<&'w Word>,
    e: Option<&'w Word>,
    in_force: Option<f64>,
    unit: f64,
) -> Result<(f64, At), G76Error> {
    match (f, e) {
        (Some(_), Some(w)) => Err(G76Error::new(
            G76ErrorKind::LeadTwice,
            At::word('E', Some(w)),
        )),
        (Some(w), None) => Ok((w.value * unit, At::word('F', Some(w)))),
        (None, Some(w)) => Ok((w.value * unit, At::word('E', Some(w)))),
        (None, None) => match in_force {
            Some(l) => Ok((l, At::letter('F'))),
            None => Err(G76Error::new(
                G76ErrorKind::Missing { what: "the lead" },
                At::letter('F'),
            )),
        },
    }
}

/// The letters of the end point that were written.
fn end_at<'w>(get: &mut impl FnMut(char) -> Option<&'w Word>) -> (At, At) {
    let x = match get('X') {
        Some(w) => At::word('X', Some(w)),
        None => At::word('U', get('U')),
    };
    let z = match get('Z') {
        Some(w) => At::word('Z', Some(w)),
        None => At::word('W', get('W')),
    };
    (x, z)
}

/// Read `G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)` with the retained first block. `end`: the end
/// point resolved by the caller (G54 frame, radius); `f_in_force`: the modal F in mm when the
/// block has none; `chamfer_angle`: parameter No. 5131 (45°).
pub(crate) fn read_second<'w>(
    mut get: impl FnMut(char) -> Option<&'w Word>,
    first: &FirstBlock,
    end: Pt,
    f_in_force: Option<f64>,
    pq_mm: f64,
    unit: f64,
    chamfer_angle: f64,
) -> Result<G76Params, G76Error> {
    let (x, z) = end_at(&mut get);
    let r = get('R');
    let p = get('P');
    let q = get('Q');
    let k = increments('P', p, pq_mm)?.ok_or_else(|| {
        G76Error::new(
            G76ErrorKind::Missing {
                what: "the thread height k, radius, in least increments",
            },
            At::letter('P'),
        )
    })?;
    let dd = increments('Q', q, pq_mm)?.ok_or_else(|| {
        G76Error::new(
            G76ErrorKind::Missing {
                what: "the first depth Δd, radius, in least increments",
            },
            At::letter('Q'),
        )
    })?;
    let (lead, lead_at) = lead(get('F'), None, f_in_force, unit)?;
    let first_p = At {
        letter: 'P',
        span: first.p_at,
    };
    Ok(G76Params {
        m: first.m,
        chamfer_leads: f64::from(first.r) / 10.0,
        chamfer_angle,
        a: f64::from(first.a),
        dmin: first.dmin,
        d: first.d,
        end,
        i: r.map_or(0.0, |w| w.value * unit),
        k,
        dd,
        lead,
        law: DepthLaw::ConstantAmount,
        edges: Edges::One,
        start_angle: 0.0,
        at: Sources {
            m: first_p,
            chamfer: first_p,
            a: first_p,
            dmin: At {
                letter: 'Q',
                span: first.q_at,
            },
            d: At {
                letter: 'R',
                span: first.r_at,
            },
            x,
            z,
            i: At::word('R', r),
            k: At::word('P', p),
            dd: At::word('Q', q),
            lead: lead_at,
        },
    })
}

/// Read the one-block form `G76 X(U) Z(W) K D [I] [A] [P] [Q] F(E)` (Haas §3.5, FS15 §4.5).
/// `end`, `f_in_force`, `unit` as for [`read_second`]; the rest comes from `cfg`.
pub(crate) fn read_one_block<'w>(
    mut get: impl FnMut(char) -> Option<&'w Word>,
    end: Pt,
    f_in_force: Option<f64>,
    unit: f64,
    cfg: &OneBlockConfig,
) -> Result<G76Params, G76Error> {
    let (x, z) = end_at(&mut get);
    let length = |letter: char, w: Option<&Word>| -> Result<Option<f64>, G76Error> {
        match cfg.kd_mm_per_unit {
            Some(mm) => increments(letter, w, mm),
            None => Ok(w.map(|w| w.value * unit)),
        }
    };
    let kw = get('K');
    let dw = get('D');
    let k = length('K', kw)?.ok_or_else(|| {
        G76Error::new(
            G76ErrorKind::Missing {
                what: "the thread height, radius",
            },
            At::letter('K'),
        )
    })?;
    let dd = length('D', dw)?.ok_or_else(|| {
        G76Error::new(
            G76ErrorKind::Missing {
                what: "the first depth of cut, radius",
            },
            At::letter('D'),
        )
    })?;
    let iw = get('I');
    let i = iw.map_or(0.0, |w| w.value * unit);
    let aw = get('A');
    let a = match aw {
        None => cfg.a,
        Some(w) if w.value.fract() == 0.0 && (0.0..=120.0).contains(&w.value) => w.value,
        Some(w) => {
            return Err(G76Error::new(
                G76ErrorKind::ToolAngle {
                    a: w.value,
                    one_block: true,
                },
                At::word('A', Some(w)),
            ))
        }
    };
    let pw = get('P');
    let (law, edges) = match pw.map(|w| (w.value, w.has_point)) {
        None => (DepthLaw::ConstantAmount, Edges::One),
        Some((1.0, false)) => (DepthLaw::ConstantAmount, Edges::One),
        Some((2.0, false)) => (DepthLaw::ConstantAmount, Edges::Alternating),
        Some((3.0, false)) => (DepthLaw::ConstantDepth, Edges::One),
        Some((4.0, false)) => (DepthLaw::ConstantDepth, Edges::Alternating),
        Some((value, _)) => {
            return Err(G76Error::new(
                G76ErrorKind::InfeedType { value },
                At::word('P', pw),
            ))
        }
    };
    let qw = get('Q');
    let start_angle = match qw {
        None => 0.0,
        Some(w)
            if !w.has_point && w.value.fract() == 0.0 && (0.0..=360_000.0).contains(&w.value) =>
        {
            w.value / 1000.0
        }
        Some(w) => {
            return Err(G76Error::new(
                G76ErrorKind::StartAngle { value: w.value },
                At::word('Q', Some(w)),
            ))
        }
    };
    let e = if cfg.flavor == Flavor::Haas {
        get('E')
    } else {
        None
    };
    let (lead, lead_at) = lead(get('F'), e, f_in_force, unit)?;
    let at = Sources {
        x,
        z,
        i: At::word('I', iw),
        k: At::word('K', kw),
        dd: At::word('D', dw),
        a: At::word('A', aw),
        d: At::word('K', kw),
        dmin: At::word('D', dw),
        chamfer: z,
        lead: lead_at,
        ..Sources::one_block()
    };
    Ok(G76Params {
        m: cfg.m,
        chamfer_leads: cfg.chamfer_leads,
        chamfer_angle: cfg.chamfer_angle,
        a,
        dmin: cfg.dmin,
        d: cfg.d,
        end,
        i,
        k,
        dd,
        lead,
        law,
        edges,
        start_angle,
        at,
    })
}

// ---------------------------------------------------------------------------------------------
// Planning
// ---------------------------------------------------------------------------------------------

/// The depth (radius, from the crest) of every pass, rough passes then the m passes at k
/// (§4.2). Checks the values that do not depend on the start point.
pub(crate) fn passes(p: &G76Params) -> Result<Vec<f64>, G76Error> {
    use G76ErrorKind as K;
    let at = &p.at;
    if !p.k.is_finite() || p.k <= 0.0 {
        return Err(G76Error::new(K::Height { k: p.k }, at.k));
    }
    if !p.dd.is_finite() || p.dd <= 0.0 {
        return Err(G76Error::new(K::FirstDepth { dd: p.dd }, at.dd));
    }
    if !p.lead.is_finite() || p.lead <= 0.0 {
        return Err(G76Error::new(K::Lead { lead: p.lead }, at.lead));
    }
    if !p.dmin.is_finite() || p.dmin < 0.0 {
        return Err(G76Error::new(K::MinDepth { dmin: p.dmin }, at.dmin));
    }
    if !p.d.is_finite() || p.d < 0.0 || p.d >= p.k {
        return Err(G76Error::new(K::Allowance { d: p.d, k: p.k }, at.d));
    }
    if p.m == 0 {
        return Err(G76Error::new(K::NoFinishingPass, at.m));
    }
    let m = p.m as usize;
    let target = p.k - p.d;
    let mut out = Vec::new();
    let mut prev = 0.0;
    for n in 1.. {
        if out.len() + m >= MAX_PASSES {
            return Err(G76Error::new(
                K::TooManyPasses {
                    estimate: estimate(p, target),
                },
                at.dd,
            ));
        }
        let nf = f64::from(n);
        let mut h = match p.law {
            DepthLaw::ConstantAmount => p.dd * nf.sqrt(),
            DepthLaw::ConstantDepth => p.dd * nf,
        };
        if h - prev < p.dmin {
            h = prev + p.dmin;
        }
        if h >= target - EPS {
            out.push(target);
            break;
        }
        out.push(h);
        prev = h;
    }
    out.extend(std::iter::repeat_n(p.k, m));
    Ok(out)
}

/// About how many passes the words ask for (for the message only).
fn estimate(p: &G76Params, target: f64) -> f64 {
    let by_dd = match p.law {
        DepthLaw::ConstantAmount => (target / p.dd).powi(2),
        DepthLaw::ConstantDepth => target / p.dd,
    };
    let by_min = if p.dmin > 0.0 {
        target / p.dmin
    } else {
        f64::INFINITY
    };
    by_dd.min(by_min).ceil() + f64::from(p.m)
}

/// Run a G76 block in the interpreter. FANUC/GSK two-block form: the first block only
/// stores m r a, Δdmin and d (retained as the control keeps them); the second cuts the
/// passes from the cycle's start point. One-block form (Haas §3.5; FANUC FS15 §4.5 with
/// `fs15_format = true`): the settings come from the profile (Haas settings 86, 99, 95/96
/// under M23) or, for FS15, from the retained first-block values. Each form under a
/// control that does not read it is an alarm naming the control.
pub(super) fn run(c: &mut super::Cycle) -> Result<super::Output, Diagnostic> {
    let g_span = c.g.map_or(c.words.span(), |w| w.span);
    let block = c.words.block;
    let pq_mm = c.machine.pq_mm();
    let unit = c.unit;
    let first = c.retained.g76.unwrap_or_default();
    let haas = c.machine.control == crate::Control::Haas;
    let form = classify(|l| block.get(l)).map_err(|e| e.diagnostic(g_span))?;
    if haas && form != Form::OneBlock {
        return Err(c.alarm(
            "LS-ONE-BLOCK-FORM",
            "the two-block G76 (P m r a, Q, R / X Z R P Q F) is the FANUC form; the Haas lathe reads G76 in one block (its Q is the start angle)",
            "write G76 X(U) Z(W) K(height) D(first depth) [I] [A] [P1-4] F in one block",
        ));
    }
    let end = |c: &mut super::Cycle| -> Result<Pt, Diagnostic> {
        Ok(Pt::new(
            c.z_target()?.unwrap_or(c.start.z),
            c.x_target()?.unwrap_or(c.start.r),
        ))
    };
    let params = match form {
        Form::First => {
            let f = read_first(|l| c.words.take(l), &first, pq_mm, unit)
                .map_err(|e| e.diagnostic(g_span))?;
            c.retained.g76 = Some(f);
            return Ok(super::Output::default());
        }
        Form::Second => {
            let end = end(c)?;
            // the chamfer angle of parameter No. 5131: 45°
            read_second(|l| c.words.take(l), &first, end, None, pq_mm, unit, 45.0)
                .map_err(|e| e.diagnostic(g_span))?
        }
        Form::OneBlock if !c.machine.one_block_cycles() => {
            let w = block.get('K').or_else(|| block.get('D'));
            return Err(Diagnostic::new(
                w.map_or(g_span, |w| w.span),
                "LS-ONE-BLOCK-FORM",
                format!(
                    "G76 with K and D in one block is the Haas/FS15 form: run with --control haas (this control is {})",
                    c.machine.control.key()
                ),
                "write the two-block form G76 P(m)(r)(a) Q R / G76 X Z R P Q F, or run with --control haas (FANUC with the FS15 format: fs15_format = true)",
            ));
        }
        Form::OneBlock => {
            let h = c.machine.haas;
            let cfg = if haas {
                OneBlockConfig::haas(
                    h.setting86,
                    h.setting99,
                    c.thread_chamfer,
                    h.setting95,
                    h.setting96,
                )
            } else {
                OneBlockConfig::fs15(&first, 45.0)
            };
            let end = end(c)?;
            read_one_block(|l| c.words.take(l), end, None, unit, &cfg)
                .map_err(|e| e.diagnostic(g_span))?
        }
    };
    let moves = moves(c.start, &params).map_err(|e| e.diagnostic(g_span))?;
    let mut out = super::Output {
        moves,
        lead: Some(params.lead),
        thread_phase: params.start_angle / 360.0,
        ..super::Output::default()
    };
    if first_depth_exceeds_height(&params) {
        out.warnings.push(c.alarm(
            "LS-G76-DEPTH",
            format!(
                "the first depth {:.4} mm is larger than the thread height {:.4} mm: one rough pass at the height less d",
                params.dd, params.k
            ),
            "check the first depth and the height (swapped?)",
        ));
    }
    Ok(out)
}

/// A thread move to `to`.
fn thread(to: Pt) -> Move {
    let mut m = Move::feed(to);
    m.motion = Motion::Thread;
    m
}

/// The moves of the whole cycle from the start point `start` (G54 frame), §4.3: five (four
/// without a chamfer) per pass, in the order of [`passes`].
pub(crate) fn moves(start: Pt, p: &G76Params) -> Result<Vec<Move>, G76Error> {
    use G76ErrorKind as K;
    let depths = passes(p)?;
    let at = &p.at;
    let theta = p.chamfer_angle;
    if !theta.is_finite() || theta <= 0.0 || theta >= 90.0 {
        return Err(G76Error::new(K::ChamferAngle { angle: theta }, at.chamfer));
    }
    // Z travel and the side of A (the shift and the chamfer point toward A).
    let dz = start.z - p.end.z;
    let travel = dz.abs();
    if travel < EPS {
        return Err(G76Error::new(K::NoZTravel, at.z));
    }
    let zeta = dz.signum();
    let gamma = p.chamfer_leads * p.lead;
    if gamma > 0.0 && gamma >= travel - EPS {
        return Err(G76Error::new(
            K::ChamferTooLong { gamma, travel },
            at.chamfer,
        ));
    }
    // Radial travel: larger than the pull-out's radial size (§4.4). With no chamfer it must
    // still be non-zero, or OD and ID cannot be told apart.
    let half_u = p.end.r - start.r;
    let pull_out = gamma * theta.to_radians().tan();
    if half_u.abs() <= pull_out + EPS {
        return Err(G76Error::new(
            K::RadialTravel {
                half_u: half_u.abs(),
                pull_out,
            },
            at.x,
        ));
    }
    if p.i != 0.0 && p.i.signum() != half_u.signum() && p.i.abs() > half_u.abs() + EPS {
        return Err(G76Error::new(K::Taper { i: p.i, half_u }, at.i));
    }
    // σ: +1 OD (the start point is outside the end point), −1 ID.
    let sigma = if start.r > p.end.r { 1.0 } else { -1.0 };
    let tan_half = (p.a / 2.0).to_radians().tan();
    let mut out = Vec::with_capacity(depths.len() * 5);
    for (n, h) in depths.iter().enumerate() {
        let t = p.k - h;
        let side = match p.edges {
            Edges::One => 1.0,
            Edges::Alternating if n % 2 == 0 => 1.0,
            Edges::Alternating => -1.0,
        };
        let s = zeta * side * t * tan_half;
        let r_end = p.end.r + sigma * t;
        let z_end = p.end.z + s;
        out.push(Move::rapid(Pt::new(start.z + s, r_end + p.i))); // ① to the pass start
        if gamma > 0.0 {
            let r_c = r_end + p.i * gamma / travel; // on the taper, γ before the end
            out.push(thread(Pt::new(z_end + zeta * gamma, r_c))); // ② thread
            out.push(thread(Pt::new(z_end, r_end + sigma * pull_out))); // ③ chamfer
        } else {
            out.push(thread(Pt::new(z_end, r_end))); // ② thread to the end
        }
        out.push(Move::rapid(Pt::new(z_end, start.r))); // ④ out in X
        out.push(Move::rapid(start)); // ⑤ back in Z
    }
    Ok(out)
}

/// Advice that does not stop the program: a first depth larger than the whole thread height
/// (P and Q of the second block swapped?). The pass law caps it at k − d (§4.2).
pub(crate) fn first_depth_exceeds_height(p: &G76Params) -> bool {
    p.dd > p.k
}

#[cfg(test)]
mod tests {
    use super::*;
    use gcode::Block;

    const IS_B: f64 = 0.001;
    const TAN30: f64 = 0.577_350_269_189_625_8;

    /// The blocks of a program (main program, in order).
    fn blocks(src: &str) -> Vec<Block> {
        gcode::parse(src).unwrap().main().unwrap().blocks.all()
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    fn assert_depths(got: &[f64], want: &[f64], tol: f64) {
        assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
        for (n, (g, w)) in got.iter().zip(want).enumerate() {
            assert!(close(*g, *w, tol), "pass {}: {g} vs {w}", n + 1);
        }
    }

    fn assert_moves_eq(a: &[Move], b: &[Move]) {
        assert_eq!(a.len(), b.len());
        for (n, (x, y)) in a.iter().zip(b).enumerate() {
            assert_eq!(x.motion, y.motion, "move {n}");
            assert!(
                close(x.to.z, y.to.z, 1e-12) && close(x.to.r, y.to.r, 1e-12),
                "move {n}: {:?} vs {:?}",
                x.to,
                y.to
            );
        }
    }

    /// Read a FANUC two-block G76 (first block at `b[i]`, second at `b[i + 1]`).
    fn fanuc(b: &[Block], end: Pt) -> Result<G76Params, G76Error> {
        assert_eq!(classify(|l| b[0].get(l)), Ok(Form::First));
        assert_eq!(classify(|l| b[1].get(l)), Ok(Form::Second));
        let first = read_first(|l| b[0].get(l), &FirstBlock::default(), IS_B, 1.0)?;
        read_second(|l| b[1].get(l), &first, end, None, IS_B, 1.0, 45.0)
    }

    /// A params value for the checks of `passes`.
    fn sample() -> G76Params {
        G76Params {
            m: 1,
            chamfer_leads: 0.0,
            chamfer_angle: 45.0,
            a: 60.0,
            dmin: 0.05,
            d: 0.02,
            end: Pt::new(-20.0, 17.835 / 2.0),
            i: 0.0,
            k: 1.082,
            dd: 0.35,
            lead: 1.5,
            law: DepthLaw::ConstantAmount,
            edges: Edges::One,
            start_angle: 0.0,
            at: Sources::two_block(),
        }
    }

    // --- The issue's M20×1.5 OD ------------------------------------------------------------

    const M20_FANUC: &str = "G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q400 F1.5\n";

    /// Hand computation, IS-B: P021060 → m = 2, r = 10 (γ = 1.0 L = 1.5 mm), a = 60;
    /// Q50 → Δdmin = 0.050; R0.05 → d = 0.050; P975 → k = 0.975; Q400 → Δd = 0.400.
    /// k − d = 0.925.
    ///   n=1  0.4·√1 = 0.400000                    (increment 0.400000)
    ///   n=2  0.4·√2 = 0.565685                    (0.165685 ≥ 0.05)
    ///   n=3  0.4·√3 = 0.692820                    (0.127135)
    ///   n=4  0.4·√4 = 0.800000                    (0.107180)
    ///   n=5  0.4·√5 = 0.894427                    (0.094427)
    ///   n=6  0.4·√6 = 0.979796 ≥ 0.925 → 0.925    (0.030573, last rough, may be < Δdmin)
    ///   then m = 2 passes at k = 0.975 (the first removes d = 0.05, the second is a spring
    ///   pass): 8 passes.
    #[test]
    fn m20_pass_depths() {
        let b = blocks(M20_FANUC);
        let p = fanuc(&b, Pt::new(-25.0, 9.025)).unwrap();
        assert_eq!((p.m, p.chamfer_leads, p.a), (2, 1.0, 60.0));
        assert!(close(p.dmin, 0.05, 1e-12) && close(p.d, 0.05, 1e-12));
        assert!(close(p.k, 0.975, 1e-12) && close(p.dd, 0.4, 1e-12));
        let want = [
            0.400_000, 0.565_685, 0.692_820, 0.800_000, 0.894_427, 0.925, 0.975, 0.975,
        ];
        assert_depths(&passes(&p).unwrap(), &want, 5e-7);
    }

    /// Each pass from A = (Z5, X22): t = k − h; start shift s = t·tan 30° toward +Z; pass X
    /// = 18.05 + 2t. Chamfer γ = 1.5 at 45°: the thread stops at Z −25 + s + 1.5 and pulls
    /// out to (Z −25 + s, r + 1.5).
    ///   h        t         s = t·tan30   X = 18.05 + 2t
    ///   0.400    0.575000  0.331977      19.200000
    ///   0.565685 0.409315  0.236318      18.868629
    ///   0.692820 0.282180  0.162917      18.614359
    ///   0.800    0.175000  0.101036      18.400000
    ///   0.894427 0.080573  0.046519      18.211146
    ///   0.925    0.050000  0.028868      18.150000
    ///   0.975    0         0             18.050000   (twice)
    #[test]
    fn m20_moves_follow_the_30_degree_flank() {
        let b = blocks(M20_FANUC);
        let start = Pt::new(5.0, 11.0);
        let p = fanuc(&b, Pt::new(-25.0, 9.025)).unwrap();
        let mv = moves(start, &p).unwrap();
        assert_eq!(mv.len(), 8 * 5);
        let table = [
            (0.331_977, 19.200_000),
            (0.236_318, 18.868_629),
            (0.162_917, 18.614_359),
            (0.101_036, 18.400_000),
            (0.046_519, 18.211_146),
            (0.028_868, 18.150_000),
            (0.0, 18.05),
            (0.0, 18.05),
        ];
        for (n, (pass, (s, x))) in mv.chunks(5).zip(table).enumerate() {
            let r = x / 2.0;
            let want = [
                (Motion::Rapid, 5.0 + s, r),
                (Motion::Thread, -25.0 + s + 1.5, r),
                (Motion::Thread, -25.0 + s, r + 1.5),
                (Motion::Rapid, -25.0 + s, 11.0),
                (Motion::Rapid, 5.0, 11.0),
            ];
            for (m, (motion, z, r)) in pass.iter().zip(want) {
                assert_eq!(m.motion, motion, "pass {}", n + 1);
                assert!(
                    close(m.to.z, z, 2e-6) && close(m.to.r, r, 2e-6),
                    "pass {}: {:?} vs ({z}, {r})",
                    n + 1,
                    m.to
                );
            }
            // The pass start lies on the 30° flank line through the final root point.
            let (root_z, root_r) = (5.0, 9.025);
            let (dz, dr) = (pass[0].to.z - root_z, pass[0].to.r - root_r);
            assert!(close(dz, dr * TAN30, 1e-12), "pass {}", n + 1);
        }
    }

    /// The same thread in Haas one-block form: K0.975 D0.4 A60 P1, setting 86 = 0.05, setting
    /// 99 = 0.05, M23 with setting 95 = 1.0 lead, 96 = 45°. Haas cuts one pass at full depth
    /// (m = 1), so its moves are the FANUC moves without the last (spring) pass; the FS15
    /// one-block form with `g76_m = 2` gives exactly the FANUC moves.
    #[test]
    fn m20_haas_and_fs15_one_block_give_the_same_moves() {
        let b = blocks(M20_FANUC);
        let start = Pt::new(5.0, 11.0);
        let end = Pt::new(-25.0, 9.025);
        let two = moves(start, &fanuc(&b, end).unwrap()).unwrap();

        let h = blocks("G76 X18.05 Z-25. K0.975 D0.4 A60 P1 F1.5\n");
        assert_eq!(classify(|l| h[0].get(l)), Ok(Form::OneBlock));
        let cfg = OneBlockConfig::haas(0.05, 0.05, true, 1.0, 45.0);
        let p = read_one_block(|l| h[0].get(l), end, None, 1.0, &cfg).unwrap();
        assert_depths(
            &passes(&p).unwrap(),
            &passes(&fanuc(&b, end).unwrap()).unwrap()[..7],
            1e-12,
        );
        assert_moves_eq(&moves(start, &p).unwrap(), &two[..35]);

        let f = blocks("G76 X18.05 Z-25. I0 K0.975 D0.4 A60 F1.5 P1 Q0\n");
        let first = FirstBlock::profile(2, 10, 60, 0.05, 0.05);
        let cfg = OneBlockConfig::fs15(&first, 45.0);
        let p = read_one_block(|l| f[0].get(l), end, None, 1.0, &cfg).unwrap();
        assert_moves_eq(&moves(start, &p).unwrap(), &two);
    }

    // --- dialects.md §7 T5 ------------------------------------------------------------------

    /// T5: 11 passes, rough depths 0.35·√n: 0.350, 0.495, 0.606, 0.700, 0.783, 0.857, 0.926,
    /// 0.990, 1.050, then 0.35·√10 = 1.107 ≥ k − d = 1.062 → 1.062; one pass at 1.082.
    /// X = 17.835 + 2(1.082 − h); shift (1.082 − h)·tan 30°: 0.423 on pass 1 … 0 on the last.
    /// No chamfer (r = 00): rapid (22, 5) → (X, 5 + s), thread to Z −20 + s, rapid X22, Z5.
    #[test]
    fn t5_fanuc_and_haas() {
        let b = blocks("G76 P010060 Q50 R0.02\nG76 X17.835 Z-20. P1082 Q350 F1.5\n");
        let start = Pt::new(5.0, 11.0);
        let end = Pt::new(-20.0, 17.835 / 2.0);
        let p = fanuc(&b, end).unwrap();
        let d = passes(&p).unwrap();
        let want_h = [
            0.350, 0.495, 0.606, 0.700, 0.783, 0.857, 0.926, 0.990, 1.050, 1.062, 1.082,
        ];
        assert_depths(&d, &want_h, 5e-4);
        let want_x = [
            19.299, 19.009, 18.787, 18.599, 18.434, 18.284, 18.147, 18.019, 17.899, 17.875, 17.835,
        ];
        let mv = moves(start, &p).unwrap();
        assert_eq!(mv.len(), 11 * 4);
        for (n, (pass, x)) in mv.chunks(4).zip(want_x).enumerate() {
            let s = (1.082 - d[n]) * TAN30;
            assert_eq!(pass[0].motion, Motion::Rapid);
            assert!(
                close(pass[0].to.r * 2.0, x, 1e-3),
                "pass {}: {:?}",
                n + 1,
                pass[0].to
            );
            assert!(close(pass[0].to.z, 5.0 + s, 1e-12));
            assert_eq!(pass[1].motion, Motion::Thread);
            assert!(
                close(pass[1].to.z, -20.0 + s, 1e-12) && close(pass[1].to.r, pass[0].to.r, 1e-12)
            );
            assert_eq!(pass[2].motion, Motion::Rapid);
            assert_eq!(pass[2].to, Pt::new(-20.0 + s, 11.0));
            assert_eq!(pass[3], Move::rapid(start));
        }
        assert!(close(mv[0].to.z - 5.0, 0.423, 5e-4));
        assert_eq!(mv[40].to.z, 5.0);

        let h = blocks("G76 X17.835 Z-20. K1.082 D0.35 A60 P1 F1.5\n");
        let cfg = OneBlockConfig::haas(0.02, 0.05, false, 1.0, 45.0);
        let ph = read_one_block(|l| h[0].get(l), end, None, 1.0, &cfg).unwrap();
        assert_moves_eq(&moves(start, &ph).unwrap(), &mv);
    }

    // --- Other behaviour --------------------------------------------------------------------

    /// Δdmin raises small increments: Δd = 0.1, Δdmin = 0.08, k − d = 0.5:
    /// 0.1, then 0.1·√2 = 0.1414 (+0.0414 < 0.08) → 0.18, 0.1·√3 = 0.173 → 0.26, → 0.34,
    /// → 0.42, → 0.50 ≥ 0.5 → 0.5 (last rough), then 0.5 at k.
    #[test]
    fn minimum_increment() {
        let p = G76Params {
            dd: 0.1,
            dmin: 0.08,
            k: 0.5,
            d: 0.0,
            ..sample()
        };
        assert_depths(
            &passes(&p).unwrap(),
            &[0.1, 0.18, 0.26, 0.34, 0.42, 0.5, 0.5],
            1e-12,
        );
    }

    /// P3 constant depth: n·Δd capped at k − d.
    #[test]
    fn constant_depth_law() {
        let p = G76Params {
            dd: 0.3,
            k: 1.0,
            d: 0.1,
            law: DepthLaw::ConstantDepth,
            ..sample()
        };
        assert_depths(&passes(&p).unwrap(), &[0.3, 0.6, 0.9, 1.0], 1e-12);
    }

    /// Δd ≥ k − d: one rough pass at k − d (with a warning predicate for Δd > k).
    #[test]
    fn first_depth_beyond_the_height() {
        let p = G76Params {
            dd: 2.0,
            ..sample()
        };
        assert_depths(&passes(&p).unwrap(), &[1.062, 1.082], 1e-12);
        assert!(first_depth_exceeds_height(&p));
        assert!(!first_depth_exceeds_height(&sample()));
    }

    /// P2 alternates the flank shift; radial infeed (A0) has none.
    #[test]
    fn alternating_and_radial_infeed() {
        let start = Pt::new(5.0, 11.0);
        let p = G76Params {
            edges: Edges::Alternating,
            ..sample()
        };
        let mv = moves(start, &p).unwrap();
        let d = passes(&p).unwrap();
        for (n, pass) in mv.chunks(4).enumerate() {
            let s = (p.k - d[n]) * TAN30 * if n % 2 == 0 { 1.0 } else { -1.0 };
            assert!(close(pass[0].to.z, 5.0 + s, 1e-12), "pass {n}");
        }
        let p = G76Params { a: 0.0, ..sample() };
        assert!(moves(start, &p)
            .unwrap()
            .chunks(4)
            .all(|m| m[0].to.z == 5.0));
    }

    /// ID thread (start inside the end point): depth goes toward +r; a taper shifts the
    /// start radius by i; the chamfer pulls out inward.
    #[test]
    fn internal_tapered_thread_with_chamfer() {
        // M30×2 ID: bore Φ27.9, root Φ30 at Z−20, start (Z3, X26).
        let p = G76Params {
            end: Pt::new(-20.0, 15.0),
            k: 1.1,
            dd: 0.4,
            d: 0.05,
            dmin: 0.05,
            i: -0.2,
            lead: 2.0,
            chamfer_leads: 0.5,
            ..sample()
        };
        let start = Pt::new(3.0, 13.0);
        let mv = moves(start, &p).unwrap();
        let h0 = passes(&p).unwrap()[0];
        let t = 1.1 - h0;
        let s = t * TAN30;
        assert!(close(mv[0].to.r, 15.0 - t - 0.2, 1e-12) && close(mv[0].to.z, 3.0 + s, 1e-12));
        // γ = 1 mm; on the taper 1 mm before the end: −0.2·1/23 above the end radius.
        assert!(close(mv[1].to.z, -20.0 + s + 1.0, 1e-12));
        assert!(close(mv[1].to.r, 15.0 - t - 0.2 / 23.0, 1e-12));
        assert!(close(mv[2].to.r, 15.0 - t - 1.0, 1e-12) && close(mv[2].to.z, -20.0 + s, 1e-12));
        assert_eq!(mv[3].to, Pt::new(-20.0 + s, 13.0));
        assert_eq!(mv[4].to, start);
        // Last pass at full depth: r = 15, no shift.
        let last = &mv[mv.len() - 5..];
        assert!(close(last[0].to.r, 14.8, 1e-12) && last[0].to.z == 3.0);
    }

    /// A thread cut toward +Z (start at Z−30, end Z0) mirrors: the shift and the chamfer
    /// point toward −Z, the side of the start point.
    #[test]
    fn thread_cut_toward_plus_z() {
        let p = G76Params {
            end: Pt::new(0.0, 17.835 / 2.0),
            chamfer_leads: 1.0,
            ..sample()
        };
        let start = Pt::new(-30.0, 11.0);
        let mv = moves(start, &p).unwrap();
        let s = (p.k - 0.35) * TAN30;
        assert!(close(mv[0].to.z, -30.0 - s, 1e-12));
        assert!(close(mv[1].to.z, -s - 1.5, 1e-12));
        assert!(close(mv[2].to.z, -s, 1e-12) && close(mv[2].to.r, mv[1].to.r + 1.5, 1e-12));
        assert!(close(mv[3].to.z, -s, 1e-12) && mv[3].to.r == 11.0);
    }

    /// Haas Q is the start angle (0.001°), not a depth; E gives the lead on Haas.
    #[test]
    fn haas_start_angle_and_e() {
        let h = blocks("G76 X18.05 Z-25. K0.975 D0.4 Q180000 E1.5\n");
        let cfg = OneBlockConfig::haas(0.0, 0.025, false, 1.0, 45.0);
        let p = read_one_block(|l| h[0].get(l), Pt::new(-25.0, 9.025), None, 1.0, &cfg).unwrap();
        assert_eq!(p.start_angle, 180.0);
        assert_eq!(p.lead, 1.5);
        assert_eq!(p.a, 0.0);
        assert!(close(p.dd, 0.4, 1e-12));
        assert_eq!((p.law, p.edges), (DepthLaw::ConstantAmount, Edges::One));
    }

    /// A first block alone keeps the retained values it does not write; F falls back to the
    /// F in force; G20 scales R, F and the calculator words.
    #[test]
    fn retained_values_and_units() {
        let b = blocks("G76 Q20\nG76 X0.7 Z-1. P40 Q10\n");
        let prev = FirstBlock::profile(3, 5, 55, 0.1, 0.01);
        let first = read_first(|l| b[0].get(l), &prev, 0.0001 * 25.4, 25.4).unwrap();
        assert_eq!((first.m, first.r, first.a, first.d), (3, 5, 55, 0.01));
        assert!(close(first.dmin, 0.002 * 25.4, 1e-12));
        let p = read_second(
            |l| b[1].get(l),
            &first,
            Pt::new(-25.4, 8.89),
            Some(1.27),
            0.0001 * 25.4,
            25.4,
            45.0,
        )
        .unwrap();
        assert!(close(p.k, 0.004 * 25.4, 1e-12) && close(p.dd, 0.001 * 25.4, 1e-12));
        assert_eq!(p.lead, 1.27);
        assert_eq!(p.at.lead.span, None);
    }

    // --- Alarms -----------------------------------------------------------------------------

    /// The error of reading (and planning) a two-block G76 from A = (5, 11).
    fn two_block_error(src: &str) -> G76Error {
        let b = blocks(src);
        let end = Pt::new(-25.0, 9.025);
        let first = match read_first(|l| b[0].get(l), &FirstBlock::default(), IS_B, 1.0) {
            Ok(f) => f,
            Err(e) => return e,
        };
        let p = match read_second(|l| b[1].get(l), &first, end, None, IS_B, 1.0, 45.0) {
            Ok(p) => p,
            Err(e) => return e,
        };
        moves(Pt::new(5.0, 11.0), &p).unwrap_err()
    }

    fn letter_col(e: &G76Error) -> (char, Option<(u32, u32)>) {
        let at = e.at.unwrap();
        (at.letter, at.span.map(|s| (s.line, s.column)))
    }

    #[test]
    fn alarm_first_depth_zero() {
        let e = two_block_error("G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q0 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::FirstDepth { .. }), "{e}");
        assert_eq!(letter_col(&e), ('Q', Some((2, 22))));
        assert_eq!(e.code(), "PS062");
    }

    #[test]
    fn alarm_height_and_lead() {
        let e = two_block_error("G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P0 Q400 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::Height { .. }), "{e}");
        assert_eq!(letter_col(&e), ('P', Some((2, 17))));
        let e = two_block_error("G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q400 F0\n");
        assert!(matches!(e.kind, G76ErrorKind::Lead { .. }), "{e}");
        assert_eq!(letter_col(&e).0, 'F');
        let e = two_block_error("G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q400\n");
        assert!(matches!(e.kind, G76ErrorKind::Missing { .. }), "{e}");
        assert_eq!(letter_col(&e), ('F', None));
    }

    /// The finishing allowance eats the whole height: d ≥ k, at the first block's R.
    #[test]
    fn alarm_depth_larger_than_the_height_allows() {
        let e = two_block_error("G76 P021060 Q50 R1.\nG76 X18.05 Z-25 P975 Q400 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::Allowance { .. }), "{e}");
        assert_eq!(letter_col(&e), ('R', Some((1, 17))));
        let p = G76Params {
            d: -0.1,
            ..sample()
        };
        assert!(matches!(
            passes(&p).unwrap_err().kind,
            G76ErrorKind::Allowance { .. }
        ));
    }

    /// γ = 9.9 L = 14.85 mm on a thread of 5 − (−5) = 10 mm: the first block's P at fault.
    #[test]
    fn alarm_chamfer_longer_than_the_thread() {
        let b = blocks("G76 P029960 Q50 R0.05\nG76 X18.05 Z-5 P975 Q400 F1.5\n");
        let p = fanuc(&b, Pt::new(-5.0, 9.025)).unwrap();
        let e = moves(Pt::new(5.0, 11.0), &p).unwrap_err();
        assert!(matches!(e.kind, G76ErrorKind::ChamferTooLong { .. }), "{e}");
        assert_eq!(letter_col(&e), ('P', Some((1, 5))));
        assert_eq!(e.code(), "LS-G76-CHAMFER");
    }

    #[test]
    fn alarm_p_digits() {
        for (src, want) in [
            ("G76 P1021060 Q50 R0.05", "PDigits"),
            ("G76 P0210.60 Q50 R0.05", "PDigits"),
            ("G76 P-21060 Q50 R0.05", "PDigits"),
            ("G76 P001060 Q50 R0.05", "NoFinishingPass"),
            ("G76 P021045 Q50 R0.05", "ToolAngle"),
        ] {
            let b = blocks(src);
            let e = read_first(|l| b[0].get(l), &FirstBlock::default(), IS_B, 1.0).unwrap_err();
            assert!(format!("{:?}", e.kind).starts_with(want), "{src}: {e}");
            assert_eq!(letter_col(&e), ('P', Some((1, 5))), "{src}");
            assert_eq!(e.code(), "PS062");
        }
        let p = G76Params { m: 0, ..sample() };
        assert_eq!(passes(&p).unwrap_err().kind, G76ErrorKind::NoFinishingPass);
    }

    #[test]
    fn alarm_decimal_point_and_negative_minimum() {
        let e = two_block_error("G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P0.975 Q400 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::DecimalPoint { .. }), "{e}");
        assert_eq!(e.code(), "LS-INCREMENT");
        assert!(e.help().contains("P1000"), "{}", e.help());
        let e = two_block_error("G76 P021060 Q50. R0.05\nG76 X18.05 Z-25 P975 Q400 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::DecimalPoint { .. }), "{e}");
        assert_eq!(letter_col(&e), ('Q', Some((1, 13))));
        let e = two_block_error("G76 P021060 Q-50 R0.05\nG76 X18.05 Z-25 P975 Q400 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::MinDepth { .. }), "{e}");
        // With P/Q in mm (GSK NO182.7) a decimal point is fine.
        let b = blocks("G76 Q0.05\n");
        let f = read_first(|l| b[0].get(l), &FirstBlock::default(), 1.0, 1.0).unwrap();
        assert_eq!(f.dmin, 0.05);
    }

    /// Δdmin 0 and Δd 0.0001 mm (IS-C Q1): (0.925 / 0.0001)² ≈ 8.6e7 passes → a clear error
    /// at once, never a hang or a huge allocation.
    #[test]
    fn alarm_too_many_passes() {
        let b = blocks("G76 P021060 Q0 R0.05\nG76 X18.05 Z-25 P9750 Q1 F1.5\n");
        let first = read_first(|l| b[0].get(l), &FirstBlock::default(), 0.0001, 1.0).unwrap();
        let p = read_second(
            |l| b[1].get(l),
            &first,
            Pt::new(-25.0, 9.025),
            None,
            0.0001,
            1.0,
            45.0,
        )
        .unwrap();
        let e = passes(&p).unwrap_err();
        let G76ErrorKind::TooManyPasses { estimate } = e.kind else {
            panic!("{e}")
        };
        assert!(estimate > 8.5e7 && estimate < 8.6e7, "{estimate}");
        assert_eq!(letter_col(&e), ('Q', Some((2, 23))));
        assert!(e.message().contains("passes"));
    }

    /// Start inside the pull-out, no radial travel at all, and a taper against U.
    #[test]
    fn alarm_travel_and_taper() {
        let p = G76Params {
            chamfer_leads: 1.0,
            ..sample()
        };
        // |U/2| = 9.5 − 8.9175 = 0.5825 < γ·tan45 = 1.5.
        let e = moves(Pt::new(5.0, 9.5), &p).unwrap_err();
        assert!(matches!(e.kind, G76ErrorKind::RadialTravel { .. }), "{e}");
        assert_eq!(e.at.unwrap().letter, 'X');
        let e = moves(Pt::new(5.0, p.end.r), &sample()).unwrap_err();
        assert!(matches!(e.kind, G76ErrorKind::RadialTravel { .. }), "{e}");
        // OD: U/2 = 8.9175 − 11 = −2.0825; i = +2.5 opposite and larger.
        let p = G76Params { i: 2.5, ..sample() };
        let e = moves(Pt::new(5.0, 11.0), &p).unwrap_err();
        assert!(matches!(e.kind, G76ErrorKind::Taper { .. }), "{e}");
        assert_eq!(e.code(), "LS-G76-TAPER");
        let p = G76Params { i: 2.0, ..sample() };
        assert!(moves(Pt::new(5.0, 11.0), &p).is_ok());
        let e = moves(Pt::new(-20.0, 11.0), &sample()).unwrap_err();
        assert_eq!(e.kind, G76ErrorKind::NoZTravel);
    }

    /// One-block words: P1–P4, A 0–120, Q whole 0.001°, K and D required.
    #[test]
    fn alarm_one_block_words() {
        let cfg = OneBlockConfig::haas(0.0, 0.025, false, 1.0, 45.0);
        let end = Pt::new(-25.0, 9.025);
        for (src, want, letter) in [
            ("G76 X18.05 Z-25 K0.975 D0.4 P975 F1.5", "InfeedType", 'P'),
            ("G76 X18.05 Z-25 K0.975 D0.4 P5 F1.5", "InfeedType", 'P'),
            ("G76 X18.05 Z-25 K0.975 D0.4 A130 F1.5", "ToolAngle", 'A'),
            ("G76 X18.05 Z-25 K0.975 D0.4 Q180. F1.5", "StartAngle", 'Q'),
            (
                "G76 X18.05 Z-25 K0.975 D0.4 Q400000 F1.5",
                "StartAngle",
                'Q',
            ),
            ("G76 X18.05 Z-25 D0.4 F1.5", "Missing", 'K'),
            ("G76 X18.05 Z-25 K0.975 F1.5", "Missing", 'D'),
            ("G76 X18.05 Z-25 K0.975 D0.4 F1.5 E1.5", "LeadTwice", 'E'),
        ] {
            let b = blocks(src);
            let e = read_one_block(|l| b[0].get(l), end, None, 1.0, &cfg).unwrap_err();
            assert!(format!("{:?}", e.kind).starts_with(want), "{src}: {e}");
            assert_eq!(e.at.unwrap().letter, letter, "{src}");
        }
        // Haas setting 86 larger than K: at K.
        let b = blocks("G76 X18.05 Z-25 K0.975 D0.4 F1.5");
        let cfg = OneBlockConfig::haas(1.0, 0.025, false, 1.0, 45.0);
        let p = read_one_block(|l| b[0].get(l), end, None, 1.0, &cfg).unwrap();
        let e = passes(&p).unwrap_err();
        assert!(matches!(e.kind, G76ErrorKind::Allowance { .. }));
        assert_eq!(letter_col(&e), ('K', Some((1, 17))));
    }

    #[test]
    fn classify_forms() {
        let form = |src: &str| {
            let b = blocks(src);
            classify(|l| b[0].get(l))
        };
        assert_eq!(form("G76 P021060 Q50 R0.05"), Ok(Form::First));
        assert_eq!(form("G76 U-3.95 W-30 P975 Q400 F1.5"), Ok(Form::Second));
        assert_eq!(form("G76 X18 Z-25 K1 D0.4 F1.5"), Ok(Form::OneBlock));
        assert_eq!(
            form("G76 P975 Q400 F1.5").unwrap_err().kind,
            G76ErrorKind::NoEndPoint
        );
        assert_eq!(
            form("G76 K1 D0.4 F1.5").unwrap_err().kind,
            G76ErrorKind::NoEndPoint
        );
        let e = form("G76 P1.5 Z-20 I-0.1 J0.1 K0.9 H2").unwrap_err();
        assert_eq!(
            (e.kind.clone(), e.code()),
            (G76ErrorKind::LinuxCnc, "LS-G76-LINUXCNC")
        );
        assert_eq!(e.at.unwrap().letter, 'J');
    }

    /// The diagnostic lands on the word, or on the fallback when no word gave the value.
    #[test]
    fn diagnostic_position() {
        let fallback = Span {
            line: 9,
            column: 1,
            offset: 0,
            len: 3,
        };
        let e = two_block_error("G76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q0 F1.5\n");
        let d = e.diagnostic(fallback);
        assert_eq!((d.span.line, d.span.column, d.code), (2, 22, "PS062"));
        let p = G76Params { m: 0, ..sample() };
        let d = passes(&p).unwrap_err().diagnostic(fallback);
        assert_eq!(d.span, fallback);
    }
}
