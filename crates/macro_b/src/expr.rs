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

use std::fmt;

use crate::span::Span;

use crate::error::{ErrorKind, MacroError, Result};
use crate::options::{Options, MAX_BRACKET_DEPTH};

/// A variable reference: `#12` or `#[expr]`.
#[derive(Debug, Clone, PartialEq)]
pub enum VarRef {
    /// `#n`.
    Direct(u32),
    /// `#[expr]`; the expression is rounded to an integer when read.
    Indirect(Box<Expr>),
}

/// A macro function (spec §5.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    /// `SIN`, degrees.
    Sin,
    /// `COS`, degrees.
    Cos,
    /// `TAN`, degrees.
    Tan,
    /// `ASIN`, result −90…90.
    Asin,
    /// `ACOS`, result 0…180.
    Acos,
    /// `ATAN[a]`, `ATAN[a]/[b]`, `ATAN[a,b]`.
    Atan,
    /// `SQRT`.
    Sqrt,
    /// `ABS`.
    Abs,
    /// `ROUND`: halves away from zero.
    Round,
    /// `FIX`: toward zero.
    Fix,
    /// `FUP`: away from zero.
    Fup,
    /// `LN`.
    Ln,
    /// `EXP`.
    Exp,
    /// `POW[a,b]`.
    Pow,
    /// `ADP`: add the decimal point.
    Adp,
    /// `BIN`: BCD to binary.
    Bin,
    /// `BCD`: binary to BCD.
    Bcd,
}

impl Func {
    /// The function named by an upper-case word.
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "SIN" => Self::Sin,
            "COS" => Self::Cos,
            "TAN" => Self::Tan,
            "ASIN" => Self::Asin,
            "ACOS" => Self::Acos,
            "ATAN" => Self::Atan,
            "SQRT" => Self::Sqrt,
            "ABS" => Self::Abs,
            "ROUND" => Self::Round,
            "FIX" => Self::Fix,
            "FUP" => Self::Fup,
            "LN" => Self::Ln,
            "EXP" => Self::Exp,
            "POW" => Self::Pow,
            "ADP" => Self::Adp,
            "BIN" => Self::Bin,
            "BCD" => Self::Bcd,
            _ => return None,
        })
    }

    /// The name as written.
    pub fn name(self) -> &'static str {
        match self {
            Self::Sin => "SIN",
            Self::Cos => "COS",
            Self::Tan => "TAN",
            Self::Asin => "ASIN",
            Self::Acos => "ACOS",
            Self::Atan => "ATAN",
            Self::Sqrt => "SQRT",
            Self::Abs => "ABS",
            Self::Round => "ROUND",
            Self::Fix => "FIX",
            Self::Fup => "FUP",
            Self::Ln => "LN",
            Self::Exp => "EXP",
            Self::Pow => "POW",
            Self::Adp => "ADP",
            Self::Bin => "BIN",
            Self::Bcd => "BCD",
        }
    }
}

/// A binary operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `AND`: bitwise on the integer parts.
    And,
    /// `MOD`: remainder.
    Mod,
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `OR`: bitwise on the integer parts.
    Or,
    /// `XOR`: bitwise on the integer parts.
    Xor,
    /// `EQ`
    Eq,
    /// `NE`
    Ne,
    /// `GT`
    Gt,
    /// `GE`
    Ge,
    /// `LT`
    Lt,
    /// `LE`
    Le,
}

impl BinOp {
    /// The precedence level of spec §5.3 (3 binds tighter than 4, 4 than 5).
    pub fn level(self) -> u8 {
        match self {
            Self::Mul | Self::Div | Self::And | Self::Mod => 3,
            Self::Add | Self::Sub | Self::Or | Self::Xor => 4,
            Self::Eq | Self::Ne | Self::Gt | Self::Ge | Self::Lt | Self::Le => 5,
        }
    }

