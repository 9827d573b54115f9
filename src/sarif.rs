//! `run --sarif F`: the run's findings as SARIF 2.1.0 (OASIS), the format GitHub code
//! scanning and other viewers read. One `result` per alarm, crash and gouge (level
//! `error`), per difference from a baseline (`warning`), and per leftover and warning
//! (`note`); `ruleId` is the finding's code (an alarm's `PS011`, a warning's
//! `LS-RAPID-SCRAPE`, and `LS-CRASH`, `LS-GOUGE`, `LS-LEFTOVER`, `LS-BASELINE-LOST`,
//! `LS-BASELINE-GAINED` for the findings that have none), each rule described once in
//! `tool.driver.rules`. Locations are relative to the working folder (`uriBaseId`
//! `SRCROOT`, the folder itself in `originalUriBaseIds`), columns count characters
//! (`columnKind` `unicodeCodePoints`); a finding tied to no line is put on line 1.

use crate::outcome::{self, Item, Kind, Outcome};
use serde_json::{json, Value};
use std::path::{Component, Path, PathBuf};

/// Where the schema of what is written is published.
const SCHEMA: &str =
    "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";

/// The SARIF log of the run's outcomes, locations relative to `cwd`.
pub(crate) fn sarif(outcomes: &[Outcome], exit_code: u8, cwd: &Path) -> String {
    let items: Vec<&Item> = outcomes
        .iter()
        .filter_map(|o| o.record.as_ref())
        .flat_map(|r| r.items.iter())
        .collect();
    let mut rules: Vec<(&str, Kind)> = vec![];
    for i in &items {
        if !rules.iter().any(|(c, _)| *c == i.code) {
            rules.push((&i.code, i.kind));
        }
    }
    let results: Vec<Value> = items
        .iter()
        .map(|i| {
            let index = rules.iter().position(|(c, _)| *c == i.code).unwrap_or(0);
            result(i, index, cwd)
        })
        .collect();
    let unusable: Vec<Value> = outcomes
        .iter()
        .filter(|o| o.record.is_none())
        .map(|o| notification(o, cwd))
        .collect();
    let log = json!({
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {
                "name": "latsim",
                "version": env!("CARGO_PKG_VERSION"),
                "semanticVersion": env!("CARGO_PKG_VERSION"),
                "rules": rules.iter().map(|(code, kind)| rule(code, *kind)).collect::<Vec<_>>(),
            }},
            "invocations": [{
                "executionSuccessful": unusable.is_empty(),
                "exitCode": exit_code,
                "toolExecutionNotifications": unusable,
            }],
            "originalUriBaseIds": {"SRCROOT": {"uri": folder_uri(cwd)}},
            "columnKind": "unicodeCodePoints",
            "results": results,
        }],
    });
    // a tree of strings, numbers and arrays: writing it cannot fail
    serde_json::to_string_pretty(&log).unwrap_or_else(|_| "{}".to_string())
}

/// A finding as a result.
fn result(i: &Item, rule_index: usize, cwd: &Path) -> Value {
    let mut region = json!({"startLine": i.line.max(1)});
    if i.line > 0 && i.column > 0 {
        region["startColumn"] = json!(i.column);
    }
    let text = if i.line == 0 {
        format!("{} (not tied to a line)", i.message)
    } else {
        i.message.clone()
    };
    json!({
        "ruleId": i.code,
        "ruleIndex": rule_index,
        "level": level(i.kind),
        "message": {"text": text},
        "locations": [{"physicalLocation": {
            "artifactLocation": artifact(Path::new(&i.file), cwd),
            "region": region,
        }}],
    })
}

/// A program that could not be simulated, as a notification of the invocation.
fn notification(o: &Outcome, cwd: &Path) -> Value {
    let why = o.error.clone().unwrap_or_else(|| {
        "not simulated: the program could not be read or set up (exit 2); the message is on stderr".to_string()
    });
    json!({
        "level": "error",
        "message": {"text": why},
        "locations": [{"physicalLocation": {"artifactLocation": artifact(&o.program, cwd)}}],
    })
}

fn level(kind: Kind) -> &'static str {
    match kind {
        Kind::Alarm | Kind::Crash | Kind::Gouge => "error",
        Kind::Possible | Kind::BaselineLost | Kind::BaselineGained => "warning",
        Kind::Leftover | Kind::Warning => "note",
    }
}

