//! One block as read: its words, its sequence number and where it stands, and the notes
//! and `M98` comments the reader keeps beside the blocks. Plain data: no reading here.

use crate::Span;

/// An address letter with its number, e.g. `X100.` or `G75.1`.
#[derive(Debug, Clone, PartialEq)]
pub struct Word {
    /// Upper-case address letter; lower-case `c`, `r`, `a` stand for the comma addresses
    /// `,C` `,R` `,A` of direct drawing dimensions (spec/dialects.md §6.5), so that no code
    /// looking for `C` (an axis) or `R` finds them. [`address`] writes either as read.
    pub letter: char,
    /// The value as written (calculator type: `X100` is 100.0).
    pub value: f64,
    /// Whether a decimal point was written (`X100.` yes, `P1500` no). Increment-unit
    /// words (G74/G75 P/Q) must not have one.
    pub has_point: bool,
    /// Where the word stands (letter through last digit).
    pub span: Span,
    /// The value written as a custom macro B expression (`X#1`, `Z[#2-0.5]`); the
    /// interpreter evaluates it before the block runs (`value` is 0 until then). Boxed:
    /// most words have none, and a million-line program holds millions of words.
    pub expr: Option<Box<macro_b::Expr>>,
}

/// An address as written: `X`, or `,C` for the comma address stored as `c`.
pub fn address(letter: char) -> String {
    if letter.is_ascii_lowercase() {
        format!(",{}", letter.to_ascii_uppercase())
    } else {
        letter.to_string()
    }
}

impl Word {
    /// The value of a G or M code in tenths, so `G75.1` is 751 and `G01` is 10.
    /// `None` when the number has more than one decimal or is out of range.
    pub fn code_tenths(&self) -> Option<i32> {
        let t = self.value * 10.0;
        let r = t.round();
        ((t - r).abs() < 1e-6 && r.abs() < 1e7).then_some(r as i32)
    }
}

/// One block: the words between two end-of-block characters.
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    /// Words in the order written, without the N word and comments.
    pub words: Box<[Word]>,
    /// The sequence number (`N14`), if any.
    pub seq: Option<u32>,
    /// Span of the N word, if any.
    pub seq_span: Option<Span>,
    /// `/` block delete was written at the start.
    pub block_delete: bool,
    /// The block delete level: 1 for `/` and `/1`, n for `/n` (1–9); 0 without `/`.
    pub delete_level: u8,
    /// The whole block's text span (first to last significant character).
    pub span: Span,
    /// A custom macro B statement (`#1 = 2`, `IF […] GOTO 5`, `WHILE […] DO1`, `END1`,
    /// `GOTO 5`): the block then has no words, except Haas `IF [cond] THEN <NC block>`,
    /// whose NC block's words are the block's words. Boxed, as [`Word::expr`].
    pub stmt: Option<Box<macro_b::Stmt>>,
}

impl Block {
    /// The first word with this letter.
    pub fn get(&self, letter: char) -> Option<&Word> {
        self.words.iter().find(|w| w.letter == letter)
    }
    /// Whether a word with this letter is present.
    pub fn has(&self, letter: char) -> bool {
        self.get(letter).is_some()
    }
    /// Whether the block holds one of these M codes, written without a decimal point.
    pub fn has_m(&self, codes: &[f64]) -> bool {
        has_m(&self.words, codes)
    }
    /// Whether the block ends the program: it holds M02 or M30.
    pub fn ends_program(&self) -> bool {
        self.has_m(&END_CODES)
    }
    /// Whether the block holds macro B: a statement, or a word written with an expression.
    pub fn has_macro(&self) -> bool {
        self.stmt.is_some() || self.words.iter().any(|w| w.expr.is_some())
    }
    /// Move the spans [`crate::Program::shift_spans`] moves.
    pub(crate) fn shift_spans(&mut self, by: u32) {
        self.span.offset += by;
        if let Some(s) = &mut self.seq_span {
            s.offset += by;
        }
        for w in &mut *self.words {
            w.span.offset += by;
            if let Some(e) = &mut w.expr {
                e.shift_spans(by);
            }
        }
        if let Some(s) = &mut self.stmt {
            s.shift_spans(by);
        }
    }
}

/// Whether `words` hold one of these M codes, written without a decimal point.
pub(crate) fn has_m(words: &[Word], codes: &[f64]) -> bool {
    words
        .iter()
        .any(|w| w.letter == 'M' && !w.has_point && codes.contains(&w.value))
}

/// The M codes that end the program ([`Block::ends_program`]).
pub(crate) const END_CODES: [f64; 2] = [2.0, 30.0];

/// A comment written after `M98` (see [`crate::Subprogram::call_texts`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CallText {
    /// Index of the block in its O program.
    pub block: usize,
    /// The text between the parentheses, trimmed.
    pub text: String,
    /// Where the comment stands, parentheses included.
    pub span: Span,
}

/// A note the reader made while accepting something unusual.
#[derive(Debug, Clone, PartialEq)]
pub struct Note {
    /// Where.
    pub span: Span,
    /// What was assumed.
    pub message: String,
}
