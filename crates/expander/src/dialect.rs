//! The control's G-code numbers → the interpreter's canonical meanings (spec/dialects.md
//! §2.1). The one place the G-code system is looked at: the interpreter, the cycles and
//! their messages speak system A (`G90` is the turning cycle everywhere inside latsim),
//! and the functions system A has no code for get internal numbers below.
//!
//! A code the control's system does not have is an alarm naming the control that has it
//! ("G95 is not a system A code … Run with --control fanuc-b?"): evidence only improves
//! the message, it never switches the dialect (§0).

use crate::codes::*;
use crate::{Control, GCodeSystem};

/// System B/C `G90`: absolute programming (group 03). No system-A code: X/Z are absolute
/// and U/W incremental there.
pub(crate) const ABSOLUTE: i32 = -903;
/// System B/C `G91`: incremental programming (group 03).
pub(crate) const INCREMENTAL: i32 = -913;
/// System B/C `G98`: a drilling cycle returns to the initial level (group 11).
pub(crate) const DRILL_RETURN_INITIAL: i32 = -981;
/// System B/C `G99`: a drilling cycle returns to the R-point level (group 11).
pub(crate) const DRILL_RETURN_R: i32 = -991;

/// Why a written code is not a code of the control's system.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Foreign {
    /// "G95 is not a system A code: …".
    pub(crate) message: String,
    /// "Run with --control fanuc-b?".
    pub(crate) help: String,
}

/// The canonical (system A, or internal) code of the written code `tenths` under `control`.
/// Codes not listed in §2.1 mean the same in every system and pass unchanged.
pub(crate) fn canonical(control: Control, tenths: i32) -> Result<i32, Foreign> {
    if control == Control::LinuxCnc {
        return crate::linuxcnc::canonical(tenths);
    }
    match control.system() {
        GCodeSystem::A => system_a(tenths),
        GCodeSystem::B => system_b(tenths),
        GCodeSystem::C => system_c(tenths),
    }
}

/// How the control writes the canonical code `canonical`, when it writes it differently
/// (system B `G77` for G90): cycle alarms are worded in the program's own codes.
pub(crate) fn written(control: Control, canonical: i32) -> Option<i32> {
    if control == Control::LinuxCnc {
        // LinuxCNC has no G77/G78/G79 cycles; its thread move is G33
        return (canonical == G32).then_some(330);
    }
    let w = match (control.system(), canonical) {
        (GCodeSystem::B, G90) => 770,
        (GCodeSystem::B, G92) => 780,
        (GCodeSystem::B, G94) => 790,
        (GCodeSystem::C, G90) => 200,
        (GCodeSystem::C, G92) => 210,
        (GCodeSystem::C, G94) => 240,
        (GCodeSystem::C, G70..=G76) if canonical % 10 == 0 => canonical + 20,
        (GCodeSystem::B | GCodeSystem::C, G32) => 330,
        _ => return None,
    };
    Some(w)
}

fn system_a(t: i32) -> Result<i32, Foreign> {
    let other = |what: &str, control: &str| {
        Err(foreign(
            t,
            'A',
            &format!("in system {} it is {what}", system_of(control)),
            control,
        ))
    };
    match t {
        910 => other("incremental programming; system A writes U/W", "fanuc-b"),
        950 => other("feed per revolution; system A writes G99", "fanuc-b"),
        770 => other("the turning cycle (system A G90)", "fanuc-b"),
        780 => other("the threading cycle (system A G92)", "fanuc-b"),
        790 => other("the facing cycle (system A G94)", "fanuc-b"),
        330 => other("thread cutting (system A G32)", "fanuc-b"),
        921 => other(
            "the workpiece coordinate preset (system A G50.3)",
            "fanuc-b",
        ),
        240 => other("the facing cycle (system A G94)", "fanuc-c"),
        t => Ok(t),
    }
}

