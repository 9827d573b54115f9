//! Each control's table of the M codes that are machine functions only (spec/dialects.md
//! §3.7, §6.6): coolant, gears, chuck, tailstock, conveyor, parts catcher, door, … None of
//! them moves the tool; a few change what the simulation warns about (the spindle stops,
//! the chuck opens) or the thread geometry (M23/M24).
//!
//! M00–M05, M08, M09, M30 and M98/M99 are program codes the interpreter runs itself; they
//! are not in these tables.

use crate::Control;

/// What a machine function changes for the simulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Effect {
    /// Nothing the section or the warnings show.
    None,
    /// The spindle stops (orientation, brake): cutting after it is warned about.
    SpindleStops,
    /// The chuck opens: cutting after it is warned about.
    ChuckOpens,
    /// The chuck closes again.
    ChuckCloses,
    /// Thread pull-out chamfer on (`true`, M23) or off (M24), modal (§3.5).
    ThreadChamfer(bool),
    /// The tailstock advances (`true`: its centre is an obstacle again) or retracts.
    Tailstock(bool),
    /// The C axis engages (`true`: the spindle is indexed, a hole off the axis is a hole
    /// in one place) or disengages.
    CAxis(bool),
}

/// The control's name and effect of machine function `m`; `None` when its table does not
/// know the code (the interpreter then accepts it with one warning per code).
pub(crate) fn machine_function(control: Control, m: u32) -> Option<(&'static str, Effect)> {
    use Effect::*;
    let common = match m {
        7 => Some(("mist coolant on", None)),
        19 => Some(("spindle orientation (the spindle stops)", SpindleStops)),
        23 => Some(("thread pull-out chamfer on", ThreadChamfer(true))),
        24 => Some(("thread pull-out chamfer off", ThreadChamfer(false))),
        29 => Some(("rigid tapping mode", None)),
        40 => Some(("spindle gear neutral", None)),
        41..=44 => Some(("spindle gear range", None)),
        _ => Option::None,
    };
    let own = match control {
        Control::Haas => match m {
            10 => Some(("chuck clamp", ChuckCloses)),
            11 => Some(("chuck unclamp", ChuckOpens)),
            12 | 13 => Some(("air blast on / off", None)),
            14 => Some(("main spindle brake on (the spindle stops)", SpindleStops)),
            15 => Some(("main spindle brake off", None)),
            21 => Some(("tailstock advance", Tailstock(true))),
            22 => Some(("tailstock retract", Tailstock(false))),
            31 | 33 => Some(("chip conveyor forward / stop", None)),
            36 | 37 => Some(("parts catcher up / down", None)),
            38 | 39 => Some(("spindle speed variation on / off", None)),
            85 | 86 => Some(("door open / close", None)),
            88 | 89 => Some(("through-spindle coolant on / off", None)),
            110 | 111 => Some(("sub-spindle chuck clamp / unclamp", None)),
            130 => Some(("show a media file", None)),
            133..=135 => Some(("live tool CW / CCW / stop", None)),
            143..=145 => Some(("sub-spindle CW / CCW / stop", None)),
            154 => Some(("C axis engage", CAxis(true))),
            155 => Some(("C axis disengage", CAxis(false))),
            _ => Option::None,
        },
        Control::Gsk980 => match m {
            10 => Some(("tailstock forward", Tailstock(true))),
            11 => Some(("tailstock back", Tailstock(false))),
            12 => Some(("chuck clamp", ChuckCloses)),
            13 => Some(("chuck release", ChuckOpens)),
            32 | 33 => Some(("lubrication on / off", None)),
            _ => Option::None,
        },
        Control::LinuxCnc => match m {
            7..=9 => Some(("coolant mist / flood / off", None)),
            48..=53 => Some(("override and feed hold controls", None)),
            _ => Option::None,
        },
        Control::FanucA | Control::FanucB | Control::FanucC => match m {
            50 | 51 => Some(("C-axis (index) mode off / on", None)),
            68 => Some(("chuck clamp", ChuckCloses)),
            69 => Some(("chuck unclamp", ChuckOpens)),
            _ => Option::None,
        },
    };
    own.or(common)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_dialect_decides_what_a_builder_code_means() {
        assert_eq!(
            machine_function(Control::Haas, 33).unwrap().0,
            "chip conveyor forward / stop"
        );
        assert_eq!(
            machine_function(Control::Gsk980, 33).unwrap().0,
            "lubrication on / off"
        );
        assert_eq!(
            machine_function(Control::Haas, 11).unwrap().1,
            Effect::ChuckOpens
        );
        assert_eq!(
            machine_function(Control::FanucB, 23).unwrap().1,
            Effect::ThreadChamfer(true)
        );
        assert!(machine_function(Control::FanucA, 33).is_none());
    }
}
