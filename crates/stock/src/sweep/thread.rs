//! Thread moves: the outline stamped where the tool passes the section plane, once a lead.

use expander::Segment;
use geom::flat::P;

/// A tool as mounted under its hint ([`crate::tools::hint_key`]).
pub(super) type ToolKey = (u32, u8, u64);

/// Most stamps one thread move may make before it is swept continuously instead, with a
/// warning (a real thread has a few hundred: 200 mm at 0.5 mm lead is 400; stamps that all
/// overlap their neighbours cost the boolean engine about k², so 4 000 took 10 s).
const MAX_THREAD_STAMPS: usize = 2_000;

/// The stamps of thread moves in program order: a pass of several moves (a thread and its
/// pull-out chamfer) is one pass, so where the next stamp falls is carried from one move to
/// the next.
#[derive(Default)]
pub(super) struct ThreadStamps {
    /// After a move the next one continues: where it ended and where the next stamp falls
    /// from there, as a fraction of the lead.
    carry: Option<(P, f64)>,
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
