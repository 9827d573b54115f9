//! Control flow over the blocks of the programs in a file: `GOTO`, `IF`, `WHILE`/`DO`/`END`,
//! block-form `IF`, calls (`G65`, `M98`, `M97`) and returns (`M99`), with the loop and call
//! limits and the executed-block budget (spec/dialects.md §5.5, §5.6, §5.8).
//!
//! The engine runs macro statements itself and hands every NC block to the interpreter
//! ([`Flow::next`]); the interpreter tells it about calls and returns it reads in those
//! blocks ([`Flow::call_macro`], [`Flow::call_sub`], [`Flow::call_local`], [`Flow::ret`]).

use crate::span::Span;

use crate::arguments::ARGUMENTS;
use crate::error::{ErrorKind, MacroError, Result};
use crate::eval::MacroState;
use crate::expr::{Expr, Stmt, StmtKind};
use crate::options::Limits;
use crate::value::Value;
use crate::vars::{Locals, System};

/// What a line of a program holds.
#[derive(Debug, Clone, PartialEq)]
pub enum Body<B> {
    /// A macro statement, run by the engine.
    Stmt(Stmt),
    /// An NC block, handed to the interpreter as it is.
    Block(B),
}

/// One block of a program: its sequence number, its place, and what it holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Line<B> {
    /// The N number, if written.
    pub seq: Option<u32>,
    /// The whole block's span.
    pub span: Span,
    /// The statement or NC block.
    pub body: Body<B>,
}

/// A note about something accepted with a warning (block-form `IF`).
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// Where.
    pub span: Span,
    /// What.
    pub message: String,
}

/// One O program prepared for running: loops and block-form `IF`s matched, sequence
/// numbers indexed. Structural mistakes (`END` without `DO`, loops nested too deep or
/// crossing, `DO` without `END`) are found here, before anything runs.
#[derive(Debug, Clone)]
pub struct MacroProgram<B> {
    number: Option<u32>,
    lines: Vec<Line<B>>,
    /// WHILE/DO → its END; END → its WHILE/DO; IF-block → its ELSE or ENDIF; ELSE → ENDIF.
    partner: Vec<usize>,
    /// (DO line, END line) of every loop.
    loops: Vec<(usize, usize)>,
    /// (N number, line), sorted: found by binary search on every jump.
    seqs: Vec<(u32, usize)>,
    warnings: Vec<Warning>,
    /// `LinuxCNC`'s o-words matched.
    o_words: crate::o_words::OStructure,
}

fn stmt_of<B>(line: &Line<B>) -> Option<&StmtKind> {
    match &line.body {
        Body::Stmt(s) => Some(&s.kind),
        Body::Block(_) => None,
    }
}

fn program_name(number: Option<u32>) -> String {
    number.map_or_else(|| "the main program".to_string(), |n| format!("O{n:04}"))
}

/// The pairing of a program's DO/END and IF/ELSE/ENDIF lines, made line by line: each
/// line's partner, the loops, and the blocks still open.
#[derive(Default)]
struct Pairing {
    partner: Vec<usize>,
    loops: Vec<(usize, usize)>,
    warnings: Vec<Warning>,
    /// Loops opened and not yet ended: (DO number, line).
    open: Vec<(u8, usize)>,
    /// Block-form IFs not yet ended: (IF line, its ELSE line).
    ifs: Vec<(usize, Option<usize>)>,
}

impl Pairing {
    /// Line `i` of `lines`: a DO, END, IF-THEN block, ELSE or ENDIF pairs; others pass.
    fn line<B>(&mut self, i: usize, lines: &[Line<B>], limits: &Limits) -> Result<()> {
        let line = &lines[i];
        match stmt_of(line) {
            Some(StmtKind::While { id, .. } | StmtKind::Do { id }) => {
                self.open_loop(*id, i, lines, limits)
            }
            Some(StmtKind::End { id }) => self.end_loop(*id, i, lines),
            Some(StmtKind::IfBlock { .. }) => {
                self.ifs.push((i, None));
                self.warnings.push(Warning {
                    span: line.span,
                    message: "block-form IF is not on older controls".into(),
                });
                Ok(())
            }
            Some(StmtKind::Else) => match self.ifs.last_mut() {
                Some((_, e @ None)) => {
                    *e = Some(i);
                    Ok(())
                }
                _ => Err(MacroError::new(
                    ErrorKind::IfStructure,
                    line.span,
                    "ELSE without IF [cond] THEN",
                    "ELSE belongs between a block-form IF [cond] THEN and its ENDIF",
                )),
            },
            Some(StmtKind::EndIf) => self.end_if(i, line.span),
            _ => Ok(()),
        }
    }

    fn open_loop<B>(&mut self, id: u8, i: usize, lines: &[Line<B>], limits: &Limits) -> Result<()> {
        let line = &lines[i];
        if self.open.len() >= limits.loop_depth {
            return Err(MacroError::new(
                ErrorKind::LoopNesting,
                line.span,
                format!("DO{id} nests loops {} deep", self.open.len() + 1),
                format!("loops may nest at most {} deep", limits.loop_depth),
            ));
        }
        if let Some(&(_, j)) = self.open.iter().find(|(m, _)| *m == id) {
            return Err(MacroError::new(
                ErrorKind::LoopNesting,
                line.span,
                format!(
                    "DO{id} inside the DO{id} opened at line {}",
                    lines[j].span.line
                ),
                "nested loops need different numbers (DO1, DO2, DO3); the same number may only be reused after its END",
            ));
        }
        self.open.push((id, i));
        Ok(())
    }

    fn end_loop<B>(&mut self, id: u8, i: usize, lines: &[Line<B>]) -> Result<()> {
        let line = &lines[i];
        match self.open.last() {
            Some(&(m, j)) if m == id => {
                self.open.pop();
                self.partner[i] = j;
                self.partner[j] = i;
                self.loops.push((j, i));
                Ok(())
            }
            Some(&(m, j)) if self.open.iter().any(|(k, _)| *k == id) => Err(MacroError::new(
                ErrorKind::LoopCrossing,
                line.span,
                format!(
                    "END{id} while DO{m} of line {} is still open: loops must not cross",
                    lines[j].span.line
                ),
                format!("close DO{m} with END{m} before END{id}"),
            )),
            _ => Err(MacroError::new(
                ErrorKind::EndWithoutDo,
                line.span,
                format!("END{id} without DO{id}"),
                format!("open the loop with WHILE [cond] DO{id} before END{id}, or remove END{id}"),
            )),
        }
    }

