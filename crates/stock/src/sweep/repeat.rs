//! Passes that repeat: a move whose points each moved a little along their own line since
//! an earlier move of the same tool, found among the last few (a thread's passes, each a
//! little deeper; a zig-zag's feeds), so that it can sweep from where the run of such
//! passes began and fill the notches between them.

use super::emit::unit;
use super::run::Run;
use super::thread::ToolKey;
use super::SweepBuilder;
use crate::outline::Outline;
use crate::tools::hint_key;
use geom::flat::{convex_hull, P};

/// Moves remembered to find the one a move repeats ([`Repeats::repeats`]): a thread pass
/// and its pull-out chamfer are two moves, a zig-zag's pass two feeds.
const RECENT_PASSES: usize = 4;

/// How far a pass's stamp may lie off the line its run of passes moves along, mm (the
/// coordinates of a pass written to 0.0001 mm and halved into the radius, computed).
const OFF_LINE: f64 = 1e-6;

/// Repeated passes of one move: its points in the first pass and in the last.
struct PassRun {
    key: ToolKey,
    first: Vec<P>,
    last: Vec<P>,
}

/// The runs of the last few moves of one kind, the newest last.
#[derive(Default)]
pub(super) struct Repeats {
    recent: Vec<PassRun>,
}

impl Repeats {
    /// Where the passes this move repeats began, when it repeats the latest remembered
    /// move of tool `key` with as many points: each of its points `at` a step `w` from that
    /// move's that `accept(w)` takes, and on the line from where their run of passes began
    /// (within [`OFF_LINE`], moving on); `None` when it repeats none. Every point of the
    /// run then moves along its own line, each pass at most an accepted step from the last,
    /// so what the outline sweeps between `first` and `at` lies between two consecutive
    /// passes (a thread's stamps: [`super::notch::notch_depth`]; a feed's segment: a strip
    /// ruled by them). Off that line, the run starts again from the move it repeats.
    pub(super) fn repeats(
        &mut self,
        key: ToolKey,
        at: &[P],
        mut accept: impl FnMut(P) -> bool,
    ) -> Option<Vec<P>> {
        let mut near = |a: &P, b: &P| accept([b[0] - a[0], b[1] - a[1]]);
        let found = self.recent.iter().rposition(|r| {
            r.key == key
                && r.last.len() == at.len()
                && r.last.iter().zip(at).all(|(a, b)| near(a, b))
        });
        let Some(i) = found else {
            if self.recent.len() == RECENT_PASSES {
                self.recent.remove(0);
            }
            let (first, last) = (at.to_vec(), at.to_vec());
            self.recent.push(PassRun { key, first, last });
            return None;
        };
        let mut run = self.recent.remove(i);
        let on = (0..at.len()).all(|j| moves_on(run.first[j], run.last[j], at[j]));
        if !on {
            run.first = std::mem::take(&mut run.last);
        }
        run.last = at.to_vec();
        let first = run.first.clone();
        self.recent.push(run);
        Some(first)
    }
}

fn dist(a: P, b: P) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Whether `p` lies on the line from `first` through `last` (within [`OFF_LINE`]), not
/// behind `last` (`last == first`: any `p`).
fn moves_on(first: P, last: P, p: P) -> bool {
    let len = dist(first, last);
    if len == 0.0 {
        return true;
    }
    let u = [(last[0] - first[0]) / len, (last[1] - first[1]) / len];
    let v = [p[0] - first[0], p[1] - first[1]];
    let along = v[0] * u[0] + v[1] * u[1];
    let off = (v[1] * u[0] - v[0] * u[1]).abs();
    off <= OFF_LINE && along >= len - OFF_LINE
}

