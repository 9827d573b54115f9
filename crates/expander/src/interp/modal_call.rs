//! The state of a `G66` modal call, kept by the macro runner (`macros.rs`) and compared by
//! the loop guard (`loop_guard.rs`): a leaf both read.

use crate::Span;
use macro_b::Locals;

/// A `G66 P… [L…] args` in force: its arguments were evaluated at the `G66` block.
#[derive(Clone, PartialEq)]
pub(super) struct ModalCall {
    pub(super) number: u32,
    pub(super) times: u32,
    pub(super) locals: Box<Locals>,
    /// The `G66` block.
    pub(super) span: Span,
}

/// The macro side of a loop's state besides the variables (for the loop guard): the
/// modal call in force and how many calls it made are running.
pub(super) struct Calls {
    pub(super) modal: Option<ModalCall>,
    pub(super) in_modal: u32,
}
