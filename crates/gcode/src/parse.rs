//! The reader: one pass over the characters, tracking line and column.
//!
//! Lexical rules (spec/language.md): a block ends at a newline or `;`; letters are
//! case-insensitive; white space is ignored everywhere, also inside a word (`Q5 000`);
//! comments are `( )`, full-width `（ ）` and `//` to the end of the line; `%` lines mark
//! the tape; `/` at the start of a block is block delete.

use crate::{Block, Note, Program, Span, Subprogram, Word};

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
    fn new(span: Span, message: impl Into<String>, help: impl Into<String>) -> Self {
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

/// Read a whole program text.
pub fn parse(source: &str) -> Result<Program, ParseError> {
    Reader::new(source).run()
}

struct PendingWord {
    letter: char,
    start: Span,
    end: Span,
    text: String,
}

struct Reader<'a> {
    chars: std::iter::Peekable<std::str::CharIndices<'a>>,
    line: u32,
    column: u32,
    program: Program,
    words: Vec<Word>,
    seq: Option<(u32, Span)>,
    block_delete: bool,
    block_start: Option<Span>,
    block_end: Span,
    pending: Option<PendingWord>,
}

impl<'a> Reader<'a> {
    fn new(src: &'a str) -> Self {
        Self {
            chars: src.char_indices().peekable(),
            line: 1,
            column: 0,
            program: Program {
                programs: vec![Subprogram {
                    number: None,
                    span: Span::default(),
                    blocks: vec![],
                }],
                notes: vec![],
            },
            words: vec![],
            seq: None,
            block_delete: false,
            block_start: None,
            block_end: Span::default(),
            pending: None,
        }
    }

    fn next(&mut self) -> Option<(Span, char)> {
        let (offset, c) = self.chars.next()?;
        self.column += 1;
        let span = Span {
            line: self.line,
            column: self.column,
            offset,
            len: c.len_utf8(),
        };
        if c == '\n' {
            self.line += 1;
            self.column = 0;
        }
        Some((span, c))
    }

    fn peek(&mut self) -> Option<char> {
        self.chars.peek().map(|&(_, c)| c)
    }

    fn mark(&mut self, span: Span) {
        if self.block_start.is_none() {
            self.block_start = Some(span);
        }
        self.block_end = span;
    }

    fn run(mut self) -> Result<Program, ParseError> {
        while let Some((span, c)) = self.next() {
            match c {
                '\n' | ';' => self.end_block()?,
                ' ' | '\t' | '\r' | '\u{3000}' | '\u{feff}' => {}
                '(' | '（' => self.skip_comment(span)?,
                '/' if self.peek() == Some('/') => {
                    self.finish_word()?;
                    self.skip_line();
                }
                '/' => {
                    if self.pending.is_some() || !self.words.is_empty() || self.seq.is_some() {
                        return Err(ParseError::new(
                            span,
                            "'/' in the middle of a block",
                            "block delete '/' must be the first character of a block",
                        ));
                    }
                    self.block_delete = true;
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
                    self.skip_line();
                }
                c if c.is_ascii_alphabetic() => {
                    self.finish_word()?;
                    self.pending = Some(PendingWord {
                        letter: c.to_ascii_uppercase(),
                        start: span,
                        end: span,
                        text: String::new(),
                    });
                    self.mark(span);
                }
                c if c.is_ascii_digit() || c == '.' || c == '+' || c == '-' => {
                    match &mut self.pending {
                        Some(p) => {
                            if p.text.len() >= MAX_NUMBER_CHARS {
                                return Err(ParseError::new(
                                    p.start.to(span),
                                    format!("number of address {} is too long", p.letter),
                                    NUMBER_HELP,
                                ));
                            }
                            p.text.push(c);
                            p.end = span;
                            self.block_end = span;
                        }
                        None => return Err(ParseError::new(
                            span,
                            format!("number '{c}' without an address letter"),
                            "every number belongs to a word such as X100. or Z-5 — add the letter",
                        )),
                    }
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
                    let (what, help) = if c.is_control() {
                        (
                            format!("unexpected control character U+{:04X}", c as u32),
                            "this does not look like a program text file; check the file you gave",
                        )
                    } else {
                        (
                            format!("unexpected character '{c}'"),
                            "only address letters, numbers, ';', '/', '%' and comments ( ) belong in a block (macro variables # are not supported)",
                        )
                    };
                    return Err(ParseError::new(span, what, help));
                }
            }
        }
        self.end_block()?;
        self.program
            .programs
            .retain(|p| p.number.is_some() || !p.blocks.is_empty());
        Ok(self.program)
    }

