//! What one program's run gives the run's CI reports (`--junit`, `--sarif`) besides its
//! exit status: the verdict line and every finding at its file, line and column.

use crate::input::Loaded;
use analysis::{Findings, MAX_LISTED};
use std::path::PathBuf;

/// One program of a run, as the CI reports see it.
#[derive(Debug)]
pub(crate) struct Outcome {
    /// The program file as given (or found in a folder given).
    pub(crate) program: PathBuf,
    /// Its exit status: 0 clean, 1 findings, 2 not simulated.
    pub(crate) code: u8,
    /// What the run found; `None`: the program was not simulated.
    pub(crate) record: Option<Record>,
    /// Why it was not simulated, when known (an internal error's message).
    pub(crate) error: Option<String>,
    /// Wall time of the program's run, s.
    pub(crate) seconds: f64,
}

impl Outcome {
    /// A program that was not simulated (its message is on stderr, or `error`).
    pub(crate) fn unusable(program: PathBuf, error: Option<String>) -> Self {
        Self {
            program,
            code: crate::EXIT_UNUSABLE,
            record: None,
            error,
            seconds: 0.0,
        }
    }
}

/// A simulated program's verdict and findings.
#[derive(Debug, Default)]
pub(crate) struct Record {
    /// The verdict line printed on the terminal.
    pub(crate) line: String,
    /// Every finding, failing ones first (alarms, crashes, gouges, baseline differences),
    /// then leftovers and warnings.
    pub(crate) items: Vec<Item>,
}

/// What a finding is, for its rule and level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// A controller alarm (the run stopped or is wrong).
    Alarm,
    /// A crash.
    Crash,
    /// A gouge, or a thread cut too deep.
    Gouge,
    /// A crash or gouge made by a tool whose size latsim assumed: possible, not in the
    /// verdict (the warning `LS-ASSUMED-TOOL` names what to state).
    Possible,
    /// Material the part lost against the baseline.
    BaselineLost,
    /// Material the part gained against the baseline.
    BaselineGained,
    /// Material left that should be gone.
    Leftover,
    /// A warning.
    Warning,
}

impl Kind {
    /// Whether it fails the run (exit 1).
    pub(crate) fn fails(self) -> bool {
        !matches!(self, Self::Possible | Self::Leftover | Self::Warning)
    }

    /// The word for it.
    pub(crate) fn word(self) -> &'static str {
        match self {
            Self::Alarm => "alarm",
            Self::Crash => "crash",
            Self::Gouge => "gouge",
            Self::Possible => "possible",
            Self::BaselineLost | Self::BaselineGained => "baseline",
            Self::Leftover => "leftover",
            Self::Warning => "warning",
        }
    }
}

/// Stable rule codes of the findings that have no code of their own.
pub(crate) const CRASH: &str = "LS-CRASH";
/// See [`CRASH`].
pub(crate) const GOUGE: &str = "LS-GOUGE";
/// See [`CRASH`].
pub(crate) const LEFTOVER: &str = "LS-LEFTOVER";
/// See [`CRASH`].
pub(crate) const POSSIBLE_CRASH: &str = "LS-POSSIBLE-CRASH";
/// See [`CRASH`].
pub(crate) const POSSIBLE_GOUGE: &str = "LS-POSSIBLE-GOUGE";
/// See [`CRASH`].
pub(crate) const BASELINE_LOST: &str = "LS-BASELINE-LOST";
/// See [`CRASH`].
pub(crate) const BASELINE_GAINED: &str = "LS-BASELINE-GAINED";

/// One finding at its place.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Item {
    pub(crate) kind: Kind,
    /// Its rule: the alarm's or warning's code, or one of the `LS-…` codes above.
    pub(crate) code: String,
    pub(crate) message: String,
    /// The file it is in (the main program, or a `--lib` file), as named on the terminal.
    pub(crate) file: String,
    /// 1-based line; 0: not tied to a line (a leftover, a tool table default).
    pub(crate) line: u32,
    /// 1-based column (characters); 0 with line 0.
    pub(crate) column: u32,
}

