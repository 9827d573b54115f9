//! The interpreter's side of `,C` / `,R` on G01 (the geometry is [`crate::corner`]): the
//! block's line is held until the next motion block; a G01 trims it, the corner piece
//! follows, and the next line starts where the piece ends. Any other motion, or the end of
//! the program, while a corner waits is an alarm (the control's "no move after a chamfer").
//! The pieces go through the same emission as every segment, so G41/G42 offsets the
//! chamfered path, as the control does. With the profile's `g01_cr = "plain"` a G01 takes
//! system A's `C±i` / `R±r` instead (a 90° corner; the sign is the next move's direction).

use super::Interp;
use crate::corner::{self, CornerKind};
use crate::words::Words;
use crate::{Diagnostic, G01Cr, Pt, Segment, Span};

/// A G01 line whose end corner waits for the next line.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PendingCorner {
    /// The line as programmed, to the corner.
    pub(crate) line: Segment,
    pub(crate) kind: CornerKind,
    /// The `,C` / `,R` word.
    pub(crate) word: Span,
    /// System A's plain `C±i` / `R±r`: the sign the next move's direction must have.
    pub(crate) toward: Option<f64>,
}

/// What a G01 asks for its end corner: the piece, its word, and for the plain form the
/// direction of the next move.
pub(super) type CornerAsk = (CornerKind, Span, Option<f64>);

impl Interp<'_> {
    /// The block's `,C` or `,R` (taken), or under `g01_cr = "plain"` its `C±i` / `R±r`; a
    /// plain R under the comma form is an error naming the profile key.
    pub(super) fn corner_word(
        &mut self,
        used: &mut Words,
    ) -> Result<Option<CornerAsk>, Diagnostic> {
        let (c, r) = (used.take('c'), used.take('r'));
        let comma = corner::corner_word(c, r, self.unit())?;
        if self.machine.g01_cr == G01Cr::Comma {
            if let Some(w) = used.take('R') {
                return Err(super::alarm(
                    w.span,
                    "LS-CORNER",
                    format!("R{} on a G01: a corner round is written ,R here", w.value),
                    "write ,R r (and ,C c for a chamfer), or set g01_cr = \"plain\" in the machine profile for system A's R±r",
                ));
            }
            return Ok(comma.map(|(k, s)| (k, s, None)));
        }
        let (pc, pr) = (used.take('C'), used.take('R'));
        let plain = match (pc, pr) {
            (None, None) => return Ok(comma.map(|(k, s)| (k, s, None))),
            (Some(c), Some(r)) => {
                return Err(super::alarm(
                    r.span,
                    "LS-CORNER",
                    format!("both C and R on one block (C at {})", c.span),
                    "a corner is either chamfered (C) or rounded (R): keep one",
                ))
            }
            (Some(w), None) => (w, false),
            (None, Some(w)) => (w, true),
        };
        let (w, round) = plain;
        if let Some((_, s)) = comma {
            return Err(super::alarm(
                w.span,
                "LS-CORNER",
                format!(
                    "a plain {} and a comma corner (at {s}) on one block",
                    w.letter
                ),
                "keep one corner word",
            ));
        }
        let (kind, sign) = corner::plain_word(w, round, self.unit())?;
        Ok(Some((kind, w.span, Some(sign))))
    }

    /// A G01 line to `to`: the corner waiting on the line before is made against it, and
    /// this line waits in its turn when it has `corner`.
    pub(super) fn feed_line(
        &mut self,
        span: Span,
        to: Pt,
        corner: Option<CornerAsk>,
    ) -> Result<(), Diagnostic> {
        if let Some(p) = self.corner.take() {
            if let Some(sign) = p.toward {
                corner::plain_fits(p.line.from, p.line.to, to, sign, p.word, p.line.span.line)?;
            }
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
            Some((kind, word, toward)) => {
                self.corner = Some(PendingCorner {
                    line,
                    kind,
                    word,
                    toward,
                });
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
