//! `LinuxCNC`'s one-line threading cycle `G76 P Z I J [R] K [Q] [H] [E] [L]` under
//! `--control linuxcnc` (issue 36; docs/linuxcnc-g76.md, from `LinuxCNC`'s G-code reference
//! "G76 Threading Cycle" and its interpreter's `convert_threading_cycle`).
//!
//! The drive line runs through the start point parallel to Z. Pass n cuts at
//! |I| + J·n^(1/R) below it (above it in a bore, I > 0) while that is less than |I| + K,
//! then H + 1 passes at |I| + K. Each pass is shifted along Z by (depth − |I|)·tan Q, so the
//! leading flank cuts; it retracts |I| + K from its depth, back to its start Z, in, threads
//! to the end (tapered over E at the ends L selects), and out. The tool ends at the end of
//! the drive line.

mod plan;
mod read;

use super::{Cycle, Output};
use crate::Diagnostic;

/// The interpreter's modes a `LinuxCNC` cycle reads (G76, the drilling cycles).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Modes {
    /// G7 in force: I, J and K are diameters (`LinuxCNC` halves them).
    pub(crate) x_diameter: bool,
    /// G41/G42 (or G41.1/G42.1) in force: `LinuxCNC` refuses G76.
    pub(crate) compensating: bool,
    /// M3/M4 in force: `LinuxCNC` refuses G76 with the spindle stopped.
    pub(crate) spindle_turning: bool,
    /// G91 in force (the drilling cycles' R and Z read otherwise).
    pub(crate) incremental: bool,
}

/// One G76 block as `LinuxCNC` reads it. Lengths in mm, radii.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Params {
    /// P: the pitch, distance along Z per revolution.
    pub(crate) pitch: f64,
    /// Z: the end of the drive line (G54 frame).
    pub(crate) end_z: f64,
    /// X of the block: where the last rapid goes (`LinuxCNC`'s interpreter; its reference
    /// says an X is an error), else the drive line.
    pub(crate) end_x: Option<f64>,
    /// I: the thread peak's offset from the drive line, negative outside.
    pub(crate) i: f64,
    /// J: the first cut's depth beyond the peak.
    pub(crate) j: f64,
    /// K: the full thread depth beyond the peak.
    pub(crate) k: f64,
    /// R: the depth degression, 1 or more.
    pub(crate) degression: f64,
    /// Q: the compound slide angle, degrees.
    pub(crate) compound: f64,
    /// H: spring passes after the first at full depth.
    pub(crate) spring: u32,
    /// E: the taper's length along the drive line, 0 or more.
    pub(crate) taper: f64,
    /// L bit 1: a taper at the entry.
    pub(crate) entry_taper: bool,
    /// L bit 2: a taper at the exit.
    pub(crate) exit_taper: bool,
}

/// Run a `LinuxCNC` G76 block (or a block repeating it: G76 is modal in `LinuxCNC`, and a
/// repeat without P, I, J, K is `LinuxCNC`'s own alarm).
pub(crate) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let mut warnings = Vec::new();
    let p = read::params(c, c.linuxcnc, &mut warnings)?;
    Ok(Output {
        moves: plan::moves(c.start, &p, c.unit),
        warnings,
        ..Output::default()
    })
}
