//! The measures the reports show of the findings: how far a groove strays ([`groove`]) and
//! how deep threads were cut ([`thread`]). (Where a leftover is thickest is the deviation's
//! own deepest point, `Finding::at` and `nearest`.)

mod groove;
mod surface;
mod thread;

pub use groove::groove_deviation;
pub use thread::{
    deepest_radius, least_gap, surface_radius_at, thread_starts, threads, Reference, Surface,
    Thread, ThreadForm, ThreadPasses,
};
