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

/// G07: no FANUC, GSK or Haas lathe code; `LinuxCNC`'s diameter mode (named in its alarm).
pub(crate) const G07: i32 = 70;
/// G10 data setting (offsets; `G10 L50` parameter input until G11).
pub(crate) const G10: i32 = 100;
/// G11 end of parameter input.
pub(crate) const G11: i32 = 110;
/// G17 XY plane (live tooling).
pub(crate) const G17: i32 = 170;
/// G19 YZ plane (live tooling).
pub(crate) const G19: i32 = 190;
/// G27 reference position return check.
pub(crate) const G27: i32 = 270;
/// G50.3 workpiece coordinate preset (system B/C G92.1).
pub(crate) const G50_3: i32 = 503;
/// G52 local coordinate system.
pub(crate) const G52: i32 = 520;
/// G53 machine coordinates for one block.
pub(crate) const G53: i32 = 530;
/// G54.1 P… additional work offsets (FANUC).
pub(crate) const G54_1: i32 = 541;
/// G80 drilling cycle cancel.
pub(crate) const G80: i32 = 800;
/// G154 P… additional work offsets (Haas).
pub(crate) const G154: i32 = 1540;

/// Codes every real program carries that change nothing a 2D section shows (spec/dialects.md
/// §6.1, §3.6): exact stop and cutting modes, look-ahead, stroke check, smoothing, the bar
/// feeder, polar interpolation off. Accepted, no effect; `words` are the letters they take.
pub(crate) fn no_effect(t: i32) -> Option<&'static [char]> {
    match t {
        // G61 exact stop, G62 corner override, G63 tapping mode, G64 cutting mode, G09 exact
        // stop one block, G08 / G05.1 look-ahead, G22 / G23 stroke check, G13.1 / G113 polar
        // interpolation off (a safe-start line).
        610 | 620 | 630 | 640 | 90 | 80 | 51 | 220 | 230 | 131 | 1130 => Some(&[]),
        // Haas G103 [P] look-ahead limit, G187 [P] [E] smoothness.
        1030 => Some(&['P']),
        1870 => Some(&['P', 'E']),
        // Haas G105 servo bar feeder command: its words drive the bar, not the tool.
        1050 => Some(&['I', 'J', 'K', 'P', 'Q', 'R']),
        _ => None,
    }
}

/// Codes that move something a turned section cannot show: the reason they are not
/// simulated (spec/dialects.md §6.1, §3.6).
pub(crate) fn not_simulated(t: i32) -> Option<&'static str> {
    Some(match t {
        71 | 1070 => "cylindrical interpolation mills the cylinder surface; not representable in a turned section",
        121 | 1120 => "polar coordinate interpolation mills with the C axis; not representable in a turned section",
        310 => "probing moves (skip function) are not simulated",
        680 | 690 => "mirror image for double turrets / balance cutting is not simulated",
        870 | 880 | 890 => "a radial (side) hole is not axisymmetric; not representable in a turned section",
        2500 | 2510 | 502 | 512 => "polygon turning is not axisymmetric; not representable in a turned section",
        140 | 150 => "sub-spindle work is outside a single 2D section",
        _ => return None,
    })
}
