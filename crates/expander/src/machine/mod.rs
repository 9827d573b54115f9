//! The machine profile (`--machine F`): what differs between one lathe and the next.
//!
//! ```toml
//! control = "gsk980"        # gsk980 | fanuc-a | fanuc-b | fanuc-c | haas: the built-in profile
//!                           # the other keys override (spec/dialects.md §0)
//! increment = "is-b"        # least input increment: "is-b" 0.001 mm | "is-c" 0.0001 mm
//! pq_units = "increment"    # G74/G75/G75.1/G76 P and Q: "increment" | "mm" (GSK NO182.7)
//! feed_mode = "g98"         # power-on feed mode: "g98" mm/min | "g99" mm/rev
//! power_on_units = "mm"     # power-on input units: "mm" | "inch" (G20/G21 in the program win)
//! x_mode = "diameter"       # X (and U) written as a "diameter" or a "radius" (FANUC DIA off, trainers)
//! rapid_x = 6000.0          # rapid traverse, mm/min of tool travel along X (radial)
//! rapid_z = 8000.0          # rapid traverse, mm/min along Z
//! rapid_path = "straight"   # "straight" | "per-axis" (each axis at its own rate: a dog-leg)
//! home = [150.0, 250.0]     # reference point [z, x] in G54 coordinates (x = diameter)
//! max_rpm = 4000.0          # spindle limit used for G96 when no G50 S clamp is given
//! power_on_feed = 0.0       # F in force before the program gives one (0: none, PS011)
//! machine_zero = [150.0, 250.0] # machine zero (G53 X0 Z0) [z, x] in G54 coordinates;
//!                           # default: the reference point `home`
//! uw_incremental = true     # system B/C: U/W outside cycles are incremental axes (false: error)
//! power_on_incremental = false # system B/C: G91 at power-on (parameter 3402 bit 3)
//! short_t = "offset"        # a one- or two-digit T: "offset" (T1 = T0001; gsk980 default) or
//!                           # "tool" (T1 = T0101; FANUC and Haas default)
//! accept_m = [50, 51]       # M codes this machine knows beyond its control's table
//! m_names = { 68 = "chuck clamp" } # names for them in the report
//! fs15_format = false       # FANUC: read the FS15 one-block G71/G72/G76 (parameter No. 0001 FCV)
//! g92_chamfer_leads = 0.0   # G92 pull-out chamfer, leads at 45° (not Haas: M23/M24 there)
//! g01_cr = "comma"          # corners on G01: "comma" (,C ,R) or "plain" (system-A C±i R±r)
//! g83_full_retract = false  # G83 peck: true full retract to R, false high-speed (No. 5101 RTR)
//! drill_clearance = 1.0     # G83 clearance δ before the next peck, mm (No. 5114)
//! drill_return = "initial"  # "initial" | "r_point": G83–G85 return level (system A, Haas)
//! [haas]                    # Haas settings (spec/dialects.md §3)
//! setting73 = 0.5           # G71/G72 retract between layers, mm (radius)
//! setting86 = 0.0           # G76 thread finish allowance, mm (radius)
//! setting99 = 0.025         # G76 minimum cut, mm (radius)
//! setting95 = 1.0           # G76/G92 chamfer (M23) size, leads
//! setting96 = 45.0          # G76/G92 chamfer angle, degrees from Z
//! peck_retract = 0.5        # G74/G75 chip-break retract, mm
//! [work_offsets]            # G55..G59 origins relative to G54, [z, x];
//! g55 = [-50.0, 0.0]        # p1 … p300: G54.1 P1… / Haas G154 P1…
//! [chuck]                   # chuck and jaws (crate::workholding): grip, face, jaw, od, depth,
//! grip = 20.0               # soft_jaw; none: no chuck checks
//! [tailstock]               # tailstock centre: tip, quill, length
//! tip = 2.0
//! ```

mod profile;

use crate::Pt;
pub use profile::ProfileError;

