//! Text -> program: blocks, words, numbers and their source spans. No geometry, no modal state.
//!
//! ```
//! let p = gcode::parse("O0002;\nG90 X120 Z-110 F200;").unwrap();
//! assert_eq!(p.main().unwrap().blocks.at(0).words[1].value, 120.0);
//! ```
pub mod encoding;
mod foreign;
mod parse;
mod program;
mod radius;

pub use encoding::{decode, DecodeError, Decoded};
pub use macro_b::Span;
pub use parse::{parse, parse_held, parse_shared, parse_with, ParseError, ReadOptions};
pub use program::{address, Block, Blocks, CallText, Note, Program, Subprogram, Word};
