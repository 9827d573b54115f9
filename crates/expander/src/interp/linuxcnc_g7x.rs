//! Running `LinuxCNC`'s G70, G71/G71.1/G71.2 and G72/G72.1/G72.2 (docs/linuxcnc.md "G70,
//! G71, G72"; [G] "G70", "G71 G72"; `interp_g7x.cc` `convert_g7x`): the cycle's block is
//! taken out of the ordinary run ([`Flow::G7x`]); the O-sub Q is then run as `LinuxCNC`
//! runs it — its o-words, parameters and modes included — with its moves captured as the
//! profile instead of cut (G0 read as G1, `A` a fillet and `C` a chamfer at the move's end,
//! `U`/`W` increments); then the cycle's moves are made from the profile
//! (`cycles::linuxcnc_g7x`, FANUC's layers in `cycles::g71_g72`).

use super::flow::{Exit, Flow};
use super::{alarm, Interp};
use crate::codes::{G71, G72};
use crate::cycles::linuxcnc_g7x::{self as g7x, Corner};
use crate::cycles::{g71_g72, Move, Output};
use crate::linuxcnc as lc;
use crate::words::Words;
use crate::{Diagnostic, IntendedKind, Pt, Segment, Span};
use gcode::{Block, Program, Word};

/// The profile being captured: where its moves start in the toolpath, its corners.
pub(super) struct Capture {
    from: usize,
    corners: Vec<Corner>,
}

/// The words of a G7x block, in mm (X a radius, G54 frame).
struct G7xWords {
    q: u32,
    start: Pt,
    d: f64,
    e: f64,
    i: f64,
    r: f64,
    passes: u32,
}

/// The canonical G7x code of block `b` and its word, if it has one.
pub(super) fn g7x_code(b: &Block) -> Option<(i32, &Word)> {
    b.words.iter().find_map(|w| {
        let t = crate::linuxcnc::canonical(w.code_tenths()?).ok()?;
        let g7x = t == lc::CYCLE_G70 || (lc::CYCLE_G72 - 2..=lc::CYCLE_G71).contains(&t);
        (w.letter == 'G' && g7x).then_some((t, w))
    })
}

