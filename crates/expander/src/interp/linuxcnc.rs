//! What `LinuxCNC` (rs274ngc) reads differently from FANUC (docs/linuxcnc.md): the modal G7/G8
//! diameter and radius mode and G90.1 absolute arc centres (applied to a copy of the block
//! before it runs, so everything after reads diameters and offsets as usual), `T n` that
//! only prepares the tool and `M6` that changes it, `G43 [H]` / `G49`, `G41.1`/`G42.1 D L`
//! with `LinuxCNC`'s orientation numbers, `G96 D` (the speed clamp) and `G33 K` (the lead).

use super::{alarm, Interp, MotionMode};
use crate::codes::*;
use crate::linuxcnc::{self as lc};
use crate::tnrc::Nose;
use crate::words::{whole_in, Words};
use crate::Diagnostic;
use gcode::{Block, Word};

/// The offset number latsim keeps the nose of `G41.1`/`G42.1` under (no tool table has it).
pub(crate) const DYNAMIC_OFFSET: u32 = 1_000_000;

/// FANUC's imaginary tip number (spec/tnrc.md) of `LinuxCNC`'s lathe tool orientation `l`.
/// `LinuxCNC`'s `latheorigin_x/z` (`interp_queue.cc`) put the tip of orientation 1 at (−X, +Z)
/// from the nose centre, 2 at (−X, −Z), 3 at (+X, −Z), 4 at (+X, +Z), 6 at −X, 8 at +X:
/// FANUC's 4, 3, 2, 1, 8, 6. 5, 7, 9 and 0 are the same in both.
pub(crate) fn fanuc_tip(l: u8) -> u8 {
    match l {
        1 => 4,
        2 => 3,
        3 => 2,
        4 => 1,
        6 => 8,
        8 => 6,
        l => l,
    }
}

