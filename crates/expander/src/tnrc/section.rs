//! The compensation buffer of the interpreter: G40/G41/G42 in force, the section of moves
//! collected from start-up to cancel, and handing it to [`super::compensate`].

use super::{compensate, Nose, Side};
use crate::codes::{G41, G42};
use crate::interp::{alarm, Interp, MotionMode};
use crate::{Diagnostic, Segment, Span};
use gcode::{Block, Word};

impl Interp<'_> {
    /// G40/G41/G42 of this block (spec/tnrc.md).
    pub(crate) fn set_compensation_mode(&mut self, comp: Option<(i32, &Word)>) {
        if let Some((t, _)) = comp {
            let side = match t {
                G41 => Some(Side::Left),
                G42 => Some(Side::Right),
                _ => None,
            };
            if side.is_some() && self.comp.is_some() && side != self.comp {
                // G41 in G42 mode (or the reverse) cancels and re-establishes.
                self.flush_compensation();
            }
            self.comp = side;
        }
    }

    /// Begin a compensation section if G41/G42 is in force, an offset is active, no section
    /// is open and this block moves: this block is the start-up block.
    pub(crate) fn start_compensation(&mut self, b: &Block) -> Result<(), Diagnostic> {
        let Some(side) = self.comp else { return Ok(()) };
        if self.section.is_some()
            || self.offset == 0
            || !['X', 'Z', 'U', 'W'].iter().any(|&l| b.has(l))
        {
            return Ok(());
        }
        if matches!(self.motion, MotionMode::Cw | MotionMode::Ccw) {
            return Err(alarm(
                b.span,
                "PS034",
                "tool nose radius compensation cannot start on an arc",
                "start G41/G42 in a G00 or G01 block with a move",
            ));
        }
        if let Some(nose) = self.nose_for_offset(b.span) {
            self.section = Some((side, nose, vec![]));
        }
        Ok(())
    }

    /// The nose of the offset in force: from the tool table, or the default with a warning;
    /// `None` for offset 00 or a tool without a nose (compensation ignored, with a warning).
    pub(crate) fn nose_for_offset(&mut self, span: Span) -> Option<Nose> {
        let offset = self.offset;
        if offset == 0 {
            return None;
        }
        Some(match self.nose_for(offset) {
            Some(Ok(n)) => n,
            Some(Err(kind)) => {
                if !self.comp_warned.contains(&offset) {
                    self.comp_warned.push(offset);
                    self.warn(span, "LS-TNRC-BLADE", format!("G41/G42 ignored: offset {offset:02} is a {kind}, not a turning insert"), "compensation applies to turning inserts with a nose radius; program the tool's reference point directly");
                }
                return None;
            }
            None => {
                let n = self.default_nose();
                if !self.comp_warned.contains(&offset) {
                    self.comp_warned.push(offset);
                    self.warn(
                        span,
                        "LS-TNRC-DEFAULT",
                        format!("offset {offset:02} has no tool table entry: compensating with the default nose r{} tip {}", n.radius, n.tip),
                        "give the tool in the tool table (--tools) with its nose_radius and tip",
                    );
                }
                n
            }
        })
    }

    /// Compensate and emit the collected section; its last move is the cancel move.
    pub(crate) fn flush_compensation(&mut self) {
        let Some((side, nose, section)) = self.section.take() else {
            return;
        };
        if section.len() >= 3 {
            // The programmed contour between start-up and cancel is an intended shape,
            // unless a G70 already handed it over as its finishing shape. A rapid inside
            // the section separates passes: each chain of feeds is its own contour (the
            // report keeps only the last pass over a stretch of surface: roughing under
            // G41/G42 is not an intent).
            let body = &section[1..section.len() - 1];
            for chain in body.split(|s| s.motion == crate::Motion::Rapid) {
                // (a G70 shape that writes G41/G42 after its ns block hands over more)
                let known = self.out.intended.iter().any(|i| {
                    i.kind == crate::IntendedKind::FinishingContour
                        && i.points.ends_with(&contour_points(chain))
                });
                if known {
                    continue;
                }
                for pass in passes(chain) {
                    let Some(first) = pass.first() else { continue };
                    self.out.intended.push(crate::Intended {
                        kind: crate::IntendedKind::Compensated {
                            part_on_left: side == Side::Right,
                        },
                        points: contour_points(pass),
                        span: first.span,
                        after_move: self.out.segments.len(),
                        began: self.out.segments.len(),
                    });
                }
            }
        }
        let c = compensate(&section, side, nose);
        self.out.comp_starts.push(self.out.segments.len());
        self.out.segments.extend(c.segments);
        self.out.alarms.extend(c.alarms);
        if let Some(engaged) = self.tailstock_pending.take() {
            self.out.tailstock.push((self.out.segments.len(), engaged));
        }
    }
}

/// The programmed points of a chain of moves, arcs as chords.
fn contour_points(chain: &[Segment]) -> Vec<crate::Pt> {
    let mut points: Vec<crate::Pt> = chain.first().map(|s| s.from).into_iter().collect();
    for seg in chain {
        points.extend(seg.polyline(0.001).into_iter().skip(1));
    }
    points
}

/// The passes of a chain of feeds under G41/G42: its runs that keep one direction along Z
/// (a move more along X than along Z stays in the run it is in: a wall leaning back is no
/// return), those going the way the chain's first run goes. A run back the other way is the tool fed back to start the next pass, no
/// contour: zig-zag roughing by hand under one G42 is then its passes, each a contour that
/// a later one over its stretch supersedes (a chain read as one contour made the second,
/// deeper pass a 1 mm gouge of the first).
fn passes(chain: &[Segment]) -> Vec<&[Segment]> {
    let dir = |s: &Segment| {
        let (dz, dr) = (s.to.z - s.from.z, s.to.r - s.from.r);
        if dz.abs() <= dr.abs() || dz.abs() <= 1e-6 {
            0.0
        } else {
            dz.signum()
        }
    };
    let mut runs: Vec<(f64, &[Segment])> = Vec::new();
    let (mut start, mut run_dir) = (0, 0.0);
    for (k, seg) in chain.iter().enumerate() {
        let d = dir(seg);
        if d != 0.0 && run_dir != 0.0 && d != run_dir {
            runs.push((run_dir, &chain[start..k]));
            start = k;
        }
        if d != 0.0 {
            run_dir = d;
        }
    }
    runs.push((run_dir, &chain[start..]));
    let first = runs.iter().map(|r| r.0).find(|&d| d != 0.0).unwrap_or(0.0);
    runs.into_iter()
        .filter(|&(d, _)| d == first || d == 0.0)
        .map(|(_, run)| run)
        .collect()
}
