//! The tape around a program (spec/dialects.md §1): the leader before the first `%`, the
//! text after the closing `%`, and the control bytes that RS-232 and DNC software leave in
//! a file. Pure functions of the text; the reader notes what they find.

/// Whether a line holds a program number or an address word (outside comments): a letter
/// followed by a number, or `:` followed by digits.
fn has_address(line: &str) -> bool {
    let mut depth = 0;
    let mut prev: Option<char> = None;
    for c in line.chars().filter(|c| *c != ' ' && *c != '\t') {
        match c {
            '(' => depth += 1,
            ')' if depth > 0 => depth -= 1,
            _ if depth > 0 => {}
            c => {
                let numeric = c.is_ascii_digit() || matches!(c, '.' | '+' | '-');
                if numeric
                    && prev.is_some_and(|p| {
                        p.is_ascii_alphabetic() || (p == ':' && c.is_ascii_digit())
                    })
                {
                    return true;
                }
                prev = Some(c);
            }
        }
    }
    false
}

/// Whether a line holds a program number and nothing else but comments (`O0090 (CONE)`).
fn program_number_only(line: &str) -> bool {
    let mut depth = 0;
    let code: String = line
        .chars()
        .filter(|&c| match c {
            '(' => {
                depth += 1;
                false
            }
            ')' if depth > 0 => {
                depth -= 1;
                false
            }
            _ => depth == 0 && !c.is_whitespace() && !c.is_control(),
        })
        .collect();
    let digits = code
        .strip_prefix(['O', 'o', ':'])
        .filter(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()));
    digits.is_some()
}

/// Where the leader ends: if a `%` comes before the first line holding a program number or
/// an address word, everything up to the end of that `%`'s line (spec/dialects.md §1).
/// A line that starts with `%` and goes on with the first block (`%O1200(TOKARKA)`, as CAM
/// systems write it) ends the leader right after that `%`: its words are the program's.
/// A program number alone on its line before the first `%` (`O0090 (CONE)`, then `%`, as
/// a training app writes its files) is leader too: the tape starts at that `%`.
pub(super) fn leader_end(src: &str) -> Option<usize> {
    let mut offset = 0;
    for line in src.split_inclusive('\n') {
        let lead = line.len()
            - line
                .trim_start_matches(|c: char| {
                    c.is_whitespace() || c.is_control() || c == '\u{feff}'
                })
                .len();
        if line[lead..].starts_with('%') && has_address(&line[lead + 1..]) {
            return Some(offset + lead + 1);
        }
        if has_address(line) && !program_number_only(line) {
            return None;
        }
        offset += line.len();
        if line.contains('%') {
            return Some(offset);
        }
    }
    None
}

/// The leader's text worth showing: without control bytes, `%` and the byte-order mark.
pub(super) fn leader_text(leader: &str) -> String {
    leader
        .chars()
        .filter(|c| !c.is_control() && *c != '%' && *c != '\u{feff}')
        .collect()
}

/// Whether the text after the closing `%` holds anything but white space, control bytes
/// and `%`.
pub(super) fn trailer_has_text(rest: &str) -> bool {
    rest.chars()
        .any(|c| !c.is_whitespace() && !c.is_control() && c != '%')
}

/// A control byte's fate: dropped silently, dropped and counted as flow control, or dropped
/// with a warning.
pub(super) fn control_kind(c: char) -> Option<ControlKind> {
    match c {
        '\u{11}'..='\u{14}' => Some(ControlKind::FlowControl),
        '\0' | '\u{8}' | '\u{7f}' | '\u{1b}' | '\u{1a}' | '\u{c}' | '\u{b}' | '\u{feff}' => {
            Some(ControlKind::Ignored)
        }
        c if (c as u32) < 0x20 && !matches!(c, '\n' | '\r' | '\t') => Some(ControlKind::Unexpected),
        _ => None,
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum ControlKind {
    FlowControl,
    Ignored,
    Unexpected,
}
