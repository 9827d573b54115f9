//! The interpreter's side of `,C` / `,R` on G01 (the geometry is [`crate::corner`]): the
//! block's line is held until the next motion block; a G01 trims it, the corner piece
//! follows, and the next line starts where the piece ends. Any other motion, or the end of
//! the program, while a corner waits is an alarm (the control's "no move after a chamfer").
//! The pieces go through the same emission as every segment, so G41/G42 offsets the
//! chamfered path, as the control does.

use super::Interp;
use crate::corner::{self, CornerKind};
use crate::words::Words;
use crate::{Diagnostic, Pt, Segment, Span};

/// A G01 line whose end corner waits for the next line.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PendingCorner {
    /// The line as programmed, to the corner.
    pub(crate) line: Segment,
    pub(crate) kind: CornerKind,
    /// The `,C` / `,R` word.
    pub(crate) word: Span,
}

impl Interp<'_> {
    /// The block's `,C` or `,R` (taken).
    pub(super) fn corner_word(
        &mut self,
        used: &mut Words,
    ) -> Result<Option<(CornerKind, Span)>, Diagnostic> {
        let (c, r) = (used.take('c'), used.take('r'));
        corner::corner_word(c, r, self.unit())
    }

    /// A G01 line to `to`: the corner waiting on the line before is made against it, and
    /// this line waits in its turn when it has `corner`.
    pub(super) fn feed_line(
        &mut self,
        span: Span,
        to: Pt,
        corner: Option<(CornerKind, Span)>,
    ) -> Result<(), Diagnostic> {
        if let Some(p) = self.corner.take() {
            let piece = corner::piece(p.line.from, p.line.to, to, p.kind)
                .map_err(|why| corner::impossible(p.word, p.line.span.line, &why))?;
            // the held line up to the piece, then the piece, both of the block that asked
            self.emit(Segment {
                to: piece.start,
                ..p.line
            });
            self.emit(Segment {
                from: piece.start,
                to: piece.end,
                arc: piece.arc,
                ..p.line
            });
        }
        let line = self.segment(
            span,
            crate::Motion::Feed,
            to,
            None,
            0.0,
            crate::ToolHint::Table,
        )?;
        match corner {
            Some((kind, word)) => {
                self.corner = Some(PendingCorner { line, kind, word });
                self.pos = to;
            }
            None => self.emit(line),
        }
        Ok(())
    }

    /// The alarm for a corner still waiting when `what` comes instead of a G01.
    pub(super) fn corner_without_line(&self, p: &PendingCorner, what: &str) -> Diagnostic {
        corner::without_line(p.word, p.line.span.line, what)
    }
}
