//! Custom macro B in the interpreter (spec/dialects.md §5), on the `macro_b` crate: the
//! statements (`#i = …`, `IF`, `GOTO`, `WHILE`/`DO`/`END`) run here as blocks of the block
//! loop, so every executed block keeps its source line; an NC block's expression words are
//! evaluated into a working copy of its program just before it runs (a vacant value drops
//! the address, §5.2), together with the finishing shape a G70–G73 block reads (and a Haas
//! `IF [cond] THEN <NC block>` runs its words when the condition holds); `G65` becomes a
//! call with a new local level; `G66` sets a modal call made the same way after every later
//! block that moves an axis, until `G67`; the system variables read the interpreter's state.
//! At the end the run's variables and the lines run more than once go into the toolpath.

use super::flow::{Callee, Flow};
use super::modal_call::{Calls, ModalCall};
use super::{alarm, Interp, MotionMode};
use crate::{Diagnostic, Pt, Span};
use gcode::{Block, Program, Subprogram, Word};
use macro_b::{
    Axis, Body, ErrorKind, Expr, Line, Locals, MacroError, MacroProgram, MacroState, Position,
    StmtKind, System, Value,
};
use std::borrow::Cow;

mod o_words;

/// The macro side of a run.
pub(crate) struct Macros {
    state: MacroState,
    /// Each O program's structure (loops matched, N numbers indexed), in the file's order.
    programs: Vec<MacroProgram<()>>,
    /// Per O program that holds macro B: the copy its blocks are evaluated into. `None`:
    /// the program runs as written.
    work: Vec<Option<Subprogram>>,
    /// How many times each block ran, per O program.
    counts: Vec<Vec<u64>>,
    /// Back jumps to each block (loop iterations), per O program.
    iterations: Vec<Vec<u64>>,
    /// The (program, block) last jumped back to: the loop the block budget names.
    last_loop: Option<(usize, usize)>,
    /// Where each file's O programs start in the vectors above, by the file's address: the
    /// main file at 0, a `--lib` file appended when it is first run (its programs number
    /// from 0 in their own file, so they need their own slots).
    bases: Vec<(usize, usize)>,
    limits: macro_b::Limits,
    /// The modal call in force (`G66`), until `G67`.
    modal: Option<ModalCall>,
    /// Calls made by the modal call that are running: their blocks (and the blocks of what
    /// they call) do not trigger it again, as on FANUC.
    in_modal: u32,
}

/// What a call entered, for [`Interp::leave_call`].
pub(super) struct Level {
    locals: bool,
    modal: bool,
}

/// The interpreter as the system variables see it (§5.7); `span` is the block being run.
struct Sys<'a, 'm> {
    it: &'a mut Interp<'m>,
    span: Span,
}

