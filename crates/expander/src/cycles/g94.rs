//! G94 — face turning cycle, flat and tapered face (spec/cycles.md).
//!
//! `G94 X(U) Z(W) [R] F;` R = Z of cut start minus Z of cut end. Modal like G90.

use super::{Cycle, Move, Output, TurnWords};
use crate::{Diagnostic, Pt};

/// The end point and R of a G90/G92/G94 block, filling what the block omits from the
/// retained words of the same cycle (or, for a new cycle, the start point and R0).
pub(super) fn turn_words(c: &mut Cycle, code: i32) -> Result<TurnWords, Diagnostic> {
    let prev = c.retained.turn.filter(|t| t.code == code && c.g.is_none());
    let x = c.x_target()?;
    let z = c.z_target()?;
    let r = c.words.mm('R', c.unit);
    let end = Pt::new(
        z.or(prev.map(|p| p.end.z)).unwrap_or(c.start.z),
        x.or(prev.map(|p| p.end.r)).unwrap_or(c.start.r),
    );
    let words = TurnWords {
        code,
        end,
        r: r.or(prev.map(|p| p.r)).unwrap_or(0.0),
    };
    c.retained.turn = Some(words);
    Ok(words)
}

/// Expand one G94 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let w = turn_words(c, 940)?;
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
