//! Diagnostics rendered like rustc: `file:line:column`, the source line, a caret, a help line.
//!
//! Rendering never panics and never prints a huge line: the snippet handed to miette is a
//! window of at most [`WINDOW`] characters around the caret (with the true line and column
//! numbers), the span is clamped to that window, and if miette still fails the diagnostic
//! is printed plain as `file:line:col: code: message`.

use miette::{
    LabeledSpan, MietteDiagnostic, MietteError, MietteSpanContents, Severity, SourceCode,
    SourceSpan, SpanContents,
};
use std::cell::Cell;

/// A program file's name and text, for showing source lines.
#[derive(Clone)]
pub(crate) struct Source {
    pub(crate) name: String,
    /// Shared with the program read from it (its blocks are read again from the text).
    pub(crate) text: std::sync::Arc<str>,
}

/// Most characters of a source line shown around the caret.
const WINDOW: usize = 120;

thread_local! {
    /// Set while this thread renders a diagnostic: a panic inside miette is caught and
    /// answered with the plain form, so the panic hook keeps quiet about it.
    static RENDERING: Cell<bool> = const { Cell::new(false) };
}

/// Installs a panic hook that stays silent for panics caught while rendering a
/// diagnostic (they fall back to the plain form) and reports every other one as usual.
pub(crate) fn install_panic_hook() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if !RENDERING.with(Cell::get) {
            default(info);
        }
    }));
}

/// The part of a source shown in a snippet: a contiguous byte range `start..end` of the
/// text (whole short lines around the caret's line, or a window of a long one), with the
/// 0-based line and character column where it starts.
struct Excerpt {
    name: String,
    data: String,
    start: usize,
    line: usize,
    column: usize,
    line_count: usize,
}

impl SourceCode for Excerpt {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let rel = span.offset().saturating_sub(self.start);
        if before == 0 && after == 0 && rel <= self.data.len() && self.data.is_char_boundary(rel) {
            // the span itself: where it starts is the place printed in the header
            let end = (rel + span.len()).min(self.data.len());
            let end = floor_char(&self.data, end).max(rel);
            let head = &self.data[..rel];
            let (line, column) = match head.rfind('\n') {
                Some(i) => (
                    self.line + head.matches('\n').count(),
                    head[i + 1..].chars().count(),
                ),
                None => (self.line, self.column + head.chars().count()),
            };
            return Ok(Box::new(MietteSpanContents::new_named(
                self.name.clone(),
                &self.data.as_bytes()[rel..end],
                (self.start + rel, end - rel).into(),
                line,
                column,
                self.data[rel..end].lines().count().max(1),
            )));
        }
        Ok(Box::new(MietteSpanContents::new_named(
            self.name.clone(),
            self.data.as_bytes(),
            (self.start, self.data.len()).into(),
            self.line,
            self.column,
            self.line_count,
        )))
    }
}

/// The 0-based number, start and end (before its line end) of the line holding `offset`.
fn line_at(text: &str, offset: usize) -> (usize, usize, usize) {
    let start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let end = text[offset..]
        .find(['\n', '\r'])
        .map_or(text.len(), |i| offset + i);
    let number = text.as_bytes()[..start]
        .iter()
        .filter(|&&b| b == b'\n')
        .count();
    (number, start, end)
}

