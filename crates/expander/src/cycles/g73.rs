//! G73 — pattern repeating cycle (seed 003, `GSK980TDb`; spec/cycles.md).
//!
//! ```text
//! G73 U(Δi) W(Δk) R(d) F S T;     relief and count: retained (GSK NO.053–055)
//! G73 P(ns) Q(nf) U(Δu) W(Δw) F S T;
//! ```
//! U and W mean Δi/Δk in a block without P/Q and Δu/Δw in a block with P and Q. Δi is
//! a radius, Δu a diameter, both signed. Pass k of d is the shape moved by
//! (Δu/2 + Δi·(d−k)/(d−1), Δw + Δk·(d−k)/(d−1)) in (r, z); d = 1 runs as 2 passes.
//!
//! Choices: a P/Q block before any relief block uses the retained values, or
//! Δi = Δk = 0 and d = 1 (the GSK data parameters at their factory value) with a warning.
//! Every element of a pass after its first is fed (seed: "bn→cn 切削進給"), also a G00
//! written inside the shape. The rough passes carry the span of the shape block they
//! copy; the rapids between passes carry the G73 block's.
//!
//! Haas one block (spec/dialects.md §3.3): `G73 P Q U W I K D F S T`: I the total X relief
//! (radius, signed), K the total Z relief, D the number of passes; the same pass law with
//! Δi = I, Δk = K, d = D. The two-block form is not Haas's (an alarm under `haas`), and the
//! one-block form is an alarm under the other controls.

use super::contour::{self, FinishingShape};
use super::{passes, Cycle, Move, Output};
use crate::{Control, Diagnostic, Pt};

/// Expand one G73 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let haas = c.machine.control == Control::Haas;
    if let Some(d) = c.words.block.get('D').filter(|_| !haas) {
        return Err(Diagnostic::new(
            d.span,
            "LS-ONE-BLOCK-FORM",
            format!(
                "G73 with D in one block is the Haas form: run with --control haas (this control is {})",
                c.machine.control.key()
            ),
            "write the two-block form G73 U(Δi) W(Δk) R(d); G73 P Q U W F, or run with --control haas",
        ));
    }
    if !c.words.has('P') && !c.words.has('Q') {
        if haas {
            return Err(c.alarm(
                "LS-ONE-BLOCK-FORM",
                "G73 needs P and Q: the Haas lathe reads the one-block form",
                "write G73 P(ns) Q(nf) U(Δu) W(Δw) I(X relief) K(Z relief) D(passes) F in one block",
            ));
        }
        return relief_block(c);
    }
    if haas {
        return haas_block(c);
    }
    let shape = contour::read(c)?;
    let du = c.words.mm('U', c.unit).unwrap_or(0.0) / 2.0; // Δu/2: radius
    let dw = c.words.mm('W', c.unit).unwrap_or(0.0);
    let mut out = Output::default();
    let (di, dk, d) = match c.retained.g73 {
        Some(v) => v,
        None => {
            out.warnings.push(c.alarm(
                "LS-G73-DEFAULT",
                "no G73 U(Δi) W(Δk) R(d) block before this one: Δi = 0, Δk = 0, d = 1 (2 passes)",
                "write G73 U(Δi) W(Δk) R(d) before the G73 P Q block",
            ));
            (0.0, 0.0, 1)
        }
    };
    out.moves = rough_passes(&shape, (di, dk, d), (du, dw));
    out.resume_at = shape.resume_at(c.index, &c.program.blocks);
    out.intended.push((
        crate::IntendedKind::FinishingContour,
        shape.intended_path(0.001),
    ));
    Ok(out)
}

/// Haas `G73 P Q U W I K D F`: everything in the one block.
fn haas_block(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let d = match c.words.take('D') {
        Some(w) if !w.has_point && (1.0..=9999.0).contains(&w.value) && w.value.fract() == 0.0 => {
            w.value as u32
        }
        Some(w) => {
            return Err(Diagnostic::new(
                w.span,
                "PS062",
                format!("G73 D{} is not a number of passes 1 … 9999", w.value),
                "Haas G73 D counts the rough passes: a whole number without a decimal point",
            ))
        }
        None => {
            return Err(c.alarm(
                "PS062",
                "Haas G73 without D (number of passes)",
                "give the number of rough passes as D, e.g. D4",
            ))
        }
    };
    let di = c.words.mm('I', c.unit).unwrap_or(0.0);
    let dk = c.words.mm('K', c.unit).unwrap_or(0.0);
    let du = c.words.mm('U', c.unit).unwrap_or(0.0) / 2.0;
    let dw = c.words.mm('W', c.unit).unwrap_or(0.0);
    let shape = contour::read(c)?;
    let mut out = Output {
        moves: rough_passes(&shape, (di, dk, d), (du, dw)),
        resume_at: shape.resume_at(c.index, &c.program.blocks),
        ..Output::default()
    };
    out.intended.push((
        crate::IntendedKind::FinishingContour,
        shape.intended_path(0.001),
    ));
    Ok(out)
}

/// The first block: store Δi, Δk, d (each word keeps its retained value when omitted).
fn relief_block(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let (pi, pk, pd) = c.retained.g73.unwrap_or((0.0, 0.0, 1));
    let di = c.words.mm('U', c.unit).unwrap_or(pi);
    let dk = c.words.mm('W', c.unit).unwrap_or(pk);
    let d = match c.words.take('R') {
        None => pd,
        Some(r) if r.value.fract() == 0.0 && (1.0..=9999.0).contains(&r.value) => r.value as u32,
        Some(r) => {
            return Err(Diagnostic::new(
                r.span,
                "PS062",
                format!("G73 R{} is not a number of passes 1 … 9999", r.value),
                "R(d) counts the rough passes: a whole number from 1 to 9999",
            ))
        }
    };
    c.retained.g73 = Some((di, dk, d));
    Ok(Output::default())
}

/// The rough passes of the seed's steps ①–⑤.
fn rough_passes(
    shape: &FinishingShape,
    (di, dk, d): (f64, f64, u32),
    (du, dw): (f64, f64),
) -> Vec<Move> {
    let d = d.max(2); // d = 1 is executed as 2 cuts (seed 003)
    let a = shape.start;
    let mut moves = Vec::with_capacity(d as usize * (shape.elements.len() + 1) + 1);
    for k in 1..=d {
        let f = f64::from(d - k) / f64::from(d - 1);
        let off = Pt::new(dw + dk * f, du + di * f);
        // ① / ③ / ⑤: rapid to A_k (from A, or from C_{k-1})
        moves.push(Move::rapid(Pt::new(a.z + off.z, a.r + off.r)));
        // ② / ④: A_k → B_k as the ns block (G00 rapid, G01 feed), then B_k → C_k fed
        moves.extend(passes::moved(shape, off));
    }
    moves.push(Move::rapid(a)); // C_d → A
    moves
}
