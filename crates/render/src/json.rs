//! The machine-readable report: a stable contract in program coordinates (`z`, `x` =
//! diameter). Private serialisation structs keep the contract independent of `Report`.

use serde::Serialize;

use crate::report::{Diagnostic, Report, Shape, Verdict};

/// Round to 6 decimals; non-finite values become `null` (JSON has no NaN).
fn r6(v: f64) -> Option<f64> {
    if !v.is_finite() {
        return None;
    }
    let r = (v * 1e6).round() / 1e6;
    // Huge values would overflow the rounding; keep them as they are.
    let r = if r.is_finite() { r } else { v };
    Some(if r == 0.0 { 0.0 } else { r })
}

/// `[z, r]` -> `[z, x]` with x = 2r.
fn zx(p: &[f64; 2]) -> [Option<f64>; 2] {
    [r6(p[0]), r6(2.0 * p[1])]
}

#[derive(Serialize)]
struct Polygon {
    outer: Vec<[Option<f64>; 2]>,
    holes: Vec<Vec<[Option<f64>; 2]>>,
}

impl Polygon {
    fn from(s: &Shape) -> Self {
        Self {
            outer: s.outer.iter().map(zx).collect(),
            holes: s.holes.iter().map(|h| h.iter().map(zx).collect()).collect(),
        }
    }
}

#[derive(Serialize)]
struct Stock {
    description: String,
    polygons: Vec<Polygon>,
}

#[derive(Serialize)]
struct Diag<'a> {
    line: u32,
    column: u32,
    code: &'a str,
    message: &'a str,
}

impl<'a> Diag<'a> {
    fn from(d: &'a Diagnostic) -> Self {
        Self {
            line: d.line,
            column: d.column,
            code: &d.code,
            message: &d.message,
        }
    }
}

#[derive(Serialize)]
struct CrashJ {
    line: u32,
    column: u32,
    z: Option<f64>,
    x: Option<f64>,
    area_mm2: Option<f64>,
    depth_mm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    body: Option<String>,
    /// The workholding entered (additive field, only when there is one).
    #[serde(skip_serializing_if = "Option::is_none")]
    obstacle: Option<String>,
    /// A possible crash of a tool the table does not state (additive, only when true).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    assumed_tool: bool,
    /// Why it happened (additive): `{kind, text, <numbers>}`, `null` when not diagnosed.
    cause: Option<CauseJ>,
    /// A checked fix (additive): `{text, tool, line, edit, verified}`, or `null`.
    remedy: Option<RemedyJ>,
}

#[derive(Serialize)]
struct CauseJ {
    kind: String,
    text: String,
    #[serde(flatten)]
    numbers: std::collections::BTreeMap<String, Option<f64>>,
}

impl From<&crate::Cause> for CauseJ {
    fn from(c: &crate::Cause) -> Self {
        Self {
            kind: c.kind.clone(),
            text: c.text.clone(),
            numbers: c.numbers.iter().map(|(k, v)| (k.clone(), r6(*v))).collect(),
        }
    }
}

#[derive(Serialize)]
struct RemedyJ {
    text: String,
    tool: Option<String>,
    line: Option<u32>,
    edit: Option<String>,
    verified: bool,
}

impl From<&crate::Remedy> for RemedyJ {
    fn from(r: &crate::Remedy) -> Self {
        Self {
            text: r.text.clone(),
            tool: r.tool.clone(),
            line: r.line,
            edit: r.edit.clone(),
            verified: r.verified,
        }
    }
}

#[derive(Serialize)]
struct LeftoverJ {
    z: Option<f64>,
    x: Option<f64>,
    area_mm2: Option<f64>,
    depth_mm: Option<f64>,
    cause: Option<CauseJ>,
    remedy: Option<RemedyJ>,
}