impl SweepBuilder<'_> {
    /// Emits the sweep of the run `run`, a single straight exact feed of a long program
    /// (its pass groups on) that repeats earlier passes of its tool, each end at most
    /// `merge_tol` from where it was in the last, along its own line: the outline swept over
    /// the quadrilateral its segments rule from the first pass to this one. Its points lie
    /// between two consecutive passes' segments, within `merge_tol / 2` of one of them (the
    /// bound of [`crate::pass_group`], whose lanes need equal steps: a zig-zag written to
    /// 0.0001 mm steps unevenly and its passes never group). Each pass's sweep then covers
    /// the last, and the notches the ends of such passes leave (3·10⁻⁶ mm at each end of a
    /// zig-zag, 82 000 vertices at 10⁵ moves) are filled. False, emitting nothing, when it
    /// repeats none, or the quadrilateral would not be convex.
    pub(super) fn emit_repeated_feed(&mut self, outline: &Outline, run: &Run) -> bool {
        let limit = self.merge_tol;
        let path = &run.path;
        if self.groups.is_none() || path.len() != 2 || self.with_body(run.tool, run.hint).is_some()
        {
            return false;
        }
        let (a, b) = (path[0], path[1]);
        // long against its steps: the segments rule a strip (no twist)
        if dist(a, b) <= 2.0 * limit {
            return false;
        }
        // either way round: a back-and-forth on one line is one run
        let at = if (a[0], a[1]) <= (b[0], b[1]) {
            [a, b]
        } else {
            [b, a]
        };
        let accept = |w: P| w[0].hypot(w[1]) <= limit * (1.0 + 1e-9);
        let key = hint_key(run.tool, run.hint);
        let Some(first) = self.feed_runs.repeats(key, &at, accept) else {
            return false;
        };
        let quad = [first[0], first[1], at[1], at[0]];
        if first[..] == at[..] || !convex(&quad) {
            return false;
        }
        let region = convex_hull(&quad);
        self.emit_ruled(
            run.last,
            outline,
            &region,
            (a, unit([b[0] - a[0], b[1] - a[1]])),
        );
        true
    }
}

/// Whether the quadrilateral `q` is convex (turning one way at every corner, or not at
/// all: a side may shrink to a point).
fn convex(q: &[P; 4]) -> bool {
    let turn = |k: usize| {
        let (o, p, r) = (q[k], q[(k + 1) % 4], q[(k + 2) % 4]);
        (p[0] - o[0]) * (r[1] - p[1]) - (p[1] - o[1]) * (r[0] - p[0])
    };
    let turns = [turn(0), turn(1), turn(2), turn(3)];
    turns.iter().all(|&t| t >= 0.0) || turns.iter().all(|&t| t <= 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    const KEY: ToolKey = (1, 0, 0);

    /// Steps of at most `step` (with the slack of a step written to 0.001 mm).
    fn upto(step: f64) -> impl FnMut(P) -> bool {
        move |w| w[0].hypot(w[1]) <= step * (1.0 + 1e-9)
    }

    /// A pass stamped at `z` (three stamps) and radius `r`.
    fn pass(z: f64, r: f64) -> Vec<P> {
        vec![[z, r], [z - 1.5, r], [z - 3.0, r]]
    }

    /// A run of passes along one line is swept from its first pass; a pass off the line, or
    /// further than the step from the last, starts again.
    #[test]
    fn a_run_of_passes_is_swept_from_where_it_began() {
        let mut t = Repeats::default();
        assert_eq!(t.repeats(KEY, &pass(0.0, 8.5), upto(0.0005)), None);
        assert_eq!(
            t.repeats(KEY, &pass(0.0, 8.4995), upto(0.0005)),
            Some(pass(0.0, 8.5))
        );
        assert_eq!(
            t.repeats(KEY, &pass(0.0, 8.499), upto(0.0005)),
            Some(pass(0.0, 8.5))
        );
        // off the run's line (a flank infeed's step): from the pass it repeats
        let off = pass(-0.0003, 8.4986);
        assert_eq!(t.repeats(KEY, &off, upto(0.0005)), Some(pass(0.0, 8.499)));
        // a step of 0.05 mm: stamped on its own
        assert_eq!(t.repeats(KEY, &pass(-0.0003, 8.45), upto(0.0005)), None);
        // another tool, or no step taken: never
        assert_eq!(
            t.repeats((2, 0, 0), &pass(-0.0003, 8.45), upto(0.0005)),
            None
        );
        assert_eq!(t.repeats(KEY, &pass(-0.0003, 8.45), |_| false), None);
    }

    /// A pass of two moves (a thread and its chamfer): each move repeats its own.
    #[test]
    fn each_move_of_a_pass_repeats_its_own() {
        let mut t = Repeats::default();
        let chamfer = |r: f64| vec![[-3.0, r], [-3.5, r + 0.5]];
        for k in 0..3 {
            let r = 8.5 - 0.0005 * f64::from(k);
            let (a, b) = (
                t.repeats(KEY, &pass(0.0, r), upto(0.0005)),
                t.repeats(KEY, &chamfer(r), upto(0.0005)),
            );
            assert_eq!(a, (k > 0).then(|| pass(0.0, 8.5)));
            assert_eq!(b, (k > 0).then(|| chamfer(8.5)));
        }
    }
}
