//! A loop that cannot end is an alarm at once (issue 37). The program is deterministic: a
//! jump back (GOTO, END, Haas `M99 P`, FANUC `M99 P` to this program, a cycle going back)
//! that reaches a block in a state the run already had at that block will go round the
//! same states for ever. That is an alarm at the jump, naming what could have ended it.
//!
//! **The state** is everything the rest of the run depends on: the macro variables (the
//! locals of every call level and the common variables, vacant apart from 0, bit for bit),
//! the modal call (`G66`), and the interpreter's machine state (position, work frames and
//! offsets, modal codes, feed, speed, spindle, tool and offset, noses, the compensation
//! buffer, a waiting `,C`/`,R` corner, the cycles' retained words, the parts counters …).
//! The callers' state (who called this program, with how many repeats left) cannot change
//! while this program runs: each program level keeps its own guard, made when it starts
//! and dropped when it returns, and each repeat of `M98 … L` starts afresh. Left out on
//! purpose: the budgets' counters (blocks, moves), the toolpath made so far (but for
//! whether it is empty, which a G50 reads), and the "warned already" flags: they change
//! the warnings, never the flow or the moves.
//!
//! **The cost**: per jump target, Brent's cycle detection on the sequence of states found
//! there. A target keeps one saved state, taken after 1, 2, 4 … 1024 visits and then every
//! 1024; each visit compares the present state with it, in O(1) while the variables differ
//! (their fingerprint is kept up to date as they are written), so a counting loop runs on
//! at one comparison a time round. Brent rather than "the last visit": it also catches a
//! state that comes back every 2, 3 … 1024 times round (a variable toggling between two
//! values), and saves a state log₂ n times in the first n visits instead of at every
//! visit. Capping the period at 1024 means a loop stuck after a long honest run is caught
//! within 1024 more times round; a cycle longer than that is left to the block budget.
//! At most 256 targets a level are remembered (the least recently visited forgotten
//! first), so memory is bounded on any program.
//!
//! **No false alarm**: states are compared exactly, never by fingerprint alone (the
//! variables bit for bit, the machine state by value); only -0.0 and 0.0 in a machine
//! length compare equal, and no G code tells them apart.

use super::frame::Frames;
use super::modal_call::Calls;
use super::{alarm, Interp, MotionMode};
use crate::cycles::Retained;
use crate::tnrc::{Nose, Side};
use crate::{Diagnostic, DrillReturn, Pt, Segment, Span};
use gcode::Blocks;
use macro_b::{Expr, OKeyword, StmtKind};
use std::collections::BTreeMap;

/// Jump targets remembered per program level.
const MAX_TARGETS: usize = 256;
/// The longest cycle caught, in times round: Brent's power stops doubling here.
const MAX_POWER: u32 = 1024;

/// Declares [`MachineState`] with the [`Interp`] fields it copies and compares, each named
/// once so the copy and the comparison cannot disagree.
macro_rules! machine_state {
    ($($field:ident: $ty:ty),* $(,)?) => {
        /// The interpreter's state that the rest of a run depends on.
        struct MachineState {
            $($field: $ty,)*
            corner: Option<(Segment, crate::corner::Ask)>,
            /// No move made yet: a G50 then states where the tool is instead of shifting.
            before_first_move: bool,
        }

        impl MachineState {
            fn of(it: &Interp<'_>) -> Self {
                Self {
                    $($field: it.$field.clone(),)*
                    corner: it.corner.map(|c| (c.line, c.ask)),
                    before_first_move: it.out.segments.is_empty(),
                }
            }

            /// Whether `it` is in this state (compared in place, nothing copied).
            fn is(&self, it: &Interp<'_>) -> bool {
                $(self.$field == it.$field &&)*
                    self.corner == it.corner.map(|c| (c.line, c.ask))
                    && self.before_first_move == it.out.segments.is_empty()
            }
        }
    };
}