impl Interp<'_> {
    /// The block as `LinuxCNC` means it, when that differs from how it is written: G7/G8 in
    /// the block set the mode first; under G8 every X is a radius, doubled here; under G90.1
    /// an arc's I and K become offsets from the start. `None`: the block as written.
    pub(super) fn linuxcnc_block(&mut self, b: &Block) -> Option<Block> {
        for w in b.words.iter().filter(|w| w.letter == 'G') {
            match w.code_tenths() {
                Some(70) => self.x_diameter = true,
                Some(80) => self.x_diameter = false,
                Some(901) => self.arc_absolute = true,
                Some(911) => self.arc_absolute = false,
                _ => {}
            }
        }
        let doubles = !self.x_diameter && b.has('X');
        let arc = self.arc_absolute && self.is_arc_block(b) && (b.has('I') || b.has('K'));
        if !doubles && !arc {
            return None;
        }
        let mut copy = b.clone();
        let u = self.unit();
        let start = self.pos - self.shift;
        for w in copy.words.iter_mut() {
            match w.letter {
                'X' if doubles => w.value *= 2.0,
                'I' if arc => w.value -= start.r / u,
                'K' if arc => w.value -= start.z / u,
                _ => {}
            }
        }
        Some(copy)
    }

    /// Whether block `b` moves along an arc (its own G2/G3, else the mode in force).
    fn is_arc_block(&self, b: &Block) -> bool {
        let own = b.words.iter().rev().find_map(|w| match w.code_tenths() {
            Some(20 | 30) if w.letter == 'G' => Some(true),
            Some(0 | 10 | 330) if w.letter == 'G' => Some(false),
            _ => None,
        });
        own.unwrap_or(matches!(self.motion, MotionMode::Cw | MotionMode::Ccw))
    }

    /// The `LinuxCNC` modes of `set_mode`: `Ok(false)` when `t` is none of them.
    pub(super) fn linuxcnc_mode(
        &mut self,
        t: i32,
        (w, b): (&Word, &Block),
        used: &mut Words,
    ) -> Result<bool, Diagnostic> {
        match t {
            // applied to the block before it ran (`linuxcnc_block`)
            lc::X_DIAMETER | lc::X_RADIUS | lc::ARC_ABSOLUTE | lc::ARC_INCREMENTAL => {}
            lc::PATH_CONTROL => {
                used.take('P');
                used.take('Q');
            }
            lc::LENGTH_OFFSET => {
                // M6 in the same block loads its tool first (LinuxCNC's order of execution)
                let m6 = b.words.iter().any(|w| w.letter == 'M' && w.value == 6.0);
                let prepared = b
                    .words
                    .iter()
                    .find(|w| w.letter == 'T')
                    .map(|t| t.value as u32);
                let loaded = match (m6, prepared.or(self.pending_tool)) {
                    (true, Some(t)) => t,
                    _ => self.tool,
                };
                self.length_offset(w, loaded, used)?
            }
            lc::LENGTH_CANCEL => {}
            lc::G92_RESET => self.drop_g92_offset(),
            G96 => {
                self.css = true;
                if let Some(d) = used.take('D') {
                    self.s_clamp = d.value;
                }
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `G43 [H n]`: the tool table's entry of the loaded tool (or of tool n) gives the
    /// offset; latsim's tools are measured to their tip, so it selects the nose only.
    fn length_offset(&mut self, g: &Word, loaded: u32, used: &mut Words) -> Result<(), Diagnostic> {
        let offset = match used.take('H') {
            Some(h) if !whole_in(h, 0.0, 99_999.0) => {
                return Err(alarm(
                    h.span,
                    "LS-VALUE",
                    "G43 H must be a tool number",
                    "write G43 H<tool number>, or G43 for the loaded tool",
                ))
            }
            Some(h) if h.value > 0.0 => h.value as u32,
            _ => loaded,
        };
        if offset == 0 {
            return Err(alarm(
                g.span,
                "LS-T-WORD",
                "G43 without a loaded tool",
                "load a tool with T<n> M6 before G43",
            ));
        }
        self.flush_compensation();
        self.offset = offset;
        Ok(())
    }

    /// `T n`: `LinuxCNC` prepares tool n; `M6` loads it.
    pub(super) fn prepare_tool(&mut self, t: &Word) -> Result<(), Diagnostic> {
        if !whole_in(t, 0.0, 99_999.0) {
            return Err(alarm(
                t.span,
                "LS-T-WORD",
                "T must be a tool number",
                "write T<n> M6 to load tool n (LinuxCNC)",
            ));
        }
        self.pending_tool = Some(t.value as u32);
        Ok(())
    }

    /// `M6`: the prepared tool is loaded and cuts from now on (tool 0 unloads: the tool
    /// in force keeps cutting, as latsim has no empty spindle).
    pub(super) fn change_tool(&mut self, m: &Word) -> Result<(), Diagnostic> {
        let Some(tool) = self.pending_tool else {
            return Err(alarm(
                m.span,
                "LS-T-WORD",
                "M6 without a tool prepared by a T word",
                "write T<n> M6",
            ));
        };
        self.flush_compensation();
        self.select_tool(tool);
        if tool != 0 && !self.out.tool_offsets.contains(&(tool, tool)) {
            self.out.tool_offsets.push((tool, tool));
        }
        Ok(())
    }

    /// `G41.1`/`G42.1 D L`: the nose of diameter D and orientation L (`LinuxCNC` numbers,
    /// `fanuc_tip`) compensates from this block on.
    pub(super) fn dynamic_nose(&mut self, g: &Word, used: &mut Words) -> Result<(), Diagnostic> {
        let Some(d) = used.take('D') else {
            return Err(alarm(
                g.span,
                "LS-VALUE",
                "G41.1/G42.1 without D (the tool diameter)",
                "write G41.1 D<diameter> L<orientation>",
            ));
        };
        let l = match used.take('L') {
            Some(l) if !whole_in(l, 0.0, 9.0) => {
                return Err(alarm(
                    l.span,
                    "LS-VALUE",
                    "L must be a lathe tool orientation 0 to 9",
                    "see LinuxCNC's lathe tool orientations",
                ))
            }
            Some(l) => l.value as u8,
            None => 0,
        };
        if d.value < 0.0 {
            return Err(alarm(
                d.span,
                "LS-VALUE",
                "negative tool diameter",
                "D is the tool's diameter",
            ));
        }
        let nose = Nose {
            radius: d.value * self.unit() / 2.0,
            tip: fanuc_tip(l),
        };
        self.flush_compensation();
        self.noses.insert(DYNAMIC_OFFSET, Ok(nose));
        self.offset = DYNAMIC_OFFSET;
        Ok(())
    }

    /// `G33 K`: the lead of a `LinuxCNC` thread move (K, not F: F stays the feed).
    pub(super) fn thread_lead(&self, b: &Block, used: &mut Words) -> Result<f64, Diagnostic> {
        match used.take('K') {
            Some(k) if k.value > 0.0 => Ok(k.value * self.unit()),
            Some(k) => Err(alarm(
                k.span,
                "LS-VALUE",
                "G33 K must be positive",
                "K is the distance per revolution",
            )),
            None => Err(alarm(
                b.span,
                "LS-VALUE",
                "G33 without K",
                "write G33 Z… K<distance per revolution>",
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linuxcnc_orientations_swap_1_4_2_3_6_8() {
        let tips: Vec<u8> = (0..=9).map(fanuc_tip).collect();
        assert_eq!(tips, vec![0, 4, 3, 2, 1, 5, 8, 7, 6, 9]);
    }
}
