//! Words: an address letter, then its number read as a slice of the source (copied only
//! when written in pieces or with a decimal comma), the comma addresses `,C` `,R` `,A`, and
//! the N and O words, which are no words of the block.

use super::{Mode, PendingWord, Reader};
use crate::read::number::{parse_number, whole, word_value, MAX_NUMBER_CHARS, NUMBER_HELP};
use crate::read::reading::{ParseError, ReadProgram};
use crate::{address, Span, Word};

/// The help of a `#` read without custom macro B.
const NO_MACRO_HELP: &str =
    "custom macro B is on by default for --control fanuc-a, fanuc-b, fanuc-c and haas; --macro on turns it on for gsk980";

impl Reader<'_> {
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

    /// Begin the word of `letter` read at `span`: its value is an expression (macro B) or a
    /// number, read from here.
    pub(super) fn start_word(&mut self, letter: char, span: Span) -> Result<(), ParseError> {
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

    /// A digit, point or sign outside the first run after the letter: part of the pending
    /// word's number (`Q5 000`), at most [`MAX_NUMBER_CHARS`] characters.
    pub(super) fn digit(&mut self, span: Span, c: char) -> Result<(), ParseError> {
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
        Ok(())
    }

    /// After a `,` just read: a digit follows and the pending number ends in one (`F0,2`).
    pub(super) fn decimal_comma_follows(&self) -> bool {
        self.pending
            .as_ref()
            .is_some_and(|p| self.number_text(p).ends_with(|c: char| c.is_ascii_digit()))
            && self.peek().is_some_and(|c| c.is_ascii_digit())
    }

    /// A decimal comma: read as `.` with `--decimal-comma`, else an error at it.
    pub(super) fn decimal_comma(&mut self, span: Span) -> Result<(), ParseError> {
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
        Ok(())
    }

    /// After a `,` just read: the address of a direct drawing dimension (`,C1.`, `,R2.`,
    /// `,A30.`, spaces allowed before the letter), as its lower-case letter (see
    /// [`Word::letter`]); `None` for anything else (a decimal comma is followed by a digit).
    pub(super) fn comma_address(&self) -> Option<char> {
        let rest = self.src[self.pos..].trim_start_matches([' ', '\t']);
        let c = rest.chars().next()?.to_ascii_lowercase();
        matches!(c, 'c' | 'r' | 'a').then_some(c)
    }

    /// The word of a comma address, whose `,` is at `span`.
    pub(super) fn comma_word(&mut self, span: Span) -> Result<(), ParseError> {
        self.finish_word()?;
        let letter = self.comma_address().expect("checked");
        // the spaces and the letter after the comma
        while self.peek().is_some_and(|c| c == ' ' || c == '\t') {
            self.next();
        }
        self.next();
        self.start_word(letter, span)
    }

    /// The error for a `#` where no macro variable can stand.
    pub(super) fn misplaced_hash(&self, span: Span) -> ParseError {
        if self.options.macros.is_some() {
            ParseError::new(
                span,
                "'#' where no macro variable can stand",
                "a variable stands in a statement (#1 = …) or right after an address letter (X#1)",
            )
        } else if self.macro_a_block() {
            ParseError::new(
                span,
                "`G65 H… P#…`: custom macro A is not simulated",
                "write the calculation in custom macro B (H01: #101 = 30., H03: #101 = #101 - 3., H84: IF [#101 LT 22.] GOTO 50) and run with --macro on",
            )
        } else {
            ParseError::new(
                span,
                "`#` needs custom macro B: run with --control fanuc-a or --macro on",
                NO_MACRO_HELP,
            )
        }
    }

    /// Whether the block read so far is a `G65 H…`: custom macro A (GSK 980TD, older
    /// FANUC), whose `P#101` is no macro B variable either.
    fn macro_a_block(&self) -> bool {
        let g65 = self
            .words
            .iter()
            .any(|w| w.letter == 'G' && w.value == 65.0);
        g65 && self.words.iter().any(|w| w.letter == 'H')
    }

    /// End the pending word: its number read, it becomes the block's N, the program's O or
    /// one of the block's words.
    pub(super) fn finish_word(&mut self) -> Result<(), ParseError> {
        let Some(p) = self.pending.take() else {
            return Ok(());
        };
        let span = p.start.to(p.end);
        let text = self.number_text(&p);
        let (value, has_point) = word_value(text, span, p.letter, || self.foreign(span))?;
        match p.letter {
            'N' => self.sequence_number(value, has_point, span),
            'O' => self.program_number(value, has_point, span),
            letter => self.push_word(Word {
                letter,
                value,
                has_point,
                span,
                expr: None,
            }),
        }
    }

    /// The block's N word.
    fn sequence_number(
        &mut self,
        value: f64,
        has_point: bool,
        span: Span,
    ) -> Result<(), ParseError> {
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
        Ok(())
    }

    /// An O word: the number of the program read so far, or the start of the next one.
    fn program_number(
        &mut self,
        value: f64,
        has_point: bool,
        span: Span,
    ) -> Result<(), ParseError> {
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
        let Mode::Whole(keep) = self.mode else {
            // the block read again after an O on its line: the O was read before
            return Ok(());
        };
        let programs = &mut self.reading.programs;
        let current = programs.last_mut().expect("always one program");
        if current.number.is_none() && current.blocks.is_empty() {
            current.number = Some(number);
            current.span = span;
            return Ok(());
        }
        if let Some(other) = programs.iter().find(|p| p.number == Some(number)) {
            return Err(ParseError::new(
                span,
                format!(
                    "program O{number:04} is defined twice (first at {})",
                    other.span
                ),
                "give each program in the file its own O number",
            ));
        }
        programs.push(ReadProgram::new(Some(number), span, keep));
        Ok(())
    }

    /// Add a word to the block: one of each address, except G and M.
    pub(super) fn push_word(&mut self, word: Word) -> Result<(), ParseError> {
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

    /// Whether the current block holds `M98` so far (as a word, or being read).
    pub(super) fn m98_read(&self) -> bool {
        let m98 = |letter: char, value: f64| letter == 'M' && value == 98.0;
        self.words
            .iter()
            .any(|w| w.expr.is_none() && m98(w.letter, w.value))
            || self.pending.as_ref().is_some_and(|p| {
                parse_number(self.number_text(p))
                    .is_some_and(|(v, point)| !point && m98(p.letter, v))
            })
    }
}
