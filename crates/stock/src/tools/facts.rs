//! What the interpreter is told about the tool table ([`toolfacts::ToolFacts`]): the nose
//! of every offset (G41/G42) and the radial grooving blades (G75.1 without I).

use super::{AxisDir, Tool, ToolTable};
use toolfacts::{Blade, Nose, ToolFacts};

impl ToolTable {
    /// The table's facts for the interpreter: nose radius and tip of every turning insert
    /// by offset number (the table's `t`, as `T0101` pairs tool 01 with offset 01; other
    /// kinds have no nose, and compensation is ignored for them with a warning), the
    /// default nose ([`Tool::DEFAULT`]'s, the same constant), and every radial grooving blade by tool number.
    pub fn facts(&self) -> ToolFacts {
        // a boring bar taken from its moves (`by_use`) compensates as one; the other tools
        // taken by use keep the default nose (a thread or a drill is not compensated)
        let noses = self
            .tools
            .iter()
            .chain(
                self.by_use
                    .iter()
                    .filter(|(_, tool)| matches!(tool, Tool::Turning { .. })),
            )
            .map(|(t, tool)| (*t, nose(tool)))
            .collect();
        let blades = self
            .tools
            .iter()
            .filter_map(|(t, tool)| match tool {
                Tool::Grooving(b) if matches!(b.width_dir, AxisDir::PlusZ | AxisDir::MinusZ) => {
                    let toward_plus_z = b.width_dir == AxisDir::PlusZ;
                    Some((
                        *t,
                        Blade {
                            width: b.width,
                            toward_plus_z,
                        },
                    ))
                }
                _ => None,
            })
            .collect();
        ToolFacts {
            noses,
            default_nose: Nose::DEFAULT,
            blades,
        }
    }
}

/// A turning insert's nose; other kinds have none, and say what they are.
fn nose(tool: &Tool) -> Result<Nose, &'static str> {
    match *tool {
        Tool::Turning {
            nose_radius, tip, ..
        } => Ok(Nose {
            radius: nose_radius,
            tip,
        }),
        Tool::Grooving { .. } => Err("grooving blade"),
        Tool::Drill { .. } => Err("drill"),
        Tool::Threading { .. } => Err("threading tool"),
    }
}
