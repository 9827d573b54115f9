//! The interpreter's side of `,C` / `,R` on G01 (the geometry is [`crate::corner`]): the
//! block's line is held until the next motion block; a G01 trims it, the corner piece
//! follows, and the next line starts where the piece ends. Any other motion, or the end of
//! the program, while a corner waits is an alarm (the control's "no move after a chamfer").
//! The pieces go through the same emission as every segment, so G41/G42 offsets the
//! chamfered path, as the control does. With the profile's `g01_cr = "plain"` a G01 takes
//! system A's `C±i` / `R±r` instead (a 90° corner; the sign is the next move's direction).

use super::Interp;
use crate::corner::{self, Ask};
use crate::words::Words;
use crate::{Diagnostic, G01Cr, Pt, Segment, Span};

/// A G01 line whose end corner waits for the next line.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PendingCorner {
    /// The line as programmed, to the corner.
    pub(crate) line: Segment,
    pub(crate) ask: Ask,
}

impl Interp<'_> {
    /// The block's `,C` or `,R` (taken), or under `g01_cr = "plain"` its `C±i` / `R±r`; a
    /// plain R under the comma form is an error naming the profile key.
    pub(super) fn corner_word(&mut self, used: &mut Words) -> Result<Option<Ask>, Diagnostic> {
        let comma = [used.take('c'), used.take('r')];
        let plain = if self.machine.g01_cr == G01Cr::Plain {
            [used.take('C'), used.take('R')]
        } else {
            if let Some(w) = used.take('R') {
                return Err(super::alarm(
                    w.span,
                    "LS-CORNER",
                    format!("R{} on a G01: a corner round is written ,R here", w.value),
                    "write ,R r (and ,C c for a chamfer), or set g01_cr = \"plain\" in the machine profile for system A's R±r",
                ));
            }
            [None, None]
        };
        corner::ask(comma, plain, self.unit())
    }

    /// A G01 line to `to`: the corner waiting on the line before is made against it, and
    /// this line waits in its turn when it has `corner`.
    pub(super) fn feed_line(
        &mut self,
        span: Span,
        to: Pt,
        corner: Option<Ask>,
    ) -> Result<(), Diagnostic> {
        if let Some(p) = self.corner.take() {
            let piece = corner::make(p.line.from, p.line.to, to, &p.ask, p.line.span.line)?;
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
            Some(ask) => {
                self.corner = Some(PendingCorner { line, ask });
                self.pos = to;
            }
            None => self.emit(line),
        }
        Ok(())
    }

    /// The alarm for a corner still waiting when `what` comes instead of a G01.
    pub(super) fn corner_without_line(&self, p: &PendingCorner, what: &str) -> Diagnostic {
        corner::without_line(p.ask.word, p.line.span.line, what)
    }
}
