//! G75.1 — GSK radial trapezoid groove cycle (seed 000, spec/cycles.md).
//!
//! ```text
//! G75.1 X Z P(Δi) Q(Δk) H(h) D(d) A(a) B(b) L(p);                          geometry
//! G75.1 R(e) V(Δv) U(Δu) W(Δw) I(w) J(0|1|2) A(r1) B(r2) D(r3) E(r4) P(abde);  process
//! ```
//! The block holding H is the geometry block; it is kept in the retained state and the
//! cycle runs when the process block (the next block, a G75.1 without H) is read.
//!
//! All geometry is computed in a local frame of the groove: `u` along Z toward the far side
//! (sign of D), `v` along the radius toward the floor (sign of H), both from the mouth corner
//! P1. Points are mapped back to (z, r) at the end, arcs flipping direction when the map is
//! a reflection.
//!
//! The tool: with I, a blade of width |I| whose reference is its start-side corner and
//! which extends toward the far side (the spec's Interpretation); without I, the tool is
//! taken as a point (GSK: "a pointed tool, G41/G42 apply"), width 0 — the interpreter does
//! not know the tool table's blade width. The start-side corner traces the start flank, the
//! floor-start corner and the mouth-start corner; the far corner (reference + width) traces
//! the far flank and its corners.
//!
//! Choices where the seed is silent:
//! - Layer 1 plunges start at the highest point of the groove's mouth (P1's level with L0,
//!   P4's level with a sloped mouth), so the Z rapids between plunges stay out of the stock.
//! - The roughing contour pass and the finishing pass return to A11 / the start point by
//!   rapids along that same level.
//! - U and W are unsigned (a negative value is an alarm); I negative means positive (seed).

pub(crate) mod pairing;
mod shape;

use pairing::Break;

use super::{Cycle, Move, Output, MAX_MOVES};
use crate::{Arc, Diagnostic, IntendedKind, Motion, Pt, ToolHint};
use shape::*;
pub use shape::{groove_shape, Corner, Trapezoid};

/// The geometry block's words, kept until the process block arrives.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Geometry {
    /// The groove's shape (start point, depth, width, angles).
    shape: Trapezoid,
    /// Radial infeed per peck, diameter, mm.
    di: f64,
    /// Z shift between plunges, mm.
    dk: f64,
    /// Line of the geometry block (for messages).
    line: u32,
    /// Index of the geometry block in its program, and the program's O number.
    at: (usize, Option<u32>),
}

/// Expand one G75.1 block: store the geometry block, or run the cycle on the process block.
pub(super) fn run(c: &mut Cycle) -> Result<Output, Diagnostic> {
    if c.words.has('H') {
        geometry_block(c)?;
        return Ok(Output::default());
    }
    let Some(g) = c.retained.g75_1.take() else {
        return Err(pairing::alarm(c.span(), None, Break::NoGeometry));
    };
    if !pairing::follows(&g, c.program, c.index) {
        return Err(pairing::alarm(c.span(), Some(&g), Break::Interrupted));
    }
    process_block(c, &g)
}