    fn end_if(&mut self, i: usize, span: Span) -> Result<()> {
        let Some((j, e)) = self.ifs.pop() else {
            return Err(MacroError::new(
                ErrorKind::IfStructure,
                span,
                "ENDIF without IF [cond] THEN",
                "open the block with IF [cond] THEN, or remove ENDIF",
            ));
        };
        self.partner[j] = e.unwrap_or(i);
        if let Some(e) = e {
            self.partner[e] = i;
        }
        self.partner[i] = j;
        Ok(())
    }

    /// Every loop and IF block ended by the program's end.
    fn all_closed<B>(&self, lines: &[Line<B>]) -> Result<()> {
        if let Some(&(id, j)) = self.open.last() {
            return Err(MacroError::new(
                ErrorKind::DoWithoutEnd,
                lines[j].span,
                format!("DO{id} without END{id}"),
                format!("close the loop with END{id}"),
            ));
        }
        if let Some(&(j, _)) = self.ifs.last() {
            return Err(MacroError::new(
                ErrorKind::IfStructure,
                lines[j].span,
                "IF [cond] THEN without ENDIF",
                "close the block with ENDIF",
            ));
        }
        Ok(())
    }
}

impl<B> MacroProgram<B> {
    /// Prepare a program. `number` is its O number (`None` for a main program without
    /// one); `limits.loop_depth` is the `DO` nesting limit.
    pub fn new(number: Option<u32>, lines: Vec<Line<B>>, limits: &Limits) -> Result<Self> {
        let mut pairing = Pairing {
            partner: vec![usize::MAX; lines.len()],
            ..Pairing::default()
        };
        let mut seqs: Vec<(u32, usize)> = Vec::new();
        for (i, line) in lines.iter().enumerate() {
            if let Some(n) = line.seq {
                seqs.push((n, i));
            }
            pairing.line(i, &lines, limits)?;
        }
        pairing.all_closed(&lines)?;
        seqs.sort_unstable();
        let o_words = crate::o_words::structure(&lines)?;
        Ok(Self {
            o_words,
            number,
            lines,
            partner: pairing.partner,
            loops: pairing.loops,
            seqs,
            warnings: pairing.warnings,
        })
    }

    /// The O number.
    pub fn number(&self) -> Option<u32> {
        self.number
    }

    /// The blocks.
    pub fn lines(&self) -> &[Line<B>] {
        &self.lines
    }

    /// The structure of its `LinuxCNC` o-words.
    pub fn o_words(&self) -> &crate::o_words::OStructure {
        &self.o_words
    }

    /// Things accepted with a warning.
    pub fn warnings(&self) -> &[Warning] {
        &self.warnings
    }

    /// The line a structured statement is paired with: `WHILE`/`DO` → its `END`, `END` →
    /// its `WHILE`/`DO`, block-form `IF` → its `ELSE` or `ENDIF`, `ELSE` → its `ENDIF`.
    pub fn partner(&self, line: usize) -> Option<usize> {
        self.partner.get(line).copied().filter(|&p| p != usize::MAX)
    }

    /// The line a jump (`GOTO n`, `M99 Pn`: `what`) from line `from` goes to: block `Nn`.
    /// A missing or duplicated number, or a target inside a loop `from` is not in, is an
    /// error at `span`.
    pub fn jump_target(&self, from: usize, n: u32, span: Span, what: &str) -> Result<usize> {
        let t = self.find_seq(n, span, what)?;
        if let Some(&(s, e)) = self
            .loops
            .iter()
            .find(|&&(s, e)| s < t && t <= e && !(s <= from && from <= e))
        {
            return Err(MacroError::new(
                ErrorKind::JumpIntoLoop,
                span,
                format!(
                    "{what} {n} jumps into the loop of lines {}–{} from outside it",
                    self.lines[s].span.line, self.lines[e].span.line
                ),
                "jump to the WHILE line or before it; jumping out of a loop or within it is allowed",
            ));
        }
        Ok(t)
    }

    /// The line of block `Nn`; a missing or duplicated number is an error at `span`.
    fn find_seq(&self, n: u32, span: Span, what: &str) -> Result<usize> {
        let from = self.seqs.partition_point(|&(m, _)| m < n);
        let to = from + self.seqs[from..].partition_point(|&(m, _)| m == n);
        match &self.seqs[from..to] {
            [] => Err(MacroError::new(
                ErrorKind::SequenceMissing,
                span,
                format!(
                    "{what} N{n}: no block N{n} in {}",
                    program_name(self.number)
                ),
                format!("number the target block N{n}, or correct the target"),
            )),
            [(_, i)] => Ok(*i),
            [(_, a), (_, b), ..] => Err(MacroError::new(
                ErrorKind::DuplicateSequence,
                span,
                format!(
                    "{what} N{n}: N{n} is written twice, at lines {} and {}",
                    self.lines[*a].span.line, self.lines[*b].span.line
                ),
                format!("give the target its own number; N{n} must be unique to jump to it"),
            )),
        }
    }
}

/// How a program level was entered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CallKind {
    /// The main program.
    Main,
    /// `G65`/`G66`: a new local level.
    Macro,
    /// `M98`/`M97`: the caller's locals.
    Sub,
}

#[derive(Debug, Clone)]
struct Frame {
    prog: usize,
    pc: usize,
    kind: CallKind,
    start: usize,
    repeats_left: u32,
    call_span: Span,
}

/// Where a handed-out block stands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct At {
    /// Index of the program in the slice given to [`Flow::new`].
    pub program: usize,
    /// Index of the line in that program.
    pub line: usize,
    /// The block's N number.
    pub seq: Option<u32>,
    /// The block's span.
    pub span: Span,
}

/// What [`Flow::next`] hands to the interpreter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step<'p, B> {
    /// An NC block to execute.
    Block {
        /// Where it stands.
        at: At,
        /// The block.
        block: &'p B,
    },
    /// Haas `IF [cond] THEN <NC block>` whose condition held: the block's text for the
    /// reader.
    ThenBlock {
        /// Where the statement stands.
        at: At,
        /// The NC block's text.
        text: &'p str,
        /// Where that text stands.
        span: Span,
    },
}

