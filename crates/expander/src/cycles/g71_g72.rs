//! G71 / G72 — stock removal in turning / facing, type I and II (spec/cycles.md).
//!
//! ```text
//! G71 U(Δd) R(e);                      G72 W(Δd) R(e);          depth and retract: retained
//! G71 P(ns) Q(nf) U(Δu) W(Δw) F S T;   G72 P(ns) Q(nf) U(Δu) W(Δw) F S T;
//! ```
//! Both cycles are one algorithm in a frame (u, v) with the start point A at the origin:
//! u runs along the cuts (Z for G71, X for G72) in the direction the shape travels from B
//! to C, v runs into the material (X for G71, Z for G72) in the direction of the ns move
//! A → B. The shape is moved by the allowances (Δu/2 in X as a radius, Δw in Z) — a
//! translation, as FANUC does — and the material between the start level v = 0 and the
//! moved shape is cut in layers.
//!
//! Motion (FANUC 0i-TF / `GSK980TDi`, with the choices the manuals leave implicit):
//! 1. Layer i lies at depth v = i·Δd; the layers stop above the deepest point of the moved
//!    shape, and the last one is the last full Δd: the remainder (< Δd) is taken by step 4.
//! 2. A layer that starts at the A column is reached by the ns block's motion (G00 rapid,
//!    G01 feed) along v; it is cut along u up to the moved shape, then the tool retracts
//!    e at 45° (up e and back e, at cutting feed) and returns along u by rapid.
//! 3. Type II (pockets): a layer meets the shape more than once. Each stretch is cut in
//!    order of u. Between stretches the tool either follows the shape over a bump that
//!    lies within the current layer (a feed), or retracts e at 45°, rapids up to the
//!    deepest layer already cut over the whole way (less e), across, down to where the
//!    shape crosses the previous layer, and follows the shape down into the pocket
//!    (a feed), so no rapid crosses uncut material.
//! 4. Back to A, then one pass along the moved shape: A → B' as the ns block (G00/G01),
//!    B' → C' fed with the shape's arcs; then a rapid back to A.
//!
//! Type I (the ns block moves along v only) requires the moved shape to be monotonic in
//! both axes: u never decreasing, v never increasing after B' (PS064). Type II (the ns block
//! moves in both axes) requires u never decreasing only. Arcs are flattened (sagitta
//! 0.1 µm) for the layer ends and the pocket walks; the final pass keeps them exact. The
//! layer moves carry the cycle block's span; the final pass carries the shape's lines.

use super::contour::{self, FinishingShape};
use super::{passes, Cycle, Move, Output};
use crate::codes::G72;
use crate::{Control, Diagnostic, Pt, Span};

/// Most layers one cycle may cut (a microscopic Δd is an error, not a hang).
const MAX_LAYERS: f64 = 200_000.0;
/// Flattening tolerance for arcs (sagitta), mm.
const SAGITTA: f64 = 1e-4;
/// Geometric tolerance, mm.
const EPS: f64 = 1e-9;

/// The words of one stock removal: depth of cut, retract, the allowance the layers stop
/// at and the one the final pass follows (`(z, r)`, r a radius), and the form's rules.
struct Removal {
    /// A note for the report (the Haas I/K reading), if any.
    note: Option<String>,
    dd: f64,
    e: f64,
    layers_off: Pt,
    final_off: Pt,
    /// Haas: a last layer at the deepest point of the moved shape (dialects.md §7 T4).
    last_layer_at_shape: bool,
    /// Haas `R1`: type II whatever the ns block gives.
    force_type2: bool,
}

