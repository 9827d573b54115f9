//! Thread moves: the outline stamped where the tool passes the section plane, once a lead.

use expander::Segment;
use geom::flat::P;

/// Most stamps one thread move may make before it is swept continuously instead, with a
/// warning (a real thread has a few hundred: 200 mm at 0.5 mm lead is 400; stamps that all
/// overlap their neighbours cost the boolean engine about k², so 4 000 took 10 s).
const MAX_THREAD_STAMPS: usize = 2_000;

/// Thread moves remembered to find the one a move repeats ([`ThreadStamps::repeats`]): a
/// pass of a thread and its pull-out chamfer is two moves, a G76 pass with a chamfer too.
const RECENT_PASSES: usize = 4;

/// How far a pass's stamp may lie off the line its run of passes moves along, mm (the
/// coordinates of a pass written to 0.0001 mm and halved into the radius, computed).
const OFF_LINE: f64 = 1e-6;

/// A tool as mounted under its hint ([`crate::tools::hint_key`]).
pub(super) type ToolKey = (u32, u8, u64);

/// Repeated passes of one thread move: where the first stamped and where the last did.
struct PassRun {
    key: ToolKey,
    first: Vec<P>,
    last: Vec<P>,
}

/// The stamps of thread moves in program order: a pass of several moves (a thread and its
/// pull-out chamfer) is one pass, so where the next stamp falls is carried from one move to
/// the next.
#[derive(Default)]
pub(super) struct ThreadStamps {
    /// After a move the next one continues: where it ended and where the next stamp falls
    /// from there, as a fraction of the lead.
    carry: Option<(P, f64)>,
    /// The runs of the last few thread moves, the newest last.
    recent: Vec<PassRun>,
}

impl ThreadStamps {
    /// Positions of the outline for the thread move `seg` (number `idx`): every lead from
    /// the start, and the end; `None` (with a warning in `warnings`) when the move must be
    /// swept continuously instead (chord tolerance `tol`). When the next move `continues`
    /// the pass (its pull-out chamfer), there is no stamp at this one's end, and the next
    /// one's stamps go on a lead apart: the section sees the tool once a lead, also on the
    /// chamfer, and the joint is no place it stops.
    pub(super) fn stamps(
        &mut self,
        (idx, seg): (usize, &Segment),
        tol: f64,
        continues: bool,
        warnings: &mut Vec<(usize, String)>,
    ) -> Option<Vec<P>> {
        let (p, q) = ([seg.from.z, seg.from.r], [seg.to.z, seg.to.r]);
        let carried = self.carry.take().filter(|(at, _)| *at == p);
        if let Some(why) = continuous(seg, tol) {
            warnings.push((idx, why));
            return None;
        }
        // the lead is measured along the dominant axis (Z for straight and taper threads)
        let len = (q[0] - p[0]).abs().max((q[1] - p[1]).abs());
        let n = (len / seg.lead).floor();
        // The tool passes the section plane once a lead, shifted by the start angle
        // (multi-start Q): at from + (phase + k)·lead along the move; the start and end
        // points are where the tool enters and leaves the thread.
        let phase = carried.map_or(seg.thread_phase.rem_euclid(1.0), |(_, f)| f);
        let at = |s: f64| {
            let t = if len > 0.0 { s / len } else { 0.0 };
            [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
        };
        let mut pts: Vec<P> = Vec::new();
        if carried.is_none() {
            pts.push(p);
        }
        pts.extend(
            (0..=n as usize + 1)
                .map(|k| (phase + k as f64) * seg.lead)
                .filter(|&s| (s > 0.0 || (carried.is_some() && s >= 0.0)) && s < len)
                .map(at),
        );
        if continues {
            // the first stamp at or past the end, counted from there
            let k = (len / seg.lead - phase).ceil().max(0.0);
            self.carry = Some((q, (phase + k - len / seg.lead).clamp(0.0, 1.0)));
        } else {
            pts.push(q);
        }
        Some(pts)
    }

    /// Where the passes this thread move repeats began, when it repeats the latest
    /// remembered thread move of tool `key` stamped as often: each of its stamps `at` a
    /// step `w` from that move's that `accept(w)` takes, and on the line from where their
    /// run of passes began (within [`OFF_LINE`], moving on); `None` when it repeats none.
    /// A point of `outline ⊕ [first, at]` then lies between two consecutive passes' stamps
    /// on that line: within the notch depth `accept` bounds (plus [`OFF_LINE`]) of one of
    /// them ([`super::notch::notch_depth`]). Off that line, the run starts again from the
    /// move it repeats.
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

/// Why the thread move `seg` is swept continuously rather than stamped (chord tolerance
/// `tol`), as the warning says it; `None` when it is stamped.
fn continuous(seg: &Segment, tol: f64) -> Option<String> {
    if seg.arc.is_some() {
        return Some("circular thread move: swept continuously".into());
    }
    if !(seg.lead.is_finite() && seg.lead > 0.0) {
        return Some(format!(
            "thread move with lead {}: swept continuously",
            seg.lead
        ));
    }
    if seg.lead <= tol {
        // The notches between stamps a lead apart are about lead·cot(flank angle) deep:
        // below the chord tolerance for any thread tool (flank half-angle ≥ 27°), so the
        // continuous sweep is the stamped section within the tolerance.
        return Some(format!(
            "thread lead {} mm is not more than the chord tolerance {} mm: swept continuously",
            seg.lead, tol
        ));
    }
    let (p, q) = ([seg.from.z, seg.from.r], [seg.to.z, seg.to.r]);
    let n = ((q[0] - p[0]).abs().max((q[1] - p[1]).abs()) / seg.lead).floor();
    (n > MAX_THREAD_STAMPS as f64).then(|| {
        format!("thread move of {n} leads (more than {MAX_THREAD_STAMPS}): swept continuously")
    })
}

/// Whether the move after the thread move `seg` continues its pass (a straight thread
/// move from where it ends: its pull-out chamfer).
pub(super) fn continued_by(seg: &Segment, next: Option<&Segment>) -> bool {
    seg.motion == expander::Motion::Thread
        && next.is_some_and(|n| {
            n.motion == expander::Motion::Thread && n.arc.is_none() && n.from == seg.to
        })
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
        let mut t = ThreadStamps::default();
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
        let mut t = ThreadStamps::default();
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
