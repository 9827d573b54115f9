//! `LinuxCNC`'s o-words run ([O] in docs/linuxcnc.md), on the structure `macro_b` matched
//! before the run ([`macro_b::OStructure`]): a `sub` met in the flow is skipped to after
//! its `endsub`; `call` runs the blocks after the `sub` on a new local level holding the
//! caller's #1…#30 with the arguments over them; `endsub`/`return` return, their value in
//! `#<_value>`; `if`/`elseif`/`else` choose one branch; `while`, `do … while` and `repeat`
//! loop, `break` and `continue` leave or go round. Every jump back is a jump of the block
//! loop, so the loop guard (issue 37) watches it like a `GOTO`.

use super::super::flow::{Callee, Flow};
use super::Macros;
use crate::Span;
use macro_b::{Expr, Locals, MacroError, OKeyword, OLabel, OLink, StmtKind, System, Value};

/// The name of the hidden counter of the `repeat` at line `line` of O program `index`
/// (the call level's own: a name with blanks cannot be written in a program).
fn counter(index: usize, line: usize) -> String {
    format!(" repeat {index} {line}")
}

/// An o-word, what it does and where it stands.
pub(in crate::interp) struct OWord<'a> {
    pub(in crate::interp) label: &'a OLabel,
    pub(in crate::interp) keyword: OKeyword,
    pub(in crate::interp) args: &'a [Expr],
    pub(in crate::interp) span: Span,
}

impl Macros {
    /// Run o-word `w` at line `i` of O program `index`: where the block loop goes next.
    pub(in crate::interp) fn o_word(
        &mut self,
        (index, i): (usize, usize),
        w: &OWord<'_>,
        sys: &mut dyn System,
    ) -> Result<Flow, MacroError> {
        use OKeyword as K;
        let link = self.programs[index].o_words().link(i);
        let link = || link.expect("an o-word block is matched when prepared");
        Ok(match w.keyword {
            K::Call => self.o_call(index, w, sys)?,
            K::Sub => Flow::Jump(link().end + 1),
            K::EndSub | K::Return => {
                if let Some(v) = w.args.first() {
                    let v = self.state.eval(v, sys)?;
                    self.state.vars.write_named("_value", v);
                    self.state
                        .vars
                        .write_named("_value_returned", Value::num(1.0));
                }
                Flow::Return {
                    seq: None,
                    span: w.span,
                }
            }
            K::If => self.o_if(index, link(), &w.args[0], sys)?,
            K::ElseIf | K::Else => Flow::Jump(link().end + 1),
            K::EndIf | K::Do => Flow::Next,
            K::While if link().head == i => {
                if self.state.condition(&w.args[0], sys)? {
                    Flow::Next
                } else {
                    Flow::Jump(link().end + 1)
                }
            }
            // the `while` that closes a `do`
            K::While => {
                if self.state.condition(&w.args[0], sys)? {
                    self.back_jump(index, link().head);
                    Flow::Jump(link().head)
                } else {
                    Flow::Next
                }
            }
            K::EndWhile => {
                self.back_jump(index, link().head);
                Flow::Jump(link().head)
            }
            K::Repeat => self.o_repeat(index, i, link(), &w.args[0], sys)?,
            K::EndRepeat => {
                let name = counter(index, link().head);
                let left = self.state.vars.named(&name).map_or(0.0, Value::or_zero) - 1.0;
                if left > 0.0 {
                    self.state.vars.write_named(&name, Value::num(left));
                    self.back_jump(index, link().head);
                    Flow::Jump(link().head + 1)
                } else {
                    self.state.vars.remove_named(&name);
                    Flow::Next
                }
            }
            K::Break => {
                self.state.vars.remove_named(&counter(index, link().head));
                Flow::Jump(link().end + 1)
            }
            K::Continue => {
                let head = link().head;
                if self.head_keyword(index, head) == Some(K::While) {
                    self.back_jump(index, head);
                    Flow::Jump(head)
                } else {
                    // `do … while` tests at its end; `endrepeat` counts
                    Flow::Jump(link().end)
                }
            }
        })
    }

    /// The keyword of o-word line `line`.
    fn head_keyword(&self, index: usize, line: usize) -> Option<OKeyword> {
        match &self.programs[index].lines().get(line)?.body {
            macro_b::Body::Stmt(s) => match &s.kind {
                StmtKind::OWord { keyword, .. } => Some(*keyword),
                _ => None,
            },
            macro_b::Body::Block(()) => None,
        }
    }

    /// `if [c]`: its branch when `c` holds, else the first `elseif` whose condition
    /// holds, else the `else` branch, else after `endif`.
    fn o_if(
        &mut self,
        index: usize,
        link: OLink,
        cond: &Expr,
        sys: &mut dyn System,
    ) -> Result<Flow, MacroError> {
        if self.state.condition(cond, sys)? {
            return Ok(Flow::Next);
        }
        let mut at = link.next;
        while at != link.end {
            let branch = match &self.programs[index].lines()[at].body {
                macro_b::Body::Stmt(s) => match &s.kind {
                    StmtKind::OWord { args, .. } => args.first().cloned(),
                    _ => None,
                },
                macro_b::Body::Block(()) => None,
            };
            match branch {
                // `else`
                None => return Ok(Flow::Jump(at + 1)),
                Some(c) if self.state.condition(&c, sys)? => return Ok(Flow::Jump(at + 1)),
                Some(_) => {}
            }
            at = self.programs[index]
                .o_words()
                .link(at)
                .map_or(link.end, |l| l.next);
        }
        Ok(Flow::Jump(link.end + 1))
    }

    /// `repeat [n]` met from before the loop: n times round (none when n < 1); its
    /// counter is a hidden named parameter of the call level, so the loop guard sees it.
    fn o_repeat(
        &mut self,
        index: usize,
        i: usize,
        link: OLink,
        n: &Expr,
        sys: &mut dyn System,
    ) -> Result<Flow, MacroError> {
        let times = self.state.eval(n, sys)?.or_zero().floor();
        if times < 1.0 {
            return Ok(Flow::Jump(link.end + 1));
        }
        self.state
            .vars
            .write_named(&counter(index, i), Value::num(times));
        Ok(Flow::Next)
    }

    /// `call [a] [b] …`: the blocks after the subroutine's `sub` (in this file, else in the
    /// file named after it) on a new local level:
    /// the caller's #1…#30 with the arguments over them (`LinuxCNC` restores #1…#30 on
    /// return; the level's named parameters start empty). `#<_value>` is cleared first.
    fn o_call(
        &mut self,
        index: usize,
        w: &OWord<'_>,
        sys: &mut dyn System,
    ) -> Result<Flow, MacroError> {
        let sub = self.programs[index].o_words().sub(w.label);
        let mut locals: Locals = [Value::VACANT; 33];
        for (n, slot) in locals.iter_mut().enumerate().take(30) {
            *slot = self.state.vars.local(n + 1);
        }
        for (slot, a) in locals.iter_mut().zip(w.args) {
            *slot = self.state.eval(a, sys)?;
        }
        self.state.vars.write_named("_value", Value::num(0.0));
        self.state
            .vars
            .write_named("_value_returned", Value::num(0.0));
        Ok(Flow::Call {
            // not in this file: LinuxCNC's `name.ngc` on its SUBROUTINE_PATH
            callee: sub.map_or_else(|| Callee::SubFile(w.label.clone()), |s| Callee::At(s + 1)),
            times: 1,
            span: w.span,
            locals: Some(Box::new(locals)),
        })
    }
}
