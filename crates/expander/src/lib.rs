//! Program -> toolpath: the modal interpreter and its segments.
pub mod toolpath;
pub use toolpath::{Arc, Feed, Motion, Pt, Segment, Span, Spindle};
