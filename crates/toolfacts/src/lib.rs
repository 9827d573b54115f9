//! The tool facts the interpreter needs from the tool table, and nothing else: the nose
//! of each offset (G41/G42 compensation) and the radial grooving blades (G75.1 without
//! I). The `stock` crate's tool table produces them (`ToolTable::facts`) and the
//! `expander` crate's options hold them, so neither crate has to know the other's types
//! for it, and the CLI only hands the value over.

use std::collections::BTreeMap;

/// A turning insert's nose as compensation sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nose {
    /// Nose radius, mm.
    pub radius: f64,
    /// Imaginary tip number 0–9 (spec/tnrc.md).
    pub tip: u8,
}

impl Nose {
    /// The nose of the documented default insert (a 55° D insert, r 0.4, tip 3), which
    /// cuts for a T number the table does not have.
    pub const DEFAULT: Self = Self {
        radius: 0.4,
        tip: 3,
    };
}

/// A radial grooving blade (its width spans along Z from the reference corner).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blade {
    /// Blade width, mm.
    pub width: f64,
    /// Whether the width spans toward +Z from the reference corner.
    pub toward_plus_z: bool,
}

/// What the tool table tells the interpreter.
#[derive(Debug, Clone, PartialEq)]
pub struct ToolFacts {
    /// The nose by offset number (`oo` of `Tttoo`); `Err` names a tool with no nose
    /// ("grooving blade", "drill", "threading tool"), for which compensation is ignored
    /// with a warning that says what it is. An offset with no entry uses
    /// [`ToolFacts::default_nose`].
    pub noses: BTreeMap<u32, Result<Nose, &'static str>>,
    /// The nose of an offset with no entry.
    pub default_nose: Nose,
    /// The radial grooving blades by tool number (`tt` of `Tttoo`).
    pub blades: BTreeMap<u32, Blade>,
}

impl Default for ToolFacts {
    /// No table: every offset gets the default nose, no tool is a blade.
    fn default() -> Self {
        Self {
            noses: BTreeMap::new(),
            default_nose: Nose::DEFAULT,
            blades: BTreeMap::new(),
        }
    }
}
