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
    /// Whether a turning entry's tip is its holder's hand letter's (a holder, no `tip`).
    pub(super) tip_from_hand: bool,
    /// Whether an entry states the side it cuts on: a turning entry its tip (`tip`, or a
    /// holder whose hand gives it), a grooving entry its body's (`shank_dir`).
    pub(super) tip_stated: bool,
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
            tip_from_hand: raw.kind == "turning" && raw.holder.is_some() && raw.tip.is_none(),
            tip_stated: (raw.kind == "turning" && (raw.tip.is_some() || raw.holder.is_some()))
                || (raw.kind == "grooving" && raw.shank_dir.is_some()),
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

/// The checks of one `[[tool]]` record: errors name its number, the field and the line.
struct Check {
    t: u32,
    line: usize,
}

impl Check {
    fn err(&self, field: &'static str, message: String) -> StockError {
        StockError::Tool {
            t: self.t,
            field,
            message,
            line: self.line,
        }
    }

    /// A finite length or angle in `(min, max]` (`[min, max]` when `zero_ok`), or its
    /// default when not given (required when there is none).
    fn num(
        &self,
        field: &'static str,
        v: Option<f64>,
        default: Option<f64>,
        min: f64,
        max: f64,
        zero_ok: bool,
    ) -> Result<f64, StockError> {
        let v = match (v, default) {
            (Some(v), _) => v,
            (None, Some(d)) => return Ok(d),
            (None, None) => return Err(self.err(field, "is required for this kind of tool".into())),
        };
        let ok = v.is_finite() && v <= max && if zero_ok { v >= min } else { v > min };
        if ok {
            return Ok(v);
        }
        let bound = if zero_ok {
            format!("at least {min}")
        } else {
            format!("greater than {min}")
        };
        Err(self.err(field, format!("= {v} must be {bound} and at most {max}")))
    }

    /// A stated bar or shank size.
    fn shank(&self, v: Option<f64>) -> Result<Option<f64>, StockError> {
        v.map(|v| self.num("shank", Some(v), None, 0.0, 1000.0, false))
            .transpose()
    }
}

fn parse_tool(
    raw: &RawTool,
    line: usize,
) -> Result<(Tool, Option<String>, HolderSize), StockError> {
    let c = Check { t: raw.t, line };
    check_fields(raw, &c)?;
    let mut size = carried_size(raw, &c)?;
    let mut designation = None;
    let tool = match raw.kind.as_str() {
        "turning" => {
            let (tool, text, turning_size) = turning(raw, &c)?;
            designation = text;
            size = turning_size;
            tool
        }
        "grooving" => grooving(raw, &c)?,
        "drill" => Tool::Drill {
            diameter: c.num("diameter", raw.diameter, None, 0.0, 10000.0, false)?,
            point_angle: c.num(
                "point_angle",
                raw.point_angle,
                Some(118.0),
                0.0,
                180.0,
                false,
            )?,
            reach: c.num("reach", raw.reach, Some(60.0), 0.0, 10000.0, false)?,
        },
        _ => threading(raw, &c)?,
    };
    Ok((tool, designation, size))
}

/// The kind is known and only its own fields are given.
fn check_fields(raw: &RawTool, c: &Check) -> Result<(), StockError> {
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
            return Err(c.err(
                "kind",
                format!("= \"{other}\" is not one of turning, grooving, drill, threading"),
            ));
        }
    };
    match fields.iter().find(|(f, set)| *set && !allowed.contains(f)) {
        Some((field, _)) => Err(c.err(field, format!("does not apply to a {} tool", raw.kind))),
        None => Ok(()),
    }
}

/// What a blade, drill or threading insert says of its holder: a blade's or a drill's
/// holder starts where its stated reach ends; the bar an ID blade or insert sits on
/// (spec/simulation.md, "ID tools are carried along Z"), an ID threading insert's stated
/// by its `shank`.
fn carried_size(raw: &RawTool, c: &Check) -> Result<HolderSize, StockError> {
    let mut size = HolderSize::default();
    if matches!(raw.kind.as_str(), "grooving" | "drill") {
        size.declared = raw.reach.is_some();
    }
    if matches!(raw.kind.as_str(), "grooving" | "threading") {
        size.shank = c.shank(raw.shank)?;
        if raw.kind == "threading" {
            size.declared = size.shank.is_some();
        }
    }
    Ok(size)
}

