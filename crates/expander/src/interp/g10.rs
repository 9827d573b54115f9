//! G10 data setting from the program (spec/dialects.md §6.3): tool offsets (nose radius
//! and tip for G41/G42), work offsets (`L2`, `L20`, in `frame`), and the parameter input
//! mode `G10 L50 … G11`, whose blocks are skipped.

use super::{alarm, Interp};
use crate::tnrc::Nose;
use crate::words::Words;
use crate::Diagnostic;
use gcode::Word;

impl Interp<'_> {
    /// One G10 block.
    pub(super) fn g10(&mut self, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        let l = used.take('L');
        let p = used.take('P');
        match (l.map(|l| l.value), p) {
            (Some(v), Some(p)) if v == 2.0 || v == 20.0 => {
                self.set_work_offset(l.unwrap_or(g), p, used)
            }
            (Some(50.0), _) => {
                self.param_mode = true;
                self.warn(
                    g.span,
                    "W-G10-L50",
                    "G10 L50: the parameter blocks up to G11 are skipped (their N words are parameter numbers)",
                    "latsim does not model control parameters; set what they change in the machine profile",
                );
                Ok(())
            }
            (None, Some(p)) if p.value == 0.0 && !p.has_point => {
                self.set_work_offset(g, p, used)
            }
            (None, Some(p)) => self.tool_offset(p, used),
            (Some(_), _) => Err(alarm(
                l.map_or(g.span, |l| l.span),
                "LS-VALUE",
                "G10 L must be 2 (work offset), 20 (additional work offset) or 50 (parameters), with P",
                "tool offsets are G10 P<n> X Z R Q without L",
            )),
            (None, None) => Err(alarm(
                g.span,
                "LS-VALUE",
                "G10 without P",
                "write G10 P<offset> X Z R Q, G10 L2 P<1-6> X Z or G10 L20 P<n> X Z",
            )),
        }
    }

    /// `G10 P<n> X Z R Q` / `U W C Q`: tool offset n (1–64 wear, 10000+n geometry). R (or
    /// the increment C) and Q set the nose the offset's G41/G42 use (a wear R adds to the
    /// nose radius). **Interpretation:** X/Z/U/W, the offset lengths, are not applied:
    /// latsim's tool positions are the programmed tip of the tool table's tools (warned).
    fn tool_offset(&mut self, p: &Word, used: &mut Words) -> Result<(), Diagnostic> {
        let (n, geometry) = match p.value {
            v if p.has_point || v < 1.0 => (0, false),
            v if v > 10_000.0 && v <= 10_099.0 => ((v - 10_000.0) as u32, true),
            v if v <= 99.0 => (v as u32, false),
            _ => (0, false),
        };
        if n == 0 {
            return Err(alarm(
                p.span,
                "LS-VALUE",
                "G10 P must be a tool offset number 1 … 99 (wear) or 10001 … 10099 (geometry)",
                "write e.g. G10 P10001 X0 Z0 R0.8 Q3",
            ));
        }
        let u = self.unit();
        let r = used.take('R').map(|w| w.value * u);
        let c = used.take('C').map(|w| w.value * u);
        let q = used.take('Q');
        let lengths: Vec<&Word> = ['X', 'Z', 'U', 'W']
            .iter()
            .filter_map(|&l| used.take(l))
            .collect();
        if let Some(q) = q {
            if q.has_point || !(0.0..=9.0).contains(&q.value) {
                return Err(alarm(
                    q.span,
                    "LS-VALUE",
                    "G10 Q is the imaginary tip number 0 … 9",
                    "write e.g. Q3",
                ));
            }
        }
        if let Some(first) = lengths.first() {
            self.warn(
                first.span,
                "W-G10-OFFSET",
                format!("G10 offset {n}: the X/Z offset lengths are not applied"),
                "latsim moves the programmed tip of the tool table's tool; only R and Q (the nose) are used",
            );
        }
        if r.is_none() && c.is_none() && q.is_none() {
            return Ok(());
        }
        match self.noses.get(&n).copied() {
            Some(Ok(nose)) => {
                let radius = match (r, geometry) {
                    (Some(r), true) => r,
                    (Some(r), false) => nose.radius + r,
                    (None, _) => nose.radius,
                } + c.unwrap_or(0.0);
                if radius < 0.0 {
                    return Err(alarm(
                        p.span,
                        "LS-VALUE",
                        format!("G10 makes the nose radius of offset {n} negative ({radius:.3} mm)"),
                        "check R and C",
                    ));
                }
                let tip = q.map_or(nose.tip, |q| q.value as u8);
                self.noses.insert(n, Ok(Nose { radius, tip }));
            }
            _ => self.warn(
                p.span,
                "W-G10-OFFSET",
                format!("G10 offset data not applied: the tool table has no turning tool with offset {n}"),
                "add the tool to --tools so G10's nose radius and tip can be used",
            ),
        }
        Ok(())
    }
}
