//! Non-cutting bodies: what holds each tool's cutting outline (the holder head and shank, a
//! boring bar, a blade's holder, a drill's holder). A body never removes material; a body
//! touching stock, at any speed, is a crash (`crate::removal`).
//!
//! Placement, in the tool's own frame (the reference point at the origin, as the cutting
//! outline; spec/simulation.md "Tools"), chosen so that the body never reaches where the
//! cutting outline works:
//! - **turning, OD** (tips 3, 4, 0, 9, 5, 7, 8): a shank of width `b` (holder designation's
//!   shank width, else the `shank` field, else [`DEFAULT_SHANK`]) starting [`BODY_GAP`]
//!   above the top of the insert outline and running [`DEFAULT_LENGTH`] (or the
//!   designation's length) toward +X; in Z it starts [`BODY_GAP`] behind the cutting
//!   corner on the side away from the cutting direction (tips 3, 0, 9, 7: toward +Z; tips
//!   4, 5: toward −Z; tip 8: centred);
//! - **turning, ID** (tips 2, 1, 6): a boring bar of diameter `d` (bar designation, else
//!   `shank`, else [`DEFAULT_SHANK`]) along +Z, starting [`BODY_GAP`] behind the insert
//!   outline, its top [`BAR_OFFSET`] below the cutting corner (f = d/2 + 3);
//! - **grooving**, OD and face: beyond `reach` along the shank direction, the holder: the
//!   blade's width plus [`BLADE_HOLDER_SIDE`] on each side, [`DEFAULT_LENGTH`] long (a
//!   blade sent deeper than its reach crashes its holder);
//! - **grooving, ID** (`shank_dir = "-x"`): spec/simulation.md, "ID tools are carried along
//!   Z": the blade projects `reach` from the top of a bar of diameter `shank` (else
//!   [`DEFAULT_BAR`]) that runs under it along +Z, out of the bore's mouth, never across the
//!   axis;
//! - **drill**: beyond `reach` (the flutes) along +Z, the drill's holder, Ø diameter +
//!   2 × [`DRILL_HOLDER_SIDE`], [`DEFAULT_LENGTH`] long;
//! - **threading**, OD: a shank like the OD turning holder's, above the insert and toward
//!   +Z from the insert's chuck-side flank; ID (`side = "id"`): the insert on a bar of
//!   diameter `shank` (else [`DEFAULT_BAR`]) along +Z under it, like an ID blade.

use super::{Tool, ToolTable};
use crate::outline::Outline;
use crate::outline::PastAxis;
use expander::ToolHint;

/// Shank width (OD holders) or bar diameter (boring bars) without a designation, mm.
pub(crate) const DEFAULT_SHANK: f64 = 20.0;
/// Diameter of the bar an ID blade or an ID threading insert sits on when the table gives
/// no `shank`, mm (spec/simulation.md, "ID tools are carried along Z").
pub(crate) const DEFAULT_BAR: f64 = 16.0;
/// Length of a body without a designation's length, mm.
pub(crate) const DEFAULT_LENGTH: f64 = 100.0;
/// Clearance between the cutting outline and the body, mm.
pub(crate) const BODY_GAP: f64 = 2.0;
/// A boring bar's top lies this far below the cutting corner, mm.
pub(crate) const BAR_OFFSET: f64 = 3.0;
/// A blade holder is wider than its blade by this much on each side, mm.
pub(crate) const BLADE_HOLDER_SIDE: f64 = 2.0;
/// A drill holder is wider than its drill by this much on each side (radius), mm.
pub(crate) const DRILL_HOLDER_SIDE: f64 = 10.0;

/// What the holder of a turning tool is known to measure: from its designation (`PCLNR
/// 2525M12`: shank width 25, length 150) or the `shank` field.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HolderSize {
    /// Shank width (OD) or bar diameter (ID), mm.
    pub shank: Option<f64>,
    /// Overall length, mm.
    pub length: Option<f64>,
    /// The table states what places the body (a holder designation or `shank` for a
    /// turning tool, `reach` for a blade or a drill). **Interpretation:** only then is the
    /// body probed: a body placed by defaults alone would call crashes on programs whose
    /// tools are simply not described (a part-off blade deeper than a default reach).
    pub declared: bool,
}

/// A tool's non-cutting body: its outline (convex parts, in the cutting outline's frame)
/// and the name a crash gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Convex parts relative to the reference point.
    pub outline: Outline,
    /// "holder", "boring bar", "blade holder", "drill holder".
    pub name: &'static str,
}

/// The bar an ID tool sits on: its top at `top` (relative to the reference point), `d`
/// thick toward the axis, from the cutting outline's left end (`lo`, `hi`: its box) along
/// +Z for `length` past its right end.
fn bar_under(lo: [f64; 2], hi: [f64; 2], top: f64, d: f64, length: f64) -> Outline {
    rect(lo[0], hi[0] + length, top - d, top)
}

fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Outline {
    Outline {
        parts: vec![vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]]],
        past_axis: PastAxis::Fold,
    }
}