impl From<&crate::Crash> for CrashJ {
    fn from(c: &crate::Crash) -> Self {
        Self {
            line: c.line,
            column: c.column,
            z: r6(c.z),
            x: r6(2.0 * c.r),
            area_mm2: r6(c.area_mm2),
            depth_mm: r6(c.depth_mm),
            body: c.body.clone(),
            obstacle: c.obstacle.clone(),
            assumed_tool: c.assumed,
            cause: c.cause.as_ref().map(CauseJ::from),
            remedy: c.remedy.as_ref().map(RemedyJ::from),
        }
    }
}

#[derive(Serialize)]
struct GougeJ {
    line: u32,
    z: Option<f64>,
    x: Option<f64>,
    area_mm2: Option<f64>,
    depth_mm: Option<f64>,
    /// A possible gouge of a tool the table does not state (additive, only when true).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    assumed_tool: bool,
    /// Why it happened (additive), or `null`.
    cause: Option<CauseJ>,
    /// A checked fix (additive), or `null`.
    remedy: Option<RemedyJ>,
}

#[derive(Serialize)]
struct GrooveJ {
    line: u32,
    ring: Vec<[Option<f64>; 2]>,
}

#[derive(Serialize)]
struct ThreadJ {
    line: u32,
    side: &'static str,
    lead_mm: Option<f64>,
    /// Number of starts (additive field): the pitch is the lead over it.
    starts: usize,
    x: Option<f64>,
    expected_x: Option<f64>,
    passes: usize,
    pass_depths_mm: Vec<Option<f64>>,
    achieved_x: Option<f64>,
    depth_error_mm: Option<f64>,
    /// Pitch diameter as cut, mm (additive field).
    pitch_diameter: Option<f64>,
    /// Included flank angle as cut, degrees (additive field).
    included_angle_deg: Option<f64>,
    /// Z where the deepest pass starts and ends (additive fields).
    z_start: Option<f64>,
    z_end: Option<f64>,
}

#[derive(Serialize)]
struct DeviationJ {
    overcut_area_mm2: Option<f64>,
    undercut_area_mm2: Option<f64>,
    max_overcut_mm: Option<f64>,
    max_undercut_mm: Option<f64>,
}

#[derive(Serialize)]
struct Doc<'a> {
    program: &'a str,
    title: &'a str,
    /// `--control` key the program was read for (additive field).
    control: &'a str,
    /// The text encoding the program was read in (additive field).
    encoding: &'a str,
    verdict: &'static str,
    stock: Stock,
    #[serde(rename = "final")]
    final_part: Vec<Polygon>,
    removed_area_mm2: Option<f64>,
    removed_volume_mm3: Option<f64>,
    segments: usize,
    cycle_time_s: Option<f64>,
    tolerance_mm: Option<f64>,
    tools: &'a [String],
    alarms: Vec<Diag<'a>>,
    warnings: Vec<Diag<'a>>,
    crashes: Vec<CrashJ>,
    rapid_cuts: Vec<CrashJ>,
    gouges: Vec<GougeJ>,
    /// The leftovers as findings (additive): place, size, cause.
    leftovers: Vec<LeftoverJ>,
    deviation: Option<DeviationJ>,
    grooves: Vec<GrooveJ>,
    /// Custom macro B's variables at the end of the run (additive field).
    variables: Vec<VariableJ<'a>>,
    /// Lines executed more than once (additive field).
    line_counts: Vec<LineCountJ>,
    /// The threads and their depth as cut (additive field).
    threads: Vec<ThreadJ>,
}

#[derive(Serialize)]
struct VariableJ<'a> {
    name: &'a str,
    value: Option<f64>,
}

#[derive(Serialize)]
struct LineCountJ {
    line: u32,
    count: u64,
}

/// The word used for a verdict in the JSON.
pub(crate) fn verdict_word(v: Verdict) -> &'static str {
    match v {
        Verdict::Clean => "clean",
        Verdict::Alarm => "alarm",
        Verdict::Crash => "crash",
        Verdict::Gouge => "gouge",
    }
}

