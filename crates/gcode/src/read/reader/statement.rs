//! Custom macro B in a block: a statement (`#1 = …`, `IF`, `WHILE`, `GOTO`) or a word whose
//! value is an expression (`X#1`, `Z[#2-0.5]`), read by the `macro_b` crate from the text.

use super::Reader;
use crate::read::expr::{block_text, expression_follows};
use crate::read::reading::ParseError;
use crate::{Span, Word};
use macro_b::Dialect;

impl Reader<'_> {
    /// Whether a macro statement starts at `span` (macro B on, nothing but an N word read
    /// of the block).
    pub(super) fn statement_starts(&self, span: Span) -> bool {
        self.options.macros.is_some_and(|dialect| {
            self.at_statement_start()
                && macro_b::starts_statement_in(&self.src[span.offset as usize..], dialect)
        })
    }

    /// A macro statement from `start` (already read) to the end of the block.
    pub(super) fn statement(&mut self, start: Span) -> Result<(), ParseError> {
        self.mark(start);
        let text = block_text(self.src, start.offset as usize).trim_end();
        let options = match self.options.macros {
            Some(Dialect::Haas) => macro_b::Options::haas(),
            Some(Dialect::LinuxCnc) => macro_b::Options::linuxcnc(),
            _ => macro_b::Options::fanuc(),
        };
        self.named_only_under_linuxcnc(text, start)?;
        let stmt =
            macro_b::parse_stmt(text, start, &options).map_err(|e| self.macro_error(e, start))?;
        // Haas `IF [cond] THEN <NC block>`: the block's words are read as words
        let end = match &stmt.kind {
            macro_b::StmtKind::IfThenBlock { text_span, .. } => text_span.offset as usize,
            _ => start.offset as usize + text.len(),
        };
        self.consume_to(end);
        self.stmt = Some(stmt);
        Ok(())
    }

    /// `LinuxCNC`'s named parameters (`#<name>`, outside comments) are an error under
    /// another control: the error naming `LinuxCNC`'s construct.
    fn named_only_under_linuxcnc(&self, text: &str, at: Span) -> Result<(), ParseError> {
        if self.options.macros == Some(Dialect::LinuxCnc) {
            return Ok(());
        }
        let mut depth = 0usize;
        let mut prev = ' ';
        for c in text.chars() {
            match c {
                '(' => depth += 1,
                ')' => depth = depth.saturating_sub(1),
                '<' if depth == 0 && prev == '#' => {
                    return Err(self.foreign(at).unwrap_or_else(|| {
                        ParseError::new(
                            at,
                            "a named parameter #<…> is LinuxCNC syntax",
                            "run with --control linuxcnc, or use numbered variables",
                        )
                    }))
                }
                _ => {}
            }
            if !c.is_whitespace() {
                prev = c;
            }
        }
        Ok(())
    }

    /// Whether the value after the address letter just read is a macro expression.
    pub(super) fn expression_follows(&self) -> bool {
        expression_follows(self.src, self.offset())
    }

    /// An address whose value is a macro expression (`X#1`, `Z[#2-0.5]`, `G#10`).
    pub(super) fn expression_word(&mut self, letter: char, at: Span) -> Result<(), ParseError> {
        if matches!(letter, 'N' | 'O') {
            return Err(ParseError::new(
                at,
                format!("{letter} needs a number, not a macro expression"),
                format!("write {letter} as digits only, e.g. {letter}14"),
            ));
        }
        let base = self.next_span();
        let text = block_text(self.src, base.offset as usize);
        let (expr, used) =
            macro_b::parse_operand(text, base).map_err(|e| self.macro_error(e, at))?;
        self.named_only_under_linuxcnc(&text[..used], at)?;
        let end = self.consume_to(base.offset as usize + used).unwrap_or(at);
        self.push_word(Word {
            letter,
            value: 0.0,
            has_point: true,
            span: at.to(end),
            expr: Some(Box::new(expr)),
        })
    }

    /// A macro statement or expression that does not read: the construct of another
    /// control on its line when it holds one (`LinuxCNC`'s `#<name> = …`), else the error.
    fn macro_error(&self, e: macro_b::MacroError, at: Span) -> ParseError {
        self.foreign(at).unwrap_or_else(|| e.into())
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
}
