//! The intended part: what the part should be, and where each statement holds
//! (spec/simulation.md, "The intended shape"). An intent comes from a `--target` drawing, a
//! G75.1 groove, a G70–G73 finishing shape or a contour cut under G41/G42 ([`program`]
//! reads the program's own).

mod contact;
pub(crate) mod program;

use contact::in_contact;
use geom::flat::{pts, P};
use geom::Rect;
use stock::{boolean, BoolOp, Shape};

/// What the part should be, and where that statement holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Intent {
    /// The intended part material.
    pub part: Vec<Shape>,
    /// Where the comparison applies (a G75.1 groove's box, a finishing shape's Z span);
    /// outside it the program may do what it likes.
    pub zone: Vec<Shape>,
    /// The intended boundary as drawn in the report: (points, closed ring or open path).
    pub outline: Vec<(Vec<[f64; 2]>, bool)>,
    /// For a contour the program cuts: who cuts it. What feed moves of another tool that
    /// makes features cut inside its zone once it began is that operation's own (a groove
    /// in a finished diameter, a drilled core, a thread relief): no gouge of this contour
    /// (**Interpretation**, [`Deviation::later_cuts`]). `None` (a `--target` drawing, a
    /// G75.1 groove): every cut is judged.
    pub owner: Option<Owner>,
}

/// Who cuts a contour the program defines, and from when.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Owner {
    /// The tool that finishes it (a G70's, not its G71's).
    pub tool: u32,
    /// The index of the first move of the first cycle that ran the shape (its G71's, before
    /// its G70): the contour began there.
    pub began: usize,
    /// The index of the first move of the cycle that finishes it.
    pub finish: usize,
    /// Cut under G41/G42 (its first move, `finish`, is the compensation's start-up): how.
    pub comp: Option<Comp>,
}

/// How a contour cut under G41/G42 was compensated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Comp {
    /// The code the program wrote: G42 keeps the part on the left of the path.
    pub part_on_left: bool,
    /// The tool's stated tip puts the part on the other side (LS-COMP-SIDE): the nose is
    /// offset into the part.
    pub wrong_side: bool,
}

impl Comp {
    /// The code the program wrote and the one its tool needs.
    pub fn codes(self) -> (&'static str, &'static str) {
        if self.part_on_left {
            ("G42", "G41")
        } else {
            ("G41", "G42")
        }
    }
}

/// The stock a contour the program cuts is read against ([`Intent::finishing`],
/// [`Intent::compensated`]): as it stood when the contour's cycle began, the part the run
/// finished with, and the blank.
#[derive(Debug, Clone, Copy)]
pub struct Stages<'a> {
    /// The stock when the contour's cycle began.
    pub began: &'a [Shape],
    /// The part at the end of the run.
    pub finished: &'a [Shape],
    /// The blank.
    pub blank: &'a [Shape],
}

/// The side toward which an open intended path is closed: where the part lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Toward {
    MinusR,
    PlusR,
    MinusZ,
    PlusZ,
}

/// Half the size of the world a zone or a closing edge may reach, mm.
pub(crate) const FAR: f64 = 1e5;

pub(crate) fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
    Shape {
        outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
        holes: vec![],
    }
}

impl Intent {
    /// `--target`: the whole intended part, compared everywhere.
    pub fn target(part: Vec<Shape>) -> Self {
        let outline = part
            .iter()
            .flat_map(|s| std::iter::once(s.outer.clone()).chain(s.holes.iter().cloned()))
            .map(|ring| (ring, true))
            .collect();
        Self {
            part,
            zone: vec![rect(-FAR, FAR, -FAR, FAR)],
            outline,
            owner: None,
        }
    }

    /// A G75.1 groove (a closed ring of material that must go): compared within the
    /// groove's bounding box grown along Z by the groove's depth on both sides (a groove cut
    /// a blade width off, or a flank gouged, shows there), where everything but the groove
    /// must stay. Material above the mouth is not the groove's business.
    pub fn groove(ring: &[[f64; 2]]) -> Self {
        let (lo, hi) = bbox(ring);
        let grow = (hi[1] - lo[1]).max(1.0);
        let zone = vec![rect(lo[0] - grow, hi[0] + grow, lo[1] - grow, hi[1])];
        let groove = boolean(
            &[Shape {
                outer: ring.to_vec(),
                holes: vec![],
            }],
            &[],
            BoolOp::Union,
        );
        Self {
            part: boolean(&zone, &groove, BoolOp::Difference),
            zone,
            outline: vec![(ring.to_vec(), true)],
            owner: None,
        }
    }