impl Interp<'_> {
    /// Under `LinuxCNC`: a G7x block becomes [`Flow::G7x`]; a block of a profile being
    /// captured runs with its A/C corners and U/W increments read. `None`: an ordinary
    /// block.
    pub(super) fn g7x_hook(&mut self, b: &Block) -> Option<Block> {
        if g7x_code(b).is_some() {
            return None;
        }
        self.g7x_capture.as_ref()?;
        let moved_by = |l| b.has(l);
        if !['A', 'C', 'U', 'W'].into_iter().any(moved_by) {
            return None;
        }
        Some(b.clone())
    }

    /// A block of the profile being captured with `A`/`C` (noted as corners of its move)
    /// or `U`/`W` (increments in absolute mode): run without them.
    pub(super) fn capture_block(
        &mut self,
        sub: &gcode::Subprogram,
        b: &Block,
        index: usize,
    ) -> Result<Flow, Diagnostic> {
        let mut copy = b.clone();
        let mut corner = None;
        let unit = self.unit();
        let here = self.pos - self.shift;
        let mut words = Vec::with_capacity(copy.words.len());
        for w in copy.words.iter() {
            let mut w = w.clone();
            match w.letter {
                'A' | 'C' => {
                    if corner.is_some() {
                        return Err(alarm(
                            w.span,
                            "LS-G7X-PROFILE",
                            "both A and C on one corner",
                            "a corner is a fillet (A) or a chamfer (C)",
                        ));
                    }
                    corner = Some((w.letter == 'C', w.value * unit, w.span));
                    continue;
                }
                'U' | 'W' if self.incremental => {
                    return Err(alarm(
                        w.span,
                        "LS-G7X-PROFILE",
                        format!("{} in incremental mode (G91) in a G7x profile", w.letter),
                        "LinuxCNC reads U and W in a profile under G90 only",
                    ));
                }
                'U' => {
                    // (the block's X is a diameter here: `linuxcnc_block` doubled a G8 X)
                    let u = if self.x_diameter {
                        w.value
                    } else {
                        2.0 * w.value
                    };
                    w.letter = 'X';
                    w.value = 2.0 * here.r / unit + u;
                }
                'W' => {
                    w.letter = 'Z';
                    w.value += here.z / unit;
                }
                _ => {}
            }
            words.push(w);
        }
        for l in ['X', 'Z'] {
            if words.iter().filter(|w| w.letter == l).count() > 1 {
                let w = words.iter().rfind(|w| w.letter == l).expect("counted");
                return Err(alarm(
                    w.span,
                    "LS-G7X-PROFILE",
                    format!("{l} and its increment in one block"),
                    "write the absolute value or the increment",
                ));
            }
        }
        copy.words = words.into_boxed_slice();
        let before = self.out.segments.len();
        let flow = self.run_block(sub, &copy, index)?;
        if let Some((chamfer, size, span)) = corner {
            let cap = self.g7x_capture.as_mut().expect("capturing");
            let made = self.out.segments.len();
            if made == before {
                return Err(alarm(
                    span,
                    "LS-G7X-PROFILE",
                    "A or C on a block that does not move",
                    "write the corner on the move that ends at it",
                ));
            }
            cap.corners.push(Corner {
                after: made - 1 - cap.from,
                chamfer,
                size,
                span,
            });
        }
        Ok(flow)
    }

    /// The words of G7x block `b` (canonical `code`), checked.
    fn g7x_words(&mut self, code: i32, g: &Word, b: &Block) -> Result<G7xWords, Diagnostic> {
        let mut used = Words::new(b, vec![]);
        for (i, w) in b.words.iter().enumerate() {
            if std::ptr::eq(w, g) {
                used.mark(i);
            }
        }
        if let Some(f) = used.take('F') {
            self.feed = f.value;
        }
        let unit = self.unit();
        let q = match used.take('Q') {
            Some(q) if q.value >= 1.0 && q.value.fract() == 0.0 => q.value as u32,
            Some(q) => {
                return Err(alarm(
                    q.span,
                    "LS-VALUE",
                    "Q must be the number of the profile's O-sub",
                    "write Q100 for o100 sub",
                ))
            }
            None => {
                return Err(alarm(
                    g.span,
                    "LS-VALUE",
                    "G7x without Q (the O-sub of the profile)",
                    "write e.g. G71 Q100 X… Z… D… I… R…",
                ))
            }
        };
        let here = self.pos - self.shift;
        let axis = |w: Option<&Word>, now: f64, scale: f64, incremental: bool| match w {
            Some(w) if incremental => now + w.value * unit / scale,
            Some(w) => w.value * unit / scale,
            None => now,
        };
        let x = axis(used.take('X'), here.r, 2.0, self.incremental);
        let z = axis(used.take('Z'), here.z, 1.0, self.incremental);
        let g70 = code == lc::CYCLE_G70;
        let mut length = |l: char, default: f64| used.take(l).map_or(default, |w| w.value * unit);
        let d = length('D', 0.0);
        let (e, i, r) = if g70 {
            (length('E', 0.0), 1.0, 0.0)
        } else {
            (0.0, length('I', 1.0 * unit), length('R', 0.5 * unit))
        };
        let passes = if g70 {
            match used.take('P') {
                Some(p) if p.value >= 1.0 && p.value.fract() == 0.0 => p.value as u32,
                Some(p) => {
                    return Err(alarm(
                        p.span,
                        "LS-VALUE",
                        "P must be a number of passes (1 or more)",
                        "write e.g. P2",
                    ))
                }
                None => 1,
            }
        } else {
            1
        };
        if i <= 0.0 {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "G7x I (the depth of cut) must be greater than zero",
                "write e.g. I1",
            ));
        }
        if r < 0.0 || d < 0.0 || e < 0.0 {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "G7x D, E and R are distances: not negative",
                "write them as positive values",
            ));
        }
        used.check_all_used()?;
        Ok(G7xWords {
            q,
            start: Pt::new(z, x) + self.shift,
            d,
            e,
            i,
            r,
            passes,
        })
    }

    /// G71.2/G72.2 "only cut after the first pocket and continue where G7x.1 stopped" ([G]
    /// "G71 G72"): latsim runs a G7x.2 as the whole cycle, which leaves the same part only
    /// after a G7x.1 of the same profile; without one `LinuxCNC` would leave the material
    /// before the first pocket, so that is an alarm rather than a part it does not make.
    /// A G7x.1 is noted for the G7x.2 that follows.
    fn continues_a_rough(
        &mut self,
        g72: bool,
        sub: i32,
        q: u32,
        at: gcode::Span,
    ) -> Result<(), Diagnostic> {
        let n = if g72 { 72 } else { 71 };
        match sub {
            1 if !self.g7x_roughed.contains(&(g72, q)) => self.g7x_roughed.push((g72, q)),
            2 if !self.g7x_roughed.contains(&(g72, q)) => {
                return Err(alarm(
                    at,
                    "LS-NOT-IMPLEMENTED",
                    format!("G{n}.2 Q{q} with no G{n}.1 Q{q} before it: LinuxCNC cuts only from the first pocket on, which latsim does not run yet"),
                    format!("rough the profile with G{n}.1 Q{q} first (LinuxCNC's own use), or with G{n} for the whole cycle"),
                ))
            }
            _ => {}
        }
        Ok(())
    }

    /// Run G7x block `b` of O program `index` of `program` at call `depth`.
    pub(super) fn linuxcnc_g7x(
        &mut self,
        program: &Program,
        index: usize,
        depth: u32,
        b: &Block,
    ) -> Result<(), Diagnostic> {
        let Some((code, g)) = g7x_code(b) else {
            return Ok(());
        };
        let w = self.g7x_words(code, g, b)?;
        if code != lc::CYCLE_G70 && self.comp.is_some() {
            return Err(alarm(
                g.span,
                "LS-G7X",
                "G71/G72 with cutter compensation on",
                "cancel it with G40 before the cycle (LinuxCNC refuses it too)",
            ));
        }
        if self.plane.is_some() {
            return Err(alarm(
                g.span,
                "LS-G7X",
                "G7x outside the ZX plane",
                "select G18 before the cycle",
            ));
        }
        let moves = self.capture_profile(program, (index, depth), &w, g.span)?;
        let shape = g7x::profile((code, b.span), w.start, &moves.0, &moves.1)?;
        let sub = lc::CYCLE_G71 - code;
        let mut out = Output::default();
        out.moves.push(Move::rapid(w.start));
        if code == lc::CYCLE_G70 {
            out.moves
                .extend(g7x::finishing_passes(&shape, (w.d, w.e, w.passes))?);
            out.comp_from = 1;
        } else {
            let g72 = code <= lc::CYCLE_G72;
            let sub = if g72 { lc::CYCLE_G72 - code } else { sub };
            self.continues_a_rough(g72, sub, w.q, g.span)?;
            let kept = g7x::at_distance(&shape, w.d)?;
            let kept = if sub == 1 {
                g7x::without_pockets(&kept, g72)
            } else {
                kept
            };
            let fanuc = if g72 { G72 } else { G71 };
            out.moves
                .extend(g71_g72::linuxcnc_rough((fanuc, g.span), &kept, w.i, w.r)?);
            if sub == 2 {
                out.warnings.push(alarm(g.span, "LS-G7X-2", format!("G{}.2 is simulated as the whole cycle (pockets included): LinuxCNC starts at the first pocket, after what G{}.1 cut; the part is the same when G{}.1 ran before", if g72 { 72 } else { 71 }, if g72 { 72 } else { 71 }, if g72 { 72 } else { 71 }), "the layers G7x.1 cut already are cut again in air: the cycle time is longer than LinuxCNC's"));
            }
        }
        out.intended
            .push((IntendedKind::FinishingContour, shape.intended_path(0.001)));
        self.out.warnings.append(&mut out.warnings);
        self.record_intended(std::mem::take(&mut out.intended), b.span);
        self.flush_compensation();
        if code == lc::CYCLE_G70 {
            self.emit_g70(out, g.span)
        } else {
            self.emit_cycle(out, g.span).map(|_| ())
        }
    }

    /// G70's moves, compensated from move `comp_from` on when G41/G42 (or their `.1`
    /// forms) are in force; the compensation stays on after the cycle, as in `LinuxCNC`
    /// (the tool stays at the profile's end; the next move under G40 is the cancel).
    fn emit_g70(&mut self, out: Output, span: Span) -> Result<(), Diagnostic> {
        for (k, m) in out.moves.into_iter().enumerate() {
            if k == out.comp_from {
                if let Some(side) = self.comp {
                    if let Some(nose) = self.nose_for_offset(span) {
                        self.section = Some((side, nose, vec![]));
                    }
                }
            }
            if m.to.dist(self.pos) >= 1e-12 {
                self.push_at(m.span.unwrap_or(span), m.motion, m.to, m.arc, 0.0, m.hint)?;
            }
        }
        Ok(())
    }

    /// Run the O-sub `w.q` with its moves captured, from the cycle's start point: the
    /// moves and the corners written on them. Nothing else of the run changes (position,
    /// modes, feed, compensation are put back; the profile's warnings are dropped).
    fn capture_profile(
        &mut self,
        program: &Program,
        (index, depth): (usize, u32),
        w: &G7xWords,
        at: Span,
    ) -> Result<(Vec<Segment>, Vec<Corner>), Diagnostic> {
        let label = macro_b::OLabel::Number(w.q);
        let Some(line) = self.o_sub_line(program, index, &label) else {
            return Err(alarm(
                at,
                "LS-G7X",
                format!("G7x Q{}: no {label} sub in this file", w.q),
                format!("define the profile as {label} sub … {label} endsub"),
            ));
        };
        if self.g7x_capture.is_some() {
            return Err(alarm(
                at,
                "LS-G7X",
                "a G7x cycle inside the profile of another",
                "the profile O-sub holds moves only",
            ));
        }
        let saved = (
            self.pos,
            self.motion,
            self.comp.take(),
            self.section.take(),
            self.feed,
        );
        let warnings = self.out.warnings.len();
        self.pos = w.start;
        if self.feed <= 0.0 {
            self.feed = 1.0;
        }
        self.g7x_capture = Some(Capture {
            from: self.out.segments.len(),
            corners: vec![],
        });
        let locals = self.o_call_locals();
        let level = self.enter_call(locals, false);
        let exit = self.run(program, index, line + 1, depth + 1);
        self.leave_call(level);
        let cap = self.g7x_capture.take().expect("capturing");
        let moves: Vec<Segment> = self.out.segments.drain(cap.from..).collect();
        self.out.warnings.truncate(warnings);
        (self.pos, self.motion, self.comp, self.section, self.feed) = saved;
        match exit? {
            Exit::Return(None) => Ok((moves, cap.corners)),
            _ => Err(alarm(
                at,
                "LS-G7X",
                format!("the profile {label} ended the program or returned elsewhere"),
                "the profile O-sub ends at its endsub",
            )),
        }
    }
}