machine_state! {
    pos: Pt,
    shift: Pt,
    motion: MotionMode,
    per_rev: bool,
    inch: bool,
    css: bool,
    s_value: f64,
    s_clamp: f64,
    spindle_on: bool,
    feed: f64,
    tool: u32,
    retained: Retained,
    comp: Option<Side>,
    offset: u32,
    section: Option<(Side, Nose, Vec<Segment>)>,
    noses: BTreeMap<u32, Result<Nose, &'static str>>,
    incremental: bool,
    plane: Option<(i32, Span)>,
    param_mode: bool,
    chuck_open: bool,
    tailstock_pending: Option<bool>,
    frames: Frames,
    thread_chamfer: bool,
    thread_phase: f64,
    parts: [f64; 2],
    drill_return: DrillReturn,
}

/// The whole state of a run at a block (this program level's).
struct State {
    machine: MachineState,
    variables: Option<macro_b::Snapshot>,
    calls: Option<Calls>,
}

impl State {
    fn of(it: &Interp<'_>) -> Self {
        Self {
            machine: MachineState::of(it),
            variables: it.variables().map(macro_b::Variables::snapshot),
            calls: it.calls(),
        }
    }

    /// Whether `it` is in this state: the cheap tests first (the variables' fingerprint,
    /// then the machine state), the variables value by value last.
    fn is(&self, it: &Interp<'_>) -> bool {
        let vars = it.variables();
        let fingerprints = match (&self.variables, vars) {
            (Some(then), Some(now)) => then.fingerprint() == now.fingerprint(),
            (None, None) => true,
            _ => false,
        };
        fingerprints
            && self.machine.is(it)
            && it.calls_are(self.calls.as_ref())
            && match (&self.variables, vars) {
                (Some(then), Some(now)) => now.same_as(then),
                _ => true,
            }
    }
}

/// What one target remembers: Brent's saved state and counters.
struct Record {
    saved: State,
    /// Visits between two saves (1, 2, 4 … [`MAX_POWER`]).
    power: u32,
    /// Visits since the save.
    since: u32,
    /// The guard's clock at the last visit (which record to forget).
    last: u64,
}

/// The loop guard of one program level: per jump target, the state saved there.
#[derive(Default)]
pub(super) struct LoopGuard {
    records: BTreeMap<usize, Record>,
    clock: u64,
}

impl LoopGuard {
    /// A visit of block `target` with `it` in its present state: `Some(n)` when the run
    /// had this very state here `n` visits ago.
    fn visit(&mut self, target: usize, it: &Interp<'_>) -> Option<u32> {
        self.clock += 1;
        let clock = self.clock;
        if let Some(r) = self.records.get_mut(&target) {
            r.last = clock;
            r.since += 1;
            if r.saved.is(it) {
                return Some(r.since);
            }
            if r.since == r.power {
                r.saved = State::of(it);
                r.power = (r.power * 2).min(MAX_POWER);
                r.since = 0;
            }
            return None;
        }
        if self.records.len() >= MAX_TARGETS {
            let oldest = self
                .records
                .iter()
                .min_by_key(|(_, r)| r.last)
                .map(|(&k, _)| k);
            oldest.and_then(|k| self.records.remove(&k));
        }
        let saved = State::of(it);
        self.records.insert(
            target,
            Record {
                saved,
                power: 1,
                since: 0,
                last: clock,
            },
        );
        None
    }
}