    /// The operator as written.
    pub fn symbol(self) -> &'static str {
        match self {
            Self::Mul => "*",
            Self::Div => "/",
            Self::And => "AND",
            Self::Mod => "MOD",
            Self::Add => "+",
            Self::Sub => "-",
            Self::Or => "OR",
            Self::Xor => "XOR",
            Self::Eq => "EQ",
            Self::Ne => "NE",
            Self::Gt => "GT",
            Self::Ge => "GE",
            Self::Lt => "LT",
            Self::Le => "LE",
        }
    }

    fn from_word(w: &str) -> Option<Self> {
        Some(match w {
            "AND" => Self::And,
            "MOD" => Self::Mod,
            "OR" => Self::Or,
            "XOR" => Self::Xor,
            "EQ" => Self::Eq,
            "NE" => Self::Ne,
            "GT" => Self::Gt,
            "GE" => Self::Ge,
            "LT" => Self::Lt,
            "LE" => Self::Le,
            _ => return None,
        })
    }
}

/// The shape of an expression node.
#[derive(Debug, Clone, PartialEq)]
pub enum ExprKind {
    /// A number as written (`2` is 2.0 inside an expression).
    Num(f64),
    /// A variable.
    Var(VarRef),
    /// `[ … ]`: keeps vacancy (`X[#1]` with #1 vacant drops the address).
    Group(Box<Expr>),
    /// Unary minus. **Interpretation**: `-#1` with #1 vacant stays vacant, so `X-#1` drops
    /// the address like `X#1`.
    Neg(Box<Expr>),
    /// Unary plus.
    Pos(Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// A function call with its one or two arguments.
    Call(Func, Vec<Expr>),
}

/// An expression with the span of its text.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where it is written.
    pub span: Span,
}

impl Expr {
    /// A number literal (for callers building expressions, e.g. a plain word value).
    pub fn number(v: f64, span: Span) -> Self {
        Self {
            kind: ExprKind::Num(v),
            span,
        }
    }

    /// Add `by` to the byte offset of every span in it (a file placed after another).
    pub fn shift_spans(&mut self, by: u32) {
        self.span.offset += by;
        match &mut self.kind {
            ExprKind::Num(_) | ExprKind::Var(VarRef::Direct(_)) => {}
            ExprKind::Var(VarRef::Indirect(e))
            | ExprKind::Group(e)
            | ExprKind::Neg(e)
            | ExprKind::Pos(e) => e.shift_spans(by),
            ExprKind::Binary(_, a, b) => {
                a.shift_spans(by);
                b.shift_spans(by);
            }
            ExprKind::Call(_, args) => args.iter_mut().for_each(|a| a.shift_spans(by)),
        }
    }

    /// The variables it names (`#n`, also in the index of a `#[ … ]`), in the order
    /// written, each once: what a condition depends on, for messages.
    pub fn variables(&self) -> Vec<u32> {
        let mut found = Vec::new();
        self.collect_variables(&mut found);
        found
    }

    fn collect_variables(&self, found: &mut Vec<u32>) {
        match &self.kind {
            ExprKind::Num(_) => {}
            ExprKind::Var(VarRef::Direct(n)) => {
                if !found.contains(n) {
                    found.push(*n);
                }
            }
            ExprKind::Var(VarRef::Indirect(e))
            | ExprKind::Group(e)
            | ExprKind::Neg(e)
            | ExprKind::Pos(e) => e.collect_variables(found),
            ExprKind::Binary(_, a, b) => {
                a.collect_variables(found);
                b.collect_variables(found);
            }
            ExprKind::Call(_, args) => args.iter().for_each(|a| a.collect_variables(found)),
        }
    }
}

impl fmt::Display for VarRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Direct(n) => write!(f, "#{n}"),
            Self::Indirect(e) => write!(f, "#[{e}]"),
        }
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            ExprKind::Num(v) => write!(f, "{v}"),
            ExprKind::Var(v) => write!(f, "{v}"),
            ExprKind::Group(e) => write!(f, "[{e}]"),
            ExprKind::Neg(e) => write!(f, "-{e}"),
            ExprKind::Pos(e) => write!(f, "+{e}"),
            ExprKind::Binary(op, a, b) => {
                if op.symbol().len() > 1 {
                    write!(f, "{a} {} {b}", op.symbol())
                } else {
                    write!(f, "{a}{}{b}", op.symbol())
                }
            }
            ExprKind::Call(Func::Atan, args) if args.len() == 2 => {
                write!(f, "ATAN[{}]/[{}]", args[0], args[1])
            }
            ExprKind::Call(func, args) => {
                write!(f, "{}[", func.name())?;
                for (i, a) in args.iter().enumerate() {
                    if i > 0 {
                        f.write_str(",")?;
                    }
                    write!(f, "{a}")?;
                }
                f.write_str("]")
            }
        }
    }
}

