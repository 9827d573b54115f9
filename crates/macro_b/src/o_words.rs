//! The structure of `LinuxCNC`'s o-words in one program ([O] in docs/linuxcnc.md): every
//! `sub`, `if`, `while`, `do` and `repeat` matched with the lines that continue and close
//! it by label, checked before anything runs. Control-flow labels are local to the
//! subroutine they stand in (a block nests inside the one opened before it); subroutine
//! labels are the file's.

use crate::error::{ErrorKind, MacroError, Result};
use crate::expr::{OKeyword, OLabel, StmtKind};
use crate::flow::Line;
use crate::span::Span;

/// Where an o-word's block opens, goes on and closes (line indices of its program).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OLink {
    /// The opening line: `sub`, `if`, `while`, `do` or `repeat`.
    pub head: usize,
    /// The next line of an `if` chain (`elseif`, `else`, `endif`); else `end`.
    pub next: usize,
    /// The closing line: `endsub`, `endif`, `endwhile`, the `while` of a `do`, `endrepeat`.
    pub end: usize,
}

/// The o-word structure of a program: each o-word line's link, and the subroutines.
#[derive(Debug, Clone, Default)]
pub struct OStructure {
    links: Vec<Option<OLink>>,
    subs: Vec<(OLabel, usize)>,
}

impl OStructure {
    /// The link of o-word line `line` (`call` has none).
    pub fn link(&self, line: usize) -> Option<OLink> {
        self.links.get(line).copied().flatten()
    }

    /// The `sub` line of subroutine `label`.
    pub fn sub(&self, label: &OLabel) -> Option<usize> {
        self.subs.iter().find(|(l, _)| l == label).map(|&(_, i)| i)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Sub,
    If,
    While,
    Do,
    Repeat,
}

/// A block opened and not yet closed.
struct Open {
    label: OLabel,
    kind: Kind,
    line: usize,
    /// `elseif`/`else` lines of an `if`; `break`, `continue`, `return` lines inside.
    members: Vec<usize>,
    /// An `if`'s `else` is written.
    has_else: bool,
}

fn error(span: Span, message: String, help: &str) -> MacroError {
    MacroError::new(ErrorKind::OWordStructure, span, message, help)
}

/// Match the o-words of `lines`.
pub(crate) fn structure<B>(lines: &[Line<B>]) -> Result<OStructure> {
    let mut s = OStructure {
        links: vec![None; lines.len()],
        subs: vec![],
    };
    let mut open: Vec<Open> = vec![];
    for (i, line) in lines.iter().enumerate() {
        let crate::flow::Body::Stmt(stmt) = &line.body else {
            continue;
        };
        let StmtKind::OWord { label, keyword, .. } = &stmt.kind else {
            continue;
        };
        word(&mut s, &mut open, (i, line.span), label, *keyword)?;
    }
    if let Some(o) = open.last() {
        let close = match o.kind {
            Kind::Sub => "endsub",
            Kind::If => "endif",
            Kind::While => "endwhile",
            Kind::Do => "while [ … ]",
            Kind::Repeat => "endrepeat",
        };
        return Err(error(
            lines[o.line].span,
            format!("{} {} without {} {close}", o.label, name(o.kind), o.label),
            "close the block with the same label",
        ));
    }
    Ok(s)
}

fn name(kind: Kind) -> &'static str {
    match kind {
        Kind::Sub => "sub",
        Kind::If => "if",
        Kind::While => "while",
        Kind::Do => "do",
        Kind::Repeat => "repeat",
    }
}

fn push(open: &mut Vec<Open>, label: &OLabel, kind: Kind, line: usize) {
    open.push(Open {
        label: label.clone(),
        kind,
        line,
        members: vec![],
        has_else: false,
    });
}

