//! Reading a machine profile (TOML): each key checked where it stands, the values a lathe
//! cannot have refused at their place with line and column; absent keys keep the built-in
//! profile of the control.

use toml::Spanned;

use super::{
    Control, DrillReturn, FeedMode, G01Cr, Increment, Machine, PqUnits, RapidPath, ShortT, Units,
    XMode,
};
use crate::text_place::line_col;
use crate::Pt;

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    control: Option<Control>,
    power_on_units: Option<Units>,
    x_mode: Option<XMode>,
    increment: Option<Increment>,
    pq_units: Option<PqUnits>,
    feed_mode: Option<FeedMode>,
    rapid_x: Option<Spanned<f64>>,
    rapid_z: Option<Spanned<f64>>,
    rapid_path: Option<RapidPath>,
    home: Option<Spanned<[f64; 2]>>,
    max_rpm: Option<Spanned<f64>>,
    power_on_feed: Option<Spanned<f64>>,
    rapid_cut_tol: Option<Spanned<f64>>,
    machine_zero: Option<Spanned<[f64; 2]>>,
    uw_incremental: Option<bool>,
    power_on_incremental: Option<bool>,
    short_t: Option<ShortT>,
    g01_cr: Option<G01Cr>,
    accept_m: Option<Vec<Spanned<u32>>>,
    m_names: Option<std::collections::BTreeMap<String, Spanned<String>>>,
    work_offsets: Option<std::collections::BTreeMap<Spanned<String>, Spanned<[f64; 2]>>>,
    fs15_format: Option<bool>,
    g92_chamfer_leads: Option<Spanned<f64>>,
    g83_full_retract: Option<bool>,
    drill_clearance: Option<Spanned<f64>>,
    drill_return: Option<DrillReturn>,
    haas: Option<HaasFile>,
    chuck: Option<crate::workholding::ChuckFile>,
    tailstock: Option<crate::workholding::TailstockFile>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct HaasFile {
    setting73: Option<Spanned<f64>>,
    setting86: Option<Spanned<f64>>,
    setting99: Option<Spanned<f64>>,
    setting95: Option<Spanned<f64>>,
    setting96: Option<Spanned<f64>>,
    peck_retract: Option<Spanned<f64>>,
}

/// Largest coordinate a profile may give, mm: no lathe travels 10 m.
const MAX_COORD_MM: f64 = 10_000.0;
/// Largest rate (rapid mm/min, spindle rev/min, power-on feed) a profile may give.
const MAX_RATE: f64 = 1.0e6;

/// A machine profile that could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct ProfileError {
    /// 1-based line (0 if unknown).
    pub line: u32,
    /// 1-based column.
    pub column: u32,
    /// What is wrong.
    pub message: String,
}

/// The profile's text, to say where a value stands.
struct Text<'a>(&'a str);

impl Text<'_> {
    /// The error for the value at `span`.
    fn bad(&self, span: std::ops::Range<usize>, message: String) -> ProfileError {
        let (line, column) = line_col(self.0, span.start);
        ProfileError {
            line,
            column,
            message,
        }
    }

    /// A point `[z, x]` (x a diameter) within the machine's reach.
    fn point(&self, name: &str, v: Spanned<[f64; 2]>) -> Result<Pt, ProfileError> {
        let c = *v.get_ref();
        if c.iter().all(|c| c.is_finite() && c.abs() <= MAX_COORD_MM) {
            Ok(Pt::new(c[0], c[1] / 2.0))
        } else {
            Err(self.bad(
                v.span(),
                format!("{name} must be [z, x] in mm, each within ±{MAX_COORD_MM}, got {c:?}"),
            ))
        }
    }

    /// A value within [lo, hi] into `slot`, if given: a setting beyond is a typo, refused
    /// at its value.
    fn within(
        &self,
        name: &str,
        v: Option<Spanned<f64>>,
        (lo, hi): (f64, f64),
        slot: &mut f64,
    ) -> Result<(), ProfileError> {
        if let Some(v) = v {
            let x = *v.get_ref();
            if !(x.is_finite() && x >= lo && x <= hi) {
                return Err(self.bad(
                    v.span(),
                    format!("{name} must be within {lo} … {hi}, got {x}"),
                ));
            }
            *slot = x;
        }
        Ok(())
    }
}

