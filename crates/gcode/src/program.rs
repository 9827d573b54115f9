//! The parsed program: O programs made of blocks made of words.

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
        self.words
            .iter()
            .any(|w| w.letter == 'M' && !w.has_point && codes.contains(&w.value))
    }
    /// Whether the block holds macro B: a statement, or a word written with an expression.
    pub fn has_macro(&self) -> bool {
        self.stmt.is_some() || self.words.iter().any(|w| w.expr.is_some())
    }
}

/// One program (`O1234` up to the next `O` or the end of the tape).
#[derive(Debug, Clone, PartialEq)]
pub struct Subprogram {
    /// The O number, `None` for blocks before any O word.
    pub number: Option<u32>,
    /// Span of the O word.
    pub span: Span,
    /// The blocks.
    pub blocks: Vec<Block>,
    /// The first comment after `M98` in a block, for those blocks only, by block index
    /// (ascending): Haas `M98 (path/O00001.nc)` calls the file the comment names. A side
    /// table, so the blocks of a million-line program do not each carry comment text.
    pub call_texts: Vec<CallText>,
}

impl Subprogram {
    /// The comment after `M98` in block `block`, if it has one.
    pub fn call_text(&self, block: usize) -> Option<&CallText> {
        self.call_texts
            .binary_search_by_key(&block, |c| c.block)
            .ok()
            .map(|k| &self.call_texts[k])
    }
}

/// A comment written after `M98` (see [`Subprogram::call_texts`]).
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

/// A whole file: the main program first, then any further O programs (subprograms).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Program {
    /// Main program first.
    pub programs: Vec<Subprogram>,
    /// Things accepted with an assumption (shown as warnings in the report).
    pub notes: Vec<Note>,
}

impl Program {
    /// The main program: the first one in the file.
    pub fn main(&self) -> Option<&Subprogram> {
        self.programs.first()
    }
    /// Find an O program by number.
    pub fn find(&self, number: u32) -> Option<&Subprogram> {
        self.programs.iter().find(|p| p.number == Some(number))
    }
    /// Move every span's byte offset by `by` (lines and columns stay): a caller that reads
    /// several files (subprograms in `--lib` folders) gives each file a byte range of its own
    /// and finds the file of a span by its offset. The caller keeps the shifted offsets
    /// within `u32` (see [`Span`]).
    pub fn shift_spans(&mut self, by: u32) {
        let shift = |s: &mut Span| s.offset += by;
        for p in &mut self.programs {
            shift(&mut p.span);
            for c in &mut p.call_texts {
                shift(&mut c.span);
            }
            for b in &mut p.blocks {
                shift(&mut b.span);
                if let Some(s) = &mut b.seq_span {
                    shift(s);
                }
                for w in &mut b.words {
                    shift(&mut w.span);
                }
            }
        }
        for n in &mut self.notes {
            shift(&mut n.span);
        }
    }

    /// Number of blocks in all programs.
    pub fn block_count(&self) -> usize {
        self.programs.iter().map(|p| p.blocks.len()).sum()
    }
}
