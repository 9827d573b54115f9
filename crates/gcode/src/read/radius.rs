//! Radius programming (issue 31): CNC trainers, FANUC controls with parameter DIA (No.
//! 1006#3) off and Linux CNC's G8 write X as a radius. latsim works in diameters, so under
//! `ReadOptions::x_radius` the reader doubles every X-axis value as it reads the block:
//! X and U, the end points, G50/G53/G28 positions and the cycles' X, and U as the
//! finishing allowance of a G71–G73 P/Q block (FANUC: Δu follows the X axis's programming).
//! Values that are radii in either mode stay: I (arc centre), R (arc radius, taper), the
//! depth U(Δd) of a `G71 U R` block and the relief U(Δi) of a `G73 U W R` block (a G7x block
//! without P). Every later reading of the block (a finishing shape, a subprogram) goes
//! through the same reader, so the whole program is read one way.

use super::reading::ParseError;
use crate::Word;

/// Double the X-axis words of one block in place.
pub(crate) fn to_diameter(words: &mut [Word]) -> Result<(), ParseError> {
    let depth_block = words
        .iter()
        .any(|w| w.letter == 'G' && (70.0..80.0).contains(&w.value))
        && !words.iter().any(|w| w.letter == 'P');
    for w in words.iter_mut() {
        let axis = w.letter == 'X' || (w.letter == 'U' && !depth_block);
        if !axis {
            continue;
        }
        if w.expr.is_some() {
            return Err(ParseError::new(
                w.span,
                format!("{} written as a macro expression under radius programming", w.letter),
                "latsim reads X as a radius only from numbers; write the value, or run the program in diameters",
            ));
        }
        w.value *= 2.0;
    }
    Ok(())
}
