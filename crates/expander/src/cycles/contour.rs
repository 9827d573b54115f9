//! The finishing shape ns..nf shared by G70, G71, G72 and G73 (spec/cycles.md, seed 003).
//!
//! The shape is found by its sequence numbers in the O program of the cycle block, before
//! or after it. It is read here without running it: the blocks may hold only G00–G03,
//! G04, G96–G99 and G40–G42, no M98/M99 (`GSK980TDb`, seed 003); the ns block must be G00 or
//! G01. The shape starts at the cycle's start point A and is returned as a list of line and
//! arc [`ShapeElement`]s in the G54 frame, each with the span of the block that wrote it
//! and the F in force inside the shape (which only G70 uses).
//!
//! Choices where the manuals are silent:
//! - An N number written twice in the O program is an alarm when a cycle refers to it
//!   (GSK: "ns~nf 不允許有相同程式段號"), even if the other copy is far away.
//! - nf before ns, or a shape that contains the cycle block itself, is an alarm.
//! - M codes other than M98/M99 inside the shape are ignored by the cycles (GSK forbids
//!   only the subprogram calls); G04 inside the shape is ignored (no dwell time is added).
//! - F, S, T and G96–G99 inside the shape: roughing ignores them (seed 003); G70 applies
//!   them from their block on, and they stay in force after G70 as after any block.
//!   G41/G42 are read: G70 runs the shape compensated on that side; roughing ignores them.

use super::Cycle;
use crate::arc::ArcWords;
use crate::codes::{G00, G01, G02, G03, G04, G40, G41, G42, G96, G97, G98, G99};
use crate::corner::{self, Ask};
use crate::tnrc::Side;
use crate::{Arc, Diagnostic, Pt, Span};
use gcode::{Block, Blocks, Word};
use std::borrow::Cow;

/// One element of a finishing shape: a line or an arc from `from` to `to` (G54 frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShapeElement {
    /// Start point.
    pub from: Pt,
    /// End point.
    pub to: Pt,
    /// Arc data for G02/G03 elements.
    pub arc: Option<Arc>,
    /// Written as G00 (a rapid) — only the ns block or a later G00 block.
    pub rapid: bool,
    /// The F word in force inside the shape at this element (`None`: none written yet).
    pub feed: Option<f64>,
    /// S, T and G96–G99 written inside the shape up to this element (G70 applies them).
    pub modes: ShapeModes,
    /// The block that wrote it.
    pub span: Span,
}

impl ShapeElement {
    /// This element as a feed of no tool and no feed rate: for its geometry only (its
    /// polyline, an offset).
    pub(crate) fn as_segment(&self) -> crate::Segment {
        crate::Segment {
            motion: crate::Motion::Feed,
            from: self.from,
            to: self.to,
            arc: self.arc,
            tool: 0,
            hint: crate::ToolHint::Table,
            lead: 0.0,
            thread_phase: 0.0,
            feed: crate::FeedId::default(),
            span: self.span,
        }
    }
}

impl ShapeElement {
    /// This element moved by `d` (a translated arc keeps its radius and direction).
    pub(crate) fn shifted(&self, d: Pt) -> Self {
        let m = |p: Pt| Pt::new(p.z + d.z, p.r + d.r);
        Self {
            from: m(self.from),
            to: m(self.to),
            arc: self.arc.map(|a| Arc {
                center: m(a.center),
                ccw: a.ccw,
            }),
            ..*self
        }
    }
}

/// Spindle, tool and feed-mode words written inside a finishing shape, as in force at an
/// element (`None`: not written in the shape so far).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ShapeModes {
    /// S value.
    pub s: Option<f64>,
    /// G96 (true) or G97 (false).
    pub css: Option<bool>,
    /// G99 (true) or G98 (false).
    pub per_rev: Option<bool>,
    /// T word value `ttoo`.
    pub tool: Option<u32>,
}

