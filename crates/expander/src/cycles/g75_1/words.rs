//! The words of the two G75.1 blocks, read and checked: the geometry block's groove, and
//! the process block's retract, layers, allowances, tool, path type and corners.

use super::shape::{Corner, Trapezoid};
use super::{Cycle, Geometry};
use crate::{Diagnostic, Pt};

/// The geometry block (the one holding H): the groove, the pecks and the shift.
pub(super) fn geometry_block(c: &mut Cycle) -> Result<Geometry, Diagnostic> {
    let x = c.x_target()?;
    let z = c.z_target()?;
    let pq = c.machine.pq_mm_under(c.unit);
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
    let (a, b, l) = angles(c, a, b, l)?;
    let shape = Trapezoid {
        start: Pt::new(z.unwrap_or(c.start.z), x.unwrap_or(c.start.r)),
        h: h.unwrap_or(0.0),
        d: d.unwrap_or(0.0),
        a,
        b,
        l,
        corners: [Corner::Sharp; 4],
    };
    Ok(Geometry {
        shape,
        di: p,
        dk: q,
        line: c.span().line,
        at: (c.index, c.program.number),
    })
}

/// The flank angles A and B (90 by default) and the mouth angle L (0), in their ranges.
fn angles(
    c: &Cycle,
    a: Option<f64>,
    b: Option<f64>,
    l: Option<f64>,
) -> Result<(f64, f64, f64), Diagnostic> {
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
    Ok((a, b, l))
}

/// The process block's words, checked.
pub(super) struct ProcessWords {
    /// R(e): the retract after each peck, radius.
    pub(super) e: f64,
    /// V(Δv): the depth of one layer, diameter; `None`: one layer.
    pub(super) dv: Option<f64>,
    /// U(Δu), W(Δw): the finishing allowances.
    pub(super) du: f64,
    pub(super) dw: f64,
    /// I: the blade width the program gives, unsigned.
    pub(super) i_word: Option<f64>,
    /// The blade width: I, or the tool table's blade.
    pub(super) width: Option<f64>,
    /// J: 0 rough only, 1 rough + finish, 2 finish only.
    pub(super) j: u8,
    /// The geometry block's groove with the process block's corners.
    pub(super) shape: Trapezoid,
}

/// The process block (a G75.1 without H), with the geometry block `g` it belongs to.
pub(super) fn process_block(c: &mut Cycle, g: &Geometry) -> Result<ProcessWords, Diagnostic> {
    let e = c.words.mm('R', c.unit).unwrap_or(0.0);
    let dv = c.words.mm('V', c.unit);
    let du = c.words.mm('U', c.unit).unwrap_or(0.0);
    let dw = c.words.mm('W', c.unit).unwrap_or(0.0);
    let i_word = c.words.mm('I', c.unit).map(f64::abs);
    let width = i_word.or(c.tool_blade.map(|b| b.0));
    let j = c.words.take('J');
    let r = ['A', 'B', 'D', 'E'].map(|l| c.words.mm(l, c.unit));
    let kinds = c.words.take('P');
    let j = path_type(c, j)?;
    let digits = corner_kinds(c, kinds)?;
    check_sizes(c, g, e, dv, du, dw, width)?;
    let shape = with_corners(c, g.shape, r, digits)?;
    Ok(ProcessWords {
        e,
        dv,
        du,
        dw,
        i_word,
        width,
        j,
        shape,
    })
}

/// J: the path type, 0 without J.
fn path_type(c: &Cycle, j: Option<&gcode::Word>) -> Result<u8, Diagnostic> {
    match j {
        None => Ok(0),
        Some(j) if !j.has_point && [0.0, 1.0, 2.0].contains(&j.value) => Ok(j.value as u8),
        Some(j) => Err(c.alarm(
            "LS-G75.1-WORD",
            format!("G75.1 J{} is not a path type", j.value),
            "J0 rough only, J1 rough + finish, J2 finish only",
        )),
    }
}

/// P(a)(b)(d)(e): for each corner, 0 a straight chamfer, 1 a round.
fn corner_kinds(c: &Cycle, kinds: Option<&gcode::Word>) -> Result<[u8; 4], Diagnostic> {
    match kinds {
        None => Ok([0u8; 4]),
        Some(p) if !p.has_point && (0.0..=1111.0).contains(&p.value) && p.value.fract() == 0.0 => {
            let v = p.value as u32;
            let d = [v / 1000 % 10, v / 100 % 10, v / 10 % 10, v % 10];
            if d.iter().any(|&x| x > 1) {
                return Err(c.alarm(
                    "LS-G75.1-WORD",
                    format!("G75.1 P{v}: each corner digit must be 0 or 1"),
                    "P(a)(b)(d)(e): 0 a straight chamfer, 1 a round, e.g. P1001",
                ));
            }
            Ok(d.map(|x| x as u8))
        }
        Some(p) => Err(c.alarm(
            "LS-G75.1-WORD",
            format!("G75.1 P{} is not four corner digits", p.value),
            "P(a)(b)(d)(e): 0 a straight chamfer, 1 a round, e.g. P1001",
        )),
    }
}

/// The retract, the layer depth, the allowances and the blade width in their ranges.
fn check_sizes(
    c: &Cycle,
    g: &Geometry,
    e: f64,
    dv: Option<f64>,
    du: f64,
    dw: f64,
    width: Option<f64>,
) -> Result<(), Diagnostic> {
    let alarm = |code, message: String, help: &str| Err(c.alarm(code, message, help));
    if e < 0.0 {
        return alarm(
            "LS-G75.1-WORD",
            format!("G75.1 retract R{e} is negative"),
            "R(e) is an unsigned radius",
        );
    }
    if e >= g.di / 2.0 {
        return alarm(
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
            "LS-G75.1-WORD",
            format!("G75.1 layer depth V{v} must be positive"),
            "V is the depth of one layer (diameter); leave it out for one layer",
        );
    }
    for (name, v) in [("U", du), ("W", dw)] {
        if v < 0.0 {
            return alarm(
                "LS-G75.1-WORD",
                format!("G75.1 finishing allowance {name}{v} is negative"),
                "U and W are unsigned allowances",
            );
        }
    }
    if width == Some(0.0) {
        return alarm(
            "LS-G75.1-WORD",
            "G75.1 tool width I0".to_string(),
            "give the blade width with I, or leave I out for a pointed tool",
        );
    }
    Ok(())
}

/// The groove with its corners A B D E: a chamfer or a round (`digits`) of the size given.
fn with_corners(
    c: &Cycle,
    mut shape: Trapezoid,
    r: [Option<f64>; 4],
    digits: [u8; 4],
) -> Result<Trapezoid, Diagnostic> {
    for (k, rk) in r.iter().enumerate() {
        match *rk {
            None => {}
            Some(v) if v < 0.0 => {
                return Err(c.alarm(
                    "LS-G75.1-WORD",
                    format!("G75.1 corner {} is negative", ['A', 'B', 'D', 'E'][k]),
                    "chamfer widths and round radii are unsigned",
                ));
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
    Ok(shape)
}
