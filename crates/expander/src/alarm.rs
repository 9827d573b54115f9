//! Controller alarms and warnings, each tied to a place in the program.

use crate::Span;

/// One alarm or warning: where, a short stable code, what happened, what to change.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    /// The word or block it concerns.
    pub span: Span,
    /// Stable code: FANUC-style where FANUC has one (`PS010`), else a latsim name.
    pub code: &'static str,
    /// What happened.
    pub message: String,
    /// What to change.
    pub help: String,
}

impl Diagnostic {
    /// A new diagnostic.
    pub fn new(
        span: Span,
        code: &'static str,
        message: impl Into<String>,
        help: impl Into<String>,
    ) -> Self {
        Self {
            span,
            code,
            message: message.into(),
            help: help.into(),
        }
    }
}

impl std::fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} [{}] {}", self.span, self.code, self.message)
    }
}