/// A finishing shape ns..nf: the intended contour of the part a G70–G73 cycle works to.
///
/// Exposed for the gouge analysis: the part lies on the side of the shape away from the
/// start point (spec/simulation.md, "The intended shape").
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct FinishingShape {
    /// The cycle that read it, in tenths (G70, G71, G72, G73).
    pub cycle: i32,
    /// The cycle's start point A = the start of the ns block, G54 frame.
    pub start: Pt,
    /// The elements from A through B (end of ns) to C (end of nf); never empty.
    pub elements: Vec<ShapeElement>,
    /// The cycle block.
    pub span: Span,
    /// Span of the ns block's axis words (where "ns moves in X only" alarms point).
    pub ns_span: Span,
    /// The ns block gave X/U (resp. Z/W): G71/G72 type I or II.
    pub ns_moves: (bool, bool),
    /// Index of the ns and nf blocks in the O program.
    pub(crate) ns_index: usize,
    /// G41/G42 written inside the shape: G70 runs it compensated on that side (roughing
    /// ignores it, spec/tnrc.md).
    pub comp: Option<Side>,
    /// The element whose block wrote G41/G42 first: G70's start-up move (the elements before
    /// it run uncompensated, as the same blocks outside the cycle would); 0 for the ns block.
    pub comp_from: usize,
    /// Index of the nf block.
    pub(crate) nf_index: usize,
    /// Warnings about words G70 cannot apply yet (S, T, G96–G99) and G41/G42.
    pub(crate) notes: Vec<Diagnostic>,
}

impl FinishingShape {
    /// Where the program continues after the cycle: after nf when the shape follows the
    /// cycle block (GSK seed 003 and FANUC: the shape is not run again as ordinary motion),
    /// else the next block (a shape written before the cycle was already run in its place;
    /// one kept after M30/M02/M99, where the program's flow never reaches it, is no more in
    /// the way than one before).
    pub(crate) fn resume_at(&self, cycle_index: usize, blocks: &Blocks) -> Option<usize> {
        let follows = self.ns_index > cycle_index
            && !blocks
                .range(cycle_index + 1..self.ns_index)
                .any(|b| ends_flow(&b));
        follows.then_some(self.nf_index + 1)
    }

    /// The intended contour for the analysis: A, then B … C with arcs chorded at `tol`.
    pub(crate) fn intended_path(&self, tol: f64) -> Vec<Pt> {
        let mut pts = vec![self.start];
        for e in &self.elements {
            pts.extend(e.as_segment().polyline(tol).into_iter().skip(1));
        }
        pts
    }

    /// Point B, the end of the ns block.
    pub(crate) fn b(&self) -> Pt {
        self.elements[0].to
    }

    /// Point C, the end of the nf block.
    pub(crate) fn c(&self) -> Pt {
        self.elements[self.elements.len() - 1].to
    }
}

/// The P(ns) and Q(nf) words of a cycle block as sequence numbers (PS061 when missing).
pub(crate) fn ns_nf(c: &mut Cycle) -> Result<(u32, u32, Span, Span), Diagnostic> {
    let p = c.words.take('P');
    let q = c.words.take('Q');
    let (Some(p), Some(q)) = (p, q) else {
        return Err(c.alarm(
            "PS061",
            format!("{} needs P(ns) and Q(nf)", super::name(c.code)),
            "give the first and last sequence numbers of the finishing shape, e.g. P14 Q19",
        ));
    };
    for w in [p, q] {
        if w.has_point || w.value < 1.0 || w.value > 99_999.0 || w.value.fract() != 0.0 {
            return Err(Diagnostic::new(
                w.span,
                "PS061",
                format!("{}{} is not a sequence number", w.letter, w.value),
                "P and Q name N numbers 1 … 99999, written without a decimal point",
            ));
        }
    }
    Ok((p.value as u32, q.value as u32, p.span, q.span))
}

/// The index of the one block numbered `n` (PS063 when absent, an alarm when written twice).
fn find(c: &Cycle, n: u32, at: Span) -> Result<usize, Diagnostic> {
    let blocks = &c.program.blocks;
    let mut hits = blocks.positions_seq(n);
    let Some(i) = hits.next() else {
        return Err(Diagnostic::new(
            at,
            "PS063",
            format!("sequence number N{n} is not in this program"),
            "the finishing shape must be in the same O program as the cycle; check P and Q",
        ));
    };
    if let Some(second) = hits.next() {
        let second = blocks.at(second);
        return Err(Diagnostic::new(
            second.seq_span.unwrap_or(second.span),
            "LS-SHAPE-N-TWICE",
            format!("N{n} is written twice in this program, so the finishing shape is ambiguous (first at {})", blocks.at(i).span),
            "give every block of a finishing shape a sequence number of its own",
        ));
    }
    Ok(i)
}

