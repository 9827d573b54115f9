//! G codes by name. A G word's value in tenths (`G75.1` is 751), as
//! [`gcode::Word::code_tenths`] gives it, so the interpreter and the cycles match on names
//! instead of bare numbers.

/// Rapid positioning.
pub(crate) const G00: i32 = 0;
/// Linear interpolation.
pub(crate) const G01: i32 = 10;
/// Circular interpolation, clockwise.
pub(crate) const G02: i32 = 20;
/// Circular interpolation, counter-clockwise.
pub(crate) const G03: i32 = 30;
/// Dwell.
pub(crate) const G04: i32 = 40;
/// Inch input.
pub(crate) const G20: i32 = 200;
/// Metric input.
pub(crate) const G21: i32 = 210;
/// Reference point return.
pub(crate) const G28: i32 = 280;
/// Thread cutting, one pass.
pub(crate) const G32: i32 = 320;
/// Tool nose radius compensation cancel.
pub(crate) const G40: i32 = 400;
/// Tool nose radius compensation, tool left of the path.
pub(crate) const G41: i32 = 410;
/// Tool nose radius compensation, tool right of the path.
pub(crate) const G42: i32 = 420;
/// Coordinate system setting / spindle clamp.
pub(crate) const G50: i32 = 500;
/// Work coordinate systems G54 … G59.
pub(crate) const G54: i32 = 540;
/// The last work coordinate system.
pub(crate) const G59: i32 = 590;
/// Finishing cycle.
pub(crate) const G70: i32 = 700;
/// Stock removal in turning.
pub(crate) const G71: i32 = 710;
/// Stock removal in facing.
pub(crate) const G72: i32 = 720;
/// Pattern repeating.
pub(crate) const G73: i32 = 730;
/// Face grooving / peck drilling.
pub(crate) const G74: i32 = 740;
/// Radial grooving.
pub(crate) const G75: i32 = 750;
/// GSK radial trapezoid groove cycle.
pub(crate) const G75_1: i32 = 751;
/// Multiple threading cycle.
pub(crate) const G76: i32 = 760;
/// Axial (OD/ID) turning cycle.
pub(crate) const G90: i32 = 900;
/// Threading cycle.
pub(crate) const G92: i32 = 920;
/// Face turning cycle.
pub(crate) const G94: i32 = 940;
/// Constant surface speed.
pub(crate) const G96: i32 = 960;
/// Constant spindle speed.
pub(crate) const G97: i32 = 970;
/// Feed per minute.
pub(crate) const G98: i32 = 980;
/// Feed per revolution.
pub(crate) const G99: i32 = 990;

/// Whether `t` is one of G54 … G59.
pub(crate) fn is_work_offset(t: i32) -> bool {
    (G54..=G59).contains(&t) && t % 10 == 0
}

/// The name of a G code in tenths: `G01`, `G75.1`.
pub(crate) fn name(t: i32) -> String {
    if t % 10 == 0 {
        format!("G{:02}", t / 10)
    } else {
        format!("G{}.{}", t / 10, t % 10)
    }
}
