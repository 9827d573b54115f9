//! The G75.1 pairing rule: a geometry block (with H) is followed directly by its process
//! block (without H); nothing but blank blocks may come between. Every break of the rule,
//! wherever it is found (the cycle, the interpreter, the program end), is worded here.

use super::Geometry;
use crate::{Diagnostic, Span};

/// How the pairing rule is broken.
pub(crate) enum Break {
    /// A process block with no geometry block before it.
    NoGeometry,
    /// Another block (or the program end) comes after the geometry block.
    Interrupted,
    /// A second geometry block comes before the first one's process block.
    SecondGeometry,
}

/// The alarm for a break of the rule at `span`; `pending` is the geometry block waiting
/// for its process block, if any.
pub(crate) fn alarm(span: Span, pending: Option<&Geometry>, b: Break) -> Diagnostic {
    let line = pending.map_or(String::new(), |g| format!(" at line {}", g.line));
    let (message, help) = match b {
        Break::NoGeometry => (
            "G75.1 process block without its geometry block".to_string(),
            "G75.1 needs two blocks: first X Z P Q H D [A B L], then R V U W I J …",
        ),
        Break::Interrupted => (
            format!("the G75.1 geometry block{line} is not followed by its process block"),
            "write the G75.1 process block (R V U W I J …) directly after the geometry block",
        ),
        Break::SecondGeometry => (
            format!("the G75.1 geometry block{line} has no process block before the next geometry block"),
            "write the G75.1 process block (R V U W I J …) directly after the geometry block",
        ),
    };
    Diagnostic::new(span, "LS-G75.1-BLOCKS", message, help)
}

/// Whether the process block at `index` of program `number` follows `g` directly.
pub(super) fn follows(g: &Geometry, program: &gcode::Subprogram, index: usize) -> bool {
    let between = (g.at.0 + 1).min(index)..index;
    g.at.1 == program.number
        && g.at.0 < index
        && program.blocks.range(between).all(|b| b.words.is_empty())
}
