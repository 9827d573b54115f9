//! Text -> program: blocks, words, numbers and their source spans. No geometry, no modal state.
mod span;
pub use span::Span;
