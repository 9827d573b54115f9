//! Two final parts compared (`latsim diff`, `run --baseline`): the regions the new part
//! gained (material it keeps that the old one lost) and lost (material the old one kept),
//! each with its area, depth and place, and the moves of each program that made it.
//!
//! The regions are the deviation's own: the old part is the intended one
//! ([`Intent::target`]), the new part the final one, so a lost region is a "gouge" and a
//! gained one a "leftover", with the same boolean, the same depth (the largest distance
//! from the old part's boundary) and the same noise filter (regions no deeper than the
//! tolerance, and slivers thinner than a tenth of it, are no difference).

use crate::deviation::{deviation, moves_over, Finding};
use crate::intent::Intent;
use expander::Segment;
use stock::{boolean, BoolOp, Mounts, Shape, ToolTable};

/// Most regions of each kind whose moves are looked for (the largest first): each costs a
/// box test per move.
pub const MAX_BLAMED: usize = 200;

/// One side of a comparison: its final part, and the moves that cut it when they are
/// known (a program that was run; a saved report holds only the part).
#[derive(Debug, Clone, Copy)]
pub struct Side<'a> {
    /// The final half section.
    pub part: &'a [Shape],
    /// The program's moves and the tools that made them.
    pub moves: Option<(&'a [Segment], &'a ToolTable)>,
}

/// A connected region where the two parts differ.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    /// The region, `[z, r]`.
    pub shape: Shape,
    /// Its area, mm² of the half section.
    pub area: f64,
    /// Its largest distance from the old part's boundary, mm.
    pub depth: f64,
    /// Where it is deepest, `[z, r]`.
    pub at: [f64; 2],
    /// Its box: lowest `[z, r]` corner.
    pub lo: [f64; 2],
    /// Its box: highest `[z, r]` corner.
    pub hi: [f64; 2],
    /// The new program's moves that made it, in move order (indices into its segments):
    /// those whose sweep cut into a lost region, those that ran within the tolerance of a
    /// gained one (they left its edge there). Empty without the program.
    pub new_moves: Vec<usize>,
    /// The old program's moves that made it: those that cut into a gained region, those
    /// that ran within the tolerance of a lost one.
    pub old_moves: Vec<usize>,
}

/// What the new part gained and lost against the old one, largest regions first.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PartDiff {
    /// Material the new part keeps that the old one did not.
    pub gained: Vec<Region>,
    /// Material the old part kept that the new one does not.
    pub lost: Vec<Region>,
}

impl PartDiff {
    /// Whether the parts agree within the tolerance.
    pub fn same(&self) -> bool {
        self.gained.is_empty() && self.lost.is_empty()
    }

    /// Area gained, mm².
    pub fn gained_area(&self) -> f64 {
        self.gained.iter().fold(0.0, |a, r| a + r.area)
    }

    /// Area lost, mm².
    pub fn lost_area(&self) -> f64 {
        self.lost.iter().fold(0.0, |a, r| a + r.area)
    }
}

/// The regions where `new`'s part differs from `old`'s by more than `tol`, with the moves
/// that made each (for the sides whose moves are known).
pub fn compare(old: &Side, new: &Side, tol: f64) -> PartDiff {
    let both = boolean(old.part, new.part, BoolOp::Union);
    let d = deviation(
        &both,
        new.part,
        &[Intent::target(old.part.to_vec())],
        tol,
        &[],
        &ToolTable::default(),
        crate::CHORD_TOL,
    );
    let mut lost: Vec<Region> = d.gouges.into_iter().map(region).collect();
    let mut gained: Vec<Region> = d.leftovers.into_iter().map(region).collect();
    for list in [&mut lost, &mut gained] {
        list.sort_by(|a, b| b.area.total_cmp(&a.area));
    }
    // a program cut what it lost (the other left its edge there), and the other way round
    blame(&mut lost, new, |r| &mut r.new_moves, 0.0);
    blame(&mut lost, old, |r| &mut r.old_moves, tol);
    blame(&mut gained, old, |r| &mut r.old_moves, 0.0);
    blame(&mut gained, new, |r| &mut r.new_moves, tol);
    PartDiff { gained, lost }
}

fn region(f: Finding) -> Region {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in &f.shape.outer {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    Region {
        shape: f.shape,
        area: f.area,
        depth: f.depth,
        at: f.at,
        lo,
        hi,
        new_moves: vec![],
        old_moves: vec![],
    }
}

/// Fill `moves_of` for the first [`MAX_BLAMED`] regions with `side`'s moves whose sweep,
/// grown by `margin`, overlaps them.
fn blame(
    regions: &mut [Region],
    side: &Side,
    moves_of: impl Fn(&mut Region) -> &mut Vec<usize>,
    margin: f64,
) {
    let Some((segments, tools)) = side.moves else {
        return;
    };
    let n = regions.len().min(MAX_BLAMED);
    let shapes: Vec<Shape> = regions[..n].iter().map(|r| r.shape.clone()).collect();
    let mut mounts = Mounts::new(tools, stock::rear_tools(segments));
    let found = moves_over(&shapes, segments, &mut mounts, crate::CHORD_TOL, margin);
    for (r, moves) in regions.iter_mut().zip(found) {
        *moves_of(r) = moves;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
        Shape {
            outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
            holes: vec![],
        }
    }

    /// A stepped shaft (Ø30 to Z-25, then Ø36) against the same shaft with its shoulder
    /// 0.2 mm further left: one lost region Z-25.2..-25, r 15..18, of 0.2 × 3 = 0.6 mm²,
    /// 0.2 mm deep; the other way round it is gained; a part against itself is the same.
    #[test]
    fn a_moved_shoulder_is_one_region_of_its_area() {
        let old = vec![rect(-40.0, 0.0, 0.0, 15.0), rect(-40.0, -25.0, 0.0, 18.0)];
        let old = boolean(&old, &[], BoolOp::Union);
        let new = vec![rect(-40.0, 0.0, 0.0, 15.0), rect(-40.0, -25.2, 0.0, 18.0)];
        let new = boolean(&new, &[], BoolOp::Union);
        fn side(part: &[Shape]) -> Side<'_> {
            Side { part, moves: None }
        }
        let d = compare(&side(&old), &side(&new), 0.01);
        assert!(d.gained.is_empty(), "{:?}", d.gained);
        assert_eq!(d.lost.len(), 1);
        let r = &d.lost[0];
        assert!((r.area - 0.6).abs() < 1e-6, "{}", r.area);
        assert!((r.depth - 0.2).abs() < 1e-6, "{}", r.depth);
        assert!((r.lo[0] + 25.2).abs() < 1e-6 && (r.hi[0] + 25.0).abs() < 1e-6);
        assert!((r.lo[1] - 15.0).abs() < 1e-6 && (r.hi[1] - 18.0).abs() < 1e-6);
        let back = compare(&side(&new), &side(&old), 0.01);
        assert!(back.lost.is_empty() && back.gained.len() == 1);
        assert!((back.gained_area() - 0.6).abs() < 1e-6);
        assert!(compare(&side(&old), &side(&old), 0.01).same());
        // a shoulder moved by less than the tolerance is no difference
        assert!(compare(&side(&old), &side(&new), 0.25).same());
    }
}
