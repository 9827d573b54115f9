//! Program flow: running an O program block by block, subprogram calls (M98), returns
//! (M99) and the program end (M02/M30). Macro B statements and G65 run through
//! `macros.rs` (`Interp::step`).

use super::{alarm, Interp};
use crate::words::{whole_in, Words};
use crate::{Diagnostic, Span};
use gcode::{Program, Word};

/// FANUC's subprogram nesting limit.
const MAX_NESTING: u32 = 4;

/// How an O program was left.
pub(super) enum Exit {
    End,
    Return(Option<u32>),
}

/// Where execution goes after a block.
pub(super) enum Flow {
    Next,
    End,
    Call {
        number: u32,
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
        let mut i = start;
        'blocks: while i < blocks.len() {
            let b = &blocks[i];
            if b.block_delete && self.opts.block_delete {
                i += 1;
                continue;
            }
            self.out.blocks += 1;
            if self.out.blocks > self.opts.max_blocks {
                return Err(self.budget_alarm(b.span, program));
            }
            match self.step(program, index, i)? {
                Flow::Next => i += 1,
                Flow::Jump(j) => i = j,
                Flow::End => return Ok(Exit::End),
                Flow::Return { seq, span } => {
                    if depth == 0 {
                        return Err(alarm(
                            span,
                            "LS-M99-MAIN",
                            "M99 in the main program would repeat it endlessly",
                            "end the main program with M30 (or M02); M99 belongs at the end of a subprogram",
                        ));
                    }
                    return Ok(Exit::Return(seq));
                }
                Flow::Call {
                    number,
                    times,
                    span,
                    locals,
                } => {
                    let Some(sub) = program
                        .programs
                        .iter()
                        .position(|p| p.number == Some(number))
                    else {
                        return Err(alarm(
                            span,
                            "PS078",
                            format!("subprogram O{number:04} not found in this file"),
                            "add the subprogram after M30 in the same file, starting with its O number",
                        ));
                    };
                    if depth + 1 > MAX_NESTING {
                        return Err(alarm(
                            span,
                            "PS077",
                            format!("subprogram calls nested deeper than {MAX_NESTING} levels (a subprogram calling itself?)"),
                            "remove the recursive M98 call or flatten the nesting",
                        ));
                    }
                    let level = self.enter_call(locals);
                    for _ in 0..times {
                        match self.run(program, sub, 0, depth + 1)? {
                            Exit::End => return Ok(Exit::End),
                            Exit::Return(None) => {}
                            Exit::Return(Some(seq)) => {
                                let Some(target) = blocks.iter().position(|x| x.seq == Some(seq))
                                else {
                                    return Err(alarm(
                                        span,
                                        "PS078",
                                        format!("M99 P{seq} returns to N{seq}, which the calling program does not have"),
                                        "give the block to return to that sequence number",
                                    ));
                                };
                                self.leave_call(level);
                                i = target;
                                continue 'blocks;
                            }
                        }
                    }
                    self.leave_call(level);
                    i += 1;
                }
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

    /// The M codes that act after the motion: M05, M09, the program end, M98 and M99.
    pub(super) fn m_codes_after(
        &mut self,
        after: &[(u32, &Word)],
        used: &mut Words,
        mut flow: Flow,
    ) -> Result<Flow, Diagnostic> {
        for &(m, w) in after {
            match m {
                5 => self.spindle_on = false,
                9 => {}
                2 | 30 => flow = Flow::End,
                98 => flow = m98(w, used)?,
                99 => flow = m99(w, used)?,
                _ => {}
            }
        }
        Ok(flow)
    }
}

/// M98 P[count]number [L count]: the call.
fn m98(w: &Word, used: &mut Words) -> Result<Flow, Diagnostic> {
    let p = used.take('P').ok_or_else(|| {
        alarm(
            w.span,
            "PS078",
            "M98 without P",
            "write M98 P<program number>, e.g. M98 P1234",
        )
    })?;
    if !whole_in(p, 1.0, 99_999_999.0) {
        return Err(alarm(
            p.span,
            "PS078",
            "M98 P needs a program number",
            "P is [repeat count (4 digits)] + program number (4 digits), e.g. P30010",
        ));
    }
    let v = p.value as u32;
    let (mut times, number) = if v > 9999 {
        (v / 10000, v % 10000)
    } else {
        (1, v)
    };
    if let Some(l) = used.take('L') {
        if !whole_in(l, 1.0, 9999.0) {
            return Err(alarm(
                l.span,
                "LS-VALUE",
                "L must be a repeat count 1 … 9999",
                "write e.g. L3",
            ));
        }
        times = l.value as u32;
    }
    Ok(Flow::Call {
        number,
        times: times.max(1),
        span: w.span,
        locals: None,
    })
}

/// M99 [P sequence]: the return, to the block after the call or to N<P>.
fn m99(w: &Word, used: &mut Words) -> Result<Flow, Diagnostic> {
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
    Ok(Flow::Return { seq, span: w.span })
}
