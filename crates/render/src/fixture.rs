//! The workholding (chuck body, jaws, tailstock centre: light grey, labelled) and the tool
//! drawn where it crashed (outline only, in the crash colour), so a machinist sees what met
//! what. Nothing is drawn when the report has neither.

use crate::doc::Doc;
use crate::layout::{colour, FS_SMALL};
use crate::path::shapes_d;
use crate::report::{Report, Shape};
use crate::scale::{Bbox, View};

use colour::{FIXTURE as FILL, FIXTURE_EDGE as EDGE};

/// The workholding's mirror (lower half), lighter still.
const FILL_MIRROR: &str = "#eff0f2";
/// Label colour.
const LABEL: &str = "#6b7380";

/// The workholding in mm under the view's transform (and its mirror below the axis).
pub(crate) fn draw_fixture(doc: &mut Doc, report: &Report, v: &View, mirror: bool) {
    if report.fixture.is_empty() {
        return;
    }
    let md = crate::path::MIN_PX / v.s;
    let all: Vec<Shape> = report
        .fixture
        .iter()
        .flat_map(|f| f.shapes.iter().cloned())
        .collect();
    let d = shapes_d(&all, md);
    if mirror {
        doc.open(
            "g",
            &[
                ("class", "fixture-mirror".into()),
                ("transform", v.transform(true)),
            ],
        );
        doc.mm_path(v, &d, FILL_MIRROR, EDGE, 0.8, &[]);
        doc.close();
    }
    doc.open(
        "g",
        &[
            ("class", "fixture".into()),
            ("transform", v.transform(false)),
        ],
    );
    doc.mm_path(v, &d, FILL, EDGE, 1.0, &[]);
    doc.close();
}

/// The labels of the workholding (main view only): each name at the middle of the part of
/// it that shows, when that part is wide enough for the text.
pub(crate) fn label_fixture(doc: &mut Doc, report: &Report, v: &View) {
    for f in &report.fixture {
        let b = Bbox::of_shapes(&f.shapes).intersect(&v.mm);
        if b.is_empty() {
            continue;
        }
        let (x0, x1) = (v.x(b.zmin), v.x(b.zmax));
        let (y0, y1) = (v.y(b.rmax), v.y(b.rmin));
        let w = crate::text::width(&f.name, FS_SMALL);
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        // "tailstock centre (retracted)" may go on two lines, split before the bracket
        let two = f.name.split_once(" (").map(|(a, b)| (a, format!("({b}")));
        let two_w = two.as_ref().map_or(f64::INFINITY, |(a, b)| {
            crate::text::width(a, FS_SMALL).max(crate::text::width(b, FS_SMALL))
        });
        if x1 - x0 >= w + 4.0 && y1 - y0 >= FS_SMALL + 2.0 {
            doc.text(cx, cy + FS_SMALL * 0.35, FS_SMALL, "middle", LABEL, &f.name);
        } else if x1 - x0 >= two_w + 4.0 && y1 - y0 >= 2.4 * FS_SMALL + 2.0 {
            let (a, b) = two.as_ref().expect("a finite width");
            doc.text(cx, cy - FS_SMALL * 0.25, FS_SMALL, "middle", LABEL, a);
            doc.text(cx, cy + FS_SMALL * 0.95, FS_SMALL, "middle", LABEL, b);
        } else if y1 - y0 >= w + 4.0 && x1 - x0 >= FS_SMALL + 2.0 {
            // a tall narrow part (a jaw seen small): the name runs upward
            doc.text_el(
                &[
                    ("x", "0".into()),
                    ("y", "0".into()),
                    ("font-size", crate::text::num(FS_SMALL, 1)),
                    ("text-anchor", "middle".into()),
                    ("fill", LABEL.into()),
                    (
                        "transform",
                        format!(
                            "translate({} {}) rotate(-90)",
                            crate::text::num(cx + FS_SMALL * 0.35, 2),
                            crate::text::num(cy, 2)
                        ),
                    ),
                ],
                &f.name,
            );
        }
    }
}

/// The outline of the tool (cutting outline and body) at each crash, in the crash colour.
pub(crate) fn draw_crash_tools(doc: &mut Doc, report: &Report, v: &View) {
    if report.crashes.iter().all(|c| c.tool.is_empty()) {
        return;
    }
    let mut d = String::new();
    for part in report.crashes.iter().flat_map(|c| c.tool.iter()) {
        d.push_str(&shapes_d(
            &[Shape {
                outer: part.clone(),
                holes: Vec::new(),
            }],
            0.0,
        ));
    }
    doc.open(
        "g",
        &[
            ("class", "crash-tool".into()),
            ("transform", v.transform(false)),
        ],
    );
    doc.mm_path(v, &d, "none", colour::CRASH, 1.6, &[]);
    doc.close();
}
