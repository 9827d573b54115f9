//! The program text a change makes ([`Change::edited`]): one implementation for the
//! binary's re-runs, the fuzzer's and the tests'.

use super::Change;

impl Change {
    /// `source` (the main program's text) with this change made; `None` for a tool change,
    /// or when the line it names is not there or does not hold the word it changes.
    pub fn edited(&self, source: &str) -> Option<String> {
        match self {
            Self::Tool { .. } => None,
            Self::Insert { line, text } => inserted(source, *line, text),
            Self::Feed { line } => fed(source, *line),
            Self::Swap { line } => swapped(source, *line),
        }
    }
}

/// `source` with `blocks` inserted before its 1-based line `line` (keeping its line ends);
/// `None` past its last line (a block of a `--lib` file).
fn inserted(source: &str, line: u32, blocks: &str) -> Option<String> {
    let at = line_start(source, line)?;
    let eol = if source.contains("\r\n") {
        "\r\n"
    } else {
        "\n"
    };
    Some(format!("{}{blocks}{eol}{}", &source[..at], &source[at..]))
}

/// `source` with the rapid word of its 1-based line `line` (`G00`, `G0`) made `G01`;
/// `None` when the line has none.
fn fed(source: &str, line: u32) -> Option<String> {
    replace_g(source, line, |n| (n == 0).then_some("G01"))
}

/// `source` with the G41 of its 1-based line `line` made G42, or its G42 made G41; `None`
/// when the line writes neither.
fn swapped(source: &str, line: u32) -> Option<String> {
    replace_g(source, line, |n| match n {
        41 => Some("G42"),
        42 => Some("G41"),
        _ => None,
    })
}

/// `source` with the first G word of its 1-based line `line` that `by` gives a new word
/// for (by its whole number: `G0`, `G00` are 0; `G41.1` is none) replaced by it.
fn replace_g(source: &str, line: u32, by: impl Fn(u32) -> Option<&'static str>) -> Option<String> {
    let at = line_start(source, line)?;
    let end = source[at..].find('\n').map_or(source.len(), |e| at + e);
    let text = &source.as_bytes()[at..end];
    let (word, len, to) = (0..text.len()).find_map(|k| {
        let digits = text[k + 1..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        let number: u32 = std::str::from_utf8(&text[k + 1..k + 1 + digits])
            .ok()?
            .parse()
            .ok()?;
        let whole = text[k].eq_ignore_ascii_case(&b'G') && text.get(k + 1 + digits) != Some(&b'.');
        whole
            .then(|| by(number))
            .flatten()
            .map(|to| (k, 1 + digits, to))
    })?;
    Some(format!(
        "{}{to}{}",
        &source[..at + word],
        &source[at + word + len..]
    ))
}

/// The byte where 1-based line `line` of `source` starts; `None` past its last line.
fn line_start(source: &str, line: u32) -> Option<usize> {
    let mut at = 0;
    for _ in 1..line {
        at += source[at..].find('\n')? + 1;
    }
    Some(at)
}

#[cfg(test)]
mod tests {
    use super::{fed, inserted, swapped};

    #[test]
    fn a_compensation_word_becomes_the_other() {
        assert_eq!(
            swapped("A\nG41 G01 Z2.\n", 2).as_deref(),
            Some("A\nG42 G01 Z2.\n")
        );
        assert_eq!(swapped("N5 G0G042X1\n", 1).as_deref(), Some("N5 G0G41X1\n"));
        assert_eq!(swapped("G40 G01 X1\n", 1), None);
        assert_eq!(swapped("G41.1 X1\n", 1), None);
    }

    #[test]
    fn a_rapid_word_becomes_a_feed() {
        assert_eq!(fed("A\nG00 X1 Z2\n", 2).as_deref(), Some("A\nG01 X1 Z2\n"));
        assert_eq!(fed("N5 G0X1\n", 1).as_deref(), Some("N5 G01X1\n"));
        assert_eq!(fed("G01 X1\n", 1), None);
    }

    #[test]
    fn blocks_go_before_their_line() {
        assert_eq!(
            inserted("A\nB\nC\n", 2, "X").as_deref(),
            Some("A\nX\nB\nC\n")
        );
        assert_eq!(
            inserted("A\r\nB\r\n", 1, "X").as_deref(),
            Some("X\r\nA\r\nB\r\n")
        );
        assert_eq!(inserted("A\nB\n", 9, "X"), None);
    }
}