/// The control a program is written for (spec/dialects.md §0). A program does not say which
/// dialect it is in, and the same code means different motion in each (`G90`, `G92`, `G94`
/// are cycles in system A, modes in B and C), so the control is an input, never a guess.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
pub enum Control {
    /// GSK 980TD, the control of the seed documents: system A words, G98 at power-on.
    #[default]
    #[serde(rename = "gsk980")]
    Gsk980,
    /// FANUC lathe, G-code system A (G99 at power-on: parameter 3402 FPM = 0).
    #[serde(rename = "fanuc-a")]
    FanucA,
    /// FANUC lathe, G-code system B (G90/G91 modes, G77/G78/G79 cycles, G94/G95 feeds).
    #[serde(rename = "fanuc-b")]
    FanucB,
    /// FANUC lathe, G-code system C (B plus G70/G71 units and G72–G78 cycles).
    #[serde(rename = "fanuc-c")]
    FanucC,
    /// Haas lathe: system A codes plus Haas one-block cycles and words.
    #[serde(rename = "haas")]
    Haas,
    /// `LinuxCNC` (rs274ngc) lathe: G7/G8 diameter/radius mode, G90/G91 and G94/G95 modes,
    /// `T n M6` with G43, O-word subroutines, its own G70/G71/G72/G76 (docs/linuxcnc.md).
    #[serde(rename = "linuxcnc")]
    LinuxCnc,
}

/// FANUC lathe G-code system (spec/dialects.md §2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GCodeSystem {
    /// G90/G92/G94 are cycles, U/W incremental (GSK, FANUC A, Haas).
    A,
    /// G90/G91 absolute/incremental, G77/G78/G79 cycles, G94/G95 feed modes.
    B,
    /// As B, and G20/G21/G24 cycles, G70/G71 inch/metric, G72–G78 multiple cycles.
    C,
}

impl Control {
    /// Every control, in the order `--control` lists them.
    pub const ALL: [Self; 6] = [
        Self::Gsk980,
        Self::FanucA,
        Self::FanucB,
        Self::FanucC,
        Self::Haas,
        Self::LinuxCnc,
    ];

    /// The CLI and profile spelling: `gsk980`, `fanuc-a`, … `haas`.
    pub fn key(self) -> &'static str {
        match self {
            Self::Gsk980 => "gsk980",
            Self::FanucA => "fanuc-a",
            Self::FanucB => "fanuc-b",
            Self::FanucC => "fanuc-c",
            Self::Haas => "haas",
            Self::LinuxCnc => "linuxcnc",
        }
    }

    /// How the report's title block names it.
    pub fn title(self) -> &'static str {
        match self {
            Self::Gsk980 => "GSK 980TD (G-code system A)",
            Self::FanucA => "FANUC lathe, G-code system A",
            Self::FanucB => "FANUC lathe, G-code system B",
            Self::FanucC => "FANUC lathe, G-code system C",
            Self::Haas => "Haas lathe",
            Self::LinuxCnc => "LinuxCNC lathe (rs274ngc)",
        }
    }

    /// Parse the CLI/profile spelling.
    pub fn from_key(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.key() == s)
    }

    /// The G-code system its codes are read in.
    pub fn system(self) -> GCodeSystem {
        match self {
            // G90/G91 distance modes, G94/G95 feed modes, G33 threads, G92 offsets
            Self::FanucB | Self::LinuxCnc => GCodeSystem::B,
            Self::FanucC => GCodeSystem::C,
            Self::Gsk980 | Self::FanucA | Self::Haas => GCodeSystem::A,
        }
    }

    /// Power-on feed mode: GSK 980TD starts in G98 (mm/min); FANUC lathes (parameter 3402
    /// FPM = 0, the factory value) and Haas start in feed per revolution (dialects.md §2.4);
    /// `LinuxCNC` starts in G94, units per minute (docs/linuxcnc.md).
    pub fn power_on_feed_mode(self) -> FeedMode {
        match self {
            Self::Gsk980 | Self::LinuxCnc => FeedMode::G98,
            _ => FeedMode::G99,
        }
    }
}

