//! Source positions: every word, block, alarm and segment points back at its text (the
//! reader and the macro language share it; `gcode::Span` re-exports it).

/// A place in the program text: 1-based line and column (in characters), plus the
/// byte range so a diagnostic renderer can underline it. 16 bytes: a million-line program
/// holds several million spans, and a text is at most `u32::MAX` bytes (the reader refuses
/// a longer one).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub struct Span {
    /// 1-based line number.
    pub line: u32,
    /// 1-based column, counted in characters (not bytes).
    pub column: u32,
    /// Byte offset of the first character in the source.
    pub offset: u32,
    /// Length in bytes.
    pub len: u32,
}

impl Span {
    /// The smallest span covering both `self` and `other` (same source assumed).
    #[inline]
    pub fn to(self, other: Self) -> Self {
        let (a, b) = if self.offset <= other.offset {
            (self, other)
        } else {
            (other, self)
        };
        let end = (b.offset + b.len).max(a.offset + a.len);
        Self {
            line: a.line,
            column: a.column,
            offset: a.offset,
            len: end - a.offset,
        }
    }
}

impl std::fmt::Display for Span {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}
