//! The parsed program: O programs made of blocks made of words.

use std::borrow::Cow;
use std::sync::Arc;

use crate::parse::{read_block, read_blocks, ReadOptions};
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
    /// Move the spans [`Program::shift_spans`] moves.
    fn shift_spans(&mut self, by: u32) {
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

/// One program (`O1234` up to the next `O` or the end of the tape).
#[derive(Debug, Clone, PartialEq)]
pub struct Subprogram {
    /// The O number, `None` for blocks before any O word.
    pub number: Option<u32>,
    /// Span of the O word.
    pub span: Span,
    /// The blocks.
    pub blocks: Blocks,
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

/// The blocks of one O program. As read, they are not held: each block is read again from
/// the program text where it is needed ([`Blocks::get`]), so a million-line program costs
/// 20 bytes a block instead of its words (~200 bytes a line), the largest part of a big
/// run's peak (issue 16). A working copy whose words are changed (macro B values) holds
/// its blocks ([`Blocks::make_mut`]).
#[derive(Clone, Default)]
pub struct Blocks(Repr);

#[derive(Clone)]
enum Repr {
    Held(Vec<Block>),
    Read(Reread),
}

impl Default for Repr {
    fn default() -> Self {
        Self::Held(vec![])
    }
}

/// Blocks read again from the text: where each one starts.
#[derive(Clone)]
struct Reread {
    text: Arc<str>,
    options: ReadOptions,
    /// Added to every span's offset (see [`Program::shift_spans`]).
    shift: u32,
    starts: Vec<BlockStart>,
    /// Some block holds macro B (see [`Block::has_macro`]).
    macros: bool,
}

impl Reread {
    /// A block read again, with its spans where [`Program::shift_spans`] put the blocks.
    fn shifted(&self, mut b: Block) -> Block {
        if self.shift != 0 {
            b.shift_spans(self.shift);
        }
        b
    }
}

/// Where a block's first character stands, and what is asked of a block without reading
/// it again: its N number, whether `/` was written, whether it ends the program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BlockStart {
    pub(crate) offset: u32,
    pub(crate) line: u32,
    pub(crate) column: u32,
    /// The N number (0: none; `N0` is refused).
    pub(crate) seq: u32,
    /// [`BlockStart::DELETE`] and [`BlockStart::ENDS`].
    pub(crate) flags: u8,
}

impl BlockStart {
    /// Written with `/` (block delete).
    pub(crate) const DELETE: u8 = 1;
    /// Holds M02 or M30 ([`Block::ends_program`]).
    pub(crate) const ENDS: u8 = 2;
}

impl Blocks {
    /// Blocks to be read again from `text`, filled by the reader ([`Blocks::push_start`]).
    pub(crate) fn reread(text: Arc<str>, options: ReadOptions) -> Self {
        Self(Repr::Read(Reread {
            text,
            options,
            shift: 0,
            starts: vec![],
            macros: false,
        }))
    }

    /// Record the next block of blocks read again (reader only); `macros`: it holds macro B.
    pub(crate) fn push_start(&mut self, start: BlockStart, macros: bool) {
        debug_assert!(
            matches!(self.0, Repr::Read(_)),
            "held blocks are pushed whole"
        );
        if let Repr::Read(r) = &mut self.0 {
            r.macros |= macros;
            r.starts.push(start);
        }
    }

    /// Free the spare capacity once reading is done.
    pub(crate) fn shrink(&mut self) {
        match &mut self.0 {
            Repr::Read(r) => r.starts.shrink_to_fit(),
            Repr::Held(v) => v.shrink_to_fit(),
        }
    }

    /// Number of blocks.
    pub fn len(&self) -> usize {
        match &self.0 {
            Repr::Held(v) => v.len(),
            Repr::Read(r) => r.starts.len(),
        }
    }

    /// No blocks.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Block `i`: borrowed when held, else read again from the text (the first reading
    /// accepted it, and a block reads the same wherever the reading starts).
    pub fn get(&self, i: usize) -> Option<Cow<'_, Block>> {
        match &self.0 {
            Repr::Held(v) => v.get(i).map(Cow::Borrowed),
            Repr::Read(r) => {
                let start = *r.starts.get(i)?;
                Some(Cow::Owned(r.shifted(read_block(&r.text, r.options, start))))
            }
        }
    }

    /// Block `i`, which must exist (as slice indexing).
    pub fn at(&self, i: usize) -> Cow<'_, Block> {
        let n = self.len();
        self.get(i)
            .unwrap_or_else(|| panic!("block {i} of a program of {n} blocks"))
    }

    /// The first block.
    pub fn first(&self) -> Option<Cow<'_, Block>> {
        self.get(0)
    }

    /// The last block.
    pub fn last(&self) -> Option<Cow<'_, Block>> {
        self.len().checked_sub(1).and_then(|i| self.get(i))
    }

    /// The blocks in order.
    pub fn iter(&self) -> impl DoubleEndedIterator<Item = Cow<'_, Block>> + '_ {
        (0..self.len()).map(|i| self.at(i))
    }

    /// Blocks `range` in order.
    pub fn range(
        &self,
        range: std::ops::Range<usize>,
    ) -> impl DoubleEndedIterator<Item = Cow<'_, Block>> + '_ {
        range.map(|i| self.at(i))
    }

    /// Blocks `range`, held: read again with one reader where they are read again (a
    /// reader for each block was a tenth of reading a million).
    pub fn read(&self, range: std::ops::Range<usize>) -> Vec<Block> {
        match &self.0 {
            Repr::Held(v) => v[range].to_vec(),
            Repr::Read(r) => read_blocks(&r.text, r.options, &r.starts[range])
                .into_iter()
                .map(|b| r.shifted(b))
                .collect(),
        }
    }

    /// All blocks, held (tests and small programs).
    pub fn all(&self) -> Vec<Block> {
        self.iter().map(Cow::into_owned).collect()
    }

    /// The N number of block `i`, without reading it again.
    pub fn seq(&self, i: usize) -> Option<u32> {
        match &self.0 {
            Repr::Held(v) => v.get(i)?.seq,
            Repr::Read(r) => Some(r.starts.get(i)?.seq).filter(|&n| n != 0),
        }
    }

    /// Whether block `i` was written with `/` (block delete), without reading it again.
    pub fn block_delete(&self, i: usize) -> bool {
        match &self.0 {
            Repr::Held(v) => v.get(i).is_some_and(|b| b.block_delete),
            Repr::Read(r) => r
                .starts
                .get(i)
                .is_some_and(|s| s.flags & BlockStart::DELETE != 0),
        }
    }

    /// Whether block `i` ends the program ([`Block::ends_program`]), without reading it again.
    pub fn ends_program(&self, i: usize) -> bool {
        match &self.0 {
            Repr::Held(v) => v.get(i).is_some_and(Block::ends_program),
            Repr::Read(r) => r
                .starts
                .get(i)
                .is_some_and(|s| s.flags & BlockStart::ENDS != 0),
        }
    }

    /// Indices of the blocks numbered `n`, in order, without reading them again.
    pub fn positions_seq(&self, n: u32) -> impl Iterator<Item = usize> + '_ {
        (0..self.len()).filter(move |&i| self.seq(i) == Some(n))
    }

    /// Whether each block is read again from the text where it is needed (else held).
    pub fn reads_again(&self) -> bool {
        matches!(self.0, Repr::Read(_))
    }

    /// Whether some block holds macro B ([`Block::has_macro`]), without reading them again.
    pub fn has_macro(&self) -> bool {
        match &self.0 {
            Repr::Held(v) => v.iter().any(Block::has_macro),
            Repr::Read(r) => r.macros,
        }
    }

    /// The blocks, held, to change their words: read once from the text the first time.
    pub fn make_mut(&mut self) -> &mut Vec<Block> {
        if let Repr::Read(_) = self.0 {
            self.0 = Repr::Held(self.all());
        }
        match &mut self.0 {
            Repr::Held(v) => v,
            Repr::Read(_) => unreachable!("made held above"),
        }
    }

    fn shift_spans(&mut self, by: u32) {
        match &mut self.0 {
            Repr::Held(v) => v.iter_mut().for_each(|b| b.shift_spans(by)),
            Repr::Read(r) => r.shift += by,
        }
    }
}

impl From<Vec<Block>> for Blocks {
    fn from(v: Vec<Block>) -> Self {
        Self(Repr::Held(v))
    }
}

/// Blocks are equal when they read the same, held or not.
impl PartialEq for Blocks {
    fn eq(&self, other: &Self) -> bool {
        self.len() == other.len() && self.iter().eq(other.iter())
    }
}

impl std::fmt::Debug for Blocks {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
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
            p.blocks.shift_spans(by);
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