impl System for Sys<'_, '_> {
    fn position(&self, kind: Position, axis: Axis) -> Option<f64> {
        let p: Pt = match kind {
            Position::BlockEnd | Position::Work => self.it.pos - self.it.shift,
            // latsim's machine frame is the G54 frame the segments live in
            Position::Machine => self.it.pos,
        };
        Some(match axis {
            Axis::X => 2.0 * p.r,
            Axis::Z => p.z,
        })
    }
    fn modal_group(&self, group: u32) -> Option<f64> {
        match group {
            1 => Some(match self.it.motion {
                MotionMode::Rapid => 0.0,
                MotionMode::Line => 1.0,
                MotionMode::Cw => 2.0,
                MotionMode::Ccw => 3.0,
                MotionMode::Thread => 32.0,
                MotionMode::Cycle(t) => f64::from(t) / 10.0,
            }),
            // G96/G97 (constant surface speed)
            2 => Some(if self.it.css { 96.0 } else { 97.0 }),
            // G90/G91 (absolute/incremental; system A writes U/W instead: always G90)
            3 => Some(if self.it.incremental { 91.0 } else { 90.0 }),
            5 => Some(if self.it.per_rev { 99.0 } else { 98.0 }),
            6 => Some(if self.it.inch { 20.0 } else { 21.0 }),
            // G40/G41/G42
            7 => Some(match self.it.comp {
                None => 40.0,
                Some(crate::tnrc::Side::Left) => 41.0,
                Some(crate::tnrc::Side::Right) => 42.0,
            }),
            _ => None,
        }
    }
    fn last_address(&self, letter: char) -> Option<Value> {
        match letter {
            'F' => Some(Value::num(self.it.feed)),
            'S' => Some(Value::num(self.it.s_value)),
            'T' => Some(Value::num(f64::from(self.it.tool * 100 + self.it.offset))),
            _ => None,
        }
    }
    fn parts_counter(&self, which: u8) -> Option<f64> {
        self.it
            .parts
            .get(usize::from(which).checked_sub(1)?)
            .copied()
    }
    fn set_parts_counter(&mut self, which: u8, value: f64) -> bool {
        match usize::from(which)
            .checked_sub(1)
            .and_then(|i| self.it.parts.get_mut(i))
        {
            Some(n) => {
                *n = value;
                true
            }
            None => false,
        }
    }
    fn named_parameter(&self, name: &str) -> Option<f64> {
        let it = &self.it;
        let here = it.pos - it.shift;
        let flag = |b: bool| if b { 1.0 } else { 0.0 };
        Some(match name {
            // LinuxCNC keeps X as a radius inside (`_setup.current_x`), in program units
            "_x" => here.r / it.unit(),
            "_z" => here.z / it.unit(),
            "_metric" => flag(!it.inch),
            "_imperial" => flag(it.inch),
            "_absolute" => flag(!it.incremental),
            "_incremental" => flag(it.incremental),
            "_lathe_diameter_mode" => flag(it.x_diameter),
            "_lathe_radius_mode" => flag(!it.x_diameter),
            "_units_per_rev" => flag(it.per_rev),
            "_units_per_minute" => flag(!it.per_rev),
            "_feed" => it.feed,
            "_rpm" => it.s_value,
            "_current_tool" => f64::from(it.tool),
            _ => return None,
        })
    }
    fn stop_message(&mut self, number: f64, message: &str) -> bool {
        self.it.warn(
            self.span,
            "LS-STOP",
            format!("stop {number}: {message}"),
            "#3006 stops the program like M00; the simulation goes on",
        );
        true
    }
}

/// The alarm code of a macro error (FANUC's where it has one).
fn code(kind: ErrorKind) -> &'static str {
    match kind {
        ErrorKind::Syntax | ErrorKind::BracketNesting | ErrorKind::Unsupported => "PS0114",
        ErrorKind::DivisionByZero => "PS0112",
        ErrorKind::Domain => "PS0119",
        ErrorKind::Vacant => "LS-VACANT",
        ErrorKind::NoSuchVariable | ErrorKind::Argument => "PS0115",
        ErrorKind::ReadOnly => "PS0116",
        ErrorKind::NotSimulated => "LS-NOT-SIMULATED",
        ErrorKind::SequenceMissing | ErrorKind::DuplicateSequence | ErrorKind::JumpIntoLoop => {
            "PS0128"
        }
        ErrorKind::EndWithoutDo
        | ErrorKind::DoWithoutEnd
        | ErrorKind::LoopNesting
        | ErrorKind::LoopCrossing
        | ErrorKind::IfStructure => "PS0124",
        ErrorKind::OWordStructure => "LS-O-WORD",
        ErrorKind::Budget => "LS-LOOP",
        ErrorKind::CallDepth => "PS077",
        ErrorKind::ProgramMissing => "PS078",
        ErrorKind::ProgramAlarm { .. } => "MACRO-ALARM",
    }
}

fn diagnostic(e: MacroError) -> Diagnostic {
    alarm(e.span, code(e.kind), e.message, e.help)
}