/// A macro statement (spec §5.6).
#[derive(Debug, Clone, PartialEq)]
pub enum StmtKind {
    /// `#i = expr`, with the comment written after it (the message of `#3000`/`#3006`).
    Assign {
        /// The variable set.
        target: VarRef,
        /// Span of the target.
        target_span: Span,
        /// The value.
        value: Expr,
        /// Text of a `( … )` comment in the statement, without the parentheses.
        comment: Option<String>,
    },
    /// `IF [cond] GOTO n`.
    IfGoto {
        /// The condition.
        cond: Expr,
        /// The target sequence number (rounded when computed).
        target: Expr,
    },
    /// `IF [cond] THEN #i = expr`.
    IfThen {
        /// The condition.
        cond: Expr,
        /// The assignment run when the condition holds.
        then: Box<Stmt>,
    },
    /// Haas: `IF [cond] THEN <NC block>`; the block text is left to the reader.
    IfThenBlock {
        /// The condition.
        cond: Expr,
        /// The NC block's text as written.
        text: String,
        /// Where the NC block's text stands.
        text_span: Span,
    },
    /// Block form `IF [cond] THEN` (nothing after `THEN`), closed by `ENDIF`.
    IfBlock {
        /// The condition.
        cond: Expr,
    },
    /// `ELSE` of a block-form `IF`.
    Else,
    /// `ENDIF` of a block-form `IF`.
    EndIf,
    /// `WHILE [cond] DO m` (Haas also `WH`).
    While {
        /// The condition.
        cond: Expr,
        /// The loop number m, 1–3.
        id: u8,
    },
    /// `DO m` without `WHILE`: loops forever (until a `GOTO` leaves it).
    Do {
        /// The loop number m, 1–3.
        id: u8,
    },
    /// `END m`.
    End {
        /// The loop number m, 1–3.
        id: u8,
    },
    /// `GOTO n`, `GOTO #i`, `GOTO [expr]`.
    Goto {
        /// The target sequence number.
        target: Expr,
    },
}

/// A macro statement with the span of its text.
#[derive(Debug, Clone, PartialEq)]
pub struct Stmt {
    /// What it is.
    pub kind: StmtKind,
    /// Where it is written.
    pub span: Span,
}

impl Stmt {
    /// The condition it tests (`IF`, `WHILE`), if any.
    pub fn condition(&self) -> Option<&Expr> {
        match &self.kind {
            StmtKind::IfGoto { cond, .. }
            | StmtKind::IfThen { cond, .. }
            | StmtKind::IfThenBlock { cond, .. }
            | StmtKind::IfBlock { cond }
            | StmtKind::While { cond, .. } => Some(cond),
            _ => None,
        }
    }

    /// Add `by` to the byte offset of every span in it (a file placed after another).
    pub fn shift_spans(&mut self, by: u32) {
        self.span.offset += by;
        match &mut self.kind {
            StmtKind::Assign {
                target,
                target_span,
                value,
                ..
            } => {
                if let VarRef::Indirect(e) = target {
                    e.shift_spans(by);
                }
                target_span.offset += by;
                value.shift_spans(by);
            }
            StmtKind::IfGoto { cond, target } => {
                cond.shift_spans(by);
                target.shift_spans(by);
            }
            StmtKind::IfThen { cond, then } => {
                cond.shift_spans(by);
                then.shift_spans(by);
            }
            StmtKind::IfThenBlock {
                cond, text_span, ..
            } => {
                cond.shift_spans(by);
                text_span.offset += by;
            }
            StmtKind::IfBlock { cond } | StmtKind::While { cond, .. } => cond.shift_spans(by),
            StmtKind::Goto { target } => target.shift_spans(by),
            StmtKind::Else | StmtKind::EndIf | StmtKind::Do { .. } | StmtKind::End { .. } => {}
        }
    }
}