/// Which words chamfer and round a G01's corner (spec/dialects.md §6.5, profile `g01_cr`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum G01Cr {
    /// `,C c` / `,R r` (FANUC 0i/30i, Haas); a plain C is the C axis, a plain R an error.
    #[default]
    Comma,
    /// System A's `C±i` / `R±r` without a comma between perpendicular moves, the sign giving
    /// the direction of the next move.
    Plain,
}

/// How a one- or two-digit T word is read (spec/dialects.md §3.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ShortT {
    /// `T1` is offset 01 of tool 00 (`T0001`).
    Offset,
    /// `T1` is tool 1 with offset 1 (`T0101`).
    Tool,
}

/// Input units at power-on (before any G20/G21).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres.
    #[default]
    Mm,
    /// Inches (a US Haas with Setting 9 = inch).
    Inch,
}

/// What an X value is: a diameter (lathes' usual programming) or a radius.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum XMode {
    /// X is the diameter.
    #[default]
    Diameter,
    /// X is the radius (FANUC parameter DIA off, Linux CNC G8, CNC trainers).
    Radius,
}

/// Least input increment system.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
pub enum Increment {
    /// 0.001 mm (the default).
    #[serde(rename = "is-b")]
    IsB,
    /// 0.0001 mm (seed 000's G75.1 example).
    #[serde(rename = "is-c")]
    IsC,
}

impl Increment {
    /// One increment in mm.
    pub fn mm(self) -> f64 {
        match self {
            Self::IsB => 0.001,
            Self::IsC => 0.0001,
        }
    }
    /// Parse the CLI spelling `is-b` / `is-c` (case-insensitive).
    pub fn from_name(s: &str) -> Option<Self> {
        match s.to_ascii_lowercase().as_str() {
            "is-b" | "isb" | "b" => Some(Self::IsB),
            "is-c" | "isc" | "c" => Some(Self::IsC),
            _ => None,
        }
    }
}

/// Feed mode at power-on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FeedMode {
    /// mm/min.
    G98,
    /// mm/rev.
    G99,
}

/// How G00 moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum RapidPath {
    /// Interpolated straight line (the default).
    Straight,
    /// Each axis at its own rate: diagonal first, then the longer axis alone.
    PerAxis,
}

/// Units of the P/Q depth and step words of G74/G75/G75.1/G76.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PqUnits {
    /// Least input increments, no decimal point (FANUC, GSK default).
    Increment,
    /// Millimetres.
    Mm,
}

/// Where a drilling cycle (G83–G85, Haas G81–G84) returns after the hole (spec/dialects.md
/// §6.2): system A and Haas have no G98/G99 return codes, so the profile says.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DrillReturn {
    /// The Z where the cycle was read (the default, **Interpretation**).
    #[default]
    Initial,
    /// The R point.
    RPoint,
}

/// The Haas settings the simulation uses (`[haas]`, spec/dialects.md §3). The defaults are
/// **Interpretations** (the machine's own settings decide).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HaasSettings {
    /// Setting 73, canned cycle retraction: the G71/G72 45° retract between layers, mm.
    pub setting73: f64,
    /// Setting 86, thread finish allowance: G76 d, mm (radius).
    pub setting86: f64,
    /// Setting 99, thread minimum cut: G76 Δdmin, mm (radius).
    pub setting99: f64,
    /// Setting 95, thread chamfer size under M23, in leads.
    pub setting95: f64,
    /// Setting 96, thread chamfer angle, degrees from the Z axis.
    pub setting96: f64,
    /// The G74/G75 chip-break retract (a setting on Haas, not a word), mm.
    pub peck_retract: f64,
}

impl Default for HaasSettings {
    fn default() -> Self {
        Self {
            setting73: 0.5,
            setting86: 0.0,
            setting99: 0.025,
            setting95: 1.0,
            setting96: 45.0,
            peck_retract: 0.5,
        }
    }
}

