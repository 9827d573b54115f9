//! The one error type of the crate: what went wrong, where, and what to change.

use crate::span::Span;

/// What kind of problem a [`MacroError`] is. Reading problems (`Syntax`, nesting found
/// when a program is prepared) and run-time alarms share the type so the interpreter can
/// report both the same way; [`ErrorKind::is_alarm`] tells them apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// The text is not a macro statement or expression.
    Syntax,
    /// More than the allowed levels of `[ ]` (5, function brackets included).
    BracketNesting,
    /// Division (or `MOD`) by zero.
    DivisionByZero,
    /// `SQRT` of a negative, `ASIN`/`ACOS` outside [−1, 1], `LN` of ≤ 0, a non-finite result.
    Domain,
    /// A vacant value where a number is required (a `GOTO` target, a `DO` number …).
    Vacant,
    /// A variable number that does not exist on the control (`#50`, `#300`, `#-1`).
    NoSuchVariable,
    /// Writing `#0` or a read-only system variable.
    ReadOnly,
    /// A system variable `latsim` does not simulate, or one the interpreter did not map.
    NotSimulated,
    /// A construct the selected control does not have (`MOD` on 0i, Haas forms on FANUC).
    Unsupported,
    /// `GOTO n` / `M99 Pn` to a sequence number that is not in the program.
    SequenceMissing,
    /// The target sequence number of a jump is written on more than one block.
    DuplicateSequence,
    /// `END m` with no open `DO m`.
    EndWithoutDo,
    /// `DO m` (or `WHILE … DO m`) with no `END m` after it.
    DoWithoutEnd,
    /// `DO` nested deeper than three, or `DO m` inside an open `DO m`, or m not 1–3.
    LoopNesting,
    /// `END m` closes a loop while a loop opened inside it is still open.
    LoopCrossing,
    /// A `GOTO` into a `DO`–`END` range from outside it.
    JumpIntoLoop,
    /// Block-form `IF … THEN` / `ELSE` / `ENDIF` not well formed.
    IfStructure,
    /// `LinuxCNC` o-words not well formed (an `endwhile` without its `while`, a `sub`
    /// inside a `sub`, a `call` of a subroutine the file does not define …).
    OWordStructure,
    /// The executed-block budget ran out (a runaway loop).
    Budget,
    /// Macro or subprogram calls nested deeper than the control allows.
    CallDepth,
    /// A called program does not exist.
    ProgramMissing,
    /// A `G65` argument that is not allowed (G L N O P, a letter twice, too many I J K).
    Argument,
    /// `#3000 = n (message)`: the program raised its own alarm.
    ProgramAlarm {
        /// The alarm number the control shows (3000 + n on FANUC, 1000 + n on Haas).
        code: u32,
    },
}

impl ErrorKind {
    /// Whether the control raises this while running (an alarm), as opposed to refusing
    /// the program text before it runs.
    pub fn is_alarm(self) -> bool {
        !matches!(
            self,
            Self::Syntax
                | Self::BracketNesting
                | Self::Unsupported
                | Self::EndWithoutDo
                | Self::DoWithoutEnd
                | Self::LoopNesting
                | Self::LoopCrossing
                | Self::IfStructure
                | Self::OWordStructure
        )
    }
}

/// A macro error: where, what, and what to change.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct MacroError {
    /// What kind of problem.
    pub kind: ErrorKind,
    /// Where the problem is (the operator, the variable, the statement).
    pub span: Span,
    /// What is wrong.
    pub message: String,
    /// What to change.
    pub help: String,
}

impl MacroError {
    /// A new error.
    pub fn new(
        kind: ErrorKind,
        span: Span,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> Self {
        Self {
            kind,
            span,
            message: message.into(),
            help: help.into(),
        }
    }

    /// A syntax error.
    pub(crate) fn syntax(span: Span, message: impl Into<String>, help: impl Into<String>) -> Self {
        Self::new(ErrorKind::Syntax, span, message, help)
    }
}

/// Result with a [`MacroError`].
pub type Result<T, E = MacroError> = std::result::Result<T, E>;
