//! What a reading takes and gives: the options, the error, and the O programs read with
//! their blocks (or where each block starts, to read it again).

use macro_b::{Dialect, MacroError};

use crate::{Block, CallText, Note, Span};

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
    pub(crate) fn new(span: Span, message: impl Into<String>, help: impl Into<String>) -> Self {
        Self {
            span,
            message: message.into(),
            help: help.into(),
        }
    }
}

impl From<MacroError> for ParseError {
    fn from(e: MacroError) -> Self {
        Self::new(e.span, e.message, e.help)
    }
}

/// How to read numbers that a FANUC would refuse.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// Read `F0,2` as `F0.2` (German-style posts); otherwise a decimal comma is an error.
    pub decimal_comma: bool,
    /// Custom macro B (spec/dialects.md §5) with this control's rules: `#` variables,
    /// `[ ]` expressions as word values and macro statements. `None`: a `#` is an error.
    pub macros: Option<Dialect>,
    /// X is programmed as a radius (FANUC parameter DIA off, Linux CNC G8, trainers): X-axis
    /// values are doubled as they are read (`radius`).
    pub x_radius: bool,
}

/// Where a block's first character stands, and what is asked of a block without reading
/// it again: its N number, whether `/` was written, whether it ends the program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BlockStart {
    pub(crate) offset: u32,
    pub(crate) line: u32,
    pub(crate) column: u32,
    /// The N number (0: none; `N0` is refused).
    pub(crate) seq: u32,
    /// [`BlockStart::DELETE`] and [`BlockStart::ENDS`].
    pub(crate) flags: u8,
}

impl BlockStart {
    /// Written with `/` (block delete).
    pub(crate) const DELETE: u8 = 1;
    /// Holds M02 or M30 ([`Block::ends_program`]).
    pub(crate) const ENDS: u8 = 2;
}

/// What a reading of a whole text gives: its O programs in order and the notes.
pub(crate) struct Reading {
    pub(crate) programs: Vec<ReadProgram>,
    pub(crate) notes: Vec<Note>,
}

/// One O program as read.
pub(crate) struct ReadProgram {
    /// The O number, `None` for blocks before any O word.
    pub(crate) number: Option<u32>,
    /// Span of the O word.
    pub(crate) span: Span,
    pub(crate) blocks: ReadBlocks,
    /// The first comment after `M98` of a block, by block index.
    pub(crate) call_texts: Vec<CallText>,
}

/// The blocks of one O program, as the reading keeps them ([`Keep`]).
pub(crate) enum ReadBlocks {
    /// Where each block starts, to be read again; whether some block holds macro B.
    Starts(Vec<BlockStart>, bool),
    /// The blocks themselves.
    Held(Vec<Block>),
}

impl ReadBlocks {
    pub(super) fn len(&self) -> usize {
        match self {
            Self::Starts(starts, _) => starts.len(),
            Self::Held(blocks) => blocks.len(),
        }
    }

    pub(super) fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Free the spare capacity once reading is done.
    pub(super) fn shrink(&mut self) {
        match self {
            Self::Starts(starts, _) => starts.shrink_to_fit(),
            Self::Held(blocks) => blocks.shrink_to_fit(),
        }
    }
}

/// What a reading of a whole text keeps of each block.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Keep {
    /// Where it starts, to read it again from the text where it is needed.
    Starts,
    /// The block itself: the reference reading, every block read by the character loop.
    Held,
}
