//! The `[[tool]]` TOML format of spec/simulation.md: serde's raw records (unknown fields
//! refused with their line and column), then each entry validated into a [`Tool`] with
//! errors naming the tool, the field and the line.

use super::{AxisDir, GroovingBlade, HolderSize, Insert, ThreadSide, Tool};
use crate::error::{from_toml, line_col};
use crate::StockError;
use serde::Deserialize;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTable {
    #[serde(default)]
    tool: Vec<Spanned<RawTool>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTool {
    t: u32,
    kind: String,
    insert: Option<String>,
    holder: Option<String>,
    shank: Option<f64>,
    nose_radius: Option<f64>,
    tip: Option<i64>,
    entering_angle: Option<f64>,
    edge: Option<f64>,
    width: Option<f64>,
    width_dir: Option<String>,
    shank_dir: Option<String>,
    reach: Option<f64>,
    corner_radius: Option<f64>,
    diameter: Option<f64>,
    point_angle: Option<f64>,
    angle: Option<f64>,
    tip_flat: Option<f64>,
    side: Option<String>,
}

const HELP: &str = "each [[tool]] needs `t` and `kind` (turning | grooving | drill | threading) and only the fields of its kind";

/// One entry read.
pub(super) struct Entry {
    /// Its T number.
    pub(super) t: u32,
    pub(super) tool: Tool,
    /// The ISO designations it was given by (`"CNMG 120408 in PCLNR 2525M12"`), if any,
    /// for the report.
    pub(super) designation: Option<String>,
    /// Its holder's size.
    pub(super) size: HolderSize,
    /// Whether the entry states the size of its cutting outline (spec/simulation.md, "Only
    /// stated geometry past the axis"): a turning insert's `edge` or an ISO insert
    /// designation, a blade's `width` and `reach`, a drill's `diameter` (required), a
    /// threading insert (its form is its angle).
    pub(super) stated: bool,
    /// Whether a turning entry states its nose radius (`nose_radius` or an ISO insert).
    pub(super) nose_stated: bool,
    /// Whether a grooving entry states its width.
    pub(super) width_stated: bool,
}

/// The table's entries in file order; a T number given twice is an error.
pub(super) fn read(text: &str) -> Result<Vec<Entry>, StockError> {
    let raw: RawTable =
        toml::from_str(text).map_err(|e| from_toml("tool table", text, &e, HELP))?;
    let mut tools: Vec<Entry> = Vec::new();
    for entry in &raw.tool {
        let (line, _) = line_col(text, entry.span().start);
        let raw = entry.get_ref();
        let (tool, designation, size) = parse_tool(raw, line)?;
        if tools.iter().any(|e| e.t == raw.t) {
            return Err(StockError::Tool {
                t: raw.t,
                field: "t",
                message: "appears twice in the table".into(),
                line,
            });
        }
        tools.push(Entry {
            t: raw.t,
            stated: size_stated(raw, designation.is_some()),
            nose_stated: raw.kind == "turning"
                && (raw.nose_radius.is_some() || designation.is_some()),
            width_stated: raw.kind == "grooving" && raw.width.is_some(),
            tool,
            designation,
            size,
        });
    }
    Ok(tools)
}

/// Whether `raw` states its cutting outline's size (see [`Entry::stated`]); `designated`:
/// its insert was given by an ISO designation, which gives the edge length.
fn size_stated(raw: &RawTool, designated: bool) -> bool {
    match raw.kind.as_str() {
        "turning" => raw.edge.is_some() || designated,
        "grooving" => raw.width.is_some() && raw.reach.is_some(),
        _ => true,
    }
}

/// What ISO designations (`insert = "CNMG 120408"`, `holder = "PCLNR 2525M12"`) say about a
/// turning tool; the explicit fields may repeat a value but not contradict it.
struct Designated {
    insert: Insert,
    nose_radius: f64,
    edge: f64,
    /// From the holder: entering angle and the usual imaginary tip for its hand, OD/ID.
    holder: Option<(f64, u8)>,
    /// From the holder: its shank section and length.
    size: HolderSize,
    text: String,
}

fn designated(raw: &RawTool) -> Result<Option<Designated>, (&'static str, String)> {
    let Some(text) = raw
        .insert
        .as_deref()
        .filter(|s| s.trim().chars().count() > 1)
    else {
        return match raw.holder {
            Some(_) => Err((
                "holder",
                "needs the insert's ISO designation in `insert` (e.g. insert = \"CNMG 120408\")"
                    .into(),
            )),
            None => Ok(None),
        };
    };
    let iso = tooling_iso::Insert::parse(text).map_err(|e| ("insert", e.to_string()))?;
    let letter = iso.shape.letter().to_string();
    let insert = Insert::from_letter(&letter).ok_or_else(|| {
        (
            "insert",
            format!(
                "= \"{text}\": shape {letter} ({}) has no outline in latsim; give the nearest \
                 shape letter (C, D, T, V, W, S, R) with explicit fields",
                iso.shape.describe()
            ),
        )
    })?;
    let mut d = Designated {
        insert,
        nose_radius: iso.nose_radius,
        edge: iso.edge_length,
        holder: None,
        size: HolderSize::default(),
        text: iso.designation.clone(),
    };
    if let Some(h) = &raw.holder {
        let holder = tooling_iso::Holder::parse(h).map_err(|e| ("holder", e.to_string()))?;
        let facts =
            tooling_iso::turning_facts(&iso, &holder).map_err(|e| ("holder", e.to_string()))?;
        d.holder = Some((facts.entering_angle, facts.tip));
        d.size = HolderSize {
            shank: Some(match holder.shank {
                tooling_iso::Shank::Square { width, .. } => width,
                tooling_iso::Shank::Bar { diameter, .. } => diameter,
            }),
            length: holder.length,
            declared: true,
        };
        d.text = format!("{} in {}", iso.designation, holder.designation);
    }
    // an explicit field that repeats the designation is fine; one that contradicts it is not
    for (field, given, value) in [
        ("nose_radius", raw.nose_radius, Some(d.nose_radius)),
        ("edge", raw.edge, Some(d.edge)),
        ("entering_angle", raw.entering_angle, d.holder.map(|h| h.0)),
        ("shank", raw.shank, d.size.shank),
    ] {
        if let (Some(g), Some(v)) = (given, value) {
            if (g - v).abs() > 1e-6 {
                return Err((
                    field,
                    format!("= {g} contradicts the designation \"{}\" ({v})", d.text),
                ));
            }
        }
    }
    Ok(Some(d))
}

fn parse_tool(
    raw: &RawTool,
    line: usize,
) -> Result<(Tool, Option<String>, HolderSize), StockError> {
    let t = raw.t;
    let err = |field: &'static str, message: String| StockError::Tool {
        t,
        field,
        message,
        line,
    };
    // a positive (or non-negative) finite length or angle, with its default
    let num = |field: &'static str,
               v: Option<f64>,
               default: Option<f64>,
               min: f64,
               max: f64,
               zero_ok: bool| {
        let v = match (v, default) {
            (Some(v), _) => v,
            (None, Some(d)) => return Ok(d),
            (None, None) => return Err(err(field, "is required for this kind of tool".into())),
        };
        let ok = v.is_finite() && v <= max && if zero_ok { v >= min } else { v > min };
        if ok {
            Ok(v)
        } else {
            let bound = if zero_ok {
                format!("at least {min}")
            } else {
                format!("greater than {min}")
            };
            Err(err(
                field,
                format!("= {v} must be {bound} and at most {max}"),
            ))
        }
    };
    let fields: [(&'static str, bool); 17] = [
        ("insert", raw.insert.is_some()),
        ("holder", raw.holder.is_some()),
        ("shank", raw.shank.is_some()),
        ("nose_radius", raw.nose_radius.is_some()),
        ("tip", raw.tip.is_some()),
        ("entering_angle", raw.entering_angle.is_some()),
        ("edge", raw.edge.is_some()),
        ("width", raw.width.is_some()),
        ("width_dir", raw.width_dir.is_some()),
        ("shank_dir", raw.shank_dir.is_some()),
        ("reach", raw.reach.is_some()),
        ("corner_radius", raw.corner_radius.is_some()),
        ("diameter", raw.diameter.is_some()),
        ("point_angle", raw.point_angle.is_some()),
        ("angle", raw.angle.is_some()),
        ("tip_flat", raw.tip_flat.is_some()),
        ("side", raw.side.is_some()),
    ];
    let allowed: &[&str] = match raw.kind.as_str() {
        "turning" => &[
            "insert",
            "holder",
            "shank",
            "nose_radius",
            "tip",
            "entering_angle",
            "edge",
        ],
        "grooving" => &[
            "width",
            "width_dir",
            "shank_dir",
            "reach",
            "corner_radius",
            "shank",
        ],
        "drill" => &["diameter", "point_angle", "reach"],
        "threading" => &["angle", "tip_flat", "side", "shank"],
        other => {
            return Err(err(
                "kind",
                format!("= \"{other}\" is not one of turning, grooving, drill, threading"),
            ));
        }
    };
    if let Some((field, _)) = fields.iter().find(|(f, set)| *set && !allowed.contains(f)) {
        return Err(err(field, format!("does not apply to a {} tool", raw.kind)));
    }
    let mut designation = None;
    let mut size = HolderSize::default();
    if matches!(raw.kind.as_str(), "grooving" | "drill") {
        // a blade's or a drill's holder starts where its stated reach ends
        size.declared = raw.reach.is_some();
    }
    if matches!(raw.kind.as_str(), "grooving" | "threading") {
        // the bar an ID blade or insert sits on (spec/simulation.md, "ID tools are
        // carried along Z"); an ID threading insert's bar is stated by its `shank`
        size.shank = raw
            .shank
            .map(|v| num("shank", Some(v), None, 0.0, 1000.0, false))
            .transpose()?;
        if raw.kind == "threading" {
            size.declared = size.shank.is_some();
        }
    }
    let tool = match raw.kind.as_str() {
        "turning" => {
            let iso = designated(raw).map_err(|(field, message)| err(field, message))?;
            let insert = match &raw.insert {
                _ if iso.is_some() => iso.as_ref().map_or(Insert::D, |d| d.insert),
                None => Insert::D,
                Some(s) => Insert::from_letter(s).ok_or_else(|| {
                    err(
                        "insert",
                        format!("= \"{s}\" is not an ISO shape letter (C, D, T, V, W, S, R)"),
                    )
                })?,
            };
            let tip = match raw.tip {
                // a holder's usual tip for its hand (an explicit `tip` wins: a rear post)
                None => iso.as_ref().and_then(|d| d.holder).map_or(3, |h| h.1),
                Some(v @ 0..=9) => v as u8,
                Some(v) => {
                    return Err(err(
                        "tip",
                        format!("= {v} is not an imaginary tip number (0-9)"),
                    ))
                }
            };
            let nose_radius = num(
                "nose_radius",
                raw.nose_radius,
                Some(iso.as_ref().map_or(0.4, |d| d.nose_radius)),
                0.0,
                100.0,
                insert != Insert::R,
            )?;
            let entering_angle = num(
                "entering_angle",
                raw.entering_angle,
                Some(iso.as_ref().and_then(|d| d.holder).map_or(93.0, |h| h.0)),
                0.0,
                180.0,
                false,
            )?;
            let edge = num(
                "edge",
                raw.edge,
                Some(iso.as_ref().map_or(11.0, |d| d.edge)),
                0.0,
                1000.0,
                false,
            )?;
            size = HolderSize {
                shank: match iso.as_ref().and_then(|d| d.size.shank) {
                    Some(s) => Some(s),
                    None => raw
                        .shank
                        .map(|v| num("shank", Some(v), None, 0.0, 1000.0, false))
                        .transpose()?,
                },
                length: iso.as_ref().and_then(|d| d.size.length),
                declared: false,
            };
            size.declared = size.shank.is_some();
            designation = iso.map(|d| d.text);
            if insert != Insert::R && entering_angle + insert.included_angle() >= 180.0 {
                return Err(err("entering_angle", format!("= {entering_angle}: with a {}° insert the trailing edge would point into the part", insert.included_angle())));
            }
            Tool::Turning {
                insert,
                nose_radius,
                tip,
                entering_angle,
                edge,
            }
        }
        "grooving" => {
            let dir = |field: &'static str, v: &Option<String>, d: AxisDir| match v {
                None => Ok(d),
                Some(s) => AxisDir::parse(s).ok_or_else(|| {
                    err(
                        field,
                        format!("= \"{s}\" is not one of \"+z\", \"-z\", \"+x\", \"-x\""),
                    )
                }),
            };
            let width = num("width", raw.width, Some(3.0), 0.0, 1000.0, false)?;
            let width_dir = dir("width_dir", &raw.width_dir, AxisDir::PlusZ)?;
            let default_shank = if width_dir.is_z() {
                AxisDir::PlusX
            } else {
                AxisDir::PlusZ
            };
            let shank_dir = dir("shank_dir", &raw.shank_dir, default_shank)?;
            if width_dir.is_z() == shank_dir.is_z() {
                return Err(err(
                    "shank_dir",
                    format!(
                        "= \"{}\" must be across the width direction \"{}\"",
                        shank_dir.text(),
                        width_dir.text()
                    ),
                ));
            }
            let reach = num("reach", raw.reach, Some(20.0), 0.0, 10000.0, false)?;
            let corner_radius = num(
                "corner_radius",
                raw.corner_radius,
                Some(0.0),
                0.0,
                width / 2.0,
                true,
            )?;
            Tool::Grooving(GroovingBlade {
                width,
                width_dir,
                shank_dir,
                reach,
                corner_radius,
            })
        }
        "drill" => Tool::Drill {
            diameter: num("diameter", raw.diameter, None, 0.0, 10000.0, false)?,
            point_angle: num(
                "point_angle",
                raw.point_angle,
                Some(118.0),
                0.0,
                180.0,
                false,
            )?,
            reach: num("reach", raw.reach, Some(60.0), 0.0, 10000.0, false)?,
        },
        _ => {
            let angle = num("angle", raw.angle, Some(60.0), 0.0, 170.0, false)?;
            let side = match raw.side.as_deref() {
                None | Some("od") => ThreadSide::Od,
                Some("id") => ThreadSide::Id,
                Some(other) => {
                    return Err(err(
                        "side",
                        format!("= \"{other}\" is not one of od, id (an OD insert cuts inward, an ID insert outward from the bore)"),
                    ))
                }
            };
            Tool::Threading {
                angle,
                tip_flat: num("tip_flat", raw.tip_flat, Some(0.0), 0.0, 100.0, true)?,
                side,
            }
        }
    };
    Ok((tool, designation, size))
}

