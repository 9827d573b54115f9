//! The work frame the program's words are read in: work offsets (G54–G59, G54.1 P / Haas
//! G154 P), the local shift G52, the preset G50.3 (B/C G92.1), machine coordinates G53
//! and the offsets a program writes itself with G10 (spec/dialects.md §6.3, §6.4).
//!
//! Segments stay in the G54 frame of the profile (the one the stock is given in); these
//! codes only move the origin later words are read from, and each shift that changes the
//! frame is shown as a warning.

use super::{alarm, Interp, MotionMode};
use crate::words::{whole_in, Words};
use crate::{Diagnostic, Machine, Pt};
use gcode::{Block, Word};
use std::collections::BTreeMap;

/// The work frames as the program leaves them.
#[derive(Clone, PartialEq)]
pub(crate) struct Frames {
    /// The work system in force.
    work: Work,
    /// Its origin in the G54 frame, with the external shift.
    origin: Pt,
    /// G54–G59 origins, as the profile gives them and G10 L2 changes them.
    offsets: [Pt; 6],
    /// Which of them the profile or a G10 L2 states.
    stated: [bool; 6],
    /// The word that selected the work system in force (none: G54 at power-on).
    selected_by: Option<gcode::Span>,
    /// The work system the last cutting move ran in.
    cut_in: Option<Work>,
    /// G54.1 P / G154 P origins, from the profile and G10 L20.
    extra: BTreeMap<u32, Pt>,
    /// The external work shift (G10 P0 / L2 P0).
    ext_shift: Pt,
    /// The G52 local shift.
    local: Pt,
    /// Machine zero in the G54 frame, per axis (z, r): the profile's `machine_zero`, or
    /// fixed by the first G10 L2 / L20 that sets the work system in force on that axis
    /// (it stays the stock's frame); `None`: unknown (docs/field-rules.md §18).
    zero: [Option<f64>; 2],
    /// G10 values (machine coordinates) not yet placed, their axis's machine zero
    /// unknown: (work system, axis 0 = Z / 1 = X radius, value).
    pending: Vec<(Work, usize, f64)>,
}

impl Frames {
    /// The profile's offsets, G54 in force.
    pub(crate) fn new(machine: &Machine) -> Self {
        Self {
            work: Work::Fixed(0),
            origin: Pt::default(),
            offsets: machine.work_offsets,
            stated: machine.work_offsets_stated,
            selected_by: None,
            cut_in: None,
            extra: machine.extra_offsets.clone(),
            ext_shift: Pt::default(),
            local: Pt::default(),
            zero: if machine.machine_zero_stated {
                [Some(machine.machine_zero.z), Some(machine.machine_zero.r)]
            } else {
                [None, None]
            },
            pending: vec![],
        }
    }

    /// Whether where work system `w` lies from the stock's frame is known: the profile
    /// states it or a G10 placed it (an additional offset is always one of them), and no
    /// G10 value of it waits for an unknown machine zero.
    fn known(&self, w: Work) -> bool {
        let stated = match w {
            Work::Fixed(k) => self.stated[k],
            Work::Extra(_) => true,
        };
        stated && !self.waits(w)
    }

    /// Whether a G10 value of `w` waits for an unknown machine zero.
    fn waits(&self, w: Work) -> bool {
        self.pending.iter().any(|&(p, _, _)| p == w)
    }

    /// The origin of work system `w` (G54 frame), without the external shift.
    fn offset(&self, w: Work) -> Pt {
        match w {
            Work::Fixed(i) => self.offsets[i],
            Work::Extra(n) => self.extra.get(&n).copied().unwrap_or_default(),
        }
    }

    /// Sets axis `axis` of work system `w`'s origin to `v`.
    fn set_axis(&mut self, w: Work, axis: usize, v: f64) {
        let mut o = self.offset(w);
        if axis == 0 {
            o.z = v;
        } else {
            o.r = v;
        }
        match w {
            Work::Fixed(i) => self.offsets[i] = o,
            Work::Extra(n) => {
                self.extra.insert(n, o);
            }
        }
    }
}