    /// Skip to the end of the line (the newline itself ends the block). Returns the last span.
    fn skip_line(&mut self) -> Span {
        let mut last = Span {
            line: self.line,
            column: self.column,
            offset: 0,
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

    fn skip_comment(&mut self, open: Span) -> Result<(), ParseError> {
        while let Some(c) = self.peek() {
            if c == '\n' {
                break;
            }
            self.next();
            if c == ')' || c == '）' {
                return Ok(());
            }
        }
        Err(ParseError::new(
            open,
            "comment not closed on this line",
            "close the comment with ')' before the end of the line",
        ))
    }

    fn finish_word(&mut self) -> Result<(), ParseError> {
        let Some(p) = self.pending.take() else {
            return Ok(());
        };
        let span = p.start.to(p.end);
        let (value, has_point) = parse_number(&p.text).ok_or_else(|| {
            if p.text.is_empty() {
                ParseError::new(
                    span,
                    format!("address {} has no value", p.letter),
                    format!("write a number right after {}, e.g. {}0", p.letter, p.letter),
                )
            } else {
                ParseError::new(
                    span,
                    format!("malformed number '{}' after {}", p.text, p.letter),
                    "a number is an optional sign, digits and at most one decimal point, e.g. -17.639 or 100.",
                )
            }
        })?;
        let whole_digits = p
            .text
            .split('.')
            .next()
            .unwrap_or("")
            .trim_start_matches(['+', '-'])
            .trim_start_matches('0')
            .len();
        if whole_digits > MAX_WHOLE_DIGITS {
            return Err(ParseError::new(
                span,
                format!(
                    "number of address {} has {whole_digits} digits before the point",
                    p.letter
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
                self.seq = Some((whole(value, has_point, span, 'N')?, span));
            }
            'O' => {
                let number = whole(value, has_point, span, 'O')?;
                if !self.words.is_empty() || self.seq.is_some() {
                    return Err(ParseError::new(
                        span,
                        "program number O inside a block",
                        "put O and its number on a line of its own, before the program's blocks",
                    ));
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
                    self.program.programs.push(Subprogram {
                        number: Some(number),
                        span,
                        blocks: vec![],
                    });
                }
            }
            letter => {
                if letter != 'G' && letter != 'M' {
                    if let Some(first) = self.words.iter().find(|w| w.letter == letter) {
                        return Err(ParseError::new(
                            span,
                            format!(
                                "address {letter} given twice in one block (first at {})",
                                first.span
                            ),
                            format!("remove one of the two {letter} words"),
                        ));
                    }
                }
                self.words.push(Word {
                    letter,
                    value,
                    has_point,
                    span,
                });
            }
        }
        Ok(())
    }

    fn end_block(&mut self) -> Result<(), ParseError> {
        self.finish_word()?;
        if let Some(start) = self.block_start.take() {
            let words = std::mem::take(&mut self.words);
            let seq = self.seq.take();
            let block_delete = std::mem::replace(&mut self.block_delete, false);
            if !words.is_empty() || seq.is_some() {
                let span = start.to(self.block_end);
                let block = Block {
                    words,
                    seq: seq.map(|s| s.0),
                    seq_span: seq.map(|s| s.1),
                    block_delete,
                    span,
                };
                self.program
                    .programs
                    .last_mut()
                    .expect("always one program")
                    .blocks
                    .push(block);
            }
        }
        self.words.clear();
        self.seq = None;
        self.block_delete = false;
        Ok(())
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

/// `[+-]? (digits [. digits*] | . digits)`; returns the value and whether a point was written.
fn parse_number(text: &str) -> Option<(f64, bool)> {
    let body = text.strip_prefix(['+', '-']).unwrap_or(text);
    let mut digits = 0;
    let mut points = 0;
    for c in body.chars() {
        match c {
            '0'..='9' => digits += 1,
            '.' => points += 1,
            _ => return None,
        }
    }
    if digits == 0 || points > 1 {
        return None;
    }
    let value: f64 = text.parse().ok()?;
    value.is_finite().then_some((value, points == 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(src: &str) -> Vec<(char, f64)> {
        parse(src).unwrap().programs[0]
            .blocks
            .iter()
            .flat_map(|b| b.words.iter().map(|w| (w.letter, w.value)))
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
        let b = &p.programs[0].blocks[0];
        assert!(b.words[0].has_point);
        assert!(!b.words[1].has_point);
    }

    #[test]
    fn blocks_split_on_semicolon_and_newline() {
        let p = parse("M30;G0 X1\nZ2;;\n\n").unwrap();
        assert_eq!(p.programs[0].blocks.len(), 3);
        assert_eq!(p.programs[0].blocks[2].span.line, 2);
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
        assert_eq!(p.programs[0].blocks[0].seq, Some(10));
        assert_eq!(p.find(2).unwrap().blocks.len(), 2);
    }

    #[test]
    fn block_delete() {
        let p = parse("/G0 X1\nG0 X2").unwrap();
        assert!(p.programs[0].blocks[0].block_delete);
        assert!(!p.programs[0].blocks[1].block_delete);
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
        let e = parse("G1 (open").unwrap_err();
        assert!(e.message.contains("comment"));
        let e = parse("\u{0}\u{1}binary").unwrap_err();
        assert!(e.message.contains("control"));
        let e = parse("G1 X1-2").unwrap_err();
        assert!(e.message.contains("malformed"));
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let e = parse("（中文）X").unwrap_err();
        assert_eq!(e.span.column, 5);
    }

    #[test]
    fn g_code_tenths() {
        let p = parse("G75.1 G01 G0").unwrap();
        let codes: Vec<_> = p.programs[0].blocks[0]
            .words
            .iter()
            .map(|w| w.code_tenths())
            .collect();
        assert_eq!(codes, vec![Some(751), Some(10), Some(0)]);
    }
}
