//! The tool table (`--tools F`): T numbers mapped to real tool outlines.
//!
//! One concern a file: [`kinds`] the tools and their defaults, [`schema`] the TOML format
//! and its validation (errors at their line), [`outline_choice`] which outline cuts under
//! a cycle's hint, [`facts`] what the interpreter is told about the table, [`hand`] a
//! holder's tip read from the program's feeds, [`by_use`] what a tool with no entry is
//! taken for from its moves.

mod bodies;
mod by_use;
mod facts;
mod hand;
mod kinds;
mod outline_choice;
mod schema;

use crate::StockError;
pub use bodies::{Body, HolderSize};
pub use by_use::{outward_travel, tip_taken_note, ToolFromUse};
pub use hand::TipFromUse;
pub use kinds::{AxisDir, GroovingBlade, Insert, ThreadSide, Tool};
pub(crate) use outline_choice::hint_key;

/// The tool table: T numbers to tools, in file order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToolTable {
    tools: Vec<(u32, Tool)>,
    /// The ISO designations an entry was given by, for the report.
    designations: Vec<(u32, String)>,
    /// What a turning tool's holder measures, when its designation or `shank` says.
    sizes: Vec<(u32, HolderSize)>,
    /// The entries whose cutting outline's size the table does not state (an insert with
    /// no `edge` nor ISO designation, a blade without `width` or `reach`).
    assumed: Vec<u32>,
    /// The turning entries whose nose radius the table states.
    noses: Vec<u32>,
    /// The grooving entries whose width the table states.
    widths: Vec<u32>,
    /// The turning entries whose tip their holder's hand letter gave (no `tip` stated).
    hand_tips: Vec<u32>,
    /// The turning entries whose tip the table states (`tip`, or a holder's hand letter).
    tips: Vec<u32>,
    /// Tools with no entry, taken for what their moves say they are ([`by_use`]): they
    /// cut as these, and their size stays unstated.
    by_use: Vec<(u32, Tool)>,
}

impl ToolTable {
    /// A table with no entries: every tool gets the default.
    pub fn empty() -> Self {
        Self::default()
    }

    /// A table from explicit entries (T number, tool).
    pub fn from_tools(tools: Vec<(u32, Tool)>) -> Self {
        Self {
            noses: tools.iter().map(|(t, _)| *t).collect(),
            widths: tools.iter().map(|(t, _)| *t).collect(),
            tips: tools.iter().map(|(t, _)| *t).collect(),
            tools,
            designations: Vec::new(),
            sizes: Vec::new(),
            assumed: Vec::new(),
            hand_tips: Vec::new(),
            by_use: Vec::new(),
        }
    }

    /// The table with tool `t` given by `fields` (a `[[tool]]` entry's TOML without `t`)
    /// instead of its own entry (or beside the others, when it has none).
    pub fn replaced(&self, t: u32, fields: &str) -> Result<Self, StockError> {
        let one = Self::from_toml(&format!("[[tool]]\nt = {t}\n{fields}"))?;
        let mut out = self.clone();
        // in place: the first entry is the tool before the first T word
        match (
            out.tools.iter().position(|(n, _)| *n == t),
            one.tools.first(),
        ) {
            (Some(k), Some(new)) => out.tools[k] = new.clone(),
            (None, Some(new)) => out.tools.push(new.clone()),
            _ => {}
        }
        out.designations.retain(|(n, _)| *n != t);
        out.sizes.retain(|(n, _)| *n != t);
        out.assumed.retain(|n| *n != t);
        out.noses.retain(|n| *n != t);
        out.widths.retain(|n| *n != t);
        out.hand_tips.retain(|n| *n != t);
        out.tips.retain(|n| *n != t);
        out.by_use.retain(|(n, _)| *n != t);
        out.designations.extend(one.designations);
        out.sizes.extend(one.sizes);
        out.assumed.extend(one.assumed);
        out.noses.extend(one.noses);
        out.widths.extend(one.widths);
        out.hand_tips.extend(one.hand_tips);
        out.tips.extend(one.tips);
        Ok(out)
    }

