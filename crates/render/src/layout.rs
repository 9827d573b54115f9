//! Page layout (px, at the PNG scale: the SVG is 1600 × 1000 and rasterised 1:1), the
//! colours, and the choice of the main view window.

use crate::report::Report;
use crate::scale::Bbox;

/// Page width, px.
pub(crate) const W: f64 = 1600.0;
/// Page height, px.
pub(crate) const H: f64 = 1000.0;

/// The main plot rectangle (left, top, width, height).
pub(crate) const MAIN: [f64; 4] = [100.0, 64.0, 940.0, 776.0];
/// Left edge and width of the right column (detail views, title block).
pub(crate) const RIGHT_X: f64 = 1100.0;
/// Width of the right column.
pub(crate) const RIGHT_W: f64 = 484.0;
/// Top of the right column.
pub(crate) const RIGHT_TOP: f64 = 64.0;
/// Lowest baseline in the right column.
pub(crate) const RIGHT_BOTTOM: f64 = 984.0;
/// Baseline of the first legend row.
pub(crate) const LEGEND_Y: f64 = 930.0;

/// Font sizes, px.
pub(crate) const FS_TITLE: f64 = 18.0;
/// Tick labels.
pub(crate) const FS_TICK: f64 = 13.0;
/// Axis labels, legend, title block.
pub(crate) const FS_TEXT: f64 = 14.0;
/// Long lists (diagnostics) and detail titles.
pub(crate) const FS_SMALL: f64 = 13.0;
/// The verdict.
pub(crate) const FS_VERDICT: f64 = 16.0;

/// Colours.
pub(crate) mod colour {
    /// Blank fill (what was removed shows in it).
    pub(crate) const BLANK: &str = "#f2ede1";
    /// Blank outline.
    pub(crate) const BLANK_EDGE: &str = "#9b9283";
    /// Final part fill.
    pub(crate) const PART: &str = "#9db0c8";
    /// Final part outline.
    pub(crate) const PART_EDGE: &str = "#3f5570";
    /// Mirror (lower half) of the blank.
    pub(crate) const BLANK_MIRROR: &str = "#f7f5f0";
    /// Mirror of the final part.
    pub(crate) const PART_MIRROR: &str = "#d6dee9";
    /// Intended shape, dashed.
    pub(crate) const INTENDED: &str = "#1f6fe5";
    /// Feed moves.
    pub(crate) const FEED: &str = "#1a7f37";
    /// Rapid moves, dashed.
    pub(crate) const RAPID: &str = "#c9930a";
    /// Thread moves.
    pub(crate) const THREAD: &str = "#00838f";
    /// Gouges.
    pub(crate) const GOUGE: &str = "#d62728";
    /// Gouge outlines: a darker red, so a gouge thinner than a pixel still shows.
    pub(crate) const GOUGE_EDGE: &str = "#a31515";
    /// Leftovers.
    pub(crate) const LEFTOVER: &str = "#ff8c2a";
    /// Leftover outlines: a darker orange, so a thin band still shows.
    pub(crate) const LEFTOVER_EDGE: &str = "#d9650b";
    /// Crash markers.
    pub(crate) const CRASH: &str = "#7b3fe4";
    /// Rapid scrapes (a rapid re-cutting at most `rapid_cut_tol`): a warning, not a crash.
    pub(crate) const SCRAPE: &str = "#b26a00";
    /// Good verdict.
    pub(crate) const OK: &str = "#1a7f37";
    /// Bad verdict, alarms.
    pub(crate) const BAD: &str = "#c62828";
    /// Warnings.
    pub(crate) const WARN: &str = "#a15c00";
    /// Secondary text.
    pub(crate) const MUTED: &str = "#5f6b7a";
    /// Ordinary text.
    pub(crate) const INK: &str = "#1d232b";
    /// Workholding (chuck, jaws, tailstock centre): light grey, behind everything.
    pub(crate) const FIXTURE: &str = "#e4e6ea";
    /// Workholding outline.
    pub(crate) const FIXTURE_EDGE: &str = "#9aa1ab";
    /// Grid lines.
    pub(crate) const GRID: &str = "#e3e7ed";
}

/// The mm window of the main view before fitting: the part data, plus the toolpath where
/// it stays near the part (a far home position runs off the frame instead), made
/// symmetric about the axis for the mirror.
pub(crate) fn main_window(report: &Report) -> Bbox {
    let part = Bbox::of_shapes(&report.stock.shapes)
        .union(&Bbox::of_shapes(&report.final_part))
        .union(&Bbox::of_shapes(&report.intended));
    let mut tp = Bbox::of_path(&report.toolpath);
    let mut crashes = Bbox::EMPTY;
    for c in &report.crashes {
        crashes.add([c.z, c.r]);
    }
    // the workholding shows where it is near the part (the limit below clips the rest)
    for f in &report.fixture {
        tp = tp.union(&Bbox::of_shapes(&f.shapes));
    }
    let base = if part.is_empty() { tp } else { part };
    if base.is_empty() {
        return Bbox::new(-10.0, 10.0, -10.0, 10.0);
    }
    let size = base.w().max(base.h()).max(1.0);
    let limit = base.grow(0.25 * size);
    // every crash is in the picture (a jaw hit 20 mm above a Φ40 bar), unless absurdly far
    let crashes = crashes.intersect(&base.grow(size));
    let win = base
        .union(&tp)
        .intersect(&limit)
        .union(&crashes)
        .grow(0.04 * size);
    let r = win.rmax.abs().max(win.rmin.abs());
    Bbox::new(win.zmin, win.zmax, -r, r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::{PathKind, PathLine, Shape};

    #[test]
    fn far_toolpath_is_clipped_to_stock_margin() {
        let r = Report {
            stock: crate::report::StockInfo {
                description: String::new(),
                shapes: vec![Shape {
                    outer: vec![[-100.0, 0.0], [0.0, 0.0], [0.0, 25.0], [-100.0, 25.0]],
                    holes: vec![],
                }],
            },
            toolpath: vec![PathLine {
                kind: PathKind::Rapid,
                line: 1,
                points: vec![[200.0, 100.0], [2.0, 26.0]].into(),
            }],
            ..Report::default()
        };
        let w = main_window(&r);
        assert!(w.zmax < 40.0 && w.zmax > 2.0, "{w:?}");
        assert!(w.rmax < 55.0 && w.rmax > 26.0, "{w:?}");
        assert_eq!(w.rmin, -w.rmax);
    }

    /// A crash on a jaw 20 mm above a Φ40 × 60 bar (beyond the 25 % margin) is in the
    /// picture; one 1000 mm away is not.
    #[test]
    fn crashes_near_the_part_are_in_the_window() {
        let crash = |z: f64, r: f64| crate::report::Crash {
            line: 6,
            z,
            r,
            ..Default::default()
        };
        let mut r = Report {
            stock: crate::report::StockInfo {
                description: String::new(),
                shapes: vec![Shape {
                    outer: vec![[-59.0, 0.0], [1.0, 0.0], [1.0, 20.0], [-59.0, 20.0]],
                    holes: vec![],
                }],
            },
            crashes: vec![crash(-14.0, 40.0)],
            ..Report::default()
        };
        let w = main_window(&r);
        assert!(w.rmax > 40.0 && w.rmax < 45.0, "{w:?}");
        r.crashes = vec![crash(-14.0, 1000.0)];
        let w = main_window(&r);
        assert!(w.rmax < 85.0, "{w:?}");
    }

    #[test]
    fn empty_report_has_a_window() {
        let w = main_window(&Report::default());
        assert!(!w.is_empty());
    }
}
