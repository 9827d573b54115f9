//! The title block in the right column: verdict, program, stock, tools, removal, cycle
//! time, tolerance, deviation, then the alarms and warnings as `line N: message`.

use crate::doc::Doc;
use crate::layout::{colour, FS_SMALL, FS_TEXT, FS_VERDICT, H, RIGHT_BOTTOM, RIGHT_W, RIGHT_X, W};
use crate::report::{Diagnostic, Report, Verdict};
use crate::text::{chars_fitting, duration, grouped, mm, plural, quantity, wrap};

/// Width of the label column.
const LABEL_W: f64 = 104.0;
/// Row pitch of label/value rows.
const ROW: f64 = 22.0;
/// Row pitch of diagnostic lines.
const DIAG_ROW: f64 = 18.0;
/// Tools listed before "+N more".
const MAX_TOOLS: usize = 4;

/// The verdict line and its colour: the findings that make the verdict, then how many are
/// only possible (a guessed tool's: not in the verdict). "GOUGE — 43 crashes, 1 gouge"
/// stood over a run whose 43 crashes were all possible (field run 9, E).
pub(crate) fn verdict_text(report: &Report) -> (String, &'static str) {
    let mut parts = Vec::new();
    if !report.alarms.is_empty() {
        parts.push(plural(report.alarms.len(), "alarm", "alarms"));
    }
    let crashes = report.crashes.iter().filter(|c| !c.assumed).count();
    if crashes > 0 {
        parts.push(plural(crashes, "crash", "crashes"));
    }
    let gouges: Vec<f64> = report
        .gouges
        .iter()
        .filter(|g| !g.assumed)
        .map(|g| g.depth_mm)
        .collect();
    if !gouges.is_empty() {
        let deepest = gouges
            .iter()
            .copied()
            .filter(|d| d.is_finite())
            .fold(0.0, f64::max);
        parts.push(format!(
            "{} ({} deep)",
            plural(gouges.len(), "gouge", "gouges"),
            mm(deepest)
        ));
    }
    let possible = report.crashes.len() - crashes + report.gouges.len() - gouges.len();
    if possible > 0 {
        parts.push(plural(possible, "possible finding", "possible findings"));
    }
    match report.verdict {
        Verdict::Clean => ("CLEAN — no gouge, no crash".to_string(), colour::OK),
        v => {
            let word = match v {
                Verdict::Alarm => "ALARM",
                Verdict::Crash => "CRASH",
                _ => "GOUGE",
            };
            (format!("{word} — {}", parts.join(", ")), colour::BAD)
        }
    }
}

/// One diagnostic as text.
fn diag_text(d: &Diagnostic) -> String {
    let msg = d.message.trim();
    let msg = if msg.is_empty() { d.code.as_str() } else { msg };
    if d.line == 0 {
        msg.to_string()
    } else {
        format!("line {}: {msg}", d.line)
    }
}

struct Block<'a> {
    doc: &'a mut Doc,
    y: f64,
}

impl Block<'_> {
    /// A label/value row; the value wraps to at most `max_lines` lines.
    fn row(&mut self, label: &str, value: &str, size: f64, fill: &str, max_lines: usize) {
        let vx = RIGHT_X + LABEL_W;
        let chars = chars_fitting(RIGHT_W - LABEL_W, size);
        self.doc
            .text(RIGHT_X, self.y, FS_TEXT, "start", colour::MUTED, label);
        let lines = wrap(value, chars, max_lines);
        if lines.is_empty() {
            self.doc.text(vx, self.y, size, "start", colour::MUTED, "—");
            self.y += ROW;
        }
        for l in lines {
            self.doc.text(vx, self.y, size, "start", fill, &l);
            self.y += ROW;
        }
    }

    /// A list of diagnostics with a header, within `rows` diagnostic rows (header
    /// included); shows "+N more" when they don't all fit.
    fn diags(&mut self, title: &str, list: &[Diagnostic], fill: &str, rows: usize) {
        if list.is_empty() || rows == 0 {
            return;
        }
        self.y += 6.0;
        self.doc.text(
            RIGHT_X,
            self.y,
            FS_TEXT,
            "start",
            fill,
            &format!("{title} ({})", list.len()),
        );
        self.y += DIAG_ROW + 2.0;
        let mut left = rows.saturating_sub(1);
        let chars = chars_fitting(RIGHT_W - 14.0, FS_SMALL);
        for (i, d) in list.iter().enumerate() {
            // Keep a row for "+N more" unless this is the last item.
            let more_row = usize::from(i + 1 < list.len());
            let max_lines = 2.min(left.saturating_sub(more_row));
            if max_lines == 0 {
                if left > 0 {
                    let more = format!("+{} more", list.len() - i);
                    self.doc.text(
                        RIGHT_X + 14.0,
                        self.y,
                        FS_SMALL,
                        "start",
                        colour::MUTED,
                        &more,
                    );
                    self.y += DIAG_ROW;
                }
                return;
            }
            for (j, l) in wrap(&diag_text(d), chars, max_lines).iter().enumerate() {
                let x = if j == 0 {
                    RIGHT_X + 14.0
                } else {
                    RIGHT_X + 28.0
                };
                self.doc.text(x, self.y, FS_SMALL, "start", colour::INK, l);
                self.y += DIAG_ROW;
                left -= 1;
            }
        }
    }
}

/// Rows a diagnostics list would like at least: its header and up to `items` items
/// (two lines each at most) and a "+N more" line.
fn diag_rows_wanted(list: &[Diagnostic], items: usize) -> usize {
    if list.is_empty() {
        return 0;
    }
    let chars = chars_fitting(RIGHT_W - 14.0, FS_SMALL);
    let lines: usize = list
        .iter()
        .take(items)
        .map(|d| wrap(&diag_text(d), chars, 2).len())
        .sum();
    1 + lines + usize::from(list.len() > items)
}