/// One o-word line `i` at `span`.
fn word(
    s: &mut OStructure,
    open: &mut Vec<Open>,
    (i, span): (usize, Span),
    label: &OLabel,
    keyword: OKeyword,
) -> Result<()> {
    use OKeyword as K;
    match keyword {
        K::Sub => {
            if let Some(o) = open.iter().find(|o| o.kind == Kind::Sub) {
                return Err(error(
                    span,
                    format!("{label} sub inside the definition of {}", o.label),
                    "subroutine definitions do not nest: define it after the other's endsub",
                ));
            }
            if s.sub(label).is_some() {
                return Err(error(
                    span,
                    format!("{label} sub is defined twice"),
                    "give each subroutine its own number or name",
                ));
            }
            s.subs.push((label.clone(), i));
            push(open, label, Kind::Sub, i);
        }
        K::If => push(open, label, Kind::If, i),
        K::Do => push(open, label, Kind::Do, i),
        K::Repeat => push(open, label, Kind::Repeat, i),
        K::While if top_is(open, label, Kind::Do) => close(s, open, i),
        K::While => push(open, label, Kind::While, i),
        K::ElseIf | K::Else => {
            let what = keyword.name();
            let Some(o) = open
                .last_mut()
                .filter(|o| o.kind == Kind::If && o.label == *label)
            else {
                return Err(error(
                    span,
                    format!("{label} {what} without an open {label} if"),
                    "elseif and else stand between an if and its endif with the same label",
                ));
            };
            if o.has_else {
                return Err(error(
                    span,
                    format!("{label} {what} after {label} else"),
                    "else is the last branch before endif",
                ));
            }
            o.has_else = keyword == K::Else;
            o.members.push(i);
        }
        K::EndSub => expect_close(s, open, (i, span), label, Kind::Sub, "endsub")?,
        K::EndIf => expect_close(s, open, (i, span), label, Kind::If, "endif")?,
        K::EndWhile => expect_close(s, open, (i, span), label, Kind::While, "endwhile")?,
        K::EndRepeat => expect_close(s, open, (i, span), label, Kind::Repeat, "endrepeat")?,
        K::Return => member(open, (i, span), label, &[Kind::Sub], "return")?,
        K::Break | K::Continue => member(
            open,
            (i, span),
            label,
            &[Kind::While, Kind::Do, Kind::Repeat],
            keyword.name(),
        )?,
        K::Call => {}
    }
    Ok(())
}

fn top_is(open: &[Open], label: &OLabel, kind: Kind) -> bool {
    open.last()
        .is_some_and(|o| o.kind == kind && o.label == *label)
}

/// A closing line `i`: it must close the innermost open block, of `kind` and `label`.
fn expect_close(
    s: &mut OStructure,
    open: &mut Vec<Open>,
    (i, span): (usize, Span),
    label: &OLabel,
    kind: Kind,
    what: &str,
) -> Result<()> {
    if top_is(open, label, kind) {
        close(s, open, i);
        return Ok(());
    }
    let message = match open.last() {
        Some(o) if open.iter().any(|p| p.kind == kind && p.label == *label) => format!(
            "{label} {what} while {} {} is still open: blocks must not cross",
            o.label,
            name(o.kind)
        ),
        _ => format!("{label} {what} without {label} {}", name(kind)),
    };
    Err(error(
        span,
        message,
        "open and close each block with the same label, the inner one closed first",
    ))
}

/// Close the innermost open block at line `end`: link its head, branches and members.
fn close(s: &mut OStructure, open: &mut Vec<Open>, end: usize) {
    let o = open.pop().expect("a block is open");
    let head = o.line;
    let link = |next| Some(OLink { head, next, end });
    if o.kind == Kind::If {
        let mut chain = vec![head];
        chain.extend(&o.members);
        chain.push(end);
        for w in chain.windows(2) {
            s.links[w[0]] = link(w[1]);
        }
    } else {
        s.links[head] = link(end);
        for &m in &o.members {
            s.links[m] = link(end);
        }
    }
    s.links[end] = link(end);
}

/// A `return`, `break` or `continue` at line `i`: a member of the innermost open block
/// of one of `kinds` with its label (inside the subroutine it stands in).
fn member(
    open: &mut [Open],
    (i, span): (usize, Span),
    label: &OLabel,
    kinds: &[Kind],
    what: &str,
) -> Result<()> {
    let found = open
        .iter_mut()
        .rev()
        .take_while(|o| o.kind != Kind::Sub || kinds.contains(&Kind::Sub))
        .find(|o| kinds.contains(&o.kind) && o.label == *label);
    match found {
        Some(o) => {
            o.members.push(i);
            Ok(())
        }
        None => Err(error(
            span,
            format!("{label} {what} outside {label}'s block"),
            if what == "return" {
                "return stands inside the sub … endsub with its label"
            } else {
                "break and continue stand inside the while, do or repeat loop with their label"
            },
        )),
    }
}
