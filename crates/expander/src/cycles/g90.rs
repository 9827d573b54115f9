//! G90 — axial turning cycle, cylinder and cone (seed 001, spec/cycles.md).
//!
//! `G90 X(U) Z(W) [R] F;` Modal: later blocks give only the words that change; X, Z and R
//! are retained. R is the radius difference cut start minus cut end, signed.

use super::{Cycle, Move, Output};
use crate::codes::G90;
use crate::Pt;

/// Expand one G90 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    let w = c.turn_words(G90)?;
    let a = c.start;
    let (end, r) = (w.end, w.r);
    // When R and U have different signs, |R| ≤ |U/2| (seed 001, figure 3-57 cases 3 and 4).
    let half_u = end.r - a.r;
    if r != 0.0 && half_u != 0.0 && r.signum() != half_u.signum() && r.abs() > half_u.abs() + 1e-9 {
        return Err(c.alarm(
            "LS-G90-R",
            format!("G90 taper R{r} is larger than the X travel U/2 = {half_u:.3} with the opposite sign"),
            "when R and U have different signs, |R| must not exceed |U/2|; check the cone's start diameter",
        ));
    }
    Ok(Output {
        moves: vec![
            Move::rapid(Pt::new(a.z, end.r + r)), // ① X rapid to the cut start
            Move::feed(end),                      // ② cut to the cut end
            Move::feed(Pt::new(end.z, a.r)),      // ③ X feed back to the start X
            Move::rapid(a),                       // ④ Z rapid back to the start point
        ],
        ..Output::default()
    })
}
