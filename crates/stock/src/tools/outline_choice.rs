//! Which outline cuts: a tool's own outline (the adapter onto `crate::outline`), the
//! default for a missing entry, and the blade a grooving cycle's hint asks for.

use super::{AxisDir, GroovingBlade, Insert, Tool, ToolTable};
use crate::outline::{self, InsertBody, Outline};
use expander::ToolHint;

/// The body of an insert's shape, for its outline.
fn body(insert: Insert) -> InsertBody {
    match insert {
        Insert::C | Insert::D | Insert::V | Insert::S => InsertBody::Rhombic,
        Insert::T | Insert::W => InsertBody::Triangle,
        Insert::R => InsertBody::Round,
    }
}

impl Tool {
    /// The outline relative to the reference point (see [`Outline`]).
    pub fn outline(&self) -> Outline {
        match *self {
            Self::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            } => outline::turning(
                body(insert),
                insert.included_angle(),
                nose_radius,
                tip,
                entering_angle,
                edge,
            ),
            Self::Grooving(b) => outline::grooving(
                b.width,
                b.width_dir.unit(),
                b.shank_dir.unit(),
                b.reach,
                b.corner_radius,
            ),
            Self::Drill {
                diameter,
                point_angle,
                reach,
            } => outline::drill(diameter, point_angle, reach),
            Self::Threading {
                angle,
                tip_flat,
                side,
            } => outline::threading(angle, tip_flat, side == super::ThreadSide::Id),
        }
    }
}

impl ToolTable {
    /// The outline for tool `t` (`tt` of `Tttoo`; 0 = no T word yet: the first entry).
    /// A missing entry or an empty table gives [`Tool::DEFAULT`] plus a warning text.
    pub fn outline(&self, t: u32) -> (Outline, Option<String>) {
        self.outline_for(t, ToolHint::Table)
    }
}

/// The shortest edge of an insert's stated core ([`ToolTable::stated_core`]), mm: a sharp
/// insert's core is its tip.
const CORE_EDGE: f64 = 0.2;

/// The tip of a blade whose width is known but not its reach: as deep as it is wide.
fn blade_stub(b: GroovingBlade) -> Outline {
    Tool::Grooving(GroovingBlade {
        reach: b.reach.min(b.width),
        ..b
    })
    .outline()
}

/// A cache key for the outline of tool `t` under `hint`.
pub(crate) fn hint_key(t: u32, hint: ToolHint) -> (u32, u8, u64) {
    match hint {
        ToolHint::Table => (t, 0, 0),
        ToolHint::Grooving | ToolHint::FaceGrooving => (t, 1, 0),
        ToolHint::Blade {
            width,
            toward_plus_z,
            shank_plus_x,
        } => (
            t,
            2 + u8::from(toward_plus_z) + 2 * u8::from(shank_plus_x),
            width.to_bits(),
        ),
    }
}

impl ToolTable {
    /// The outline that cuts tool `t` when a cycle adds `hint` (spec/simulation.md, Tools):
    /// the table's entry; in a grooving cycle with no entry, the default 3 mm blade; for
    /// G75.1's I, a blade of the program's width (shank, reach and corner radius from the
    /// table's grooving entry, if any). The text is a warning when a default stands in.
    pub fn outline_for(&self, t: u32, hint: ToolHint) -> (Outline, Option<String>) {
        let (tool, warning) = self.resolve(t, hint);
        (tool.outline(), warning)
    }

    /// Whether the table states the size of the outline that cuts for tool `t` under `hint`
    /// (spec/simulation.md, "Only stated geometry past the axis"): not for a default
    /// standing in, nor for an entry whose size is assumed; a G75.1 blade (its width the
    /// program's) takes its reach from the table's grooving entry.
    pub fn size_stated(&self, t: u32, hint: ToolHint) -> bool {
        let entry = if t == 0 {
            self.numbers().first().copied()
        } else {
            Some(t)
        };
        let Some(entry) = entry.filter(|&n| self.get(n).is_some()) else {
            return false;
        };
        let ok = match hint {
            ToolHint::Blade { .. } => matches!(self.get(entry), Some(Tool::Grooving(_))),
            _ => self.resolve(t, hint).1.is_none(),
        };
        ok && !self.assumed.contains(&entry)
    }

