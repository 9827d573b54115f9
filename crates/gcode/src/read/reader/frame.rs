//! The reader's tape and what is not code: the leader and the closing `%`, control bytes,
//! comments, `//` and prose after `;`, annotations outside parentheses, and the characters
//! no block holds (an error naming them, or the construct of a control latsim does not read).

use super::{Reader, Step};
use crate::read::comment::{comment_end, is_prose};
use crate::read::foreign;
use crate::read::reading::ParseError;
use crate::read::tape::{leader_end, leader_text, trailer_has_text, ControlKind};
use crate::{Note, Span};

impl Reader<'_> {
    /// The error for a `"`: no string literals in a block.
    pub(super) fn string_literal(span: Span) -> ParseError {
        ParseError::new(
            span,
            "string literal is not part of this dialect",
            "quoted text belongs in a comment ( … )",
        )
    }

    /// Skip the leader (spec/dialects.md §1), noting what it held.
    pub(super) fn skip_leader(&mut self) {
        let Some(end) = leader_end(self.src) else {
            return;
        };
        let text = leader_text(&self.src[..end]);
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

    /// A `%` in the text: the end of the tape, where a control reads no further.
    pub(super) fn percent(&mut self, span: Span) -> Result<(), ParseError> {
        self.finish_word()?;
        if !self.words.is_empty() || self.seq.is_some() {
            return Err(ParseError::new(
                span,
                "'%' inside a block",
                "'%' marks the start or end of the tape and stands on its own line",
            ));
        }
        self.skip_trailer(span);
        Ok(())
    }

    /// After the closing `%`: nothing more is read; anything but white space and control
    /// bytes there is noted.
    fn skip_trailer(&mut self, at: Span) {
        if trailer_has_text(&self.src[self.offset()..]) {
            self.note(
                at,
                "text after the closing % is not read (a control stops at %)",
            );
        }
        self.pos = self.src.len();
    }

    /// Count a dropped control byte.
    pub(super) fn control(&mut self, kind: ControlKind, span: Span) {
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

    /// The notes for the control bytes dropped.
    pub(super) fn control_notes(&mut self) {
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

    /// Skip to the end of the line (the newline itself ends the block). Returns the last span.
    pub(super) fn skip_line(&mut self) -> Span {
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

    /// A comment from `(` (already read), to its end as [`comment_end`] reads it: nested
    /// parentheses, an unclosed `(` and a `%` inside are noted. The first comment after an
    /// `M98` is kept (Haas `M98 (path)`).
    pub(super) fn skip_comment(&mut self, open: Span) {
        let rest = self.rest_of_line();
        let (end, nested) = comment_end(rest);
        if nested {
            self.note(open, "nested parentheses read as one comment: a FANUC control would end the comment at the first ')' and read the rest as code");
        }
        let body = &rest[..end.unwrap_or(rest.len())];
        if body.contains('%') && self.options.macros != Some(macro_b::Dialect::LinuxCnc) {
            // (LinuxCNC reads a file to its end: `%` in a comment is text, as in
            // `(debug, %.3f#1)`)
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
    }

    /// A `;`: the end of a block, and where the rest of the line is prose (a comment in
    /// another control's style), a comment.
    pub(super) fn semicolon(&mut self, span: Span) -> Result<Step, ParseError> {
        self.end_block()?;
        if self.found.is_some() {
            return Ok(Step::Found);
        }
        if self.options.macros == Some(macro_b::Dialect::LinuxCnc) {
            // LinuxCNC: the rest of the line is a comment, whatever it holds ([OV] "Comments")
            self.skip_line();
            return Ok(Step::Go);
        }
        let rest = self.rest_of_line();
        if self.pos < self.no_prose_before {
            // a part of a rest already found no prose (see the field)
        } else if !is_prose(rest) {
            if !rest.as_bytes().contains(&b'(') {
                self.no_prose_before = self.pos + rest.len();
            }
        } else {
            self.prose(span);
        }
        Ok(Step::Go)
    }

    /// Skip the prose after the `;` at `span`, with a note.
    fn prose(&mut self, span: Span) {
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
        if self.options.macros == Some(macro_b::Dialect::LinuxCnc) {
            // LinuxCNC's own comment (G-code overview, "Comments")
            return;
        }
        self.note(
            start.to(end),
            "text after ';' read as a comment (a Mach3/Fagor/Siemens-style comment: a FANUC control would read it as code); write it as ( … )",
        );
    }

    /// A non-ASCII character outside a comment: manuals print annotations after the block
    /// without parentheses (seed 003: `w-20 ; 精加工形狀程式段`). Read as a comment, noted.
    pub(super) fn annotation(&mut self, span: Span) -> Result<(), ParseError> {
        self.finish_word()?;
        let end = self.skip_line();
        self.reading.notes.push(Note {
            span: span.to(end),
            message: "text outside parentheses read as a comment; write it as ( … ) for a real controller".into(),
        });
        Ok(())
    }

    /// The error for a character no block holds, or for the construct of a control latsim
    /// does not read on its line.
    pub(super) fn unexpected(&self, span: Span, c: char) -> ParseError {
        if let Some(e) = self.foreign(span) {
            return e;
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
        ParseError::new(span, what, help)
    }

    /// The error naming the construct of a control latsim does not read (`LinuxCNC`, Okuma,
    /// …) on the line of `at`, if the line holds one.
    pub(super) fn foreign(&self, at: Span) -> Option<ParseError> {
        let at = (at.offset as usize).min(self.src.len());
        let start = self.src[..at].rfind('\n').map_or(0, |i| i + 1);
        let end = self.src[at..].find('\n').map_or(self.src.len(), |i| at + i);
        let found = foreign::construct(&self.src[start..end])?;
        let line = Span {
            line: self.line,
            column: 1,
            offset: start as u32,
            len: (end - start).min(u32::MAX as usize) as u32,
        };
        if self.options.macros == Some(macro_b::Dialect::LinuxCnc)
            && found.whose.starts_with("LinuxCNC")
        {
            // --control linuxcnc reads LinuxCNC's constructs: the error is the reader's own
            return None;
        }
        Some(ParseError::new(
            line,
            format!(
                "{} is {} syntax, not FANUC, GSK or Haas",
                found.what, found.whose
            ),
            format!(
                "latsim reads FANUC, GSK and Haas lathe programs, and LinuxCNC ones with --control linuxcnc; {} constructs are not supported",
                found.whose
            ),
        ))
    }
}