/// A block after which the flow does not go on to the next: M02, M30 (end) or M99 (return).
fn ends_flow(b: &Block) -> bool {
    b.has_m(&[2.0, 30.0, 99.0])
}

/// Find and read the finishing shape P(ns)..Q(nf) of the cycle block.
pub(crate) fn read(c: &mut Cycle) -> Result<FinishingShape, Diagnostic> {
    let (ns, nf, p_span, q_span) = ns_nf(c)?;
    let i0 = find(c, ns, p_span)?;
    let i1 = find(c, nf, q_span)?;
    if i1 < i0 {
        return Err(Diagnostic::new(
            q_span,
            "LS-SHAPE-ORDER",
            format!("N{nf} (Q) stands before N{ns} (P)"),
            "P is the first block of the shape and Q the last; swap them",
        ));
    }
    if (i0..=i1).contains(&c.index) {
        return Err(c.alarm(
            "LS-SHAPE-ORDER",
            format!("the finishing shape N{ns}..N{nf} contains the cycle block itself"),
            "write the shape entirely before or after the cycle block",
        ));
    }
    let blocks: Vec<Block> = c
        .program
        .blocks
        .range(i0..i1 + 1)
        .map(Cow::into_owned)
        .collect();
    let mut r = Reader {
        pos: c.start,
        shift: c.shift,
        unit: c.unit,
        mode: G00,
        feed: None,
        modes: ShapeModes::default(),
        elements: vec![],
        notes: vec![],
        ns_moves: (false, false),
        ns_span: blocks[0].span,
        comp: None,
        comp_from: 0,
        corner: None,
        plain: c.machine.g01_cr == crate::G01Cr::Plain,
    };
    for (k, b) in blocks.iter().enumerate() {
        r.block(b, k == 0)?;
    }
    if let Some((_, ask, line)) = r.corner {
        let end = blocks[blocks.len() - 1].span.line;
        return Err(corner::without_line(
            ask.word,
            line,
            &format!("the finishing shape ends (line {end})"),
        ));
    }
    if r.elements.is_empty() {
        return Err(Diagnostic::new(
            blocks[0].span,
            "LS-SHAPE-EMPTY",
            format!("the finishing shape N{ns}..N{nf} does not move"),
            "the shape needs at least one move with X/U or Z/W",
        ));
    }
    Ok(FinishingShape {
        cycle: c.code,
        start: c.start,
        elements: r.elements,
        span: c.span(),
        ns_span: r.ns_span,
        ns_moves: r.ns_moves,
        ns_index: i0,
        nf_index: i1,
        notes: r.notes,
        comp: r.comp,
        comp_from: r.comp_from,
    })
}

/// Reads the shape's blocks with their own modal motion, starting at A.
struct Reader {
    pos: Pt,
    shift: Pt,
    unit: f64,
    /// Motion code in tenths: G00, G01, G02, G03.
    mode: i32,
    feed: Option<f64>,
    modes: ShapeModes,
    elements: Vec<ShapeElement>,
    notes: Vec<Diagnostic>,
    ns_moves: (bool, bool),
    ns_span: Span,
    comp: Option<Side>,
    comp_from: usize,
    /// A line with a corner word whose corner waits for the next line: its element, what
    /// it asks, its line.
    corner: Option<(usize, Ask, u32)>,
    /// System A's plain `C±i` / `R±r` corners (profile `g01_cr = "plain"`).
    plain: bool,
}

/// The alarm for a code not allowed inside a finishing shape.
fn forbidden(w: &Word, what: String) -> Diagnostic {
    Diagnostic::new(
        w.span,
        "LS-SHAPE-CODE",
        format!("{what} is not allowed inside a finishing shape"),
        "between ns and nf only G00–G03, G04, G96–G99 and G40–G42 may stand, and no M98/M99",
    )
}

