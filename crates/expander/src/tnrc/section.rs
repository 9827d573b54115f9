//! The compensation state the interpreter keeps (G40/G41/G42 mode, the offset in force) and
//! the section of programmed moves it buffers from the start-up block to the cancel block
//! (or a suspending block), which [`super::compensate`] then offsets as a whole.

use super::{Nose, Side};
use crate::{Diagnostic, Segment, Span, Toolpath};
use std::collections::BTreeMap;

/// Where the noses of the tool offsets come from: the tool table's entries by offset
/// number (`None` for a grooving blade), and the documented default for the others.
pub(crate) struct NoseTable<'a> {
    /// Nose per offset number `oo` of `Tttoo`.
    pub(crate) noses: &'a BTreeMap<u32, Option<Nose>>,
    /// The nose of an offset with no entry.
    pub(crate) default: Nose,
}

/// G41/G42 in force, the offset, and the open section.
#[derive(Debug, Default)]
pub(crate) struct Compensation {
    /// G41/G42 mode in force (group 07); `None` is G40.
    pub(crate) side: Option<Side>,
    /// Tool offset number `oo` in force.
    pub(crate) offset: u32,
    /// The section being collected (start-up first), with its side and nose.
    section: Option<(Side, Nose, Vec<Segment>)>,
    /// Offsets already warned about (blade, no entry).
    warned: Vec<u32>,
}

impl Compensation {
    /// Whether a section is being collected.
    pub(crate) fn is_open(&self) -> bool {
        self.section.is_some()
    }

    /// Moves buffered in the open section.
    pub(crate) fn buffered(&self) -> usize {
        self.section.as_ref().map_or(0, |s| s.2.len())
    }

    /// Keep `seg` in the open section, or hand it back when none is open.
    pub(crate) fn buffer(&mut self, seg: Segment) -> Option<Segment> {
        match &mut self.section {
            Some((_, _, buf)) => {
                buf.push(seg);
                None
            }
            None => Some(seg),
        }
    }

    /// Open a section on `side` with the nose of the offset in force (none for offset 00 or
    /// a blade).
    pub(crate) fn open(&mut self, side: Side, noses: &NoseTable, span: Span, out: &mut Toolpath) {
        if let Some(nose) = self.nose(noses, span, out) {
            self.section = Some((side, nose, vec![]));
        }
    }

    /// Begin a section if G41/G42 is in force, an offset is active, no section is open and
    /// the block moves (`moves`): this block is the start-up block. Compensation cannot
    /// start on an arc (PS034).
    pub(crate) fn start(
        &mut self,
        moves: bool,
        on_arc: bool,
        span: Span,
        noses: &NoseTable,
        out: &mut Toolpath,
    ) -> Result<(), Diagnostic> {
        let Some(side) = self.side else { return Ok(()) };
        if self.section.is_some() || self.offset == 0 || !moves {
            return Ok(());
        }
        if on_arc {
            return Err(Diagnostic::new(
                span,
                "PS034",
                "tool nose radius compensation cannot start on an arc",
                "start G41/G42 in a G00 or G01 block with a move",
            ));
        }
        self.open(side, noses, span, out);
        Ok(())
    }

    /// The nose of the offset in force: from the tool table, or the default with a warning;
    /// `None` for offset 00 or a grooving blade (compensation ignored, with a warning).
    fn nose(&mut self, noses: &NoseTable, span: Span, out: &mut Toolpath) -> Option<Nose> {
        let offset = self.offset;
        if offset == 0 {
            return None;
        }
        Some(match noses.noses.get(&offset) {
            Some(Some(n)) => *n,
            Some(None) => {
                if !self.warned.contains(&offset) {
                    self.warned.push(offset);
                    out.warnings.push(Diagnostic::new(span, "LS-TNRC-BLADE", format!("G41/G42 ignored: offset {offset:02} is a grooving blade"), "compensation applies to pointed inserts; program the blade's corner directly"));
                }
                return None;
            }
            None => {
                let n = noses.default;
                if !self.warned.contains(&offset) {
                    self.warned.push(offset);
                    out.warnings.push(Diagnostic::new(
                        span,
                        "LS-TNRC-DEFAULT",
                        format!("offset {offset:02} has no tool table entry: compensating with the default nose r{} tip {}", n.radius, n.tip),
                        "give the tool in the tool table (--tools) with its nose_radius and tip",
                    ));
                }
                n
            }
        })
    }

    /// Compensate and emit the collected section; its last move is the cancel move. The
    /// programmed contour between start-up and cancel is an intended shape, unless a G70
    /// already handed it over as its finishing shape.
    pub(crate) fn flush(&mut self, out: &mut Toolpath) {
        let Some((side, nose, section)) = self.section.take() else {
            return;
        };
        if section.len() >= 3 {
            let body = &section[1..section.len() - 1];
            let mut points = vec![body[0].from];
            for seg in body {
                points.extend(seg.polyline(0.001).into_iter().skip(1));
            }
            let known = out.intended.iter().any(|i| {
                i.kind == crate::IntendedKind::FinishingContour
                    && i.points.get(1..) == Some(&points[..])
            });
            if !known {
                out.intended.push(crate::Intended {
                    kind: crate::IntendedKind::Compensated {
                        part_on_left: side == Side::Right,
                    },
                    points,
                    span: section[0].span,
                });
            }
        }
        let c = super::compensate(&section, side, nose);
        out.segments.extend(c.segments);
        out.alarms.extend(c.alarms);
    }
}