fn system_b(t: i32) -> Result<i32, Foreign> {
    match t {
        900 => Ok(ABSOLUTE),
        910 => Ok(INCREMENTAL),
        770 => Ok(G90),
        780 => Ok(G92),
        790 => Ok(G94),
        330 => Ok(G32),
        920 => Ok(G50),
        921 => Ok(G50_3),
        940 => Ok(G98),
        950 => Ok(G99),
        980 => Ok(DRILL_RETURN_INITIAL),
        990 => Ok(DRILL_RETURN_R),
        320 => Err(foreign(
            t,
            'B',
            "thread cutting in system A; system B writes G33",
            "fanuc-a",
        )),
        500 | 503 => Err(foreign(
            t,
            'B',
            "the coordinate setting of system A; system B writes G92 (G92.1 for G50.3)",
            "fanuc-a",
        )),
        240 => Err(foreign(t, 'B', "the facing cycle of system C", "fanuc-c")),
        t => Ok(t),
    }
}

fn system_c(t: i32) -> Result<i32, Foreign> {
    match t {
        700 => Ok(G20),
        710 => Ok(G21),
        720..=780 if t % 10 == 0 => Ok(t - 20),
        200 => Ok(G90),
        210 => Ok(G92),
        240 => Ok(G94),
        790 => Err(foreign(
            t,
            'C',
            "the facing cycle of system B; system C writes G24",
            "fanuc-b",
        )),
        t => system_b(t).map_err(|f| Foreign {
            message: f.message.replacen("system B code", "system C code", 1),
            ..f
        }),
    }
}

fn system_of(control: &str) -> &'static str {
    match control {
        "fanuc-c" => "C",
        "fanuc-a" | "gsk980" => "A",
        _ => "B",
    }
}

fn foreign(t: i32, system: char, what: &str, control: &str) -> Foreign {
    Foreign {
        message: format!("{} is not a system {system} code: {what}", g_name(t)),
        help: format!(
            "Run with --control {control}? (the control decides how a program's codes are read; \
             latsim never guesses it)"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn system_b_and_c_read_the_cycles_under_their_system_a_names() {
        for (control, written, meant) in [
            (Control::FanucB, 770, G90),
            (Control::FanucB, 780, G92),
            (Control::FanucB, 790, G94),
            (Control::FanucB, 920, G50),
            (Control::FanucB, 950, G99),
            (Control::FanucB, 940, G98),
            (Control::FanucB, 900, ABSOLUTE),
            (Control::FanucC, 200, G90),
            (Control::FanucC, 210, G92),
            (Control::FanucC, 240, G94),
            (Control::FanucC, 710, G21),
            (Control::FanucC, 700, G20),
            (Control::FanucC, 730, G71),
            (Control::FanucC, 780, G76),
            (Control::FanucC, 910, INCREMENTAL),
            (Control::Haas, 900, G90),
            (Control::Gsk980, 920, G92),
        ] {
            assert_eq!(
                canonical(control, written),
                Ok(meant),
                "{control:?} {written}"
            );
        }
    }

    #[test]
    fn a_code_of_another_system_names_the_control_to_try() {
        let f = canonical(Control::FanucA, 950).unwrap_err();
        assert!(
            f.message.starts_with("G95 is not a system A code"),
            "{}",
            f.message
        );
        assert!(f.help.contains("--control fanuc-b"), "{}", f.help);
        let f = canonical(Control::FanucB, 320).unwrap_err();
        assert!(f.help.contains("fanuc-a"), "{}", f.help);
        let f = canonical(Control::FanucC, 790).unwrap_err();
        assert!(f.message.contains("system C"), "{}", f.message);
        assert!(canonical(Control::FanucC, 320)
            .unwrap_err()
            .message
            .contains("system C code"));
    }

    #[test]
    fn written_inverts_canonical() {
        for control in Control::ALL {
            for canon in [G32, G70, G71, G72, G73, G74, G75, G76, G90, G92, G94] {
                if let Some(w) = written(control, canon) {
                    assert_eq!(canonical(control, w), Ok(canon), "{control:?} {w}");
                }
            }
        }
    }
}