impl Machine {
    /// Read a profile; absent keys keep the defaults of its `control` (else gsk980).
    pub fn from_toml(text: &str) -> Result<Self, ProfileError> {
        Self::from_toml_for(text, None)
    }

    /// Read a profile on the built-in profile of `control` (the command line's
    /// `--control`, which wins over the file's `control` key); absent keys keep its values.
    pub fn from_toml_for(text: &str, control: Option<Control>) -> Result<Self, ProfileError> {
        let mut file: File = toml::from_str(text).map_err(|e| {
            let (line, column) = e.span().map(|s| line_col(text, s.start)).unwrap_or((0, 0));
            ProfileError {
                line,
                column,
                message: e.message().to_string(),
            }
        })?;
        let mut m = Self::for_control(control.or(file.control).unwrap_or_default());
        let text = Text(text);
        m.set_modes(&file);
        m.read_rates(&mut file, &text)?;
        m.read_cycle_settings(&mut file, &text)?;
        m.read_workholding(&mut file, &text)?;
        m.read_m_codes(&mut file, &text)?;
        m.read_work_offsets(&mut file, &text)?;
        Ok(m)
    }

    /// The modes and switches, which need no check beyond their type.
    fn set_modes(&mut self, f: &File) {
        let m = self;
        if let Some(v) = f.power_on_units {
            m.power_on_units = v;
        }
        if let Some(v) = f.x_mode {
            m.x_mode = v;
        }
        if let Some(v) = f.increment {
            m.increment = v;
        }
        if let Some(v) = f.pq_units {
            m.pq_units = v;
        }
        if let Some(v) = f.feed_mode {
            m.feed_mode = v;
        }
        if let Some(v) = f.rapid_path {
            m.rapid_path = v;
        }
        m.fs15_format = f.fs15_format.unwrap_or(m.fs15_format);
        m.g83_full_retract = f.g83_full_retract.unwrap_or(m.g83_full_retract);
        m.drill_return = f.drill_return.unwrap_or(m.drill_return);
        if let Some(v) = f.uw_incremental {
            m.uw_incremental = v;
        }
        if let Some(v) = f.power_on_incremental {
            m.power_on_incremental = v;
        }
        if let Some(v) = f.g01_cr {
            m.g01_cr = v;
        }
        if let Some(v) = f.short_t {
            m.short_t = v;
        }
    }

    /// The rates (rapids, spindle, power-on feed), the rapid cut tolerance and the home.
    fn read_rates(&mut self, f: &mut File, text: &Text) -> Result<(), ProfileError> {
        for (name, v, slot) in [
            ("rapid_x", f.rapid_x.take(), &mut self.rapid_x),
            ("rapid_z", f.rapid_z.take(), &mut self.rapid_z),
            ("max_rpm", f.max_rpm.take(), &mut self.max_rpm),
        ] {
            if let Some(v) = v {
                let x = *v.get_ref();
                if !(x.is_finite() && x > 0.0 && x <= MAX_RATE) {
                    return Err(text.bad(
                        v.span(),
                        format!("{name} must be a positive number up to {MAX_RATE:e}, got {x}"),
                    ));
                }
                *slot = x;
            }
        }
        if let Some(v) = f.power_on_feed.take() {
            let x = *v.get_ref();
            if !(x.is_finite() && (0.0..=MAX_RATE).contains(&x)) {
                return Err(text.bad(
                    v.span(),
                    format!("power_on_feed must be zero or positive up to {MAX_RATE:e}, got {x}"),
                ));
            }
            self.power_on_feed = x;
        }
        if let Some(v) = f.rapid_cut_tol.take() {
            let x = *v.get_ref();
            if !(x.is_finite() && (0.0..=MAX_COORD_MM).contains(&x)) {
                return Err(text.bad(
                    v.span(),
                    format!("rapid_cut_tol must be a depth in mm, zero or positive, got {x}"),
                ));
            }
            self.rapid_cut_tol = x;
        }
        if let Some(h) = f.home.take() {
            self.home = text.point("home", h)?;
        }
        Ok(())
    }

