//! Diagnostics rendered like rustc: `file:line:column`, the source line, a caret, a help line.

use miette::{LabeledSpan, MietteDiagnostic, NamedSource, Severity};

/// A program file's name and text, for showing source lines.
pub(crate) struct Source {
    pub(crate) name: String,
    pub(crate) text: String,
}

/// Print one diagnostic pointing into `src` at byte range `offset..offset+len`.
pub(crate) fn print_at(
    src: &Source,
    offset: usize,
    len: usize,
    code: &str,
    message: &str,
    help: &str,
    warning: bool,
) {
    let offset = offset.min(src.text.len());
    let len = len
        .min(src.text.len() - offset)
        .max(usize::from(offset < src.text.len()));
    let mut d = MietteDiagnostic::new(message.to_string())
        .with_code(code.to_string())
        .with_severity(if warning {
            Severity::Warning
        } else {
            Severity::Error
        })
        .with_label(LabeledSpan::at(offset..offset + len, "here"));
    if !help.is_empty() {
        d = d.with_help(help.to_string());
    }
    let report = miette::Report::new(d)
        .with_source_code(NamedSource::new(src.name.clone(), src.text.clone()));
    eprintln!("{report:?}");
}

/// Print a diagnostic that belongs to a line and column of a file (TOML inputs).
pub(crate) fn print_line_col(
    src: &Source,
    line: usize,
    column: usize,
    code: &str,
    message: &str,
    help: &str,
) {
    let offset = offset_of(&src.text, line, column);
    print_at(src, offset, 1, code, message, help, false);
}

/// Print an error that has no place in a file (a missing file, a bad flag value).
pub(crate) fn print_plain(message: &str, help: &str) {
    let mut d = MietteDiagnostic::new(message.to_string());
    if !help.is_empty() {
        d = d.with_help(help.to_string());
    }
    eprintln!("{:?}", miette::Report::new(d));
}

/// Byte offset of a 1-based line and character column.
pub(crate) fn offset_of(text: &str, line: usize, column: usize) -> usize {
    let mut offset = 0;
    for (i, l) in text.split_inclusive('\n').enumerate() {
        if i + 1 == line {
            return offset
                + l.char_indices()
                    .nth(column.saturating_sub(1))
                    .map_or(l.len(), |(b, _)| b);
        }
        offset += l.len();
    }
    text.len()
}
