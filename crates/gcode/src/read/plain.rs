//! The fast path: a plain block — address letters with numbers, spaces between — read in
//! one go (most blocks of a CAM program are plain, and the character loop was a third of a
//! run). A block with anything else (a comment, `/`, `,`, `O`, a macro expression, a
//! number in pieces, an error) is left whole to the character loop. The reference reading
//! (`Keep::Held`) reads every block with the loop, so that the tests compare the two.

use super::number::plain_number;
use crate::{Span, Word};

/// A plain block read: where it ends (its `\n`, `;` or the end of the text, for the loop
/// to end the block), its N word, and its first and last characters (`None`: no word).
pub(super) struct Plain {
    pub(super) end: usize,
    pub(super) seq: Option<(u32, Span)>,
    pub(super) first: Option<Span>,
    pub(super) last: Option<Span>,
}

/// Read the plain block that starts at byte `base` (on `line`, after column `base_column`)
/// into `words`; `None` where the block is not plain (`words` then holds a part: clear it).
/// `macros`: custom macro B is on, so a block starting with a statement is not plain.
#[inline]
pub(super) fn read(
    src: &str,
    base: usize,
    line: u32,
    base_column: u32,
    macros: bool,
    words: &mut Vec<Word>,
) -> Option<Plain> {
    let bytes = src.as_bytes();
    // every byte read is ASCII: one column each
    let span_at = |i: usize| Span {
        line,
        column: base_column + (i - base) as u32 + 1,
        offset: i as u32,
        len: 1,
    };
    let mut read = Plain {
        end: base,
        seq: None,
        first: None,
        last: None,
    };
    let mut i = base;
    loop {
        while matches!(bytes.get(i), Some(b' ' | b'\t')) {
            i += 1;
        }
        let Some(&b) = bytes.get(i) else { break };
        match b {
            b'\n' | b';' => break,
            b'\r' if bytes.get(i + 1) == Some(&b'\n') => {
                i += 1;
                break;
            }
            b'O' | b'o' => return None,
            b if b.is_ascii_alphabetic() => {}
            _ => return None,
        }
        if macros && words.is_empty() && macro_b::starts_statement(&src[i..]) {
            return None;
        }
        let letter = char::from(b.to_ascii_uppercase());
        let start = i + 1;
        let (len, value, has_point) = plain_number(&bytes[start..])?;
        let end = start + len;
        let first = span_at(i);
        let last = span_at(end - 1);
        let span = first.to(last);
        if letter == 'N' {
            if read.seq.is_some() || has_point || !(1.0..=99_999_999.0).contains(&value) {
                return None;
            }
            read.seq = Some((value as u32, span));
        } else {
            if letter != 'G' && letter != 'M' && words.iter().any(|w| w.letter == letter) {
                return None;
            }
            words.push(Word {
                letter,
                value,
                has_point,
                span,
                expr: None,
            });
        }
        read.first.get_or_insert(first);
        read.last = Some(last);
        i = end;
    }
    read.end = i;
    Some(read)
}
