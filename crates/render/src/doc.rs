//! The SVG document under construction, built with the **svg** crate's element tree, and
//! its px-space drawing primitives (text, lines, rectangles, circles, clip paths, mm
//! paths, the crash marker). Every drawing module writes through it; it imports no drawing
//! module, so imports flow one way.
//!
//! Numbers are formatted here ([`num`]: fixed decimals, no `-0`), not by the svg crate.
//! Path data is in mm under a view transform and must keep sub-micron detail (a 0.25 mm
//! allowance on a Φ125 part, strokes 2 px wide at 10⁴ px/mm: up to nine decimals): the
//! crate's path `Data` holds one `f32` per coordinate (about seven significant digits,
//! 10 µm at 100 mm), and its `f64` values print every digit (`0.30000000000000004`,
//! larger files, no fixed decimals). So path `d` strings come from [`crate::path`] and
//! every value reaches the crate as text; the crate builds the element tree, nests the
//! groups, escapes text and attributes, and writes the document.

use svg::node::element::Element;
use svg::node::{Node, Text};

use crate::scale::View;
use crate::text::num;

/// An element's attributes, values already formatted.
pub(crate) type Attrs<'a> = &'a [(&'a str, String)];

/// An SVG document under construction: the root `<svg>` and the elements opened in it.
pub(crate) struct Doc {
    /// Open elements, the root first; drawing goes into the last.
    open: Vec<Element>,
}

/// A new element with these attributes.
fn element(name: &str, attrs: Attrs) -> Element {
    let mut el = Element::new(name);
    for (k, v) in attrs {
        el.assign(*k, v.as_str());
    }
    el
}

impl Doc {
    /// A document `w` × `h` px (user units = px) in `font_family`.
    pub(crate) fn new(w: f64, h: f64, font_family: &str) -> Self {
        let root = element(
            "svg",
            &[
                ("xmlns", "http://www.w3.org/2000/svg".into()),
                ("width", num(w, 2)),
                ("height", num(h, 2)),
                ("viewBox", format!("0 0 {} {}", num(w, 2), num(h, 2))),
                ("font-family", font_family.into()),
            ],
        );
        Self { open: vec![root] }
    }

    /// The finished document's markup.
    pub(crate) fn finish(mut self) -> String {
        while self.open.len() > 1 {
            self.close();
        }
        let mut out = self
            .open
            .pop()
            .map_or_else(String::new, |root| root.to_string());
        out.push('\n');
        out
    }

    fn add(&mut self, el: Element) {
        if let Some(parent) = self.open.last_mut() {
            parent.append(el);
        }
    }

    /// Open an element (a group, `defs`) that what is drawn next goes into, until
    /// [`Doc::close`].
    pub(crate) fn open(&mut self, name: &str, attrs: Attrs) {
        self.open.push(element(name, attrs));
    }

    /// Close the element last opened.
    pub(crate) fn close(&mut self) {
        if self.open.len() > 1 {
            if let Some(el) = self.open.pop() {
                self.add(el);
            }
        }
    }

    /// An element without children.
    pub(crate) fn leaf(&mut self, name: &str, attrs: Attrs) {
        self.add(element(name, attrs));
    }

    /// A text element with these attributes.
    pub(crate) fn text_el(&mut self, attrs: Attrs, s: &str) {
        let mut el = element("text", attrs);
        el.append(Text::new(s));
        self.add(el);
    }

    /// A text element; `anchor` is start, middle or end.
    pub(crate) fn text(&mut self, x: f64, y: f64, size: f64, anchor: &str, fill: &str, s: &str) {
        self.text_el(
            &[
                ("x", num(x, 2)),
                ("y", num(y, 2)),
                ("font-size", num(size, 1)),
                ("text-anchor", anchor.into()),
                ("fill", fill.into()),
            ],
            s,
        );
    }

    /// A px-space line, dashed when `dash` is not empty.
    pub(crate) fn line(&mut self, a: [f64; 2], b: [f64; 2], stroke: &str, w: f64, dash: &str) {
        let mut attrs = vec![
            ("x1", num(a[0], 2)),
            ("y1", num(a[1], 2)),
            ("x2", num(b[0], 2)),
            ("y2", num(b[1], 2)),
            ("stroke", stroke.into()),
            ("stroke-width", num(w, 2)),
        ];
        if !dash.is_empty() {
            attrs.push(("stroke-dasharray", dash.into()));
        }
        self.leaf("line", &attrs);
    }

    /// A px-space rectangle.
    pub(crate) fn rect(&mut self, r: [f64; 4], fill: &str, stroke: &str, w: f64) {
        let mut attrs = box_attrs(r);
        attrs.extend([
            ("fill", fill.into()),
            ("stroke", stroke.into()),
            ("stroke-width", num(w, 2)),
        ]);
        self.leaf("rect", &attrs);
    }

    /// A px-space circle.
    pub(crate) fn circle(&mut self, c: [f64; 2], r: f64, fill: &str, stroke: &str, w: f64) {
        self.leaf(
            "circle",
            &[
                ("cx", num(c[0], 2)),
                ("cy", num(c[1], 2)),
                ("r", num(r, 2)),
                ("fill", fill.into()),
                ("stroke", stroke.into()),
                ("stroke-width", num(w, 2)),
            ],
        );
    }

    /// A white, slightly see-through box with rounded corners `rx` under a label.
    pub(crate) fn label_box(&mut self, r: [f64; 4], rx: f64, opacity: f64, stroke: &str, w: f64) {
        let mut attrs = box_attrs(r);
        attrs.extend([
            ("rx", num(rx, 2)),
            ("fill", "#ffffff".into()),
            ("fill-opacity", num(opacity, 2)),
            ("stroke", stroke.into()),
            ("stroke-width", num(w, 2)),
        ]);
        self.leaf("rect", &attrs);
    }

    /// Define a rectangular clip path (in its own `defs`).
    pub(crate) fn clip(&mut self, id: &str, r: [f64; 4]) {
        self.open("defs", &[]);
        self.open("clipPath", &[("id", id.into())]);
        self.leaf("rect", &box_attrs(r));
        self.close();
        self.close();
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
        if !d.is_empty() {
            let attrs = path_attrs(v, d, fill, stroke, px_w, dash);
            self.leaf("path", &attrs);
        }
    }

    /// An unfilled mm path (a toolpath line) whose stroke is `opacity` opaque: a paint
    /// opacity, not a group's, which resvg would draw on a layer of its own and blend back.
    pub(crate) fn mm_line(
        &mut self,
        v: &View,
        d: &str,
        stroke: &str,
        px_w: f64,
        dash: &[f64],
        opacity: f64,
    ) {
        if !d.is_empty() {
            let mut attrs = path_attrs(v, d, "none", stroke, px_w, dash);
            attrs.push(("stroke-opacity", num(opacity, 2)));
            self.leaf("path", &attrs);
        }
    }

    /// Paints the page (`page`: its width and height, px) white outside the frame `r`: what
    /// a view drew past its frame is hidden as a clip path hides it on a white page, pixel
    /// for pixel when `r` lies on whole pixels. resvg draws a clipped group on a layer the
    /// size of what it holds and masks it: 10–15 ms of the PNG of a 55 ms run.
    pub(crate) fn matte(&mut self, r: [f64; 4], page: [f64; 2]) {
        let [x, y, w, h] = r.map(|c| num(c, 2));
        let [pw, ph] = page.map(|c| num(c, 2));
        self.leaf(
            "path",
            &[
                ("d", format!("M0 0H{pw}V{ph}H0Z M{x} {y}v{h}h{w}v-{h}Z")),
                ("fill", "#ffffff".into()),
                ("fill-rule", "evenodd".into()),
                ("stroke", "none".into()),
            ],
        );
    }
}

/// The attributes of an mm path `d` under the view `v`: widths and dashes given in px.
fn path_attrs(
    v: &View,
    d: &str,
    fill: &str,
    stroke: &str,
    px_w: f64,
    dash: &[f64],
) -> Vec<(&'static str, String)> {
    let mut attrs = vec![
        ("d", d.to_string()),
        ("fill", fill.into()),
        ("fill-rule", "evenodd".into()),
        ("stroke", stroke.into()),
        ("stroke-width", num(px_w / v.s, 9)),
        ("stroke-linejoin", "round".into()),
    ];
    if !dash.is_empty() {
        let ds: Vec<String> = dash.iter().map(|x| num(x / v.s, 9)).collect();
        attrs.push(("stroke-dasharray", ds.join(" ")));
    }
    attrs
}

/// The place and size of a px box `[x, y, w, h]` (a negative size is drawn as none).
fn box_attrs(r: [f64; 4]) -> Vec<(&'static str, String)> {
    vec![
        ("x", num(r[0], 2)),
        ("y", num(r[1], 2)),
        ("width", num(r[2].max(0.0), 2)),
        ("height", num(r[3].max(0.0), 2)),
    ]
}

/// A crash marker: a filled circle with a white cross.
pub(crate) fn marker(doc: &mut Doc, x: f64, y: f64, c: &str) {
    doc.circle([x, y], 7.0, c, "#ffffff", 1.2);
    doc.line([x - 3.5, y - 3.5], [x + 3.5, y + 3.5], "#ffffff", 1.6, "");
    doc.line([x - 3.5, y + 3.5], [x + 3.5, y - 3.5], "#ffffff", 1.6, "");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_nest_and_text_is_escaped() {
        let mut doc = Doc::new(10.0, 20.0, "DejaVu Sans");
        doc.open("g", &[("id", "a".into())]);
        doc.text(1.0, 2.0, 12.0, "start", "#000", "a < b & \"c\"");
        doc.line([0.0, 0.0], [1.0, 1.0], "#000", 1.0, "2 2");
        doc.close();
        doc.rect([0.0, 0.0, 1.0, -1.0], "none", "#000", 1.0);
        let s = doc.finish();
        assert!(s.starts_with(r#"<svg font-family="DejaVu Sans" height="20" viewBox="0 0 10 20" width="10" xmlns="http://www.w3.org/2000/svg">"#), "{s}");
        assert!(s.contains(">a &lt; b &amp; \"c\"</text>"), "{s}");
        assert!(s.contains(r#"stroke-dasharray="2 2""#));
        let g = s.find(r#"<g id="a">"#).unwrap();
        let end = s.find("</g>").unwrap();
        assert!(g < s.find("<text").unwrap() && s.find("<line").unwrap() < end);
        assert!(
            end < s.find("<rect").unwrap(),
            "the rect is after the group"
        );
        assert!(s.contains(r#"height="0""#), "negative sizes clamp");
        assert!(s.trim_end().ends_with("</svg>"));
    }
}