/// Letters whose values are whole numbers (codes, speeds, tools, counts, program and
/// sequence numbers, increments): a value put there is rounded half away from zero (`M#1`
/// with #1 = 3.5 is M04, spec §5.2).
const INTEGER_ADDRESSES: &str = "MSTPQL";

impl Macros {
    /// Prepare the programs of a file: check their `DO`/`END` structure and index them.
    fn new(program: &Program, options: macro_b::Options) -> Result<Self, MacroError> {
        let mut m = Self {
            state: MacroState::new(options),
            programs: vec![],
            work: vec![],
            counts: vec![],
            iterations: vec![],
            last_loop: None,
            bases: vec![],
            limits: options.limits,
            modal: None,
            in_modal: 0,
        };
        m.base(program)?;
        Ok(m)
    }

    /// Where `program`'s O programs start, if it has run.
    fn base_of(&self, program: &Program) -> Option<usize> {
        let key = std::ptr::from_ref(program) as usize;
        self.bases.iter().find(|(k, _)| *k == key).map(|&(_, b)| b)
    }

    /// Where `program`'s O programs start in the per-program vectors, preparing them (their
    /// `DO`/`END` structure checked, N numbers indexed) the first time the file runs.
    fn base(&mut self, program: &Program) -> Result<usize, MacroError> {
        let key = std::ptr::from_ref(program) as usize;
        if let Some(&(_, base)) = self.bases.iter().find(|(k, _)| *k == key) {
            return Ok(base);
        }
        let base = self.programs.len();
        for sub in &program.programs {
            // Statements (GOTO, WHILE, IF) consult their own program's lines only, so a
            // program without macro B needs none: its blocks are not read again for them.
            let macros = sub.blocks.has_macro();
            let lines = macros
                .then(|| sub.blocks.iter())
                .into_iter()
                .flatten()
                .map(|b| Line {
                    seq: b.seq,
                    span: b.span,
                    body: b
                        .stmt
                        .as_deref()
                        .cloned()
                        .map_or(Body::Block(()), Body::Stmt),
                })
                .collect();
            self.programs
                .push(MacroProgram::new(sub.number, lines, &self.limits)?);
            self.work.push(macros.then(|| sub.clone()));
            self.counts.push(vec![0; sub.blocks.len()]);
            self.iterations.push(vec![0; sub.blocks.len()]);
        }
        self.bases.push((key, base));
        Ok(base)
    }

    fn back_jump(&mut self, index: usize, head: usize) {
        self.last_loop = Some((index, head));
        self.iterations[index][head] += 1;
    }

    /// Run a macro statement: where the block loop goes next; `None` when the block's NC
    /// words run now (Haas `IF [cond] THEN <NC block>` whose condition held).
    fn statement(
        &mut self,
        index: usize,
        i: usize,
        kind: &StmtKind,
        stmt: &macro_b::Stmt,
        sys: &mut dyn System,
    ) -> Result<Option<Flow>, MacroError> {
        let prog = &self.programs[index];
        let after = |line: usize| prog.partner(line).map_or(Flow::Next, |p| Flow::Jump(p + 1));
        Ok(Some(match kind {
            StmtKind::Assign { .. } | StmtKind::IfThen { .. } => {
                self.state.execute(stmt, sys)?;
                Flow::Next
            }
            StmtKind::IfGoto { cond, target } => {
                if self.state.condition(cond, sys)? {
                    self.goto(index, i, target, sys)?
                } else {
                    Flow::Next
                }
            }
            StmtKind::Goto { target } => self.goto(index, i, target, sys)?,
            StmtKind::While { cond, .. } | StmtKind::IfBlock { cond } => {
                if self.state.condition(cond, sys)? {
                    Flow::Next
                } else {
                    after(i)
                }
            }
            StmtKind::Else => after(i),
            StmtKind::Do { .. } | StmtKind::EndIf => Flow::Next,
            StmtKind::End { .. } => {
                let head = prog.partner(i).expect("an END is matched when prepared");
                self.back_jump(index, head);
                Flow::Jump(head)
            }
            StmtKind::IfThenBlock { cond, .. } => {
                if self.state.condition(cond, sys)? {
                    return Ok(None);
                }
                Flow::Next
            }
            StmtKind::OWord {
                label,
                keyword,
                args,
            } => {
                let w = o_words::OWord {
                    label,
                    keyword: *keyword,
                    args,
                    span: stmt.span,
                };
                self.o_word((index, i), &w, sys)?
            }
        }))
    }

