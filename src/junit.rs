//! `run --junit F`: the run as `JUnit` XML, the format Jenkins (its `JUnit` plugin), GitLab
//! (`artifacts:reports:junit`) and GitHub test-report actions read: one `<testsuite>`, one
//! `<testcase>` per program (`classname` its folder, `name` its file, `time` its run), a
//! `<failure>` when its run failed (a gouge, crash or alarm, or a part that differs from its
//! baseline) listing each finding as `file:line:column: kind CODE: message`, an `<error>`
//! when it could not be simulated, and the verdict line as `<system-out>`.
//!
//! Written by hand: a handful of elements, text escaped for XML 1.0 (the characters XML
//! 1.0 cannot hold, as control bytes from a program's comments, are replaced).

use crate::outcome::{Item, Outcome};
use std::fmt::Write as _;
use std::path::Path;

/// The document for the run's outcomes (in program order) and its wall time.
pub(crate) fn junit(outcomes: &[Outcome], seconds: f64) -> String {
    let failures = outcomes
        .iter()
        .filter(|o| o.record.is_some() && o.code != crate::EXIT_CLEAN)
        .count();
    let errors = outcomes.iter().filter(|o| o.record.is_none()).count();
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let counts = format!(
        "tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" time=\"{}\"",
        outcomes.len(),
        time(seconds)
    );
    let _ = writeln!(out, "<testsuites name=\"latsim\" {counts}>");
    let _ = writeln!(
        out,
        "  <testsuite name=\"latsim run\" {counts} skipped=\"0\">"
    );
    for o in outcomes {
        testcase(&mut out, o);
    }
    out.push_str("  </testsuite>\n</testsuites>\n");
    out
}

/// Seconds with millisecond precision.
fn time(s: f64) -> String {
    format!("{:.3}", if s.is_finite() { s.max(0.0) } else { 0.0 })
}

/// One program's test case.
fn testcase(out: &mut String, o: &Outcome) {
    let folder = o
        .program
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = o.program.file_name().map_or_else(
        || o.program.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let _ = writeln!(
        out,
        "    <testcase classname=\"{}\" name=\"{}\" file=\"{}\" time=\"{}\">",
        esc(&folder.display().to_string()),
        esc(&name),
        esc(&o.program.display().to_string()),
        time(o.seconds)
    );
    match &o.record {
        None => {
            let why = o.error.clone().unwrap_or_else(|| {
                "the program could not be read or set up (exit 2): the message is on stderr"
                    .to_string()
            });
            let _ = writeln!(
                out,
                "      <error message=\"not simulated\" type=\"unusable\">{}</error>",
                esc(&why)
            );
        }
        Some(r) => {
            let failing: Vec<&Item> = r.items.iter().filter(|i| i.kind.fails()).collect();
            if o.code != crate::EXIT_CLEAN {
                let body: Vec<String> = failing.iter().map(|i| finding_line(i)).collect();
                let _ = writeln!(
                    out,
                    "      <failure message=\"{}\" type=\"{}\">{}</failure>",
                    esc(&summary(&failing)),
                    failing.first().map_or("failure", |i| i.kind.word()),
                    esc(&body.join("\n"))
                );
            }
            let _ = writeln!(out, "      <system-out>{}</system-out>", esc(&r.line));
        }
    }
    out.push_str("    </testcase>\n");
}

/// `file:line:column: kind CODE: message` (`file:line:` without a column, `file:`
/// without a line).
pub(crate) fn finding_line(i: &Item) -> String {
    let place = match (i.line, i.column) {
        (0, _) => i.file.clone(),
        (l, 0) => format!("{}:{l}", i.file),
        (l, c) => format!("{}:{l}:{c}", i.file),
    };
    format!("{place}: {} {}: {}", i.kind.word(), i.code, i.message)
}

/// `2 gouges, 1 crash` — the failing findings counted by kind.
fn summary(failing: &[&Item]) -> String {
    let mut counts: Vec<(&str, usize)> = vec![];
    for i in failing {
        match counts.iter_mut().find(|(w, _)| *w == i.kind.word()) {
            Some((_, n)) => *n += 1,
            None => counts.push((i.kind.word(), 1)),
        }
    }
    if counts.is_empty() {
        return "failed".to_string();
    }
    counts
        .iter()
        .map(|(w, n)| format!("{n} × {w}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Text for XML 1.0 content and attribute values: markup escaped, a line end written as a
/// character reference (an attribute keeps it so), tabs and carriage returns as spaces,
/// and the characters XML 1.0 cannot hold (the other control characters, U+FFFE, U+FFFF)
/// replaced by U+FFFD.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            '\t' | '\r' => out.push(' '),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xml_text_is_escaped_and_control_characters_replaced() {
        assert_eq!(
            esc("a<b & \"c\"\n'd'"),
            "a&lt;b &amp; &quot;c&quot;&#10;&apos;d&apos;"
        );
        assert_eq!(esc("x\u{1}y\u{FFFF}"), "x\u{FFFD}y\u{FFFD}");
    }
}
