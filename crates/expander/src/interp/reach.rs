//! Blocks after the main program's end that nothing can reach (spec/dialects.md §1: text
//! after M30 that is not in an O block is reachable only by M97 or GOTO; if nothing refers
//! to it, warn "unreachable").
//!
//! **Interpretation**: the tail counts as referred to when any P or Q word of the program
//! (M97 P, M99 P, G70–G73 P/Q, …) names one of its sequence numbers; a P or Q that is not a
//! sequence number is over-counted, so the warning errs on the side of silence.

use gcode::{Block, Subprogram};
use std::borrow::Cow;

/// The first block after the first M02/M30 of `main`, when no P/Q word of the program names
/// a sequence number of the blocks from there on.
pub(super) fn unreachable_tail(main: &Subprogram) -> Option<Cow<'_, Block>> {
    let blocks = &main.blocks;
    let end = (0..blocks.len()).find(|&i| blocks.ends_program(i))?;
    let first = blocks.get(end + 1)?;
    let named = |n: u32| {
        blocks.iter().any(|b| {
            b.words
                .iter()
                .any(|w| matches!(w.letter, 'P' | 'Q') && !w.has_point && w.value == f64::from(n))
        })
    };
    let referred = (end + 1..blocks.len())
        .filter_map(|i| blocks.seq(i))
        .any(named);
    (!referred).then_some(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tail(src: &str) -> Option<u32> {
        let p = gcode::parse(src).unwrap();
        unreachable_tail(p.main().unwrap()).map(|b| b.span.line)
    }

    #[test]
    fn blocks_after_m30_need_a_reference() {
        assert_eq!(tail("G0 X1\nM30\nG0 X2\n"), Some(3));
        assert_eq!(tail("M97 P100\nM30\nN100 G0 X2\nM99\n"), None);
        assert_eq!(tail("G0 X1\nM30\n"), None);
        assert_eq!(tail("G0 X1\nM30\nN100 G0 X2\nM99\n"), Some(3));
    }
}
