//! G94 — face turning cycle, flat and tapered face (spec/cycles.md).
//!
//! `G94 X(U) Z(W) [R] F;` R = Z of cut start minus Z of cut end. Modal like G90.

use super::{Cycle, Move, Output};
use crate::codes::G94;
use crate::{Diagnostic, Pt};

/// Expand one G94 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let w = c.turn_words(G94)?;
    let a = c.start;
    let (end, r) = (w.end, w.r);
    let half_w = end.z - a.z;
    if r != 0.0 && half_w != 0.0 && r.signum() != half_w.signum() && r.abs() > half_w.abs() + 1e-9 {
        return Err(c.alarm(
            "LS-G94-R",
            format!(
                "G94 taper R{r} is larger than the Z travel W = {half_w:.3} with the opposite sign"
            ),
            "when R and W have different signs, |R| must not exceed |W|",
        ));
    }
    Ok(Output {
        moves: vec![
            Move::rapid(Pt::new(end.z + r, a.r)), // ① Z rapid to the cut start
            Move::feed(end),                      // ② cut to the cut end
            Move::feed(Pt::new(a.z, end.r)),      // ③ Z feed back to the start Z
            Move::rapid(a),                       // ④ X rapid back to the start point
        ],
        ..Output::default()
    })
}
