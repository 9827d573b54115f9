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

mod error;
mod plan;
mod read;

use crate::{Diagnostic, Pt, Span};
use gcode::Word;
use plan::{first_depth_exceeds_height, moves};
use read::{classify, read_first, read_one_block, read_second, Form};

/// Most passes one G76 may cut: a microscopic Δd is an error, not a hang.
pub(crate) const MAX_PASSES: usize = 10_000;
/// Tool angles the FANUC two-block P(a) digits accept (§4.4).
pub(crate) const TOOL_ANGLES: [u32; 6] = [0, 29, 30, 55, 60, 80];
/// Geometric tolerance, mm.
pub(crate) const EPS: f64 = 1e-9;

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

/// Run a G76 block in the interpreter. FANUC/GSK two-block form: the first block only
/// stores m r a, Δdmin and d (retained as the control keeps them); the second cuts the
/// passes from the cycle's start point. One-block form (Haas §3.5; FANUC FS15 §4.5 with
/// `fs15_format = true`): the settings come from the profile (Haas settings 86, 99, 95/96
/// under M23) or, for FS15, from the retained first-block values. Each form under a
/// control that does not read it is an alarm naming the control.
pub(super) fn run(c: &mut super::Cycle) -> Result<super::Output, Diagnostic> {
    let g_span = c.g.map_or(c.words.span(), |w| w.span);
    let block = c.words.block;
    let pq_mm = c.machine.pq_mm_under(c.unit);
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
            return Err(one_block_refused(c, g_span));
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
        tool_angle: (params.at.a.span.is_some() && params.a > 0.0).then_some(params.a),
        ..super::Output::default()
    };
    if first_depth_exceeds_height(&params) {
        out.warnings.push(first_depth_warning(c, &params));
    }
    Ok(out)
}

/// The one-block G76 under a control that reads only the two-block form.
fn one_block_refused(c: &super::Cycle, g_span: Span) -> Diagnostic {
    let block = c.words.block;
    let w = block.get('K').or_else(|| block.get('D'));
    Diagnostic::new(
        w.map_or(g_span, |w| w.span),
        "LS-ONE-BLOCK-FORM",
        format!(
            "G76 with K and D in one block is the Haas/FS15 form: run with --control haas (this control is {})",
            c.machine.control.key()
        ),
        "write the two-block form G76 P(m)(r)(a) Q R / G76 X Z R P Q F, or run with --control haas (FANUC with the FS15 format: fs15_format = true)",
    )
}

/// A first depth larger than the thread height cuts one rough pass at the height less d.
fn first_depth_warning(c: &super::Cycle, params: &G76Params) -> Diagnostic {
    c.alarm(
        "LS-G76-DEPTH",
        format!(
            "the first depth {:.4} mm is larger than the thread height {:.4} mm: one rough pass at the height less d",
            params.dd, params.k
        ),
        "check the first depth and the height (swapped?)",
    )
}

#[cfg(test)]
mod tests {
    use super::error::{G76Error, G76ErrorKind};
    use super::plan::passes;
    use super::*;
    use crate::cycles::Move;
    use crate::Motion;
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

    /// FANUC's manual writes `R200` for a 0.2 mm allowance (numbers without a decimal point
    /// in the least increment); latsim reads it as 200 mm, as every such number: the alarm's
    /// help says so and gives `R0.2` (field run: two public FANUC and Mazak samples).
    #[test]
    fn an_allowance_without_a_decimal_point_names_its_least_increment_reading() {
        let e = two_block_error("G76 P021060 Q100 R200\nG76 X18.05 Z-25 P975 Q400 F1.5\n");
        assert!(matches!(e.kind, G76ErrorKind::Allowance { .. }), "{e}");
        assert!(e.help().contains("write R0.2"), "{}", e.help());
        let e = two_block_error("G76 P021060 Q100 R1.5\nG76 X18.05 Z-25 P975 Q400 F1.5\n");
        assert!(!e.help().contains("write R"), "{}", e.help());
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

    /// No radial travel at all, and a taper against U, are alarms; a start inside the
    /// pull-out is not (the HUST rule [S19] is no FANUC, GSK or Haas alarm): the pull-out
    /// climbs past the start X and the pass rapids back to it.
    #[test]
    fn alarm_travel_and_taper() {
        let p = G76Params {
            chamfer_leads: 1.0,
            ..sample()
        };
        // |U/2| = 9.5 − 8.9175 = 0.5825 < γ·tan45 = 1.5: runs.
        let mv = moves(Pt::new(5.0, 9.5), &p).unwrap();
        let last = p.end.r + 1.5; // the final pass's pull-out ends at root + γ·tan45
        assert!(mv
            .iter()
            .any(|m| close(m.to.r, last, 1e-9) && close(m.to.z, p.end.z, 1e-9)));
        assert!(
            close(mv[mv.len() - 2].to.r, 9.5, 1e-12)
                && close(mv[mv.len() - 2].to.z, p.end.z, 1e-12)
        );
        let e = moves(Pt::new(5.0, p.end.r), &sample()).unwrap_err();
        assert_eq!(e.kind, G76ErrorKind::NoRadialTravel, "{e}");
        assert_eq!(e.at.unwrap().letter, 'X');
        assert_eq!(e.code(), "LS-G76-TRAVEL");
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
