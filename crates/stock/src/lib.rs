//! Blank, tool outlines, sweeps, material removal, crash detection and measures.
//!
//! Everything here lives in the (z, r) half plane, mm, f64 (r = X / 2), except the TOML
//! files, which are in program coordinates (z, x = diameter). The crate knows nothing of
//! G-code text: it consumes [`expander::Segment`]s.
//!
//! ```
//! use stock::{Blank, ToolTable, SimOptions, simulate, area};
//! let blank = Blank::bar(20.0, 10.0, 0.0, None).unwrap();
//! let sim = simulate(&blank, &ToolTable::empty(), &[], &SimOptions::default(), &mut |_| {});
//! assert!((area(&sim.final_shapes) - 100.0).abs() < 1e-6);
//! ```

mod blank;
mod deviation;
mod error;
mod fixture;
mod measure;
mod outline;
mod overlay;
mod pass_group;
mod pose;
mod profile;
mod removal;
mod ring_air;
mod section;
mod snapshot;
mod sweep;
mod tools;

pub use blank::Blank;
pub use deviation::{deviation, Deviation, Finding, Intent};
pub use error::StockError;
pub use fixture::{Fixture, FixtureCrash, Obstacle, GRIPPED_LENGTH, TAILSTOCK_CENTRE};
pub use measure::{
    area, deepest_radius, groove_deviation, hausdorff, least_gap, revolved_volume,
    surface_radius_at, symmetric_difference_area, thread_starts, threads, Reference, Surface,
    Thread, ThreadForm, ThreadPasses,
};
pub use outline::Outline;
pub use overlay::BoolOp;
pub use pose::{tool_at_crash, tool_outlines};
pub use profile::profile_from_toml;
pub use removal::{simulate, Crash, SimOptions, Simulation, CRASH_MIN_AREA};
pub use section::rear_tools;
pub use snapshot::EXACT_MAX_MOVES as SNAPSHOT_EXACT_MAX_MOVES;
pub use tools::{AxisDir, Body, GroovingBlade, HolderSize, Insert, ThreadSide, Tool, ToolTable};

/// A polygon with holes in (z, r): `outer` counter-clockwise, `holes` clockwise; rings are
/// not closed (the first point is not repeated).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Shape {
    /// Outer boundary, counter-clockwise.
    pub outer: Vec<[f64; 2]>,
    /// Holes, clockwise.
    pub holes: Vec<Vec<[f64; 2]>>,
}

/// Boolean operation between two shape sets (non-zero fill), on a grid fitted to both.
/// Rings holding a non-finite coordinate are ignored.
pub fn boolean(a: &[Shape], b: &[Shape], op: BoolOp) -> Vec<Shape> {
    overlay::boolean(a, b, op)
}