impl Tool {
    /// The non-cutting body (see the module documentation for its placement).
    pub fn body(&self, size: HolderSize) -> Body {
        let cut = self.outline();
        let (lo, hi) = cut.bbox().unwrap_or(([0.0, 0.0], [0.0, 0.0]));
        let shank = size.shank.unwrap_or(DEFAULT_SHANK);
        let length = size.length.unwrap_or(DEFAULT_LENGTH);
        let g = BODY_GAP;
        match *self {
            Self::Turning { tip: 1 | 2 | 6, .. } => Body {
                outline: rect(
                    hi[0] + g,
                    hi[0] + g + length,
                    -BAR_OFFSET - shank,
                    -BAR_OFFSET,
                ),
                name: "boring bar",
            },
            Self::Turning { tip, .. } => {
                let (z0, z1) = match tip {
                    4 | 5 => (-g - shank, -g),
                    8 => (-shank / 2.0, shank / 2.0),
                    _ => (g, g + shank),
                };
                Body {
                    outline: rect(z0, z1, hi[1] + g, hi[1] + g + length),
                    name: "holder",
                }
            }
            Self::Grooving(b) if b.shank_dir == super::AxisDir::MinusX => Body {
                outline: bar_under(lo, hi, -b.reach, size.shank.unwrap_or(DEFAULT_BAR), length),
                name: "boring bar",
            },
            Self::Threading {
                side: super::ThreadSide::Id,
                ..
            } => Body {
                outline: bar_under(lo, hi, lo[1], size.shank.unwrap_or(DEFAULT_BAR), length),
                name: "boring bar",
            },
            Self::Grooving(b) => {
                let (w, s) = (b.width_dir.unit(), b.shank_dir.unit());
                let corners = [
                    [-BLADE_HOLDER_SIDE, b.reach],
                    [b.width + BLADE_HOLDER_SIDE, b.reach],
                    [b.width + BLADE_HOLDER_SIDE, b.reach + DEFAULT_LENGTH],
                    [-BLADE_HOLDER_SIDE, b.reach + DEFAULT_LENGTH],
                ];
                let pts: Vec<[f64; 2]> = corners
                    .iter()
                    .map(|&[a, c]| [a * w[0] + c * s[0], a * w[1] + c * s[1]])
                    .collect();
                Body {
                    outline: Outline {
                        parts: vec![geom::flat::convex_hull(&pts)],
                        past_axis: PastAxis::Fold,
                    },
                    name: "blade holder",
                }
            }
            Self::Drill {
                diameter, reach, ..
            } => {
                let half = diameter / 2.0 + DRILL_HOLDER_SIDE;
                Body {
                    outline: rect(reach, reach + DEFAULT_LENGTH, -half, half),
                    name: "drill holder",
                }
            }
            Self::Threading { .. } => Body {
                outline: rect(lo[0], lo[0] + shank, hi[1] + g, hi[1] + g + length),
                name: "holder",
            },
        }
    }
}

impl ToolTable {
    /// The body of the tool that cuts for tool `t` under `hint` (the one
    /// [`ToolTable::outline_for`] outlines), when the table declares it (see
    /// [`HolderSize::declared`]); a defaulted tool has none.
    pub fn body_for(&self, t: u32, hint: ToolHint) -> Option<Body> {
        let t_table = if t == 0 {
            self.numbers().first().copied().unwrap_or(0)
        } else {
            t
        };
        let size = self
            .sizes
            .iter()
            .find(|(n, _)| *n == t_table)
            .map(|(_, s)| *s)
            .unwrap_or_default();
        let (tool, defaulted) = self.resolve(t, hint);
        (size.declared && defaulted.is_none()).then(|| tool.body(size))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Insert;

    fn bbox(b: &Body) -> ([f64; 2], [f64; 2]) {
        b.outline.bbox().unwrap()
    }

    #[test]
    fn od_holder_sits_above_the_insert_toward_plus_z() {
        let t = Tool::Turning {
            insert: Insert::C,
            nose_radius: 0.0,
            tip: 3,
            entering_angle: 95.0,
            edge: 10.0,
        };
        // a sharp C insert on 95°: edges at 85° and 5° from +Z, 10 mm; the far corner is
        // at 10 (sin 85° + sin 5°) = 10.834 above the tip
        let top = 10.0 * (85f64.to_radians().sin() + 5f64.to_radians().sin());
        let b = t.body(HolderSize {
            shank: Some(25.0),
            length: Some(150.0),
            declared: true,
        });
        assert_eq!(b.name, "holder");
        let (lo, hi) = bbox(&b);
        assert!((lo[0] - 2.0).abs() < 1e-9 && (hi[0] - 27.0).abs() < 1e-9);
        assert!((lo[1] - (top + 2.0)).abs() < 1e-9, "{lo:?}");
        assert!((hi[1] - (top + 152.0)).abs() < 1e-9, "{hi:?}");
    }

    #[test]
    fn boring_bar_runs_plus_z_below_the_tip() {
        let t = Tool::Turning {
            insert: Insert::C,
            nose_radius: 0.0,
            tip: 2,
            entering_angle: 95.0,
            edge: 10.0,
        };
        let b = t.body(HolderSize {
            shank: Some(20.0),
            length: None,
            declared: true,
        });
        assert_eq!(b.name, "boring bar");
        let (lo, hi) = bbox(&b);
        // the insert reaches 10 (cos 5° + cos 85°) = 10.834 along +Z
        let front = 10.0 * (5f64.to_radians().cos() + 85f64.to_radians().cos());
        assert!((lo[0] - (front + 2.0)).abs() < 1e-9, "{lo:?}");
        assert!((hi[0] - lo[0] - 100.0).abs() < 1e-9);
        assert_eq!((lo[1], hi[1]), (-23.0, -3.0));
    }

    #[test]
    fn blade_holder_begins_at_the_reach() {
        let b = Tool::DEFAULT_BLADE.body(HolderSize::default());
        assert_eq!(b.name, "blade holder");
        assert_eq!(bbox(&b), ([-2.0, 20.0], [5.0, 120.0]));
        let d = Tool::Drill {
            diameter: 10.0,
            point_angle: 118.0,
            reach: 60.0,
        }
        .body(HolderSize::default());
        assert_eq!(bbox(&d), ([60.0, -15.0], [160.0, 15.0]));
    }
}
