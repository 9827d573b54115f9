//! Program flow: running an O program block by block, subprogram calls (M98; Haas M97
//! local calls), returns (M99) and the program end (M02/M30). GOTO, WHILE and macro calls
//! belong here too.
//!
//! The control decides what the words mean (spec/dialects.md §3.6, §5.8):
//! - `M98 P…`: FANUC/GSK pack the repeat count and the number (`P30010` = 3 × O0010,
//!   `L` overrides the count); Haas P is the program number (5 digits), `L` the repeats.
//! - A called program is looked for in the file, then in the `--lib` folders
//!   ([`crate::Library`]); nowhere is alarm PS078 at the call.
//! - `M98 (path/O00001.nc)` (Haas): call the first program of the file the comment names,
//!   relative to the main program's folder ([`crate::Library::file`]); `L` repeats.
//! - `M97 P n [L k]` (Haas): call the blocks from `N n` of the same program until M99.
//! - `M99 P n`: FANUC returns to `N n` of the caller; Haas branches to `N n` of the program
//!   it is in and does not return. M99 in a Haas main program loops to its start: run once,
//!   then stop with a warning.
//!
//! Macro B statements and G65 run through `macros.rs` (`Interp::step`).

use super::ahead::Ahead;
use super::loop_guard::LoopGuard;
use super::{alarm, Interp};
use crate::words::{whole_in, Words};
use crate::{Control, Diagnostic, Span};
use gcode::{Blocks, CallText, Program, Word};
use std::sync::Arc;

/// FANUC's subprogram nesting limit.
const MAX_NESTING: u32 = 4;
/// Haas nests subprogram calls up to 9 levels (S15; **Interpretation** for M97/M98).
const MAX_NESTING_HAAS: u32 = 9;
/// `LinuxCNC` nests subroutine calls up to 10 levels ([O] "Subroutines").
const MAX_NESTING_LINUXCNC: u32 = 10;

/// What a call runs.
pub(super) enum Callee {
    /// An O program by number (M98, G65).
    Program(u32),
    /// An O program by number, called by the `G66` modal call after a move: its blocks do
    /// not trigger the modal call again.
    Modal(u32),
    /// The first program of a file, by its path (Haas `M98 (path)`).
    File(String),
    /// The blocks from this N number of the calling program (Haas M97).
    Local(u32),
    /// The blocks from this index of the calling program (`LinuxCNC`'s `o… call`).
    At(usize),
    /// `LinuxCNC`'s subroutine of another file: `o<name> call` runs the `o<name> sub` of
    /// `name.ngc` in the main program's folder (`o123 call`: `123.ngc`).
    SubFile(macro_b::OLabel),
}

/// How an O program was left.
pub(super) enum Exit {
    End,
    /// M99, to the block after the call or (FANUC `M99 P`) to the caller's block `N seq`:
    /// `(seq, the M99 block)`.
    Return(Option<(u32, Span)>),
}

/// How a call ended, for the calling program.
enum Called {
    /// Go on after the call.
    Done,
    /// The program ended (M30 in the called program).
    End,
    /// `M99 P`: go on at this block of the caller; the M99 block.
    ReturnTo(usize, Span),
}

/// Where execution goes after a block.
pub(super) enum Flow {
    Next,
    End,
    Call {
        callee: Callee,
        times: u32,
        span: Span,
        /// A G65 call's new local level.
        locals: Option<Box<macro_b::Locals>>,
    },
    Return {
        seq: Option<u32>,
        span: Span,
    },
    /// Continue at this block index (G70–G73 skip their finishing shape).
    Jump(usize),
    /// Continue at the block numbered `seq` of this program (Haas `M99 P`).
    Branch {
        seq: u32,
        span: Span,
    },
    /// A `LinuxCNC` G70/G71/G72 block (as `LinuxCNC` means it): it runs its profile O-sub.
    G7x(Box<gcode::Block>),
}

/// Where a call goes: program index and first block in this file, or a library program.
enum Target {
    Here(usize, usize),
    Library(Arc<Program>, usize),
    /// A library program from this block.
    LibraryAt(Arc<Program>, usize, usize),
}

/// The index of the one block numbered `seq` (an alarm at `span` when absent or written
/// twice: a jump to a duplicated N is ambiguous, spec/dialects.md §1).
fn seq_index(blocks: &Blocks, seq: u32, span: Span, what: &str) -> Result<usize, Diagnostic> {
    let mut hits = blocks.positions_seq(seq);
    let Some(i) = hits.next() else {
        return Err(alarm(
            span,
            "PS078",
            format!("{what} N{seq}, which this program does not have"),
            format!("give the block to go to the sequence number N{seq}"),
        ));
    };
    if let Some(second) = hits.next() {
        return Err(alarm(
            span,
            "LS-N-TWICE",
            format!(
                "{what} N{seq}, which is written twice (lines {} and {})",
                blocks.at(i).span.line,
                blocks.at(second).span.line
            ),
            "give each block that is a jump target a sequence number of its own",
        ));
    }
    Ok(i)
}