/// The words of a crash: what met what, and what the area is of (shared with the
/// terminal's crash lines).
pub(crate) fn crash_words(body: Option<&str>, obstacle: Option<&str>) -> (String, &'static str) {
    let what = match (obstacle, body) {
        (Some(o), _) if o == analysis::GRIPPED_LENGTH => {
            "the tool cuts the blank inside the chuck jaws (gripped length)".to_string()
        }
        (Some(o), Some(body)) => format!("the tool's {body} meets the {o}"),
        (Some(o), None) => format!("the tool's cutting edge meets the {o}"),
        (None, Some(body)) => format!("the tool's {body} meets stock"),
        (None, None) => "rapid into stock".to_string(),
    };
    let of = match obstacle {
        None | Some(analysis::GRIPPED_LENGTH) => "of stock",
        Some(_) => "of overlap",
    };
    (what, of)
}

/// Every finding of a run at its place: alarms, crashes, gouges (and threads cut too
/// deep), the differences from the baseline, then leftovers and warnings (the removal's
/// `LS-STOCK` too; at most [`MAX_LISTED`] of each list, like the reports).
pub(crate) fn items(
    loaded: &Loaded,
    sim: &stock::Simulation,
    f: &Findings,
    tol: f64,
    against: Option<&Against>,
) -> Vec<Item> {
    let at = At { loaded, f, tol };
    let mut out = at.failing();
    if let Some(d) = against.and_then(|a| a.diff.as_ref()) {
        out.extend(baseline_items(loaded, d));
    }
    out.extend(at.notes(sim));
    out
}

/// Puts a run's findings at their file, line and column.
struct At<'a> {
    loaded: &'a Loaded,
    f: &'a Findings,
    tol: f64,
}

impl At<'_> {
    fn item(&self, span: expander::Span, kind: Kind, code: &str, message: String) -> Item {
        let (src, _) = self.loaded.source_at(span.offset as usize);
        Item {
            kind,
            code: code.to_string(),
            message,
            file: src.name.clone(),
            line: span.line,
            column: span.column,
        }
    }

    /// The span of move `i`.
    fn move_span(&self, i: usize) -> expander::Span {
        let segments = &self.loaded.toolpath.segments;
        segments.get(i).map(|s| s.span).unwrap_or_default()
    }

    /// Whether a note is a thread cut deeper than the tolerance: a gouge.
    fn too_deep(&self, n: &analysis::Note) -> bool {
        n.code == "LS-THREAD-DEPTH"
            && self
                .f
                .threads
                .iter()
                .any(|t| t.span == n.span && t.too_deep(self.tol))
    }

    /// The findings that fail the run (alarms, crashes, gouges, threads too deep), and the
    /// possible crashes and gouges of assumed tools with them.
    fn failing(&self) -> Vec<Item> {
        let (f, tp) = (self.f, &self.loaded.toolpath);
        let mut out: Vec<Item> = vec![];
        for d in tp.alarms.iter().take(MAX_LISTED) {
            out.push(self.item(d.span, Kind::Alarm, d.code, d.message.clone()));
        }
        for n in f.alarms.iter().take(MAX_LISTED) {
            out.push(self.item(n.span, Kind::Alarm, n.code, n.message.clone()));
        }
        for c in f.crashes.iter().take(MAX_LISTED) {
            let (what, of) = crash_words(c.body, c.obstacle);
            let message = format!(
                "crash: {what} at Z{:.3} X{:.3}, {:.3} mm deep, {:.3} mm² {of}",
                c.at[0],
                2.0 * c.at[1],
                c.depth,
                c.area
            );
            let (kind, code) = if c.assumed {
                (Kind::Possible, POSSIBLE_CRASH)
            } else {
                (Kind::Crash, CRASH)
            };
            out.push(self.item(self.move_span(c.segment), kind, code, message));
        }
        let gouges = f.deviation.iter().flat_map(|d| d.gouges.iter());
        for g in gouges.take(MAX_LISTED) {
            let message = format!(
                "gouge: {:.4} mm deep, {:.4} mm² at Z{:.3} X{:.3}",
                g.depth,
                g.area,
                g.at[0],
                2.0 * g.at[1]
            );
            let span = g.made_by.map(|i| self.move_span(i)).unwrap_or_default();
            let (kind, code) = if g.assumed {
                (Kind::Possible, POSSIBLE_GOUGE)
            } else {
                (Kind::Gouge, GOUGE)
            };
            out.push(self.item(span, kind, code, message));
        }
        for n in f.part_warnings.iter().filter(|n| self.too_deep(n)) {
            out.push(self.item(n.span, Kind::Gouge, n.code, n.message.clone()));
        }
        out
    }

    /// Leftovers (tied to no line: no move removed them) and warnings.
    fn notes(&self, sim: &stock::Simulation) -> Vec<Item> {
        let (f, tp) = (self.f, &self.loaded.toolpath);
        let mut out: Vec<Item> = vec![];
        let leftovers = f.deviation.iter().flat_map(|d| d.leftovers.iter());
        for l in leftovers.take(MAX_LISTED) {
            let message = format!(
                "leftover: {:.4} mm thick, {:.4} mm² at Z{:.3} X{:.3}: material the intended part does not have (no move is named: no move removed it)",
                l.depth,
                l.area,
                l.at[0],
                2.0 * l.at[1]
            );
            let nowhere = expander::Span::default();
            out.push(self.item(nowhere, Kind::Leftover, LEFTOVER, message));
        }
        let warnings = tp.warnings.iter().map(|d| (d.span, d.code, &d.message));
        let notes = f.warnings.iter().chain(&f.part_warnings);
        let notes = notes
            .filter(|n| !self.too_deep(n))
            .map(|n| (n.span, n.code, &n.message));
        let stock = sim
            .warnings
            .iter()
            .map(|(seg, m)| (self.move_span(*seg), "LS-STOCK", m));
        for (span, code, message) in warnings.chain(notes).chain(stock).take(MAX_LISTED) {
            out.push(self.item(span, Kind::Warning, code, message.clone()));
        }
        out
    }
}

