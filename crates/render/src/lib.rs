//! Report -> SVG, PNG, JSON and a self-contained HTML page.
//!
//! The picture is a 1600 × 1000 px SVG (user units = px), rasterised 1:1 into a
//! 1600 × 1000 PNG. Coordinates inside the SVG are mm under a view transform, so path
//! data keeps sub-micron detail; the toolpath is thinned to what the picture can show.
//!
//! The JSON is a stable contract in program coordinates (`z`, `x` = diameter):
//! `program`, `title`, `verdict`, `stock`, `final`, `removed_area_mm2`,
//! `removed_volume_mm3`, `segments`, `cycle_time_s`, `tolerance_mm`, `tools`, `alarms`,
//! `warnings`, `crashes`, `gouges`, `deviation`, and `grooves` (`[{"line": n, "ring":
//! [[z, x], …]}]`, the G75.1 grooves of [`Report::grooves`]), `variables` (`[{"name":
//! "#1", "value": 14.0}]`, custom macro B's variables at the end, `null` when vacant) and
//! `line_counts` (`[{"line": n, "count": k}]`, lines run more than once). Numbers are rounded to 6
//! decimals; non-finite numbers are written as `null`.
//!
//! The picture's right column holds zoomed detail views of each crash, gouge and groove,
//! then of the largest leftover (at most three, findings first) above the title block.
//! Gouges and leftovers are filled and outlined 2 px wide whatever the scale, so a band
//! thinner than a pixel still shows.
//!
//! The HTML page ([`html`]) is self-contained: the same SVG inline, the tables, and a
//! move slider drawing on a `<canvas>` from a compact JSON block embedded in the page.
mod block;
mod detail;
mod diff;
mod doc;
mod fixture;
mod fonts;
mod groove;
mod html;
mod json;
mod layout;
mod marks;
mod path;
mod plot;
mod png;
mod report;
mod scale;
mod svg;
mod text;

pub use diff::{
    diff_html, diff_json, diff_png, diff_svg, DiffFinding, DiffRegion, DiffReport, ToolTime,
};
pub use report::*;

/// Width of the SVG and PNG, px.
pub const WIDTH_PX: u32 = layout::W as u32;
/// Height of the SVG and PNG, px.
pub const HEIGHT_PX: u32 = layout::H as u32;

/// Why a PNG could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The generated SVG did not parse (a bug in this crate).
    #[error("internal SVG error: {0}")]
    Svg(String),
    /// The pixmap could not be allocated.
    #[error("cannot allocate a {0} × {1} pixmap")]
    Size(u32, u32),
    /// PNG encoding failed.
    #[error("PNG encoding failed: {0}")]
    Encode(String),
}

/// The full report picture as an SVG document (1600 × 1000 px).
pub fn svg(report: &Report) -> String {
    svg::svg(report)
}

/// The same picture rasterised (anti-aliased, embedded `DejaVu Sans` and a CJK subset), as PNG bytes of
/// 1600 × 1000 px. Deterministic: the same report gives the same bytes.
pub fn png(report: &Report) -> Result<Vec<u8>, RenderError> {
    Picture::draw(report).png()
}

/// The report picture drawn once for the SVG, the PNG and the HTML page that all show it:
/// drawing a million-move toolpath was a quarter of a run writing all three.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture(String);

impl Picture {
    /// Draw the report picture.
    pub fn draw(report: &Report) -> Self {
        Self(svg::svg(report))
    }

    /// The picture as an SVG document: [`svg`].
    pub fn svg(&self) -> &str {
        &self.0
    }

    /// The picture as PNG bytes: [`png`].
    pub fn png(&self) -> Result<Vec<u8>, RenderError> {
        png::rasterise(&self.0)
    }

    /// The HTML page of `report`, the report this picture was drawn from: [`html`].
    pub fn html(&self, report: &Report) -> String {
        html::html(report, &self.0)
    }

    /// The same page from its data block worked out beforehand ([`HtmlData::of`], on
    /// another thread while the picture is drawn).
    pub fn html_with(&self, report: &Report, data: HtmlData) -> String {
        html::page(report, &self.0, data.0)
    }
}

/// The HTML page's data for its move slider (the toolpath, the stock snapshots, the
/// layers), which needs no picture: for a long program most of the page's work, so a
/// caller can work it out while the picture is drawn ([`Picture::html_with`]).
pub struct HtmlData(html::Data);

impl HtmlData {
    /// The data of `report`'s page.
    pub fn of(report: &Report) -> Self {
        Self(html::Data::of(report))
    }
}

/// The report as one self-contained HTML page (no network, no external files; works
/// from `file://`): the report picture as inline SVG, the summary and findings tables,
/// and a move slider that replays the toolpath over the stock (using
/// [`Report::snapshots`] when present). Deterministic; bounded in size for any toolpath
/// (the embedded path is thinned to about 200 000 points, and the page says so).
pub fn html(report: &Report) -> String {
    Picture::draw(report).html(report)
}

/// The machine-readable report as pretty JSON (see the crate docs for the fields).
pub fn json(report: &Report) -> String {
    json::json(report)
}

/// The JSON word of a verdict: `clean`, `alarm`, `crash` or `gouge`.
pub fn verdict_word(v: Verdict) -> &'static str {
    json::verdict_word(v)
}