impl Interp<'_> {
    /// Run one O program from block `start`; `depth` 0 is the main program.
    pub(super) fn run(
        &mut self,
        program: &Program,
        index: usize,
        start: usize,
        depth: u32,
    ) -> Result<Exit, Diagnostic> {
        let blocks = &program.programs[index].blocks;
        std::thread::scope(|s| {
            let mut ahead = Ahead::start(s, blocks, start);
            self.run_from(program, index, start, depth, &mut ahead)
        })
    }

    /// [`Interp::run`], with the blocks read `ahead` where there are. Every jump back
    /// (GOTO, END, M99 P, a return to N of this program) goes past the loop guard.
    fn run_from(
        &mut self,
        program: &Program,
        index: usize,
        start: usize,
        depth: u32,
        ahead: &mut Option<Ahead>,
    ) -> Result<Exit, Diagnostic> {
        let blocks = &program.programs[index].blocks;
        // the callers wait while this program runs: the guard's states are this level's
        let mut guard = LoopGuard::default();
        let mut i = start;
        while i < blocks.len() {
            if self.opts.block_delete && blocks.block_delete(i) {
                i += 1;
                continue;
            }
            self.out.blocks += 1;
            if self.out.blocks > self.opts.max_blocks {
                return Err(self.budget_alarm(blocks.at(i).span, program));
            }
            if ahead.as_mut().is_some_and(|a| a.get(i).is_none()) {
                // gone back before the blocks read ahead: read where they run from now on
                *ahead = None;
            }
            let read = ahead.as_mut().and_then(|a| a.get(i));
            let from = i;
            let mut jump = None;
            i = match self.step(program, index, i, read)? {
                Flow::Next => i + 1,
                Flow::Jump(j) => j,
                Flow::End => return Ok(Exit::End),
                Flow::Return { seq, span } => return self.leave(depth, seq, span),
                Flow::Call {
                    callee,
                    times,
                    span,
                    locals,
                } => {
                    let call = (callee, times, span, locals);
                    match self.call(program, index, depth, call)? {
                        Called::Done => i + 1,
                        Called::End => return Ok(Exit::End),
                        Called::ReturnTo(target, at) => {
                            jump = Some(at);
                            target
                        }
                    }
                }
                Flow::Branch { seq, span } => {
                    jump = Some(span);
                    seq_index(blocks, seq, span, "branches to")?
                }
                Flow::G7x(b) => {
                    self.linuxcnc_g7x(program, index, depth, &b)?;
                    i + 1
                }
            };
            if i <= from {
                self.came_back(&mut guard, blocks, (from, i), jump)?;
            }
        }
        let span = blocks.last().map(|b| b.span).unwrap_or_default();
        if depth == 0 {
            self.warn(
                span,
                "LS-NO-END",
                "the program ends without M30 or M02",
                "end the main program with M30",
            );
            Ok(Exit::End)
        } else {
            self.warn(
                span,
                "LS-NO-M99",
                "the subprogram ends without M99; returning",
                "end the subprogram with M99",
            );
            Ok(Exit::Return(None))
        }
    }

    /// M99 at `span`: the return to the caller (to its block `N seq`, if given). In the main
    /// program M99 loops to its start, as a bar-fed job ends its part (dialects.md §3.6,
    /// §5.8: FANUC and Haas alike; "Bounded execution": ended by the loop rule of §3.6): the
    /// program is simulated once, with a warning.
    fn leave(&mut self, depth: u32, seq: Option<u32>, span: Span) -> Result<Exit, Diagnostic> {
        if depth == 0 {
            self.warn(
                span,
                "LS-M99-MAIN",
                "M99 in the main program loops to its start (a bar feeder's next part): simulated once",
                "end the main program with M30 to run it once",
            );
            return Ok(Exit::End);
        }
        Ok(Exit::Return(seq.map(|seq| (seq, span))))
    }

    /// Run a call of block `Flow::Call` (callee, repeats, the calling block, G65 locals)
    /// from O program `index` at `depth`: its repeats, one after the other.
    fn call(
        &mut self,
        program: &Program,
        index: usize,
        depth: u32,
        (callee, times, span, locals): (Callee, u32, Span, Option<Box<macro_b::Locals>>),
    ) -> Result<Called, Diagnostic> {
        let limit = match self.machine.control {
            Control::Haas => MAX_NESTING_HAAS,
            Control::LinuxCnc => MAX_NESTING_LINUXCNC,
            _ => MAX_NESTING,
        };
        if depth + 1 > limit {
            return Err(alarm(
                span,
                "PS077",
                format!("subprogram calls nested deeper than {limit} levels (a subprogram calling itself?)"),
                "remove the recursive call or flatten the nesting",
            ));
        }
        let target = match &callee {
            Callee::SubFile(label) => self.sub_file(label, span)?,
            _ => self.callee(program, index, &callee, span)?,
        };
        let (called, sub, from) = match &target {
            Target::Here(sub, from) => (program, *sub, *from),
            Target::Library(p, sub) => (&**p, *sub, 0),
            Target::LibraryAt(p, sub, from) => (&**p, *sub, *from),
        };
        let level = self.enter_call(locals, matches!(callee, Callee::Modal(_)));
        for _ in 0..times {
            match self.run(called, sub, from, depth + 1)? {
                Exit::End => return Ok(Called::End),
                Exit::Return(None) => {}
                Exit::Return(Some((seq, at))) => {
                    let blocks = &program.programs[index].blocks;
                    let target = seq_index(blocks, seq, span, "returns to")?;
                    self.leave_call(level);
                    return Ok(Called::ReturnTo(target, at));
                }
            }
        }
        self.leave_call(level);
        Ok(Called::Done)
    }

    /// The program or block a call runs: in this file, else in the `--lib` folders.
    fn callee(
        &self,
        program: &Program,
        index: usize,
        callee: &Callee,
        span: Span,
    ) -> Result<Target, Diagnostic> {
        let number = match *callee {
            Callee::Local(seq) => {
                let blocks = &program.programs[index].blocks;
                let from = seq_index(blocks, seq, span, "M97 calls")?;
                return Ok(Target::Here(index, from));
            }
            Callee::File(ref path) => return self.file(path, span),
            Callee::At(from) => return Ok(Target::Here(index, from)),
            Callee::SubFile(_) => unreachable!("a file's subroutine is found by sub_file"),
            Callee::Program(n) | Callee::Modal(n) => n,
        };
        if let Some(sub) = program
            .programs
            .iter()
            .position(|p| p.number == Some(number))
        {
            return Ok(Target::Here(sub, 0));
        }
        let help = "add the subprogram after M30 in the same file, or give the folder that holds it with --lib DIR";
        let Some(lib) = self.opts.library.as_ref().filter(|l| l.0.has_folders()) else {
            return Err(alarm(
                span,
                "PS078",
                format!("subprogram O{number:04} not found in this file"),
                help,
            ));
        };
        match lib.0.find(number) {
            Ok(Some(p)) => match p.programs.iter().position(|s| s.number == Some(number)) {
                Some(sub) => Ok(Target::Library(p, sub)),
                None => Err(alarm(
                    span,
                    "PS078",
                    format!("the library file for O{number:04} does not hold that program"),
                    help,
                )),
            },
            Ok(None) => Err(alarm(
                span,
                "PS078",
                format!("subprogram O{number:04} not found in this file nor in the --lib folders"),
                help,
            )),
            Err(why) => Err(alarm(
                span,
                "PS078",
                format!("subprogram O{number:04}: {why}"),
                "fix the library file",
            )),
        }
    }

    /// The `LinuxCNC` subroutine `label` of the file named after it (`o<name>`: `name.ngc`,
    /// `o123`: `123.ngc`) in the main program's folder: from the block after its `sub`.
    fn sub_file(&mut self, label: &macro_b::OLabel, span: Span) -> Result<Target, Diagnostic> {
        let name = match label {
            macro_b::OLabel::Name(n) => format!("{n}.ngc"),
            macro_b::OLabel::Number(n) => format!("{n}.ngc"),
        };
        let help = format!("define {label} sub … {label} endsub in this file, or put {name} (holding it) beside the program");
        let program = match &self.opts.library {
            Some(lib) => lib.0.file(&name),
            None => Err("no folder of the main program to look in".to_string()),
        }
        .map_err(|why| {
            alarm(
                span,
                "PS078",
                format!("{label} call: the subroutine is not defined in this file, and {why}"),
                help.clone(),
            )
        })?;
        match self.o_sub_in_file(&program, label)? {
            Some(line) => Ok(Target::LibraryAt(program, 0, line + 1)),
            None => Err(alarm(
                span,
                "PS078",
                format!("{label} call: {name} does not define {label} sub"),
                help,
            )),
        }
    }

    /// The file a Haas `M98 (path)` calls: its first program, from its first block.
    fn file(&self, path: &str, span: Span) -> Result<Target, Diagnostic> {
        let help = "give the path of a program file in the main program's folder, e.g. M98 (subs/O00101.nc)";
        let program = match &self.opts.library {
            Some(lib) => lib.0.file(path),
            None => Err("no folder of the main program to look in".to_string()),
        }
        .map_err(|why| alarm(span, "PS078", format!("M98 ({path}): {why}"), help))?;
        if program.programs.is_empty() {
            return Err(alarm(
                span,
                "PS078",
                format!("M98 ({path}): the file holds no program"),
                help,
            ));
        }
        Ok(Target::Library(program, 0))
    }

    /// The M codes that act after the motion: M05, M09, the program end, M97, M98 and M99.
    /// `path`: the comment after the block's M98 (Haas `M98 (path)`).
    pub(super) fn m_codes_after(
        &mut self,
        after: &[(u32, &Word)],
        used: &mut Words,
        path: Option<&CallText>,
        mut flow: Flow,
    ) -> Result<Flow, Diagnostic> {
        for &(m, w) in after {
            match m {
                5 => self.spindle_on = false,
                9 => {}
                2 | 30 => flow = Flow::End,
                97 => flow = m97(w, used)?,
                98 => flow = m98(w, used, self.machine.control == Control::Haas, path)?,
                99 => flow = m99(w, used, self.machine.control == Control::Haas)?,
                _ => {}
            }
        }
        Ok(flow)
    }
}