/// Expand one G71 or G72 block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    let g72 = c.code == G72;
    let haas = c.machine.control == Control::Haas;
    if !c.words.has('P') && !c.words.has('Q') {
        if haas || c.words.has('D') {
            return Err(one_block_only(c));
        }
        return depth_block(c, g72);
    }
    let removal = removal_words(c, g72, haas)?;
    let shape = contour::read(c)?;
    let (shape, returns) = if haas {
        super::shape_return::trim(shape, g72)
    } else {
        (shape, None)
    };
    let frame = Frame::new((c.code, c.span()), &shape, g72, removal.force_type2)?;
    let poly = Poly::new(&shape, &frame, removal.layers_off)?;
    let levels = poly.v_max / removal.dd;
    if levels > MAX_LAYERS {
        return Err(c.alarm(
            "LS-TOO-MANY-LAYERS",
            format!("depth of cut {} mm makes {levels:.0} layers", removal.dd),
            "give a larger depth of cut Δd",
        ));
    }
    let mut moves = rough(&poly, &frame, &removal, shape.elements[0].rapid);
    // 4. the final pass along the moved shape, then back to A
    moves.extend(passes::moved(&shape, removal.final_off));
    moves.push(Move::rapid(shape.start));
    let mut out = Output {
        moves,
        resume_at: shape.resume_at(c.index, &c.program.blocks),
        warnings: vec![],
        ..Output::default()
    };
    if let Some(note) = removal.note {
        out.warnings.push(c.alarm("LS-HAAS-IK", note, ""));
    }
    out.warnings.extend(returns);
    out.intended.push((
        crate::IntendedKind::FinishingContour,
        shape.intended_path(0.001),
    ));
    Ok(out)
}

/// `LinuxCNC`'s G71/G72 (docs/linuxcnc.md, "G70, G71, G72"): FANUC's type II layers of
/// depth `dd` with the 45° retract `e` over `shape` (already offset by `LinuxCNC`'s D), then
/// the pass along the shape; the tool stays at its end. `code` and `span`: the cycle (G71 or
/// G72 canonical) and its block, for the alarms.
pub(crate) fn linuxcnc_rough(
    (code, span): (i32, Span),
    shape: &FinishingShape,
    dd: f64,
    e: f64,
) -> Result<Vec<Move>, Diagnostic> {
    let g72 = code == G72;
    let removal = Removal {
        note: None,
        dd,
        e,
        layers_off: Pt::new(0.0, 0.0),
        final_off: Pt::new(0.0, 0.0),
        last_layer_at_shape: false,
        force_type2: true,
    };
    let frame = Frame::new((code, span), shape, g72, true)?;
    let poly = Poly::new(shape, &frame, removal.layers_off)?;
    if poly.v_max / dd > MAX_LAYERS {
        return Err(Diagnostic::new(
            span,
            "LS-TOO-MANY-LAYERS",
            format!("depth of cut I{dd} makes {:.0} layers", poly.v_max / dd),
            "give a larger depth of cut I",
        ));
    }
    let mut moves = rough(&poly, &frame, &removal, false);
    moves.extend(passes::moved(shape, removal.final_off));
    Ok(moves)
}

/// The depth of cut and the allowances: the Haas/FS15 one-block form (D in the block), or
/// the FANUC two-block form (the retained depth block); each form where the control does
/// not read it is an alarm naming it.
fn removal_words(c: &mut Cycle, g72: bool, haas: bool) -> Result<Removal, Diagnostic> {
    if let Some(d) = c.words.block.get('D') {
        if !c.machine.one_block_cycles() {
            return Err(Diagnostic::new(
                d.span,
                "LS-ONE-BLOCK-FORM",
                format!(
                    "{} with D in one block is the Haas/FS15 form: run with --control haas (this control is {})",
                    code_name(g72),
                    c.machine.control.key()
                ),
                format!(
                    "under {} write the two-block form {}, or run with --control haas (or fs15_format = true in the machine profile)",
                    c.machine.control.key(),
                    if g72 { "G72 W(Δd) R(e); G72 P Q U W F" } else { "G71 U(Δd) R(e); G71 P Q U W F" }
                ),
            ));
        }
        one_block(c, g72)
    } else if haas {
        Err(c.alarm(
            "PS062",
            format!("Haas {} without D (depth of cut)", code_name(g72)),
            "give the depth of each layer as D (mm); Setting 72, the machine's default depth, is not simulated",
        ))
    } else {
        two_block(c, g72)
    }
}

