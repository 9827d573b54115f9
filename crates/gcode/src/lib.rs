//! Text -> program: blocks, words, numbers and their source spans. No geometry, no modal state.
//!
//! ```
//! let p = gcode::parse("O0002;\nG90 X120 Z-110 F200;").unwrap();
//! assert_eq!(p.main().unwrap().blocks.at(0).words[1].value, 120.0);
//! ```
//!
//! The modules, each below the next: `block` (a block's data), `read` (the reading, by
//! stage), `program` (the O programs, whose blocks are read again through `read`), `parse`
//! (the entry points).
mod block;
pub mod encoding;
mod parse;
mod program;
mod read;

pub use block::{address, Block, CallText, Note, Word};
pub use encoding::{decode, DecodeError, Decoded};
pub use macro_b::Span;
pub use parse::{parse, parse_held, parse_shared, parse_with};
pub use program::{Blocks, Program, Subprogram};
pub use read::{ParseError, ReadOptions};