/// M98 P[count]number [L count] (FANUC/GSK), M98 P number [L count] or M98 (path) [L count]
/// (Haas): the call.
fn m98(
    w: &Word,
    used: &mut Words,
    haas: bool,
    path: Option<&CallText>,
) -> Result<Flow, Diagnostic> {
    if let Some(path) = path.filter(|_| haas && !used.has('P')) {
        return Ok(Flow::Call {
            callee: Callee::File(path.text.clone()),
            times: repeats(used)?.unwrap_or(1),
            span: w.span,
            locals: None,
        });
    }
    let p = used.take('P').ok_or_else(|| {
        alarm(
            w.span,
            "PS078",
            "M98 without P",
            "write M98 P<program number>, e.g. M98 P1234",
        )
    })?;
    let max = if haas { 99_999.0 } else { 99_999_999.0 };
    if !whole_in(p, 1.0, max) {
        return Err(alarm(
            p.span,
            "PS078",
            "M98 P needs a program number",
            if haas {
                "Haas: P is the program number (1 … 99999), L the repeat count, e.g. M98 P1001 L3"
            } else {
                "P is [repeat count (4 digits)] + program number (4 digits), e.g. P30010"
            },
        ));
    }
    let v = p.value as u32;
    let (mut times, number) = if v > 9999 && !haas {
        (v / 10000, v % 10000)
    } else {
        (1, v)
    };
    if let Some(l) = repeats(used)? {
        times = l;
    }
    Ok(Flow::Call {
        callee: Callee::Program(number),
        times: times.max(1),
        span: w.span,
        locals: None,
    })
}