/// 1.–3. the roughing layers in the frame of the cycle, mapped back to (z, r).
fn rough(poly: &Poly, frame: &Frame, removal: &Removal, ns_rapid: bool) -> Vec<Move> {
    let mut r = Rough {
        poly,
        dd: removal.dd,
        e: removal.e,
        ns_rapid,
        cur: (0.0, 0.0),
        out: vec![],
    };
    r.layers(removal.last_layer_at_shape);
    r.out
        .iter()
        .map(|&(rapid, p, span)| {
            let mut m = if rapid {
                Move::rapid(frame.to_pt(p))
            } else {
                Move::feed(frame.to_pt(p))
            };
            m.span = span;
            m
        })
        .collect()
}

fn code_name(g72: bool) -> &'static str {
    if g72 {
        "G72"
    } else {
        "G71"
    }
}

/// The alarm for a first block (`G71 U R`) under a control that has only the one-block form.
fn one_block_only(c: &Cycle) -> Diagnostic {
    let g72 = c.code == G72;
    c.alarm(
        "LS-ONE-BLOCK-FORM",
        format!(
            "{} needs P and Q: {} reads the one-block form",
            code_name(g72),
            c.machine.control.title()
        ),
        format!(
            "write {} P(ns) Q(nf) U(Δu) W(Δw) D(depth) F in one block",
            code_name(g72)
        ),
    )
}

/// FANUC/GSK second block `P Q U W F`: Δd and e from the retained first block.
fn two_block(c: &mut Cycle, g72: bool) -> Result<Removal, Diagnostic> {
    let du = c.words.mm('U', c.unit).unwrap_or(0.0) / 2.0; // Δu/2: radius
    let dw = c.words.mm('W', c.unit).unwrap_or(0.0);
    let retained = if g72 { c.retained.g72 } else { c.retained.g71 };
    let Some((dd, e)) = retained else {
        return Err(c.alarm(
            "PS062",
            format!("no depth of cut for {}", super::name(c.code)),
            if g72 {
                "write G72 W(Δd) R(e) before the G72 P Q block"
            } else {
                "write G71 U(Δd) R(e) before the G71 P Q block"
            },
        ));
    };
    let off = Pt::new(dw, du);
    Ok(Removal {
        note: None,
        dd,
        e,
        layers_off: off,
        final_off: off,
        last_layer_at_shape: false,
        force_type2: false,
    })
}

/// Haas (and FANUC FS15) one block `P Q U W D [I K] F S T [R1]` (spec/dialects.md §3.2):
/// D is the depth of each layer in mm (calculator type, G72: along Z); the retract is Haas
/// Setting 73 (`haas.setting73`), under FS15 the retained `G71 R(e)` (else 0).
///
/// **Interpretation** of I/K (Haas calls them only a "rough pass allowance"): the layers
/// stop at the shape moved by (U/2 + I, W + K) (I a radius); the final pass follows the
/// shape moved by (U/2, W). With I = K = 0 this is the FANUC G71, plus (Haas) a last layer
/// at the moved shape's deepest point before the final pass (dialects.md §7 T4).
fn one_block(c: &mut Cycle, g72: bool) -> Result<Removal, Diagnostic> {
    let haas = c.machine.control == Control::Haas;
    let d = c.words.take('D').expect("the caller checked D");
    let dd = d.value * c.unit;
    if dd.is_nan() || dd <= 0.0 {
        return Err(Diagnostic::new(
            d.span,
            "PS062",
            format!("depth of cut D{} must be positive", d.value),
            "give the depth of each layer as a positive D in mm, e.g. D2.",
        ));
    }
    let du = c.words.mm('U', c.unit).unwrap_or(0.0) / 2.0;
    let dw = c.words.mm('W', c.unit).unwrap_or(0.0);
    let (i, k) = if haas {
        (
            c.words.mm('I', c.unit).unwrap_or(0.0),
            c.words.mm('K', c.unit).unwrap_or(0.0),
        )
    } else {
        (0.0, 0.0)
    };
    let force_type2 = match c.words.take('R') {
        Some(r) if haas && r.value == 1.0 && !r.has_point => true,
        Some(r) => {
            return Err(Diagnostic::new(
                r.span,
                "LS-WORD-UNUSED",
                format!(
                    "R{} has no meaning in a one-block {}",
                    r.value,
                    code_name(g72)
                ),
                "Haas reads only R1 here (type II, YASNAC mode); the retract is Setting 73",
            ))
        }
        None => false,
    };
    let e = if haas {
        c.machine.haas.setting73
    } else {
        let retained = if g72 { c.retained.g72 } else { c.retained.g71 };
        retained.map_or(0.0, |r| r.1)
    };
    let note = (i != 0.0 || k != 0.0).then(|| {
        format!(
            "{}: the layers stop at the shape moved by X{:+.4} (diameter) Z{:+.4} (U + 2I, W + K); the final pass follows it moved by X{:+.4} Z{:+.4} (U, W) — Interpretation of the Haas rough allowance I/K",
            code_name(g72),
            2.0 * (du + i),
            dw + k,
            2.0 * du,
            dw
        )
    });
    Ok(Removal {
        note,
        dd,
        e,
        layers_off: Pt::new(dw + k, du + i),
        final_off: Pt::new(dw, du),
        last_layer_at_shape: haas,
        force_type2,
    })
}