/// The baseline's differences as findings at the line of this program whose move was the
/// last to make each region (its finishing cut; none known: line 0, no line).
fn baseline_items(loaded: &Loaded, d: &render::DiffReport) -> Vec<Item> {
    let regions = d
        .lost
        .iter()
        .enumerate()
        .map(|(i, r)| (format!("L{}", i + 1), r, true))
        .chain(
            d.gained
                .iter()
                .enumerate()
                .map(|(i, r)| (format!("G{}", i + 1), r, false)),
        );
    regions
        .take(MAX_LISTED)
        .map(|(label, r, lost)| Item {
            kind: if lost {
                Kind::BaselineLost
            } else {
                Kind::BaselineGained
            },
            code: if lost { BASELINE_LOST } else { BASELINE_GAINED }.to_string(),
            message: format!(
                "against the baseline {}: {}",
                d.old,
                r.describe(&label, lost)
            ),
            file: loaded.source.name.clone(),
            line: r.new_place.map_or(0, |p| p[0]),
            column: r.new_place.map_or(0, |p| p[1]),
        })
        .collect()
}

/// The end of a simulated program's run: its verdict line printed (with what the baseline
/// says; for a single program also the regions that differ), and its outcome. Exit 1 for
/// an alarm, crash or gouge, or a part that differs from its baseline.
pub(crate) fn finish(
    program: &std::path::Path,
    mut line: String,
    items: Vec<Item>,
    against: Option<Against>,
    verdict: analysis::Verdict,
    batch: bool,
) -> Outcome {
    let differs = against.as_ref().is_some_and(Against::differs);
    if let Some(a) = &against {
        line.push_str(&a.suffix);
        if !batch && differs {
            for l in &a.details {
                eprintln!("{l}");
            }
        }
    }
    println!("{line}");
    let clean = verdict == analysis::Verdict::Clean && !differs;
    Outcome {
        program: program.to_path_buf(),
        code: if clean {
            crate::EXIT_CLEAN
        } else {
            crate::EXIT_FINDINGS
        },
        record: Some(Record { line, items }),
        error: None,
        seconds: 0.0,
    }
}

/// A run compared with its baseline: what the verdict line adds, and the diff when there
/// was a baseline to compare with.
pub(crate) struct Against {
    /// `; against base/part.json: same part, …`, or the note that there is no baseline.
    pub(crate) suffix: String,
    /// The diff; `None`: the baseline folder holds no report of this program.
    pub(crate) diff: Option<render::DiffReport>,
    /// The diff's lines after its first, printed under the verdict of a single run.
    pub(crate) details: Vec<String>,
}

impl Against {
    /// Whether the part differs from the baseline's (a failed run).
    pub(crate) fn differs(&self) -> bool {
        self.diff.as_ref().is_some_and(render::DiffReport::differs)
    }
}