fn geometry_block(c: &mut Cycle) -> Result<(), Diagnostic> {
    if let Some(g) = &c.retained.g75_1 {
        return Err(pairing::alarm(c.span(), Some(g), Break::SecondGeometry));
    }
    let x = c.x_target()?;
    let z = c.z_target()?;
    let pq = c.machine.pq_mm();
    let p = c.words.increments('P', pq)?;
    let q = c.words.increments('Q', pq)?;
    let h = c.words.mm('H', c.unit);
    let d = c.words.mm('D', c.unit);
    let a = c.words.take('A').map(|w| w.value);
    let b = c.words.take('B').map(|w| w.value);
    let l = c.words.take('L').map(|w| w.value);
    let required = [
        ("H", h, "the groove depth (diameter, signed)"),
        ("D", d, "the floor width (signed)"),
        ("P", p, "the radial infeed per peck (diameter)"),
        ("Q", q, "the Z shift between plunges"),
    ];
    for (name, v, what) in required {
        match v {
            Some(v) if v != 0.0 => {}
            _ => {
                return Err(c.alarm(
                    "LS-G75.1-WORD",
                    format!("G75.1 geometry block: {name} is missing or 0"),
                    format!("give {name}: {what}"),
                ))
            }
        }
    }
    let (p, q) = (p.unwrap_or(0.0), q.unwrap_or(0.0));
    for (name, v) in [("P", p), ("Q", q)] {
        if v < 0.0 {
            return Err(c.alarm(
                "LS-G75.1-WORD",
                format!("G75.1: {name} is negative"),
                format!("{name} is unsigned; the directions come from the signs of H and D"),
            ));
        }
    }
    let (a, b, l) = (a.unwrap_or(90.0), b.unwrap_or(90.0), l.unwrap_or(0.0));
    for (name, v, ok, range) in [
        ("A", a, a > 0.0 && a <= 90.0, "0 < A ≤ 90"),
        ("B", b, b > 0.0 && b <= 90.0, "0 < B ≤ 90"),
        ("L", l, (0.0..90.0).contains(&l), "0 ≤ L < 90"),
    ] {
        if !ok {
            return Err(c.alarm(
                "LS-G75.1-ANGLE",
                format!("G75.1: angle {name}{v} is out of its range"),
                format!("the angle must be {range} degrees"),
            ));
        }
    }
    let shape = Trapezoid {
        start: Pt::new(z.unwrap_or(c.start.z), x.unwrap_or(c.start.r)),
        h: h.unwrap_or(0.0),
        d: d.unwrap_or(0.0),
        a,
        b,
        l,
        corners: [Corner::Sharp; 4],
    };
    c.retained.g75_1 = Some(Geometry {
        shape,
        di: p,
        dk: q,
        line: c.span().line,
        at: (c.index, c.program.number),
    });
    Ok(())
}

/// The moves of the cycle, built in the local frame.
struct Path<'t> {
    shape: &'t Trapezoid,
    moves: Vec<Move>,
    hint: ToolHint,
}

impl Path<'_> {
    fn go(&mut self, motion: Motion, q: Uv) {
        let mut m = if motion == Motion::Rapid {
            Move::rapid(self.shape.to_pt(q))
        } else {
            Move::feed(self.shape.to_pt(q))
        };
        m.hint = self.hint;
        self.moves.push(m);
    }
    fn rapid(&mut self, q: Uv) {
        self.go(Motion::Rapid, q);
    }
    fn feed(&mut self, q: Uv) {
        self.go(Motion::Feed, q);
    }
    fn arc(&mut self, q: Uv, centre: Uv, ccw: bool) {
        let mut m = Move::feed(self.shape.to_pt(q));
        m.arc = Some(Arc {
            center: self.shape.to_pt(centre),
            ccw: ccw != self.shape.mirrored(),
        });
        m.hint = self.hint;
        self.moves.push(m);
    }
}