/// The first block: store Δd and e (each keeps its retained value when omitted).
fn depth_block(c: &mut Cycle, g72: bool) -> Result<Output, Diagnostic> {
    let (letter, prev) = if g72 {
        ('W', c.retained.g72)
    } else {
        ('U', c.retained.g71)
    };
    let d_word = c.words.take(letter);
    let e_word = c.words.take('R');
    let dd = d_word.map_or(prev.map(|p| p.0), |w| Some(w.value * c.unit));
    let e = e_word.map_or(prev.map_or(0.0, |p| p.1), |w| w.value * c.unit);
    let Some(dd) = dd else {
        return Err(c.alarm(
            "PS062",
            format!("{} without a depth of cut", super::name(c.code)),
            format!("write the depth of cut per layer as {letter}(Δd)"),
        ));
    };
    if dd <= 0.0 {
        return Err(Diagnostic::new(
            d_word.map_or(c.span(), |w| w.span),
            "PS062",
            format!("depth of cut {letter}{dd} must be positive"),
            "give the depth of cut per layer as a positive value",
        ));
    }
    if e < 0.0 {
        return Err(Diagnostic::new(
            e_word.map_or(c.span(), |w| w.span),
            "PS062",
            format!("retract R{e} must not be negative"),
            "give the 45° retract e as a positive value (or 0)",
        ));
    }
    if g72 {
        c.retained.g72 = Some((dd, e));
    } else {
        c.retained.g71 = Some((dd, e));
    }
    Ok(Output::default())
}

/// The (u, v) frame of one cycle: A at the origin, u along the cuts, v into the material.
struct Frame {
    a: Pt,
    swap: bool,
    su: f64,
    sv: f64,
    /// Type II: the ns block moves in both axes.
    type2: bool,
}

