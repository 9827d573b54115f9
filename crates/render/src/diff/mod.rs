//! What changed between two runs (`latsim diff`, `run --baseline`), as plain data, and its
//! reports: a picture with both sections overlaid and the differences coloured (SVG and
//! PNG, 1600 × 1000 px like the run's report), a self-contained HTML page, and JSON.
//!
//! Coordinates are `[z, r]` (r = X / 2) like [`crate::Report`]; the JSON writes `[z, x]`.

mod json;
mod page;
mod picture;

use crate::report::{Shape, Verdict};
use crate::text::num;
use crate::RenderError;

/// A region where the new part differs from the old one.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DiffRegion {
    /// The region, `[z, r]`.
    pub shape: Shape,
    /// Its area, mm² of the half section.
    pub area_mm2: f64,
    /// Its largest distance from the old part's boundary, mm.
    pub depth_mm: f64,
    /// Where it is deepest, z.
    pub z: f64,
    /// Where it is deepest, r.
    pub r: f64,
    /// Its box, lowest `[z, r]`.
    pub lo: [f64; 2],
    /// Its box, highest `[z, r]`.
    pub hi: [f64; 2],
    /// The new program's lines whose moves made it (empty: not known, a saved report).
    pub new_lines: Vec<u32>,
    /// The old program's lines whose moves made it.
    pub old_lines: Vec<u32>,
    /// Line and column of the new program's last move that made it (its finishing cut, or
    /// the last move that left its edge): where a CI annotation puts it; `None`: unknown.
    pub new_place: Option<[u32; 2]>,
}

impl DiffRegion {
    /// What the region is, in program words: `L1 lost 0.6 mm², 0.2 mm deep, Z-25.2…-25
    /// X30…36; new lines 10, 14, 15; old lines 14, 15` (`label` numbers it, `lost` says
    /// which list it is in).
    pub fn describe(&self, label: &str, lost: bool) -> String {
        format!(
            "{label} {} {} mm², {} mm deep, Z{}…{} X{}…{}; new lines {}; old lines {}",
            if lost { "lost" } else { "gained" },
            num(self.area_mm2, 4),
            num(self.depth_mm, 4),
            num(self.lo[0], 3),
            num(self.hi[0], 3),
            num(2.0 * self.lo[1], 3),
            num(2.0 * self.hi[1], 3),
            lines(&self.new_lines),
            lines(&self.old_lines)
        )
    }
}

/// `14, 15, 16` (at most eight, then `…`), or `—` when none is known.
fn lines(l: &[u32]) -> String {
    if l.is_empty() {
        return "—".into();
    }
    let mut s: Vec<String> = l.iter().take(8).map(u32::to_string).collect();
    if l.len() > 8 {
        s.push("…".into());
    }
    s.join(", ")
}

/// A tool's time on each side (`None`: the tool is not used there).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToolTime {
    /// `T01`.
    pub tool: String,
    /// Seconds in the old run.
    pub old_s: Option<f64>,
    /// Seconds in the new run.
    pub new_s: Option<f64>,
}

/// A finding (alarm, warning, crash, rapid scrape, gouge) that only one side has.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DiffFinding {
    /// `alarm`, `warning`, `crash`, `rapid_scrape` or `gouge` (the run report's lists).
    pub kind: String,
    /// Its code (`PS011`, `LS-RAPID-SCRAPE`; `LS-CRASH`, `LS-GOUGE` for those).
    pub code: String,
    /// Its line in the program that has it (0: none).
    pub line: u32,
    /// Where, `[z, r]`, for crashes, scrapes and gouges.
    pub at: Option<[f64; 2]>,
    /// What it says.
    pub message: String,
}

/// Everything a diff shows.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DiffReport {
    /// The old side: a program or a saved report, as named.
    pub old: String,
    /// The new side.
    pub new: String,
    /// The tolerance below which the parts agree, mm.
    pub tolerance_mm: f64,
    /// The verdict of each side's run: old, new.
    pub verdicts: [Verdict; 2],
    /// The old final part.
    pub old_part: Vec<Shape>,
    /// The new final part.
    pub new_part: Vec<Shape>,
    /// Material the new part keeps that the old one did not, largest first.
    pub gained: Vec<DiffRegion>,
    /// Material the old part kept that the new one does not, largest first.
    pub lost: Vec<DiffRegion>,
    /// Cycle time, s: old, new.
    pub cycle_time_s: [f64; 2],
    /// Time per tool, in order of first use (the new run's tools first).
    pub tools: Vec<ToolTime>,
    /// Findings of the new run the old one did not have.
    pub appeared: Vec<DiffFinding>,
    /// Findings of the old run the new one does not have.
    pub gone: Vec<DiffFinding>,
}

impl DiffReport {
    /// Whether the parts differ (by more than the tolerance).
    pub fn differs(&self) -> bool {
        !(self.gained.is_empty() && self.lost.is_empty())
    }

    /// Area gained, mm².
    pub fn gained_area(&self) -> f64 {
        self.gained.iter().fold(0.0, |a, r| a + r.area_mm2)
    }

    /// Area lost, mm².
    pub fn lost_area(&self) -> f64 {
        self.lost.iter().fold(0.0, |a, r| a + r.area_mm2)
    }

    /// Tools whose time changed by at least `min_s` seconds (or that one side lacks).
    pub fn changed_tools(&self, min_s: f64) -> impl Iterator<Item = &ToolTime> {
        self.tools.iter().filter(move |t| match (t.old_s, t.new_s) {
            (Some(a), Some(b)) => (a - b).abs() >= min_s,
            _ => true,
        })
    }
}

/// The diff picture as an SVG document (1600 × 1000 px): both sections overlaid (the old
/// part's edge dashed), lost material red, gained material green, each region numbered
/// and zoomed in the right column with its lines, then the times and findings.
pub fn diff_svg(d: &DiffReport) -> String {
    picture::svg(d)
}

/// The diff picture rasterised, PNG bytes of 1600 × 1000 px.
pub fn diff_png(d: &DiffReport) -> Result<Vec<u8>, RenderError> {
    crate::png::rasterise(&picture::svg(d))
}

/// The diff as one self-contained HTML page: the picture inline and the tables.
pub fn diff_html(d: &DiffReport) -> String {
    page::html(d, &picture::svg(d))
}

/// The diff as pretty JSON (see README, "latsim diff").
pub fn diff_json(d: &DiffReport) -> String {
    json::json(d)
}
