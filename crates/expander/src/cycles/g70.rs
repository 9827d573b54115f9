//! G70 — finishing cycle (spec/cycles.md).

use super::{Cycle, Output};

/// Expand one block of the cycle.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    Err(super::not_implemented(c))
}
