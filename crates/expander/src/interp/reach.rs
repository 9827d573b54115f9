//! Blocks after the main program's end that nothing can reach (spec/dialects.md §1: text
//! after M30 that is not in an O block is reachable only by M97 or GOTO; if nothing refers
//! to it, warn "unreachable").
//!
//! **Interpretation**: the tail counts as referred to when any P or Q word of the program
//! (M97 P, M99 P, G70–G73 P/Q, …) names one of its sequence numbers; a P or Q that is not a
//! sequence number is over-counted, so the warning errs on the side of silence.

use gcode::{Block, Subprogram};
use std::borrow::Cow;
use std::collections::HashSet;

/// The first block after the first M02/M30 of `main`, when no P/Q word of the program names
/// a sequence number of the blocks from there on.
pub(super) fn unreachable_tail(main: &Subprogram) -> Option<Cow<'_, Block>> {
    let blocks = &main.blocks;
    let end = (0..blocks.len()).find(|&i| blocks.ends_program(i))?;
    let first = blocks.get(end + 1)?;
    if (end + 1..blocks.len()).any(|i| closes_o_word(&blocks.at(i))) {
        // LinuxCNC: the end stands inside an o-word block (`o10 if … M2 o10 endif`)
        return None;
    }
    let tail: Vec<u32> = (end + 1..blocks.len())
        .filter_map(|i| blocks.seq(i))
        .collect();
    if tail.is_empty() {
        return Some(first);
    }
    // the numbers P and Q words name, from one reading of the blocks (each block is read
    // again from the text, so not once for every number of the tail)
    let mut named = HashSet::new();
    for b in blocks.iter() {
        for w in b.words.iter() {
            let n = w.value as u32;
            if matches!(w.letter, 'P' | 'Q') && !w.has_point && w.value == f64::from(n) {
                named.insert(n);
            }
        }
    }
    let referred = tail.iter().any(|n| named.contains(n));
    (!referred).then_some(first)
}

/// Whether `b` continues or closes a `LinuxCNC` o-word block opened before it.
fn closes_o_word(b: &Block) -> bool {
    use macro_b::{OKeyword as K, StmtKind};
    matches!(
        b.stmt.as_deref().map(|s| &s.kind),
        Some(StmtKind::OWord {
            keyword: K::ElseIf
                | K::Else
                | K::EndIf
                | K::EndWhile
                | K::While
                | K::EndRepeat
                | K::EndSub,
            ..
        })
    )
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
        // a Q names a block of the tail too; a P written with a point names none
        assert_eq!(tail("G70 P5 Q200\nM30\nN100 G0 X2\nN200 X3\n"), None);
        assert_eq!(tail("M97 P100.\nM30\nN100 G0 X2\n"), Some(3));
    }
}
