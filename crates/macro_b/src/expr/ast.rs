//! The expression and statement trees, with their spans, and how they print.

use std::fmt;

use crate::span::Span;

/// A variable reference: `#12` or `#[expr]`.
#[derive(Debug, Clone, PartialEq)]
pub enum VarRef {
    /// `#n`.
    Direct(u32),
    /// `#[expr]`; the expression is rounded to an integer when read.
    Indirect(Box<Expr>),
    /// `LinuxCNC`'s named parameter `#<name>` (lower case, blanks removed): local to the
    /// call level, global when the name starts with `_`.
    Named(String),
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
    /// `LinuxCNC`'s `EXISTS[#<name>]`: 1 when the named parameter is defined.
    Exists,
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
            "EXISTS" => Self::Exists,
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
            Self::Exists => "EXISTS",
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

    pub(super) fn from_word(w: &str) -> Option<Self> {
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
            ExprKind::Num(_) | ExprKind::Var(VarRef::Direct(_) | VarRef::Named(_)) => {}
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

    /// The named parameters it reads (`#<name>`), in the order written, each once.
    pub fn named(&self) -> Vec<String> {
        let mut found = Vec::new();
        self.collect_named(&mut found);
        found
    }

    fn collect_named(&self, found: &mut Vec<String>) {
        match &self.kind {
            ExprKind::Num(_) | ExprKind::Var(VarRef::Direct(_)) => {}
            ExprKind::Var(VarRef::Named(n)) => {
                if !found.contains(n) {
                    found.push(n.clone());
                }
            }
            ExprKind::Var(VarRef::Indirect(e))
            | ExprKind::Group(e)
            | ExprKind::Neg(e)
            | ExprKind::Pos(e) => e.collect_named(found),
            ExprKind::Binary(_, a, b) => {
                a.collect_named(found);
                b.collect_named(found);
            }
            ExprKind::Call(_, args) => args.iter().for_each(|a| a.collect_named(found)),
        }
    }

    fn collect_variables(&self, found: &mut Vec<u32>) {
        match &self.kind {
            ExprKind::Num(_) | ExprKind::Var(VarRef::Named(_)) => {}
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
            Self::Named(n) => write!(f, "#<{n}>"),
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
    /// `LinuxCNC`'s o-word: `o100 if [c]`, `o<name> call [a] [b]`, `o100 endsub [v]` …
    OWord {
        /// The o-number or name.
        label: OLabel,
        /// What it does.
        keyword: OKeyword,
        /// Its bracketed expressions (the condition, the count, the arguments, the value).
        args: Vec<Expr>,
    },
}

/// The label of a `LinuxCNC` o-word: `o100` or `o<name>` (lower case).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum OLabel {
    /// `o100`.
    Number(u32),
    /// `o<name>`.
    Name(String),
}

impl fmt::Display for OLabel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Number(n) => write!(f, "o{n}"),
            Self::Name(n) => write!(f, "o<{n}>"),
        }
    }
}

/// What a `LinuxCNC` o-word does ([O] in docs/linuxcnc.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OKeyword {
    /// `sub`: a subroutine's definition starts (skipped where it stands).
    Sub,
    /// `endsub [v]`: the definition ends; run, it returns.
    EndSub,
    /// `return [v]`: return from the subroutine.
    Return,
    /// `call [a] [b] …`: call the subroutine with #1… set.
    Call,
    /// `if [c]`.
    If,
    /// `elseif [c]`.
    ElseIf,
    /// `else`.
    Else,
    /// `endif`.
    EndIf,
    /// `while [c]`: a loop's head, or the end of a `do` loop with the same label.
    While,
    /// `endwhile`.
    EndWhile,
    /// `do`.
    Do,
    /// `repeat [n]`.
    Repeat,
    /// `endrepeat`.
    EndRepeat,
    /// `break`: leave the loop.
    Break,
    /// `continue`: the loop's next test.
    Continue,
}

impl OKeyword {
    /// The keyword of a lower-case word.
    pub fn from_word(w: &str) -> Option<Self> {
        Some(match w {
            "sub" => Self::Sub,
            "endsub" => Self::EndSub,
            "return" => Self::Return,
            "call" => Self::Call,
            "if" => Self::If,
            "elseif" => Self::ElseIf,
            "else" => Self::Else,
            "endif" => Self::EndIf,
            "while" => Self::While,
            "endwhile" => Self::EndWhile,
            "do" => Self::Do,
            "repeat" => Self::Repeat,
            "endrepeat" => Self::EndRepeat,
            "break" => Self::Break,
            "continue" => Self::Continue,
            _ => return None,
        })
    }

    /// The keyword as written.
    pub fn name(self) -> &'static str {
        match self {
            Self::Sub => "sub",
            Self::EndSub => "endsub",
            Self::Return => "return",
            Self::Call => "call",
            Self::If => "if",
            Self::ElseIf => "elseif",
            Self::Else => "else",
            Self::EndIf => "endif",
            Self::While => "while",
            Self::EndWhile => "endwhile",
            Self::Do => "do",
            Self::Repeat => "repeat",
            Self::EndRepeat => "endrepeat",
            Self::Break => "break",
            Self::Continue => "continue",
        }
    }

    /// How many bracketed expressions it takes: (at least, at most).
    pub fn arity(self) -> (usize, usize) {
        match self {
            Self::If | Self::ElseIf | Self::While | Self::Repeat => (1, 1),
            Self::EndSub | Self::Return => (0, 1),
            Self::Call => (0, 30),
            _ => (0, 0),
        }
    }
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
            StmtKind::OWord {
                keyword: OKeyword::If | OKeyword::ElseIf | OKeyword::While,
                args,
                ..
            } => args.first(),
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
            StmtKind::OWord { args, .. } => args.iter_mut().for_each(|a| a.shift_spans(by)),
            StmtKind::Else | StmtKind::EndIf | StmtKind::Do { .. } | StmtKind::End { .. } => {}
        }
    }
}

// ---------------------------------------------------------------------------------------
// Lexer