/// Pretty JSON of the report (see the crate docs for the contract).
pub(crate) fn json(report: &Report) -> String {
    let doc = Doc {
        program: &report.program,
        title: &report.title,
        control: &report.control,
        encoding: &report.encoding,
        verdict: verdict_word(report.verdict),
        stock: Stock {
            description: report.stock.description.clone(),
            polygons: report.stock.shapes.iter().map(Polygon::from).collect(),
        },
        final_part: report.final_part.iter().map(Polygon::from).collect(),
        removed_area_mm2: r6(report.removed_area_mm2),
        removed_volume_mm3: r6(report.removed_volume_mm3),
        segments: report.segments,
        cycle_time_s: r6(report.cycle_time_s),
        tolerance_mm: r6(report.tolerance_mm),
        tools: &report.tools,
        alarms: report.alarms.iter().map(Diag::from).collect(),
        warnings: report.warnings.iter().map(Diag::from).collect(),
        crashes: report.crashes.iter().map(CrashJ::from).collect(),
        rapid_cuts: report.rapid_cuts.iter().map(CrashJ::from).collect(),
        gouges: report
            .gouges
            .iter()
            .map(|g| GougeJ {
                line: g.line,
                z: r6(g.z),
                x: r6(2.0 * g.r),
                area_mm2: r6(g.area_mm2),
                depth_mm: r6(g.depth_mm),
                assumed_tool: g.assumed,
                cause: g.cause.as_ref().map(CauseJ::from),
                remedy: g.remedy.as_ref().map(RemedyJ::from),
            })
            .collect(),
        leftovers: report
            .leftover_list
            .iter()
            .map(|l| LeftoverJ {
                z: r6(l.z),
                x: r6(2.0 * l.r),
                area_mm2: r6(l.area_mm2),
                depth_mm: r6(l.depth_mm),
                cause: l.cause.as_ref().map(CauseJ::from),
                remedy: None,
            })
            .collect(),
        deviation: report.deviation.as_ref().map(|d| DeviationJ {
            overcut_area_mm2: r6(d.overcut_area_mm2),
            undercut_area_mm2: r6(d.undercut_area_mm2),
            max_overcut_mm: r6(d.max_overcut_mm),
            max_undercut_mm: r6(d.max_undercut_mm),
        }),
        grooves: report
            .grooves
            .iter()
            .map(|g| GrooveJ {
                line: g.line,
                ring: g.ring.iter().map(zx).collect(),
            })
            .collect(),
        variables: report
            .variables
            .iter()
            .map(|(name, value)| VariableJ {
                name,
                value: *value,
            })
            .collect(),
        line_counts: report
            .line_counts
            .iter()
            .map(|&(line, count)| LineCountJ { line, count })
            .collect(),
        threads: report
            .threads
            .iter()
            .map(|t| ThreadJ {
                line: t.line,
                side: if t.inside { "id" } else { "od" },
                lead_mm: r6(t.lead_mm),
                starts: t.starts.max(1),
                x: r6(t.x_mm),
                expected_x: t.expected_x_mm.and_then(r6),
                passes: t.pass_depths_mm.len(),
                pass_depths_mm: t.pass_depths_mm.iter().map(|&d| r6(d)).collect(),
                achieved_x: t.achieved_x_mm.and_then(r6),
                depth_error_mm: t.depth_error_mm.and_then(r6),
                pitch_diameter: t.pitch_diameter_mm.and_then(r6),
                included_angle_deg: t.included_angle_deg.and_then(r6),
                z_start: r6(t.z_start_mm),
                z_end: r6(t.z_end_mm),
            })
            .collect(),
    };
    // Serialising plain structs of strings, integers and Option<f64> cannot fail.
    serde_json::to_string_pretty(&doc).unwrap_or_else(|_| "{}".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding() {
        assert_eq!(r6(1.23456789), Some(1.234568));
        assert_eq!(r6(-0.0000001), Some(0.0));
        assert_eq!(r6(f64::NAN), None);
        assert_eq!(r6(1e300), Some(1e300));
    }
}