/// Nearest char boundary at or before `i`.
fn floor_char(text: &str, mut i: usize) -> usize {
    i = i.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The excerpt shown for a caret at byte `offset`, and the span clamped into it.
fn excerpt(src: &Source, offset: usize, len: usize) -> (Excerpt, usize, usize) {
    let text = &*src.text;
    let offset = floor_char(text, offset);
    let (_, lstart, lend) = line_at(text, offset);
    let short = |a: usize, b: usize| text[a..b].chars().count() <= WINDOW;
    let (start, end) = if short(lstart, lend) {
        // the caret's line with one short neighbour line on each side, as rustc shows
        let mut s = lstart;
        if lstart > 0 {
            let (_, ps, pe) = line_at(text, lstart - 1);
            if short(ps, pe) {
                s = ps;
            }
        }
        let mut e = lend;
        let next = text[lend..].find('\n').map(|i| lend + i + 1);
        if let Some(ns) = next.filter(|&ns| ns < text.len()) {
            let (_, _, ne) = line_at(text, ns);
            if short(ns, ne) {
                e = ne;
            }
        }
        (s, e)
    } else {
        // a window of the long line around the caret
        let before: Vec<usize> = text[lstart..offset]
            .char_indices()
            .map(|(i, _)| lstart + i)
            .collect();
        let s = before
            .len()
            .checked_sub(WINDOW / 3)
            .map_or(lstart, |k| before[k]);
        let e = text[offset..lend]
            .char_indices()
            .nth(WINDOW - WINDOW / 3)
            .map_or(lend, |(i, _)| offset + i);
        (s, e)
    };
    let (first_line, first_start, _) = line_at(text, start);
    let column = text[first_start..start].chars().count();
    let data = text[start..end].to_string();
    let line_count = data.lines().count().max(1);
    let len = len
        .min(end.saturating_sub(offset))
        .max(usize::from(offset < end));
    (
        Excerpt {
            name: src.name.clone(),
            data,
            start,
            line: first_line,
            column,
            line_count,
        },
        offset,
        len,
    )
}

/// 1-based line and character column of a byte offset.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = floor_char(text, offset);
    let (line, start, _) = line_at(text, offset);
    (line + 1, text[start..offset].chars().count() + 1)
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
    let (excerpt, offset, len) = excerpt(src, offset, len);
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
    let report = miette::Report::new(d).with_source_code(excerpt);
    match render(&report) {
        Some(text) => eprint!("{text}"),
        None => {
            let (line, col) = line_col(&src.text, offset);
            let kind = if warning { "warning" } else { "error" };
            eprintln!("{}:{line}:{col}: {kind}[{code}]: {message}", src.name);
            if !help.is_empty() {
                eprintln!("  help: {help}");
            }
        }
    }
}

/// The report drawn by miette's handler (as `{report:?}` prints it), or `None` if it
/// panicked.
fn render(report: &miette::Report) -> Option<String> {
    RENDERING.with(|r| r.set(true));
    let out = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| format!("{report:?}\n")));
    RENDERING.with(|r| r.set(false));
    out.ok()
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
    let report = miette::Report::new(d);
    match render(&report) {
        Some(text) => eprint!("{text}"),
        None => {
            eprintln!("error: {message}");
            if !help.is_empty() {
                eprintln!("  help: {help}");
            }
        }
    }
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

/// `v` rounded to tenths for the terminal, never `-0.0` (a change or a removal too small to
/// print is none: a blank the program only grazes removed −2·10⁻⁶ mm²).
pub(crate) fn tenths(v: f64) -> f64 {
    (v * 10.0).round() / 10.0 + 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn src(text: &str) -> Source {
        Source {
            name: "t.nc".into(),
            text: text.into(),
        }
    }

    fn shown(text: &str, offset: usize, len: usize) -> String {
        let (e, o, l) = excerpt(&src(text), offset, len);
        let d = MietteDiagnostic::new("m").with_label(LabeledSpan::at(o..o + l, "here"));
        render(&miette::Report::new(d).with_source_code(e)).unwrap()
    }

    #[test]
    fn short_lines_show_their_neighbours_and_the_true_place() {
        let s = shown("G0 X1\nG1 Z5 Q7\nM30\n", 12, 2);
        assert!(s.contains("[t.nc:2:7]"), "{s}");
        assert!(s.contains("G0 X1") && s.contains("M30"), "{s}");
    }

    #[test]
    fn a_caret_far_along_a_long_line_is_shown_in_a_window() {
        let line = format!("G0 X1 {}Q5", "Z1".repeat(40_000));
        let offset = line.find('Q').unwrap();
        let s = shown(&line, offset, 100_000);
        assert!(s.contains("[t.nc:1:80007]"), "{s}");
        assert!(s.lines().all(|l| l.chars().count() < 200), "{s}");
    }

    #[test]
    fn offsets_inside_a_character_and_past_the_end_are_clamped() {
        let s = shown("(ä)\nX", 2, 5);
        assert!(s.contains("[t.nc:1:2]"), "{s}");
        let s = shown("G0", 50, 5);
        assert!(s.contains("t.nc"), "{s}");
    }
}
