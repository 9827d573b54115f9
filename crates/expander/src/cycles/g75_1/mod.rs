//! G75.1 — GSK radial trapezoid groove cycle (seed 000, spec/cycles.md).
//!
//! ```text
//! G75.1 X Z P(Δi) Q(Δk) H(h) D(d) A(a) B(b) L(p);                          geometry
//! G75.1 R(e) V(Δv) U(Δu) W(Δw) I(w) J(0|1|2) A(r1) B(r2) D(r3) E(r4) P(abde);  process
//! ```
//! The block holding H is the geometry block; it is kept in the retained state and the
//! cycle runs when the process block (the next block, a G75.1 without H) is read.
//!
//! All geometry is computed in a local frame of the groove: `u` along Z toward the far side
//! (sign of D), `v` along the radius toward the floor (sign of H), both from the mouth corner
//! P1. Points are mapped back to (z, r) at the end, arcs flipping direction when the map is
//! a reflection.
//!
//! The tool: with I, a blade of width |I| whose reference is its start-side corner and
//! which extends toward the far side (the spec's Interpretation); without I, the tool is
//! taken as a point (GSK: "a pointed tool, G41/G42 apply"), width 0 — the interpreter does
//! not know the tool table's blade width. The start-side corner traces the start flank, the
//! floor-start corner and the mouth-start corner; the far corner (reference + width) traces
//! the far flank and its corners.
//!
//! Choices where the seed is silent:
//! - Layer 1 plunges start at the highest point of the groove's mouth (P1's level with L0,
//!   P4's level with a sloped mouth), so the Z rapids between plunges stay out of the stock.
//! - The roughing contour pass and the finishing pass return to A11 / the start point by
//!   rapids along that same level.
//! - U and W are unsigned (a negative value is an alarm); I negative means positive (seed).

mod motion;
pub(crate) mod pairing;
mod plan;
mod shape;
mod words;

use pairing::Break;

use super::{Cycle, Move, Output};
use crate::{Diagnostic, IntendedKind};
pub(crate) use shape::Trapezoid;

/// The geometry block's words, kept until the process block arrives.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Geometry {
    /// The groove's shape (start point, depth, width, angles).
    shape: Trapezoid,
    /// Radial infeed per peck, diameter, mm.
    di: f64,
    /// Z shift between plunges, mm.
    dk: f64,
    /// Line of the geometry block (for messages).
    line: u32,
    /// Index of the geometry block in its program, and the program's O number.
    at: (usize, Option<u32>),
}

/// Expand one G75.1 block: store the geometry block, or run the cycle on the process block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    if c.words.has('H') {
        if let Some(g) = &c.retained.g75_1 {
            return Err(pairing::alarm(c.span(), Some(g), Break::SecondGeometry));
        }
        c.retained.g75_1 = Some(words::geometry_block(c)?);
        return Ok(Output::default());
    }
    let Some(g) = c.retained.g75_1.take() else {
        return Err(pairing::alarm(c.span(), None, Break::NoGeometry));
    };
    if !pairing::follows(&g, c.program, c.index) {
        return Err(pairing::alarm(c.span(), Some(&g), Break::Interrupted));
    }
    process_block(c, &g)
}

/// The process block: its words read, the cycle planned on the geometry block's groove,
/// its moves made; the groove is the shape the cycle intends.
fn process_block(c: &mut Cycle, g: &Geometry) -> Result<Output, Diagnostic> {
    let words = words::process_block(c, g)?;
    let plan = plan::plan(c, g, &words)?;
    let warnings = plan::blade_warning(c, &words).into_iter().collect();
    let mut moves = motion::moves(&plan);
    // rapid back to where the tool was before the cycle
    let mut back = Move::rapid(c.start);
    back.hint = plan.hint;
    moves.push(back);
    let ring = plan
        .shape
        .ring(0.001)
        .map_err(|m| c.alarm("LS-G75.1-SHAPE", m, "check the chamfers and angles"))?;
    Ok(Output {
        moves,
        warnings,
        intended: vec![(IntendedKind::Groove, ring)],
        ..Output::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Pt;
    use shape::Corner;

    /// The seed 000 example: P1 (30, 25), P2 (20, 15), P3 (10, 15), P4 (−7.32, 25).
    #[test]
    fn seed_000_trapezoid() {
        let t = Trapezoid {
            start: Pt::new(30.0, 25.0),
            h: -20.0,
            d: -10.0,
            a: 45.0,
            b: 30.0,
            l: 0.0,
            corners: [Corner::Sharp; 4],
        };
        let ring = t.ring(0.001).unwrap();
        let want = [
            (30.0, 25.0),
            (20.0, 15.0),
            (10.0, 15.0),
            (10.0 - 10.0 * 3f64.sqrt(), 25.0),
        ];
        assert_eq!(ring.len(), 4);
        for (p, w) in ring.iter().zip(want) {
            assert!(
                (p.z - w.0).abs() < 1e-9 && (p.r - w.1).abs() < 1e-9,
                "{p:?} {w:?}"
            );
        }
    }

    /// Corners: a chamfer moves the ring's end onto the mouth line; a round is chorded.
    #[test]
    fn corners_in_the_ring() {
        let mut t = Trapezoid {
            start: Pt::new(0.0, 30.0),
            h: -16.0,
            d: -12.0,
            a: 90.0,
            b: 90.0,
            l: 0.0,
            corners: [
                Corner::Round(1.0),
                Corner::Chamfer(1.5),
                Corner::Sharp,
                Corner::Sharp,
            ],
        };
        let ring = t.ring(0.001).unwrap();
        assert!(ring[0].dist(Pt::new(1.0, 30.0)) < 1e-9, "{:?}", ring[0]);
        assert!(ring
            .iter()
            .any(|p| (p.z - 0.0).abs() < 1e-12 && (p.r - 29.0).abs() < 1e-12));
        assert!(ring[ring.len() - 1].dist(Pt::new(-13.5, 30.0)) < 1e-9);
        t.corners[2] = Corner::Chamfer(9.0);
        assert!(t.ring(0.001).unwrap_err().contains("start flank"));
    }
}
