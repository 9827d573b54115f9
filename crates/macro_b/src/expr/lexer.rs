//! The tokens of macro B text and the parser's lexing side: reading ahead, spans, and
//! errors at the token in hand.

use super::parser::Parser;
use crate::error::{MacroError, Result};
use crate::span::Span;

#[derive(Debug, Clone, PartialEq)]
pub(super) enum Tok {
    Hash,
    LBr,
    RBr,
    Comma,
    Plus,
    Minus,
    Star,
    Slash,
    Assign,
    /// A number and whether it had a decimal point.
    Num(f64, bool),
    /// A run of letters, upper-cased.
    Word(String),
    /// `( … )` text.
    Comment(String),
    /// `LinuxCNC`'s `<name>` (after `#` or `o`): lower case, blanks removed.
    Name(String),
    End,
}

#[derive(Debug, Clone)]
pub(super) struct Token {
    pub(super) tok: Tok,
    pub(super) start: usize,
    pub(super) end: usize,
}

/// The text being read and where it stands in the file.
pub(super) struct Src<'a> {
    pub(super) text: &'a str,
    pub(super) base: Span,
}

impl Src<'_> {
    pub(super) fn span(&self, start: usize, end: usize) -> Span {
        let before = &self.text[..start];
        let (line, column) = match before.rfind('\n') {
            None => (
                self.base.line,
                self.base.column + before.chars().count() as u32,
            ),
            Some(nl) => (
                self.base.line + before.matches('\n').count() as u32,
                before[nl + 1..].chars().count() as u32 + 1,
            ),
        };
        Span {
            line,
            column,
            offset: self.base.offset + start as u32,
            len: (end - start) as u32,
        }
    }
}

impl Parser<'_> {
    pub(super) fn lex_one(&mut self) -> Result<Token> {
        let text = self.src.text;
        let bytes = text.as_bytes();
        while self.at < text.len() {
            let c = text[self.at..].chars().next().expect("in range");
            if c.is_whitespace() || c == '\u{3000}' {
                self.at += c.len_utf8();
            } else {
                break;
            }
        }
        let start = self.at;
        let Some(c) = text[start..].chars().next() else {
            return Ok(Token {
                tok: Tok::End,
                start,
                end: start,
            });
        };
        let simple = |t: Tok| (t, start + 1);
        let (tok, end) =
            match c {
                '#' => simple(Tok::Hash),
                '[' => simple(Tok::LBr),
                ']' => simple(Tok::RBr),
                ',' => simple(Tok::Comma),
                '+' => simple(Tok::Plus),
                '-' => simple(Tok::Minus),
                '*' => simple(Tok::Star),
                '/' => simple(Tok::Slash),
                '=' => simple(Tok::Assign),
                ';' => (Tok::End, start),
                '<' => self.name(start)?,
                '(' => {
                    let close = text[start..].find(')').map(|i| start + i);
                    let end = close.map_or(text.len(), |i| i + 1);
                    let body = &text[start + 1..close.unwrap_or(text.len())];
                    (Tok::Comment(body.trim().to_string()), end)
                }
                c if c.is_ascii_digit() || c == '.' => {
                    let mut end = start;
                    let mut point = false;
                    while end < text.len() {
                        let b = bytes[end];
                        if b.is_ascii_digit() {
                            end += 1;
                        } else if b == b'.' && !point {
                            point = true;
                            end += 1;
                        } else {
                            break;
                        }
                    }
                    let s = &text[start..end];
                    let v = if s == "." {
                        None
                    } else {
                        s.parse::<f64>().ok()
                    };
                    match v {
                        Some(v) if s.len() <= 20 => (Tok::Num(v, point), end),
                        _ => return Err(MacroError::syntax(
                            self.src.span(start, end),
                            format!("malformed number '{s}'"),
                            "a number is digits with at most one decimal point, e.g. 17.5 or 100.",
                        )),
                    }
                }
                c if c.is_ascii_alphabetic() => {
                    let mut end = start;
                    while end < text.len() && bytes[end].is_ascii_alphabetic() {
                        end += 1;
                    }
                    (Tok::Word(text[start..end].to_ascii_uppercase()), end)
                }
                c => {
                    return Err(MacroError::syntax(
                        self.src.span(start, start + c.len_utf8()),
                        format!("unexpected character '{c}' in a macro expression"),
                        "expressions use # [ ] + - * / , numbers and macro words",
                    ))
                }
            };
        self.at = end;
        Ok(Token { tok, start, end })
    }

    /// `<name>` from the `<` at `start`: up to its `>`, blanks removed, lower case
    /// (`LinuxCNC`'s named parameters and o-word names, [OV] "Named Parameters").
    fn name(&self, start: usize) -> Result<(Tok, usize)> {
        let text = self.src.text;
        let Some(close) = text[start..].find('>').map(|i| start + i) else {
            return Err(MacroError::syntax(
                self.src.span(start, text.len()),
                "'<' without its '>'",
                "write a name as <name>, e.g. #<depth> or o<turn>",
            ));
        };
        let name: String = text[start + 1..close]
            .chars()
            .filter(|c| !c.is_whitespace())
            .flat_map(char::to_lowercase)
            .collect();
        if name.is_empty() {
            return Err(MacroError::syntax(
                self.src.span(start, close + 1),
                "an empty name <>",
                "write a name between < and >",
            ));
        }
        Ok((Tok::Name(name), close + 1))
    }

    pub(super) fn peek_n(&mut self, k: usize) -> Result<&Token> {
        while self.ahead.len() <= k {
            let t = self.lex_one()?;
            self.ahead.push(t);
        }
        Ok(&self.ahead[k])
    }

    pub(super) fn peek(&mut self) -> Result<&Tok> {
        Ok(&self.peek_n(0)?.tok)
    }

    pub(super) fn bump(&mut self) -> Result<Token> {
        self.peek_n(0)?;
        let t = self.ahead.remove(0);
        if t.tok != Tok::End {
            self.last_end = t.end;
        }
        Ok(t)
    }

    pub(super) fn span_of(&self, t: &Token) -> Span {
        self.src.span(t.start, t.end)
    }

    pub(super) fn span_from(&self, start: usize) -> Span {
        self.src.span(start, self.last_end.max(start))
    }

    pub(super) fn describe(t: &Tok) -> String {
        match t {
            Tok::Hash => "'#'".into(),
            Tok::LBr => "'['".into(),
            Tok::RBr => "']'".into(),
            Tok::Comma => "','".into(),
            Tok::Plus => "'+'".into(),
            Tok::Minus => "'-'".into(),
            Tok::Star => "'*'".into(),
            Tok::Slash => "'/'".into(),
            Tok::Assign => "'='".into(),
            Tok::Num(v, _) => format!("the number {v}"),
            Tok::Word(w) => format!("'{w}'"),
            Tok::Comment(_) => "a comment".into(),
            Tok::Name(n) => format!("<{n}>"),
            Tok::End => "the end of the block".into(),
        }
    }

    pub(super) fn error_here(
        &mut self,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> MacroError {
        let span = match self.peek_n(0) {
            Ok(t) => {
                let t = t.clone();
                self.span_of(&t)
            }
            Err(e) => return e,
        };
        MacroError::syntax(span, message, help)
    }
}
