//! Fingerprints of the variables, for telling a loop that cannot end: every value has a
//! pseudo-random share in its slot (vacant has none), and the fingerprint is their sum,
//! kept up to date as values change (O(1) a write, O(33) a call level). Equal
//! fingerprints only say "very likely the same values"; a [`Snapshot`] compares them bit
//! for bit.

use crate::value::Value;

/// The slot of common `#n` (100–199, 500–999).
pub(crate) fn common_slot(n: usize) -> usize {
    n
}

/// The slot of local index `i` (0–32, `#1` is 0) of call level `level` (0: main): after the
/// common variables, 33 a level.
pub(crate) fn local_slot(level: usize, i: usize) -> usize {
    1000 + 33 * level + i
}

/// `SplitMix64`'s finaliser: a bijection that spreads every input bit over the output.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// What a value adds to the fingerprint in `slot`: 0 when vacant, so vacant and 0.0 differ
/// and a fresh set of variables has fingerprint 0.
pub(crate) fn share(slot: usize, v: Value) -> u64 {
    match v.get() {
        None => 0,
        Some(x) => mix(x.to_bits() ^ mix(slot as u64 ^ 0x9e37_79b9_7f4a_7c15)),
    }
}

/// The values of all variables at one moment, compactly (the slots that hold a value):
/// what [`crate::Variables::same_as`] compares the present values with.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Snapshot {
    pub(crate) fingerprint: u64,
    /// Call levels open.
    pub(crate) levels: usize,
    /// (slot, bits of the value) of every slot that is not vacant, in slot order.
    pub(crate) values: Vec<(u32, u64)>,
    /// (level or `None` for a global, name, bits or `None` for vacant) of every named
    /// parameter (`LinuxCNC`).
    pub(crate) names: Vec<(Option<usize>, String, Option<u64>)>,
}

impl Snapshot {
    /// The variables' fingerprint at the time (compare it first: O(1)).
    pub fn fingerprint(&self) -> u64 {
        self.fingerprint
    }
}
