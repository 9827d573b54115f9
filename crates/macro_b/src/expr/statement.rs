//! Macro statements: assignments, IF/GOTO/THEN, WHILE/DO/END, block-form IF.

use super::ast::*;
use super::lexer::{Tok, Token};
use super::parser::Parser;
use crate::error::{ErrorKind, MacroError, Result};
use crate::options::{Dialect, Options};

impl Parser<'_> {
    pub(super) fn assignment(&mut self) -> Result<Stmt> {
        let start = self.peek_n(0)?.start;
        let (target, target_span) = self.var_ref()?;
        if *self.peek()? != Tok::Assign {
            let found = Self::describe(&self.peek()?.clone());
            return Err(self.error_here(
                format!("expected '=' after {target}, found {found}"),
                format!("write {target} = <expression>"),
            ));
        }
        self.bump()?;
        if *self.peek()? == Tok::End {
            return Err(self.error_here(
                format!("{target} = has no value"),
                format!("write a value after '=', or {target} = #0 to make it vacant"),
            ));
        }
        let value = self.expr()?;
        let mut comment = None;
        loop {
            match self.peek()?.clone() {
                Tok::Comment(c) => {
                    self.bump()?;
                    comment.get_or_insert(c);
                }
                Tok::End => break,
                other => {
                    let found = Self::describe(&other);
                    return Err(self.error_here(
                        format!("unexpected {found} after the value of {target}"),
                        "one assignment per block; put operators between values, and a whole expression in brackets",
                    ));
                }
            }
        }
        Ok(Stmt {
            kind: StmtKind::Assign {
                target,
                target_span,
                value,
                comment,
            },
            span: self.span_from(start),
        })
    }

    pub(super) fn statement(&mut self, options: &Options) -> Result<Stmt> {
        let first = self.peek_n(0)?.clone();
        let start = first.start;
        let word = match &first.tok {
            Tok::Hash => return self.assignment(),
            Tok::Word(w) => w.clone(),
            other => {
                let found = Self::describe(other);
                return Err(self.error_here(
                    format!("{found} does not start a macro statement"),
                    "a macro statement is #i = …, IF, WHILE, DO, END or GOTO",
                ));
            }
        };
        if options.dialect == Dialect::LinuxCnc {
            if word == "O" {
                self.bump()?;
                return self.o_word(start);
            }
            return Err(MacroError::new(
                ErrorKind::Unsupported,
                self.span_of(&first),
                format!("{word} is FANUC macro B, not LinuxCNC"),
                "LinuxCNC's flow is o-words: o100 if [c] … o100 endif, o100 while [c] … o100 endwhile, o100 sub … o100 endsub with o100 call",
            ));
        }
        self.bump()?;
        let kind = match word.as_str() {
            "IF" => self.if_statement(options)?,
            "WHILE" | "WH" => self.while_statement(&word, &first, options)?,
            "DO" => {
                let id = self.loop_id("DO")?;
                self.expect_end("the loop number")?;
                StmtKind::Do { id }
            }
            "END" => {
                let id = self.loop_id("END")?;
                self.expect_end("the loop number")?;
                StmtKind::End { id }
            }
            "GOTO" => {
                let target = self.goto_target()?;
                self.expect_end("the GOTO target")?;
                StmtKind::Goto { target }
            }
            "ELSE" => {
                self.expect_end("ELSE")?;
                StmtKind::Else
            }
            "ENDIF" => {
                self.expect_end("ENDIF")?;
                StmtKind::EndIf
            }
            _ => {
                return Err(MacroError::syntax(
                    self.span_of(&first),
                    format!("'{word}' does not start a macro statement"),
                    "a macro statement is #i = …, IF, WHILE, DO, END or GOTO",
                ))
            }
        };
        Ok(Stmt {
            kind,
            span: self.span_from(start),
        })
    }

    /// After `IF`: `[c] GOTO n`, `[c] THEN #i = …`, block-form `[c] THEN`, or (Haas)
    /// `[c] THEN` and an NC block.
    fn if_statement(&mut self, options: &Options) -> Result<StmtKind> {
        let cond = self.condition("IF")?;
        if self.word_is("GOTO")? {
            self.bump()?;
            let target = self.goto_target()?;
            self.expect_end("the GOTO target")?;
            return Ok(StmtKind::IfGoto { cond, target });
        }
        if !self.word_is("THEN")? {
            let found = Self::describe(&self.peek()?.clone());
            return Err(self.error_here(
                format!("expected GOTO or THEN after the IF condition, found {found}"),
                "write IF [cond] GOTO n or IF [cond] THEN #i = …",
            ));
        }
        self.bump()?;
        match self.peek()?.clone() {
            Tok::End | Tok::Comment(_) => {
                self.expect_end("THEN")?;
                Ok(StmtKind::IfBlock { cond })
            }
            Tok::Hash => {
                let inner = self.assignment()?;
                Ok(StmtKind::IfThen {
                    cond,
                    then: Box::new(inner),
                })
            }
            Tok::Word(w) if w == "GOTO" => {
                Err(self.error_here("THEN GOTO is not allowed", "write IF [cond] GOTO n"))
            }
            _ => self.then_nc_block(cond, options),
        }
    }

    /// Haas `IF [c] THEN` followed by an NC block: the rest of the text, run when `c` holds.
    fn then_nc_block(&mut self, cond: Expr, options: &Options) -> Result<StmtKind> {
        let rest_start = self.peek_n(0)?.start;
        let text = self.src.text[rest_start..].trim_end();
        let text_span = self.src.span(rest_start, rest_start + text.len());
        if !options.is_haas() {
            return Err(MacroError::new(
                ErrorKind::Unsupported,
                text_span,
                "IF … THEN with an NC block is a Haas form",
                "on FANUC THEN runs one assignment; use IF [cond] GOTO n around the block",
            ));
        }
        let text = text.to_string();
        self.at = self.src.text.len();
        self.ahead.clear();
        self.last_end = self.src.text.len();
        Ok(StmtKind::IfThenBlock {
            cond,
            text,
            text_span,
        })
    }

    /// After `WHILE` (or Haas `WH`, the keyword `first`): `[c] DO m`.
    fn while_statement(
        &mut self,
        word: &str,
        first: &Token,
        options: &Options,
    ) -> Result<StmtKind> {
        if word == "WH" && !options.is_haas() {
            return Err(MacroError::new(
                ErrorKind::Unsupported,
                self.span_of(first),
                "WH is the Haas short form of WHILE",
                "write WHILE",
            ));
        }
        let cond = self.condition("WHILE")?;
        if !self.word_is("DO")? {
            let found = Self::describe(&self.peek()?.clone());
            return Err(self.error_here(
                format!("expected DO after the WHILE condition, found {found}"),
                "write WHILE [cond] DO1",
            ));
        }
        self.bump()?;
        let id = self.loop_id("DO")?;
        self.expect_end("the loop number")?;
        Ok(StmtKind::While { cond, id })
    }
}