    /// A G70–G73 finishing shape: `path[0]` is the start point A, `path[1..]` the shape
    /// B..C. The part lies on the side away from A (spec): below the shape when A is above
    /// it (OD), above it when A is below (ID), left of it when A is to its right (facing).
    /// The comparison is limited to the shape's Z span (its X span for facing).
    ///
    /// Only the profile bounds the part (spec, "The intended shape"): what the shape runs
    /// through before it first touches the stock when the cycle began, and after it last
    /// leaves it, is approach and retract, and so is a lead-in in front of the finished
    /// part's face ([`in_contact`]).
    pub fn finishing(path: &[[f64; 2]], stages: &Stages) -> Option<Self> {
        let (a, shape) = path.split_first()?;
        let (lo, hi) = bbox(shape);
        // the shape's first move from A says the side (an OD shape goes in from A, an ID one
        // out), whatever its exit does: an OD shape that leaves above A (`N20 X52.` from a
        // start at X50) was read as a face and kept nothing of the OD (field run 6, A)
        let first = shape.first()?;
        let toward = if first[1] < a[1] - 1e-9 {
            Toward::MinusR
        } else if first[1] > a[1] + 1e-9 {
            Toward::PlusR
        } else if a[1] >= hi[1] - 1e-9 {
            Toward::MinusR
        } else if a[1] <= lo[1] + 1e-9 {
            Toward::PlusR
        } else if a[0] >= hi[0] - 1e-9 {
            Toward::MinusZ
        } else {
            return None;
        };
        Self::open_path(&in_contact(shape, stages), toward, None)
    }

    /// A contour cut under G41/G42: the part lies on the side of the path away from the
    /// tool (`part_on_left` of the direction of travel for G42). The region is closed
    /// toward the side the path's normals on the part side point to on average (below for
    /// OD turning, above for ID boring, left for facing); the comparison is limited to the
    /// path's Z span (its X span when closed along Z). As for a finishing shape, approach
    /// and retract are no part, also when deciding the side: a retract off the last
    /// diameter would otherwise turn an OD contour into a face.
    pub fn compensated(path: &[[f64; 2]], part_on_left: bool, stages: &Stages) -> Option<Self> {
        let path = in_contact(path, stages);
        let mut n = [0.0, 0.0];
        for w in path.windows(2) {
            let d = [w[1][0] - w[0][0], w[1][1] - w[0][1]];
            let left = [-d[1], d[0]];
            let s = if part_on_left { 1.0 } else { -1.0 };
            n = [n[0] + s * left[0], n[1] + s * left[1]];
        }
        let toward = if n[1].abs() >= n[0].abs() {
            if n[1] < 0.0 {
                Toward::MinusR
            } else {
                Toward::PlusR
            }
        } else if n[0] < 0.0 {
            Toward::MinusZ
        } else {
            Toward::PlusZ
        };
        Self::open_path(&path, toward, contact::front_of(stages.finished))
    }

    /// The part bounded by an open path and closed far away `toward` one side.
    /// `front`: the finished part's front, where a back face's part (closed toward +Z)
    /// ends: in front of it is the face stock the program faced off, not part.
    fn open_path(shape: &[[f64; 2]], toward: Toward, front: Option<f64>) -> Option<Self> {
        let (first, last) = (*shape.first()?, *shape.last()?);
        if shape.len() < 2 {
            return None;
        }
        let (lo, hi) = bbox(shape);
        let mut ring = shape.to_vec();
        let zone = match toward {
            Toward::MinusR | Toward::PlusR => {
                let r = if toward == Toward::MinusR { -FAR } else { FAR };
                ring.extend([[last[0], r], [first[0], r]]);
                rect(lo[0], hi[0], -FAR, FAR)
            }
            Toward::MinusZ | Toward::PlusZ => {
                let z = match toward {
                    Toward::MinusZ => -FAR,
                    _ => front.filter(|f| *f > hi[0]).unwrap_or(FAR),
                };
                ring.extend([[z, last[1]], [z, first[1]]]);
                // a back face (its part toward +Z: a part-off's chamfer and parting line)
                // speaks of the stock it cuts, within its own Z span; behind it lies the bar
                // that holds the part, the next part's stock, not stock to be gone (it drew
                // a leftover band the length of the bar; field run 5, C)
                let (back, ahead) = if toward == Toward::PlusZ {
                    (lo[0], z)
                } else {
                    (-FAR, FAR)
                };
                rect(back, ahead, lo[1], hi[1])
            }
        };
        let part = boolean(
            &[Shape {
                outer: ring,
                holes: vec![],
            }],
            &[],
            BoolOp::Union,
        );
        Some(Self {
            part,
            zone: vec![zone],
            outline: vec![(shape.to_vec(), false)],
            owner: None,
        })
    }
}

/// Box of a ring as (least, greatest) corner.
pub(crate) fn bbox(ring: &[P]) -> (P, P) {
    let r = Rect::of(pts(ring));
    (r.min.into(), r.max.into())
}
