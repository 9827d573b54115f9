//! The expression parser: precedence levels, operands, variables and function calls.

use super::ast::*;
use super::lexer::{Src, Tok, Token};
use crate::error::{ErrorKind, MacroError, Result};
use crate::options::MAX_BRACKET_DEPTH;
use crate::span::Span;

/// Most operators in one expression: far beyond real programs, and it keeps evaluation's
/// recursion shallow whatever the input.
const MAX_OPERATORS: usize = 200;

pub(super) struct Parser<'a> {
    pub(super) src: Src<'a>,
    /// Byte position of the lexer.
    pub(super) at: usize,
    /// Tokens read ahead and not yet consumed.
    pub(super) ahead: Vec<Token>,
    /// End of the last consumed token.
    pub(super) last_end: usize,
    pub(super) depth: usize,
    /// Operators read so far (bounds the tree's depth).
    pub(super) ops: usize,
}

pub(super) fn keyword_help() -> &'static str {
    "macro words are IF GOTO THEN WHILE DO END, the operators EQ NE GT GE LT LE AND OR XOR MOD, and the functions SIN COS TAN ASIN ACOS ATAN SQRT ABS ROUND FIX FUP LN EXP POW ADP BIN BCD (LinuxCNC: EXISTS)"
}

impl<'a> Parser<'a> {
    pub(super) fn new(text: &'a str, base: Span) -> Self {
        let base = if base.line == 0 {
            Span {
                line: 1,
                column: 1,
                ..base
            }
        } else {
            base
        };
        Self {
            src: Src { text, base },
            at: 0,
            ahead: Vec::new(),
            last_end: 0,
            depth: 0,
            ops: 0,
        }
    }
}

