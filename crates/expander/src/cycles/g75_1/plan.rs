//! The G75.1 cycle planned on its groove: the finishing contour, the roughing contour moved
//! in by the allowances, the floors and the top level, the layers, and the checks that the
//! blade fits and the cycle stays bounded.

use super::shape::{u_at, uv, Contour, Trapezoid, Uv};
use super::words::ProcessWords;
use super::{Cycle, Geometry};
use crate::cycles::MAX_MOVES;
use crate::{Diagnostic, ToolHint};

/// What the moves are made from, in the groove's local frame (u along Z toward the far
/// side, v along the radius toward the floor).
pub(super) struct Plan {
    /// The groove with its corners.
    pub(super) shape: Trapezoid,
    /// Its finishing contour.
    pub(super) contour: Contour,
    /// The blade width (0: a pointed tool).
    pub(super) width: f64,
    /// The roughing contour's start side and far side (the far one traced by the far corner).
    pub(super) rough_start: Vec<Uv>,
    pub(super) rough_far: Vec<Uv>,
    /// The roughing floor and the top level over the groove's mouth.
    pub(super) v_floor: f64,
    pub(super) v_top: f64,
    /// The bottom of each roughing layer, the last at the roughing floor.
    pub(super) bottoms: Vec<f64>,
    /// The peck Δi/2, the shift Δk and the retract e.
    pub(super) di: f64,
    pub(super) dk: f64,
    pub(super) e: f64,
    /// J: 0 rough only, 1 rough + finish, 2 finish only.
    pub(super) j: u8,
    /// What cuts: I's blade, or the tool table's.
    pub(super) hint: ToolHint,
}

impl Plan {
    /// The start side of the roughing contour at depth `v`.
    pub(super) fn start_at(&self, v: f64) -> f64 {
        u_at(&self.rough_start, v, true)
    }

    /// The far side of the roughing contour at depth `v` (where the far corner goes).
    pub(super) fn far_at(&self, v: f64) -> f64 {
        u_at(&self.rough_far, v, false)
    }
}

/// Plan the cycle: the contours, the floors, the layers and the checks.
pub(super) fn plan(c: &Cycle, g: &Geometry, w: &ProcessWords) -> Result<Plan, Diagnostic> {
    let shape = w.shape;
    let contour = shape.contour().map_err(|m| {
        c.alarm(
            "LS-G75.1-SHAPE",
            format!("G75.1: {m}"),
            "check H, D, the angles A B L and the corner sizes A B D E",
        )
    })?;
    let width = w.width.unwrap_or(0.0);
    let v_floor = shape.h.abs() / 2.0 - w.du / 2.0; // roughing floor
    if v_floor <= 0.0 {
        return Err(c.alarm(
            "LS-G75.1-SHAPE",
            format!("G75.1 allowance U{} is as deep as the groove", w.du),
            "U is a diameter allowance; make it smaller than H",
        ));
    }
    // the roughing contour: the finishing sides without the mouth corners, moved in by Δw
    // (the far side also by the blade width: the far corner traces it) and no deeper than
    // the roughing floor
    let tol = 0.001;
    let rough_start: Vec<Uv> = contour
        .rough_start(tol)
        .into_iter()
        .map(|q| uv(q.u + w.dw, q.v.min(v_floor)))
        .collect();
    let rough_far: Vec<Uv> = contour
        .rough_far(tol)
        .into_iter()
        .map(|q| uv(q.u - w.dw - width, q.v.min(v_floor)))
        .collect();
    // the top level: the highest point of the mouth over the groove
    let far_mouth = contour.els.last().map_or(contour.p4, |e| e.to);
    let v_top = 0.0f64
        .min(contour.p4.v)
        .min(far_mouth.v)
        .min(contour.first.v);
    let mut plan = Plan {
        shape,
        contour,
        width,
        rough_start,
        rough_far,
        v_floor,
        v_top,
        bottoms: vec![],
        di: g.di / 2.0,
        dk: g.dk,
        e: w.e,
        j: w.j,
        hint: hint(w),
    };
    check_width(c, &plan)?;
    plan.bottoms = layers(c, &plan, w.dv)?;
    Ok(plan)
}

/// The blade must fit the roughing floor, and the finishing floor between the corners D
/// and E.
fn check_width(c: &Cycle, p: &Plan) -> Result<(), Diagnostic> {
    let width = p.width;
    let room = p.far_at(p.v_floor) - p.start_at(p.v_floor);
    if room < -1e-9 {
        return Err(c.alarm(
            "LS-G75.1-WIDTH",
            format!(
                "G75.1 tool width {width} mm is wider than the roughing floor {:.4} mm",
                room + width
            ),
            "use a narrower blade (I) or a wider floor (D); the floor less 2 × W and the corners D E must hold the tool",
        ));
    }
    let els = &p.contour.els;
    let far_from = p.contour.far_from;
    let floor_from = els[far_from - 1].to;
    let flat = els[far_from].to.u - floor_from.u;
    if flat < width - 1e-9 {
        return Err(c.alarm(
            "LS-G75.1-WIDTH",
            format!("G75.1 tool width {width} mm is wider than the floor between the corners D and E ({flat:.4} mm)"),
            "use a narrower blade (I) or smaller corners D and E",
        ));
    }
    Ok(())
}

/// The roughing layers' bottoms from the mouth at P1, the last one at the roughing floor
/// (`dv`: the layer depth, diameter), bounded before any move is made.
fn layers(c: &Cycle, p: &Plan, dv: Option<f64>) -> Result<Vec<f64>, Diagnostic> {
    let layer = dv.map_or(p.v_floor, |v| v / 2.0);
    let layers = ((p.v_floor / layer) - 1e-9).ceil().max(1.0);
    let per_plunge = 2.0 * ((p.v_floor - p.v_top) / p.di).ceil() + 3.0;
    let plunges = ((p.far_at(p.v_top) - p.start_at(p.v_top)).abs() / p.dk).ceil() + 1.0;
    let estimate = layers * plunges * per_plunge;
    if estimate > MAX_MOVES as f64 {
        return Err(c.alarm(
            "LS-CYCLE-TOO-LONG",
            format!("G75.1 would make about {estimate:.0} moves, more than {MAX_MOVES}"),
            "check P, Q and V: P and Q are in least input increments",
        ));
    }
    let layers = layers as usize;
    Ok((1..=layers)
        .map(|m| {
            if m == layers {
                p.v_floor
            } else {
                layer * m as f64
            }
        })
        .collect())
}

/// I makes the blade; without I the table's tool cuts as the table defines it.
fn hint(w: &ProcessWords) -> ToolHint {
    w.i_word.map_or(ToolHint::Table, |width| ToolHint::Blade {
        width,
        toward_plus_z: w.shape.d > 0.0,
        shank_plus_x: w.shape.h < 0.0,
    })
}

/// Without I, a table blade referenced at the far corner lands its width away (spec: the
/// report warns).
pub(super) fn blade_warning(c: &Cycle, w: &ProcessWords) -> Option<Diagnostic> {
    let (None, Some((bw, plus_z))) = (w.i_word, c.tool_blade) else {
        return None;
    };
    if plus_z == (w.shape.d > 0.0) {
        return None;
    }
    Some(Diagnostic::new(
        c.span(),
        "LS-G75.1-CORNER",
        format!(
            "the tool table's blade extends toward {} from its reference corner, but this groove runs toward {}: the groove lands {bw} mm away",
            if plus_z { "+Z" } else { "-Z" },
            if plus_z { "-Z" } else { "+Z" }
        ),
        "reference the blade at its corner on the groove's start side (width_dir toward the groove), or give I",
    ))
}