#[cfg(test)]
mod tests {
    use super::super::ToolTable;
    use crate::StockError;

    #[test]
    fn bad_entries_name_tool_and_field() {
        let unknown = "[[tool]]\nt = 1\nkind = \"turning\"\nnose = 0.4\n";
        match ToolTable::from_toml(unknown) {
            Err(StockError::Toml { line, message, .. }) => {
                assert_eq!(line, 4);
                assert!(message.contains("nose"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        let cases = [
            ("kind = \"grooving\"\nwidth = -3.0", "width"),
            ("kind = \"turning\"\ntip = 10", "tip"),
            ("kind = \"turning\"\ninsert = \"Q\"", "insert"),
            ("kind = \"drill\"", "diameter"),
            ("kind = \"drill\"\ndiameter = 10.0\nwidth = 3.0", "width"),
            (
                "kind = \"grooving\"\nwidth_dir = \"+z\"\nshank_dir = \"-z\"",
                "shank_dir",
            ),
            ("kind = \"laser\"", "kind"),
            ("kind = \"threading\"\nside = \"inside\"", "side"),
            ("kind = \"turning\"\nside = \"id\"", "side"),
        ];
        for (body, field) in cases {
            let text = format!("[[tool]]\nt = 5\n{body}\n");
            match ToolTable::from_toml(&text) {
                Err(StockError::Tool {
                    t, field: f, line, ..
                }) => {
                    assert_eq!((t, f, line), (5, field, 1), "{body}");
                }
                other => panic!("{body}: {other:?}"),
            }
        }
    }

    #[test]
    fn threading_side() {
        use super::super::{ThreadSide, Tool};
        let side = |body: &str| {
            let t = ToolTable::from_toml(&format!("[[tool]]\nt = 4\nkind = \"threading\"\n{body}"))
                .unwrap();
            match t.get(4) {
                Some(&Tool::Threading { side, .. }) => side,
                other => panic!("{other:?}"),
            }
        };
        assert_eq!(side(""), ThreadSide::Od);
        assert_eq!(side("side = \"od\""), ThreadSide::Od);
        assert_eq!(side("side = \"id\""), ThreadSide::Id);
    }
}
