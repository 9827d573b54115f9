//! Reading a program text, by stage: the tape around the program (leader, trailer, control
//! bytes: [`tape`]), what is not code (comments, prose after `;`: [`comment`]), the
//! character loop ([`reader`]) with its fast path for plain blocks ([`plain`]), and the
//! numbers ([`number`]). The reader walks the bytes and decodes a character only where one
//! is not ASCII; a word's number is a slice of the source (copied only when written in
//! pieces, `Q5 000`), so a million-line program costs one allocation per block: its words.
//!
//! Lexical rules (spec/language.md): a block ends at a newline or `;`; letters are
//! case-insensitive; white space is ignored everywhere, also inside a word (`Q5 000`);
//! comments are `( )`, full-width `（ ）` and `//` to the end of the line; `%` lines mark
//! the tape; `/` at the start of a block is block delete.
//!
//! Framing as tape files and DNC software leave it (spec/dialects.md §1): a leader before
//! the first `%` is skipped, the reading stops at the closing `%`, RS-232 and other control
//! bytes are dropped, a lone CR ends a block like LF, `:` is the program number address,
//! text after `;` that is not a program is a comment, a nested or unclosed comment is read
//! the way the author meant it — each with a note the report shows.
//!
//! This module knows blocks ([`crate::block`]) but not the program that holds them: it
//! hands over a [`Reading`], and `Blocks` read one block again through [`one_block`].

mod comment;
mod expr;
mod foreign;
mod number;
mod plain;
mod radius;
mod reader;
mod reading;
mod tape;

use crate::{Block, Span};
use reader::Reader;
pub(crate) use reading::{BlockStart, Keep, ReadBlocks, Reading};
pub use reading::{ParseError, ReadOptions};

/// Read a whole text.
pub(crate) fn whole(src: &str, options: ReadOptions, keep: Keep) -> Result<Reading, ParseError> {
    check_length(src.len())?;
    Reader::new(src, options, reader::Mode::Whole(keep)).run()
}

/// Read the one block that starts at `start` again (see `Blocks::get`).
pub(crate) fn one_block(text: &str, options: ReadOptions, start: BlockStart) -> Block {
    Reader::new(text, options, reader::Mode::One).read_again(start)
}

/// Read the blocks that start at `starts` again, with one reader (see `Blocks::read`).
pub(crate) fn blocks_again(text: &str, options: ReadOptions, starts: &[BlockStart]) -> Vec<Block> {
    let mut r = Reader::new(text, options, reader::Mode::One);
    starts.iter().map(|&start| r.read_again(start)).collect()
}

/// Spans hold byte offsets as `u32` (a million-line program holds millions of them), so a
/// longer text is refused here rather than given wrong places.
fn check_length(len: usize) -> Result<(), ParseError> {
    if u32::try_from(len).is_ok() {
        return Ok(());
    }
    Err(ParseError::new(
        Span {
            line: 1,
            column: 1,
            offset: 0,
            len: 0,
        },
        format!("the program text is {len} bytes, more than the reader takes (4 GiB)"),
        "split the program into files of at most 4 GiB",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_text_over_4_gib_is_refused_not_misplaced() {
        assert!(check_length(u32::MAX as usize).is_ok());
        let e = check_length(u32::MAX as usize + 1).unwrap_err();
        assert!(e.message.contains("4294967296 bytes"), "{}", e.message);
        assert_eq!((e.span.line, e.span.column), (1, 1));
    }
}