impl Interp<'_> {
    /// G54–G59 (`g`): the work system `i` (0 = G54), with the G52 local shift kept.
    pub(super) fn select_work_offset(&mut self, g: &Word, i: usize) {
        self.frames.work = Work::Fixed(i);
        self.frames.selected_by = Some(g.span);
        self.frames.origin = self.frames.offsets[i] + self.frames.ext_shift;
        self.shift = self.frames.origin + self.frames.local;
    }

    /// Before a cutting move: a program that cuts in one work system and then in another
    /// needs both origins (spec/dialects.md §6: a missing work offset is an error), an
    /// alarm at the word that selected the second; one work system alone, whichever, is the
    /// frame the stock is given in, and selecting one without cutting in it (a reset
    /// before M30) is no matter (docs/field-rules.md §18).
    pub(super) fn cut_in_work_system(&mut self) -> Result<(), Diagnostic> {
        let now = self.frames.work;
        let known = |w: Work| self.frames.known(w);
        match self.frames.cut_in {
            Some(before) if before != now && !(known(before) && known(now)) => {
                let name = |w: Work| match w {
                    Work::Fixed(k) => format!("G{}", 54 + k),
                    Work::Extra(n) => format!("P{n}"),
                };
                let unknown = if known(now) { before } else { now };
                let key = match unknown {
                    Work::Fixed(k) => (format!("g{}", 54 + k), format!("G10 L2 P{}", k + 1)),
                    Work::Extra(n) => (format!("p{n}"), format!("G10 L20 P{n}")),
                };
                let span = self.frames.selected_by.unwrap_or_default();
                if self.frames.waits(unknown) {
                    return Err(alarm(
                        span,
                        "LS-WORK-OFFSET",
                        format!(
                            "{} cuts after cutting in {}, and {} is set by G10 in machine coordinates while the machine profile gives no machine_zero: where one work system lies from the other is unknown",
                            name(now),
                            name(before),
                            name(unknown)
                        ),
                        "add machine_zero = [z, x] to the --machine profile (machine zero in G54's frame), or set the first work system by G10 too (G10 L2 P1 for G54): the difference of the two places them",
                    ));
                }
                Err(alarm(
                    span,
                    "LS-WORK-OFFSET",
                    format!(
                        "{} cuts after cutting in {}, and the machine profile gives no origin for {}: where one work system lies from the other is unknown",
                        name(now),
                        name(before),
                        name(unknown)
                    ),
                    format!("add {} = [z, x] under [work_offsets] in the --machine profile (its zero in G54's frame), or set it with {}", key.0, key.1),
                ))
            }
            _ => {
                self.frames.cut_in = Some(now);
                Ok(())
            }
        }
    }

    /// The work system in force again after its offset changed (G10).
    fn reselect_work(&mut self) {
        let o = self.frames.offset(self.frames.work);
        self.frames.origin = o + self.frames.ext_shift;
        self.shift = self.frames.origin + self.frames.local;
    }

    /// `G54.1 P<n>` (FANUC), `G154 P<n>` (Haas), `G54 P<n>`: an additional work offset
    /// from the profile's `[work_offsets] p<n>`; a missing one is an alarm at P.
    pub(super) fn select_extra_offset(
        &mut self,
        g: &Word,
        used: &mut Words,
    ) -> Result<(), Diagnostic> {
        let Some(p) = used.take('P') else {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "an additional work offset needs P (its number)",
                "write e.g. G54.1 P1 (FANUC) or G154 P1 (Haas)",
            ));
        };
        if !whole_in(p, 1.0, 300.0) {
            return Err(alarm(
                p.span,
                "LS-VALUE",
                "P must be an additional work offset number 1 … 300",
                "write e.g. P1",
            ));
        }
        let n = p.value as u32;
        let Some(&o) = self.frames.extra.get(&n) else {
            return Err(alarm(
                p.span,
                "LS-WORK-OFFSET",
                format!("additional work offset P{n} is not in the machine profile"),
                format!("add p{n} = [z, x] under [work_offsets] in the --machine profile, or set it with G10 L20 P{n}"),
            ));
        };
        self.frames.work = Work::Extra(n);
        self.frames.selected_by = Some(g.span);
        self.frames.origin = o + self.frames.ext_shift;
        self.shift = self.frames.origin + self.frames.local;
        Ok(())
    }

    /// G52 X Z: a local shift of the work frame (G52 X0 Z0 cancels). **Interpretation**
    /// (Haas: Setting 33 dependent): applied like a work offset shift, warned.
    pub(super) fn g52(&mut self, b: &Block, used: &mut Words) -> Result<(), Diagnostic> {
        let u = self.unit();
        let x = used.take('X').map(|w| w.value * u / 2.0);
        let z = used.take('Z').map(|w| w.value * u);
        if x.is_none() && z.is_none() {
            return Err(alarm(
                b.span,
                "LS-VALUE",
                "G52 without X or Z",
                "write G52 X… Z… for the local shift, G52 X0 Z0 to cancel it",
            ));
        }
        self.frames.local = Pt::new(
            z.unwrap_or(self.frames.local.z),
            x.unwrap_or(self.frames.local.r),
        );
        self.shift = self.frames.origin + self.frames.local;
        self.warn(
            b.span,
            "W-G52",
            format!(
                "G52 local shift ΔX {:.3} ΔZ {:.3} (diameter, mm): later words are read in the shifted frame; the section stays in the first frame",
                2.0 * self.frames.local.r,
                self.frames.local.z
            ),
            "on a Haas the meaning of G52 depends on Setting 33; latsim applies it like a work offset shift",
        );
        Ok(())
    }

    /// G50.3 (system A) / G92.1 (B, C) X0 Z0: the named axes go back to the selected work
    /// system, cancelling the G50/G92 and G52 shifts. **Interpretation:** only the zero
    /// form is accepted (the form programs use; other values need the control's preset
    /// parameters).
    pub(super) fn preset(&mut self, g: &Word, used: &mut Words) -> Result<(), Diagnostic> {
        let x = used.take('X').or_else(|| used.take('U'));
        let z = used.take('Z').or_else(|| used.take('W'));
        if x.is_none() && z.is_none() {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "workpiece coordinate preset without an axis",
                "write e.g. G92.1 X0 Z0 (G50.3 X0 Z0 in system A)",
            ));
        }
        for w in [x, z].into_iter().flatten() {
            if w.value != 0.0 {
                return Err(alarm(
                    w.span,
                    "LS-VALUE",
                    "the workpiece coordinate preset takes 0 for each axis",
                    "write X0 Z0",
                ));
            }
        }
        self.frames.local = Pt::default();
        if x.is_some() {
            self.shift.r = self.frames.origin.r;
        }
        if z.is_some() {
            self.shift.z = self.frames.origin.z;
        }
        Ok(())
    }

    /// `LinuxCNC`'s `G92.1` / `G92.2`: the G92 offset is dropped, and with it the G52 shift
    /// (`LinuxCNC`'s G52 "shares parameters with G92", coordinates.adoc "The G52 command"):
    /// later words are read in the work system in force. (The two differ only in parameters
    /// 5211–5219, which latsim does not keep.)
    pub(super) fn drop_g92_offset(&mut self) {
        self.frames.local = Pt::default();
        self.shift = self.frames.origin;
    }

    /// G53 X Z: a move to that machine position (from the profile's `machine_zero`). FANUC
    /// and GSK move at rapid traverse whatever the mode; Haas at the G00/G01 in force
    /// (spec/dialects.md §6.4, docs/field-rules.md). A rapid never cuts, so if its sweep
    /// meets stock that is a crash.
    pub(super) fn g53(&mut self, b: &Block, used: &mut Words, g: &Word) -> Result<(), Diagnostic> {
        if let Some(w) = used.take('U').or_else(|| used.take('W')) {
            return Err(alarm(
                w.span,
                "LS-VALUE",
                "G53 takes machine coordinates X and Z, not increments",
                "write G53 X… Z…",
            ));
        }
        let u = self.unit();
        let x = used.take('X');
        let z = used.take('Z');
        if x.is_none() && z.is_none() {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "G53 without an axis",
                "write e.g. G53 X0 (X to machine zero) or G53 X0 Z0",
            ));
        }
        // machine zero as the profile gives it or the program's G10s fixed it
        let guess = self.machine.machine_zero;
        let zero = Pt::new(
            self.frames.zero[0].unwrap_or(guess.z),
            self.frames.zero[1].unwrap_or(guess.r),
        );
        if zero == self.machine.home {
            self.note_once(
                g.span,
                "W-MACHINE-ZERO",
                "G53: machine zero is taken as the reference point (home)",
                "give machine_zero = [z, x] in the --machine profile if this lathe's machine zero is elsewhere",
            );
        }
        let to = Pt::new(
            z.map_or(self.pos.z, |w| zero.z + w.value * u),
            x.map_or(self.pos.r, |w| zero.r + w.value * u / 2.0),
        );
        if self.machine.control == crate::Control::Haas && self.motion == MotionMode::Line {
            if to.dist(self.pos) < 1e-12 {
                return Ok(());
            }
            return self.push(b, crate::Motion::Feed, to, None, 0.0);
        }
        self.rapid(b, to)
    }

    /// G10 L2 P1–6 X Z / G10 L20 P<n> X Z: work offset n set from the program (machine
    /// coordinates of the work zero, measured from the profile's `machine_zero`), for the
    /// rest of the run; the active system moves at once.
    pub(super) fn set_work_offset(
        &mut self,
        l: &Word,
        p: &Word,
        used: &mut Words,
    ) -> Result<(), Diagnostic> {
        let extra = l.value == 20.0;
        let range = if extra { 1.0..=300.0 } else { 0.0..=6.0 };
        if p.has_point || !range.contains(&p.value) {
            return Err(alarm(
                p.span,
                "LS-VALUE",
                format!(
                    "G10 L{} P must be {}",
                    l.value,
                    if extra {
                        "1 … 300"
                    } else {
                        "0 (external shift) or 1 … 6 (G54 … G59)"
                    }
                ),
                "write e.g. G10 L2 P1 X0 Z-350.",
            ));
        }
        let n = p.value as u32;
        let u = self.unit();
        let x = used.take('X').map(|w| w.value * u / 2.0);
        let z = used.take('Z').map(|w| w.value * u);
        if !extra && n == 0 {
            // The external shift is a shift, not a position.
            let old = self.frames.ext_shift;
            let new = Pt::new(z.unwrap_or(old.z), x.unwrap_or(old.r));
            self.frames.ext_shift = new;
            self.g10_note(l, "the external work shift".to_string(), new - old, "");
            self.reselect_work();
            return Ok(());
        }
        let work = if extra {
            // a new additional offset: in the stock's frame until placed
            self.frames.extra.entry(n).or_default();
            Work::Extra(n)
        } else {
            Work::Fixed(n as usize - 1)
        };
        let old = self.frames.offset(work);
        let active = work == self.frames.work;
        let mut placed = "";
        for (axis, value) in [(0, z), (1, x)] {
            let Some(value) = value else { continue };
            self.frames
                .pending
                .retain(|&(w, a, _)| !(w == work && a == axis));
            match self.frames.zero[axis] {
                Some(zero) => self.frames.set_axis(work, axis, zero + value),
                None if active => {
                    // the work system in force stays where the stock is: this value fixes
                    // machine zero, and the values waiting for it are placed
                    let here = if axis == 0 { old.z } else { old.r };
                    let zero = here - value;
                    self.frames.zero[axis] = Some(zero);
                    let (now, still): (Vec<_>, Vec<_>) = std::mem::take(&mut self.frames.pending)
                        .into_iter()
                        .partition(|&(_, a, _)| a == axis);
                    self.frames.pending = still;
                    for (w, a, v) in now {
                        self.frames.set_axis(w, a, zero + v);
                    }
                    placed = "; the profile gives no machine_zero: this work system stays the stock's frame and machine zero is placed from it";
                }
                None => {
                    self.frames.pending.push((work, axis, value));
                    placed = "; the profile gives no machine_zero: it is placed against the stock once a G10 sets the work system in force";
                }
            }
        }
        if let Work::Fixed(i) = work {
            self.frames.stated[i] = true;
        }
        let new = self.frames.offset(work);
        let name = match work {
            Work::Extra(n) => format!("additional work offset P{n}"),
            Work::Fixed(i) => format!("G{}", 54 + i),
        };
        self.g10_note(l, name, new - old, placed);
        if active {
            self.reselect_work();
        }
        Ok(())
    }

    /// The warning W-G10-WORK: G10 moved `name`'s origin by `moved`.
    fn g10_note(&mut self, l: &Word, name: String, moved: Pt, placed: &str) {
        self.warn(
            l.span,
            "W-G10-WORK",
            format!(
                "G10 sets {name}: its origin moves by ΔX {:.3} ΔZ {:.3} (diameter, mm) for the rest of the run{placed}",
                2.0 * moved.r,
                moved.z
            ),
            "the section stays in the profile's G54 frame; work offsets are machine coordinates from the profile's machine_zero",
        );
    }
}

/// A work system.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Work {
    /// G54 … G59 (0 … 5).
    Fixed(usize),
    /// G54.1 P<n> / G154 P<n>.
    Extra(u32),
}
