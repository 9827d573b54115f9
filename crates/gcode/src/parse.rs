//! The reader: one pass over the characters, tracking line and column. It walks the bytes
//! and decodes a character only where one is not ASCII; a word's number is a slice of the
//! source (copied only when written in pieces, `Q5 000`), so a million-line program costs
//! one allocation per block: its words.
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

use std::sync::Arc;

use crate::program::{BlockStart, END_CODES};
use crate::{address, Block, Blocks, Note, Program, Span, Subprogram, Word};
use macro_b::{Dialect, Func, MacroError, Stmt};

/// A reading error: where, what, and what to change.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct ParseError {
    /// Where the problem is.
    pub span: Span,
    /// What is wrong.
    pub message: String,
    /// What to change.
    pub help: String,
}

impl ParseError {
    pub(crate) fn new(span: Span, message: impl Into<String>, help: impl Into<String>) -> Self {
        Self {
            span,
            message: message.into(),
            help: help.into(),
        }
    }
}

/// Longest number text accepted; more digits than this cannot be a real coordinate.
const MAX_NUMBER_CHARS: usize = 20;
/// Most digits before the decimal point (leading zeros aside): the largest value a
/// FANUC/GSK word holds is 9 digits (99999999.9 at IS-B is already 100 km).
const MAX_WHOLE_DIGITS: usize = 9;
/// The help for numbers that are too long.
const NUMBER_HELP: &str = "a number has at most 9 digits before the point and 20 characters in all";

/// How to read numbers that a FANUC would refuse.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// Read `F0,2` as `F0.2` (German-style posts); otherwise a decimal comma is an error.
    pub decimal_comma: bool,
    /// Custom macro B (spec/dialects.md §5) with this control's rules: `#` variables,
    /// `[ ]` expressions as word values and macro statements. `None`: a `#` is an error.
    pub macros: Option<Dialect>,
    /// X is programmed as a radius (FANUC parameter DIA off, Linux CNC G8, trainers): X-axis
    /// values are doubled as they are read (`crate::radius`).
    pub x_radius: bool,
}

impl From<MacroError> for ParseError {
    fn from(e: MacroError) -> Self {
        Self::new(e.span, e.message, e.help)
    }
}

/// The help of a `#` read without custom macro B.
const NO_MACRO_HELP: &str =
    "custom macro B is on by default for --control fanuc-a, fanuc-b, fanuc-c and haas; --macro on turns it on for gsk980";

/// Read a whole program text.
pub fn parse(source: &str) -> Result<Program, ParseError> {
    parse_with(source, ReadOptions::default())
}

/// Read a whole program text with options.
pub fn parse_with(source: &str, options: ReadOptions) -> Result<Program, ParseError> {
    parse_shared(Arc::from(source), options)
}

/// Read a whole program text with options, keeping the text (shared, not copied) to read
/// its blocks again where they are needed ([`Blocks`]).
pub fn parse_shared(source: Arc<str>, options: ReadOptions) -> Result<Program, ParseError> {
    check_length(source.len())?;
    Reader::new(&source, options, Mode::Index(Arc::clone(&source))).run()
}

/// Read a whole program text holding every block: the reference the re-read blocks of
/// [`parse_with`] are compared with in tests.
#[doc(hidden)]
pub fn parse_held(source: &str, options: ReadOptions) -> Result<Program, ParseError> {
    check_length(source.len())?;
    Reader::new(source, options, Mode::Held).run()
}

/// Read the one block that starts at `start` again (see [`Blocks::get`]).
pub(crate) fn read_block(text: &str, options: ReadOptions, start: BlockStart) -> Block {
    Reader::new(text, options, Mode::One).read_again(start)
}