    fn goto(
        &mut self,
        index: usize,
        i: usize,
        target: &Expr,
        sys: &mut dyn System,
    ) -> Result<Flow, MacroError> {
        let n = self.state.sequence_number(target, "GOTO", sys)?;
        let t = self.programs[index].jump_target(i, n, target.span, "GOTO")?;
        if t <= i {
            self.back_jump(index, i);
        }
        Ok(Flow::Jump(t))
    }

    /// The value an expression puts into an address: `None` when vacant (the address is
    /// then not written). Whole-number addresses are rounded half away from zero, G codes
    /// to tenths, lengths and feeds to their increment.
    fn word_value(
        &mut self,
        w: &Word,
        e: &Expr,
        increment: f64,
        sys: &mut dyn System,
    ) -> Result<Option<(f64, bool)>, MacroError> {
        if INTEGER_ADDRESSES.contains(w.letter) {
            return Ok(self.state.integer_value(e, sys)?.map(|v| (v as f64, false)));
        }
        let increment = match w.letter {
            'G' => 0.1,
            'F' => 0.0001,
            _ => increment,
        };
        Ok(self
            .state
            .address_value(e, increment, sys)?
            .map(|v| (v, true)))
    }

    /// Evaluate the expression words of `from` into `to`.
    fn evaluate(
        &mut self,
        from: &Block,
        to: &mut Block,
        increment: f64,
        sys: &mut dyn System,
    ) -> Result<(), MacroError> {
        let mut words = Vec::with_capacity(from.words.len());
        for w in &from.words {
            let Some(e) = &w.expr else {
                words.push(w.clone());
                continue;
            };
            if let Some((value, has_point)) = self.word_value(w, e, increment, sys)? {
                words.push(Word {
                    value,
                    has_point,
                    expr: None,
                    ..w.clone()
                });
            }
        }
        to.words = words.into_boxed_slice();
        Ok(())
    }

    /// Evaluate block `i` of `sub` into `work`; for a G70–G73 block also the blocks of its
    /// finishing shape `P`…`Q`, which the cycle reads from the program.
    fn evaluate_for(
        &mut self,
        sub: &Subprogram,
        work: &mut Subprogram,
        i: usize,
        increment: f64,
        sys: &mut dyn System,
    ) -> Result<(), MacroError> {
        let work = work.blocks.make_mut();
        let original = sub.blocks.at(i);
        if original.has_macro() {
            self.evaluate(&original, &mut work[i], increment, sys)?;
        }
        let b = &work[i];
        if !reads_shape(b) {
            return Ok(());
        }
        let seq = |letter| {
            let n = b.get(letter)?.value as u32;
            sub.blocks.positions_seq(n).next()
        };
        let (Some(p), Some(q)) = (seq('P'), seq('Q')) else {
            return Ok(());
        };
        // (a Q before P names no shape: the cycle's alarm, not this loop's)
        let Some(shape) = work.get_mut(p..=q) else {
            return Ok(());
        };
        for (k, slot) in (p..=q).zip(shape) {
            let original = sub.blocks.at(k);
            if original.has_macro() {
                self.evaluate(&original, slot, increment, sys)?;
            }
        }
        Ok(())
    }