/// A lathe's settings. `Machine::default()` is a GSK980TDi-like lathe.
#[derive(Debug, Clone, PartialEq)]
pub struct Machine {
    /// The control (dialect) the programs are written for.
    pub control: Control,
    /// Input units at power-on.
    pub power_on_units: Units,
    /// X programmed as a diameter or a radius (the reader doubles radii: gcode's
    /// `ReadOptions::x_radius`).
    pub x_mode: XMode,
    /// IS-B or IS-C.
    pub increment: Increment,
    /// P/Q units of the grooving and threading cycles.
    pub pq_units: PqUnits,
    /// Power-on feed mode.
    pub feed_mode: FeedMode,
    /// Rapid rate along X (radial travel), mm/min.
    pub rapid_x: f64,
    /// Rapid rate along Z, mm/min.
    pub rapid_z: f64,
    /// Rapid path shape.
    pub rapid_path: RapidPath,
    /// Reference point in G54 coordinates, (z, r).
    pub home: Pt,
    /// Spindle limit, rev/min (G96 without G50 S).
    pub max_rpm: f64,
    /// Origins of G54..G59 relative to G54, (z, r).
    pub work_offsets: [Pt; 6],
    /// Which of [`Machine::work_offsets`] the profile states (G54 always: the frame the
    /// stock is given in); a program that cuts in one work system and then switches to
    /// one of unknown origin is an alarm.
    pub work_offsets_stated: [bool; 6],
    /// F in force at power-on (0: none, so a cutting move before any F is alarm PS011,
    /// as on FANUC; a GSK keeps its last F, which a profile can give here).
    pub power_on_feed: f64,
    /// A rapid that removes stock is a crash when the thickness it removes (normal to the
    /// move) exceeds this, mm; below it is a rapid scrape, a warning (spec/simulation.md,
    /// "Rapids that cut").
    pub rapid_cut_tol: f64,
    /// Machine zero in the G54 frame, (z, r): where `G53 X0 Z0` goes (spec/dialects.md §6.4).
    /// **Interpretation:** the reference point `home` unless the profile says otherwise
    /// (on FANUC and Haas lathes the reference position is usually machine zero).
    pub machine_zero: Pt,
    /// Whether the profile gives `machine_zero`: a G10 L2 / L20 writes a work offset in
    /// machine coordinates, placed against the stock only from a stated machine zero (or
    /// one the program's own G10s fix; docs/field-rules.md §18).
    pub machine_zero_stated: bool,
    /// System B/C: U and W outside cycles are incremental axes (`true`, with one warning per
    /// program: it depends on the builder, dialects.md §2.2) or an error (`false`).
    pub uw_incremental: bool,
    /// System B/C: G91 (incremental) at power-on instead of G90 (parameter 3402 bit 3).
    pub power_on_incremental: bool,
    /// How a one- or two-digit T word is read.
    pub short_t: ShortT,
    /// Which words chamfer and round a G01's corner.
    pub g01_cr: G01Cr,
    /// Additional work offsets G54.1 P<n> / Haas G154 P<n>, origins in the G54 frame (z, r).
    pub extra_offsets: std::collections::BTreeMap<u32, Pt>,
    /// M codes this machine knows beyond its control's table (profile `accept_m`).
    pub accept_m: Vec<u32>,
    /// Names of M codes for the report (profile `m_names`).
    pub m_names: std::collections::BTreeMap<u32, String>,
    /// FANUC with the FS15 tape format (parameter No. 0001 FCV): one-block G71/G72/G76.
    pub fs15_format: bool,
    /// The pull-out chamfer of G92 on controls other than Haas (where M23/M24 switch it), in
    /// leads at 45°: the machine's signal or parameter (spec/dialects.md §4.7); 0 = none.
    pub g92_chamfer_leads: f64,
    /// G83 pecks retract fully to the R point (else high-speed: back by the clearance).
    pub g83_full_retract: bool,
    /// G83 clearance δ above the previous depth before the next peck, mm.
    pub drill_clearance: f64,
    /// Return level of the drilling cycles where no G98/G99 says it.
    pub drill_return: DrillReturn,
    /// Haas settings.
    pub haas: HaasSettings,
    /// Chuck and tailstock (`[chuck]`, `[tailstock]`); none by default.
    pub workholding: crate::Workholding,
}

