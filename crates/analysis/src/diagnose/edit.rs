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
/// `None` when one does, or when the program has no plain one. The F of a thread (G32, G33,
/// G34, G76, G78, G92) is its lead, no feed (review 1128h, #4: `F1.5` of a G92 was offered
/// as the feed into a face); a macro's `F#1` counts as a feed in force, and is none to copy.
pub(super) fn feed_word_for(source: &str, line: u32) -> Option<String> {
    for (k, text) in source.lines().enumerate() {
        match feed_word(text) {
            Feed::None => {}
            _ if k < line as usize => return None,
            Feed::Plain(f) => return Some(f),
            Feed::Other => return None,
        }
    }
    None
}

/// A block's F word (outside its comments), if it is a feed.
enum Feed {
    None,
    /// As written (`F0.05`).
    Plain(String),
    /// A macro's (`F#1`, `F[#1*2]`): a feed, but no number to copy.
    Other,
}

/// The feed word of a block: its F (outside its comments), unless it is a thread's lead.
fn feed_word(block: &str) -> Feed {
    let code = block.split(';').next().unwrap_or("");
    let mut depth = 0;
    let b = code.as_bytes();
    let mut found = Feed::None;
    let mut thread = false;
    for (k, &c) in b.iter().enumerate() {
        let word_start = depth == 0 && (k == 0 || !b[k - 1].is_ascii_alphabetic());
        match c {
            b'(' => depth += 1,
            b')' => depth = (depth - 1).max(0),
            b'G' | b'g' if word_start => {
                let n: String = b[k + 1..]
                    .iter()
                    .take_while(|d| d.is_ascii_digit())
                    .map(|&d| d as char)
                    .collect();
                thread |= matches!(n.parse::<u32>(), Ok(32 | 33 | 34 | 76 | 78 | 92));
            }
            b'F' | b'f' if word_start && matches!(found, Feed::None) => {
                let rest = code[k + 1..].trim_start();
                let n = rest
                    .bytes()
                    .take_while(|d| d.is_ascii_digit() || *d == b'.')
                    .count();
                found = if n > 0 {
                    Feed::Plain(format!("F{}", &rest[..n]))
                } else if rest.starts_with(['#', '[']) {
                    Feed::Other
                } else {
                    Feed::None
                };
            }
            _ => {}
        }
    }
    if thread {
        Feed::None
    } else {
        found
    }
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
        // a thread's F is its lead; a macro's F is a feed in force; a space may follow F
        assert_eq!(
            feed_word_for("G00 Z-3.\nG92 X28. Z-20. F1.5\nG01 X1 F0.1\n", 1).as_deref(),
            Some("F0.1")
        );
        assert_eq!(
            feed_word_for("G00 Z-3.\nG76 X28. Z-20. P900 Q300 F1.5\n", 1),
            None
        );
        assert_eq!(feed_word_for("G01 F#1\nG00 X1\n", 2), None);
        assert_eq!(
            feed_word_for("G00 X1\nG01 X0 F 0.2\n", 1).as_deref(),
            Some("F0.2")
        );
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
