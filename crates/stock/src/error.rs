//! The one error type of the crate, with source positions for TOML input.

/// Everything that can go wrong while reading a blank, a profile or a tool table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StockError {
    /// A TOML file (profile or tool table) that does not parse or does not fit the format.
    #[error("{file} line {line}, column {column}: {message}")]
    Toml {
        /// Which kind of file: "profile" or "tool table".
        file: &'static str,
        /// 1-based line of the offending text.
        line: usize,
        /// 1-based column (in characters) of the offending text.
        column: usize,
        /// What is wrong.
        message: String,
        /// One sentence on how to fix it.
        help: String,
    },
    /// A tool table entry with a value out of range or not applicable to its kind.
    #[error("tool T{t} (line {line}): `{field}` {message}")]
    Tool {
        /// The entry's `t`.
        t: u32,
        /// The field at fault, named as in the file.
        field: &'static str,
        /// What is wrong with it.
        message: String,
        /// 1-based line where the entry starts.
        line: usize,
    },
    /// A `--stock` size such as `125x110` that cannot be read.
    #[error("stock size `{text}`: {message}")]
    Dims {
        /// The text as given.
        text: String,
        /// What is wrong.
        message: String,
    },
    /// Blank dimensions that describe no solid (negative length, bore wider than the bar...).
    #[error("blank: {0}")]
    Blank(String),
}

impl StockError {
    /// A help sentence for diagnostics, when there is one.
    pub fn help(&self) -> Option<&str> {
        match self {
            Self::Toml { help, .. } => Some(help),
            Self::Tool { .. } => Some("see the [[tool]] format in the simulation spec; every length is in mm, angles in degrees"),
            Self::Dims { .. } => Some("write the bar as DIAMETERxLENGTH in mm, for example 125x110"),
            Self::Blank(_) => None,
        }
    }
}

/// 1-based (line, column in characters) of byte `offset` in `text` (clamped to the text).
pub(crate) fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before[line_start..].chars().count() + 1;
    (line, column)
}

/// Turns a `toml` deserialisation error into a [`StockError::Toml`].
pub(crate) fn from_toml(
    file: &'static str,
    text: &str,
    err: &toml::de::Error,
    help: &str,
) -> StockError {
    let (line, column) = err.span().map_or((1, 1), |s| line_col(text, s.start));
    StockError::Toml {
        file,
        line,
        column,
        message: err.message().trim().to_string(),
        help: help.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_are_one_based_and_count_chars() {
        let text = "ab\nØcd\n";
        assert_eq!(line_col(text, 0), (1, 1));
        assert_eq!(line_col(text, 3), (2, 1));
        // 'Ø' is two bytes: 'c' is the second character of line 2
        assert_eq!(line_col(text, 5), (2, 2));
    }
}
