//! The parsed program: O programs made of blocks made of words.

use std::borrow::Cow;
use std::sync::Arc;

use crate::read::{blocks_again, one_block, BlockStart, ReadBlocks, ReadOptions, Reading};
use crate::{Block, CallText, Note, Span};

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

impl Blocks {
    /// Blocks to be read again from `text`, where the reader found them to start;
    /// `macros`: some block holds macro B.
    fn reread(text: Arc<str>, options: ReadOptions, starts: Vec<BlockStart>, macros: bool) -> Self {
        Self(Repr::Read(Reread {
            text,
            options,
            shift: 0,
            starts,
            macros,
        }))
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
                Some(Cow::Owned(r.shifted(one_block(&r.text, r.options, start))))
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
            Repr::Read(r) => blocks_again(&r.text, r.options, &r.starts[range])
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

/// A whole file: its O programs in the file's order, the main one ([`Program::main`]) and
/// subprograms.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Program {
    /// In the file's order; the main program is usually the first ([`Program::main`]).
    pub programs: Vec<Subprogram>,
    /// Things accepted with an assumption (shown as warnings in the report).
    pub notes: Vec<Note>,
}

impl Program {
    /// The main program: the first one in the file ([`Program::main_index`]).
    pub fn main(&self) -> Option<&Subprogram> {
        self.programs.get(self.main_index())
    }

    /// Which program is the main one: the first in the file, unless another program of the
    /// file calls it (`M98`, `M198`, `G65` with its number): a FANUC punch-out lists the
    /// programs in number order, so subprograms may come first (field run 10, B2: O3102 ran
    /// as the main program and crashed where O3101 called it after its own turning); then
    /// the first program no other one calls (a chain of subprograms listed first, a main
    /// program that ends with M99 for a bar feeder: review 1128h, #2).
    pub fn main_index(&self) -> usize {
        if self.programs.len() < 2 {
            return 0;
        }
        let calls: Vec<Vec<u32>> = self.programs.iter().map(calls_in).collect();
        let uncalled = |k: usize| {
            self.programs[k].number.is_none_or(|n| {
                // a call from another program (a program calling itself is a loop)
                !calls
                    .iter()
                    .enumerate()
                    .any(|(j, c)| j != k && c.contains(&n))
            })
        };
        if uncalled(0) {
            return 0;
        }
        (1..self.programs.len()).find(|&k| uncalled(k)).unwrap_or(0)
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

    /// The program a reading of `text` found: blocks kept where they start are read again
    /// from `text` where they are needed.
    pub(crate) fn from_reading(reading: Reading, text: &Arc<str>, options: ReadOptions) -> Self {
        let programs = reading
            .programs
            .into_iter()
            .map(|p| Subprogram {
                number: p.number,
                span: p.span,
                blocks: match p.blocks {
                    ReadBlocks::Starts(starts, macros) => {
                        Blocks::reread(Arc::clone(text), options, starts, macros)
                    }
                    ReadBlocks::Held(blocks) => Blocks::from(blocks),
                },
                call_texts: p.call_texts,
            })
            .collect();
        Self {
            programs,
            notes: reading.notes,
        }
    }

    /// Number of blocks in all programs.
    pub fn block_count(&self) -> usize {
        self.programs.iter().map(|p| p.blocks.len()).sum()
    }
}

/// The program numbers the blocks of `p` may call: `M98 P`, `M198 P` or `G65 P`, as
/// written (Haas' five digits) and as FANUC's packed count and number (`M98 P30020`, three
/// times O0020).
fn calls_in(p: &Subprogram) -> Vec<u32> {
    p.blocks
        .iter()
        .filter(|b| {
            b.has_m(&[98.0, 198.0]) || b.words.iter().any(|w| w.letter == 'G' && w.value == 65.0)
        })
        .filter_map(|b| {
            let v = b.get('P')?.value;
            (v.fract() == 0.0 && (0.0..1e9).contains(&v)).then_some(v as u32)
        })
        .flat_map(|v| [v, v % 10_000])
        .collect()
}

#[cfg(test)]
mod tests {
    /// The main program is the first, unless the first ends with M99 and a later program
    /// that ends with M30 calls it (a punch-out in number order, field run 10, B2).
    #[test]
    fn a_subprogram_listed_first_is_not_the_main_program() {
        let main = |src: &str| {
            let p = crate::parse(src).unwrap();
            (p.main_index(), p.main().and_then(|m| m.number))
        };
        let sub = "O0020\nG00 X36. Z-38.\nU2. W-1.\nM99\n";
        let caller = "O0010\nG00 X44. Z2.\nM98 P0020\nM30\n";
        assert_eq!(main(&format!("{sub}{caller}")), (1, Some(10)));
        assert_eq!(main(&format!("{caller}{sub}")), (0, Some(10)));
        // FANUC's packed count and number (three times O0020), and G65
        assert_eq!(
            main(&format!("{sub}O0010\nM98 P30020\nM30\n")),
            (1, Some(10))
        );
        assert_eq!(main(&format!("{sub}O0010\nG65 P20\nM30\n")), (1, Some(10)));
        // a first program that nothing calls stays the main one
        assert_eq!(main(&format!("{sub}O0010\nM98 P30\nM30\n")), (0, Some(20)));
        assert_eq!(
            main("O0020\nG00 X1\nM30\nO0030\nG00 X2\nM99\n"),
            (0, Some(20))
        );
        // a main program that ends with M99 (a bar feeder's loop), and a chain of
        // subprograms listed first (review 1128h, #2)
        assert_eq!(main(&format!("{sub}O0010\nM98 P20\nM99\n")), (1, Some(10)));
        let chain = "O0001\nG00 X1\nM99\nO0002\nM98 P1\nM99\nO0100\nM98 P2\nM30\n";
        assert_eq!(main(chain), (2, Some(100)));
        // Haas' five-digit numbers
        assert_eq!(
            main("O12345\nG00 X1\nM99\nO00010\nM98 P12345\nM30\n"),
            (1, Some(10))
        );
    }
}
