//! What is not code: comments in parentheses (read the way the author meant them where
//! FANUC would read them otherwise, spec/dialects.md §1) and prose after `;` (a comment in
//! another control's style).

/// Macro B words that are letters only; any other run of two letters after `;` is prose.
const KEYWORDS: [&str; 37] = [
    "IF", "GOTO", "WHILE", "WH", "DO", "END", "THEN", "ELSE", "ENDIF", "EQ", "NE", "GT", "GE",
    "LT", "LE", "AND", "OR", "XOR", "MOD", "SIN", "COS", "TAN", "ATAN", "ASIN", "ACOS", "SQRT",
    "ABS", "ROUND", "FIX", "FUP", "LN", "EXP", "POW", "ADP", "BIN", "BCD", "POPEN",
];

/// Whether the text after a `;` is prose (a comment in another control's style) rather
/// than blocks: it holds a non-ASCII character, or a run of two or more letters that is
/// not a macro keyword (in a program every letter is followed by its number).
#[inline]
pub(super) fn is_prose(rest: &str) -> bool {
    let mut depth = 0;
    // the run of letters (a comment inside does not break it); only its first
    // `LONGEST_KEYWORD + 1` letters are kept, enough to tell a keyword from prose
    let mut run = [0u8; LONGEST_KEYWORD + 1];
    let mut len = 0;
    let prose = |run: &[u8], len: usize| {
        len >= 2
            && (len > LONGEST_KEYWORD
                || !KEYWORDS
                    .iter()
                    .any(|k| k.as_bytes().eq_ignore_ascii_case(&run[..len])))
    };
    for &b in rest.as_bytes() {
        match b {
            b'(' => depth += 1,
            b')' if depth > 0 => depth -= 1,
            _ if depth > 0 => {}
            b if !b.is_ascii() => return true,
            b if b.is_ascii_alphabetic() => {
                if len < run.len() {
                    run[len] = b;
                }
                len += 1;
            }
            _ => {
                if prose(&run, len) {
                    return true;
                }
                len = 0;
            }
        }
    }
    prose(&run, len)
}

/// The longest of [`KEYWORDS`].
const LONGEST_KEYWORD: usize = 5;

/// Where a comment opened by `(` ends on its line (`rest`: the line after the `(`): after
/// its `)`, or `None` when it is not closed; and whether nested parentheses were read as
/// one comment. **Interpretation** (dialects.md §1): FANUC ends a comment at the first
/// `)`; when a `(` opens inside it and, read with nesting, the parentheses balance on the
/// line, the whole is one comment; an unclosed `(` runs to the end of the line.
pub(super) fn comment_end(rest: &str) -> (Option<usize>, bool) {
    let closes = |c: char| c == ')' || c == '）';
    let opens = |c: char| c == '(' || c == '（';
    let first_close = rest.find(closes);
    let nested_end = {
        let mut depth = 1;
        let mut end = None;
        for (i, c) in rest.char_indices() {
            if opens(c) {
                depth += 1;
            } else if closes(c) {
                depth -= 1;
                if depth == 0 {
                    end = Some(i + c.len_utf8());
                    break;
                }
            }
        }
        end
    };
    let nested = rest
        .find(opens)
        .is_some_and(|o| first_close.is_none_or(|c| o < c));
    match (first_close, nested_end) {
        (_, Some(e)) if nested => (Some(e), true),
        (Some(c), _) => (
            Some(c + rest[c..].chars().next().map_or(1, char::len_utf8)),
            false,
        ),
        (None, _) => (None, false),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A keyword is not prose, a longer run of letters is, through a comment too.
    #[test]
    fn keywords_are_no_prose_and_runs_of_letters_are() {
        assert!(!is_prose(" WHILE [#1 LT 2] DO1"));
        assert!(is_prose(" WHILEX"));
        assert!(is_prose(" A(x)B1"));
        assert!(!is_prose(" A(xyz)1"));
        assert_eq!(
            KEYWORDS.iter().map(|k| k.len()).max(),
            Some(LONGEST_KEYWORD)
        );
    }
}