impl Parser<'_> {
    pub(super) fn expect_rbr(&mut self, open: &Token) -> Result<()> {
        if *self.peek()? == Tok::RBr {
            self.bump()?;
            self.depth -= 1;
            Ok(())
        } else {
            let found = Self::describe(&self.peek()?.clone());
            let open_span = self.span_of(open);
            Err(self.error_here(
                format!("expected ']' to close the '[' at {open_span}, found {found}"),
                "every '[' needs its ']'",
            ))
        }
    }

    pub(super) fn open_bracket(&mut self) -> Result<Token> {
        let t = self.bump()?;
        debug_assert_eq!(t.tok, Tok::LBr);
        self.depth += 1;
        if self.depth > MAX_BRACKET_DEPTH {
            return Err(MacroError::new(
                ErrorKind::BracketNesting,
                self.span_of(&t),
                format!("brackets nested {} deep", self.depth),
                format!("at most {MAX_BRACKET_DEPTH} levels of [ ] (function brackets included); compute a part into a variable first"),
            ));
        }
        Ok(t)
    }

    /// Level 5 down to level 3, then unary.
    pub(super) fn expr(&mut self) -> Result<Expr> {
        self.level(5)
    }

    pub(super) fn peek_binop(&mut self) -> Result<Option<BinOp>> {
        Ok(match self.peek()? {
            Tok::Star => Some(BinOp::Mul),
            Tok::Slash => Some(BinOp::Div),
            Tok::Plus => Some(BinOp::Add),
            Tok::Minus => Some(BinOp::Sub),
            Tok::Word(w) => BinOp::from_word(w),
            _ => None,
        })
    }

    pub(super) fn count_op(&mut self, t: &Token) -> Result<()> {
        self.ops += 1;
        if self.ops > MAX_OPERATORS {
            return Err(MacroError::syntax(
                self.span_of(t),
                format!("more than {MAX_OPERATORS} operators in one expression"),
                "split the computation over several assignments",
            ));
        }
        Ok(())
    }

    pub(super) fn level(&mut self, level: u8) -> Result<Expr> {
        if level < 3 {
            return self.unary();
        }
        let mut lhs = self.level(level - 1)?;
        while let Some(op) = self.peek_binop()? {
            if op.level() != level {
                break;
            }
            let t = self.bump()?;
            self.count_op(&t)?;
            let rhs = self.level(level - 1)?;
            let span = lhs.span.to(rhs.span);
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            };
        }
        Ok(lhs)
    }

    pub(super) fn unary(&mut self) -> Result<Expr> {
        match self.peek()? {
            Tok::Minus | Tok::Plus => {
                let t = self.bump()?;
                self.count_op(&t)?;
                let e = self.unary()?;
                let span = self.span_of(&t).to(e.span);
                let kind = if t.tok == Tok::Minus {
                    ExprKind::Neg(Box::new(e))
                } else {
                    ExprKind::Pos(Box::new(e))
                };
                Ok(Expr { kind, span })
            }
            _ => self.primary(),
        }
    }

    pub(super) fn var_ref(&mut self) -> Result<(VarRef, Span)> {
        let hash = self.bump()?;
        debug_assert_eq!(hash.tok, Tok::Hash);
        let r = match self.peek()?.clone() {
            Tok::Num(v, point) => {
                let t = self.bump()?;
                if point || v.fract() != 0.0 || v > f64::from(u32::MAX) {
                    return Err(MacroError::syntax(
                        self.span_of(&hash).to(self.span_of(&t)),
                        format!("#{v}: a variable number is a whole number"),
                        "write the number without a decimal point, e.g. #1, or #[expr] for a computed number",
                    ));
                }
                VarRef::Direct(v as u32)
            }
            Tok::LBr => {
                let open = self.open_bracket()?;
                let e = self.expr()?;
                self.expect_rbr(&open)?;
                VarRef::Indirect(Box::new(e))
            }
            Tok::Name(name) => {
                self.bump()?;
                VarRef::Named(name)
            }
            Tok::Hash => {
                return Err(
                    self.error_here("'##' is not valid", "write an indirect reference as #[#1]")
                )
            }
            other => {
                let found = Self::describe(&other);
                return Err(self.error_here(
                    format!(
                        "'#' must be followed by a variable number or [expression], found {found}"
                    ),
                    "write #1, #100 or #[#1+1]",
                ));
            }
        };
        Ok((r, self.span_from(hash.start)))
    }

    pub(super) fn primary(&mut self) -> Result<Expr> {
        let t = self.peek_n(0)?.clone();
        match &t.tok {
            Tok::Num(v, _) => {
                self.bump()?;
                Ok(Expr::number(*v, self.span_of(&t)))
            }
            Tok::Hash => {
                let (r, span) = self.var_ref()?;
                Ok(Expr {
                    kind: ExprKind::Var(r),
                    span,
                })
            }
            Tok::LBr => {
                let open = self.open_bracket()?;
                let e = self.expr()?;
                self.expect_rbr(&open)?;
                Ok(Expr {
                    kind: ExprKind::Group(Box::new(e)),
                    span: self.span_from(t.start),
                })
            }
            Tok::Word(w) => match Func::from_name(w) {
                Some(f) => self.call(f, &t),
                None => Err(MacroError::syntax(
                    self.span_of(&t),
                    format!("'{w}' is not a macro function"),
                    keyword_help(),
                )),
            },
            other => {
                let found = Self::describe(other);
                Err(self.error_here(
                    format!("expected a number, a #variable, '[' or a function, found {found}"),
                    "complete the expression",
                ))
            }
        }
    }

    pub(super) fn call(&mut self, f: Func, name: &Token) -> Result<Expr> {
        self.bump()?;
        if *self.peek()? != Tok::LBr {
            return Err(self.error_here(
                format!("{} needs its argument in brackets", f.name()),
                format!("write {}[…]", f.name()),
            ));
        }
        let open = self.open_bracket()?;
        let mut args = vec![self.expr()?];
        if f == Func::Exists && !matches!(&args[0].kind, ExprKind::Var(VarRef::Named(_))) {
            return Err(MacroError::syntax(
                args[0].span,
                "EXISTS takes a named parameter",
                "write EXISTS[#<name>]",
            ));
        }
        if *self.peek()? == Tok::Comma {
            if !matches!(f, Func::Atan | Func::Pow) {
                return Err(self.error_here(
                    format!("{} takes one argument", f.name()),
                    "remove the second argument",
                ));
            }
            self.bump()?;
            args.push(self.expr()?);
        }
        self.expect_rbr(&open)?;
        // ATAN[a]/[b]: the two-argument form
        if f == Func::Atan
            && args.len() == 1
            && self.peek_n(0)?.tok == Tok::Slash
            && self.peek_n(1)?.tok == Tok::LBr
        {
            self.bump()?;
            let open = self.open_bracket()?;
            args.push(self.expr()?);
            self.expect_rbr(&open)?;
        }
        if f == Func::Pow && args.len() != 2 {
            return Err(MacroError::syntax(
                self.span_from(name.start),
                "POW takes two arguments",
                "write POW[a,b]",
            ));
        }
        Ok(Expr {
            kind: ExprKind::Call(f, args),
            span: self.span_from(name.start),
        })
    }

    pub(super) fn expect_end(&mut self, what: &str) -> Result<()> {
        loop {
            match self.peek()? {
                Tok::Comment(_) => {
                    self.bump()?;
                }
                Tok::End => return Ok(()),
                other => {
                    let found = Self::describe(&other.clone());
                    return Err(self.error_here(
                        format!("unexpected {found} after {what}"),
                        "end the statement here, or put the rest in brackets [ ]",
                    ));
                }
            }
        }
    }

    pub(super) fn word_is(&mut self, w: &str) -> Result<bool> {
        Ok(matches!(self.peek()?, Tok::Word(x) if x == w))
    }

    /// `[cond]` after IF / WHILE: the brackets are required.
    pub(super) fn condition(&mut self, keyword: &str) -> Result<Expr> {
        if *self.peek()? != Tok::LBr {
            return Err(self.error_here(
                format!("{keyword} needs its condition in brackets"),
                format!("write {keyword} [#1 GT 0] …"),
            ));
        }
        self.primary()
    }

    pub(super) fn loop_id(&mut self, keyword: &str) -> Result<u8> {
        let t = self.peek_n(0)?.clone();
        match t.tok {
            Tok::Num(v, false) if (1.0..=3.0).contains(&v) && v.fract() == 0.0 => {
                self.bump()?;
                Ok(v as u8)
            }
            Tok::Num(v, _) => Err(MacroError::new(
                ErrorKind::LoopNesting,
                self.span_of(&t),
                format!("{keyword} {v}: loop numbers are 1, 2 and 3"),
                format!("write {keyword}1, {keyword}2 or {keyword}3"),
            )),
            other => {
                let found = Self::describe(&other);
                Err(self.error_here(
                    format!("{keyword} needs a loop number, found {found}"),
                    format!("write {keyword}1, {keyword}2 or {keyword}3"),
                ))
            }
        }
    }

    /// A `GOTO` target: `n`, `#i`, `[expr]`.
    pub(super) fn goto_target(&mut self) -> Result<Expr> {
        match self.peek()? {
            Tok::Num(..) | Tok::Hash | Tok::LBr => self.primary(),
            other => {
                let found = Self::describe(&other.clone());
                Err(self.error_here(
                    format!("GOTO needs a sequence number, found {found}"),
                    "write GOTO 10, GOTO #1 or GOTO [#1+10]",
                ))
            }
        }
    }
}