impl Default for Machine {
    fn default() -> Self {
        Self::for_control(Control::Gsk980)
    }
}

impl Machine {
    /// The built-in profile of a control: its power-on modes; the rest as the `GSK980TDi`.
    pub fn for_control(control: Control) -> Self {
        Self {
            control,
            power_on_units: Units::Mm,
            // LinuxCNC powers on in G8, radius mode (G-code reference, "G8")
            x_mode: if control == Control::LinuxCnc {
                XMode::Radius
            } else {
                XMode::Diameter
            },
            increment: Increment::IsB,
            pq_units: PqUnits::Increment,
            feed_mode: control.power_on_feed_mode(),
            rapid_x: 6000.0,
            rapid_z: 8000.0,
            rapid_path: RapidPath::Straight,
            home: Pt::new(150.0, 125.0),
            max_rpm: 4000.0,
            work_offsets: [Pt::default(); 6],
            work_offsets_stated: [true, false, false, false, false, false],
            power_on_feed: 0.0,
            rapid_cut_tol: 0.1,
            machine_zero: Pt::new(150.0, 125.0),
            machine_zero_stated: false,
            // U and W are axes of their own in LinuxCNC
            uw_incremental: control != Control::LinuxCnc,
            power_on_incremental: false,
            g01_cr: G01Cr::Comma,
            short_t: if control == Control::Gsk980 {
                ShortT::Offset
            } else {
                ShortT::Tool
            },
            extra_offsets: Default::default(),
            accept_m: vec![],
            m_names: Default::default(),
            fs15_format: false,
            g92_chamfer_leads: 0.0,
            g83_full_retract: false,
            drill_clearance: 1.0,
            // LinuxCNC powers on retracting to the R plane (interp_setup.cc: R_PLANE, G99)
            drill_return: if control == Control::LinuxCnc {
                DrillReturn::RPoint
            } else {
                DrillReturn::Initial
            },
            haas: HaasSettings::default(),
            workholding: crate::Workholding::default(),
        }
    }

    /// Whether the control reads the one-block G71/G72/G76 (Haas, or FANUC with the FS15
    /// format; spec/dialects.md §3.2, §4.5).
    pub fn one_block_cycles(&self) -> bool {
        self.control == Control::Haas
            || (self.fs15_format
                && matches!(
                    self.control,
                    Control::FanucA | Control::FanucB | Control::FanucC
                ))
    }

    /// Millimetres per P/Q unit of the grooving/threading cycles (metric).
    pub fn pq_mm(&self) -> f64 {
        self.pq_mm_under(1.0)
    }

    /// Millimetres per P/Q unit under the units in force (`unit`: 1, or 25.4 under G20):
    /// the least input increment is 0.001 mm or 0.0001 in (IS-B), a tenth of that under
    /// IS-C, so an inch increment is 2.54 metric ones (cycles.md: P and Q in least input
    /// increments; a FANUC inch G76 P0479 is 0.0479 in, not 0.479 mm).
    pub fn pq_mm_under(&self, unit: f64) -> f64 {
        match self.pq_units {
            PqUnits::Increment => self.increment_mm_under(unit),
            PqUnits::Mm => unit,
        }
    }