/// Height the title block needs (fixed rows plus a useful share of the diagnostics), so
/// the detail views above it can give way.
pub(crate) fn min_height(report: &Report) -> f64 {
    // Laid out on a scratch document that is thrown away.
    let mut scratch = Doc::new(W, H, "");
    let mut b = Block {
        doc: &mut scratch,
        y: 0.0,
    };
    fixed_rows(&mut b, report);
    let diag = diag_rows_wanted(&report.alarms, 3) + diag_rows_wanted(&report.warnings, 2);
    b.y + 24.0 + 12.0 + diag as f64 * DIAG_ROW + 12.0
}

fn fixed_rows(b: &mut Block, report: &Report) {
    let (verdict, vc) = verdict_text(report);
    b.row("verdict", &verdict, FS_VERDICT, vc, 2);

    let mut program = report.program.clone();
    if !report.title.is_empty() && !program.starts_with(&report.title) {
        program = format!("{program} ({})", report.title);
    }
    b.row("program", &program, FS_TEXT, colour::INK, 2);
    if !report.control.is_empty() {
        // the dialect the program was read in: the same text means other motion elsewhere
        b.row("control", &report.control, FS_TEXT, colour::INK, 1);
    }
    let feed = report.segments.saturating_sub(report.rapid_segments);
    b.row(
        "moves",
        &format!(
            "{} (rapid {}, feed {})",
            grouped(report.segments as f64, 0),
            grouped(report.rapid_segments as f64, 0),
            grouped(feed as f64, 0)
        ),
        FS_TEXT,
        colour::INK,
        1,
    );
    b.row("stock", &report.stock.description, FS_TEXT, colour::INK, 2);
    if report.tools.is_empty() {
        b.row("tools", "", FS_TEXT, colour::INK, 1);
    }
    for (i, t) in report.tools.iter().take(MAX_TOOLS).enumerate() {
        b.row(
            if i == 0 { "tools" } else { "" },
            t,
            FS_TEXT,
            colour::INK,
            1,
        );
    }
    if report.tools.len() > MAX_TOOLS {
        b.row(
            "",
            &format!("+{} more", report.tools.len() - MAX_TOOLS),
            FS_TEXT,
            colour::MUTED,
            1,
        );
    }
    b.row(
        "removed",
        &format!(
            "{} mm² section / {} mm³",
            quantity(report.removed_area_mm2),
            quantity(report.removed_volume_mm3)
        ),
        FS_TEXT,
        colour::INK,
        1,
    );
    b.row(
        "cycle time",
        &duration(report.cycle_time_s),
        FS_TEXT,
        colour::INK,
        1,
    );
    b.row(
        "tolerance",
        &mm(report.tolerance_mm),
        FS_TEXT,
        colour::INK,
        1,
    );
    if let Some(d) = &report.deviation {
        let over = format!(
            "{} mm², max {}",
            quantity(d.overcut_area_mm2),
            mm(d.max_overcut_mm)
        );
        let under = format!(
            "{} mm², max {}",
            quantity(d.undercut_area_mm2),
            mm(d.max_undercut_mm)
        );
        b.row("overcut", &over, FS_TEXT, colour::INK, 1);
        b.row("undercut", &under, FS_TEXT, colour::INK, 1);
    }
}

/// Draw the title block starting below `top`.
pub(crate) fn title_block(doc: &mut Doc, report: &Report, top: f64) {
    doc.open("g", &[("id", "title-block".into())]);
    let mut b = Block { doc, y: top + 24.0 };
    fixed_rows(&mut b, report);

    // Share what is left: alarms first, but warnings keep room for their header, an
    // item and "+N more" when there is room at all.
    let rows = ((RIGHT_BOTTOM - b.y - 12.0) / DIAG_ROW).floor().max(0.0) as usize;
    let warn_min = diag_rows_wanted(&report.warnings, 1).min(3);
    let alarm_rows = if rows >= warn_min + 3 {
        rows - warn_min
    } else {
        rows
    };
    let y0 = b.y;
    b.diags("alarms", &report.alarms, colour::BAD, alarm_rows);
    let used = ((b.y - y0) / DIAG_ROW).ceil() as usize;
    b.diags(
        "warnings",
        &report.warnings,
        colour::WARN,
        rows.saturating_sub(used),
    );
    b.doc.close();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::{Crash, Gouge};

    fn gouge(depth_mm: f64, assumed: bool) -> Gouge {
        Gouge {
            line: 12,
            z: -10.0,
            r: 12.0,
            area_mm2: 1.0,
            depth_mm,
            assumed,
            cause: None,
            remedy: None,
        }
    }

    /// Field run 9 (E): a run with one certain gouge and 43 possible crashes read
    /// "GOUGE — 43 crashes, 1 gouge (12 mm deep)" over a verdict of 0 crashes. Only the
    /// certain findings are counted as such; the possible ones are counted apart, and a
    /// possible gouge's depth is not the headline's.
    #[test]
    fn the_headline_counts_possible_findings_apart() {
        let report = Report {
            verdict: Verdict::Gouge,
            crashes: vec![
                Crash {
                    assumed: true,
                    ..Crash::default()
                };
                43
            ],
            gouges: vec![gouge(12.0, false), gouge(20.0, true)],
            ..Report::default()
        };
        let (text, _) = verdict_text(&report);
        assert_eq!(text, "GOUGE — 1 gouge (12 mm deep), 44 possible findings");
    }
}