/// A turning tool: its ISO designations first, then the fields that give or repeat them.
fn turning(raw: &RawTool, c: &Check) -> Result<(Tool, Option<String>, HolderSize), StockError> {
    let iso = designated(raw).map_err(|(field, message)| c.err(field, message))?;
    let insert = match &raw.insert {
        _ if iso.is_some() => iso.as_ref().map_or(Insert::D, |d| d.insert),
        None => Insert::D,
        Some(s) => Insert::from_letter(s).ok_or_else(|| {
            c.err(
                "insert",
                format!("= \"{s}\" is not an ISO shape letter (C, D, T, V, W, S, R)"),
            )
        })?,
    };
    let tip = match raw.tip {
        // a holder's usual tip for its hand (an explicit `tip` wins: a rear post)
        None => iso.as_ref().and_then(|d| d.holder).map_or(3, |h| h.1),
        Some(v @ 0..=9) => v as u8,
        Some(v) => return Err(c.err("tip", format!("= {v} is not an imaginary tip number (0-9)"))),
    };
    let nose_radius = c.num(
        "nose_radius",
        raw.nose_radius,
        Some(iso.as_ref().map_or(0.4, |d| d.nose_radius)),
        0.0,
        100.0,
        insert != Insert::R,
    )?;
    let entering_angle = c.num(
        "entering_angle",
        raw.entering_angle,
        Some(iso.as_ref().and_then(|d| d.holder).map_or(93.0, |h| h.0)),
        0.0,
        180.0,
        false,
    )?;
    let edge = c.num(
        "edge",
        raw.edge,
        Some(iso.as_ref().map_or(11.0, |d| d.edge)),
        0.0,
        1000.0,
        false,
    )?;
    let shank = match iso.as_ref().and_then(|d| d.size.shank) {
        Some(s) => Some(s),
        None => c.shank(raw.shank)?,
    };
    let size = HolderSize {
        shank,
        length: iso.as_ref().and_then(|d| d.size.length),
        declared: shank.is_some(),
    };
    if insert != Insert::R && entering_angle + insert.included_angle() >= 180.0 {
        return Err(c.err(
            "entering_angle",
            format!(
                "= {entering_angle}: with a {}° insert the trailing edge would point into the part",
                insert.included_angle()
            ),
        ));
    }
    let tool = Tool::Turning {
        insert,
        nose_radius,
        tip,
        entering_angle,
        edge,
    };
    Ok((tool, iso.map(|d| d.text), size))
}

/// A grooving blade: width, the directions of its width and shank (across each other),
/// reach and corner radius.
fn grooving(raw: &RawTool, c: &Check) -> Result<Tool, StockError> {
    let dir = |field: &'static str, v: &Option<String>, d: AxisDir| match v {
        None => Ok(d),
        Some(s) => AxisDir::parse(s).ok_or_else(|| {
            c.err(
                field,
                format!("= \"{s}\" is not one of \"+z\", \"-z\", \"+x\", \"-x\""),
            )
        }),
    };
    let width = c.num("width", raw.width, Some(3.0), 0.0, 1000.0, false)?;
    let width_dir = dir("width_dir", &raw.width_dir, AxisDir::PlusZ)?;
    let default_shank = if width_dir.is_z() {
        AxisDir::PlusX
    } else {
        AxisDir::PlusZ
    };
    let shank_dir = dir("shank_dir", &raw.shank_dir, default_shank)?;
    if width_dir.is_z() == shank_dir.is_z() {
        return Err(c.err(
            "shank_dir",
            format!(
                "= \"{}\" must be across the width direction \"{}\"",
                shank_dir.text(),
                width_dir.text()
            ),
        ));
    }
    let reach = c.num("reach", raw.reach, Some(20.0), 0.0, 10000.0, false)?;
    let corner_radius = c.num(
        "corner_radius",
        raw.corner_radius,
        Some(0.0),
        0.0,
        width / 2.0,
        true,
    )?;
    Ok(Tool::Grooving(GroovingBlade {
        width,
        width_dir,
        shank_dir,
        reach,
        corner_radius,
    }))
}

/// A threading insert: its included angle, tip flat and side.
fn threading(raw: &RawTool, c: &Check) -> Result<Tool, StockError> {
    let angle = c.num("angle", raw.angle, Some(60.0), 0.0, 170.0, false)?;
    let side = match raw.side.as_deref() {
        None | Some("od") => ThreadSide::Od,
        Some("id") => ThreadSide::Id,
        Some(other) => {
            return Err(c.err(
                "side",
                format!("= \"{other}\" is not one of od, id (an OD insert cuts inward, an ID insert outward from the bore)"),
            ))
        }
    };
    Ok(Tool::Threading {
        angle,
        tip_flat: c.num("tip_flat", raw.tip_flat, Some(0.0), 0.0, 100.0, true)?,
        side,
    })
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