    /// The locals a `G65` or `G66` block (`code` 650 or 660) passes, its program number and
    /// repeat count.
    fn g65(
        &mut self,
        b: &Block,
        code: i32,
        increment: f64,
        sys: &mut dyn System,
        notes: &mut Vec<(Span, String)>,
    ) -> Result<(u32, u32, Locals), Diagnostic> {
        let name = if code == 660 { "G66" } else { "G65" };
        let mut args = Vec::new();
        let (mut number, mut times) = (None, 1);
        for w in &b.words {
            let value = match &w.expr {
                Some(e) => self.state.eval(e, sys).map_err(diagnostic)?,
                None => {
                    let (v, note) =
                        macro_b::g65_argument_value(w.letter, w.value, w.has_point, increment);
                    if let Some(n) = note.filter(|_| !matches!(w.letter, 'G' | 'P' | 'L')) {
                        notes.push((w.span, n));
                    }
                    Value::num(v)
                }
            };
            let whole = |what: &str, max: f64| match value.get() {
                Some(v) if v.fract() == 0.0 && (0.0..=max).contains(&v) => Ok(v as u32),
                None => Err(alarm(
                    w.span,
                    "LS-VACANT",
                    format!("{name} {what}: the variable is vacant"),
                    "give the variable a value before this block",
                )),
                _ => Err(alarm(
                    w.span,
                    "PS078",
                    format!("{name} {what} {} is not a whole number 0 … {max}", value),
                    format!("write e.g. {name} P9010 L1 A1. B2."),
                )),
            };
            match w.letter {
                'G' if w.code_tenths() == Some(code) && w.expr.is_none() => {}
                'G' => {
                    return Err(alarm(
                        w.span,
                        "PS0115",
                        format!("a {name} block holds only P, L and the arguments"),
                        "put other G codes on a block of their own",
                    ))
                }
                'P' => number = Some(whole("P", 9999.0)?),
                'L' => times = whole("L", 9999.0)?,
                letter => args.push(macro_b::Argument {
                    letter,
                    value,
                    span: w.span,
                }),
            }
        }
        let number = number.ok_or_else(|| {
            alarm(
                b.span,
                "PS078",
                format!("{name} without P"),
                format!(
                    "write {name} P<program number> and the arguments, e.g. {name} P9010 A1. B2."
                ),
            )
        })?;
        let locals = macro_b::g65_locals(&args).map_err(diagnostic)?;
        Ok((number, times, locals))
    }
}

/// The alarm for `G65 Hm P#i Q#j R#k`, custom macro A (GSK 980TD, older FANUC controls):
/// its operations (H01 assign … H86 jump) are not simulated; read as a macro B call it
/// would call program "#i" (field run 6, F: "G65 P: the variable is vacant").
pub(super) fn macro_a(b: &Block) -> Diagnostic {
    let h = b.words.iter().find(|w| w.letter == 'H');
    let span = h.map_or(b.span, |w| w.span);
    let op = h.map_or(String::new(), |w| format!(" H{:02}", w.value));
    alarm(
        span,
        "LS-MACRO-A",
        format!("G65{op}: custom macro A (G65 Hm P#i Q#j R#k) is not simulated"),
        "write the calculation in custom macro B (H01: #101 = 30., H03: #101 = #101 - 3., H84: IF [#101 LT 22.] GOTO 50) and run with --macro on",
    )
}

/// Whether the block has a plain `G<code/10>` word (`code` in tenths: 650 is G65).
fn has_code(b: &Block, code: i32) -> bool {
    b.words
        .iter()
        .any(|w| w.letter == 'G' && w.expr.is_none() && w.code_tenths() == Some(code))
}

/// The G70–G73 cycles that read a finishing shape `P`…`Q` of the program.
fn reads_shape(b: &Block) -> bool {
    b.words
        .iter()
        .any(|w| w.letter == 'G' && matches!(w.code_tenths(), Some(700 | 710 | 720 | 730)))
}