fn process_block(c: &mut Cycle, g: &Geometry) -> Result<Output, Diagnostic> {
    let e = c.words.mm('R', c.unit).unwrap_or(0.0);
    let dv = c.words.mm('V', c.unit);
    let du = c.words.mm('U', c.unit).unwrap_or(0.0);
    let dw = c.words.mm('W', c.unit).unwrap_or(0.0);
    let i_word = c.words.mm('I', c.unit).map(f64::abs);
    let w = i_word.or(c.tool_blade.map(|b| b.0));
    let j = c.words.take('J');
    let r = ['A', 'B', 'D', 'E'].map(|l| c.words.mm(l, c.unit));
    let kinds = c.words.take('P');
    let alarm = |c: &Cycle, code, message: String, help: &str| Err(c.alarm(code, message, help));

    // -- words of the process block.
    let j = match j {
        None => 0,
        Some(j) if !j.has_point && [0.0, 1.0, 2.0].contains(&j.value) => j.value as u8,
        Some(j) => {
            return alarm(
                c,
                "LS-G75.1-WORD",
                format!("G75.1 J{} is not a path type", j.value),
                "J0 rough only, J1 rough + finish, J2 finish only",
            )
        }
    };
    let digits = match kinds {
        None => [0u8; 4],
        Some(p) if !p.has_point && (0.0..=1111.0).contains(&p.value) && p.value.fract() == 0.0 => {
            let v = p.value as u32;
            let d = [v / 1000 % 10, v / 100 % 10, v / 10 % 10, v % 10];
            if d.iter().any(|&x| x > 1) {
                return alarm(
                    c,
                    "LS-G75.1-WORD",
                    format!("G75.1 P{v}: each corner digit must be 0 or 1"),
                    "P(a)(b)(d)(e): 0 a straight chamfer, 1 a round, e.g. P1001",
                );
            }
            d.map(|x| x as u8)
        }
        Some(p) => {
            return alarm(
                c,
                "LS-G75.1-WORD",
                format!("G75.1 P{} is not four corner digits", p.value),
                "P(a)(b)(d)(e): 0 a straight chamfer, 1 a round, e.g. P1001",
            )
        }
    };
    if e < 0.0 {
        return alarm(
            c,
            "LS-G75.1-WORD",
            format!("G75.1 retract R{e} is negative"),
            "R(e) is an unsigned radius",
        );
    }
    if e >= g.di / 2.0 {
        return alarm(
            c,
            "LS-G75.1-E",
            format!(
                "G75.1 retract R{e} is not smaller than the peck Δi/2 = {} mm",
                g.di / 2.0
            ),
            "make R(e) smaller than half of the geometry block's P (P is a diameter)",
        );
    }
    if let Some(v) = dv.filter(|&v| v <= 0.0) {
        return alarm(
            c,
            "LS-G75.1-WORD",
            format!("G75.1 layer depth V{v} must be positive"),
            "V is the depth of one layer (diameter); leave it out for one layer",
        );
    }
    for (name, v) in [("U", du), ("W", dw)] {
        if v < 0.0 {
            return alarm(
                c,
                "LS-G75.1-WORD",
                format!("G75.1 finishing allowance {name}{v} is negative"),
                "U and W are unsigned allowances",
            );
        }
    }
    if w == Some(0.0) {
        return alarm(
            c,
            "LS-G75.1-WORD",
            "G75.1 tool width I0".to_string(),
            "give the blade width with I, or leave I out for a pointed tool",
        );
    }
    let mut shape = g.shape;
    for (k, rk) in r.iter().enumerate() {
        match *rk {
            None => {}
            Some(v) if v < 0.0 => {
                return alarm(
                    c,
                    "LS-G75.1-WORD",
                    format!("G75.1 corner {} is negative", ['A', 'B', 'D', 'E'][k]),
                    "chamfer widths and round radii are unsigned",
                );
            }
            Some(0.0) => {}
            Some(v) => {
                shape.corners[k] = if digits[k] == 1 {
                    Corner::Round(v)
                } else {
                    Corner::Chamfer(v)
                }
            }
        }
    }

    // -- geometry.
    let k = shape.contour().map_err(|m| {
        c.alarm(
            "LS-G75.1-SHAPE",
            format!("G75.1: {m}"),
            "check H, D, the angles A B L and the corner sizes A B D E",
        )
    })?;
    let (first, els, far_from) = (k.first, &k.els, k.far_from);
    let t = shape.h.abs() / 2.0;
    let width = w.unwrap_or(0.0);
    let v_floor = t - du / 2.0; // roughing floor
    if v_floor <= 0.0 {
        return alarm(
            c,
            "LS-G75.1-SHAPE",
            format!("G75.1 allowance U{du} is as deep as the groove"),
            "U is a diameter allowance; make it smaller than H",
        );
    }
    // the roughing contour: the finishing sides without the mouth corners, moved in by Δw
    // (the far side also by the blade width: the far corner traces it) and no deeper than
    // the roughing floor
    let tol = 0.001;
    let rough_start: Vec<Uv> = k
        .rough_start(tol)
        .into_iter()
        .map(|q| uv(q.u + dw, q.v.min(v_floor)))
        .collect();
    let rough_far: Vec<Uv> = k
        .rough_far(tol)
        .into_iter()
        .map(|q| uv(q.u - dw - width, q.v.min(v_floor)))
        .collect();
    let start_at = |v: f64| u_at(&rough_start, v, true);
    let far_at = |v: f64| u_at(&rough_far, v, false);
    let room = far_at(v_floor) - start_at(v_floor);
    if room < -1e-9 {
        return alarm(
            c,
            "LS-G75.1-WIDTH",
            format!(
                "G75.1 tool width {width} mm is wider than the roughing floor {:.4} mm",
                room + width
            ),
            "use a narrower blade (I) or a wider floor (D); the floor less 2 × W and the corners D E must hold the tool",
        );
    }
    // the finishing floor flat between the corners D and E must hold the blade too
    let floor_from = els[far_from - 1].to;
    let flat = els[far_from].to.u - floor_from.u;
    if flat < width - 1e-9 {
        return alarm(
            c,
            "LS-G75.1-WIDTH",
            format!("G75.1 tool width {width} mm is wider than the floor between the corners D and E ({flat:.4} mm)"),
            "use a narrower blade (I) or smaller corners D and E",
        );
    }
    // the top level: the highest point of the mouth over the groove
    let far_mouth = els.last().map_or(k.p4, |e| e.to);
    let v_top = 0.0f64.min(k.p4.v).min(far_mouth.v).min(first.v);

    // -- roughing layers: bottoms from the mouth at P1, the last one at the roughing floor.
    let layer = dv.map_or(v_floor, |v| v / 2.0);
    let layers = ((v_floor / layer) - 1e-9).ceil().max(1.0);
    let dk = g.dk;
    let di = g.di / 2.0;
    let per_plunge = 2.0 * ((v_floor - v_top) / di).ceil() + 3.0;
    let plunges = ((far_at(v_top) - start_at(v_top)).abs() / dk).ceil() + 1.0;
    let estimate = layers * plunges * per_plunge;
    if estimate > MAX_MOVES as f64 {
        return alarm(
            c,
            "LS-CYCLE-TOO-LONG",
            format!("G75.1 would make about {estimate:.0} moves, more than {MAX_MOVES}"),
            "check P, Q and V: P and Q are in least input increments",
        );
    }
    // I makes the blade; without I the table's tool cuts as the table defines it, so a
    // blade referenced at the far corner lands w away (spec: the report warns).
    let hint = i_word.map_or(ToolHint::Table, |width| ToolHint::Blade {
        width,
        toward_plus_z: shape.d > 0.0,
        shank_plus_x: shape.h < 0.0,
    });
    let mut warnings = vec![];
    if let (None, Some((bw, plus_z))) = (i_word, c.tool_blade) {
        if plus_z != (shape.d > 0.0) {
            warnings.push(Diagnostic::new(
                c.span(),
                "LS-G75.1-CORNER",
                format!(
                    "the tool table's blade extends toward {} from its reference corner, but this groove runs toward {}: the groove lands {bw} mm away",
                    if plus_z { "+Z" } else { "-Z" },
                    if plus_z { "-Z" } else { "+Z" }
                ),
                "reference the blade at its corner on the groove's start side (width_dir toward the groove), or give I",
            ));
        }
    }
    let mut path = Path {
        shape: &shape,
        moves: Vec::new(),
        hint,
    };
    let layers = layers as usize;
    let bottoms: Vec<f64> = (1..=layers)
        .map(|m| {
            if m == layers {
                v_floor
            } else {
                layer * m as f64
            }
        })
        .collect();
    let a11 = uv(start_at(bottoms[0]), v_top);

    // ① rapid to the rough start A11
    path.rapid(a11);
    if j != 2 {
        let (mut top, mut prev_top, mut last_u) = (v_top, v_top, a11.u);
        for &vb in &bottoms {
            let (u0, u1) = (start_at(vb), far_at(vb).max(start_at(vb)));
            let n = ((u1 - u0) / dk - 1e-9).ceil().max(0.0) as usize + 1;
            // ⑧/② to the layer's first plunge A_m1: Z first at the previous layer's start
            // level, then down to this layer's start (the previous layer's bottom)
            path.rapid(uv(u0, prev_top));
            path.rapid(uv(u0, top));
            for k in 0..n {
                // ⑦ the plunges Δk apart, the last exactly at A_mf
                let u = if k + 1 == n { u1 } else { u0 + dk * k as f64 };
                path.rapid(uv(u, top));
                // ③–⑤ pecks: Δi/2, back e, Δi/2 + e, …; the last stops at B_mn
                let pecks = (((vb - top) / di) - 1e-9).ceil().max(1.0) as usize;
                for s in 1..=pecks {
                    let bottom = if s == pecks { vb } else { top + di * s as f64 };
                    path.feed(uv(u, bottom));
                    if s < pecks && e > 0.0 {
                        path.rapid(uv(u, bottom - e));
                    }
                }
                // ⑥ back to A_mn
                path.rapid(uv(u, top));
                last_u = u;
            }
            prev_top = top;
            top = vb;
        }
        // ⑧ out to the mouth level, back to A11
        path.rapid(uv(last_u, v_top));
        path.rapid(a11);
        // ⑨ the roughing contour: down the start side, along the floor, up the far side
        path.feed(uv(rough_start[0].u, v_top));
        for &q in rough_start.iter().chain(&rough_far) {
            path.feed(q);
        }
        let up = rough_far[rough_far.len() - 1];
        path.rapid(uv(up.u, v_top));
        path.rapid(a11);
    }
    if j != 0 {
        // ⑩ the finishing contour with chamfers and rounds; the far corner traces the far side
        path.rapid(uv(first.u, v_top));
        path.feed(first);
        for (i, el) in els.iter().enumerate() {
            let shift = if i >= far_from { width } else { 0.0 };
            let to = uv(el.to.u - shift, el.to.v);
            match el.arc {
                None => path.feed(to),
                Some((centre, ccw)) => path.arc(to, uv(centre.u - shift, centre.v), ccw),
            }
        }
        let far_end = els.last().map_or(first, |el| el.to).u - width;
        path.rapid(uv(far_end, v_top));
        path.rapid(uv(0.0, v_top));
        path.rapid(uv(0.0, 0.0)); // the finishing start point (X, Z)
    }
    // rapid back to where the tool was before the cycle
    let mut moves = path.moves;
    let mut back = Move::rapid(c.start);
    back.hint = hint;
    moves.push(back);
    Ok(Output {
        moves,
        warnings,
        intended: vec![(
            IntendedKind::Groove,
            shape
                .ring(0.001)
                .map_err(|m| c.alarm("LS-G75.1-SHAPE", m, "check the chamfers and angles"))?,
        )],
        ..Output::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The seed 000 example: P1 (30, 25), P2 (20, 15), P3 (10, 15), P4 (−7.32, 25).
    #[test]
    fn seed_000_trapezoid() {
        let t = Trapezoid {
            start: Pt::new(30.0, 25.0),
            h: -20.0,
            d: -10.0,
            a: 45.0,
            b: 30.0,
            l: 0.0,
            corners: [Corner::Sharp; 4],
        };
        let ring = groove_shape(&t, 0.001).unwrap();
        let want = [
            (30.0, 25.0),
            (20.0, 15.0),
            (10.0, 15.0),
            (10.0 - 10.0 * 3f64.sqrt(), 25.0),
        ];
        assert_eq!(ring.len(), 4);
        for (p, w) in ring.iter().zip(want) {
            assert!(
                (p.z - w.0).abs() < 1e-9 && (p.r - w.1).abs() < 1e-9,
                "{p:?} {w:?}"
            );
        }
    }

    /// Corners: a chamfer moves the ring's end onto the mouth line; a round is chorded.
    #[test]
    fn corners_in_the_ring() {
        let mut t = Trapezoid {
            start: Pt::new(0.0, 30.0),
            h: -16.0,
            d: -12.0,
            a: 90.0,
            b: 90.0,
            l: 0.0,
            corners: [
                Corner::Round(1.0),
                Corner::Chamfer(1.5),
                Corner::Sharp,
                Corner::Sharp,
            ],
        };
        let ring = groove_shape(&t, 0.001).unwrap();
        assert!(ring[0].dist(Pt::new(1.0, 30.0)) < 1e-9, "{:?}", ring[0]);
        assert!(ring
            .iter()
            .any(|p| (p.z - 0.0).abs() < 1e-12 && (p.r - 29.0).abs() < 1e-12));
        assert!(ring[ring.len() - 1].dist(Pt::new(-13.5, 30.0)) < 1e-9);
        t.corners[2] = Corner::Chamfer(9.0);
        assert!(groove_shape(&t, 0.001).unwrap_err().contains("start flank"));
    }
}