/// Read the blocks that start at `starts` again, with one reader (see [`Blocks::read`]).
pub(crate) fn read_blocks(text: &str, options: ReadOptions, starts: &[BlockStart]) -> Vec<Block> {
    let mut r = Reader::new(text, options, Mode::One);
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

/// Macro B words that are letters only; any other run of two letters after `;` is prose.
const KEYWORDS: [&str; 37] = [
    "IF", "GOTO", "WHILE", "WH", "DO", "END", "THEN", "ELSE", "ENDIF", "EQ", "NE", "GT", "GE",
    "LT", "LE", "AND", "OR", "XOR", "MOD", "SIN", "COS", "TAN", "ATAN", "ASIN", "ACOS", "SQRT",
    "ABS", "ROUND", "FIX", "FUP", "LN", "EXP", "POW", "ADP", "BIN", "BCD", "POPEN",
];

/// Whether the text after a `;` is prose (a comment in another control's style) rather
/// than blocks: it holds a non-ASCII character, or a run of two or more letters that is
/// not a macro keyword (in a program every letter is followed by its number).
fn is_prose(rest: &str) -> bool {
    let mut depth = 0;
    // the run of letters (a comment inside does not break it); only its first
    // `LONGEST_KEYWORD + 1` letters are kept, enough to tell a keyword from prose
    let mut run = [0u8; LONGEST_KEYWORD + 1];
    let mut len = 0;
    let prose = |run: &[u8], len: usize| {
        len >= 2
            && (len > LONGEST_KEYWORD
                || !KEYWORDS
                    .iter()
                    .any(|k| k.as_bytes().eq_ignore_ascii_case(&run[..len])))
    };
    for &b in rest.as_bytes() {
        match b {
            b'(' => depth += 1,
            b')' if depth > 0 => depth -= 1,
            _ if depth > 0 => {}
            b if !b.is_ascii() => return true,
            b if b.is_ascii_alphabetic() => {
                if len < run.len() {
                    run[len] = b;
                }
                len += 1;
            }
            _ => {
                if prose(&run, len) {
                    return true;
                }
                len = 0;
            }
        }
    }
    prose(&run, len)
}

/// The longest of [`KEYWORDS`].
const LONGEST_KEYWORD: usize = 5;

/// Whether a line holds a program number or an address word (outside comments): a letter
/// followed by a number, or `:` followed by digits.
fn has_address(line: &str) -> bool {
    let mut depth = 0;
    let mut prev: Option<char> = None;
    for c in line.chars().filter(|c| *c != ' ' && *c != '\t') {
        match c {
            '(' => depth += 1,
            ')' if depth > 0 => depth -= 1,
            _ if depth > 0 => {}
            c => {
                let numeric = c.is_ascii_digit() || matches!(c, '.' | '+' | '-');
                if numeric
                    && prev.is_some_and(|p| {
                        p.is_ascii_alphabetic() || (p == ':' && c.is_ascii_digit())
                    })
                {
                    return true;
                }
                prev = Some(c);
            }
        }
    }
    false
}

/// Where the leader ends: if a `%` comes before the first line holding a program number or
/// an address word, everything up to the end of that `%`'s line (spec/dialects.md §1).
/// A line that starts with `%` and goes on with the first block (`%O1200(TOKARKA)`, as CAM
/// systems write it) ends the leader right after that `%`: its words are the program's.
fn leader_end(src: &str) -> Option<usize> {
    let mut offset = 0;
    for line in src.split_inclusive('\n') {
        let lead = line.len()
            - line
                .trim_start_matches(|c: char| {
                    c.is_whitespace() || c.is_control() || c == '\u{feff}'
                })
                .len();
        if line[lead..].starts_with('%') && has_address(&line[lead + 1..]) {
            return Some(offset + lead + 1);
        }
        if has_address(line) {
            return None;
        }
        offset += line.len();
        if line.contains('%') {
            return Some(offset);
        }
    }
    None
}

/// A control byte's fate: dropped silently, dropped and counted as flow control, or dropped
/// with a warning.
fn control_kind(c: char) -> Option<ControlKind> {
    match c {
        '\u{11}'..='\u{14}' => Some(ControlKind::FlowControl),
        '\0' | '\u{8}' | '\u{7f}' | '\u{1b}' | '\u{1a}' | '\u{c}' | '\u{b}' | '\u{feff}' => {
            Some(ControlKind::Ignored)
        }
        c if (c as u32) < 0x20 && !matches!(c, '\n' | '\r' | '\t') => Some(ControlKind::Unexpected),
        _ => None,
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum ControlKind {
    FlowControl,
    Ignored,
    Unexpected,
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

/// What the reader does with a block it has read.
enum Mode {
    /// Record where it starts, to read it again from this text (see [`Blocks`]).
    Index(Arc<str>),
    /// Keep it.
    Held,
    /// Stop after it: reading one block again ([`read_block`]).
    One,
}

struct Reader<'a> {
    src: &'a str,
    options: ReadOptions,
    mode: Mode,
    /// The block read in [`Mode::One`].
    found: Option<Block>,
    /// Byte offset of the next character.
    pos: usize,
    line: u32,
    column: u32,
    program: Program,
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
    fn new(src: &'a str, options: ReadOptions, mode: Mode) -> Self {
        // reading one block again keeps no program (nor allocates one)
        let blocks = match mode {
            Mode::One => None,
            _ => Some(new_blocks(&mode, options)),
        };
        Self {
            src,
            options,
            mode,
            found: None,
            pos: 0,
            line: 1,
            column: 0,
            program: Program {
                programs: blocks
                    .map(|blocks| Subprogram {
                        number: None,
                        span: Span::default(),
                        blocks,
                        call_texts: vec![],
                    })
                    .into_iter()
                    .collect(),
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
        self.program.notes.push(Note {
            span,
            message: message.into(),
        });
    }

    /// Skip the leader (spec/dialects.md §1), noting what it held.
    fn skip_leader(&mut self) {
        let Some(end) = leader_end(self.src) else {
            return;
        };
        let text: String = self.src[..end]
            .chars()
            .filter(|c| !c.is_control() && *c != '%' && *c != '\u{feff}')
            .collect();
        let mut first = None;
        while self.offset() < end {
            let Some((span, _)) = self.next() else { break };
            first.get_or_insert(span);
        }
        if !self.src[..end].ends_with('\n') && !self.src[..end].ends_with('\r') {
            self.note(
                first.unwrap_or_default(),
                "'%' and the first block share a line: read as the tape start, then the block (a FANUC reading a memory card skips the rest of this line)",
            );
        }
        let text = text.trim();
        if !text.is_empty() {
            let shown: String = text.chars().take(40).collect();
            let span = first.unwrap_or_default();
            self.note(
                span,
                format!("leader skipped: \"{shown}\" (everything before the first % is not read)"),
            );
        }
    }

    /// After the closing `%`: nothing more is read; anything but white space and control
    /// bytes there is noted.
    fn skip_trailer(&mut self, at: Span) {
        let rest = &self.src[self.offset()..];
        if rest
            .chars()
            .any(|c| !c.is_whitespace() && !c.is_control() && c != '%')
        {
            self.note(
                at,
                "text after the closing % is not read (a control stops at %)",
            );
        }
        self.pos = self.src.len();
    }

    /// Count a dropped control byte.
    fn control(&mut self, kind: ControlKind, span: Span) {
        let slot = match kind {
            ControlKind::FlowControl => &mut self.flow_control,
            ControlKind::Unexpected => &mut self.unexpected_control,
            ControlKind::Ignored => return,
        };
        if slot.0 == 0 {
            slot.1 = span;
        }
        slot.0 += 1;
    }

    fn control_notes(&mut self) {
        let (n, at) = self.flow_control;
        if n > 0 {
            self.note(
                at,
                format!("{n} RS-232 flow-control byte(s) (DC1–DC4) removed"),
            );
        }
        let (n, at) = self.unexpected_control;
        if n > 0 {
            self.note(
                at,
                format!("{n} unexpected control character(s) removed; check that this is a program text file"),
            );
        }
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

    /// The number text of a pending word.
    fn number_text(&self, p: &PendingWord) -> &str {
        if p.copied {
            &self.number
        } else {
            &self.src[p.text.clone()]
        }
    }

    /// Add a character to the pending word's number (`at`: where it was read; `,` stands
    /// there for a decimal comma read as `.`). The number stays a slice of the source while
    /// it is written in one piece.
    fn push_number(&mut self, c: char, at: Span) {
        let Some(p) = &mut self.pending else { return };
        p.end = at;
        let offset = at.offset as usize;
        if !p.copied {
            let in_place = self.src.as_bytes()[offset] == c as u8;
            if in_place && p.text.is_empty() {
                p.text = offset..offset + 1;
                return;
            }
            if in_place && p.text.end == offset {
                p.text.end += 1;
                return;
            }
            self.number.clear();
            self.number.push_str(&self.src[p.text.clone()]);
            p.copied = true;
        }
        self.number.push(c);
    }

    /// The digits, point and signs right after an address letter, read in one go (the
    /// common case; the character loop reads the rest and says when a number is too long).
    fn scan_number(&mut self) {
        let bytes = self.src.as_bytes();
        let start = self.pos;
        let mut end = start;
        while end < bytes.len()
            && end - start < MAX_NUMBER_CHARS
            && matches!(bytes[end], b'0'..=b'9' | b'.' | b'+' | b'-')
        {
            end += 1;
        }
        if end == start {
            return;
        }
        let n = (end - start) as u32;
        let last = Span {
            line: self.line,
            column: self.column + n,
            offset: (end - 1) as u32,
            len: 1,
        };
        self.column += n;
        self.pos = end;
        if let Some(p) = &mut self.pending {
            p.text = start..end;
            p.end = last;
        }
        self.block_end = last;
    }

    fn mark(&mut self, span: Span) {
        if self.block_start.is_none() {
            self.block_start = Some(span);
        }
        self.block_end = span;
    }

    fn run(mut self) -> Result<Program, ParseError> {
        self.skip_leader();
        self.read()?;
        self.control_notes();
        self.program
            .programs
            .retain(|p| p.number.is_some() || !p.blocks.is_empty());
        for p in &mut self.program.programs {
            p.blocks.shrink();
        }
        Ok(self.program)
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
            match c {
                '\n' => self.end_block()?,
                // a lone CR (EIA end of block, old Mac files) ends a block like LF
                '\r' if self.peek() != Some('\n') => self.end_block()?,
                ';' => {
                    self.end_block()?;
                    if self.found.is_some() {
                        return Ok(());
                    }
                    let rest = self.rest_of_line();
                    if self.pos < self.no_prose_before {
                        // a part of a rest already found no prose (see the field)
                    } else if !is_prose(rest) {
                        if !rest.as_bytes().contains(&b'(') {
                            self.no_prose_before = self.pos + rest.len();
                        }
                    } else {
                        let mut start = span;
                        while self.peek().is_some_and(|c| c == ' ' || c == '\t') {
                            self.next();
                        }
                        if let Some(c) = self.peek() {
                            start = Span {
                                line: self.line,
                                column: self.column + 1,
                                offset: self.pos as u32,
                                len: c.len_utf8() as u32,
                            };
                        }
                        let end = self.skip_line();
                        self.note(
                            start.to(end),
                            "text after ';' read as a comment (a Mach3/Fagor/Siemens-style comment: a FANUC control would read it as code); write it as ( … )",
                        );
                    }
                }
                ' ' | '\t' | '\r' | '\u{3000}' => {}
                '(' | '（' => self.skip_comment(span)?,
                ':' if self.block_is_empty() && self.peek().is_some_and(|c| c.is_ascii_digit()) => {
                    self.pending = Some(PendingWord::new('O', span));
                    self.mark(span);
                }
                '"' => {
                    return Err(ParseError::new(
                        span,
                        "string literal is not part of this dialect",
                        "quoted text belongs in a comment ( … )",
                    ))
                }
                ',' if self.pending.as_ref().is_some_and(|p| {
                    self.number_text(p).ends_with(|c: char| c.is_ascii_digit())
                }) && self.peek().is_some_and(|c| c.is_ascii_digit()) =>
                {
                    if !self.options.decimal_comma {
                        let p = self.pending.as_ref().expect("checked");
                        let shown = format!("{}{},", p.letter, self.number_text(p));
                        return Err(ParseError::new(
                            span,
                            format!("decimal comma in {shown}…"),
                            "write the decimal point as '.', or read the whole file with --decimal-comma",
                        ));
                    }
                    self.push_number('.', span);
                }
                ',' if self.comma_address().is_some() => {
                    self.finish_word()?;
                    let letter = self.comma_address().expect("checked");
                    // the spaces and the letter after the comma
                    while self.peek().is_some_and(|c| c == ' ' || c == '\t') {
                        self.next();
                    }
                    self.next();
                    self.start_word(letter, span)?;
                }
                '/' if self.peek() == Some('/') => {
                    self.finish_word()?;
                    self.skip_line();
                }
                '/' => {
                    // at the start of a block, or right after its N word (`N20 /X…`)
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
                    if let Some(level) =
                        self.peek().and_then(|c| c.to_digit(10)).filter(|&d| d >= 1)
                    {
                        self.next();
                        self.delete_level = level as u8;
                    }
                    self.mark(span);
                }
                '%' => {
                    self.finish_word()?;
                    if !self.words.is_empty() || self.seq.is_some() {
                        return Err(ParseError::new(
                            span,
                            "'%' inside a block",
                            "'%' marks the start or end of the tape and stands on its own line",
                        ));
                    }
                    // the end of the tape: a control reads no further
                    self.skip_trailer(span);
                }
                c if (c == '#' || c.is_ascii_alphabetic())
                    && self.options.macros.is_some()
                    && self.at_statement_start()
                    && macro_b::starts_statement(&self.src[span.offset as usize..]) =>
                {
                    self.finish_word()?;
                    self.statement(span)?;
                }
                '#' => {
                    let message = if self.options.macros.is_some() {
                        "'#' where no macro variable can stand"
                    } else {
                        "`#` needs custom macro B: run with --control fanuc-a or --macro on"
                    };
                    return Err(ParseError::new(
                        span,
                        message,
                        if self.options.macros.is_some() {
                            "a variable stands in a statement (#1 = …) or right after an address letter (X#1)"
                        } else {
                            NO_MACRO_HELP
                        },
                    ));
                }
                c if c.is_ascii_alphabetic() => {
                    self.finish_word()?;
                    self.start_word(c.to_ascii_uppercase(), span)?;
                }
                c if c.is_ascii_digit() || c == '.' || c == '+' || c == '-' => {
                    let Some(p) = &self.pending else {
                        return Err(ParseError::new(
                            span,
                            format!("number '{c}' without an address letter"),
                            "every number belongs to a word such as X100. or Z-5 — add the letter",
                        ));
                    };
                    if self.number_text(p).len() >= MAX_NUMBER_CHARS {
                        return Err(ParseError::new(
                            p.start.to(span),
                            format!("number of address {} is too long", p.letter),
                            NUMBER_HELP,
                        ));
                    }
                    self.push_number(c, span);
                    self.block_end = span;
                }
                c if !c.is_ascii() && !c.is_control() => {
                    // Manuals print annotations after the block without parentheses
                    // (seed 003: `w-20 ; 精加工形狀程式段`). Accept them as comments, noted.
                    self.finish_word()?;
                    let end = self.skip_line();
                    self.program.notes.push(Note {
                        span: span.to(end),
                        message: "text outside parentheses read as a comment; write it as ( … ) for a real controller".into(),
                    });
                }
                c => {
                    if let Some(e) = self.foreign(span) {
                        return Err(e);
                    }
                    let (what, help) = if c.is_control() {
                        (
                            format!("unexpected control character U+{:04X}", c as u32),
                            "this does not look like a program text file; check the file you gave",
                        )
                    } else {
                        (
                            format!("unexpected character '{c}'"),
                            "only address letters, numbers, ';', '/', '%' and comments ( ) belong in a block",
                        )
                    };
                    return Err(ParseError::new(span, what, help));
                }
            }
        }
        self.end_block()
    }

    /// Nothing of the current block read yet.
    fn block_is_empty(&self) -> bool {
        self.pending.is_none() && self.words.is_empty() && self.seq.is_none() && !self.block_delete
    }

    /// Nothing but an N word (or `/`) read of the current block: a macro statement may
    /// start here.
    fn at_statement_start(&self) -> bool {
        self.words.is_empty()
            && self.stmt.is_none()
            && self.pending.as_ref().is_none_or(|p| p.letter == 'N')
    }

    /// The text from byte `start` to the end of its block: the next newline, lone CR or
    /// `;` outside a comment.
    fn block_text(&self, start: usize) -> &'a str {
        let rest = &self.src[start..];
        let mut depth = 0usize;
        for (i, c) in rest.char_indices() {
            match c {
                '(' => depth += 1,
                ')' => depth = depth.saturating_sub(1),
                '\n' | '\r' => return &rest[..i],
                ';' if depth == 0 => return &rest[..i],
                _ => {}
            }
        }
        rest
    }

    /// Consume the characters up to byte `end`, extending the block; the last span.
    fn consume_to(&mut self, end: usize) -> Option<Span> {
        let mut last = None;
        while self.offset() < end {
            let (span, _) = self.next()?;
            last = Some(span);
        }
        if let Some(l) = last {
            self.block_end = l;
        }
        last
    }

    /// The span of the next character (a zero-length span at the end of the text).
    fn next_span(&mut self) -> Span {
        let offset = self.offset();
        Span {
            line: self.line,
            column: self.column + 1,
            offset: offset as u32,
            len: 0,
        }
    }

    /// A macro statement from `start` (already read) to the end of the block.
    fn statement(&mut self, start: Span) -> Result<(), ParseError> {
        self.mark(start);
        let text = self.block_text(start.offset as usize).trim_end();
        let options = match self.options.macros {
            Some(Dialect::Haas) => macro_b::Options::haas(),
            _ => macro_b::Options::fanuc(),
        };
        let stmt = macro_b::parse_stmt(text, start, &options)?;
        // Haas `IF [cond] THEN <NC block>`: the block's words are read as words
        let end = match &stmt.kind {
            macro_b::StmtKind::IfThenBlock { text_span, .. } => text_span.offset as usize,
            _ => start.offset as usize + text.len(),
        };
        self.consume_to(end);
        self.stmt = Some(stmt);
        Ok(())
    }

    /// Whether the value after an address letter is a macro expression: `#…`, `[…]`, a
    /// function (`ROUND[…]`), each possibly after a sign.
    fn expression_follows(&self) -> bool {
        let at = self.offset();
        let next = &self.src.as_bytes()[at..];
        let unsigned = next.strip_prefix(b"-").or_else(|| next.strip_prefix(b"+"));
        if unsigned
            .unwrap_or(next)
            .first()
            .is_some_and(|b| b.is_ascii_digit() || *b == b'.')
        {
            // a number, the common case: no `#`, `[` or function name
            return false;
        }
        let rest = self.block_text(at);
        let t = rest.trim_start_matches([' ', '\t']);
        let t = t
            .strip_prefix(['-', '+'])
            .unwrap_or(t)
            .trim_start_matches([' ', '\t']);
        if t.starts_with(['#', '[']) {
            return true;
        }
        let name_len = t.bytes().take_while(u8::is_ascii_alphabetic).count();
        Func::from_name(&t[..name_len].to_ascii_uppercase()).is_some()
            && t[name_len..]
                .trim_start_matches([' ', '\t'])
                .starts_with('[')
    }

    /// An address whose value is a macro expression (`X#1`, `Z[#2-0.5]`, `G#10`).
    fn expression_word(&mut self, letter: char, at: Span) -> Result<(), ParseError> {
        if matches!(letter, 'N' | 'O') {
            return Err(ParseError::new(
                at,
                format!("{letter} needs a number, not a macro expression"),
                format!("write {letter} as digits only, e.g. {letter}14"),
            ));
        }
        let base = self.next_span();
        let text = self.block_text(base.offset as usize);
        let (expr, used) = macro_b::parse_operand(text, base)?;
        let end = self.consume_to(base.offset as usize + used).unwrap_or(at);
        self.push_word(Word {
            letter,
            value: 0.0,
            has_point: true,
            span: at.to(end),
            expr: Some(Box::new(expr)),
        })
    }

    /// Add a word to the block: one of each address, except G and M.
    fn push_word(&mut self, word: Word) -> Result<(), ParseError> {
        let letter = word.letter;
        let then_block = self
            .stmt
            .as_ref()
            .is_some_and(|s| matches!(s.kind, macro_b::StmtKind::IfThenBlock { .. }));
        if self.stmt.is_some() && !then_block {
            return Err(ParseError::new(
                word.span,
                "an NC word after a macro statement",
                "put the macro statement on a block of its own",
            ));
        }
        // G65 assignment II repeats I J K (spec/dialects.md §5.5)
        let g65 = || {
            matches!(letter, 'I' | 'J' | 'K')
                && self
                    .words
                    .iter()
                    .any(|w| w.letter == 'G' && w.value == 65.0)
        };
        if letter != 'G' && letter != 'M' && !g65() {
            if let Some(first) = self.words.iter().find(|w| w.letter == letter) {
                let a = address(letter);
                return Err(ParseError::new(
                    word.span,
                    format!(
                        "address {a} given twice in one block (first at {})",
                        first.span
                    ),
                    format!("remove one of the two {a} words"),
                ));
            }
        }
        self.words.push(word);
        Ok(())
    }

    /// Begin the word of `letter` read at `span`: its value is an expression (macro B) or a
    /// number, read from here.
    fn start_word(&mut self, letter: char, span: Span) -> Result<(), ParseError> {
        if self.options.macros.is_some() && self.expression_follows() {
            self.expression_word(letter, span)?;
            self.mark(span);
        } else {
            self.pending = Some(PendingWord::new(letter, span));
            // the block reaches the letter, then its digits (`scan_number` moves the end)
            self.mark(span);
            self.scan_number();
        }
        Ok(())
    }

    /// After a `,` just read: the address of a direct drawing dimension (`,C1.`, `,R2.`,
    /// `,A30.`, spaces allowed before the letter), as its lower-case letter (see
    /// [`Word::letter`]); `None` for anything else (a decimal comma is followed by a digit).
    fn comma_address(&self) -> Option<char> {
        let rest = self.src[self.pos..].trim_start_matches([' ', '\t']);
        let c = rest.chars().next()?.to_ascii_lowercase();
        matches!(c, 'c' | 'r' | 'a').then_some(c)
    }

    /// Skip to the end of the line (the newline itself ends the block). Returns the last span.
    fn skip_line(&mut self) -> Span {
        // nothing to skip: an empty span here (not at the start of the file), so that
        // `span.to(skip_line())` stays on the line
        let mut last = Span {
            line: self.line,
            column: self.column,
            offset: self.offset() as u32,
            len: 0,
        };
        while let Some(c) = self.peek() {
            if c == '\n' {
                break;
            }
            if let Some((s, _)) = self.next() {
                last = s;
            }
        }
        last
    }

    /// A comment from `(` (already read): FANUC ends it at the first `)`. **Interpretation**
    /// (dialects.md §1): when a `(` opens inside it and, read with nesting, the
    /// parentheses balance on the line, the whole is one comment, with a note; an unclosed
    /// `(` runs to the end of the line, with a note; a `%` inside is text, with a note.
    fn skip_comment(&mut self, open: Span) -> Result<(), ParseError> {
        let rest = self.rest_of_line();
        let closes = |c: char| c == ')' || c == '）';
        let opens = |c: char| c == '(' || c == '（';
        let first_close = rest.find(closes);
        let nested_end = {
            let mut depth = 1;
            let mut end = None;
            for (i, c) in rest.char_indices() {
                if opens(c) {
                    depth += 1;
                } else if closes(c) {
                    depth -= 1;
                    if depth == 0 {
                        end = Some(i + c.len_utf8());
                        break;
                    }
                }
            }
            end
        };
        let nested = rest
            .find(opens)
            .is_some_and(|o| first_close.is_none_or(|c| o < c));
        let end = match (first_close, nested_end) {
            (_, Some(e)) if nested => {
                self.note(open, "nested parentheses read as one comment: a FANUC control would end the comment at the first ')' and read the rest as code");
                Some(e)
            }
            (Some(c), _) => Some(c + rest[c..].chars().next().map_or(1, char::len_utf8)),
            (None, _) => None,
        };
        let body = &rest[..end.unwrap_or(rest.len())];
        if body.contains('%') {
            self.note(open, "'%' inside a comment: read on as text (a FANUC control stops reading the file at a %)");
        }
        let stop = self.offset() + body.len();
        let mut last = open;
        while self.offset() < stop {
            let Some((span, _)) = self.next() else { break };
            last = span;
        }
        if self.call_text.is_none() && self.m98_read() {
            let text = body.strip_suffix([')', '）']).unwrap_or(body).trim();
            self.call_text = Some((text.to_string(), open.to(last)));
        }
        if end.is_none() {
            self.note(open, "comment not closed on this line: read as a comment to the end of the line; close it with ')'");
        }
        Ok(())
    }

    /// Whether the current block holds `M98` so far (as a word, or being read).
    fn m98_read(&self) -> bool {
        let m98 = |letter: char, value: f64| letter == 'M' && value == 98.0;
        self.words
            .iter()
            .any(|w| w.expr.is_none() && m98(w.letter, w.value))
            || self.pending.as_ref().is_some_and(|p| {
                parse_number(self.number_text(p))
                    .is_some_and(|(v, point)| !point && m98(p.letter, v))
            })
    }

    /// The error naming a Linux CNC construct on the line of `at`, if the line holds one.
    fn foreign(&self, at: Span) -> Option<ParseError> {
        let at = (at.offset as usize).min(self.src.len());
        let start = self.src[..at].rfind('\n').map_or(0, |i| i + 1);
        let end = self.src[at..].find('\n').map_or(self.src.len(), |i| at + i);
        let what = crate::foreign::linuxcnc(&self.src[start..end])?;
        Some(ParseError::new(
            Span {
                line: self.line,
                column: 1,
                offset: start as u32,
                len: (end - start).min(u32::MAX as usize) as u32,
            },
            format!("{what} is LinuxCNC (rs274ngc) syntax, not FANUC, GSK or Haas"),
            "latsim reads FANUC, GSK and Haas lathe programs; LinuxCNC programs are not supported",
        ))
    }

    fn finish_word(&mut self) -> Result<(), ParseError> {
        let Some(p) = self.pending.take() else {
            return Ok(());
        };
        let span = p.start.to(p.end);
        let text = self.number_text(&p);
        let foreign = self.foreign(span);
        let (value, has_point) = parse_number(text).ok_or_else(|| {
            if let Some(e) = foreign {
                e
            } else if text.is_empty() {
                ParseError::new(
                    span,
                    format!("address {} has no value", address(p.letter)),
                    format!(
                        "write a number right after {}, e.g. {}0",
                        address(p.letter),
                        address(p.letter)
                    ),
                )
            } else {
                ParseError::new(
                    span,
                    format!("malformed number '{}' after {}", text, address(p.letter)),
                    "a number is an optional sign, digits and at most one decimal point, e.g. -17.639 or 100.",
                )
            }
        })?;
        // digits before the point, signs and leading zeros aside
        let whole_digits = text
            .bytes()
            .take_while(|&b| b != b'.')
            .skip_while(|&b| b == b'+' || b == b'-')
            .skip_while(|&b| b == b'0')
            .count();
        if whole_digits > MAX_WHOLE_DIGITS {
            return Err(ParseError::new(
                span,
                format!(
                    "number of address {} has {whole_digits} digits before the point",
                    address(p.letter)
                ),
                NUMBER_HELP,
            ));
        }
        match p.letter {
            'N' => {
                if let Some((_, first)) = self.seq {
                    return Err(ParseError::new(
                        span,
                        format!("two sequence numbers in one block (the first at {first})"),
                        "keep one N word per block",
                    ));
                }
                let n = whole(value, has_point, span, 'N')?;
                if n == 0 {
                    return Err(ParseError::new(
                        span,
                        "N0 is not a sequence number",
                        "number blocks from N1 (up to 8 digits), or leave the N word out",
                    ));
                }
                self.seq = Some((n, span));
            }
            'O' => {
                let number = whole(value, has_point, span, 'O')?;
                if number == 0 {
                    return Err(ParseError::new(
                        span,
                        "O0 is not a program number",
                        "number programs from O1 (up to 8 digits)",
                    ));
                }
                if !self.words.is_empty() || self.seq.is_some() {
                    return Err(ParseError::new(
                        span,
                        "program number O inside a block",
                        "put O and its number on a line of its own, before the program's blocks",
                    ));
                }
                if let Mode::One = self.mode {
                    // the block read again after an O on its line: the O was read before
                    return Ok(());
                }
                let current = self
                    .program
                    .programs
                    .last_mut()
                    .expect("always one program");
                if current.number.is_none() && current.blocks.is_empty() {
                    current.number = Some(number);
                    current.span = span;
                } else {
                    if let Some(other) = self.program.find(number) {
                        return Err(ParseError::new(
                            span,
                            format!(
                                "program O{number:04} is defined twice (first at {})",
                                other.span
                            ),
                            "give each program in the file its own O number",
                        ));
                    }
                    let blocks = new_blocks(&self.mode, self.options);
                    self.program.programs.push(Subprogram {
                        number: Some(number),
                        span,
                        blocks,
                        call_texts: vec![],
                    });
                }
            }
            letter => self.push_word(Word {
                letter,
                value,
                has_point,
                span,
                expr: None,
            })?,
        }
        Ok(())
    }

    fn end_block(&mut self) -> Result<(), ParseError> {
        self.finish_word()?;
        if self.options.x_radius {
            crate::radius::to_diameter(&mut self.words)?;
        }
        if let Some(start) = self.block_start.take() {
            let seq = self.seq.take();
            let block_delete = std::mem::replace(&mut self.block_delete, false);
            let delete_level = std::mem::replace(&mut self.delete_level, 0);
            let stmt = self.stmt.take();
            let call_text = self.call_text.take();
            if !self.words.is_empty() || seq.is_some() || stmt.is_some() {
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
                if let Mode::One = self.mode {
                    self.found = Some(block(&self.words));
                } else {
                    let sub = self
                        .program
                        .programs
                        .last_mut()
                        .expect("always one program");
                    if let Some((text, span)) = call_text {
                        sub.call_texts.push(crate::CallText {
                            block: sub.blocks.len(),
                            text,
                            span,
                        });
                    }
                    if let Mode::Index(_) = self.mode {
                        let flags = if block_delete { BlockStart::DELETE } else { 0 }
                            | if crate::program::has_m(&self.words, &END_CODES) {
                                BlockStart::ENDS
                            } else {
                                0
                            };
                        let at = BlockStart {
                            offset: start.offset,
                            line: start.line,
                            column: start.column,
                            seq: seq.map_or(0, |s| s.0),
                            flags,
                        };
                        let macros = has_stmt || self.words.iter().any(|w| w.expr.is_some());
                        sub.blocks.push_start(at, macros);
                    } else {
                        sub.blocks.make_mut().push(block(&self.words));
                    }
                }
            }
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

    /// The block that starts at `start`, read again ([`Mode::One`]); the reader is as new
    /// for it, whatever it read before.
    fn read_again(&mut self, start: BlockStart) -> Block {
        self.pos = start.offset as usize;
        self.line = start.line;
        self.column = start.column - 1;
        self.no_prose_before = 0;
        self.at_block_start = true;
        self.program.notes.clear();
        match (self.read(), self.found.take()) {
            (Ok(()), Some(b)) => b,
            (read, _) => panic!(
                "the block at line {}, column {} read differently the second time: {read:?}",
                start.line, start.column
            ),
        }
    }

    /// A plain block — address letters with numbers, spaces between — read in one go (most
    /// blocks of a CAM program are plain, and the character loop was a third of a run). It
    /// leaves the block's words read and the reader at the block's end (`\n`, `;` or the end
    /// of the text) for the loop to end the block. A block with anything else (a comment,
    /// `/`, `,`, `O`, a macro expression, a number in pieces, an error) is left whole to the
    /// loop. The reference reading ([`Mode::Held`], [`parse_held`]) reads every block
    /// with the loop, so that the tests compare the two.
    fn read_plain_block(&mut self) {
        if matches!(self.mode, Mode::Held) {
            return;
        }
        let (pos, column, block_end) = (self.pos, self.column, self.block_end);
        if !self.plain_block() {
            self.pos = pos;
            self.column = column;
            self.block_end = block_end;
            self.block_start = None;
            self.words.clear();
            self.seq = None;
        }
    }

    /// [`Reader::read_plain_block`]'s reading: false where the block is not plain.
    fn plain_block(&mut self) -> bool {
        let bytes = self.src.as_bytes();
        let (base, base_column) = (self.pos, self.column);
        // every byte read is ASCII: one column each
        let span_at = |line: u32, i: usize| Span {
            line,
            column: base_column + (i - base) as u32 + 1,
            offset: i as u32,
            len: 1,
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
                b'O' | b'o' => return false,
                b if b.is_ascii_alphabetic() => {}
                _ => return false,
            }
            if self.options.macros.is_some()
                && self.words.is_empty()
                && macro_b::starts_statement(&self.src[i..])
            {
                return false;
            }
            let letter = char::from(b.to_ascii_uppercase());
            let start = i + 1;
            let Some((len, value, has_point)) = plain_number(&bytes[start..]) else {
                return false;
            };
            let end = start + len;
            let first = span_at(self.line, i);
            let last = span_at(self.line, end - 1);
            let span = first.to(last);
            if letter == 'N' {
                if self.seq.is_some() || has_point || !(1.0..=99_999_999.0).contains(&value) {
                    return false;
                }
                self.seq = Some((value as u32, span));
            } else {
                if letter != 'G' && letter != 'M' && self.words.iter().any(|w| w.letter == letter) {
                    return false;
                }
                self.words.push(Word {
                    letter,
                    value,
                    has_point,
                    span,
                    expr: None,
                });
            }
            self.block_start.get_or_insert(first);
            self.block_end = last;
            i = end;
        }
        self.column = base_column + (i - base) as u32;
        self.pos = i;
        true
    }
}

/// The blocks of a new O program, as `mode` keeps them.
fn new_blocks(mode: &Mode, options: ReadOptions) -> Blocks {
    match mode {
        Mode::Index(text) => Blocks::reread(Arc::clone(text), options),
        Mode::Held | Mode::One => Blocks::default(),
    }
}

fn whole(value: f64, has_point: bool, span: Span, letter: char) -> Result<u32, ParseError> {
    if has_point || !(0.0..=99_999_999.0).contains(&value) {
        return Err(ParseError::new(
            span,
            format!("{letter} needs a whole number without a decimal point"),
            format!("write {letter} as digits only, e.g. {letter}14"),
        ));
    }
    Ok(value as u32)
}

/// The exact powers of ten of [`parse_number`]'s fast path.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The number at the start of `bytes` as a plain block writes it, read in one pass: an
/// optional sign, digits with at most one point, fewer than [`MAX_NUMBER_CHARS`]
/// characters and at most [`MAX_WHOLE_DIGITS`] digits before the point (leading zeros
/// aside), ended by anything but a digit, point or sign, with a value on
/// [`parse_number`]'s fast path. Its length, value (the one `parse_number` gives) and
/// whether a point was written; `None` for anything else, which the character loop reads.
fn plain_number(bytes: &[u8]) -> Option<(usize, f64, bool)> {
    let mut i = usize::from(matches!(bytes.first(), Some(b'+' | b'-')));
    let (mut mantissa, mut digits, mut decimals, mut point, mut whole) =
        (0u64, 0usize, 0usize, false, 0usize);
    while let Some(&b) = bytes.get(i) {
        match b {
            b'0'..=b'9' => {
                if !point && (whole > 0 || b != b'0') {
                    whole += 1;
                }
                // fewer than 20 characters: at most 19 digits, below u64::MAX
                mantissa = mantissa * 10 + u64::from(b - b'0');
                digits += 1;
                decimals += usize::from(point);
            }
            b'.' if !point => point = true,
            b'.' | b'+' | b'-' => return None,
            _ => break,
        }
        i += 1;
        if i >= MAX_NUMBER_CHARS {
            return None;
        }
    }
    if digits == 0 || whole > MAX_WHOLE_DIGITS || mantissa >= 1 << 53 {
        return None;
    }
    let value = mantissa as f64 / POW10[decimals];
    let value = if bytes[0] == b'-' { -value } else { value };
    Some((i, value, point))
}

/// `[+-]? (digits [. digits*] | . digits)`; returns the value and whether a point was written.
fn parse_number(text: &str) -> Option<(f64, bool)> {
    let bytes = text.as_bytes();
    let body = match bytes.first() {
        Some(b'+' | b'-') => &bytes[1..],
        _ => bytes,
    };
    let mut digits = 0;
    let mut points = 0;
    // the digits as one integer and how many stand after the point
    let (mut mantissa, mut decimals) = (0u64, 0i32);
    for &b in body {
        match b {
            b'0'..=b'9' => {
                digits += 1;
                mantissa = mantissa
                    .saturating_mul(10)
                    .saturating_add(u64::from(b - b'0'));
                decimals += points;
            }
            b'.' => points += 1,
            _ => return None,
        }
    }
    if digits == 0 || points > 1 {
        return None;
    }
    // Clinger's fast path: an integer below 2^53 over an exact power of ten is one
    // correctly rounded division, the very value `str::parse` returns (a million-line
    // program has millions of numbers, and `parse` was a third of reading them)
    if mantissa < 1 << 53 && digits <= 19 && decimals <= 22 {
        let value = mantissa as f64 / POW10[decimals as usize];
        let value = if bytes[0] == b'-' { -value } else { value };
        return Some((value, points == 1));
    }
    let value: f64 = text.parse().ok()?;
    value.is_finite().then_some((value, points == 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Text outside parentheses that ends its line is noted where it stands (the note ran
    /// from the start of the file when nothing followed the character).
    #[test]
    fn a_note_for_text_at_the_end_of_a_line_stays_on_it() {
        let p = parse("O0001\nG0 X50. Z2.\nG1 Z-5. F0.2 \u{e9}\nG0 X60.\nM30\n").unwrap();
        let n = &p.notes[0];
        assert_eq!(
            (n.span.line, n.span.column, n.span.offset, n.span.len),
            (3, 14, 31, 2),
            "{:?}",
            n.span
        );
    }

    /// The fast path gives `str::parse`'s value bit for bit, sign of zero included.
    #[test]
    fn numbers_read_as_str_parse_reads_them() {
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut fast = 0;
        for i in 0..300_000u64 {
            let r = next();
            let whole = match i % 4 {
                0 => r % 10,
                1 => r % 100_000,
                2 => r % 100_000_000,
                _ => r % 10_000_000_000_000_000,
            };
            let places = (r >> 40) % 24;
            let frac = format!(
                "{:0width$}",
                (r >> 8) % 10u64.pow(places.min(18) as u32),
                width = places as usize
            );
            let sign = ["", "-", "+"][(r >> 60) as usize % 3];
            let text = match (r >> 56) % 4 {
                0 => format!("{sign}{whole}"),
                1 => format!("{sign}{whole}."),
                2 => format!("{sign}.{frac}"),
                _ => format!("{sign}{whole}.{frac}"),
            };
            let Some((v, _)) = parse_number(&text) else {
                panic!("{text} not read");
            };
            let expect: f64 = text.parse().unwrap();
            assert_eq!(v.to_bits(), expect.to_bits(), "{text}");
            let body = text.trim_start_matches(['+', '-']).replace('.', "");
            fast += usize::from(body.len() <= 15);
        }
        assert!(fast > 100_000, "{fast}");
        for text in [
            "-0",
            "-0.000",
            "0.",
            ".5",
            "9007199254740993",
            "1.7976931348623157",
            "0.1",
            "-123.4567",
        ] {
            let (v, _) = parse_number(text).unwrap();
            assert_eq!(
                v.to_bits(),
                text.parse::<f64>().unwrap().to_bits(),
                "{text}"
            );
        }
    }

    fn words(src: &str) -> Vec<(char, f64)> {
        parse(src).unwrap().programs[0]
            .blocks
            .iter()
            .flat_map(|b| {
                b.words
                    .iter()
                    .map(|w| (w.letter, w.value))
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    #[test]
    fn spaces_inside_words_and_case() {
        assert_eq!(
            words("g74 z-28.0 Q5 000 f0.1"),
            vec![('G', 74.0), ('Z', -28.0), ('Q', 5000.0), ('F', 0.1)]
        );
        assert_eq!(
            words("G28 U0 W 0;"),
            vec![('G', 28.0), ('U', 0.0), ('W', 0.0)]
        );
    }

    #[test]
    fn number_forms() {
        assert_eq!(
            words("X100. u.1 w0. R6. Z-17.639 P30000"),
            vec![
                ('X', 100.0),
                ('U', 0.1),
                ('W', 0.0),
                ('R', 6.0),
                ('Z', -17.639),
                ('P', 30000.0)
            ]
        );
        let p = parse("X100. P1500").unwrap();
        let b = &p.programs[0].blocks.all()[0];
        assert!(b.words[0].has_point);
        assert!(!b.words[1].has_point);
    }

    #[test]
    fn blocks_split_on_semicolon_and_newline() {
        let p = parse("M30;G0 X1\nZ2;;\n\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert_eq!(p.programs[0].blocks.all()[2].span.line, 2);
    }

    #[test]
    fn comments() {
        assert_eq!(
            words("G0 X1 (hello; world) Z2 （中文）\nG1 X2 // rest ; ignored"),
            vec![('G', 0.0), ('X', 1.0), ('Z', 2.0), ('G', 1.0), ('X', 2.0)]
        );
    }

    #[test]
    fn annotation_after_block_is_noted() {
        let p = parse("w-20 ; 精加工形狀程式段\nX1").unwrap();
        assert_eq!(p.notes.len(), 1);
        assert_eq!(p.programs[0].blocks.len(), 2);
    }

    #[test]
    fn o_programs_and_sequence_numbers() {
        let p = parse("%\nO0001;\nN10 G0 X1;\nM98 P2;\nM30;\nO0002;\nG1 X2;\nM99;\n%").unwrap();
        assert_eq!(p.programs.len(), 2);
        assert_eq!(p.programs[0].number, Some(1));
        assert_eq!(p.programs[0].blocks.all()[0].seq, Some(10));
        assert_eq!(p.find(2).unwrap().blocks.len(), 2);
    }

    #[test]
    fn block_delete() {
        let p = parse("/G0 X1\nG0 X2").unwrap();
        assert!(p.programs[0].blocks.all()[0].block_delete);
        assert!(!p.programs[0].blocks.all()[1].block_delete);
    }

    #[test]
    fn errors_have_line_and_column() {
        let e = parse("G0 X10\nG1 Z-5 X\n").unwrap_err();
        assert_eq!((e.span.line, e.span.column), (2, 8));
        assert!(e.message.contains("no value"), "{}", e.message);
        let e = parse("G1 X1.2.3").unwrap_err();
        assert!(e.message.contains("malformed"));
        let e = parse("G1 X1 X2").unwrap_err();
        assert_eq!(e.span.column, 7);
        assert!(e.message.contains("twice"));
        let e = parse("G1 #1=2").unwrap_err();
        assert_eq!(e.span.column, 4);
        let e = parse("G1 \"A\"").unwrap_err();
        assert!(e.message.contains("string literal"), "{}", e.message);
        let e = parse("G1 X1-2").unwrap_err();
        assert!(e.message.contains("malformed"));
    }

    fn notes(p: &Program) -> Vec<String> {
        p.notes.iter().map(|n| n.message.clone()).collect()
    }

    #[test]
    fn dialects_t1_framing() {
        // spec/dialects.md §7 T1: DC2, a DNC leader glued to %, ':' program number,
        // nested parentheses with quotes, a block of only N, the closing % and DC4
        let text = "\u{12}&HE:%\n:0100 (FRAMING (NESTED) \"Q\" TEST) ;\nN10 G21 G99 ;\nN20 T0101 ;\nN30 G97 S800 M03 ;\nN40 ;\nN50 G00 X52. Z2. ;\nN60 G90 X46. Z-30. F0.2 ;\nN70 X42. ;\nN80 G00 X100. Z100. ;\nN90 M30 ;\n%\n\u{14}";
        let p = parse(text).unwrap();
        assert_eq!(p.programs.len(), 1);
        assert_eq!(p.programs[0].number, Some(100));
        let blocks = &p.programs[0].blocks.all();
        assert_eq!(blocks.len(), 9);
        assert!(blocks[3].words.is_empty() && blocks[3].seq == Some(40));
        let n = notes(&p);
        assert_eq!(n.len(), 2, "{n:?}");
        assert!(n[0].contains("leader skipped: \"&HE:\""), "{n:?}");
        assert!(n[1].contains("nested parentheses"), "{n:?}");
        // the flow-control bytes: DC2 was in the leader, DC4 after the closing %
        let p = parse("G0 X1\u{11}0 Z2\n\u{13}M30\n").unwrap();
        assert_eq!(p.programs[0].blocks.all()[0].words[1].value, 10.0);
        assert!(notes(&p)[0].contains("2 RS-232"), "{:?}", notes(&p));
    }

    #[test]
    fn leader_only_before_the_first_address_line() {
        // a % after program text ends the tape; what follows is not read
        let p = parse("O1\nG0 X1\n%\nG0 X2\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1);
        assert!(notes(&p)[0].contains("after the closing %"));
        // blank lines and a comment before % are leader, with nothing to report
        let p = parse("\n(O1234.NC)\n%\nG0 X1\n%\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1);
        assert!(notes(&p)[0].contains("O1234.NC"), "{:?}", notes(&p));
    }

    #[test]
    fn percent_glued_to_the_program_number_starts_the_tape() {
        // issue 31: `%O1200(TOKARKA)` on line 1 was read as the closing % — no blocks
        let p = parse("%O1200(TOKARKA)\nG0 X10 Z2\nG1 Z-5 F.1\nM30\n%\n").unwrap();
        assert_eq!(p.programs[0].number, Some(1200));
        assert_eq!(p.programs[0].blocks.len(), 3, "{:?}", notes(&p));
        assert!(notes(&p)[0].contains("share a line"), "{:?}", notes(&p));
        // the same after a leader line and with a BOM
        let p = parse("\u{feff}  %O12\nG0 X1\nG0 X2\n%").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
    }

    #[test]
    fn line_ends_and_control_bytes() {
        let p = parse("G0 X1\rG0 X2\r\nG0 X3\n\r\rG0 X4\u{1a}").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 4);
        assert!(p.notes.is_empty(), "{:?}", notes(&p));
        let p = parse("\u{feff}G0\u{0}\u{1} X1\tZ2").unwrap();
        assert_eq!(p.programs[0].blocks.all()[0].words.len(), 3);
        assert!(
            notes(&p)[0].contains("1 unexpected control"),
            "{:?}",
            notes(&p)
        );
    }

    #[test]
    fn prose_after_semicolon_is_a_comment_but_blocks_are_blocks() {
        let p = parse("T0505 ;grooving blade 3 mm\nG0 X1;G1 Z2 F.1;\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert_eq!(notes(&p).len(), 1);
        assert!(notes(&p)[0].contains("after ';'"));
        let p = parse("G0 X1 ; (note) G1 Z2\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
        // macro words are not prose: they stay code (and are refused as code)
        assert!(parse("G0 X1 ; IF [#1 EQ 2] GOTO 5\n").is_err());
    }

    #[test]
    fn comments_unclosed_nested_and_with_percent() {
        let p = parse("G1 X1 (open\nG0 X2").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
        assert!(notes(&p)[0].contains("not closed"));
        // FANUC's reading where the parentheses do not balance: ends at the first ')'
        let p = parse("(TOOL 3 (55 DEG) RH) X1").unwrap();
        assert!(notes(&p)[0].contains("nested"));
        assert_eq!(p.programs[0].blocks.all()[0].words.len(), 1);
        // where they do not balance, FANUC's reading: the comment ends at the first ')'
        let e = parse("(A (B) C").unwrap_err();
        assert!(e.message.contains("C has no value"), "{}", e.message);
        assert_eq!(e.span.column, 8);
        let p = parse("G1 X1 (50% FEED)\nG0 X2").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 2);
        assert!(notes(&p)[0].contains("'%' inside a comment"));
    }

    #[test]
    fn program_and_sequence_numbers_and_block_delete_levels() {
        assert!(parse("O0\nG0 X1").unwrap_err().message.contains("O0"));
        assert!(parse("N0 G0 X1").unwrap_err().message.contains("N0"));
        assert_eq!(
            parse(":1234\nG0 X1").unwrap().programs[0].number,
            Some(1234)
        );
        let p = parse("/2 G0 X1\nN20 /X2\n/G0 X3").unwrap();
        let levels: Vec<u8> = p.programs[0]
            .blocks
            .iter()
            .map(|b| b.delete_level)
            .collect();
        assert_eq!(levels, [2, 1, 1]);
        assert!(p.programs[0].blocks.iter().all(|b| b.block_delete));
    }

    #[test]
    fn decimal_comma_is_an_error_unless_asked_for() {
        let e = parse("G1 X56,08 F0,2").unwrap_err();
        assert!(e.message.contains("decimal comma"), "{}", e.message);
        assert_eq!(e.span.column, 7);
        let p = parse_with(
            "G1 X56,08 F0,2",
            ReadOptions {
                decimal_comma: true,
                ..ReadOptions::default()
            },
        )
        .unwrap();
        assert_eq!(p.programs[0].blocks.all()[0].words[1].value, 56.08);
        assert_eq!(p.programs[0].blocks.all()[0].words[2].value, 0.2);
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let e = parse("（中文）X").unwrap_err();
        assert_eq!(e.span.column, 5);
    }

    fn macro_b(src: &str) -> Result<Program, ParseError> {
        parse_with(
            src,
            ReadOptions {
                macros: Some(Dialect::Fanuc),
                ..ReadOptions::default()
            },
        )
    }

    #[test]
    fn macro_statements_and_expression_words_with_spans() {
        let p = macro_b("N5 #1 = 2 + 3 * 4 ;\nWHILE [#1 GT 2] DO1\nG00 X#1 Z[#2-0.5] F0.2 (C)\nEND1\n#3000 = 1 (TOOL BROKEN) ;\n").unwrap();
        let b = &p.programs[0].blocks.all();
        assert_eq!(b.len(), 5);
        assert_eq!(b[0].seq, Some(5));
        let s = b[0].stmt.as_ref().unwrap();
        assert_eq!((s.span.line, s.span.column), (1, 4));
        assert!(b[0].words.is_empty());
        assert!(matches!(
            b[1].stmt.as_ref().unwrap().kind,
            macro_b::StmtKind::While { id: 1, .. }
        ));
        let w = &b[2].words;
        assert_eq!(w.len(), 4);
        assert_eq!(w[1].expr.as_ref().unwrap().to_string(), "#1");
        assert_eq!((w[1].span.column, w[1].span.len), (5, 3));
        let z = w[2].expr.as_ref().unwrap();
        assert_eq!(z.to_string(), "[#2-0.5]");
        assert_eq!((w[2].span.column, z.span.column), (9, 10));
        assert_eq!(
            (w[3].letter, w[3].value, w[3].expr.is_none()),
            ('F', 0.2, true)
        );
        assert!(matches!(
            b[3].stmt.as_ref().unwrap().kind,
            macro_b::StmtKind::End { id: 1 }
        ));
        let macro_b::StmtKind::Assign { comment, .. } = &b[4].stmt.as_ref().unwrap().kind else {
            panic!("an assignment")
        };
        assert_eq!(comment.as_deref(), Some("TOOL BROKEN"));
        // functions and signs as word values, G#10, spaces and ';' between blocks
        let p = macro_b("G#10 X-#1 Z ROUND[#2];IF [#1 EQ #0] GOTO 10;GOTO#3").unwrap();
        let b = &p.programs[0].blocks.all();
        assert_eq!(b.len(), 3);
        assert!(b[0].words.iter().all(|w| w.expr.is_some()));
        assert!(b[1].stmt.is_some() && b[2].stmt.is_some());
        // plain programs read as before
        assert_eq!(macro_b("G0 X1 Z2").unwrap(), parse("G0 X1 Z2").unwrap());
    }

    #[test]
    fn macro_errors_at_their_column() {
        // without macro B a # is an error that says how to turn it on
        let e = parse("G0 X1\nG1 X#1").unwrap_err();
        assert_eq!((e.span.line, e.span.column), (2, 5));
        assert!(e.message.contains("needs custom macro B"), "{}", e.message);
        assert!(e.message.contains("--control fanuc-a"), "{}", e.message);
        let e = macro_b("#1 = [2 + 3").unwrap_err();
        assert_eq!(e.span.line, 1);
        let e = macro_b("G0 X#1 X2").unwrap_err();
        assert!(e.message.contains("twice"), "{}", e.message);
        let e = macro_b("N#1 G0").unwrap_err();
        assert!(e.message.contains("N needs a number"), "{}", e.message);
        let e = macro_b("G0 X1#2").unwrap_err();
        assert_eq!(e.span.column, 6);
        let e = macro_b("#1 = 5 / \n").unwrap_err();
        assert_eq!(e.span.line, 1);
    }

    #[test]
    fn g_code_tenths() {
        let p = parse("G75.1 G01 G0").unwrap();
        let codes: Vec<_> = p.programs[0].blocks.all()[0]
            .words
            .iter()
            .map(|w| w.code_tenths())
            .collect();
        assert_eq!(codes, vec![Some(751), Some(10), Some(0)]);
    }

    #[test]
    fn numbers_written_in_pieces_keep_their_spans() {
        // a number in one piece is a slice of the source; in pieces it is copied
        let p = parse("G1 X1 2.5(c)0\u{11}1 Z-3\n").unwrap();
        let w = &p.programs[0].blocks.all()[0].words;
        assert_eq!((w[1].value, w[1].has_point), (12.501, true));
        assert_eq!(
            (w[1].span.column, w[1].span.offset, w[1].span.len),
            (4, 3, 12)
        );
        assert_eq!((w[2].value, w[2].span.column, w[2].span.len), (-3.0, 17, 3));
        let comma = ReadOptions {
            decimal_comma: true,
            ..ReadOptions::default()
        };
        let p = parse_with("X1 2,5 Z3,25", comma).unwrap();
        let w = &p.programs[0].blocks.all()[0].words;
        assert_eq!((w[0].value, w[1].value), (12.5, 3.25));
        assert_eq!((w[0].span.len, w[1].span.len), (6, 5));
        let e = parse_with("X1,2,3", comma).unwrap_err();
        assert!(
            e.message.contains("malformed number '1.2.3'"),
            "{}",
            e.message
        );
        // the 21st character of a number is refused where it stands, in one piece or not
        let e = parse("X123456789012345678901").unwrap_err();
        assert!(e.message.contains("too long"), "{}", e.message);
        assert_eq!((e.span.column, e.span.len), (1, 22));
        let e = parse("X1234567890 1234567890 1").unwrap_err();
        assert_eq!((e.span.column, e.span.len), (1, 24));
        // after a full-width space and comment, columns count characters
        let e = parse("\u{3000}（注）X1 Y").unwrap_err();
        assert_eq!((e.span.column, e.span.offset), (8, 15));
    }

    #[test]
    fn prose_after_a_later_semicolon_of_the_same_line() {
        // the rest after the first ';' is no prose, so neither is the rest after the second
        let p = parse("G0 X1;G1 Z2;G3 X4\n").unwrap();
        assert_eq!((p.programs[0].blocks.len(), p.notes.len()), (3, 0));
        // but inside '(' the first test saw no prose where the second does
        let p = parse("G0 X1; G1 ((x) ; ab\nG0 X2").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert!(notes(&p)[0].contains("after ';'"), "{:?}", notes(&p));
        // a keyword is not prose, a longer run of letters is, through a comment too
        assert!(!is_prose(" WHILE [#1 LT 2] DO1"));
        assert!(is_prose(" WHILEX"));
        assert!(is_prose(" A(x)B1"));
        assert!(!is_prose(" A(xyz)1"));
        assert_eq!(
            KEYWORDS.iter().map(|k| k.len()).max(),
            Some(LONGEST_KEYWORD)
        );
    }

    #[test]
    fn a_text_over_4_gib_is_refused_not_misplaced() {
        assert!(check_length(u32::MAX as usize).is_ok());
        let e = check_length(u32::MAX as usize + 1).unwrap_err();
        assert!(e.message.contains("4294967296 bytes"), "{}", e.message);
        assert_eq!((e.span.line, e.span.column), (1, 1));
    }

    /// Blocks read again from the text ([`Blocks`]) are the blocks the reader read, for the
    /// starts a block can have: an O or `:` on the block's line, `/2`, an N word before
    /// `/`, a comma address, `;` between blocks and prose after one, a lone CR, non-ASCII
    /// text before a block on its line, a leader, comments before the block, macro
    /// statements, Haas `IF … THEN`, expressions, `M98 (path)`, and the closing `%`.
    #[test]
    fn blocks_read_again_are_the_blocks_read() {
        let texts = [
            "%\nO1000 G0 X1. Z2.\n:2000 G1 X3\n/2 G0 X4\nN5 /G1 Z-1.\nG1 X5. ,C1.\nG1 Z-9 , R 2.\nM30\n%\n",
            "G0 X1;G1 Z2; ;N7 X3 ; this is prose\rG0 X9\r\nM30",
            "(\u{e9}\u{e9}) G0 X1\n\u{3000}G1 Z-2. F0.1 (note)\n  N10 G0 X5\nM30",
            "LEADER TEXT\n%\nO0001 (TITLE)\n#1=2.5\nN10 G0 X#1 Z[#1+1]\nWHILE[#1LT5]DO1\n#1=#1+1\nEND1\nIF[#1GT2]GOTO10\nM98 (sub.nc) P1\nM30\n%\ntrailer",
            "O0002\nIF [#1 EQ 0] THEN G0 X1.\nG65 P9010 A1. I2. I3.\nM30\nO9010\nG0 X#1\nM99\n",
        ];
        for text in texts {
            let read = read_as_held(text);
            assert!(!read.is_empty(), "{text:?}");
            for p in read {
                assert!(p.block_count() > 0, "{text:?}");
                for sub in &p.programs {
                    // one reader for all, as a chunk read ahead is
                    assert_eq!(sub.blocks.read(0..sub.blocks.len()), sub.blocks.all());
                    for (i, b) in sub.blocks.iter().enumerate() {
                        assert_eq!(sub.blocks.seq(i), b.seq);
                        assert_eq!(sub.blocks.block_delete(i), b.block_delete);
                        assert_eq!(sub.blocks.ends_program(i), b.ends_program());
                    }
                    assert_eq!(
                        sub.blocks.has_macro(),
                        sub.blocks.iter().any(|b| b.has_macro())
                    );
                }
            }
        }
        let p = parse_with(
            texts[3],
            ReadOptions {
                macros: Some(Dialect::Fanuc),
                ..ReadOptions::default()
            },
        )
        .unwrap();
        assert!(p.programs[0].blocks.has_macro());
        assert!(p.programs[0].blocks.positions_seq(10).eq([1]));
    }

    /// Plain blocks are read in one go ([`Reader::read_plain_block`]); the reference
    /// reading reads them character by character. Both give the same blocks, notes and
    /// errors, also for the blocks the quick reading must leave to the loop.
    #[test]
    fn plain_blocks_read_in_one_go_read_as_the_loop_reads_them() {
        let texts = [
            "G00 X1. Z2.\nG01 Z-5.0000 F0.1;\nN20 G1 X+.5 Z-0.;\n",
            "\tg1 x1 z2\r\nG1\tX3 ;\r\n\r\nM30\r\n",
            "G1 X1 .5\n",
            "G1 X1. X2.\n",
            "G65 P9010 I1. I2. J3.\nM30\n",
            "N0 G1 X1\n",
            "N1.5 G1 X1\n",
            "N1 N2 G1 X1\n",
            "N123456789 G1\n",
            "G1 X1234567890.\n",
            "G1 X12345678901234567890\n",
            "G1 X1234567890123456789\n",
            "G1 X-\n",
            "G1 X--5\n",
            "G1 X1.2.3\n",
            "GX1\n",
            "G1 X1\rG1 Z2\n",
            "G1 X1 \u{11} Z2\n",
            "O1234 G1 X1\nG1 X2\n",
            "N10 G1 X1 (c)\nN20 /G1\nG1 X1 ,C1.\n",
            "G1 X1; prose here\nG1 X#1\nG1 X-#1\nIF[#1GT1]GOTO10\nN10 #1=2\nG1 X[1]\n",
            "G1 X1\u{3000}Z2\nG1 X1 %\n",
            "G1 X1",
        ];
        for text in texts {
            read_as_held(text);
        }
    }

    /// `text` read under every option set, read again from the text ([`parse_with`]) and
    /// held by the reference reading ([`parse_held`]): the same blocks, notes or error. The
    /// programs read.
    fn read_as_held(text: &str) -> Vec<Program> {
        let mut programs = vec![];
        for macros in [None, Some(Dialect::Fanuc), Some(Dialect::Haas)] {
            for (decimal_comma, x_radius) in [(false, false), (true, false), (false, true)] {
                let options = ReadOptions {
                    decimal_comma,
                    macros,
                    x_radius,
                };
                let read = parse_with(text, options);
                assert_eq!(read, parse_held(text, options), "{text:?} {options:?}");
                programs.extend(read.ok());
            }
        }
        programs
    }

    /// [`plain_number`] reads what [`parse_number`] reads from the same characters, or
    /// leaves it to the character loop: every string of up to 5 characters of `0 5 . + - X`,
    /// and long ones at the limits.
    #[test]
    fn plain_numbers_read_as_parse_number_reads_them() {
        let alphabet = [b'0', b'5', b'.', b'+', b'-', b'X'];
        let mut texts: Vec<Vec<u8>> = vec![vec![]];
        for len in 1..=5 {
            let mut more = vec![];
            for t in texts.iter().filter(|t| t.len() == len - 1) {
                for &c in &alphabet {
                    let mut u = t.clone();
                    u.push(c);
                    more.push(u);
                }
            }
            texts.extend(more);
        }
        for long in [
            "123456789.123",
            "1234567890.",
            "0001234567.5",
            "9007199254740991",
            "9007199254740992",
            "-1234567.8901234",
            "12345678901234567.5",
            "1234567890123456789",
            "-.000000000000000001",
        ] {
            texts.push(long.as_bytes().to_vec());
        }
        for t in &texts {
            let scanned = t
                .iter()
                .take_while(|b| matches!(b, b'0'..=b'9' | b'.' | b'+' | b'-'))
                .count();
            let text = std::str::from_utf8(&t[..scanned]).unwrap();
            let reference = parse_number(text);
            let whole = text
                .bytes()
                .take_while(|&b| b != b'.')
                .skip_while(|&b| b == b'+' || b == b'-')
                .skip_while(|&b| b == b'0')
                .count();
            match plain_number(t) {
                Some((len, value, point)) => {
                    assert_eq!(len, scanned, "{text}");
                    let (v, p) = reference.unwrap_or_else(|| panic!("{text}"));
                    assert_eq!((value.to_bits(), point), (v.to_bits(), p), "{text}");
                    assert!(
                        whole <= MAX_WHOLE_DIGITS && scanned < MAX_NUMBER_CHARS,
                        "{text}"
                    );
                }
                None => {
                    let digits: String = text.chars().filter(char::is_ascii_digit).collect();
                    let slow = digits.parse::<u128>().is_ok_and(|m| m >= 1 << 53);
                    assert!(
                        reference.is_none()
                            || whole > MAX_WHOLE_DIGITS
                            || scanned >= MAX_NUMBER_CHARS
                            || slow,
                        "{text}"
                    );
                }
            }
        }
    }

    /// Issue 16/17 memory: a million-line program keeps 20 bytes a block (where it starts,
    /// read again where needed); the blocks being run stay small too (macro parts are
    /// boxed; words exactly as many).
    #[test]
    fn blocks_and_words_stay_compact() {
        assert_eq!(std::mem::size_of::<crate::program::BlockStart>(), 20);
        let p = parse(&"G01 X1. Z2. F0.1;\n".repeat(1000)).unwrap();
        assert_eq!(p.programs[0].blocks.len(), 1000);
        assert_eq!(std::mem::size_of::<Span>(), 16);
        assert!(
            std::mem::size_of::<Word>() <= 40,
            "{}",
            std::mem::size_of::<Word>()
        );
        assert!(
            std::mem::size_of::<Block>() <= 72,
            "{}",
            std::mem::size_of::<Block>()
        );
        let p = parse("G01 X1. Z2. F0.1;\nG00 X3.;\n").unwrap();
        let b = &p.programs[0].blocks.all();
        assert_eq!((b[0].words.len(), b[1].words.len()), (4, 2));
    }
}