/// The motion code a shape block writes (with its word), and whether G04 makes it a dwell.
struct BlockCodes<'b> {
    motion: Option<(i32, &'b Word)>,
    dwell: bool,
}

/// The axis, arc and corner words of one shape block, read.
struct Target<'b> {
    /// The end point (the position when the block gives no axis word).
    to: Pt,
    /// X/U and Z/W given.
    x_given: bool,
    z_given: bool,
    arc_words: ArcWords<'b>,
    /// `,C` `,R`, plain `C` `R` (system A's), and `,A`.
    comma: [Option<&'b Word>; 2],
    plain: [Option<&'b Word>; 2],
    angle: Option<&'b Word>,
}

impl Reader {
    /// Read one block of the shape (`first`: the ns block): its codes, its words, and the
    /// element it adds (with the corner a previous block asked for).
    fn block(&mut self, b: &Block, first: bool) -> Result<(), Diagnostic> {
        let BlockCodes { motion, dwell } = self.codes(b)?;
        if first {
            ns_motion(b, motion)?;
        }
        if let Some((t, _)) = motion {
            self.mode = t;
        }
        let mut t = self.words(b, dwell)?;
        if first {
            self.ns_moves = (t.x_given, t.z_given);
            self.ns_span = b.span;
        }
        if let Some(w) = t.angle {
            t.to = corner::line_at_angle(self.pos, t.to, w, (t.x_given, t.z_given))?;
            (t.x_given, t.z_given) = (true, true);
        }
        let corner = corner::ask(t.comma, t.plain, self.unit)?;
        if let (Some(ask), true) = (corner, t.to.dist(self.pos) < 1e-12) {
            return Err(corner::standing_still(ask.word));
        }
        if !t.x_given && !t.z_given {
            if let Some(alarm) = t.arc_words.without_end_point() {
                return Err(alarm);
            }
            return Ok(());
        }
        let from = self.pos;
        let arc = if matches!(self.mode, G02 | G03) {
            let ccw = self.mode == G03;
            let centre = t.arc_words.centre(from, t.to, ccw, self.unit, b.span)?;
            Some(Arc {
                center: centre,
                ccw,
            })
        } else {
            None
        };
        if t.to.dist(from) > 1e-12 {
            self.add(b, from, t.to, arc, corner)?;
        }
        self.pos = t.to;
        Ok(())
    }

    /// The block's G and M codes: the motion code written (with its word), whether G04
    /// makes it a dwell; G96–G99 and G41/G42 put in force; any other code is an alarm.
    fn codes<'b>(&mut self, b: &'b Block) -> Result<BlockCodes<'b>, Diagnostic> {
        let mut motion: Option<(i32, &Word)> = None;
        let mut dwell = false;
        for w in b.words.iter() {
            match w.letter {
                'G' => {
                    let t = w.code_tenths().unwrap_or(-1);
                    match t {
                        G00 | G01 | G02 | G03 => motion = Some((t, w)),
                        G04 => dwell = true,
                        G40 => {}
                        G96 | G97 => self.modes.css = Some(t == G96),
                        G98 | G99 => self.modes.per_rev = Some(t == G99),
                        G41 | G42 if self.comp.is_none() => {
                            self.comp = Some(if t == G41 { Side::Left } else { Side::Right });
                            self.comp_from = self.elements.len();
                        }
                        G41 | G42 => {}
                        _ => return Err(forbidden(w, format!("G{}", w.value))),
                    }
                }
                'M' if w.value == 98.0 || w.value == 99.0 => {
                    return Err(forbidden(w, format!("M{}", w.value)))
                }
                _ => {}
            }
        }
        Ok(BlockCodes { motion, dwell })
    }

    /// The block's other words: the end point, the arc's, the corners', and S, T, F, which
    /// stay in force inside the shape; a word with no meaning here is an alarm.
    fn words<'b>(&mut self, b: &'b Block, dwell: bool) -> Result<Target<'b>, Diagnostic> {
        let mut t = Target {
            to: self.pos,
            x_given: false,
            z_given: false,
            arc_words: ArcWords::default(),
            comma: [None; 2],
            plain: [None; 2],
            angle: None,
        };
        let line = self.mode == G01;
        let arc = matches!(self.mode, G02 | G03);
        for w in b.words.iter() {
            let v = w.value * self.unit;
            match w.letter {
                'c' if line => t.comma[0] = Some(w),
                'r' if line => t.comma[1] = Some(w),
                'a' if line => t.angle = Some(w),
                'C' if self.plain && line => t.plain[0] = Some(w),
                'R' if self.plain && line => t.plain[1] = Some(w),
                'G' | 'M' => {}
                'S' => self.modes.s = Some(w.value),
                'T' if !w.has_point && (0.0..=9999.0).contains(&w.value) => {
                    self.modes.tool = Some(w.value as u32)
                }
                'T' => return Err(t_word(w)),
                'F' => self.feed = Some(w.value),
                'P' if dwell => {}
                'X' | 'U' if dwell => {}
                'X' => (t.to.r, t.x_given) = (v / 2.0 + self.shift.r, true),
                'U' => (t.to.r, t.x_given) = (self.pos.r + v / 2.0, true),
                'Z' => (t.to.z, t.z_given) = (v + self.shift.z, true),
                'W' => (t.to.z, t.z_given) = (self.pos.z + v, true),
                'R' if arc => t.arc_words.r = Some(w),
                'I' if arc => t.arc_words.i = Some(w),
                'K' if arc => t.arc_words.k = Some(w),
                _ => return Err(unused(w)),
            }
        }
        Ok(t)
    }

    /// Add the element `from`..`to` of block `b`; the corner a previous line asked for is cut
    /// between that line and this one, and the corner this block asks for waits for the next.
    fn add(
        &mut self,
        b: &Block,
        from: Pt,
        to: Pt,
        arc: Option<Arc>,
        corner: Option<Ask>,
    ) -> Result<(), Diagnostic> {
        let mut element = ShapeElement {
            from,
            to,
            arc,
            rapid: self.mode == G00,
            feed: self.feed,
            modes: self.modes,
            span: b.span,
        };
        if let Some((k, ask, line)) = self.corner.take() {
            if element.rapid || element.arc.is_some() {
                let what = if element.rapid { "a rapid" } else { "an arc" };
                return Err(corner::without_line(
                    ask.word,
                    line,
                    &format!("{what} comes (line {})", b.span.line),
                ));
            }
            // the line before ends where the piece starts; the piece is of its block
            let before = self.elements[k];
            let piece = corner::make(before.from, before.to, element.to, &ask, line)?;
            self.elements[k].to = piece.start;
            self.elements.push(ShapeElement {
                from: piece.start,
                to: piece.end,
                arc: piece.arc,
                ..before
            });
            element.from = piece.end;
        }
        self.elements.push(element);
        if let Some(ask) = corner {
            self.corner = Some((self.elements.len() - 1, ask, b.span.line));
        }
        Ok(())
    }
}

