//! The character loop: one pass over the text, tracking line and column, each character
//! handed to the stage it belongs to — the block and its end ([`block`]), words and numbers
//! ([`word`]), the tape and what is not code ([`frame`]), macro B ([`statement`]).

mod block;
mod frame;
mod statement;
mod word;

use super::reading::{Keep, ParseError, ReadBlocks, ReadOptions, ReadProgram, Reading};
use super::tape::control_kind;
use crate::{Block, Note, Span, Word};
use macro_b::Stmt;

/// What the reader does with the text.
pub(super) enum Mode {
    /// Read it all, keeping each block as [`Keep`] says.
    Whole(Keep),
    /// Read one block again and stop after it ([`super::one_block`]).
    One,
}

/// A word being read: its letter, and its number so far.
struct PendingWord {
    letter: char,
    start: Span,
    end: Span,
    /// The number as a byte range of the source, while it is written in one piece.
    text: std::ops::Range<usize>,
    /// The number is in [`Reader::number`] instead (written in pieces, or a decimal comma).
    copied: bool,
}

impl PendingWord {
    fn new(letter: char, at: Span) -> Self {
        Self {
            letter,
            start: at,
            end: at,
            text: 0..0,
            copied: false,
        }
    }
}

/// After a character: read on, or the block asked for ([`Mode::One`]) is found.
#[derive(PartialEq, Eq)]
enum Step {
    Go,
    Found,
}

pub(super) struct Reader<'a> {
    src: &'a str,
    options: ReadOptions,
    mode: Mode,
    /// The block read in [`Mode::One`].
    found: Option<Block>,
    /// Byte offset of the next character.
    pos: usize,
    line: u32,
    column: u32,
    /// What is read (in [`Mode::One`] no program: only notes, dropped).
    reading: Reading,
    words: Vec<Word>,
    seq: Option<(u32, Span)>,
    block_delete: bool,
    block_start: Option<Span>,
    block_end: Span,
    pending: Option<PendingWord>,
    /// The number of the pending word when it is not one slice of the source.
    number: String,
    /// A `;` before this offset needs no prose test: it is on a line whose rest after an
    /// earlier `;` was no prose and held no `(`, and so is every later part of it.
    no_prose_before: usize,
    delete_level: u8,
    /// Flow-control bytes dropped, and the first one's place.
    flow_control: (usize, Span),
    /// Other unexpected control bytes dropped, and the first one's place.
    unexpected_control: (usize, Span),
    /// The macro statement of the current block.
    stmt: Option<Stmt>,
    /// The first comment after an `M98` of the current block (Haas `M98 (path)`).
    call_text: Option<(String, Span)>,
    /// The next character starts a block: [`Reader::read_plain_block`] may read it.
    at_block_start: bool,
}

impl<'a> Reader<'a> {
    pub(super) fn new(src: &'a str, options: ReadOptions, mode: Mode) -> Self {
        // reading one block again keeps no program (nor allocates one)
        let programs = match mode {
            Mode::One => vec![],
            Mode::Whole(keep) => vec![ReadProgram::new(None, Span::default(), keep)],
        };
        Self {
            src,
            options,
            mode,
            found: None,
            pos: 0,
            line: 1,
            column: 0,
            reading: Reading {
                programs,
                notes: vec![],
            },
            words: vec![],
            seq: None,
            block_delete: false,
            block_start: None,
            block_end: Span::default(),
            pending: None,
            number: String::new(),
            no_prose_before: 0,
            delete_level: 0,
            flow_control: (0, Span::default()),
            unexpected_control: (0, Span::default()),
            stmt: None,
            call_text: None,
            at_block_start: true,
        }
    }

    /// Read the whole text.
    pub(super) fn run(mut self) -> Result<Reading, ParseError> {
        self.skip_leader();
        self.read()?;
        self.control_notes();
        self.reading
            .programs
            .retain(|p| p.number.is_some() || !p.blocks.is_empty());
        for p in &mut self.reading.programs {
            p.blocks.shrink();
        }
        Ok(self.reading)
    }

