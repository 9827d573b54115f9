//! `LinuxCNC` (rs274ngc) G codes → the interpreter's canonical meanings (docs/linuxcnc.md).
//! Its distance, feed and thread codes are those of FANUC system B (`G90`/`G91`, `G94`/`G95`,
//! `G33`, `G92` as the coordinate setting); what system B has no code for gets an internal
//! number below. A `LinuxCNC` code latsim does not run is named by [`unsupported`] (an alarm
//! at its word, never a skip); a code `LinuxCNC` does not have is an alarm naming `LinuxCNC`.

use crate::codes::*;
use crate::dialect::{self, Foreign};

/// `G7`: X is a diameter from this block on.
pub(crate) const X_DIAMETER: i32 = -1070;
/// `G8`: X is a radius from this block on (`LinuxCNC`'s power-on mode).
pub(crate) const X_RADIUS: i32 = -1080;
/// `G43 [H]`: the tool length offset of the loaded tool (or of tool H).
pub(crate) const LENGTH_OFFSET: i32 = -1430;
/// `G49`: no tool length offset.
pub(crate) const LENGTH_CANCEL: i32 = -1490;
/// `G41.1 D L`: compensation left, the nose given in the block.
pub(crate) const DYNAMIC_LEFT: i32 = -1411;
/// `G42.1 D L`: compensation right, the nose given in the block.
pub(crate) const DYNAMIC_RIGHT: i32 = -1421;
/// `G90.1`: arc centres I K are absolute positions.
pub(crate) const ARC_ABSOLUTE: i32 = -1901;
/// `G91.1`: arc centres I K are offsets from the start (power-on).
pub(crate) const ARC_INCREMENTAL: i32 = -1911;
/// `G61`, `G61.1`, `G64 [P Q]`: path blending; no effect on the section.
pub(crate) const PATH_CONTROL: i32 = -1640;
/// `G70 Q X Z D E P`: `LinuxCNC`'s finishing cycle over the profile in O-sub Q.
pub(crate) const CYCLE_G70: i32 = -1700;
/// `G71`, `G71.1`, `G71.2`: `LinuxCNC`'s roughing along Z (`+ 0/1/2`).
pub(crate) const CYCLE_G71: i32 = -1710;
/// `G72`, `G72.1`, `G72.2`: `LinuxCNC`'s roughing along X (`+ 0/1/2`).
pub(crate) const CYCLE_G72: i32 = -1720;
/// `G76 P Z I J R K Q H E L`: `LinuxCNC`'s one-line threading cycle.
pub(crate) const CYCLE_G76: i32 = -1760;
/// `G73 Z R Q [D]`: `LinuxCNC`'s peck drilling with chip breaking (the drilling cycles run in
/// G17, along Z: `cycles/drill.rs`).
pub(crate) const DRILL_CHIP_BREAK: i32 = -1730;
/// `G33.1 Z K`: rigid tapping on the axis, in and back out at the lead K.
pub(crate) const RIGID_TAP: i32 = -1331;
/// `G92.1`, `G92.2`: the G92 (and G52) offset dropped.
pub(crate) const G92_RESET: i32 = -1921;

/// Whether `t` (canonical) is one of the `LinuxCNC` drilling cycles latsim runs: in G17 they
/// drill along Z, on the lathe's axis.
pub(crate) fn is_drilling(t: i32) -> bool {
    matches!(t, G81 | G82 | G83 | G85 | DRILL_CHIP_BREAK)
}

/// The canonical code of `LinuxCNC`'s `tenths`; a code `LinuxCNC` does not have is an error.
pub(crate) fn canonical(t: i32) -> Result<i32, Foreign> {
    Ok(match t {
        70 => X_DIAMETER,
        80 => X_RADIUS,
        411 => DYNAMIC_LEFT,
        421 => DYNAMIC_RIGHT,
        430 => LENGTH_OFFSET,
        490 => LENGTH_CANCEL,
        901 => ARC_ABSOLUTE,
        911 => ARC_INCREMENTAL,
        610 | 611 | 640 => PATH_CONTROL,
        700 => CYCLE_G70,
        710..=712 => CYCLE_G71 - (t - 710),
        720..=722 => CYCLE_G72 - (t - 720),
        760 => CYCLE_G76,
        921 | 922 => G92_RESET,
        730 => DRILL_CHIP_BREAK,
        331 => RIGID_TAP,
        810 | 820 | 830 | 850 => t,
        330 => G32,
        920 => G50,
        900 => dialect::ABSOLUTE,
        910 => dialect::INCREMENTAL,
        940 => G98,
        950 => G99,
        980 => dialect::DRILL_RETURN_INITIAL,
        990 => dialect::DRILL_RETURN_R,
        0 | 10 | 20 | 30 | 40 | 170 | 180 | 190 | 200 | 210 | 280 | 400 | 410 | 420 | 520 | 530
        | 800 | 960 | 970 => t,
        540..=590 if t % 10 == 0 => t,
        t if unsupported(t).is_some() => t,
        t => {
            return Err(Foreign {
                message: format!("{} is not a LinuxCNC G code", g_name(t)),
                help: "see LinuxCNC's G-code reference (docs/linuxcnc.md lists what latsim runs); \
                       a FANUC program runs with --control fanuc-a"
                    .into(),
            })
        }
    })
}

/// Why latsim does not run the `LinuxCNC` code `t` (canonical): named at its word.
pub(crate) fn unsupported(t: i32) -> Option<&'static str> {
    Some(match t {
        50..=53 => "G5, G5.1, G5.2, G5.3 (splines and NURBS) are not run by latsim",
        100 => "G10 (tool table and coordinate system setting) is not run by latsim under --control linuxcnc",
        191 | 281 | 301 | 300 => "G19.1, G28.1, G30, G30.1 (stored positions) are not run by latsim",
        380..=385 => "G38.n (probing) moves are not simulated",
        431 | 432 => "G43.1, G43.2 (dynamic and added tool length offsets) are not run by latsim",
        591..=593 => "G59.1, G59.2, G59.3 (work offsets 7 to 9) are not run by latsim",
        740 | 840 => "G74, G84 (tapping with a floating holder) are not run by latsim",
        860..=890 => "G86-G89 (boring with spindle stop, back boring, manual out, dwell and feed out) are not run by latsim",
        923 => "G92.3 (the G92 offset restored from parameters 5211-5219) is not run by latsim",
        930 => "G93 (inverse time feed) is not run by latsim",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linuxcnc_codes_read_as_system_b_and_its_own() {
        assert_eq!(canonical(70), Ok(X_DIAMETER));
        assert_eq!(canonical(80), Ok(X_RADIUS));
        assert_eq!(canonical(711), Ok(CYCLE_G71 - 1));
        assert_eq!(canonical(950), Ok(G99));
        assert_eq!(canonical(330), Ok(G32));
        assert_eq!(canonical(920), Ok(G50));
        assert!(canonical(500).is_err(), "G50 is no LinuxCNC code");
        assert!(canonical(320).is_err(), "G32 is no LinuxCNC code");
        assert_eq!(canonical(331), Ok(RIGID_TAP));
        assert_eq!(canonical(921), Ok(G92_RESET));
        assert_eq!(canonical(730), Ok(DRILL_CHIP_BREAK));
        assert_eq!(canonical(830), Ok(G83));
        assert!(unsupported(canonical(840).unwrap()).is_some());
        assert_eq!(canonical(922), Ok(G92_RESET));
        assert!(unsupported(canonical(923).unwrap()).is_some());
    }
}