/// The control-flow engine of one run over the programs of a file.
#[derive(Debug)]
pub struct Flow<'p, B> {
    programs: &'p [MacroProgram<B>],
    frames: Vec<Frame>,
    limits: Limits,
    executed: u64,
    counts: Vec<Vec<u64>>,
    /// (program, line) of the loop head last jumped back to, for the budget alarm.
    last_loop: Option<(usize, usize)>,
    iterations: Vec<Vec<u64>>,
}

impl<'p, B> Flow<'p, B> {
    /// Start at the first line of `programs[main]`.
    pub fn new(programs: &'p [MacroProgram<B>], main: usize, limits: Limits) -> Self {
        Self {
            programs,
            frames: vec![Frame {
                prog: main,
                pc: 0,
                kind: CallKind::Main,
                start: 0,
                repeats_left: 0,
                call_span: Span::default(),
            }],
            limits,
            executed: 0,
            counts: programs.iter().map(|p| vec![0; p.lines.len()]).collect(),
            last_loop: None,
            iterations: programs.iter().map(|p| vec![0; p.lines.len()]).collect(),
        }
    }

    /// Blocks executed so far (macro statements and NC blocks).
    pub fn executed(&self) -> u64 {
        self.executed
    }

    /// How many times each line of `programs[program]` was executed.
    pub fn line_counts(&self, program: usize) -> &[u64] {
        &self.counts[program]
    }

    /// Iterations of the loops of `programs[program]`, per line: how many times control
    /// jumped back to the line's `WHILE`/`DO` (from its `END`), or back from the line's
    /// `GOTO` or `M99`. 0 for lines that head no loop.
    pub fn loop_iterations(&self, program: usize) -> &[u64] {
        &self.iterations[program]
    }

    /// Call levels open, the main program included.
    pub fn depth(&self) -> usize {
        self.frames.len()
    }

    /// The kind of the current level.
    pub fn current_kind(&self) -> CallKind {
        self.frames.last().map_or(CallKind::Main, |f| f.kind)
    }

    /// The call chain, e.g. `O0001 line 3 → O9010 line 5 → O9011`.
    pub fn call_chain(&self) -> String {
        let mut out = String::new();
        for (i, f) in self.frames.iter().enumerate() {
            if i > 0 {
                out.push_str(&format!(" line {} → ", f.call_span.line));
            }
            out.push_str(&program_name(self.programs[f.prog].number));
        }
        out
    }

    fn top(&mut self) -> &mut Frame {
        self.frames
            .last_mut()
            .expect("a frame is open while running")
    }

    fn back_jump(&mut self, prog: usize, head: usize) {
        self.last_loop = Some((prog, head));
        self.iterations[prog][head] += 1;
    }

    fn budget_error(&self, prog: usize, line: usize) -> MacroError {
        let max = self.limits.max_blocks;
        let help = "the loop's exit condition never holds; correct it, or raise --max-steps if the program really runs this long";
        match self.last_loop {
            Some((p, l)) => {
                let line = &self.programs[p].lines[l];
                let what = match stmt_of(line) {
                    Some(StmtKind::While { id, .. }) => format!("WHILE … DO{id}"),
                    Some(StmtKind::Do { id }) => format!("DO{id}"),
                    Some(StmtKind::Goto { .. } | StmtKind::IfGoto { .. }) => "GOTO".into(),
                    _ => "M99".into(),
                };
                let n = self.iterations[p][l];
                MacroError::new(
                    ErrorKind::Budget,
                    line.span,
                    format!(
                        "block budget of {max} executed blocks exhausted: the loop at line {} ({what}) ran {n} times",
                        line.span.line
                    ),
                    help,
                )
            }
            None => MacroError::new(
                ErrorKind::Budget,
                self.programs[prog].lines[line].span,
                format!("block budget of {max} executed blocks exhausted"),
                help,
            ),
        }
    }