    /// Byte offset of the next character.
    fn offset(&self) -> usize {
        self.pos
    }

    /// The rest of the current line, not consumed.
    fn rest_of_line(&self) -> &'a str {
        let start = self.offset();
        let rest = &self.src[start..];
        let end = rest.bytes().position(|b| b == b'\n');
        &rest[..end.unwrap_or(rest.len())]
    }

    fn note(&mut self, span: Span, message: impl Into<String>) {
        self.reading.notes.push(Note {
            span,
            message: message.into(),
        });
    }

    #[inline]
    fn next(&mut self) -> Option<(Span, char)> {
        let c = self.peek()?;
        let offset = self.pos;
        self.pos += c.len_utf8();
        self.column += 1;
        // the text is at most u32::MAX bytes (`check_length`)
        let span = Span {
            line: self.line,
            column: self.column,
            offset: offset as u32,
            len: c.len_utf8() as u32,
        };
        if c == '\n' {
            self.line += 1;
            self.column = 0;
        }
        Some((span, c))
    }

    #[inline]
    fn peek(&self) -> Option<char> {
        let &b = self.src.as_bytes().get(self.pos)?;
        if b.is_ascii() {
            Some(char::from(b))
        } else {
            self.src[self.pos..].chars().next()
        }
    }

    /// Read to the end of the text (in [`Mode::One`], to the end of the first block).
    fn read(&mut self) -> Result<(), ParseError> {
        loop {
            if std::mem::take(&mut self.at_block_start) && self.found.is_none() {
                self.read_plain_block();
            }
            let Some((span, c)) = self.next() else { break };
            if self.found.is_some() {
                return Ok(());
            }
            if let Some(kind) = control_kind(c) {
                self.control(kind, span);
                continue;
            }
            if self.character(span, c)? == Step::Found {
                return Ok(());
            }
        }
        self.end_block()
    }

    /// One character (not a dropped control byte), handed to the stage it belongs to.
    #[inline(always)]
    fn character(&mut self, span: Span, c: char) -> Result<Step, ParseError> {
        match c {
            '\n' => self.end_block()?,
            // a lone CR (EIA end of block, old Mac files) ends a block like LF
            '\r' if self.peek() != Some('\n') => self.end_block()?,
            ';' => return self.semicolon(span),
            ' ' | '\t' | '\r' | '\u{3000}' => {}
            '(' | '（' => self.skip_comment(span),
            ':' if self.block_is_empty() && self.peek().is_some_and(|c| c.is_ascii_digit()) => {
                self.pending = Some(PendingWord::new('O', span));
                self.mark(span);
            }
            '"' => return Err(Self::string_literal(span)),
            ',' if self.decimal_comma_follows() => self.decimal_comma(span)?,
            ',' if self.comma_address().is_some() => self.comma_word(span)?,
            '/' if self.peek() == Some('/') => {
                self.finish_word()?;
                self.skip_line();
            }
            '/' => self.slash(span)?,
            '%' => self.percent(span)?,
            c if (c == '#' || c.is_ascii_alphabetic()) && self.statement_starts(span) => {
                self.finish_word()?;
                self.statement(span)?;
            }
            '#' => return Err(self.misplaced_hash(span)),
            c if c.is_ascii_alphabetic() => {
                self.finish_word()?;
                self.start_word(c.to_ascii_uppercase(), span)?;
            }
            c if c.is_ascii_digit() || c == '.' || c == '+' || c == '-' => self.digit(span, c)?,
            c if !c.is_ascii() && !c.is_control() => self.annotation(span)?,
            c => return Err(self.unexpected(span, c)),
        }
        Ok(Step::Go)
    }
}

impl ReadProgram {
    /// A new O program (`number`: its O word, at `span`), its blocks kept as `keep` says.
    fn new(number: Option<u32>, span: Span, keep: Keep) -> Self {
        Self {
            number,
            span,
            blocks: match keep {
                Keep::Starts => ReadBlocks::Starts(vec![], false),
                Keep::Held => ReadBlocks::Held(vec![]),
            },
            call_texts: vec![],
        }
    }
}
