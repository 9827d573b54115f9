//! Constructs of controls latsim does not read, named where the reader stops (issue 31):
//! the field test met Linux CNC lathe programs, whose o-word subroutines (`O100 SUB`,
//! `O<turning> sub`) and named parameters (`#<wear>`) otherwise stop the reader with
//! "address S has no value" or "unexpected character '<'", which names nothing; Okuma OSP
//! programs (`$NAME.MIN%` headers, `DEF WORK`, `CALL OSUB`, named variables `PRES=1`) and
//! Philips 3000 ones (`G13 N1=8001`), which stopped at "unexpected character '$'" or "'='".

/// A construct of a control latsim does not read, on one line: what it is and whose.
#[derive(Debug, PartialEq)]
pub(crate) struct Foreign {
    /// What the line holds, e.g. "an o-word (O… SUB, …)".
    pub(crate) what: String,
    /// Whose syntax it is, e.g. "`LinuxCNC` (rs274ngc)".
    pub(crate) whose: &'static str,
}

/// The construct of a control latsim does not read on this line, if it holds one.
pub(crate) fn construct(line: &str) -> Option<Foreign> {
    if let Some(what) = linuxcnc(line) {
        return Some(Foreign {
            what: what.into(),
            whose: "LinuxCNC (rs274ngc)",
        });
    }
    if let Some(what) = okuma(line) {
        return Some(Foreign {
            what,
            whose: "Okuma OSP",
        });
    }
    assignment(line).map(|what| Foreign {
        what,
        whose: "another control's language (Okuma, Siemens, Philips …)",
    })
}

/// The Okuma OSP construct on this line: the file header `$NAME.MIN%`, a statement of its
/// own (`DEF WORK`, `CLEAR`, `DRAW`, `CALL O…`), or a sequence name `NAME` (N and letters).
fn okuma(line: &str) -> Option<String> {
    let l = line.trim_start().to_ascii_uppercase();
    if l.starts_with('$')
        && [".MIN%", ".SSB%", ".SDF%", ".LIB%"]
            .iter()
            .any(|ext| l.contains(ext))
    {
        return Some(format!("the file header {}", line.trim()));
    }
    let first = l.split_whitespace().next().unwrap_or("");
    if first == "DEF" || first == "CLEAR" || first == "DRAW" || l.starts_with("CALL O") {
        return Some(format!("the statement {first}"));
    }
    // a sequence name starts a line, or is named by a cycle in it (`G85 NLAP1 D2.5`)
    let sequence_name = |token: &&str| {
        token.strip_prefix('N').is_some_and(|name| {
            name.starts_with(|c: char| c.is_ascii_alphabetic())
                && name.chars().all(|c| c.is_ascii_alphanumeric())
        })
    };
    let code = without_comments(&l);
    let name = code.split_whitespace().find(sequence_name)?;
    Some(format!("the sequence name {name} (N with letters)"))
}

/// An assignment `NAME=value` or `N1=value` outside comments (a variable or parameter of
/// another control; FANUC macro B assigns `#n = …`).
fn assignment(line: &str) -> Option<String> {
    let code = without_comments(line);
    let bytes = code.as_bytes();
    let eq = code.find('=')?;
    let before = code[..eq].trim_end();
    // counted in bytes: an ASCII letter or digit is one byte, so this is a character's
    // start even after a non-ASCII one (`ÿ=`)
    let name_start = before.len()
        - before
            .bytes()
            .rev()
            .take_while(u8::is_ascii_alphanumeric)
            .count();
    let name = &before[name_start..];
    let is_name = name.starts_with(|c: char| c.is_ascii_alphabetic());
    let after_hash = name_start > 0 && bytes[name_start - 1] == b'#';
    (is_name && !after_hash).then(|| {
        let value: String = code[eq + 1..]
            .trim_start()
            .chars()
            .take_while(|c| !c.is_whitespace())
            .collect();
        format!("the assignment {name}={value}")
    })
}

/// The line without its `( … )` comments.
fn without_comments(line: &str) -> String {
    let mut depth = 0usize;
    line.chars()
        .filter(|&c| {
            match c {
                '(' => depth += 1,
                ')' => {
                    let was = depth;
                    depth = depth.saturating_sub(1);
                    return was == 0;
                }
                _ => {}
            }
            depth == 0
        })
        .collect()
}

/// The Linux CNC construct on this line, if any: what the error names instead.
fn linuxcnc(line: &str) -> Option<&'static str> {
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
    use super::*;

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

    /// Okuma OSP headers, statements, sequence names and named variables, and Philips
    /// parameter assignments, are named; FANUC macro B assignments and plain blocks are not.
    #[test]
    fn names_okuma_and_assignments_of_other_controls() {
        let whose = |l: &str| construct(l).map(|f| f.whose);
        assert_eq!(whose("$FLANGE.MIN%"), Some("Okuma OSP"));
        assert_eq!(whose("DEF WORK"), Some("Okuma OSP"));
        // a LAP cycle names its contour's sequence mid-line (field run 8, G)
        assert_eq!(whose("G85 NLAP1 D2.5 F0.3 U0.2 W0.1"), Some("Okuma OSP"));
        assert_eq!(whose("N10 G00 X20. (NOTE NLAP1)"), None);
        assert_eq!(whose("CALL OCHEK"), Some("Okuma OSP"));
        assert_eq!(whose("NAT00"), Some("Okuma OSP"));
        let f = construct("PRES=1    (CHUCK PRESSURE *** LOW:0 - HIGH:1)").unwrap();
        assert_eq!(f.what, "the assignment PRES=1");
        let f = construct("N180 G13 N1=8001 N2=8011").unwrap();
        assert_eq!(f.what, "the assignment N1=8001");
        assert!(construct("#1 = 2 (A=B)").is_none());
        assert!(construct("IF [#1 EQ 2] THEN #3 = 1").is_none());
        assert!(construct("N10 G0 X1 (R=2)").is_none());
        assert!(construct("N10 G0 X1").is_none());
        assert!(construct("O0001 (SHAFT)").is_none());
    }
}