    /// Millimetres per least input increment under the units in force (see
    /// [`Machine::pq_mm_under`]).
    pub fn increment_mm_under(&self, unit: f64) -> f64 {
        self.increment.mm() * if unit == 1.0 { 1.0 } else { unit / 10.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_profile() {
        let m = Machine::from_toml("increment = \"is-c\"\nrapid_path = \"per-axis\"\nhome = [100.0, 200.0]\n[work_offsets]\ng55 = [-10.0, 0.0]").unwrap();
        assert_eq!(m.increment, Increment::IsC);
        assert_eq!(m.rapid_path, RapidPath::PerAxis);
        assert_eq!(m.home, Pt::new(100.0, 100.0));
        assert_eq!(m.work_offsets[1], Pt::new(-10.0, 0.0));
        assert!((m.pq_mm() - 0.0001).abs() < 1e-12);
    }

    #[test]
    fn a_control_brings_its_power_on_modes_and_the_file_overrides_them() {
        assert_eq!(Machine::default().control, Control::Gsk980);
        assert_eq!(Machine::default().feed_mode, FeedMode::G98);
        for c in [
            Control::FanucA,
            Control::FanucB,
            Control::FanucC,
            Control::Haas,
        ] {
            assert_eq!(Machine::for_control(c).feed_mode, FeedMode::G99, "{c:?}");
            assert_eq!(Control::from_key(c.key()), Some(c));
        }
        let m = Machine::from_toml("control = \"haas\"\npower_on_units = \"inch\"").unwrap();
        assert_eq!(
            (m.control, m.feed_mode, m.power_on_units),
            (Control::Haas, FeedMode::G99, Units::Inch)
        );
        let m = Machine::from_toml("x_mode = \"radius\"").unwrap();
        assert_eq!(m.x_mode, XMode::Radius);
        assert!(Machine::from_toml("x_mode = \"radial\"").is_err());
        let m = Machine::from_toml("control = \"haas\"\nfeed_mode = \"g98\"").unwrap();
        assert_eq!(
            m.feed_mode,
            FeedMode::G98,
            "a key of the file wins over the control's value"
        );
        // The command line's control wins over the file's.
        let m = Machine::from_toml_for("control = \"haas\"", Some(Control::FanucB)).unwrap();
        assert_eq!(m.control.system(), GCodeSystem::B);
        let e = Machine::from_toml("control = \"siemens\"").unwrap_err();
        assert_eq!(e.line, 1);
    }

    #[test]
    fn unknown_key_is_an_error_with_position() {
        let e = Machine::from_toml("increment = \"is-b\"\nrapid_y = 5").unwrap_err();
        assert_eq!(e.line, 2);
        let e = Machine::from_toml("rapid_x = -5.0").unwrap_err();
        assert!(e.message.contains("positive"));
        assert_eq!((e.line, e.column), (1, 11));
    }

    #[test]
    fn absurd_places_and_rates_are_refused_at_their_value() {
        // found/minimal/P4: a home at 1e308 overflowed the removal grid
        let e = Machine::from_toml("power_on_feed = 100.0\nhome = [1e308, -1e308]").unwrap_err();
        assert_eq!((e.line, e.column), (2, 8));
        assert!(e.message.contains("home"), "{}", e.message);
        let e = Machine::from_toml("[work_offsets]\ng55 = [0.0, 20000.0]").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(Machine::from_toml("max_rpm = 1e9").is_err());
        assert!(Machine::from_toml("home = [9999.0, -9999.0]").is_ok());
    }

    #[test]
    fn haas_and_drilling_keys() {
        let m = Machine::from_toml(
            "control = \"haas\"\ng83_full_retract = true\ndrill_return = \"r_point\"\n[haas]\nsetting73 = 0.2\nsetting86 = 0.02",
        )
        .unwrap();
        assert_eq!(m.haas.setting73, 0.2);
        assert_eq!(m.haas.setting86, 0.02);
        assert_eq!(m.haas.setting99, 0.025);
        assert!(m.g83_full_retract && m.one_block_cycles());
        assert_eq!(m.drill_return, DrillReturn::RPoint);
        let e = Machine::from_toml("[haas]\nsetting96 = 90.0").unwrap_err();
        assert_eq!((e.line, e.column), (2, 13));
        assert!(e.message.contains("haas.setting96"), "{}", e.message);
        assert!(Machine::from_toml("[haas]\nsetting72 = 1.0").is_err());
        assert!(Machine::from_toml("drill_clearance = -1.0").is_err());
        assert!(!Machine::for_control(Control::FanucA).one_block_cycles());
        assert!(
            Machine::from_toml("control = \"fanuc-a\"\nfs15_format = true")
                .unwrap()
                .one_block_cycles()
        );
    }
}