/// The ns block must be G00 or G01 (PS065).
fn ns_motion(b: &Block, motion: Option<(i32, &Word)>) -> Result<(), Diagnostic> {
    match motion {
        Some((G00 | G01, _)) => Ok(()),
        Some((_, w)) => Err(Diagnostic::new(
            w.span,
            "PS065",
            "the first block of the finishing shape (ns) must be G00 or G01",
            "start the shape with a straight G00 or G01 move from the start point",
        )),
        None => Err(Diagnostic::new(
            b.seq_span.unwrap_or(b.span),
            "PS065",
            "the first block of the finishing shape (ns) must be G00 or G01",
            "write G00 or G01 in the ns block",
        )),
    }
}

/// The alarm for a T word that is not `Tttoo`.
fn t_word(w: &Word) -> Diagnostic {
    Diagnostic::new(
        w.span,
        "LS-T-WORD",
        "T must be four digits Tttoo",
        "write e.g. T0101: tool 01 with offset 01",
    )
}

/// The alarm for a word with no meaning in a shape block.
fn unused(w: &Word) -> Diagnostic {
    Diagnostic::new(
        w.span,
        "LS-WORD-UNUSED",
        format!(
            "address {} has no meaning in this block of the finishing shape",
            gcode::address(w.letter)
        ),
        "remove the word, or use the code that takes it (e.g. R with G02/G03)",
    )
}