impl Interp<'_> {
    /// Start the macro side of the run when custom macro B is on: the programs' loop
    /// structure is checked before anything runs.
    pub(super) fn prepare_macros(&mut self, program: &Program) -> Result<(), Diagnostic> {
        let Some(options) = self.opts.macros else {
            return Ok(());
        };
        let mut macros = Macros::new(program, options).map_err(diagnostic)?;
        for &(n, v) in &self.opts.vars {
            macros
                .state
                .vars
                .load(n, v, Span::default())
                .map_err(diagnostic)?;
        }
        for p in &macros.programs {
            for w in p.warnings() {
                self.warn(w.span, "LS-MACRO", w.message.clone(), "");
            }
        }
        self.macros = Some(Box::new(macros));
        Ok(())
    }

    /// Put the run's variables and the lines run more than once into the toolpath.
    pub(super) fn finish_macros(&mut self, program: &Program) {
        let Some(m) = self.macros.take() else {
            return;
        };
        self.out.variables = m
            .state
            .vars
            .report()
            .into_iter()
            .map(|v| (format!("#{}", v.number), v.value.get()))
            .chain(
                m.state
                    .vars
                    .named_report()
                    .into_iter()
                    .map(|(n, v)| (format!("#<{n}>"), v.get())),
            )
            .collect();
        let mut lines: Vec<(u32, u64)> = Vec::new();
        for (sub, counts) in program.programs.iter().zip(&m.counts) {
            for (i, &n) in counts.iter().enumerate() {
                if n > 1 {
                    lines.push((sub.blocks.at(i).span.line, n));
                }
            }
        }
        lines.sort_unstable();
        lines.dedup_by(|a, b| {
            let same = a.0 == b.0;
            if same {
                b.1 += a.1;
            }
            same
        });
        self.out.line_counts = lines;
    }

    /// The least increment a length written with an expression is rounded to.
    fn increment(&self) -> f64 {
        if self.inch {
            0.0001
        } else {
            self.machine.increment.mm()
        }
    }

    /// Run block `i` of O program `index` (`read`: the block, when read already): a macro
    /// statement, a `G65` call, or an NC block with its expressions evaluated. Without custom
    /// macro B, just the block.
    pub(super) fn step(
        &mut self,
        program: &Program,
        index: usize,
        i: usize,
        read: Option<&Block>,
    ) -> Result<Flow, Diagnostic> {
        let sub = &program.programs[index];
        let b = read.map_or_else(|| sub.blocks.at(i), Cow::Borrowed);
        let Some(mut m) = self.macros.take() else {
            return self.block(sub, &b, i);
        };
        let flow = match m.base(program) {
            Ok(base) => self.step_with(&mut m, sub, &b, base + index, i),
            Err(e) => Err(diagnostic(e)),
        };
        self.macros = Some(m);
        flow
    }

    /// [`Interp::step`] with macro B: block `b`, block `i` of `sub`, O program `index` of
    /// the programs macro B knows.
    fn step_with(
        &mut self,
        m: &mut Macros,
        sub: &Subprogram,
        b: &Block,
        index: usize,
        i: usize,
    ) -> Result<Flow, Diagnostic> {
        m.counts[index][i] += 1;
        let increment = self.increment();
        let span = b.span;
        if let Some(stmt) = &b.stmt {
            let mut sys = Sys { it: self, span };
            if let Some(flow) = m
                .statement(index, i, &stmt.kind, stmt, &mut sys)
                .map_err(diagnostic)?
            {
                return Ok(flow);
            }
        }
        if let Some(code) = [650, 660].into_iter().find(|&c| has_code(b, c)) {
            // a GSK 980's G65 with H is its macro A, never a macro B call with argument H
            if code == 650 && b.has('H') && self.machine.control == crate::Control::Gsk980 {
                return Err(macro_a(b));
            }
            let mut notes = vec![];
            let (number, times, locals) =
                m.g65(b, code, increment, &mut Sys { it: self, span }, &mut notes)?;
            for (at, note) in notes {
                self.warn(
                    at,
                    "LS-G65-ARG",
                    note,
                    "write the argument with a decimal point to pass it as written",
                );
            }
            let locals = Box::new(locals);
            if code == 650 {
                return Ok(Flow::Call {
                    callee: Callee::Program(number),
                    times,
                    span,
                    locals: Some(locals),
                });
            }
            if let Some(earlier) = &m.modal {
                return Err(alarm(
                    span,
                    "LS-NOT-SIMULATED",
                    format!(
                        "G66 while the modal call of line {} is in force: nested modal calls are not simulated",
                        earlier.span.line
                    ),
                    "cancel the first modal call with G67 before this G66",
                ));
            }
            m.modal = Some(ModalCall {
                number,
                times,
                locals,
                span,
            });
            return Ok(Flow::Next);
        }
        if has_code(b, 670) {
            if let Some(w) = b
                .words
                .iter()
                .find(|w| w.letter != 'G' || w.code_tenths() != Some(670))
            {
                return Err(alarm(
                    w.span,
                    "PS0115",
                    "a G67 block cancels the modal call and holds nothing else",
                    "put G67 on a block of its own",
                ));
            }
            m.modal = None;
            return Ok(Flow::Next);
        }
        let flow = match m.work[index].take() {
            None => self.block(sub, b, i),
            Some(mut work) => {
                let flow = m
                    .evaluate_for(sub, &mut work, i, increment, &mut Sys { it: self, span })
                    .map_err(diagnostic)
                    .and_then(|()| self.block(&work, &work.blocks.at(i), i));
                m.work[index] = Some(work);
                flow
            }
        }?;
        self.modal_call(m, flow, span)
    }

    /// After a block that moved an axis while `G66` is in force (and outside the macro the
    /// modal call runs): the call, with the arguments of the `G66` block.
    fn modal_call(&self, m: &Macros, flow: Flow, span: Span) -> Result<Flow, Diagnostic> {
        let Some(call) = m.modal.as_ref().filter(|_| self.moved && m.in_modal == 0) else {
            return Ok(flow);
        };
        if !matches!(flow, Flow::Next) {
            return Err(alarm(
                span,
                "LS-NOT-SIMULATED",
                "a block that moves under G66 and also calls, returns or ends: the order of the move, the modal call and the M code is not simulated",
                "put the M98/M99/M30 on a block of its own",
            ));
        }
        Ok(Flow::Call {
            callee: Callee::Modal(call.number),
            times: call.times,
            span,
            locals: Some(call.locals.clone()),
        })
    }

    /// Enter a call: a `G65`/`G66` level (its locals) and, for the modal call, the blocks
    /// that do not trigger it.
    pub(super) fn enter_call(&mut self, locals: Option<Box<Locals>>, modal: bool) -> Level {
        let Some(m) = self.macros.as_mut() else {
            return Level {
                locals: false,
                modal: false,
            };
        };
        if modal {
            m.in_modal += 1;
        }
        let level = Level {
            locals: locals.is_some(),
            modal,
        };
        if let Some(locals) = locals {
            m.state.vars.push_level(*locals);
        }
        level
    }

    /// Leave what [`Interp::enter_call`] entered.
    pub(super) fn leave_call(&mut self, level: Level) {
        if let Some(m) = self.macros.as_mut() {
            if level.locals {
                m.state.vars.pop_level();
            }
            if level.modal {
                m.in_modal -= 1;
            }
        }
    }

    /// The `sub` line of `LinuxCNC` subroutine `label` in O program `index` of `program`.
    pub(super) fn o_sub_line(
        &self,
        program: &Program,
        index: usize,
        label: &macro_b::OLabel,
    ) -> Option<usize> {
        let m = self.macros.as_ref()?;
        m.programs[m.base_of(program)? + index].o_words().sub(label)
    }

    /// The `sub` line of `LinuxCNC` subroutine `label` in the first O program of `program`
    /// (a file of the library), its structure prepared the first time.
    pub(super) fn o_sub_in_file(
        &mut self,
        program: &Program,
        label: &macro_b::OLabel,
    ) -> Result<Option<usize>, Diagnostic> {
        let Some(m) = self.macros.as_mut() else {
            return Ok(None);
        };
        let base = m.base(program).map_err(diagnostic)?;
        Ok(m.programs.get(base).and_then(|p| p.o_words().sub(label)))
    }

    /// The locals of a `LinuxCNC` call without arguments: the caller's #1…#30.
    pub(super) fn o_call_locals(&self) -> Option<Box<Locals>> {
        let m = self.macros.as_ref()?;
        let mut locals: Locals = [Value::VACANT; 33];
        for (n, slot) in locals.iter_mut().enumerate().take(30) {
            *slot = m.state.vars.local(n + 1);
        }
        Some(Box::new(locals))
    }

    /// Custom macro B's variables, when it is on.
    pub(super) fn variables(&self) -> Option<&macro_b::Variables> {
        self.macros.as_ref().map(|m| &m.state.vars)
    }

    /// The modal call state, when custom macro B is on.
    pub(super) fn calls(&self) -> Option<Calls> {
        self.macros.as_ref().map(|m| Calls {
            modal: m.modal.clone(),
            in_modal: m.in_modal,
        })
    }

    /// Whether the modal call state is still `calls` (compared in place, nothing copied).
    pub(super) fn calls_are(&self, calls: Option<&Calls>) -> bool {
        match (self.macros.as_ref(), calls) {
            (Some(m), Some(c)) => m.modal == c.modal && m.in_modal == c.in_modal,
            (None, None) => true,
            _ => false,
        }
    }

    /// The value of `#n` for a message, without noting it as read: a local or common
    /// variable as it is, a system variable as the machine answers (`None` if it cannot).
    pub(super) fn value_for_message(&mut self, n: u32, span: Span) -> Option<Value> {
        let mut m = self.macros.take()?;
        let value = match m.state.vars.peek(n) {
            Some(v) => Some(v),
            None => {
                let options = m.state.options;
                let sys = &mut Sys { it: self, span };
                m.state.vars.read(i64::from(n), span, &options, sys).ok()
            }
        };
        self.macros = Some(m);
        value
    }

    /// The alarm of the block budget: it names the loop last jumped back to, if any.
    pub(super) fn budget_alarm(&self, span: Span, program: &Program) -> Diagnostic {
        let max = self.opts.max_blocks;
        let help = "the loop's exit condition never holds (or M98 repeats and M99 jumps never end); correct it, or raise --max-steps if the program really runs this long";
        // the loop is named when it lies in the program that was running (its file's slots)
        let in_program = |m: &Macros, (p, l): (usize, usize)| {
            let local = p.checked_sub(m.base_of(program)?)?;
            program
                .programs
                .get(local)?
                .blocks
                .get(l)
                .map(|_| (local, l))
        };
        match self.macros.as_ref().and_then(|m| {
            let last = m.last_loop?;
            in_program(m, last).map(|local| (m, last, local))
        }) {
            Some((m, (p, l), (local, _))) => {
                let head = program.programs[local].blocks.at(l);
                alarm(
                    head.span,
                    "LS-LOOP",
                    format!(
                        "more than {max} blocks executed: the loop at line {} ran {} times and does not end",
                        head.span.line, m.iterations[p][l]
                    ),
                    help,
                )
            }
            None => alarm(
                span,
                "LS-LOOP",
                format!("more than {max} blocks executed: the program does not end"),
                help,
            ),
        }
    }
}