impl Frame {
    fn new(
        (code, span): (i32, Span),
        shape: &FinishingShape,
        g72: bool,
        force_type2: bool,
    ) -> Result<Self, Diagnostic> {
        let (a, b, end) = (shape.start, shape.b(), shape.c());
        let (x, z) = shape.ns_moves;
        let (x, z) = if force_type2 { (true, true) } else { (x, z) };
        let (infeed, along) = if g72 { (z, x) } else { (x, z) };
        let (ax, other) = if g72 { ("Z", "X") } else { ("X", "Z") };
        if !infeed {
            return Err(Diagnostic::new(
                shape.ns_span,
                "LS-SHAPE-NS",
                format!(
                    "the ns block of {} must move in {ax} (type I: {ax} only; type II: {ax} and {other})",
                    super::name(code)
                ),
                format!("start the shape with a G00/G01 move in {ax} from the start point"),
            ));
        }
        let (sv, su) = if g72 {
            ((b.z - a.z).signum(), (end.r - b.r).signum())
        } else {
            ((b.r - a.r).signum(), (end.z - b.z).signum())
        };
        if (if g72 { b.z - a.z } else { b.r - a.r }).abs() < EPS {
            return Err(Diagnostic::new(
                shape.ns_span,
                "LS-SHAPE-NS",
                format!("the ns block does not move in {ax}: the cut depth direction is unknown"),
                format!("the ns block moves from the start point toward the shape in {ax}"),
            ));
        }
        if (if g72 { end.r - b.r } else { end.z - b.z }).abs() < EPS {
            return Err(Diagnostic::new(
                span,
                "PS064",
                format!("the finishing shape does not travel in {other} from B to C"),
                format!(
                    "{} cuts along {other}: the shape must run along {other}",
                    super::name(code)
                ),
            ));
        }
        Ok(Self {
            a,
            swap: g72,
            su,
            sv,
            type2: along,
        })
    }

    fn to_uv(&self, p: Pt) -> (f64, f64) {
        let (dz, dr) = (p.z - self.a.z, p.r - self.a.r);
        if self.swap {
            (self.su * dr, self.sv * dz)
        } else {
            (self.su * dz, self.sv * dr)
        }
    }

    fn to_pt(&self, (u, v): (f64, f64)) -> Pt {
        let (a, b) = (self.su * u, self.sv * v);
        if self.swap {
            Pt::new(self.a.z + b, self.a.r + a)
        } else {
            Pt::new(self.a.z + a, self.a.r + b)
        }
    }
}

/// The moved shape as a polyline in (u, v), arcs flattened.
struct Poly {
    pts: Vec<(f64, f64)>,
    /// The span of the shape block each segment `pts[j] → pts[j+1]` comes from.
    spans: Vec<Span>,
    /// The layer at the A column is free before the first crossing (type I).
    free_start: bool,
    v_max: f64,
}

impl Poly {
    fn new(shape: &FinishingShape, f: &Frame, off: Pt) -> Result<Self, Diagnostic> {
        let els: Vec<_> = shape.elements.iter().map(|e| e.shifted(off)).collect();
        let mut pts = vec![];
        let mut spans = vec![];
        let b_moved = f.to_uv(els[0].to);
        if f.type2 {
            // Type II: A → B' is part of the shape. The allowance moves B' and not A, so a
            // ns block that stays at A's Z (`G00 X20 Z2` from Z2) puts B' up to W beyond A:
            // the leg starts at B''s column then, rather than running backwards (a false
            // PS064 on a sound program).
            let a = f.to_uv(shape.start);
            pts.push((a.0.min(b_moved.0), a.1));
        }
        pts.push(b_moved);
        if f.type2 {
            spans.push(els[0].span);
        }
        for e in &els[1..] {
            match e.arc {
                None => {
                    pts.push(f.to_uv(e.to));
                    spans.push(e.span);
                }
                Some(arc) => {
                    let rad = arc.center.dist(e.from);
                    let a0 = (e.from.r - arc.center.r).atan2(e.from.z - arc.center.z);
                    let a1 = (e.to.r - arc.center.r).atan2(e.to.z - arc.center.z);
                    let tau = std::f64::consts::TAU;
                    let mut sweep = a1 - a0;
                    if arc.ccw && sweep <= 0.0 {
                        sweep += tau;
                    }
                    if !arc.ccw && sweep >= 0.0 {
                        sweep -= tau;
                    }
                    let step = 2.0 * (1.0 - SAGITTA / rad.max(SAGITTA * 2.0)).acos();
                    let n = ((sweep.abs() / step).ceil() as usize).clamp(1, 100_000);
                    for k in 1..=n {
                        let t = a0 + sweep * k as f64 / n as f64;
                        let p = if k == n {
                            e.to
                        } else {
                            Pt::new(arc.center.z + rad * t.cos(), arc.center.r + rad * t.sin())
                        };
                        pts.push(f.to_uv(p));
                        spans.push(e.span);
                    }
                }
            }
        }
        // monotonic checks (PS064)
        for (j, w) in pts.windows(2).enumerate() {
            let (p, q) = (w[0], w[1]);
            if q.0 < p.0 - 1e-6 {
                return Err(not_monotonic(spans[j], f.swap, true));
            }
            if !f.type2 && q.1 > p.1 + 1e-6 {
                return Err(not_monotonic(spans[j], f.swap, false));
            }
        }
        let v_max = pts.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        Ok(Self {
            pts,
            spans,
            free_start: !f.type2,
            v_max,
        })
    }