impl Interp<'_> {
    /// The run jumped from block `from` back to block `target` of `blocks` (the jump
    /// written at `jump`, else block `from` itself): an alarm when it was here in this
    /// state before.
    pub(super) fn came_back(
        &mut self,
        guard: &mut LoopGuard,
        blocks: &Blocks,
        (from, target): (usize, usize),
        jump: Option<Span>,
    ) -> Result<(), Diagnostic> {
        match guard.visit(target, self) {
            None => Ok(()),
            Some(period) => {
                // (a block may be read again from the text: only for the alarm)
                let jump = jump.unwrap_or_else(|| blocks.at(from).span);
                Err(self.endless(blocks, (from, target), jump, period))
            }
        }
    }

    /// The alarm of an endless loop that repeats its state every `period` times round:
    /// it names the variables of the conditions that could have ended it, with their
    /// values.
    fn endless(
        &mut self,
        blocks: &Blocks,
        (from, target): (usize, usize),
        jump: Span,
        period: u32,
    ) -> Diagnostic {
        let conditions = exit_conditions(blocks, from, target);
        let mut numbers: Vec<u32> = vec![];
        for n in conditions.iter().flat_map(Expr::variables) {
            // (#0 is vacant by definition: nothing to change)
            if n != 0 && !numbers.contains(&n) {
                numbers.push(n);
            }
        }
        let mut named: Vec<String> = numbers
            .iter()
            .map(|&n| match self.value_for_message(n, jump) {
                Some(v) if v.is_vacant() => format!("#{n} (vacant)"),
                Some(v) => format!("#{n} (= {v})"),
                None => format!("#{n}"),
            })
            .collect();
        // LinuxCNC's named parameters
        for name in conditions.iter().flat_map(Expr::named) {
            let value = self.variables().and_then(|v| v.named(&name));
            let shown = match value {
                Some(v) if !v.is_vacant() => format!("#<{name}> (= {v})"),
                _ => format!("#<{name}>"),
            };
            if !named.contains(&shown) {
                named.push(shown);
            }
        }
        let head = blocks.at(target).span.line;
        let (what, why) = explain(period, &conditions, &named);
        let o_word = matches!(
            blocks.at(from).stmt.as_deref().map(|s| &s.kind),
            Some(StmtKind::OWord { .. })
        );
        let help = if o_word {
            "make the loop change what its condition tests (step a counter, move the tool), or leave it with o… break; a control would run it until the operator stops it"
        } else if conditions.is_empty() {
            "give the loop a way out (IF [ … ] GOTO past it, or a WHILE condition), or remove the jump back; a control would run it until the operator stops it"
        } else {
            "make the loop change what its condition tests (step a counter, move the tool), or leave it with a GOTO; a control would run it until the operator stops it"
        };
        alarm(
            jump,
            "LS-LOOP",
            format!(
                "endless loop: this loop (back to line {head}) {what} (variables, position, modes): {why}"
            ),
            help,
        )
    }
}

/// What the loop repeats and why it cannot end, for the alarm's message.
fn explain(period: u32, conditions: &[Expr], named: &[String]) -> (String, String) {
    let what = if period == 1 {
        "repeats the same state every time round".to_string()
    } else {
        format!("comes back to the same state every {period} times round")
    };
    let why = match (conditions.first(), named) {
        (None, _) => "nothing in it can end it".to_string(),
        (Some(c), []) => format!("its condition {c} holds no variable"),
        (_, [one]) if period == 1 => format!("{one} never changes"),
        (_, many) if period == 1 => format!("{} never change", join(many)),
        (_, [one]) => format!("{one} comes back to the same value"),
        (_, many) => format!("{} come back to the same values", join(many)),
    };
    (what, why)
}

/// `a`, `a and b`, `a, b and c`.
fn join(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// The conditions that could end the loop of the jump from block `from` back to
/// `target`: an `IF … GOTO`'s own, an `END`'s `WHILE`; otherwise every condition
/// written in the loop's blocks.
fn exit_conditions(blocks: &Blocks, from: usize, target: usize) -> Vec<Expr> {
    let stmt = |i: usize| blocks.at(i).stmt.as_deref().cloned();
    let own = stmt(from).and_then(|s| match &s.kind {
        StmtKind::IfGoto { cond, .. } => Some(cond.clone()),
        StmtKind::End { .. }
        | StmtKind::OWord {
            keyword: OKeyword::EndWhile,
            ..
        } => stmt(target).and_then(|w| w.condition().cloned()),
        // the `while` that closes a LinuxCNC `do`
        StmtKind::OWord {
            keyword: OKeyword::While,
            ..
        } => s.condition().cloned(),
        _ => None,
    });
    match own {
        Some(cond) => vec![cond],
        None => (target..=from)
            .filter_map(|i| stmt(i).and_then(|s| s.condition().cloned()))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_read_as_english() {
        let v = |s: &[&str]| s.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(join(&v(&["#1"])), "#1");
        assert_eq!(join(&v(&["#1", "#2"])), "#1 and #2");
        assert_eq!(join(&v(&["#1", "#2", "#3"])), "#1, #2 and #3");
    }
}
