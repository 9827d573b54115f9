//! The SVG document under construction and its px-space drawing primitives (text,
//! lines, rectangles, clip paths, mm paths, the crash marker). Every drawing module
//! writes through it; it imports no drawing module, so imports flow one way.

use std::fmt::Write as _;

use crate::scale::View;
use crate::text::{esc, num};

/// An SVG document under construction, with px-space helpers.
pub(crate) struct Doc {
    /// The markup so far.
    pub(crate) out: String,
}

impl Doc {
    /// Append raw markup.
    pub(crate) fn raw(&mut self, s: &str) {
        self.out.push_str(s);
    }

    /// A text element; `anchor` is start, middle or end.
    pub(crate) fn text(&mut self, x: f64, y: f64, size: f64, anchor: &str, fill: &str, s: &str) {
        let _ = writeln!(
            self.out,
            r#"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}" fill="{fill}">{}</text>"#,
            num(x, 2),
            num(y, 2),
            num(size, 1),
            esc(s)
        );
    }

    /// A px-space line.
    pub(crate) fn line(&mut self, a: [f64; 2], b: [f64; 2], stroke: &str, w: f64, extra: &str) {
        let _ = writeln!(
            self.out,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{stroke}" stroke-width="{}" {extra}/>"#,
            num(a[0], 2),
            num(a[1], 2),
            num(b[0], 2),
            num(b[1], 2),
            num(w, 2)
        );
    }

    /// A px-space rectangle.
    pub(crate) fn rect(&mut self, r: [f64; 4], fill: &str, stroke: &str, w: f64) {
        let _ = writeln!(
            self.out,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{fill}" stroke="{stroke}" stroke-width="{}"/>"#,
            num(r[0], 2),
            num(r[1], 2),
            num(r[2].max(0.0), 2),
            num(r[3].max(0.0), 2),
            num(w, 2)
        );
    }

    /// Define a rectangular clip path.
    pub(crate) fn clip(&mut self, id: &str, r: [f64; 4]) {
        let _ = writeln!(
            self.out,
            r#"<clipPath id="{id}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>"#,
            num(r[0], 2),
            num(r[1], 2),
            num(r[2], 2),
            num(r[3], 2)
        );
    }

    /// A path in mm inside a view transform; widths and dashes are given in px and
    /// converted so they look the same at any scale.
    pub(crate) fn mm_path(
        &mut self,
        v: &View,
        d: &str,
        fill: &str,
        stroke: &str,
        px_w: f64,
        dash: &[f64],
    ) {
        if d.is_empty() {
            return;
        }
        let _ = write!(
            self.out,
            r#"<path d="{d}" fill="{fill}" fill-rule="evenodd" stroke="{stroke}" stroke-width="{}" stroke-linejoin="round""#,
            num(px_w / v.s, 9)
        );
        if !dash.is_empty() {
            let ds: Vec<String> = dash.iter().map(|x| num(x / v.s, 9)).collect();
            let _ = write!(self.out, r#" stroke-dasharray="{}""#, ds.join(" "));
        }
        self.out.push_str("/>\n");
    }
}

/// A crash marker: a filled circle with a white cross.
pub(crate) fn marker(doc: &mut Doc, x: f64, y: f64, c: &str) {
    let _ = writeln!(
        doc.out,
        r##"<circle cx="{}" cy="{}" r="7" fill="{c}" stroke="#ffffff" stroke-width="1.2"/>"##,
        num(x, 2),
        num(y, 2)
    );
    doc.line([x - 3.5, y - 3.5], [x + 3.5, y + 3.5], "#ffffff", 1.6, "");
    doc.line([x - 3.5, y + 3.5], [x + 3.5, y - 3.5], "#ffffff", 1.6, "");
}
