//! Program flow: the block loop of one O program, subprogram calls (M98) and returns
//! (M99, M99 P), the end of the program (M02/M30), and the block budget that ends
//! endless loops. Macro B's GOTO/WHILE/IF will live here too.

use super::modal::After;
use super::{alarm, Exit, Flow, Interp, MAX_NESTING};
use crate::words::Words;
use crate::Diagnostic;
use gcode::Program;

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
                return Err(alarm(
                    b.span,
                    "LS-LOOP",
                    format!(
                        "more than {} blocks executed: the program does not end",
                        self.opts.max_blocks
                    ),
                    "check M98 repeat counts and M99 jumps for an endless loop",
                ));
            }
            match self.block(&program.programs[index], i)? {
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
                                i = target;
                                continue 'blocks;
                            }
                        }
                    }
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

    /// The M codes that act after the motion: spindle stop, coolant off, program end,
    /// subprogram call and return. `None` leaves the block's flow as it is.
    pub(super) fn m_words_after(
        &mut self,
        after: &After,
        used: &mut Words,
    ) -> Result<Option<Flow>, Diagnostic> {
        let mut flow = None;
        for &(m, w) in after {
            match m {
                5 => self.spindle_on = false,
                9 => {}
                2 | 30 => flow = Some(Flow::End),
                98 => {
                    let p = used.take('P').ok_or_else(|| {
                        alarm(
                            w.span,
                            "PS078",
                            "M98 without P",
                            "write M98 P<program number>, e.g. M98 P1234",
                        )
                    })?;
                    if p.has_point || p.value < 1.0 || p.value > 99_999_999.0 {
                        return Err(alarm(p.span, "PS078", "M98 P needs a program number", "P is [repeat count (4 digits)] + program number (4 digits), e.g. P30010"));
                    }
                    let v = p.value as u32;
                    let (mut times, number) = if v > 9999 {
                        (v / 10000, v % 10000)
                    } else {
                        (1, v)
                    };
                    if let Some(l) = used.take('L') {
                        if l.has_point || l.value < 1.0 || l.value > 9999.0 {
                            return Err(alarm(
                                l.span,
                                "LS-VALUE",
                                "L must be a repeat count 1 … 9999",
                                "write e.g. L3",
                            ));
                        }
                        times = l.value as u32;
                    }
                    flow = Some(Flow::Call {
                        number,
                        times: times.max(1),
                        span: w.span,
                    });
                }
                99 => {
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
                    flow = Some(Flow::Return { seq, span: w.span });
                }
                _ => {}
            }
        }
        Ok(flow)
    }
}
