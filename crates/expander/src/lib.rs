//! Program -> toolpath: the modal interpreter, (later) the canned cycles and tool nose
//! radius compensation. Knows nothing of stock or pictures.
//!
//! ```
//! let program = gcode::parse("G99 M3 S500 T0101\nG0 X40 Z2\nG1 Z-20 F0.2\nM30").unwrap();
//! let tp = expander::expand(&program, &expander::Machine::default(), &Default::default());
//! assert!(tp.alarms.is_empty());
//! assert_eq!(tp.segments.last().unwrap().to, expander::Pt::new(-20.0, 20.0));
//! ```
mod alarm;
mod arc;
mod codes;
mod corner;
mod cycles;
mod dialect;
mod interp;
mod library;
mod machine;
mod mcodes;
mod text_place;
pub mod timing;
mod tnrc;
mod toolpath;
mod words;
mod workholding;

pub use alarm::Diagnostic;
pub use interp::{expand, Options, Toolpath};
pub use library::{Library, LibraryRef};
pub use machine::{
    Control, DrillReturn, FeedMode, G01Cr, GCodeSystem, HaasSettings, Increment, Machine, PqUnits,
    ProfileError, RapidPath, ShortT, Units, XMode,
};
pub use toolpath::{
    Arc, Feed, FeedId, Feeds, Intended, IntendedKind, Motion, Pt, Segment, Span, Spindle, ToolHint,
};
pub use workholding::{Chuck, Tailstock, Workholding, WorkholdingError};