    /// The stretches of u where the layer at depth `c` is clear of the moved shape.
    fn stretches(&self, c: f64) -> Vec<(Option<Cross>, Option<Cross>)> {
        let free = |p: (f64, f64)| p.1 >= c - EPS;
        let mut out = vec![];
        let mut open: Option<Option<Cross>> = self.free_start.then_some(None);
        if !self.free_start && free(self.pts[0]) {
            open = Some(Some(Cross {
                seg: 0,
                p: self.pts[0],
            }));
        }
        for (j, w) in self.pts.windows(2).enumerate() {
            let (p, q) = (w[0], w[1]);
            if free(p) == free(q) {
                continue;
            }
            let t = ((c - p.1) / (q.1 - p.1)).clamp(0.0, 1.0);
            let x = Cross {
                seg: j,
                p: (p.0 + t * (q.0 - p.0), c),
            };
            match open.take() {
                Some(s) => out.push((s, Some(x))),
                None => open = Some(Some(x)),
            }
        }
        if let Some(s) = open {
            out.push((s, None));
        }
        // a stretch from the A column that ends before it (type I with Δw behind A)
        out.retain(|(s, e)| {
            let u0 = s.map_or(0.0, |s| s.p.0);
            e.is_none_or(|e| e.p.0 > u0 + EPS)
        });
        out
    }

    /// The shallowest point of the shape over u in [lo, hi] (∞ where the shape is not).
    fn v_min(&self, lo: f64, hi: f64) -> f64 {
        let mut m = f64::INFINITY;
        for w in self.pts.windows(2) {
            let (p, q) = (w[0], w[1]);
            if q.0 < lo || p.0 > hi {
                continue;
            }
            let at = |u: f64| {
                if (q.0 - p.0).abs() < EPS {
                    p.1.min(q.1)
                } else {
                    p.1 + (q.1 - p.1) * ((u - p.0) / (q.0 - p.0)).clamp(0.0, 1.0)
                }
            };
            m = m.min(at(lo.max(p.0))).min(at(hi.min(q.0)));
        }
        m
    }

    /// Walking back along the shape from `x`, the first point at depth `level` or above.
    fn back_to(&self, x: Cross, level: f64) -> Cross {
        let mut j = x.seg;
        loop {
            let p = self.pts[j];
            if p.1 <= level + EPS {
                let q = if j == x.seg { x.p } else { self.pts[j + 1] };
                let t = if (q.1 - p.1).abs() < EPS {
                    0.0
                } else {
                    ((level - p.1) / (q.1 - p.1)).clamp(0.0, 1.0)
                };
                return Cross {
                    seg: j,
                    p: (p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)),
                };
            }
            if j == 0 {
                return Cross { seg: 0, p };
            }
            j -= 1;
        }
    }
}

/// A point on the moved shape: on segment `seg`, at `p`.
#[derive(Debug, Clone, Copy)]
struct Cross {
    seg: usize,
    p: (f64, f64),
}

/// The layer cutting state.
struct Rough<'a> {
    poly: &'a Poly,
    dd: f64,
    e: f64,
    ns_rapid: bool,
    cur: (f64, f64),
    /// (rapid, end point in (u, v), span override)
    out: Vec<(bool, (f64, f64), Option<Span>)>,
}

