//! FANUC custom macro B (with the Haas differences) for the interpreter: expressions,
//! statements, variables with vacancy, system variables, control flow and `G65` arguments,
//! as spec/dialects.md §5 gives them. Every error carries the [`Span`] of its text.
//!
//! How the interpreter uses it:
//!
//! 1. The reader routes a block whose text [`starts_statement`] to [`parse_stmt`], and
//!    reads the value of an NC word written with `#`, `[` or a function through
//!    [`parse_operand`] (plain numbers stay as they are).
//! 2. Each O program becomes a [`MacroProgram`] of [`Line`]s, each a macro statement or
//!    the interpreter's own NC block type; preparing it checks `DO`/`END` structure.
//! 3. A [`Flow`] runs the statements and hands out NC blocks ([`Flow::next`]); the
//!    interpreter evaluates word values with [`MacroState::address_value`] (vacant → the
//!    word is not written) and [`MacroState::integer_value`], and reports `G65`, `M98`,
//!    `M97` and `M99` with [`Flow::call_macro`] ([`g65_locals`] builds the arguments),
//!    [`Flow::call_sub`], [`Flow::call_local`] and [`Flow::ret`].
//! 4. System variables are read through the interpreter's [`System`] implementation.
//!
//! ```
//! use macro_b::{parse_operand, parse_stmt, Body, Flow, Line, MacroProgram, MacroState,
//!               NoMachine, Options, Span, Step};
//!
//! let opts = Options::fanuc();
//! let text = ["#1 = 0", "WHILE [#1 LT 3] DO1", "#1 = #1 + 1", "END1"];
//! let mut lines: Vec<Line<&str>> = Vec::new();
//! for (i, t) in text.iter().enumerate() {
//!     let at = Span { line: i as u32 + 1, column: 1, offset: 0, len: t.len() as u32 };
//!     let stmt = parse_stmt(t, at, &opts).unwrap();
//!     lines.push(Line { seq: None, span: at, body: Body::Stmt(stmt) });
//! }
//! // an NC block of the interpreter's own type
//! lines.push(Line { seq: None, span: Span::default(), body: Body::Block("G00 X#1") });
//! let programs = [MacroProgram::new(None, lines, &opts.limits).unwrap()];
//!
//! let mut state = MacroState::new(opts);
//! let mut flow = Flow::new(&programs, 0, opts.limits);
//! let Some(Step::Block { block, .. }) = flow.next(&mut state, &mut NoMachine).unwrap() else {
//!     panic!("the NC block comes next")
//! };
//! assert_eq!(*block, "G00 X#1");
//! let (x, used) = parse_operand("#1", Span::default()).unwrap();
//! assert_eq!(used, 2);
//! assert_eq!(state.address_value(&x, 0.001, &mut NoMachine).unwrap(), Some(3.0));
//! assert!(flow.next(&mut state, &mut NoMachine).unwrap().is_none());
//! ```
mod arguments;
mod error;
mod eval;
mod expr;
mod fingerprint;
mod flow;
mod named;
mod o_words;
mod options;
mod span;
mod value;
mod vars;

#[cfg(test)]
mod spec_tests;

pub use arguments::{letter_of_argument, ARGUMENTS};
pub use error::{ErrorKind, MacroError, Result};
pub use eval::MacroState;
pub use expr::{
    parse_expr, parse_operand, parse_stmt, starts_statement, starts_statement_in, BinOp, Expr,
    ExprKind, Func, OKeyword, OLabel, Stmt, StmtKind, VarRef,
};
pub use fingerprint::Snapshot;
pub use flow::{
    g65_argument_value, g65_locals, Argument, At, Body, CallKind, Flow, Line, MacroProgram, Step,
    Warning,
};
pub use o_words::{OLink, OStructure};
pub use options::{Dialect, Limits, Options, DEFAULT_MAX_BLOCKS, MAX_BRACKET_DEPTH};
pub use span::Span;
pub use value::{fix, fup, round_half_away, round_to_increment, Value};
pub use vars::{Axis, Locals, NoMachine, Position, System, Timer, VarEntry, Variables};