/// A rule, described once: the findings latsim names itself in words, the others (the
/// control's alarms, latsim's warnings) by their kind and code; the message of each
/// result says what happened.
fn rule(code: &str, kind: Kind) -> Value {
    let (name, text) = match code {
        outcome::CRASH => ("Crash", "A rapid ran into stock, a tool's body met stock, or a tool entered the chuck, its jaws or the tailstock (or cut inside the jaws)"),
        outcome::GOUGE => ("Gouge", "Part material cut away: the final part lacks material the intended part has, deeper than the tolerance"),
        outcome::LEFTOVER => ("Leftover", "Material left that the intended part does not have, thicker than the tolerance"),
        outcome::POSSIBLE_CRASH => ("PossibleCrash", "A crash made by a tool whose size latsim assumed (no table entry states it): possible, not in the verdict; state the tool"),
        outcome::POSSIBLE_GOUGE => ("PossibleGouge", "A gouge made by a tool whose size latsim assumed (no table entry states it): possible, not in the verdict; state the tool"),
        outcome::BASELINE_LOST => ("BaselineLost", "The part lost material against the baseline report"),
        outcome::BASELINE_GAINED => ("BaselineGained", "The part gained material against the baseline report"),
        "LS-THREAD-DEPTH" => ("ThreadDepth", "A thread cut deeper or shallower than expected"),
        _ => match kind {
            Kind::Alarm => ("Alarm", "A controller alarm: the run stopped or is wrong"),
            _ => ("Warning", "A warning about the program or the run"),
        },
    };
    json!({
        "id": code,
        "name": name,
        "shortDescription": {"text": format!("{text} ({code})")},
        "defaultConfiguration": {"level": level(kind)},
    })
}

/// An artifact location: relative to the working folder (`SRCROOT`) when the file is in
/// it, else an absolute `file:` URI.
fn artifact(file: &Path, cwd: &Path) -> Value {
    match relative(file, cwd) {
        Some(rel) => json!({"uri": encode(&rel), "uriBaseId": "SRCROOT"}),
        None => json!({"uri": format!("file://{}", encode(absolute(file, cwd)))}),
    }
}

/// `file` relative to `cwd` with `/` separators, `.` and `..` resolved; `None` when it
/// lies outside.
fn relative(file: &Path, cwd: &Path) -> Option<String> {
    let full = absolute(file, cwd);
    let rest = full.strip_prefix(normal(cwd)).ok()?;
    let parts: Vec<String> = rest
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    (!parts.is_empty()).then(|| parts.join("/"))
}

/// `file` made absolute against `cwd`, `.` and `..` resolved lexically.
fn absolute(file: &Path, cwd: &Path) -> PathBuf {
    normal(&cwd.join(file))
}

fn normal(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            c => out.push(c),
        }
    }
    out
}

/// The working folder as a `file:` URI ending in `/`.
fn folder_uri(cwd: &Path) -> String {
    let mut s = format!("file://{}", encode(normal(cwd)));
    if !s.ends_with('/') {
        s.push('/');
    }
    s
}

/// A path as a URI reference: unreserved characters and `/` as they are, every other
/// byte of its UTF-8 percent-encoded (a space, `%`, `#`, `?`, non-ASCII names).
fn encode(p: impl AsRef<Path>) -> String {
    let s = p.as_ref().to_string_lossy().replace('\\', "/");
    let mut out = String::with_capacity(s.len());
    for b in s.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            out.push(b as char);
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_become_uri_references_relative_to_the_folder() {
        let cwd = Path::new("/w/repo");
        assert_eq!(
            relative(Path::new("progs/a b.nc"), cwd).as_deref(),
            Some("progs/a b.nc")
        );
        assert_eq!(
            relative(Path::new("/w/repo/./x/../p.nc"), cwd).as_deref(),
            Some("p.nc")
        );
        assert_eq!(relative(Path::new("../other/p.nc"), cwd), None);
        assert_eq!(encode("progs/a b#1%.nc"), "progs/a%20b%231%25.nc");
        assert_eq!(encode("零件.nc"), "%E9%9B%B6%E4%BB%B6.nc");
        assert_eq!(folder_uri(cwd), "file:///w/repo/");
    }
}