impl Parser<'_> {
    /// A `LinuxCNC` o-word after its `o` ([O] in docs/linuxcnc.md): the label (`100` or
    /// `<name>`), the keyword and its bracketed expressions.
    fn o_word(&mut self, start: usize) -> Result<Stmt> {
        let t = self.bump()?;
        let label = match &t.tok {
            Tok::Num(v, false) if *v <= f64::from(u32::MAX) => OLabel::Number(*v as u32),
            Tok::Name(n) => OLabel::Name(n.clone()),
            other => {
                let found = Self::describe(other);
                return Err(MacroError::syntax(
                    self.span_of(&t),
                    format!("an o-word needs a number or <name>, found {found}"),
                    "write o100 sub or o<name> sub (a computed o[…] label is not read by latsim)",
                ));
            }
        };
        let k = self.bump()?;
        let keyword = match &k.tok {
            Tok::Word(w) => OKeyword::from_word(&w.to_ascii_lowercase()),
            _ => None,
        };
        let Some(keyword) = keyword else {
            let found = Self::describe(&k.tok);
            return Err(MacroError::syntax(
                self.span_of(&k),
                format!("{label} needs a keyword, found {found}"),
                "o-word keywords: sub endsub return call if elseif else endif while endwhile do repeat endrepeat break continue",
            ));
        };
        let (least, most) = keyword.arity();
        let mut args = Vec::new();
        while *self.peek()? == Tok::LBr {
            if args.len() == most {
                return Err(self.error_here(
                    format!(
                        "{label} {} takes at most {most} bracketed value(s)",
                        keyword.name()
                    ),
                    "remove the extra [ … ]",
                ));
            }
            args.push(self.primary()?);
        }
        if args.len() < least {
            return Err(self.error_here(
                format!("{label} {} needs its value in brackets", keyword.name()),
                format!("write {label} {} [ … ]", keyword.name()),
            ));
        }
        self.expect_end(&format!("{label} {}", keyword.name()))?;
        Ok(Stmt {
            kind: StmtKind::OWord {
                label,
                keyword,
                args,
            },
            span: self.span_from(start),
        })
    }
}
