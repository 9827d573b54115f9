//! G codes by their value in tenths (`Word::code_tenths`): G75.1 is 751. Named so that the
//! interpreter and the cycles read `G75_1`, not a bare 751.

/// G00 rapid.
pub(crate) const G00: i32 = 0;
/// G01 line.
pub(crate) const G01: i32 = 10;
/// G02 clockwise arc.
pub(crate) const G02: i32 = 20;
/// G03 counter-clockwise arc.
pub(crate) const G03: i32 = 30;
/// G04 dwell.
pub(crate) const G04: i32 = 40;
/// G18 ZX plane, the lathe's plane (accepted, no effect).
pub(crate) const G18: i32 = 180;
/// G20 inch input.
pub(crate) const G20: i32 = 200;
/// G21 metric input.
pub(crate) const G21: i32 = 210;
/// G28 reference point return.
pub(crate) const G28: i32 = 280;
/// G32 thread cutting.
pub(crate) const G32: i32 = 320;
/// G40 compensation cancel.
pub(crate) const G40: i32 = 400;
/// G41 compensation, tool left of the contour.
pub(crate) const G41: i32 = 410;
/// G42 compensation, tool right of the contour.
pub(crate) const G42: i32 = 420;
/// G50 coordinate setting (and G50 S spindle clamp).
pub(crate) const G50: i32 = 500;
/// G54, the first work coordinate system; G55–G59 follow in steps of 10.
pub(crate) const G54: i32 = 540;
/// G59, the last work coordinate system.
pub(crate) const G59: i32 = 590;
/// G70 finishing cycle.
pub(crate) const G70: i32 = 700;
/// G71 stock removal in turning.
pub(crate) const G71: i32 = 710;
/// G72 stock removal in facing.
pub(crate) const G72: i32 = 720;
/// G73 pattern repeating.
pub(crate) const G73: i32 = 730;
/// G74 face peck drilling / grooving.
pub(crate) const G74: i32 = 740;
/// G75 radial grooving.
pub(crate) const G75: i32 = 750;
/// G75.1 GSK trapezoid groove cycle.
pub(crate) const G75_1: i32 = 751;
/// G76 multiple threading cycle (recognised, not run yet).
pub(crate) const G76: i32 = 760;
/// G80 drilling cycle cancel.
pub(crate) const G80: i32 = 800;
/// G81 Haas drilling cycle.
pub(crate) const G81: i32 = 810;
/// G82 Haas drilling cycle with dwell.
pub(crate) const G82: i32 = 820;
/// G83 face peck drilling (FANUC), Haas peck drilling.
pub(crate) const G83: i32 = 830;
/// G84 face tapping.
pub(crate) const G84: i32 = 840;
/// G85 face boring (FANUC).
pub(crate) const G85: i32 = 850;
/// G90 turning cycle.
pub(crate) const G90: i32 = 900;
/// G92 threading cycle.
pub(crate) const G92: i32 = 920;
/// G94 facing cycle.
pub(crate) const G94: i32 = 940;
/// G96 constant surface speed.
pub(crate) const G96: i32 = 960;
/// G97 constant spindle speed.
pub(crate) const G97: i32 = 970;
/// G98 feed per minute.
pub(crate) const G98: i32 = 980;
/// G99 feed per revolution.
pub(crate) const G99: i32 = 990;

/// The work coordinate system index (0 for G54 … 5 for G59) of a G code, if it is one.
pub(crate) fn work_offset(t: i32) -> Option<usize> {
    (G54..=G59)
        .contains(&t)
        .then_some(t - G54)
        .filter(|d| d % 10 == 0)
        .map(|d| (d / 10) as usize)
}

/// The name of a G code as the manuals write it: G01, G75.1.
pub(crate) fn g_name(t: i32) -> String {
    if t % 10 == 0 {
        format!("G{:02}", t / 10)
    } else {
        format!("G{}.{}", t / 10, t % 10)
    }
}