impl Rough<'_> {
    fn go(&mut self, rapid: bool, p: (f64, f64), span: Option<Span>) {
        if (p.0 - self.cur.0).abs() > EPS || (p.1 - self.cur.1).abs() > EPS {
            self.out.push((rapid, p, span));
            self.cur = p;
        }
    }

    /// Steps 1–3 and the return to A; `last_at_shape`: one more layer at the deepest point
    /// of the moved shape (Haas).
    fn layers(&mut self, last_at_shape: bool) {
        let n = ((self.poly.v_max - EPS) / self.dd).ceil() as usize;
        let mut levels: Vec<f64> = (1..n).map(|i| i as f64 * self.dd).collect();
        if last_at_shape && self.poly.v_max > EPS {
            levels.push(self.poly.v_max);
        }
        let mut prev = 0.0;
        for (i, &c) in levels.iter().enumerate() {
            let i = i + 1;
            let stretches = self.poly.stretches(c);
            for (k, &(start, end)) in stretches.iter().enumerate() {
                match start {
                    // 2. from the A column, by the ns block's motion
                    None => {
                        self.travel(0.0, i);
                        self.go(self.ns_rapid, (0.0, c), None);
                    }
                    Some(s) => {
                        let over = k > 0
                            && stretches[k - 1].1.is_some_and(|pe| {
                                self.poly.v_min(pe.p.0, s.p.0) >= prev - EPS && self.cur == pe.p
                            });
                        if over {
                            // 3. over a bump within this layer: follow the shape
                            let pe = stretches[k - 1].1.expect("checked");
                            self.follow(pe, s);
                        } else {
                            // 3. into a pocket: across above the cut layers, down the wall
                            let w = self.poly.back_to(s, prev);
                            self.travel(w.p.0, i);
                            self.go(true, w.p, None);
                            self.follow(w, s);
                        }
                    }
                }
                let u_end = end.map_or(self.poly.pts[self.poly.pts.len() - 1].0, |x| x.p.0);
                self.go(false, (u_end, c), None);
                let bump_next = stretches.get(k + 1).is_some_and(|(ns, _)| {
                    ns.is_some_and(|ns| self.poly.v_min(u_end, ns.p.0) >= prev - EPS)
                });
                if !bump_next {
                    // 2. retract e at 45°
                    self.go(false, ((u_end - self.e).max(0.0), c - self.e), None);
                }
            }
            prev = c;
        }
        self.travel(0.0, levels.len());
        self.go(true, (0.0, 0.0), None);
    }

    /// Rapid up to the deepest cut layer that spans the way to `u` (less e), then across.
    fn travel(&mut self, u: f64, cut: usize) {
        let (lo, hi) = (u.min(self.cur.0), u.max(self.cur.0));
        let gm = self.poly.v_min(lo, hi);
        let j = (((gm + EPS) / self.dd).floor().max(0.0) as usize).min(cut);
        let level = if j == 0 {
            0.0
        } else {
            (j as f64 * self.dd - self.e).max(0.0)
        };
        let level = level.min(self.cur.1);
        self.go(true, (self.cur.0, level), None);
        self.go(true, (u, level), None);
    }

    /// Feed along the shape from `a` to `b` (both on it, `a` first).
    fn follow(&mut self, a: Cross, b: Cross) {
        for j in a.seg..b.seg {
            let span = Some(self.poly.spans[j]);
            self.go(false, self.poly.pts[j + 1], span);
        }
        let span = Some(self.poly.spans[b.seg]);
        self.go(false, b.p, span);
    }
}

/// PS064 at the shape block that breaks monotony.
fn not_monotonic(span: Span, g72: bool, along: bool) -> Diagnostic {
    let axis = match (g72, along) {
        (false, true) | (true, false) => "Z",
        _ => "X",
    };
    Diagnostic::new(
        span,
        "PS064",
        format!("the finishing shape is not monotonic in {axis} here"),
        if along {
            "the cut axis must only advance along the shape; split the part into two cycles"
        } else {
            "type I needs a shape that only climbs back toward the start; use type II (X and Z in the ns block) for pockets"
        },
    )
}