    /// The G92 pull-out, the drilling clearance and the Haas settings.
    fn read_cycle_settings(&mut self, f: &mut File, text: &Text) -> Result<(), ProfileError> {
        if let Some(c) = f.g92_chamfer_leads.take() {
            let x = *c.get_ref();
            if !(x.is_finite() && (0.0..=9.9).contains(&x)) {
                return Err(text.bad(
                    c.span(),
                    format!("g92_chamfer_leads must be 0 to 9.9 leads, got {x}"),
                ));
            }
            self.g92_chamfer_leads = x;
        }
        // lengths in mm within [lo, 100 mm], angles within (0°, 90°)
        let clearance = f.drill_clearance.take();
        text.within(
            "drill_clearance",
            clearance,
            (0.0, 100.0),
            &mut self.drill_clearance,
        )?;
        if let Some(h) = f.haas.take() {
            let s = &mut self.haas;
            text.within(
                "haas.setting73",
                h.setting73,
                (0.0, 100.0),
                &mut s.setting73,
            )?;
            text.within(
                "haas.setting86",
                h.setting86,
                (0.0, 100.0),
                &mut s.setting86,
            )?;
            text.within(
                "haas.setting99",
                h.setting99,
                (0.0, 100.0),
                &mut s.setting99,
            )?;
            text.within("haas.setting95", h.setting95, (0.0, 99.0), &mut s.setting95)?;
            text.within("haas.setting96", h.setting96, (1.0, 89.0), &mut s.setting96)?;
            let retract = h.peck_retract;
            text.within(
                "haas.peck_retract",
                retract,
                (0.0, 100.0),
                &mut s.peck_retract,
            )?;
        }
        Ok(())
    }

    /// The chuck and the tailstock, and the machine zero (the home unless given).
    fn read_workholding(&mut self, f: &mut File, text: &Text) -> Result<(), ProfileError> {
        if let Some(c) = f.chuck.take() {
            self.workholding.chuck = Some(c.read().map_err(|(s, msg)| text.bad(s, msg))?);
        }
        if let Some(t) = f.tailstock.take() {
            self.workholding.tailstock = Some(t.read().map_err(|(s, msg)| text.bad(s, msg))?);
        }
        self.machine_zero = self.home;
        if let Some(z) = f.machine_zero.take() {
            self.machine_zero = text.point("machine_zero", z)?;
            self.machine_zero_stated = true;
        }
        Ok(())
    }

    /// The M codes accepted as machine functions, and their names.
    fn read_m_codes(&mut self, f: &mut File, text: &Text) -> Result<(), ProfileError> {
        for code in f.accept_m.take().unwrap_or_default() {
            let c = *code.get_ref();
            if c > 999 {
                return Err(text.bad(
                    code.span(),
                    format!("accept_m: M{c} is not an M code (0 … 999)"),
                ));
            }
            self.accept_m.push(c);
        }
        for (key, name) in f.m_names.take().unwrap_or_default() {
            let Some(c) = key
                .trim_start_matches(['M', 'm'])
                .parse::<u32>()
                .ok()
                .filter(|&c| c <= 999)
            else {
                return Err(text.bad(
                    name.span(),
                    format!("m_names: \"{key}\" is not an M code number (e.g. 68)"),
                ));
            };
            self.m_names.insert(c, name.into_inner());
        }
        Ok(())
    }

    /// The work offsets G54–G59 and the additional ones P1–P300.
    fn read_work_offsets(&mut self, f: &mut File, text: &Text) -> Result<(), ProfileError> {
        for (key, v) in f.work_offsets.take().unwrap_or_default() {
            let name = key.get_ref().to_ascii_lowercase();
            let fixed = ["g54", "g55", "g56", "g57", "g58", "g59"]
                .iter()
                .position(|&g| g == name);
            let extra = name
                .strip_prefix('p')
                .and_then(|n| n.parse::<u32>().ok())
                .filter(|n| (1..=300).contains(n));
            match (fixed, extra) {
                (Some(i), _) => {
                    self.work_offsets[i] = text.point(&name, v)?;
                    self.work_offsets_stated[i] = true;
                }
                (None, Some(n)) => {
                    self.extra_offsets.insert(n, text.point(&name, v)?);
                }
                _ => {
                    return Err(text.bad(
                        key.span(),
                        format!("work_offsets: unknown key `{name}` (g54 … g59, or p1 … p300 for G54.1 P / G154 P)"),
                    ))
                }
            }
        }
        Ok(())
    }
}
