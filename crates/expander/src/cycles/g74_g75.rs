//! G74 face grooving / peck drilling and G75 radial grooving (seed 002, spec/cycles.md).

use super::{Cycle, Output};

/// Expand one G74/G75 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    Err(super::not_implemented(c))
}
