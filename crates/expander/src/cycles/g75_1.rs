//! G75.1 — GSK radial trapezoid groove cycle (seed 000, spec/cycles.md).

use super::{Cycle, Output};

/// The geometry block's words, kept until the process block arrives.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Geometry {}

/// Expand one G75.1 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, crate::Diagnostic> {
    Err(super::not_implemented(c))
}