    /// Run macro statements up to the next NC block and hand it out; `None` at the end of
    /// the main program. Falling off the end of a called program returns like `M99`.
    pub fn next(
        &mut self,
        state: &mut MacroState,
        sys: &mut dyn System,
    ) -> Result<Option<Step<'p, B>>> {
        let programs = self.programs;
        loop {
            let Some(f) = self.frames.last() else {
                return Ok(None);
            };
            let (pi, li) = (f.prog, f.pc);
            let prog = &programs[pi];
            if li >= prog.lines.len() {
                if f.kind == CallKind::Main {
                    return Ok(None);
                }
                let span = prog.lines.last().map_or(f.call_span, |l| l.span);
                self.ret(state, None, span)?;
                continue;
            }
            self.executed += 1;
            if self.executed > self.limits.max_blocks {
                return Err(self.budget_error(pi, li));
            }
            self.counts[pi][li] += 1;
            let line = &prog.lines[li];
            let at = At {
                program: pi,
                line: li,
                seq: line.seq,
                span: line.span,
            };
            let stmt = match &line.body {
                Body::Block(b) => {
                    self.top().pc += 1;
                    return Ok(Some(Step::Block { at, block: b }));
                }
                Body::Stmt(s) => s,
            };
            match &stmt.kind {
                StmtKind::Assign { .. } | StmtKind::IfThen { .. } => {
                    state.execute(stmt, sys)?;
                    self.top().pc += 1;
                }
                StmtKind::IfThenBlock {
                    cond,
                    text,
                    text_span,
                } => {
                    self.top().pc += 1;
                    if state.condition(cond, sys)? {
                        return Ok(Some(Step::ThenBlock {
                            at,
                            text,
                            span: *text_span,
                        }));
                    }
                }
                StmtKind::IfGoto { cond, target } => {
                    if state.condition(cond, sys)? {
                        self.goto(state, sys, target, pi, li)?;
                    } else {
                        self.top().pc += 1;
                    }
                }
                StmtKind::Goto { target } => self.goto(state, sys, target, pi, li)?,
                StmtKind::While { cond, .. } => {
                    if state.condition(cond, sys)? {
                        self.top().pc += 1;
                    } else {
                        self.top().pc = prog.partner[li] + 1;
                    }
                }
                StmtKind::Do { .. } | StmtKind::EndIf => self.top().pc += 1,
                StmtKind::End { .. } => {
                    let head = prog.partner[li];
                    self.back_jump(pi, head);
                    self.top().pc = head;
                }
                StmtKind::IfBlock { cond } => {
                    if state.condition(cond, sys)? {
                        self.top().pc += 1;
                    } else {
                        self.top().pc = prog.partner[li] + 1;
                    }
                }
                StmtKind::Else => self.top().pc = prog.partner[li] + 1,
                StmtKind::OWord { .. } => {
                    return Err(MacroError::new(
                        ErrorKind::Unsupported,
                        stmt.span,
                        "o-words run in latsim's interpreter, not in this engine",
                        "run the program with latsim --control linuxcnc",
                    ))
                }
            }
        }
    }

    fn goto(
        &mut self,
        state: &mut MacroState,
        sys: &mut dyn System,
        target: &Expr,
        pi: usize,
        li: usize,
    ) -> Result<()> {
        let n = state.sequence_number(target, "GOTO", sys)?;
        self.jump_within(pi, li, n, target.span, "GOTO")
    }

    /// Jump to block `Nn` of program `pi` from its line `li`.
    fn jump_within(&mut self, pi: usize, li: usize, n: u32, span: Span, what: &str) -> Result<()> {
        let t = self.programs[pi].jump_target(li, n, span, what)?;
        if t <= li {
            self.back_jump(pi, li);
        }
        self.top().pc = t;
        Ok(())
    }

    /// Haas `M99 Pn` (and `[cond] M99 Pn` when its condition held): a jump to block `Nn`
    /// of the current program that does not return to the caller (spec §3.6). Call it
    /// after [`Flow::next`] handed out the `M99` block; `span` is the P word.
    pub fn jump(&mut self, seq: u32, span: Span) -> Result<()> {
        let f = self.frames.last().expect("running");
        let (pi, li) = (f.prog, f.pc.saturating_sub(1));
        self.jump_within(pi, li, seq, span, "M99 P")
    }

    fn find_program(&self, number: u32, span: Span) -> Result<usize> {
        self.programs
            .iter()
            .position(|p| p.number == Some(number))
            .ok_or_else(|| {
                MacroError::new(
                    ErrorKind::ProgramMissing,
                    span,
                    format!("program O{number:04} not found"),
                    format!("add O{number:04} to the file or give it as a library"),
                )
            })
    }

    fn check_depth(&self, kind: CallKind, span: Span) -> Result<()> {
        let count = |k| self.frames.iter().filter(|f| f.kind == k).count();
        let (n, limit, what) = match kind {
            CallKind::Macro => (
                count(CallKind::Macro),
                self.limits.macro_depth,
                "macro calls",
            ),
            _ => (
                count(CallKind::Sub),
                self.limits.sub_depth,
                "subprogram calls",
            ),
        };
        let total = self.frames.len() - 1;
        let (over, limit, what) = if n >= limit {
            (true, limit, what)
        } else {
            (
                total >= self.limits.total_depth,
                self.limits.total_depth,
                "calls in total",
            )
        };
        if over {
            return Err(MacroError::new(
                ErrorKind::CallDepth,
                span,
                format!("more than {limit} {what} nested: {} → …", self.call_chain()),
                "a program that calls itself needs an exit condition; otherwise flatten the calls",
            ));
        }
        Ok(())
    }

    fn push(&mut self, prog: usize, start: usize, kind: CallKind, repeats: u32, span: Span) {
        self.frames.push(Frame {
            prog,
            pc: start,
            kind,
            start,
            repeats_left: repeats - 1,
            call_span: span,
        });
    }

    /// `G65 P<number> L<repeats>` (and each call of a `G66` modal call): a new local level
    /// holding `args` ([`g65_locals`]). `span` is the calling block. Call it after
    /// [`Flow::next`] handed out the calling block; `L0` calls nothing.
    pub fn call_macro(
        &mut self,
        state: &mut MacroState,
        number: u32,
        repeats: u32,
        args: Locals,
        span: Span,
    ) -> Result<()> {
        let prog = self.find_program(number, span)?;
        if repeats == 0 {
            return Ok(());
        }
        self.check_depth(CallKind::Macro, span)?;
        state.vars.push_level(args);
        self.push(prog, 0, CallKind::Macro, repeats, span);
        Ok(())
    }

    /// `M98 P<number> L<repeats>`: the subprogram runs with the caller's locals.
    pub fn call_sub(&mut self, number: u32, repeats: u32, span: Span) -> Result<()> {
        let prog = self.find_program(number, span)?;
        if repeats == 0 {
            return Ok(());
        }
        self.check_depth(CallKind::Sub, span)?;
        self.push(prog, 0, CallKind::Sub, repeats, span);
        Ok(())
    }

    /// Haas `M97 P<seq> L<repeats>`: a local subprogram starting at block `N<seq>` of the
    /// current program, returning at its `M99`.
    pub fn call_local(&mut self, seq: u32, repeats: u32, span: Span) -> Result<()> {
        let prog = self.frames.last().expect("running").prog;
        let start = self.programs[prog].find_seq(seq, span, "M97 P")?;
        if repeats == 0 {
            return Ok(());
        }
        self.check_depth(CallKind::Sub, span)?;
        self.push(prog, start, CallKind::Sub, repeats, span);
        Ok(())
    }

    /// `M99` (`to_seq` = its P): repeat the called program while repeats remain, else
    /// return to the block after the call (or to block `N<to_seq>` of the calling program),
    /// dropping a `G65` level's locals. In the main program `M99` jumps to its start (or
    /// to `N<to_seq>`), and the block budget ends it if nothing else does.
    pub fn ret(&mut self, state: &mut MacroState, to_seq: Option<u32>, span: Span) -> Result<()> {
        let programs = self.programs;
        let f = self.frames.last().expect("running").clone();
        if f.kind == CallKind::Main {
            let pc = match to_seq {
                Some(n) => programs[f.prog].find_seq(n, span, "M99 P")?,
                None => 0,
            };
            let at = self.top().pc.saturating_sub(1);
            self.back_jump(f.prog, at);
            self.top().pc = pc;
            return Ok(());
        }
        if f.repeats_left > 0 {
            let top = self.top();
            top.repeats_left -= 1;
            top.pc = top.start;
            return Ok(());
        }
        self.frames.pop();
        if f.kind == CallKind::Macro {
            state.vars.pop_level();
        }
        if let Some(n) = to_seq {
            let caller = self.frames.last().expect("main stays").prog;
            let pc = programs[caller].find_seq(n, span, "M99 P")?;
            self.top().pc = pc;
        }
        Ok(())
    }
}

