//! Blocks: where one starts (the plain fast path, block delete `/`), where it ends, and what
//! is kept of it — the block itself, or where it starts, to read it again.

use super::{Mode, Reader};
use crate::block::{has_m, END_CODES};
use crate::read::reading::{BlockStart, Keep, ParseError, ReadBlocks};
use crate::read::{plain, radius};
use crate::{Block, CallText, Span, Word};

impl Reader<'_> {
    /// The block reaches `span` (and starts there if nothing of it was read yet).
    pub(super) fn mark(&mut self, span: Span) {
        if self.block_start.is_none() {
            self.block_start = Some(span);
        }
        self.block_end = span;
    }

    /// Nothing of the current block read yet.
    pub(super) fn block_is_empty(&self) -> bool {
        self.pending.is_none() && self.words.is_empty() && self.seq.is_none() && !self.block_delete
    }

    /// Nothing but an N word (or `/`) read of the current block: a macro statement may
    /// start here.
    pub(super) fn at_statement_start(&self) -> bool {
        self.words.is_empty()
            && self.stmt.is_none()
            && self.pending.as_ref().is_none_or(|p| p.letter == 'N')
    }

    /// A `/` (not `//`): block delete, at the start of a block or right after its N word
    /// (`N20 /X…`), with its level `/1`–`/9`.
    pub(super) fn slash(&mut self, span: Span) -> Result<(), ParseError> {
        if self.pending.as_ref().is_some_and(|p| p.letter == 'N') {
            self.finish_word()?;
        }
        if self.pending.is_some() || !self.words.is_empty() || self.block_delete {
            return Err(ParseError::new(
                span,
                "'/' in the middle of a block",
                "block delete '/' must be the first character of a block (or follow its N word)",
            ));
        }
        self.block_delete = true;
        self.delete_level = 1;
        if let Some(level) = self.peek().and_then(|c| c.to_digit(10)).filter(|&d| d >= 1) {
            self.next();
            self.delete_level = level as u8;
        }
        self.mark(span);
        Ok(())
    }

    /// The end of a block: its last word finished, X read as a radius doubled, the block
    /// kept, and the reader ready for the next one.
    pub(super) fn end_block(&mut self) -> Result<(), ParseError> {
        self.finish_word()?;
        if self.options.x_radius {
            radius::to_diameter(&mut self.words)?;
        }
        if let Some(start) = self.block_start.take() {
            self.keep_block(start);
        }
        self.words.clear();
        self.seq = None;
        self.block_delete = false;
        self.delete_level = 0;
        self.stmt = None;
        self.call_text = None;
        self.at_block_start = true;
        Ok(())
    }

    /// Keep the block that started at `start`, if it holds anything: as the block found
    /// ([`Mode::One`]), or in the program being read as [`Keep`] says.
    fn keep_block(&mut self, start: Span) {
        let seq = self.seq.take();
        let block_delete = std::mem::replace(&mut self.block_delete, false);
        let delete_level = std::mem::replace(&mut self.delete_level, 0);
        let stmt = self.stmt.take();
        let call_text = self.call_text.take();
        if self.words.is_empty() && seq.is_none() && stmt.is_none() {
            return;
        }
        let has_stmt = stmt.is_some();
        let span = start.to(self.block_end);
        let block = move |words: &[Word]| Block {
            // exactly as long as needed, and no capacity word
            words: words.into(),
            seq: seq.map(|s| s.0),
            seq_span: seq.map(|s| s.1),
            block_delete,
            delete_level,
            span,
            stmt: stmt.map(Box::new),
        };
        let Mode::Whole(_) = self.mode else {
            self.found = Some(block(&self.words));
            return;
        };
        let sub = self
            .reading
            .programs
            .last_mut()
            .expect("always one program");
        if let Some((text, span)) = call_text {
            sub.call_texts.push(CallText {
                block: sub.blocks.len(),
                text,
                span,
            });
        }
        match &mut sub.blocks {
            ReadBlocks::Starts(starts, macros) => {
                let flags = if block_delete { BlockStart::DELETE } else { 0 }
                    | if has_m(&self.words, &END_CODES) {
                        BlockStart::ENDS
                    } else {
                        0
                    };
                starts.push(BlockStart {
                    offset: start.offset,
                    line: start.line,
                    column: start.column,
                    seq: seq.map_or(0, |s| s.0),
                    flags,
                });
                *macros |= has_stmt || self.words.iter().any(|w| w.expr.is_some());
            }
            ReadBlocks::Held(blocks) => blocks.push(block(&self.words)),
        }
    }

    /// The block that starts at `start`, read again ([`Mode::One`]); the reader is as new
    /// for it, whatever it read before.
    pub(in crate::read) fn read_again(&mut self, start: BlockStart) -> Block {
        self.pos = start.offset as usize;
        self.line = start.line;
        self.column = start.column - 1;
        self.no_prose_before = 0;
        self.at_block_start = true;
        self.reading.notes.clear();
        match (self.read(), self.found.take()) {
            (Ok(()), Some(b)) => b,
            (read, _) => panic!(
                "the block at line {}, column {} read differently the second time: {read:?}",
                start.line, start.column
            ),
        }
    }

    /// At the start of a block: read it in one go if it is plain ([`plain`]), leaving the
    /// reader at its end for the loop to end the block; else leave it whole to the loop.
    /// The reference reading ([`Keep::Held`]) reads every block with the loop.
    pub(super) fn read_plain_block(&mut self) {
        if matches!(self.mode, Mode::Whole(Keep::Held)) {
            return;
        }
        let macros = self.options.macros.is_some();
        let read = plain::read(
            self.src,
            self.pos,
            self.line,
            self.column,
            macros,
            &mut self.words,
        );
        let Some(read) = read else {
            self.words.clear();
            return;
        };
        self.column += (read.end - self.pos) as u32;
        self.pos = read.end;
        if read.seq.is_some() {
            self.seq = read.seq;
        }
        if let Some(first) = read.first {
            self.block_start.get_or_insert(first);
        }
        if let Some(last) = read.last {
            self.block_end = last;
        }
    }
}