// ---------------------------------------------------------------------------------------
// Lexer

#[derive(Debug, Clone, PartialEq)]
enum Tok {
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
    End,
}

#[derive(Debug, Clone)]
struct Token {
    tok: Tok,
    start: usize,
    end: usize,
}

/// The text being read and where it stands in the file.
struct Src<'a> {
    text: &'a str,
    base: Span,
}

impl Src<'_> {
    fn span(&self, start: usize, end: usize) -> Span {
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

/// Most operators in one expression: far beyond real programs, and it keeps evaluation's
/// recursion shallow whatever the input.
const MAX_OPERATORS: usize = 200;

struct Parser<'a> {
    src: Src<'a>,
    /// Byte position of the lexer.
    at: usize,
    /// Tokens read ahead and not yet consumed.
    ahead: Vec<Token>,
    /// End of the last consumed token.
    last_end: usize,
    depth: usize,
    /// Operators read so far (bounds the tree's depth).
    ops: usize,
}

fn keyword_help() -> &'static str {
    "macro words are IF GOTO THEN WHILE DO END, the operators EQ NE GT GE LT LE AND OR XOR MOD, and the functions SIN COS TAN ASIN ACOS ATAN SQRT ABS ROUND FIX FUP LN EXP POW ADP BIN BCD"
}

