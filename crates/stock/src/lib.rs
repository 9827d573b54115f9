//! The removal engine: the blank, the tools as mounted, the sweep of every move and the
//! material it removes, with the crashes the removal meets (rapids into stock, bodies
//! touching stock). What a run concludes from it (gouges, workholding, threads, the
//! verdict) is the `analysis` crate's.
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
mod budget;
mod error;
mod mounted;
mod outline;
mod overlay;
mod pass_group;
mod profile;
mod removal;
mod ring_air;
mod section;
mod shape;
mod snapshot;
mod sweep;
mod tools;

pub use blank::Blank;
pub use budget::{process_memory, Ledger, MemoryBudget, OverBudget, RunMemory};
pub use error::StockError;
pub use mounted::{chord_sweeps, float_sweep, move_path, Mounted, Mounts};
pub use outline::{Outline, PastAxis};
pub use overlay::{clean, BoolOp};
pub use profile::profile_from_toml;
pub use removal::{simulate, Crash, SimOptions, Simulation, CRASH_MIN_AREA};
pub use section::rear_tools;
pub use shape::{area, boolean, hausdorff, revolved_volume, symmetric_difference_area, Shape};
pub use snapshot::{player_marks, EXACT_MAX_MOVES as SNAPSHOT_EXACT_MAX_MOVES};
pub use tools::{
    outward_travel, tip_taken_note, AxisDir, Body, GroovingBlade, HolderSize, Insert, ThreadSide,
    TipFromUse, Tool, ToolFromUse, ToolTable,
};
