//! G71 / G72 — stock removal in turning / facing (spec/cycles.md).

use super::{Cycle, Output};

/// Expand one block of the cycle.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    Err(super::not_implemented(c))
}
