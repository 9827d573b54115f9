//! What the interpreter is told about the tool table: the nose of every offset (G41/G42)
//! and the radial grooving blades (G75.1 without I).

use super::{AxisDir, Tool, ToolTable};

impl ToolTable {
    /// Nose radius and tip of every turning insert, by offset number (the table's `t`, as
    /// `T0101` pairs tool 01 with offset 01), for G41/G42; other kinds are `None`, for
    /// which compensation is ignored with a warning.
    pub fn noses(&self) -> std::collections::BTreeMap<u32, Option<expander::tnrc::Nose>> {
        self.tools
            .iter()
            .map(|(t, tool)| {
                let nose = match tool {
                    Tool::Turning {
                        nose_radius, tip, ..
                    } => Some(expander::tnrc::Nose {
                        radius: *nose_radius,
                        tip: *tip,
                    }),
                    _ => None,
                };
                (*t, nose)
            })
            .collect()
    }

    /// Every radial grooving blade by tool number: its width, and whether it extends toward
    /// +Z from its reference corner (G75.1 without I cuts with it).
    pub fn blades(&self) -> std::collections::BTreeMap<u32, (f64, bool)> {
        self.tools
            .iter()
            .filter_map(|(t, tool)| match tool {
                Tool::Grooving {
                    width, width_dir, ..
                } if matches!(width_dir, AxisDir::PlusZ | AxisDir::MinusZ) => {
                    Some((*t, (*width, *width_dir == AxisDir::PlusZ)))
                }
                _ => None,
            })
            .collect()
    }
}
