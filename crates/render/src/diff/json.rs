//! The diff as JSON, in program coordinates (`z`, `x` = diameter), numbers rounded to 6
//! decimals like the run's report; fields are only ever added.

use serde::Serialize;

use super::{DiffFinding, DiffRegion, DiffReport};
use crate::report::Shape;

/// Round to 6 decimals; non-finite values become `null` (as the run's report does).
fn r6(v: f64) -> Option<f64> {
    if !v.is_finite() {
        return None;
    }
    let r = (v * 1e6).round() / 1e6;
    let r = if r.is_finite() { r } else { v };
    Some(if r == 0.0 { 0.0 } else { r })
}

fn zx(p: &[f64; 2]) -> [Option<f64>; 2] {
    [r6(p[0]), r6(2.0 * p[1])]
}

#[derive(Serialize)]
struct Polygon {
    outer: Vec<[Option<f64>; 2]>,
    holes: Vec<Vec<[Option<f64>; 2]>>,
}

fn polygons(shapes: &[Shape]) -> Vec<Polygon> {
    shapes
        .iter()
        .map(|s| Polygon {
            outer: s.outer.iter().map(zx).collect(),
            holes: s.holes.iter().map(|h| h.iter().map(zx).collect()).collect(),
        })
        .collect()
}

#[derive(Serialize)]
struct RegionJ<'a> {
    area_mm2: Option<f64>,
    depth_mm: Option<f64>,
    z: Option<f64>,
    x: Option<f64>,
    z_min: Option<f64>,
    z_max: Option<f64>,
    x_min: Option<f64>,
    x_max: Option<f64>,
    new_lines: &'a [u32],
    old_lines: &'a [u32],
    new_line: Option<u32>,
    new_column: Option<u32>,
    polygon: Vec<Polygon>,
}

fn region(r: &DiffRegion) -> RegionJ<'_> {
    RegionJ {
        area_mm2: r6(r.area_mm2),
        depth_mm: r6(r.depth_mm),
        z: r6(r.z),
        x: r6(2.0 * r.r),
        z_min: r6(r.lo[0]),
        z_max: r6(r.hi[0]),
        x_min: r6(2.0 * r.lo[1]),
        x_max: r6(2.0 * r.hi[1]),
        new_lines: &r.new_lines,
        old_lines: &r.old_lines,
        new_line: r.new_place.map(|p| p[0]),
        new_column: r.new_place.map(|p| p[1]),
        polygon: polygons(std::slice::from_ref(&r.shape)),
    }
}

#[derive(Serialize)]
struct Change {
    old: Option<f64>,
    new: Option<f64>,
    change: Option<f64>,
}

fn change(old: Option<f64>, new: Option<f64>) -> Change {
    Change {
        old: old.and_then(r6),
        new: new.and_then(r6),
        change: old.zip(new).and_then(|(a, b)| r6(b - a)),
    }
}

#[derive(Serialize)]
struct ToolJ<'a> {
    tool: &'a str,
    #[serde(flatten)]
    seconds: Change,
}

#[derive(Serialize)]
struct FindingJ<'a> {
    kind: &'a str,
    code: &'a str,
    line: u32,
    z: Option<f64>,
    x: Option<f64>,
    message: &'a str,
}

fn finding(f: &DiffFinding) -> FindingJ<'_> {
    FindingJ {
        kind: &f.kind,
        code: &f.code,
        line: f.line,
        z: f.at.and_then(|p| r6(p[0])),
        x: f.at.and_then(|p| r6(2.0 * p[1])),
        message: &f.message,
    }
}

#[derive(Serialize)]
struct Findings<'a> {
    appeared: Vec<FindingJ<'a>>,
    gone: Vec<FindingJ<'a>>,
}

#[derive(Serialize)]
struct Doc<'a> {
    old: &'a str,
    new: &'a str,
    verdict: &'static str,
    tolerance_mm: Option<f64>,
    old_verdict: &'static str,
    new_verdict: &'static str,
    gained_area_mm2: Option<f64>,
    lost_area_mm2: Option<f64>,
    gained: Vec<RegionJ<'a>>,
    lost: Vec<RegionJ<'a>>,
    cycle_time_s: Change,
    tools: Vec<ToolJ<'a>>,
    findings: Findings<'a>,
    old_final: Vec<Polygon>,
    new_final: Vec<Polygon>,
}

/// Pretty JSON of the diff.
pub(super) fn json(d: &DiffReport) -> String {
    let doc = Doc {
        old: &d.old,
        new: &d.new,
        verdict: if d.differs() { "differs" } else { "same" },
        tolerance_mm: r6(d.tolerance_mm),
        old_verdict: crate::verdict_word(d.verdicts[0]),
        new_verdict: crate::verdict_word(d.verdicts[1]),
        gained_area_mm2: r6(d.gained_area()),
        lost_area_mm2: r6(d.lost_area()),
        gained: d.gained.iter().map(region).collect(),
        lost: d.lost.iter().map(region).collect(),
        cycle_time_s: change(Some(d.cycle_time_s[0]), Some(d.cycle_time_s[1])),
        tools: d
            .tools
            .iter()
            .map(|t| ToolJ {
                tool: &t.tool,
                seconds: change(t.old_s, t.new_s),
            })
            .collect(),
        findings: Findings {
            appeared: d.appeared.iter().map(finding).collect(),
            gone: d.gone.iter().map(finding).collect(),
        },
        old_final: polygons(&d.old_part),
        new_final: polygons(&d.new_part),
    };
    // plain structs of strings, integers and options: serialising cannot fail
    serde_json::to_string_pretty(&doc).unwrap_or_else(|_| "{}".to_string())
}