impl<'a> Parser<'a> {
    fn new(text: &'a str, base: Span) -> Self {
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

    fn lex_one(&mut self) -> Result<Token> {
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

    fn peek_n(&mut self, k: usize) -> Result<&Token> {
        while self.ahead.len() <= k {
            let t = self.lex_one()?;
            self.ahead.push(t);
        }
        Ok(&self.ahead[k])
    }

    fn peek(&mut self) -> Result<&Tok> {
        Ok(&self.peek_n(0)?.tok)
    }

    fn bump(&mut self) -> Result<Token> {
        self.peek_n(0)?;
        let t = self.ahead.remove(0);
        if t.tok != Tok::End {
            self.last_end = t.end;
        }
        Ok(t)
    }

    fn span_of(&self, t: &Token) -> Span {
        self.src.span(t.start, t.end)
    }

    fn span_from(&self, start: usize) -> Span {
        self.src.span(start, self.last_end.max(start))
    }

    fn describe(t: &Tok) -> String {
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
            Tok::End => "the end of the block".into(),
        }
    }

    fn error_here(&mut self, message: impl Into<String>, help: impl Into<String>) -> MacroError {
        let span = match self.peek_n(0) {
            Ok(t) => {
                let t = t.clone();
                self.span_of(&t)
            }
            Err(e) => return e,
        };
        MacroError::syntax(span, message, help)
    }

    fn expect_rbr(&mut self, open: &Token) -> Result<()> {
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

    fn open_bracket(&mut self) -> Result<Token> {
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
    fn expr(&mut self) -> Result<Expr> {
        self.level(5)
    }

    fn peek_binop(&mut self) -> Result<Option<BinOp>> {
        Ok(match self.peek()? {
            Tok::Star => Some(BinOp::Mul),
            Tok::Slash => Some(BinOp::Div),
            Tok::Plus => Some(BinOp::Add),
            Tok::Minus => Some(BinOp::Sub),
            Tok::Word(w) => BinOp::from_word(w),
            _ => None,
        })
    }

    fn count_op(&mut self, t: &Token) -> Result<()> {
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

    fn level(&mut self, level: u8) -> Result<Expr> {
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

    fn unary(&mut self) -> Result<Expr> {
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

    fn var_ref(&mut self) -> Result<(VarRef, Span)> {
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

    fn primary(&mut self) -> Result<Expr> {
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

    fn call(&mut self, f: Func, name: &Token) -> Result<Expr> {
        self.bump()?;
        if *self.peek()? != Tok::LBr {
            return Err(self.error_here(
                format!("{} needs its argument in brackets", f.name()),
                format!("write {}[…]", f.name()),
            ));
        }
        let open = self.open_bracket()?;
        let mut args = vec![self.expr()?];
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

    fn expect_end(&mut self, what: &str) -> Result<()> {
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

    fn word_is(&mut self, w: &str) -> Result<bool> {
        Ok(matches!(self.peek()?, Tok::Word(x) if x == w))
    }

    /// `[cond]` after IF / WHILE: the brackets are required.
    fn condition(&mut self, keyword: &str) -> Result<Expr> {
        if *self.peek()? != Tok::LBr {
            return Err(self.error_here(
                format!("{keyword} needs its condition in brackets"),
                format!("write {keyword} [#1 GT 0] …"),
            ));
        }
        self.primary()
    }

    fn loop_id(&mut self, keyword: &str) -> Result<u8> {
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
    fn goto_target(&mut self) -> Result<Expr> {
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

    fn assignment(&mut self) -> Result<Stmt> {
        let start = self.peek_n(0)?.start;
        let (target, target_span) = self.var_ref()?;
        if *self.peek()? != Tok::Assign {
            let found = Self::describe(&self.peek()?.clone());
            return Err(self.error_here(
                format!("expected '=' after {target}, found {found}"),
                format!("write {target} = <expression>"),
            ));
        }
        self.bump()?;
        if *self.peek()? == Tok::End {
            return Err(self.error_here(
                format!("{target} = has no value"),
                format!("write a value after '=', or {target} = #0 to make it vacant"),
            ));
        }
        let value = self.expr()?;
        let mut comment = None;
        loop {
            match self.peek()?.clone() {
                Tok::Comment(c) => {
                    self.bump()?;
                    comment.get_or_insert(c);
                }
                Tok::End => break,
                other => {
                    let found = Self::describe(&other);
                    return Err(self.error_here(
                        format!("unexpected {found} after the value of {target}"),
                        "one assignment per block; put operators between values, and a whole expression in brackets",
                    ));
                }
            }
        }
        Ok(Stmt {
            kind: StmtKind::Assign {
                target,
                target_span,
                value,
                comment,
            },
            span: self.span_from(start),
        })
    }

    fn statement(&mut self, options: &Options) -> Result<Stmt> {
        let first = self.peek_n(0)?.clone();
        let start = first.start;
        let word = match &first.tok {
            Tok::Hash => return self.assignment(),
            Tok::Word(w) => w.clone(),
            other => {
                let found = Self::describe(other);
                return Err(self.error_here(
                    format!("{found} does not start a macro statement"),
                    "a macro statement is #i = …, IF, WHILE, DO, END or GOTO",
                ));
            }
        };
        self.bump()?;
        let kind = match word.as_str() {
            "IF" => {
                let cond = self.condition("IF")?;
                if self.word_is("GOTO")? {
                    self.bump()?;
                    let target = self.goto_target()?;
                    self.expect_end("the GOTO target")?;
                    StmtKind::IfGoto { cond, target }
                } else if self.word_is("THEN")? {
                    let then_tok = self.bump()?;
                    match self.peek()?.clone() {
                        Tok::End | Tok::Comment(_) => {
                            self.expect_end("THEN")?;
                            StmtKind::IfBlock { cond }
                        }
                        Tok::Hash => {
                            let inner = self.assignment()?;
                            StmtKind::IfThen {
                                cond,
                                then: Box::new(inner),
                            }
                        }
                        Tok::Word(w) if w == "GOTO" => {
                            return Err(self
                                .error_here("THEN GOTO is not allowed", "write IF [cond] GOTO n"))
                        }
                        _ => {
                            let rest_start = self.peek_n(0)?.start;
                            let text = self.src.text[rest_start..].trim_end();
                            let text_span = self.src.span(rest_start, rest_start + text.len());
                            if !options.is_haas() {
                                return Err(MacroError::new(
                                    ErrorKind::Unsupported,
                                    text_span,
                                    "IF … THEN with an NC block is a Haas form",
                                    "on FANUC THEN runs one assignment; use IF [cond] GOTO n around the block",
                                ));
                            }
                            let _ = then_tok;
                            let text = text.to_string();
                            self.at = self.src.text.len();
                            self.ahead.clear();
                            self.last_end = self.src.text.len();
                            StmtKind::IfThenBlock {
                                cond,
                                text,
                                text_span,
                            }
                        }
                    }
                } else {
                    let found = Self::describe(&self.peek()?.clone());
                    return Err(self.error_here(
                        format!("expected GOTO or THEN after the IF condition, found {found}"),
                        "write IF [cond] GOTO n or IF [cond] THEN #i = …",
                    ));
                }
            }
            "WHILE" | "WH" => {
                if word == "WH" && !options.is_haas() {
                    return Err(MacroError::new(
                        ErrorKind::Unsupported,
                        self.span_of(&first),
                        "WH is the Haas short form of WHILE",
                        "write WHILE",
                    ));
                }
                let cond = self.condition("WHILE")?;
                if !self.word_is("DO")? {
                    let found = Self::describe(&self.peek()?.clone());
                    return Err(self.error_here(
                        format!("expected DO after the WHILE condition, found {found}"),
                        "write WHILE [cond] DO1",
                    ));
                }
                self.bump()?;
                let id = self.loop_id("DO")?;
                self.expect_end("the loop number")?;
                StmtKind::While { cond, id }
            }
            "DO" => {
                let id = self.loop_id("DO")?;
                self.expect_end("the loop number")?;
                StmtKind::Do { id }
            }
            "END" => {
                let id = self.loop_id("END")?;
                self.expect_end("the loop number")?;
                StmtKind::End { id }
            }
            "GOTO" => {
                let target = self.goto_target()?;
                self.expect_end("the GOTO target")?;
                StmtKind::Goto { target }
            }
            "ELSE" => {
                self.expect_end("ELSE")?;
                StmtKind::Else
            }
            "ENDIF" => {
                self.expect_end("ENDIF")?;
                StmtKind::EndIf
            }
            _ => {
                return Err(MacroError::syntax(
                    self.span_of(&first),
                    format!("'{word}' does not start a macro statement"),
                    "a macro statement is #i = …, IF, WHILE, DO, END or GOTO",
                ))
            }
        };
        Ok(Stmt {
            kind,
            span: self.span_from(start),
        })
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;

    /// Shifting a statement's spans is reading it further on in the text: every kind, with
    /// indirect variables, groups, signs, functions and a Haas `THEN` block.
    #[test]
    fn shifted_statements_are_statements_read_further_on() {
        let at = |offset: u32| Span {
            line: 3,
            column: 1,
            offset,
            len: 0,
        };
        let fanuc = Options::fanuc();
        let haas = Options::haas();
        for (text, options) in [
            ("#[#1 + 1] = -SIN[#2] * [#3 - 1] (note)", &fanuc),
            ("IF [#1 GT +2] GOTO #[#4]", &fanuc),
            ("IF [#1 EQ 0] THEN #5 = ATAN[#1]/[2]", &fanuc),
            ("IF [#1 EQ 0] THEN G0 X1.", &haas),
            ("IF [#1 NE 0] THEN", &haas),
            ("ELSE", &haas),
            ("ENDIF", &haas),
            ("WHILE [#1 LT 3] DO1", &fanuc),
            ("DO2", &fanuc),
            ("END1", &fanuc),
            ("GOTO [#1 + 10]", &fanuc),
        ] {
            let mut shifted = parse_stmt(text, at(0), options).unwrap();
            shifted.shift_spans(1000);
            assert_eq!(
                shifted,
                parse_stmt(text, at(1000), options).unwrap(),
                "{text}"
            );
        }
    }

    fn p(s: &str) -> Expr {
        parse_expr(s, Span::default()).unwrap_or_else(|e| panic!("{s}: {e} at {}", e.span))
    }

    #[test]
    fn precedence_table_shapes() {
        // level 3 over level 4
        assert_eq!(p("2 + 3 * 4").to_string(), "2+3*4");
        let ExprKind::Binary(BinOp::Add, _, r) = p("2 + 3 * 4").kind else {
            panic!()
        };
        assert!(matches!(r.kind, ExprKind::Binary(BinOp::Mul, ..)));
        // brackets over everything
        let ExprKind::Binary(BinOp::Mul, l, _) = p("[2 + 3] * 4").kind else {
            panic!()
        };
        assert!(matches!(l.kind, ExprKind::Group(_)));
        // AND is level 3 like *, OR level 4 like +
        let ExprKind::Binary(BinOp::Or, _, r) = p("1 OR 2 AND 3").kind else {
            panic!()
        };
        assert!(matches!(r.kind, ExprKind::Binary(BinOp::And, ..)));
        // comparisons lowest
        let ExprKind::Binary(BinOp::Gt, l, r) = p("#1 + 1 GT #2 * 2").kind else {
            panic!()
        };
        assert!(matches!(l.kind, ExprKind::Binary(BinOp::Add, ..)));
        assert!(matches!(r.kind, ExprKind::Binary(BinOp::Mul, ..)));
        // left to right at one level
        let ExprKind::Binary(BinOp::Sub, l, _) = p("10 - 4 - 3").kind else {
            panic!()
        };
        assert!(matches!(l.kind, ExprKind::Binary(BinOp::Sub, ..)));
        // unary binds tighter than *
        let ExprKind::Binary(BinOp::Mul, l, _) = p("-2 * 3").kind else {
            panic!()
        };
        assert!(matches!(l.kind, ExprKind::Neg(_)));
        // function binds tighter than /
        assert!(matches!(
            p("SIN[30] / 2").kind,
            ExprKind::Binary(BinOp::Div, ..)
        ));
    }

    #[test]
    fn atan_forms() {
        let e = p("ATAN[1]/[-1]");
        assert!(matches!(&e.kind, ExprKind::Call(Func::Atan, a) if a.len() == 2));
        let e = p("ATAN[1,-1]");
        assert!(matches!(&e.kind, ExprKind::Call(Func::Atan, a) if a.len() == 2));
        let e = p("ATAN[1]/2");
        assert!(matches!(&e.kind, ExprKind::Binary(BinOp::Div, ..)));
        assert!(parse_expr("SIN[1,2]", Span::default()).is_err());
        assert!(parse_expr("POW[2]", Span::default()).is_err());
    }

    #[test]
    fn variables_and_spans() {
        let base = Span {
            line: 7,
            column: 5,
            offset: 100,
            len: 0,
        };
        let e = parse_expr("#1 + #[#2 * 2]", base).unwrap();
        let ExprKind::Binary(_, l, r) = &e.kind else {
            panic!()
        };
        assert_eq!(
            (l.span.line, l.span.column, l.span.offset, l.span.len),
            (7, 5, 100, 2)
        );
        assert_eq!((r.span.column, r.span.len), (10, 9));
        assert_eq!(e.span.len, 14);
        assert!(matches!(r.kind, ExprKind::Var(VarRef::Indirect(_))));
        let err = parse_expr("##1", base).unwrap_err();
        assert!(err.help.contains("#[#1]"));
        assert_eq!(err.span.column, 6);
        assert!(parse_expr("#1.5", base).is_err());
    }

    #[test]
    fn bracket_limit() {
        assert!(parse_expr("[[[[[1]]]]]", Span::default()).is_ok());
        let e = parse_expr("[[[[[[1]]]]]]", Span::default()).unwrap_err();
        assert_eq!(e.kind, ErrorKind::BracketNesting);
        assert_eq!(e.span.column, 6);
        // function brackets count
        let e = parse_expr("[[[[SIN[[1]]]]]]", Span::default()).unwrap_err();
        assert_eq!(e.kind, ErrorKind::BracketNesting);
    }

    #[test]
    fn huge_inputs_are_refused_not_overflowed() {
        let long = vec!["1"; 5000].join("+");
        let e = parse_expr(&long, Span::default()).unwrap_err();
        assert!(e.message.contains("operators"));
        let signs = format!("{}1", "-".repeat(100_000));
        assert!(parse_expr(&signs, Span::default()).is_err());
        assert!(parse_expr(&vec!["1"; 200].join("+"), Span::default()).is_ok());
    }

    #[test]
    fn syntax_errors_point_at_the_place() {
        let e = parse_expr("1 + * 2", Span::default()).unwrap_err();
        assert_eq!(e.span.column, 5);
        let e = parse_expr("[1 + 2", Span::default()).unwrap_err();
        assert!(e.message.contains("']'"), "{}", e.message);
        let e = parse_expr("FOO[1]", Span::default()).unwrap_err();
        assert!(e.message.contains("FOO"));
        let e = parse_expr("1 2", Span::default()).unwrap_err();
        assert_eq!(e.span.column, 3);
        let e = parse_expr("SIN 30", Span::default()).unwrap_err();
        assert!(e.help.contains("SIN["));
    }

    #[test]
    fn statements() {
        let o = Options::fanuc();
        let s = |t: &str| parse_stmt(t, Span::default(), &o);
        assert!(matches!(s("#1 = 2").unwrap().kind, StmtKind::Assign { .. }));
        let st = s("#3000 = 1 (TOOL BROKEN)").unwrap();
        let StmtKind::Assign { comment, .. } = st.kind else {
            panic!()
        };
        assert_eq!(comment.as_deref(), Some("TOOL BROKEN"));
        assert!(matches!(
            s("IF [#1 GT 3] GOTO 10").unwrap().kind,
            StmtKind::IfGoto { .. }
        ));
        assert!(matches!(
            s("IF[#1GT3]GOTO#2").unwrap().kind,
            StmtKind::IfGoto { .. }
        ));
        assert!(matches!(
            s("IF [#1 LT #2] THEN #1 = #2").unwrap().kind,
            StmtKind::IfThen { .. }
        ));
        assert!(matches!(
            s("WHILE [#1 GT #2] DO1").unwrap().kind,
            StmtKind::While { id: 1, .. }
        ));
        assert!(matches!(s("END1").unwrap().kind, StmtKind::End { id: 1 }));
        assert!(matches!(s("DO 2").unwrap().kind, StmtKind::Do { id: 2 }));
        assert!(matches!(
            s("GOTO [#1 + 10]").unwrap().kind,
            StmtKind::Goto { .. }
        ));
        assert!(matches!(
            s("IF [#1 EQ 1] THEN").unwrap().kind,
            StmtKind::IfBlock { .. }
        ));
        assert!(matches!(s("ELSE").unwrap().kind, StmtKind::Else));
        assert!(matches!(s("ENDIF").unwrap().kind, StmtKind::EndIf));
        // errors
        let e = s("IF [#1 EQ 1] THEN GOTO 5").unwrap_err();
        assert!(e.message.contains("THEN GOTO"));
        let e = s("IF #1 EQ 1 GOTO 5").unwrap_err();
        assert!(e.message.contains("brackets"));
        let e = s("WHILE [#1 GT 0] DO4").unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopNesting);
        assert_eq!(e.span.column, 19);
        let e = s("IF [1] THEN G01 X#24").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Unsupported);
        assert_eq!(e.span.column, 13);
        assert!(s("WH [1] DO1").is_err());
        assert!(s("#1 = ").is_err());
        assert!(s("#1 = 2 3").is_err());
        // Haas forms
        let h = Options::haas();
        let st = parse_stmt("IF [#1 NE #0] THEN G01 X#24 F#9", Span::default(), &h).unwrap();
        let StmtKind::IfThenBlock {
            text, text_span, ..
        } = st.kind
        else {
            panic!()
        };
        assert_eq!(text, "G01 X#24 F#9");
        assert_eq!(text_span.column, 20);
        assert!(parse_stmt("WH [1] DO1", Span::default(), &h).is_ok());
    }

    #[test]
    fn operands_for_words() {
        let (e, n) = parse_operand("#1Z5.", Span::default()).unwrap();
        assert_eq!(n, 2);
        assert!(matches!(e.kind, ExprKind::Var(VarRef::Direct(1))));
        let (e, n) = parse_operand("[#2-0.5] F0.2", Span::default()).unwrap();
        assert_eq!(n, 8);
        assert!(matches!(e.kind, ExprKind::Group(_)));
        let (e, n) = parse_operand("-#1 Z2", Span::default()).unwrap();
        assert_eq!(n, 3);
        assert!(matches!(e.kind, ExprKind::Neg(_)));
        let (_, n) = parse_operand("ROUND[#1]", Span::default()).unwrap();
        assert_eq!(n, 9);
        assert!(starts_statement("#1=2"));
        assert!(starts_statement("  while [1] do1"));
        assert!(starts_statement("IF[1]GOTO5"));
        assert!(!starts_statement("G00 X#1"));
        assert!(!starts_statement("DWELL"));
    }
}
