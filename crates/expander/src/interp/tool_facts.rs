//! The tool facts the interpreter reads from its options: the nose of an offset (G41/G42)
//! and the grooving blade of a tool (G75.1). The only place that reads them.

use super::Interp;
use crate::tnrc::Nose;

impl Interp<'_> {
    /// The tool table's entry for offset `offset`: `Some(Err(kind))` is a tool without a
    /// nose, `None` no entry.
    pub(crate) fn nose_for(&self, offset: u32) -> Option<Result<Nose, &'static str>> {
        self.opts.noses.get(&offset).copied()
    }

    /// The nose of an offset with no entry.
    pub(crate) fn default_nose(&self) -> Nose {
        self.opts.default_nose
    }

    /// Tool `tool`'s radial grooving blade: width, and whether it extends toward +Z.
    pub(crate) fn blade_for(&self, tool: u32) -> Option<(f64, bool)> {
        self.opts.blades.get(&tool).copied()
    }
}
