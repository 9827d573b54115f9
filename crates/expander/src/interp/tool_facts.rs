//! The tool facts the interpreter reads from its options (`toolfacts::ToolFacts`, which
//! the tool table produces): the nose of an offset (G41/G42) and the grooving blade of a
//! tool (G75.1). The only place that reads them.

use super::Interp;
use crate::tnrc::Nose;

impl Interp<'_> {
    /// The tool table's entry for offset `offset`: `Some(Err(kind))` is a tool without a
    /// nose, `None` no entry.
    pub(crate) fn nose_for(&self, offset: u32) -> Option<Result<Nose, &'static str>> {
        self.noses.get(&offset).copied()
    }

    /// The nose of an offset with no entry.
    pub(crate) fn default_nose(&self) -> Nose {
        nose(self.opts.tools.default_nose)
    }

    /// Tool `tool`'s radial grooving blade: width, and whether it extends toward +Z.
    pub(crate) fn blade_for(&self, tool: u32) -> Option<(f64, bool)> {
        let blade = self.opts.tools.blades.get(&tool)?;
        Some((blade.width, blade.toward_plus_z))
    }
}

/// The compensation's nose (which knows its tip vector) from the table's facts.
pub(super) fn nose(n: toolfacts::Nose) -> Nose {
    Nose {
        radius: n.radius,
        tip: n.tip,
    }
}
