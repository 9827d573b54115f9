//! `LinuxCNC`'s named parameters ([OV] "Named Parameters" in docs/linuxcnc.md): `#<name>`
//! local to the call level it is set in, `#<_name>` global. A name is defined by its first
//! assignment; reading one that is not is an error (`EXISTS[#<name>]` asks first).
//! Names that hold a space cannot be written in a program (`LinuxCNC` removes blanks from
//! names): the interpreter keeps its own per-level state under them (`repeat` counters).

use std::collections::BTreeMap;

use crate::value::Value;

/// The named parameters of a run: one map per call level and the globals.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Named {
    pub(crate) levels: Vec<BTreeMap<String, Value>>,
    pub(crate) globals: BTreeMap<String, Value>,
}

impl Default for Named {
    fn default() -> Self {
        Self {
            levels: vec![BTreeMap::new()],
            globals: BTreeMap::new(),
        }
    }
}

/// Whether `name` is a global (`_` first).
pub(crate) fn is_global(name: &str) -> bool {
    name.starts_with('_')
}

/// The fingerprint slot of `name` at `level` (`None`: a global): a hash well above the
/// numbered variables' slots. Equal slots only make the fingerprint less telling; the
/// snapshot compares names themselves.
pub(crate) fn name_slot(level: Option<usize>, name: &str) -> usize {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    let level = level.map_or(0, |l| l as u64 + 1);
    (h ^ level.wrapping_mul(0x9e37_79b9_7f4a_7c15)) as usize | (1 << 40)
}

impl Named {
    /// The map `name` lives in at the current level.
    pub(crate) fn map_mut(&mut self, name: &str) -> (&mut BTreeMap<String, Value>, Option<usize>) {
        if is_global(name) {
            (&mut self.globals, None)
        } else {
            let level = self.levels.len() - 1;
            (&mut self.levels[level], Some(level))
        }
    }

    /// The value of `name` at the current level, if defined.
    pub(crate) fn get(&self, name: &str) -> Option<Value> {
        let map = if is_global(name) {
            &self.globals
        } else {
            self.levels.last().expect("main level")
        };
        map.get(name).copied()
    }

    /// (level or `None` for globals, name, bits or `None` for vacant) of every name, in
    /// order: what a snapshot compares.
    pub(crate) fn held(&self) -> Vec<(Option<usize>, String, Option<u64>)> {
        let globals = self.globals.iter().map(|(n, v)| (None, n, v));
        let locals = self
            .levels
            .iter()
            .enumerate()
            .flat_map(|(l, m)| m.iter().map(move |(n, v)| (Some(l), n, v)));
        globals
            .chain(locals)
            .map(|(l, n, v)| (l, n.clone(), v.get().map(f64::to_bits)))
            .collect()
    }
}
