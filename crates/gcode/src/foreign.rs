//! Constructs of controls latsim does not read, named where the reader stops (issue 31):
//! the field test met Linux CNC lathe programs, whose o-word subroutines (`O100 SUB`,
//! `O<turning> sub`) and named parameters (`#<wear>`) otherwise stop the reader with
//! "address S has no value" or "unexpected character '<'", which names nothing.

/// The Linux CNC construct on this line, if any: what the error names instead.
pub(crate) fn linuxcnc(line: &str) -> Option<&'static str> {
    let l = line.trim_start().to_ascii_lowercase();
    if l.contains("#<") {
        return Some("a named parameter #<…>");
    }
    let rest = l.strip_prefix('o')?;
    let rest = if let Some(named) = rest.strip_prefix('<') {
        named.split_once('>')?.1
    } else {
        rest.trim_start_matches(|c: char| c.is_ascii_digit())
    };
    const WORDS: [&str; 15] = [
        "sub",
        "endsub",
        "call",
        "if",
        "elseif",
        "else",
        "endif",
        "while",
        "endwhile",
        "do",
        "repeat",
        "endrepeat",
        "return",
        "break",
        "continue",
    ];
    let word = rest.trim_start();
    let word = &word[..word
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(word.len())];
    (WORDS.contains(&word) || line.trim_start()[1..].starts_with('<'))
        .then_some("an o-word (O… SUB, O<name> CALL, O… IF …)")
}

#[cfg(test)]
mod tests {
    use super::linuxcnc;

    #[test]
    fn names_linuxcnc_o_words_and_parameters() {
        assert!(linuxcnc("O100 SUB").is_some());
        assert!(linuxcnc("o<turning> sub").is_some());
        assert!(linuxcnc("O110 IF [#<_imperial>]").is_some());
        assert!(linuxcnc("#<wear> = [10000 + 1]").is_some());
        assert!(linuxcnc("O1234 (SHAFT)").is_none());
        assert!(linuxcnc("O0001").is_none());
        assert!(linuxcnc("G0 X1").is_none());
    }
}
