//! A warning or alarm of the analysis (a leaf: the checks that raise one need nothing else
//! of the findings).

use expander::Span;

/// A warning or alarm the analysis raises, at the line of the move it concerns.
#[derive(Debug, Clone, PartialEq)]
pub struct Note {
    /// Where in the program.
    pub span: Span,
    /// Short stable code, e.g. `LS-RAPID-SCRAPE`.
    pub code: &'static str,
    /// What happened and what to change.
    pub message: String,
}
