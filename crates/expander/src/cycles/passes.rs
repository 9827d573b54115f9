//! A finishing shape turned into moves: the G70 finishing pass as written, and the G71/G72
//! final pass and the G73 rough passes along the shape moved by an offset.

use super::contour::FinishingShape;
use super::Move;
use crate::Pt;

/// The finishing pass A → B → C as written: each element with its own motion, F and the
/// S/T/G96–G99 in force there, and the span of its shape block.
pub(super) fn finishing(shape: &FinishingShape) -> Vec<Move> {
    shape
        .elements
        .iter()
        .map(|e| {
            let mut m = if e.rapid {
                Move::rapid(e.to)
            } else {
                Move::feed(e.to)
            };
            m.arc = e.arc;
            m.feed = e.feed;
            m.modes = Some(e.modes);
            m.span = Some(e.span);
            m
        })
        .collect()
}

/// The shape moved by `off`, fed throughout except a G00 first element (the ns block);
/// each move carries the span of the shape block it copies.
pub(super) fn moved(shape: &FinishingShape, off: Pt) -> impl Iterator<Item = Move> + '_ {
    shape.elements.iter().enumerate().map(move |(i, e)| {
        let e = e.shifted(off);
        let mut m = if i == 0 && e.rapid {
            Move::rapid(e.to)
        } else {
            Move::feed(e.to)
        };
        m.arc = e.arc;
        m.span = Some(e.span);
        m
    })
}
