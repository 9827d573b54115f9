//! The G75.1 motion ①–⑩ (spec/cycles.md), built in the groove's local frame and mapped
//! back to (z, r).

use super::plan::Plan;
use super::shape::{uv, Trapezoid, Uv};
use crate::cycles::Move;
use crate::{Arc, Motion, ToolHint};

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

/// The cycle's moves: ① to the rough start, the roughing layers (J0, J1), the finishing
/// contour (J1, J2).
pub(super) fn moves(p: &Plan) -> Vec<Move> {
    let mut path = Path {
        shape: &p.shape,
        moves: Vec::new(),
        hint: p.hint,
    };
    let a11 = uv(p.start_at(p.bottoms[0]), p.v_top);
    // ① rapid to the rough start A11
    path.rapid(a11);
    if p.j != 2 {
        rough(&mut path, p, a11);
    }
    if p.j != 0 {
        finish(&mut path, p);
    }
    path.moves
}

/// ②–⑨ the roughing layers, each plunged Δk apart in pecks, then the roughing contour.
fn rough(path: &mut Path, p: &Plan, a11: Uv) {
    let (mut top, mut prev_top, mut last_u) = (p.v_top, p.v_top, a11.u);
    for &vb in &p.bottoms {
        let (u0, u1) = (p.start_at(vb), p.far_at(vb).max(p.start_at(vb)));
        let n = ((u1 - u0) / p.dk - 1e-9).ceil().max(0.0) as usize + 1;
        // ⑧/② to the layer's first plunge A_m1: Z first at the previous layer's start
        // level, then down to this layer's start (the previous layer's bottom)
        path.rapid(uv(u0, prev_top));
        path.rapid(uv(u0, top));
        for k in 0..n {
            // ⑦ the plunges Δk apart, the last exactly at A_mf
            let u = if k + 1 == n { u1 } else { u0 + p.dk * k as f64 };
            path.rapid(uv(u, top));
            // ③–⑤ pecks: Δi/2, back e, Δi/2 + e, …; the last stops at B_mn
            let pecks = (((vb - top) / p.di) - 1e-9).ceil().max(1.0) as usize;
            for s in 1..=pecks {
                let bottom = if s == pecks {
                    vb
                } else {
                    top + p.di * s as f64
                };
                path.feed(uv(u, bottom));
                if s < pecks && p.e > 0.0 {
                    path.rapid(uv(u, bottom - p.e));
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
    path.rapid(uv(last_u, p.v_top));
    path.rapid(a11);
    // ⑨ the roughing contour: down the start side, along the floor, up the far side
    path.feed(uv(p.rough_start[0].u, p.v_top));
    for &q in p.rough_start.iter().chain(&p.rough_far) {
        path.feed(q);
    }
    let up = p.rough_far[p.rough_far.len() - 1];
    path.rapid(uv(up.u, p.v_top));
    path.rapid(a11);
}

/// ⑩ the finishing contour with chamfers and rounds; the far corner traces the far side.
fn finish(path: &mut Path, p: &Plan) {
    let k = &p.contour;
    let (first, els, far_from, width) = (k.first, &k.els, k.far_from, p.width);
    path.rapid(uv(first.u, p.v_top));
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
    path.rapid(uv(far_end, p.v_top));
    path.rapid(uv(0.0, p.v_top));
    path.rapid(uv(0.0, 0.0)); // the finishing start point (X, Z)
}
