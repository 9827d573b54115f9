//! A block's words with a record of which ones something has used: the rest are reported,
//! never skipped.

use crate::{Diagnostic, Span};
use gcode::{Block, Word};

/// The words of one block and which of them have been used.
pub(crate) struct Words<'b> {
    pub(crate) block: &'b Block,
    used: Vec<bool>,
}

impl<'b> Words<'b> {
    /// The words of `block`, none used yet; `used` is a buffer to fill (a million-line
    /// program would otherwise allocate and free one for every block).
    pub(crate) fn new(block: &'b Block, mut used: Vec<bool>) -> Self {
        used.clear();
        used.resize(block.words.len(), false);
        Self { block, used }
    }

    /// The buffer back, for the next block.
    pub(crate) fn into_buffer(self) -> Vec<bool> {
        self.used
    }

    /// The word with this letter, marked used.
    pub(crate) fn take(&mut self, letter: char) -> Option<&'b Word> {
        let i = self.block.words.iter().position(|w| w.letter == letter)?;
        self.used[i] = true;
        Some(&self.block.words[i])
    }

    /// Mark the word at index `i` used.
    pub(crate) fn mark(&mut self, i: usize) {
        self.used[i] = true;
    }

    /// Whether the block has this letter (without using it).
    pub(crate) fn has(&self, letter: char) -> bool {
        self.block.has(letter)
    }

    /// A length word in mm (calculator type: `X130` is 130 mm), scaled by `unit` (25.4 under G20).
    pub(crate) fn mm(&mut self, letter: char, unit: f64) -> Option<f64> {
        self.take(letter).map(|w| w.value * unit)
    }

    /// A depth/step word in least input increments (G74/G75/G75.1/G76 P and Q): no decimal
    /// point allowed when `mm_per_unit` is an increment; returns mm.
    pub(crate) fn increments(
        &mut self,
        letter: char,
        mm_per_unit: f64,
    ) -> Result<Option<f64>, Diagnostic> {
        let Some(w) = self.take(letter) else {
            return Ok(None);
        };
        if mm_per_unit < 1.0 && w.has_point {
            return Err(Diagnostic::new(
                w.span,
                "LS-INCREMENT",
                format!("{letter} is in least input increments ({mm_per_unit} mm) and takes no decimal point"),
                format!("write {letter} as a whole number of increments, e.g. {letter}{} for 1.5 mm", (1.5 / mm_per_unit).round()),
            ));
        }
        Ok(Some(w.value * mm_per_unit))
    }

    /// Length words (X Z U W R I K) beyond what a lathe can mean are alarms at the word,
    /// so absurd values never become geometry (a 10 m radius or travel; `unit` is 25.4
    /// under G20).
    pub(crate) fn check_domain(&self, unit: f64) -> Result<(), Diagnostic> {
        const MAX_LENGTH_MM: f64 = 10_000.0;
        for w in &self.block.words {
            if matches!(w.letter, 'X' | 'Z' | 'U' | 'W' | 'R' | 'I' | 'K')
                && (w.value * unit).abs() > MAX_LENGTH_MM
            {
                return Err(Diagnostic::new(
                    w.span,
                    "LS-RANGE",
                    format!(
                        "{}{} is {} mm: beyond what a lathe can travel or cut",
                        w.letter,
                        w.value,
                        w.value * unit
                    ),
                    format!("lengths are limited to ±{MAX_LENGTH_MM} mm (10 m); check the number"),
                ));
            }
        }
        Ok(())
    }

    /// The first word nothing has used, as an alarm.
    pub(crate) fn check_all_used(&self) -> Result<(), Diagnostic> {
        match self.used.iter().position(|u| !u) {
            None => Ok(()),
            Some(i) => {
                let w = &self.block.words[i];
                Err(Diagnostic::new(
                    w.span,
                    "LS-WORD-UNUSED",
                    format!(
                        "address {} has no meaning in this block",
                        gcode::address(w.letter)
                    ),
                    unused_help(w.letter),
                ))
            }
        }
    }

    /// The block's span.
    pub(crate) fn span(&self) -> Span {
        self.block.span
    }
}

/// Whether a word is a whole number (written without a decimal point) within `lo ..= hi`.
pub(crate) fn whole_in(w: &Word, lo: f64, hi: f64) -> bool {
    !w.has_point && (lo..=hi).contains(&w.value)
}

/// What to change about an unused word.
fn unused_help(letter: char) -> &'static str {
    match letter {
        'c' | 'r' => {
            "a chamfer ,C or round ,R stands on a G01 line that moves, and the next move is a G01"
        }
        'a' => "a line's angle ,A stands on a G01 line with one end coordinate",
        _ => "remove the word, or use the code that takes it (e.g. R with G02/G03)",
    }
}
