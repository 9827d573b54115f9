//! The expression language of custom macro B and its statements, read from text with
//! spans (spec/dialects.md §5.3, §5.4, §5.6).
//!
//! Precedence, highest first; equal levels group left to right:
//!
//! | level | operators |
//! |---|---|
//! | 1 | `[ … ]` |
//! | 2 | functions, unary `+ -` |
//! | 3 | `* / AND MOD` |
//! | 4 | `+ - OR XOR` |
//! | 5 | `EQ NE GT GE LT LE` |

mod ast;
mod lexer;
mod parser;
mod statement;
#[cfg(test)]
mod tests;

pub use ast::{BinOp, Expr, ExprKind, Func, OKeyword, OLabel, Stmt, StmtKind, VarRef};

use crate::error::Result;
use crate::options::Options;
use crate::span::Span;
use lexer::Tok;
use parser::Parser;

/// Parse a whole expression. `base` is the span of the text's first character in the
/// program (line, column, byte offset); every node's span is placed from it.
pub fn parse_expr(text: &str, base: Span) -> Result<Expr> {
    let mut p = Parser::new(text, base);
    if *p.peek()? == Tok::End {
        return Err(p.error_here("empty expression", "write a value"));
    }
    let e = p.expr()?;
    p.expect_end("the expression")?;
    Ok(e)
}

/// Parse one macro statement (the text of one block without its N word):
/// `#i = expr`, `IF [c] GOTO n`, `IF [c] THEN #i = expr`, `WHILE [c] DO m`, `DO m`,
/// `END m`, `GOTO n`, block-form `IF [c] THEN` / `ELSE` / `ENDIF`. A `( … )` comment in
/// the text is kept as the message of an assignment (`#3000 = 1 (TOOL BROKEN)`).
pub fn parse_stmt(text: &str, base: Span, options: &Options) -> Result<Stmt> {
    let mut p = Parser::new(text, base);
    p.statement(options)
}

/// Parse the value of an NC address written after its letter: `#1`, `-#1`, `#[#1+2]`,
/// `[#2-0.5]`, `ROUND[#1]`, or a plain number. Returns the expression and how many bytes
/// of `text` it used, so the reader goes on after it (`X#1Z5.`: `#1`, 2 bytes).
pub fn parse_operand(text: &str, base: Span) -> Result<(Expr, usize)> {
    let mut p = Parser::new(text, base);
    let e = p.unary()?;
    Ok((e, p.last_end))
}

/// Whether a block's text (after its N word) is a macro statement rather than an NC block:
/// it starts with `#` or a statement keyword. The reader uses this to route the block.
pub fn starts_statement(text: &str) -> bool {
    let t = text.trim_start();
    if t.starts_with('#') {
        return true;
    }
    let word = &t[..t.bytes().take_while(u8::is_ascii_alphabetic).count()];
    ["IF", "WHILE", "WH", "DO", "END", "GOTO", "ELSE", "ENDIF"]
        .iter()
        .any(|k| k.eq_ignore_ascii_case(word))
}

/// [`starts_statement`] for `dialect`: under `LinuxCNC` also an o-word (`o100 sub`,
/// `o<name> call`, an `o` label followed by one of its keywords).
pub fn starts_statement_in(text: &str, dialect: crate::Dialect) -> bool {
    starts_statement(text) || (dialect == crate::Dialect::LinuxCnc && starts_o_word(text))
}

/// Whether the text starts with an o-word: `o`, a number or `<name>`, a word.
fn starts_o_word(text: &str) -> bool {
    let t = text.trim_start();
    let Some(rest) = t.strip_prefix(['o', 'O']) else {
        return false;
    };
    let rest = rest.trim_start_matches([' ', '\t']);
    let rest = if let Some(named) = rest.strip_prefix('<') {
        match named.split_once('>') {
            Some((_, after)) => after,
            None => return true, // the parser names the missing '>'
        }
    } else {
        let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
        if digits == 0 {
            return false;
        }
        &rest[digits..]
    };
    let rest = rest.trim_start_matches([' ', '\t']);
    // a keyword, or a word that is no address (`o1 frob`: the parser names it)
    rest.bytes().take_while(u8::is_ascii_alphabetic).count() >= 2
}
