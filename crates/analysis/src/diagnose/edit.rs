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

/// `source` with the rapid word of its 1-based line `line` (`G00`, `G0`) made `G01`, and
/// the feed word [`feed_word_for`] asks for written at the block's end; `None` when the line
/// has no rapid word.
fn fed(source: &str, line: u32) -> Option<String> {
    let mut text = replace_g(source, line, |n| (n == 0).then_some("G01"))?;
    if let Some(f) = feed_word_for(source, line) {
        let at = line_start(&text, line)?;
        let end = text[at..].find('\n').map_or(text.len(), |e| at + e);
        let block = &text[at..end];
        // before the end-of-block `;` or the line end
        let cut = block
            .find(';')
            .unwrap_or(block.trim_end_matches('\r').len());
        text.insert_str(at + cut, &format!(" {f}"));
    }
    Some(text)
}

/// The feed word (`F0.05`) a rapid at 1-based line `line` made a feed must carry: the
/// program's next one when no F word stands on that line or before it (a `G01` with no feed
/// in force is an alarm: a blade's `G00 X20.` before the `G01 X-1. F0.05` that parts off);
/// `None` when one does, or when the program has none.
pub(super) fn feed_word_for(source: &str, line: u32) -> Option<String> {
    let mut next = None;
    for (k, text) in source.lines().enumerate() {
        let f = feed_word(text);
        if k < line as usize {
            if f.is_some() {
                return None;
            }
        } else if f.is_some() {
            next = f;
            break;
        }
    }
    next
}

/// The F word of a block (outside its comments), as written.
fn feed_word(block: &str) -> Option<String> {
    let code = block.split(';').next().unwrap_or("");
    let mut depth = 0;
    let b = code.as_bytes();
    for (k, &c) in b.iter().enumerate() {
        match c {
            b'(' => depth += 1,
            b')' => depth = (depth - 1).max(0),
            b'F' | b'f' if depth == 0 && (k == 0 || !b[k - 1].is_ascii_alphabetic()) => {
                let n = b[k + 1..]
                    .iter()
                    .take_while(|d| d.is_ascii_digit() || **d == b'.')
                    .count();
                if n > 0 {
                    return Some(format!("F{}", &code[k + 1..k + 1 + n]));
                }
            }
            _ => {}
        }
    }
    None
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
    use super::{fed, feed_word_for, inserted, swapped};

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
        assert_eq!(
            fed("F1\nG00 X1 Z2\n", 2).as_deref(),
            Some("F1\nG01 X1 Z2\n")
        );
        assert_eq!(fed("F.1\nN5 G0X1\n", 2).as_deref(), Some("F.1\nN5 G01X1\n"));
        assert_eq!(fed("G01 X1\n", 1), None);
    }

    /// With no feed in force, the rapid made a feed takes the program's next F word, written
    /// before the block's end (`;`, a CR); a feed word in a comment is none.
    #[test]
    fn a_rapid_made_a_feed_with_no_feed_in_force_takes_the_next_one() {
        let text = "(FEED F9)\nG00 X20.;\r\nG01 X-1. F0.05;\r\n";
        assert_eq!(feed_word_for(text, 2).as_deref(), Some("F0.05"));
        assert_eq!(
            fed(text, 2).as_deref(),
            Some("(FEED F9)\nG01 X20. F0.05;\r\nG01 X-1. F0.05;\r\n")
        );
        assert_eq!(
            fed("G00 X20.\r\nG01 X-1. F0.05\n", 1).as_deref(),
            Some("G01 X20. F0.05\r\nG01 X-1. F0.05\n")
        );
        assert_eq!(feed_word_for("G99 F0.2\nG00 X1\nG01 X0 F0.1\n", 2), None);
        assert_eq!(feed_word_for("G00 X1\nM30\n", 1), None);
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