/// One argument word of a `G65` block, as written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Argument {
    /// The address letter.
    pub letter: char,
    /// Its value (vacant when written with a vacant variable: the argument is not given).
    pub value: Value,
    /// Where the word stands.
    pub span: Span,
}

/// The local set a `G65` call starts with: vacant except the arguments (spec §5.5).
/// Pass the argument words in the order written, without `P` and `L`. Assignment I maps
/// A–Z as [`ARGUMENTS`]; assignment II reads `I J K` as up to ten triplets (#4…#33), a
/// second I, J or K starting the next triplet; where both name a variable the value given
/// later wins.
pub fn g65_locals(args: &[Argument]) -> Result<Locals> {
    let mut locals = [Value::VACANT; 33];
    let mut seen: Vec<(char, Span)> = Vec::new();
    let (mut triplet, mut last): (usize, Option<usize>) = (0, None);
    for a in args {
        let n = match a.letter {
            'I' | 'J' | 'K' => {
                let q = (a.letter as u8 - b'I') as usize;
                if last.is_some_and(|p| q <= p) {
                    triplet += 1;
                }
                last = Some(q);
                if triplet >= 10 {
                    return Err(MacroError::new(
                        ErrorKind::Argument,
                        a.span,
                        "G65: more than ten I J K triplets",
                        "assignment II passes at most ten I J K triplets (#4–#33)",
                    ));
                }
                4 + 3 * triplet + q
            }
            c => {
                let Some(&(_, n)) = ARGUMENTS.iter().find(|(l, _)| *l == c) else {
                    return Err(MacroError::new(
                        ErrorKind::Argument,
                        a.span,
                        format!("address {c} cannot be a G65 argument"),
                        "G L N O P are not arguments; P names the program and L the repeat count",
                    ));
                };
                if let Some((_, first)) = seen.iter().find(|(l, _)| *l == c) {
                    return Err(MacroError::new(
                        ErrorKind::Argument,
                        a.span,
                        format!("G65 argument {c} given twice (first at {first})"),
                        format!("remove one of the two {c} words"),
                    ));
                }
                seen.push((c, a.span));
                n as usize
            }
        };
        locals[n - 1] = a.value;
    }
    Ok(locals)
}

