//! Re-running a job with a change, for the diagnosis's remedies (`analysis::diagnose`): the
//! main program's text with blocks inserted, or the tool table with one tool replaced, read
//! and expanded as the first time and run on the same blank, machine and tolerance.

use crate::job::Job;
use analysis::diagnose::{Change, Rerun, Rerunning};

/// A job, its tolerance and its run's memory budget, re-runnable.
pub(crate) struct Rerunner<'a> {
    pub(crate) job: &'a Job,
    pub(crate) tol: f64,
    pub(crate) memory: Option<stock::RunMemory>,
}

impl Rerun for Rerunner<'_> {
    fn rerun(&self, change: &Change) -> Option<Rerunning> {
        let loaded = &self.job.loaded;
        let (text, tools) = match change {
            Change::Tool { t, entry } => (
                loaded.source.text.to_string(),
                self.job.tools.replaced(*t, entry).ok()?,
            ),
            Change::Insert { line, text } => (
                inserted(&loaded.source.text, *line, text)?,
                self.job.tools.clone(),
            ),
            Change::Feed { line } => (fed(&loaded.source.text, *line)?, self.job.tools.clone()),
        };
        let program = gcode::parse_with(&text, loaded.read).ok()?;
        let opts = expander::Options {
            tools: tools.facts(),
            ..loaded.opts.clone()
        };
        let toolpath = expander::expand(&program, &loaded.machine, &opts);
        let settings = analysis::Settings {
            tools: &tools,
            ..self.job.settings(self.tol)
        };
        let opts = stock::SimOptions {
            max_memory: self.memory.clone(),
            ..stock::SimOptions::default()
        };
        let (sim, findings) =
            analysis::pipeline(&toolpath, &self.job.intents, &settings, &opts, &mut |_| {});
        // a re-run stopped over the budget checks nothing
        if sim.over_budget.is_some() {
            return None;
        }
        Some(Rerunning {
            findings,
            alarms: toolpath.alarms.len(),
        })
    }
}

/// `source` with `blocks` inserted before its 1-based line `line` (keeping its line ends);
/// `None` past its last line (a block of a `--lib` file).
fn inserted(source: &str, line: u32, blocks: &str) -> Option<String> {
    let mut at = 0;
    for _ in 1..line {
        at += source[at..].find('\n')? + 1;
    }
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
    let mut at = 0;
    for _ in 1..line {
        at += source[at..].find('\n')? + 1;
    }
    let end = source[at..].find('\n').map_or(source.len(), |e| at + e);
    let text = &source.as_bytes()[at..end];
    let (word, len) = (0..text.len()).find_map(|k| {
        let digits = text[k + 1..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        let rapid = text[k].eq_ignore_ascii_case(&b'G')
            && digits > 0
            && text[k + 1..k + 1 + digits].iter().all(|&b| b == b'0')
            && text.get(k + 1 + digits) != Some(&b'.');
        rapid.then_some((k, 1 + digits))
    })?;
    Some(format!(
        "{}G01{}",
        &source[..at + word],
        &source[at + word + len..]
    ))
}

#[cfg(test)]
mod tests {
    use super::{fed, inserted};

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