    /// Parses the `[[tool]]` TOML format of the simulation spec.
    pub fn from_toml(text: &str) -> Result<Self, StockError> {
        let entries = schema::read(text)?;
        Ok(Self {
            designations: entries
                .iter()
                .filter_map(|e| e.designation.clone().map(|d| (e.t, d)))
                .collect(),
            sizes: entries.iter().map(|e| (e.t, e.size)).collect(),
            assumed: entries.iter().filter(|e| !e.stated).map(|e| e.t).collect(),
            noses: entries
                .iter()
                .filter(|e| e.nose_stated)
                .map(|e| e.t)
                .collect(),
            widths: entries
                .iter()
                .filter(|e| e.width_stated)
                .map(|e| e.t)
                .collect(),
            hand_tips: entries
                .iter()
                .filter(|e| e.tip_from_hand)
                .map(|e| e.t)
                .collect(),
            tips: entries
                .iter()
                .filter(|e| e.tip_stated)
                .map(|e| e.t)
                .collect(),
            tools: entries.into_iter().map(|e| (e.t, e.tool)).collect(),
            by_use: Vec::new(),
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

    /// The tool that cuts for `t` outside the cycles' hints: its entry, else what its moves
    /// say it is ([`ToolTable::tools_from_use`]), else the default insert.
    pub fn tool_or_default(&self, t: u32) -> &Tool {
        self.get(t)
            .or_else(|| self.use_default(t))
            .unwrap_or(&Tool::DEFAULT)
    }

    /// Whether tool `t` has no entry and is taken for what its moves say
    /// ([`ToolTable::tools_from_use`]) rather than the default insert.
    pub fn taken_from_moves(&self, t: u32) -> bool {
        self.get(t).is_none() && self.use_default(t).is_some()
    }

    /// What tool `t`, which has no entry, is taken for from its moves.
    fn use_default(&self, t: u32) -> Option<&Tool> {
        self.by_use
            .iter()
            .find(|(n, _)| *n == t)
            .map(|(_, tool)| tool)
    }

    /// Whether `seg` is cut by a grooving blade: the table's tool is one (or a tool with
    /// no entry is taken for one from its moves), or a grooving cycle says so (its hint).
    pub fn blade_cuts(&self, seg: &expander::Segment) -> bool {
        seg.hint != expander::ToolHint::Table
            || matches!(self.tool_or_default(seg.tool), Tool::Grooving(_))
    }

    /// The T numbers in the table, in file order.
    pub fn numbers(&self) -> Vec<u32> {
        self.tools.iter().map(|(t, _)| *t).collect()
    }

    /// Whether the table states turning tool `t`'s tip (`tip`, or its holder's hand
    /// letter): where it lies from the part is then known, OD or ID.
    pub fn tip_stated(&self, t: u32) -> bool {
        let t = if t == 0 {
            self.numbers().first().copied().unwrap_or(0)
        } else {
            t
        };
        self.tips.contains(&t)
    }

    /// The ISO designations tool `t` was given by (`"CNMG 120408 in PCLNR 2525M12"`).
    pub fn designation(&self, t: u32) -> Option<&str> {
        let t = if t == 0 { *self.numbers().first()? } else { t };
        self.designations
            .iter()
            .find(|(n, _)| *n == t)
            .map(|(_, d)| d.as_str())
    }

    /// One human line per tool, e.g. "T01 turning V 35°, r0.4, tip 3, κr 93°", with the
    /// designation when the table gave one ("… (CNMG 120408 in PCLNR 2525M12)").
    pub fn describe(&self, t: u32) -> String {
        match self.get(t) {
            Some(tool) => match self.designation(t) {
                Some(d) => format!("T{t:02} {} ({d})", tool.describe()),
                None => format!("T{t:02} {}", tool.describe()),
            },
            None => format!("T{t:02} {} (default)", self.tool_or_default(t).describe()),
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

    /// ISO designations give the outline facts; what the explicit fields would say.
    #[test]
    fn iso_designations_give_the_turning_facts() {
        let t = ToolTable::from_toml(
            "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n\
             [[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"CCMT 09T304\"\nholder = \"S20R-SCLCR09\"\n\
             [[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"VNMG 160404\"\nentering_angle = 93\n\
             [[tool]]\nt = 4\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\ntip = 4\nnose_radius = 0.8\n",
        )
        .unwrap();
        let turning = |n| match t.get(n) {
            Some(&Tool::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            }) => (
                insert,
                nose_radius,
                tip,
                entering_angle,
                (edge * 1000.0).round() / 1000.0,
            ),
            other => panic!("{other:?}"),
        };
        // C 80°, r0.8 (code 08), style L κr 95°, right-hand OD: tip 3; edge 12.896
        assert_eq!(turning(1), (Insert::C, 0.8, 3, 95.0, 12.896));
        // a right-hand boring bar with an L-style head: tip 2 (tnrc.md), κr 95°, r0.4, 9.672
        assert_eq!(turning(2), (Insert::C, 0.4, 2, 95.0, 9.672));
        // an insert alone: its shape, radius and edge, the holder's angle given explicitly
        assert_eq!(turning(3), (Insert::V, 0.4, 3, 93.0, 16.606));
        // an explicit tip wins (a rear post); a repeated radius that agrees is accepted
        assert_eq!(turning(4).2, 4);
        assert_eq!(
            t.describe(1),
            "T01 turning C 80°, r0.8, tip 3, κr 95° (CNMG 120408 in PCLNR 2525M12)"
        );
        assert_eq!(t.designation(3), Some("VNMG 160404"));
    }

    /// A wrong or inconsistent designation is an error at its tool's line naming the field.
    #[test]
    fn bad_designations_are_errors_at_their_line() {
        let cases = [
            // a C insert in a V holder
            (
                "insert = \"CNMG 120408\"\nholder = \"SVJBR 2525M16\"",
                "holder",
                "shape",
            ),
            // no such style letter
            (
                "insert = \"CNMG 120408\"\nholder = \"PCQNR 2525M12\"",
                "holder",
                "style",
            ),
            // no such nose radius code
            ("insert = \"CNMG 120407\"", "insert", "nose"),
            // the explicit field contradicts the designation
            (
                "insert = \"CNMG 120408\"\nnose_radius = 0.4",
                "nose_radius",
                "contradicts",
            ),
            // a holder without an insert designation
            (
                "insert = \"C\"\nholder = \"PCLNR 2525M12\"",
                "holder",
                "designation",
            ),
            // a shape latsim has no outline for
            ("insert = \"KNUX 160404\"", "insert", "outline"),
        ];
        for (body, field, word) in cases {
            let text = format!("# tools\n[[tool]]\nt = 5\nkind = \"turning\"\n{body}\n");
            match ToolTable::from_toml(&text) {
                Err(StockError::Tool {
                    t,
                    field: f,
                    line,
                    message,
                }) => {
                    assert_eq!((t, f, line), (5, field, 2), "{body}: {message}");
                    assert!(message.to_lowercase().contains(word), "{body}: {message}");
                }
                other => panic!("{body}: {other:?}"),
            }
        }
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