/// The value a `G65` argument passes. With a decimal point it is the value as written.
/// Without one, `A B C I J K Q R U V W X Y Z` pass `written × increment` (the least input
/// increment; give 1.0 for a calculator-type profile) and `D E F H M S T` pass whole
/// units (spec §5.2). The second element is the info line the report shows for every
/// argument written without a decimal point.
pub fn g65_argument_value(
    letter: char,
    written: f64,
    has_point: bool,
    increment: f64,
) -> (f64, Option<String>) {
    if has_point {
        return (written, None);
    }
    let v = if "ABCIJKQRUVWXYZ".contains(letter) {
        written * increment
    } else {
        written
    };
    let v = if v.abs() < 1e15 {
        // keep it the closest double to the decimal value (5 × 0.001 = 0.005)
        (v * 1e9).round() / 1e9
    } else {
        v
    };
    (
        v,
        Some(format!(
            "G65 argument {letter}{written} has no decimal point: it passes {v}"
        )),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_stmt;
    use crate::options::Options;
    use crate::vars::NoMachine;

    /// A tiny program format for tests: `N10 stmt` lines; lines starting with `!` are NC
    /// blocks whose text is kept.
    fn program(number: Option<u32>, text: &str) -> Result<MacroProgram<String>> {
        program_with(number, text, &Options::fanuc())
    }

    fn program_with(
        number: Option<u32>,
        text: &str,
        options: &Options,
    ) -> Result<MacroProgram<String>> {
        let mut lines = Vec::new();
        let mut offset = 0;
        for (i, raw) in text.lines().enumerate() {
            let line_no = i as u32 + 1;
            let mut body = raw.trim_start();
            let mut col = (raw.len() - body.len()) as u32 + 1;
            let mut seq = None;
            if let Some(rest) = body.strip_prefix('N') {
                let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
                seq = Some(digits.parse().unwrap());
                let after = rest[digits.len()..].trim_start();
                col += (body.len() - after.len()) as u32;
                body = after;
            }
            let span = Span {
                line: line_no,
                column: 1,
                offset,
                len: raw.len() as u32,
            };
            let base = Span {
                line: line_no,
                column: col,
                offset: offset + (col - 1),
                len: 0,
            };
            offset += raw.len() as u32 + 1;
            if body.is_empty() {
                continue;
            }
            let body = if let Some(nc) = body.strip_prefix('!') {
                Body::Block(nc.to_string())
            } else {
                Body::Stmt(parse_stmt(body, base, options)?)
            };
            lines.push(Line { seq, span, body });
        }
        MacroProgram::new(number, lines, &options.limits)
    }

    /// Run to the end, collecting NC block texts; `M98 Pn`, `M99`, `G65 Pn …` blocks
    /// written as `!CALL n`, `!SUB n`, `!RET`, `!RETP n` drive the calls.
    fn run(programs: &[MacroProgram<String>], state: &mut MacroState) -> Result<Vec<String>> {
        let mut flow = Flow::new(programs, 0, state.options.limits);
        let mut out = Vec::new();
        while let Some(step) = flow.next(state, &mut NoMachine)? {
            let Step::Block { at, block } = step else {
                panic!()
            };
            let words: Vec<&str> = block.split_whitespace().collect();
            match words.as_slice() {
                ["CALL", n, rest @ ..] => {
                    let mut locals = [Value::VACANT; 33];
                    if let Some(x) = rest.first() {
                        locals[23] = Value::num(x.parse().unwrap());
                    }
                    flow.call_macro(state, n.parse().unwrap(), 1, locals, at.span)?
                }
                ["CALLL", n, l] => flow.call_macro(
                    state,
                    n.parse().unwrap(),
                    l.parse().unwrap(),
                    [Value::VACANT; 33],
                    at.span,
                )?,
                ["SUB", n] => flow.call_sub(n.parse().unwrap(), 1, at.span)?,
                ["SUBL", n, l] => flow.call_sub(n.parse().unwrap(), l.parse().unwrap(), at.span)?,
                ["LOCAL", n, l] => {
                    flow.call_local(n.parse().unwrap(), l.parse().unwrap(), at.span)?
                }
                ["RET"] => flow.ret(state, None, at.span)?,
                ["RETP", n] => flow.ret(state, Some(n.parse().unwrap()), at.span)?,
                ["JUMP", n] => flow.jump(n.parse().unwrap(), at.span)?,
                ["END"] => break,
                _ => out.push(block.clone()),
            }
        }
        Ok(out)
    }

    fn run_one(text: &str) -> Result<(Vec<String>, MacroState)> {
        let p = [program(None, text)?];
        let mut state = MacroState::new(Options::fanuc());
        let out = run(&p, &mut state)?;
        Ok((out, state))
    }

    fn local(state: &MacroState, n: usize) -> Value {
        state.vars.local(n)
    }

    #[test]
    fn while_loops_and_goto() {
        let (out, s) = run_one(
            "#1 = 0\n#2 = 0\nWHILE [#1 LT 3] DO1\n#1 = #1 + 1\n#3 = 0\nWHILE [#3 LT 2] DO2\n#3 = #3 + 1\n#2 = #2 + 1\nEND2\n!B\nEND1\nGOTO 20\n!SKIPPED\nN20 !AFTER",
        )
        .unwrap();
        assert_eq!(local(&s, 2), Value::num(6.0));
        assert_eq!(out, vec!["B", "B", "B", "AFTER"]);
        // GOTO with computed targets, rounded: 4.49 → N4, 4.5 → N5
        let (out, _) =
            run_one("#1 = 4.49\nGOTO #1\nN4 !FOUR\nGOTO 99\nN5 !FIVE\nN99 !LAST").unwrap();
        assert_eq!(out, vec!["FOUR", "LAST"]);
        let (out, _) = run_one("#1 = 4.5\nGOTO #1\nN4 !FOUR\nN5 !FIVE").unwrap();
        assert_eq!(out, vec!["FIVE"]);
        // backward GOTO loop, IF … GOTO
        let (out, s) = run_one("#1 = 0\nN1 #1 = #1 + 1\nIF [#1 LT 5] GOTO 1\n!DONE").unwrap();
        assert_eq!(out, vec!["DONE"]);
        assert_eq!(local(&s, 1), Value::num(5.0));
        // the same loop number reused by sequential loops; jumping out of a loop
        let (out, _) = run_one(
            "#1 = 0\nWHILE [#1 LT 2] DO1\n#1 = #1 + 1\nEND1\nWHILE [1] DO1\nGOTO 9\nEND1\nN9 !OUT",
        )
        .unwrap();
        assert_eq!(out, vec!["OUT"]);
        // DO without WHILE loops until a GOTO leaves it
        let (out, s) =
            run_one("#1 = 0\nDO1\n#1 = #1 + 1\nIF [#1 GE 7] GOTO 5\nEND1\nN5 !X").unwrap();
        assert_eq!(out, vec!["X"]);
        assert_eq!(local(&s, 1), Value::num(7.0));
    }

    #[test]
    fn block_form_if() {
        let text = "IF [#1 EQ 1] THEN\n!ONE\nELSE\n!OTHER\nENDIF\n!AFTER";
        let p = [program(None, text).unwrap()];
        assert_eq!(p[0].warnings().len(), 1);
        let mut s = MacroState::new(Options::fanuc());
        assert_eq!(run(&p, &mut s).unwrap(), vec!["OTHER", "AFTER"]);
        let mut s = MacroState::new(Options::fanuc());
        s.vars.set_local(1, Value::num(1.0));
        assert_eq!(run(&p, &mut s).unwrap(), vec!["ONE", "AFTER"]);
        let e = program(None, "ELSE").unwrap_err();
        assert_eq!(e.kind, ErrorKind::IfStructure);
        let e = program(None, "IF [1] THEN\n!A").unwrap_err();
        assert_eq!(e.kind, ErrorKind::IfStructure);
    }

    #[test]
    fn structure_errors_name_the_line() {
        let e = program(None, "!A\nN5 END1").unwrap_err();
        assert_eq!(e.kind, ErrorKind::EndWithoutDo);
        assert_eq!(e.span.line, 2);
        assert_eq!(e.message, "END1 without DO1");
        let e = program(
            None,
            "WHILE [1] DO1\nWHILE [1] DO2\nWHILE [1] DO3\nDO1\nEND1\nEND3\nEND2\nEND1",
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopNesting);
        assert_eq!(e.span.line, 4);
        let e = program(
            None,
            "WHILE [1] DO1\nWHILE [1] DO2\nDO3\nWHILE [1] DO3\nEND3\nEND3\nEND2\nEND1",
        )
        .unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopNesting);
        assert_eq!(e.span.line, 4);
        let e = program(None, "WHILE [1] DO1\nWHILE [1] DO2\nDO1\nEND1").unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopNesting);
        assert!(e.message.contains("line 1"), "{}", e.message);
        let e = program(None, "WHILE [1] DO1\nWHILE [1] DO2\nEND1\nEND2").unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopCrossing);
        assert_eq!(e.span.line, 3);
        let e = program(None, "!A\nWHILE [1] DO2\n!B").unwrap_err();
        assert_eq!(e.kind, ErrorKind::DoWithoutEnd);
        assert_eq!(e.span.line, 2);
        let e = program(None, "WHILE [1] DO4\nEND4").unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopNesting);
        assert_eq!((e.span.line, e.span.column), (1, 13));
        // limits come from the options: 2 deep allowed only
        let mut o = Options::fanuc();
        o.limits.loop_depth = 2;
        let e = program_with(None, "DO1\nDO2\nDO3\nEND3\nEND2\nEND1", &o).unwrap_err();
        assert_eq!(e.kind, ErrorKind::LoopNesting);
        assert_eq!(e.span.line, 3);
    }

    #[test]
    fn jump_errors() {
        let e = run_one("!A\nGOTO 30\nN20 !B").unwrap_err();
        assert_eq!(e.kind, ErrorKind::SequenceMissing);
        assert_eq!((e.span.line, e.span.column), (2, 6));
        assert!(e.message.contains("N30"), "{}", e.message);
        let e = run_one("N10 !A\nGOTO 10\nN10 !B").unwrap_err();
        assert_eq!(e.kind, ErrorKind::DuplicateSequence);
        assert!(e.message.contains("lines 1 and 3"), "{}", e.message);
        let e = run_one("GOTO #5").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Vacant);
        assert_eq!(e.span.column, 6);
        let e = run_one("GOTO 0").unwrap_err();
        assert_eq!(e.kind, ErrorKind::SequenceMissing);
        // into a loop from outside: alarm; within and out: fine
        let e = run_one("GOTO 5\nWHILE [1] DO1\nN5 !A\nEND1").unwrap_err();
        assert_eq!(e.kind, ErrorKind::JumpIntoLoop);
        assert!(e.message.contains("lines 2–4"), "{}", e.message);
        let (out, _) =
            run_one("#1 = 0\nWHILE [#1 LT 1] DO1\n#1 = 1\nGOTO 5\n!SKIP\nN5 !IN\nEND1").unwrap();
        assert_eq!(out, vec!["IN"]);
        // duplicates that are not jumped to are fine
        let (out, _) = run_one("N1 !A\nN1 !B").unwrap();
        assert_eq!(out, vec!["A", "B"]);
    }

    #[test]
    fn runaway_loop_ends_by_budget_quickly() {
        let e = run_one("#1 = 0\nWHILE [#1 GE 0] DO1\n#1 = #1 + 1\nEND1").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Budget);
        assert_eq!(e.span.line, 2);
        assert!(
            e.message
                .contains("block budget of 10000000 executed blocks exhausted: the loop at line 2 (WHILE … DO1) ran 3333333 times"),
            "{}",
            e.message
        );
        // GOTO loops and DO without WHILE too
        let e = run_one("!A\nN1 #1 = 1\nGOTO 1").unwrap_err();
        assert_eq!(e.kind, ErrorKind::Budget);
        assert_eq!(e.span.line, 3);
        assert!(e.message.contains("(GOTO)"), "{}", e.message);
        let p = [program(None, "DO2\n!A\nEND2").unwrap()];
        let mut s = MacroState::new(Options::fanuc());
        s.options.limits.max_blocks = 1000;
        let e = run(&p, &mut s).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Budget);
        assert!(e.message.contains("(DO2)"), "{}", e.message);
        // M99 in the main program loops to the start until the budget ends it
        let p = [program(None, "!A\n!RET").unwrap()];
        let mut s = MacroState::new(Options::fanuc());
        s.options.limits.max_blocks = 100;
        let e = run(&p, &mut s).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Budget);
        assert!(e.message.contains("(M99)"), "{}", e.message);
    }

    #[test]
    fn calls_and_returns() {
        let o = Options::fanuc();
        let main = program(None, "#1 = 1\n!CALL 9000 7\n!AFTER\n#2 = #1").unwrap();
        let sub = program(Some(9000), "#5 = #24\n!IN\n#1 = 99\n!RET").unwrap();
        let p = [main, sub];
        let mut s = MacroState::new(o);
        let out = run(&p, &mut s).unwrap();
        assert_eq!(out, vec!["IN", "AFTER"]);
        // the G65 level had its own #1; the main's #1 is untouched
        assert_eq!(local(&s, 2), Value::num(1.0));
        assert!(local(&s, 5).is_vacant());
        // M98 shares locals; L repeats; M99 P returns to a block of the caller
        let main = program(None, "#1 = 0\n!SUBL 100 3\n!RETURNED\n!SUB 200\nN50 !AT50").unwrap();
        let s100 = program(Some(100), "#1 = #1 + 1\n!RET").unwrap();
        let s200 = program(Some(200), "!IN200\n!RETP 50").unwrap();
        let p = [main, s100, s200];
        let mut s = MacroState::new(o);
        let out = run(&p, &mut s).unwrap();
        assert_eq!(out, vec!["RETURNED", "IN200", "AT50"]);
        assert_eq!(local(&s, 1), Value::num(3.0));
        // G65 L repeats keep the locals between repetitions
        let main = program(None, "!CALLL 300 4\n!DONE").unwrap();
        let s300 = program(Some(300), "#1 = #1 + 1\n#100 = #1\n!RET").unwrap();
        let p = [main, s300];
        let mut s = MacroState::new(o);
        run(&p, &mut s).unwrap();
        assert_eq!(s.vars.common(100), Some(Value::num(4.0)));
        assert!(local(&s, 1).is_vacant());
        // Haas M99 Pn: a branch inside the subprogram, no return
        let main = program(None, "!SUB 20\n!BACK").unwrap();
        let s20 = program(
            Some(20),
            "N5 #1 = #1 + 1\n!IN\nIF [#1 GE 2] GOTO 9\n!JUMP 5\nN9 !RET",
        )
        .unwrap();
        let p = [main, s20];
        let mut s = MacroState::new(Options::haas());
        assert_eq!(run(&p, &mut s).unwrap(), vec!["IN", "IN", "BACK"]);
        // falling off the end of a subprogram returns
        let main = program(None, "!SUB 400\n!BACK").unwrap();
        let s400 = program(Some(400), "!IN").unwrap();
        let p = [main, s400];
        let mut s = MacroState::new(o);
        assert_eq!(run(&p, &mut s).unwrap(), vec!["IN", "BACK"]);
        // Haas M97 local subprogram
        let main = program(None, "!LOCAL 100 2\n!END\nN100 !G\n!RET").unwrap();
        let p = [main];
        let mut s = MacroState::new(o);
        assert_eq!(run(&p, &mut s).unwrap(), vec!["G", "G"]);
        // missing program
        let p = [program(None, "!A\n!CALL 1234").unwrap()];
        let e = run(&p, &mut MacroState::new(o)).unwrap_err();
        assert_eq!(e.kind, ErrorKind::ProgramMissing);
        assert_eq!(e.span.line, 2);
        assert!(e.message.contains("O1234"));
        // M99 P to a missing block of the caller
        let main = program(None, "!SUB 10\n!A").unwrap();
        let s10 = program(Some(10), "!RETP 77").unwrap();
        let e = run(&[main, s10], &mut MacroState::new(o)).unwrap_err();
        assert_eq!(e.kind, ErrorKind::SequenceMissing);
        assert!(e.message.contains("M99 P N77"), "{}", e.message);
    }

    #[test]
    fn call_depth_limits() {
        let o = Options::fanuc();
        // a macro that calls itself forever: the 6th G65 level is refused
        let main = program(None, "!CALL 1").unwrap();
        let rec = program(Some(1), "#100 = #100 + 1\n!CALL 1").unwrap();
        let p = [main, rec];
        let mut s = MacroState::new(o);
        let e = run(&p, &mut s).unwrap_err();
        assert_eq!(e.kind, ErrorKind::CallDepth);
        assert!(
            e.message.starts_with("more than 5 macro calls nested"),
            "{}",
            e.message
        );
        assert!(
            e.message
                .contains("the main program line 1 → O0001 line 2 → O0001"),
            "{}",
            e.message
        );
        assert_eq!(s.vars.common(100), Some(Value::num(5.0)));
        // Haas allows 9
        let mut s = MacroState::new(Options::haas());
        let p = [
            program_with(None, "!CALL 1", &Options::haas()).unwrap(),
            program_with(Some(1), "#100 = #100 + 1\n!CALL 1", &Options::haas()).unwrap(),
        ];
        run(&p, &mut s).unwrap_err();
        assert_eq!(s.vars.common(100), Some(Value::num(9.0)));
        // M98: 10 deep
        let p = [
            program(None, "!SUB 1").unwrap(),
            program(Some(1), "#100 = #100 + 1\n!SUB 1").unwrap(),
        ];
        let mut s = MacroState::new(o);
        let e = run(&p, &mut s).unwrap_err();
        assert!(e.message.contains("10 subprogram calls"), "{}", e.message);
        assert_eq!(s.vars.common(100), Some(Value::num(10.0)));
        // total
        let mut o2 = o;
        o2.limits.total_depth = 3;
        let p = [
            program(None, "!SUB 1").unwrap(),
            program(Some(1), "!CALL 2").unwrap(),
            program(Some(2), "!SUB 1").unwrap(),
        ];
        let mut s = MacroState::new(o2);
        let e = run(&p, &mut s).unwrap_err();
        assert!(
            e.message.contains("more than 3 calls in total"),
            "{}",
            e.message
        );
    }

    fn arg(letter: char, v: f64) -> Argument {
        Argument {
            letter,
            value: Value::num(v),
            span: Span::default(),
        }
    }

    #[test]
    fn g65_assignment_one() {
        // every letter of the table lands in its variable
        let args: Vec<Argument> = ARGUMENTS
            .iter()
            .map(|&(c, n)| arg(c, f64::from(n) * 10.0))
            .collect();
        let l = g65_locals(&args).unwrap();
        for &(c, n) in &ARGUMENTS {
            assert_eq!(l[n as usize - 1], Value::num(f64::from(n) * 10.0), "{c}");
        }
        for n in [10, 12, 14, 15, 16] {
            assert!(l[n - 1].is_vacant(), "#{n}");
        }
        assert_eq!(crate::arguments::letter_of_argument(24), Some('X'));
        assert_eq!(crate::arguments::letter_of_argument(10), None);
        // a vacant argument is not given
        let l = g65_locals(&[Argument {
            letter: 'X',
            value: Value::VACANT,
            span: Span::default(),
        }])
        .unwrap();
        assert!(l[23].is_vacant());
    }

    #[test]
    fn g65_assignment_two() {
        // A B C then I J K triplets: #4…#33
        let mut args = vec![arg('A', 1.0), arg('B', 2.0), arg('C', 3.0)];
        for t in 0..10 {
            for (k, c) in ['I', 'J', 'K'].into_iter().enumerate() {
                args.push(arg(c, (4 + 3 * t + k) as f64));
            }
        }
        let l = g65_locals(&args).unwrap();
        for (i, v) in l.iter().enumerate() {
            assert_eq!(*v, Value::num(i as f64 + 1.0), "#{}", i + 1);
        }
        // an eleventh triplet is an error
        args.push(arg('I', 0.0));
        let e = g65_locals(&args).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Argument);
        // a second I (or a J after K) starts the next triplet
        let l = g65_locals(&[arg('I', 1.0), arg('K', 3.0), arg('J', 5.0), arg('I', 7.0)]).unwrap();
        assert_eq!(l[3], Value::num(1.0));
        assert_eq!(l[5], Value::num(3.0));
        assert_eq!(l[7], Value::num(5.0)); // J of triplet 2 = #8
        assert_eq!(l[9], Value::num(7.0)); // I of triplet 3 = #10
                                           // mixed: the value given later wins (#7 is D and I of triplet 2)
        let l = g65_locals(&[arg('D', 1.0), arg('I', 2.0), arg('I', 3.0)]).unwrap();
        assert_eq!(l[6], Value::num(3.0));
        let l = g65_locals(&[arg('I', 2.0), arg('I', 3.0), arg('D', 1.0)]).unwrap();
        assert_eq!(l[6], Value::num(1.0));
        // not arguments; twice
        for c in ['G', 'L', 'N', 'O', 'P'] {
            let e = g65_locals(&[arg(c, 1.0)]).unwrap_err();
            assert_eq!(e.kind, ErrorKind::Argument, "{c}");
        }
        let e = g65_locals(&[arg('X', 1.0), arg('X', 2.0)]).unwrap_err();
        assert!(e.message.contains("given twice"));
    }

    #[test]
    fn g65_argument_units() {
        assert_eq!(g65_argument_value('X', 100.0, true, 0.001), (100.0, None));
        let (v, info) = g65_argument_value('X', 100.0, false, 0.001);
        assert_eq!(v, 0.1);
        assert!(info.unwrap().contains("passes 0.1"));
        assert_eq!(g65_argument_value('A', 1.0, false, 0.0001).0, 0.0001);
        assert_eq!(g65_argument_value('F', 100.0, false, 0.001).0, 100.0);
        assert_eq!(g65_argument_value('T', 5.0, false, 0.001).0, 5.0);
        assert_eq!(g65_argument_value('Z', 5.0, false, 1.0).0, 5.0);
    }
}