    /// The part of a guessed outline the table does state ([`ToolTable::size_stated`] is
    /// false): for a turning insert whose nose radius is given but not its size, the nose
    /// with edges as short as the nose allows — a part of the insert whatever its size;
    /// `None` when nothing of the outline is stated (then only its reference point is).
    pub fn stated_core(&self, t: u32, hint: ToolHint) -> Option<Outline> {
        if self.size_stated(t, hint) {
            return None;
        }
        if let ToolHint::Blade { .. } = hint {
            // the program gives the blade's width (G75.1 I): its tip is stated
            return match self.resolve(t, hint).0 {
                Tool::Grooving(b) => Some(blade_stub(b)),
                _ => None,
            };
        }
        let n = if t == 0 { *self.numbers().first()? } else { t };
        if hint != ToolHint::Table {
            return None;
        }
        if self.widths.contains(&n) {
            return match self.get(n)?.clone() {
                Tool::Grooving(b) => Some(blade_stub(b)),
                _ => None,
            };
        }
        if !self.noses.contains(&n) {
            return None;
        }
        match self.get(n)?.clone() {
            Tool::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                ..
            } => Some(
                Tool::Turning {
                    insert,
                    nose_radius,
                    tip,
                    entering_angle,
                    edge: (2.0 * nose_radius).max(CORE_EDGE),
                }
                .outline(),
            ),
            _ => None,
        }
    }

    /// The tool that cuts for tool `t` under `hint`, described (a default's or a cycle's
    /// blade's own description).
    pub fn describe_for(&self, t: u32, hint: ToolHint) -> String {
        self.resolve(t, hint).0.describe()
    }

    /// The warning for an entry whose outline's size is assumed, once per tool.
    pub fn size_warning(&self, t: u32, hint: ToolHint) -> Option<String> {
        if self.size_stated(t, hint) || self.resolve(t, hint).1.is_some() {
            return None;
        }
        let n = if t == 0 {
            self.numbers().first().copied()?
        } else {
            t
        };
        let what = match self.get(n)? {
            Tool::Turning { edge, .. } => format!(
                "insert size not given, {} mm edges assumed (state `edge` or an ISO insert such as \"CNMG 120408\")",
                crate::blank::fmt_num(*edge)
            ),
            Tool::Grooving(b) => format!(
                "blade width or reach not given, {} × {} mm assumed (state `width` and `reach`)",
                crate::blank::fmt_num(b.width),
                crate::blank::fmt_num(b.reach)
            ),
            _ => return None,
        };
        Some(format!("T{n:02}: {what}; past the axis it is not checked"))
    }

    /// The tool that cuts for tool `t` under `hint` (see [`ToolTable::outline_for`]), with
    /// the warning when a default stands in.
    pub(super) fn resolve(&self, t: u32, hint: ToolHint) -> (Tool, Option<String>) {
        let table = || match (self.get(t), self.use_default(t)) {
            (Some(tool), _) => (tool.clone(), None),
            (None, Some(tool)) => (tool.clone(), Some(super::by_use::taken_note(t, tool))),
            (None, None) => {
                let why = if self.tools.is_empty() {
                    format!("no tool table: T{t:02} is taken as the default")
                } else {
                    format!("T{t:02} has no entry in the tool table: using the default")
                };
                (
                    Tool::DEFAULT,
                    Some(format!("{why} ({})", Tool::DEFAULT.describe())),
                )
            }
        };
        match hint {
            ToolHint::Table => table(),
            ToolHint::Grooving | ToolHint::FaceGrooving => match (self.get(t), self.use_default(t)) {
                (Some(tool), _) => (tool.clone(), None),
                (None, Some(tool)) => (tool.clone(), Some(super::by_use::taken_note(t, tool))),
                (None, None) => (
                    Tool::DEFAULT_BLADE,
                    Some(format!("T{t:02} has no entry in the tool table: the grooving cycle uses the default ({})", Tool::DEFAULT_BLADE.describe())),
                ),
            },
            ToolHint::Blade { width, toward_plus_z, shank_plus_x } => {
                let default_shank = if shank_plus_x { AxisDir::PlusX } else { AxisDir::MinusX };
                let (shank_dir, reach, corner_radius) = match self.get(t) {
                    Some(Tool::Grooving(b)) => (b.shank_dir, b.reach, b.corner_radius),
                    _ => (default_shank, 20.0, 0.0),
                };
                if width.is_finite() && width > 0.0 && width < 1e4 {
                    let width_dir = if toward_plus_z { AxisDir::PlusZ } else { AxisDir::MinusZ };
                    let shank_dir = if matches!(shank_dir, AxisDir::PlusX | AxisDir::MinusX) { shank_dir } else { default_shank };
                    (Tool::Grooving(GroovingBlade { width, width_dir, shank_dir, reach, corner_radius: corner_radius.min(width / 2.0) }), None)
                } else {
                    let (tool, _) = table();
                    (tool, Some(format!("blade width {width} is not a positive length: T{t:02}'s outline is used")))
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g75_1_blade_without_a_table_entry_faces_the_groove() {
        let t = ToolTable::empty();
        let od = ToolHint::Blade {
            width: 4.0,
            toward_plus_z: false,
            shank_plus_x: true,
        };
        let id = ToolHint::Blade {
            width: 4.0,
            toward_plus_z: false,
            shank_plus_x: false,
        };
        let (o, w) = t.outline_for(1, od);
        let (lo, hi) = o.bbox().unwrap();
        assert!(
            w.is_none() && lo[1] >= -1e-9 && hi[1] > 10.0 && (lo[0] + 4.0).abs() < 1e-9,
            "{lo:?} {hi:?}"
        );
        let (lo, hi) = t.outline_for(1, id).0.bbox().unwrap();
        assert!(
            hi[1] <= 1e-9 && lo[1] < -10.0,
            "an ID blade runs toward -X: {lo:?} {hi:?}"
        );
    }
}
