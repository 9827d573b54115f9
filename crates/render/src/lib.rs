//! Report -> SVG, PNG and JSON.
mod report;
pub use report::*;
