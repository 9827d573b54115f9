//! A tool with no entry, taken for what its moves say it is. A tool that only cuts thread
//! passes (G32, G92, G76) is a threading insert, not the 55° turning default: that default
//! cut a 96° thread and scraped the flank at every pull-out (field run 4, 5d). Its side is
//! the side its passes come in from: from outside the thread (an OD insert) or from the
//! bore (an ID one). Its size is a guess all the same, so its findings stay possible ones
//! (spec/simulation.md, "Findings from assumed tools"; docs/field-rules.md §17).
//!
//! The program is not expanded again: the interpreter has compensated the tool as one with
//! no entry (the default nose), which only a thread pass under G41/G42 would show, and the
//! thread cycles cut their passes without compensation.

use super::{ThreadSide, Tool, ToolTable};
use expander::{Motion, Segment};

/// A tool with no entry whose every cutting move is a thread pass.
#[derive(Debug, Clone, PartialEq)]
pub struct ThreadFromUse {
    /// The T number.
    pub t: u32,
    /// The side its passes come in from.
    pub side: ThreadSide,
    /// The index of its first thread move.
    pub first: usize,
}

impl ThreadFromUse {
    /// The threading insert it is taken for: 60° (metric and unified threads), sharp.
    pub fn tool(&self) -> Tool {
        Tool::Threading {
            angle: 60.0,
            tip_flat: 0.0,
            side: self.side,
        }
    }
}

/// What the moves of one tool with no entry say.
struct Tally {
    t: u32,
    first: usize,
    /// Feeds other than thread passes.
    feeds: usize,
    /// Thread runs entered from outside the thread (+) or from inside it (−), and left the
    /// same way.
    outside: i64,
}

impl ToolTable {
    /// The tools with no entry (and a T word: tool 0 is the table's first entry) whose
    /// cutting moves in `segments` are all thread passes.
    pub fn threads_from_use(&self, segments: &[Segment]) -> Vec<ThreadFromUse> {
        let mut tallies: Vec<Tally> = vec![];
        for (i, s) in segments.iter().enumerate() {
            if s.motion == Motion::Rapid || s.tool == 0 || self.get(s.tool).is_some() {
                continue;
            }
            let k = match tallies.iter().position(|t| t.t == s.tool) {
                Some(k) => k,
                None => {
                    tallies.push(Tally {
                        t: s.tool,
                        first: i,
                        feeds: 0,
                        outside: 0,
                    });
                    tallies.len() - 1
                }
            };
            let tally = &mut tallies[k];
            if s.motion == Motion::Feed {
                tally.feeds += 1;
                continue;
            }
            // a thread run's ends: the move that brought the tool in, and the one out
            let r = s.from.r;
            if let Some(p) = i.checked_sub(1).map(|j| &segments[j]) {
                if p.motion != Motion::Thread {
                    tally.outside += side_of(p.from.r - r);
                }
            }
            if let Some(n) = segments.get(i + 1).filter(|n| n.motion != Motion::Thread) {
                tally.outside += side_of(n.to.r - s.to.r);
            }
        }
        tallies
            .into_iter()
            .filter(|t| t.feeds == 0)
            .map(|t| ThreadFromUse {
                t: t.t,
                // a thread that says nothing of its side is an outside one, the usual
                side: if t.outside < 0 {
                    ThreadSide::Id
                } else {
                    ThreadSide::Od
                },
                first: t.first,
            })
            .collect()
    }

    /// The table with the tools `found` taken for threading inserts: still no entries
    /// ([`ToolTable::get`] has none of them, their size is not stated), but what cuts
    /// for them ([`ToolTable::outline_for`], [`ToolTable::tool_or_default`]).
    pub fn with_threads_from_use(&self, found: &[ThreadFromUse]) -> Self {
        let mut out = self.clone();
        out.by_use.extend(found.iter().map(|f| (f.t, f.tool())));
        out
    }
}

/// +1 when `dr` (a move's radial travel away from the thread) is outward, −1 inward.
fn side_of(dr: f64) -> i64 {
    if dr > 1e-9 {
        1
    } else if dr < -1e-9 {
        -1
    } else {
        0
    }
}