/// L: a repeat count 1 … 9999.
fn repeats(used: &mut Words) -> Result<Option<u32>, Diagnostic> {
    let Some(l) = used.take('L') else {
        return Ok(None);
    };
    if !whole_in(l, 1.0, 9999.0) {
        return Err(alarm(
            l.span,
            "LS-VALUE",
            "L must be a repeat count 1 … 9999",
            "write e.g. L3",
        ));
    }
    Ok(Some(l.value as u32))
}

/// Haas M97 P(N number) [L count]: call the blocks from N<P> of this program until M99.
fn m97(w: &Word, used: &mut Words) -> Result<Flow, Diagnostic> {
    let p = used.take('P').ok_or_else(|| {
        alarm(
            w.span,
            "PS078",
            "M97 without P",
            "write M97 P<sequence number>, e.g. M97 P100 to call N100",
        )
    })?;
    if !whole_in(p, 1.0, 99_999_999.0) {
        return Err(alarm(
            p.span,
            "PS078",
            "M97 P needs a sequence number",
            "write e.g. M97 P100 to call the local subprogram at N100",
        ));
    }
    let times = repeats(used)?.unwrap_or(1);
    Ok(Flow::Call {
        callee: Callee::Local(p.value as u32),
        times,
        span: w.span,
        locals: None,
    })
}

/// M99 [P sequence]: the return, to the block after the call or (FANUC) to N<P> of the
/// caller; Haas M99 P branches to N<P> of this program.
fn m99(w: &Word, used: &mut Words, haas: bool) -> Result<Flow, Diagnostic> {
    let seq = match used.take('P') {
        Some(p) if p.has_point || p.value < 0.0 => {
            return Err(alarm(
                p.span,
                "LS-VALUE",
                "M99 P needs a sequence number",
                "write e.g. M99 P20 to return to N20",
            ));
        }
        Some(p) => Some(p.value as u32),
        None => None,
    };
    Ok(match seq {
        Some(seq) if haas => Flow::Branch { seq, span: w.span },
        seq => Flow::Return { seq, span: w.span },
    })
}
