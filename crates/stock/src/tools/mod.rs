//! The tool table (`--tools F`): T numbers mapped to real tool outlines.
//!
//! One concern a file: [`kinds`] the tools and their defaults, [`schema`] the TOML format
//! and its validation (errors at their line), [`outline_choice`] which outline cuts under
//! a cycle's hint, [`facts`] what the interpreter is told about the table.

mod facts;
mod kinds;
mod outline_choice;
mod schema;

use crate::StockError;
pub use kinds::{AxisDir, GroovingBlade, Insert, Tool};
pub(crate) use outline_choice::hint_key;

/// The tool table: T numbers to tools, in file order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToolTable {
    tools: Vec<(u32, Tool)>,
}

impl ToolTable {
    /// A table with no entries: every tool gets the default.
    pub fn empty() -> Self {
        Self::default()
    }

    /// A table from explicit entries (T number, tool).
    pub fn from_tools(tools: Vec<(u32, Tool)>) -> Self {
        Self { tools }
    }

    /// Parses the `[[tool]]` TOML format of the simulation spec.
    pub fn from_toml(text: &str) -> Result<Self, StockError> {
        Ok(Self {
            tools: schema::read(text)?,
        })
    }

    /// The tool for number `t` (0 = no T word yet: the first entry), if the table has it.
    pub fn get(&self, t: u32) -> Option<&Tool> {
        if t == 0 {
            return self.tools.first().map(|(_, tool)| tool);
        }
        self.tools
            .iter()
            .find(|(n, _)| *n == t)
            .map(|(_, tool)| tool)
    }

    /// The T numbers in the table, in file order.
    pub fn numbers(&self) -> Vec<u32> {
        self.tools.iter().map(|(t, _)| *t).collect()
    }

    /// One human line per tool, e.g. "T01 turning V 35°, r0.4, tip 3, κr 93°".
    pub fn describe(&self, t: u32) -> String {
        match self.get(t) {
            Some(tool) => format!("T{t:02} {}", tool.describe()),
            None => format!("T{t:02} {} (default)", Tool::DEFAULT.describe()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPEC_TABLE: &str = r#"
[[tool]]
t = 1                  # T0101 -> tool 1 (offset 01 turns on its nose radius for G41/G42)
kind = "turning"       # turning | grooving | drill | threading
insert = "V"           # ISO shape letter: C 80°, D 55°, T 60°, V 35°, W 80°, S 90°, R round
nose_radius = 0.4      # mm
tip = 3                # imaginary tip number 0-9 (tnrc.md)
entering_angle = 93    # holder lead angle in degrees (default 93)
edge = 11.0            # cutting edge length in mm (default 11)

[[tool]]
t = 2
kind = "grooving"
width = 3.0
width_dir = "+z"       # from the reference corner the blade spans +z: reference = left corner
shank_dir = "+x"       # the blade body runs from the cutting edge toward +x (OD); -x ID; +z face
reach = 20.0           # blade length in mm (default 20)
corner_radius = 0.0

[[tool]]
t = 3
kind = "drill"
diameter = 10.0
point_angle = 118
reach = 60.0

[[tool]]
t = 4
kind = "threading"
angle = 60
tip_flat = 0.0
"#;

    #[test]
    fn spec_table_parses_with_its_names() {
        let t = ToolTable::from_toml(SPEC_TABLE).unwrap();
        assert_eq!(t.numbers(), vec![1, 2, 3, 4]);
        assert_eq!(t.describe(1), "T01 turning V 35°, r0.4, tip 3, κr 93°");
        assert_eq!(t.describe(3), "T03 drill Ø10, 118° point");
        let (o, w) = t.outline(2);
        assert!(w.is_none());
        assert_eq!(o.bbox().unwrap(), ([0.0, 0.0], [3.0, 20.0]));
        // T0 before any T word: the first entry
        assert_eq!(t.outline(0).0, t.outline(1).0);
    }

    #[test]
    fn missing_tools_get_the_default_with_a_warning() {
        let (o, w) = ToolTable::empty().outline(7);
        assert_eq!(o, Tool::DEFAULT.outline());
        assert!(w.unwrap().contains("55°"));
        let t = ToolTable::from_toml(SPEC_TABLE).unwrap();
        assert!(t.outline(9).1.unwrap().contains("T09"));
    }
}
