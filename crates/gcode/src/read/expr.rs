//! Where custom macro B stands in a block's text: the `macro_b` crate reads the statement or
//! the expression; the reader only finds where it starts and where its block ends.

use macro_b::Func;

/// The text from byte `start` to the end of its block: the next newline, lone CR or `;`
/// outside a comment.
pub(super) fn block_text(src: &str, start: usize) -> &str {
    let rest = &src[start..];
    let mut depth = 0usize;
    for (i, c) in rest.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            '\n' | '\r' => return &rest[..i],
            ';' if depth == 0 => return &rest[..i],
            _ => {}
        }
    }
    rest
}

/// Whether the value after an address letter (at byte `at`) is a macro expression: `#…`,
/// `[…]`, a function (`ROUND[…]`), each possibly after a sign.
pub(super) fn expression_follows(src: &str, at: usize) -> bool {
    let next = &src.as_bytes()[at..];
    let unsigned = next.strip_prefix(b"-").or_else(|| next.strip_prefix(b"+"));
    if unsigned
        .unwrap_or(next)
        .first()
        .is_some_and(|b| b.is_ascii_digit() || *b == b'.')
    {
        // a number, the common case: no `#`, `[` or function name
        return false;
    }
    let rest = block_text(src, at);
    let t = rest.trim_start_matches([' ', '\t']);
    let t = t
        .strip_prefix(['-', '+'])
        .unwrap_or(t)
        .trim_start_matches([' ', '\t']);
    if t.starts_with(['#', '[']) {
        return true;
    }
    let name_len = t.bytes().take_while(u8::is_ascii_alphabetic).count();
    Func::from_name(&t[..name_len].to_ascii_uppercase()).is_some()
        && t[name_len..]
            .trim_start_matches([' ', '\t'])
            .starts_with('[')
}
