//! A move's tool as mounted, and the path and sweep of a move: the one home of the idea
//! "this move's tool, as mounted, swept along the move". The removal cuts with it, and the
//! analysis (deviation, workholding, the tool drawn at a crash and in the player) asks the
//! same questions of the same tool.
//!
//! A tool is mounted once per (tool number, cycle hint, post): its cutting outline and its
//! body as the table describes them, mirrored about the axis on a rear post
//! ([`crate::section`]: a rear-post tool's tip number reads the same on both posts).

use crate::outline::{Outline, PastAxis};
use crate::tools::hint_key;
use crate::{Body, ToolTable};
use expander::{Motion, Segment, ToolHint};
use geom::flat::{convex_hull, sweep_convex, P};
use geom::{Pt, Rect};
use std::collections::HashMap;
use std::sync::Arc;

/// A tool as mounted: what cuts, what holds it, and the table's warning when a default
/// stands in for the tool.
#[derive(Debug, Clone, PartialEq)]
pub struct Mounted {
    /// The cutting outline (insert, blade, drill, threading insert); shared, so that moves
    /// of one tool can tell they share it (`Arc::ptr_eq`).
    pub edge: Arc<Outline>,
    /// The non-cutting body, when the table states what places it.
    pub body: Option<Body>,
    /// Why a default outline cuts for this tool (no entry, a cycle's default blade).
    pub warning: Option<String>,
    /// For an outline whose size is assumed, the part of it the table states
    /// (`ToolTable::stated_core`: an insert's nose), as mounted; `None` for a stated tool
    /// or when nothing of it is stated.
    pub core: Option<Arc<Outline>>,
}

impl Mounted {
    /// Tool `t` under `hint`, mirrored about the axis when `rear` (a rear post).
    pub fn new(tools: &ToolTable, t: u32, hint: ToolHint, rear: bool) -> Self {
        let (mut edge, warning) = tools.outline_for(t, hint);
        let mut body = tools.body_for(t, hint);
        // only stated geometry past the axis (spec/simulation.md)
        let past = match (tools.size_stated(t, hint), rear) {
            (true, _) => PastAxis::Fold,
            (false, false) => PastAxis::DropBelow,
            (false, true) => PastAxis::DropAbove,
        };
        edge.past_axis = past;
        if let Some(b) = &mut body {
            b.outline.past_axis = past;
        }
        let warning = warning.or_else(|| tools.size_warning(t, hint));
        let core = tools.stated_core(t, hint);
        if !rear {
            return Self {
                edge: Arc::new(edge),
                body,
                warning,
                core: core.map(Arc::new),
            };
        }
        Self {
            core: core.map(|c| Arc::new(c.mirrored())),
            edge: Arc::new(edge.mirrored()),
            body: body.map(|b| Body {
                outline: b.outline.mirrored(),
                name: b.name,
            }),
            warning,
        }
    }

    /// The box of the cutting outline and the body, relative to the reference point.
    pub fn bbox(&self) -> Rect {
        Rect::of(
            self.edge
                .parts
                .iter()
                .chain(self.body.iter().flat_map(|b| b.outline.parts.iter()))
                .flatten()
                .map(|&p| Pt::from(p)),
        )
    }

    /// The part named `body` (the body when it carries that name), else the cutting outline.
    pub fn part(&self, body: Option<&str>) -> &Outline {
        match (body, &self.body) {
            (Some(name), Some(b)) if b.name == name => &b.outline,
            _ => &self.edge,
        }
    }
}

/// The key a mounted tool is kept under: tool, hint, rear post.
type Key = ((u32, u8, u64), bool);

/// The tools of a run as mounted, each made once: consecutive moves nearly always share
/// their tool, so the last one is kept beside the map (a hash a move showed in profiles).
#[derive(Debug)]
pub struct Mounts<'a> {
    tools: &'a ToolTable,
    rear: Vec<u32>,
    all: HashMap<Key, Arc<Mounted>>,
    last: Option<(Key, Arc<Mounted>)>,
}

impl<'a> Mounts<'a> {
    /// The tools of `tools`, those numbered in `rear` on a rear post
    /// ([`crate::rear_tools`]).
    pub fn new(tools: &'a ToolTable, rear: Vec<u32>) -> Self {
        Self {
            tools,
            rear,
            all: HashMap::new(),
            last: None,
        }
    }

    /// Whether tool `t` sits on a rear post.
    pub fn is_rear(&self, t: u32) -> bool {
        self.rear.contains(&t)
    }

    /// The tools on a rear post.
    pub fn rear(&self) -> &[u32] {
        &self.rear
    }

    /// The table the tools come from.
    pub fn tools(&self) -> &'a ToolTable {
        self.tools
    }

    /// Tool `t` under `hint` as mounted.
    pub fn get(&mut self, t: u32, hint: ToolHint) -> Arc<Mounted> {
        let rear = self.is_rear(t);
        let key = (hint_key(t, hint), rear);
        if let Some((k, m)) = &self.last {
            if *k == key {
                return Arc::clone(m);
            }
        }
        let tools = self.tools;
        let m = Arc::clone(
            self.all
                .entry(key)
                .or_insert_with(|| Arc::new(Mounted::new(tools, t, hint, rear))),
        );
        self.last = Some((key, Arc::clone(&m)));
        m
    }

    /// The tool of move `seg` as mounted.
    pub fn of(&mut self, seg: &Segment) -> Arc<Mounted> {
        self.get(seg.tool, seg.hint)
    }
}

/// The path the tool's reference point follows over `seg`, as `[z, r]` points: a thread
/// move's two ends (where the tool is stamped along it is the removal's business), else
/// the move's chords within `chord_tol`. At least two points.
pub fn move_path(seg: &Segment, chord_tol: f64) -> Vec<P> {
    if seg.motion == Motion::Thread {
        vec![[seg.from.z, seg.from.r], [seg.to.z, seg.to.r]]
    } else {
        seg.polyline(chord_tol).iter().map(|p| [p.z, p.r]).collect()
    }
}

/// The sweep of each convex part of `outline` along `path`, chord by chord, where it was
/// programmed (not folded): a convex counter-clockwise hull per chord and part, chords in
/// order, parts in order within a chord. A path of one point gives the outline placed there.
pub fn chord_sweeps<'o>(outline: &'o Outline, path: &'o [P]) -> impl Iterator<Item = Vec<P>> + 'o {
    let pieces: Vec<[P; 2]> = match path {
        [] => Vec::new(),
        [p] => vec![[*p, *p]],
        _ => path.windows(2).map(|w| [w[0], w[1]]).collect(),
    };
    pieces.into_iter().flat_map(move |[a, b]| {
        outline.parts.iter().map(move |part| {
            let placed: Vec<P> = part.iter().map(|v| [v[0] + a[0], v[1] + a[1]]).collect();
            convex_hull(&sweep_convex(&placed, [b[0] - a[0], b[1] - a[1]]))
        })
    })
}

/// The sweep of `outline` along `path` in the section: [`chord_sweeps`] folded about the
/// axis (each hull's part below it mirrored, or left out when the outline's size is
/// assumed: [`crate::PastAxis`]), as convex counter-clockwise polygons.
pub fn float_sweep(outline: &Outline, path: &[P]) -> Vec<Vec<P>> {
    chord_sweeps(outline, path)
        .flat_map(|hull| crate::section::fold(&hull, outline.past_axis))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Insert, Tool};

    fn v35() -> ToolTable {
        ToolTable::from_tools(vec![(
            1,
            Tool::Turning {
                insert: Insert::V,
                nose_radius: 0.0,
                tip: 3,
                entering_angle: 93.0,
                edge: 11.0,
            },
        )])
    }

    /// A rear-post tool is the mirror of the table's, edge and warning alike; a tool with
    /// no entry carries the table's warning.
    #[test]
    fn a_rear_post_tool_is_mounted_mirrored() {
        let tools = v35();
        let front = Mounted::new(&tools, 1, ToolHint::Table, false);
        let rear = Mounted::new(&tools, 1, ToolHint::Table, true);
        assert_eq!(*rear.edge, front.edge.mirrored());
        assert!(front.warning.is_none() && front.body.is_none());
        let (lo, hi) = (front.bbox().min, rear.bbox().max);
        assert!((lo.r + hi.r).abs() < 1e-12, "{lo:?} {hi:?}");
        assert!(Mounted::new(&tools, 7, ToolHint::Table, false)
            .warning
            .is_some());
        let mut mounts = Mounts::new(&tools, vec![1]);
        assert_eq!(*mounts.get(1, ToolHint::Table), rear);
    }

    /// A 1 × 1 square swept 3 along Z from (0, 1): one hull of area 4 above the axis; swept
    /// from (0, -0.5) across the axis it folds into two pieces.
    #[test]
    fn a_sweep_is_one_hull_a_chord_folded_at_the_axis() {
        let mut square = Outline {
            parts: vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]],
            past_axis: PastAxis::Fold,
        };
        let area = |r: &[P]| geom::ring::signed_area(&geom::flat::pts(r));
        let s = float_sweep(&square, &[[0.0, 1.0], [3.0, 1.0]]);
        assert_eq!(s.len(), 1);
        assert!((area(&s[0]) - 4.0).abs() < 1e-12);
        let s = float_sweep(&square, &[[0.0, -0.5], [3.0, -0.5]]);
        assert_eq!(s.len(), 2);
        assert!((s.iter().map(|r| area(r)).sum::<f64>() - 4.0).abs() < 1e-12);
        assert!(s.iter().flatten().all(|p| p[1] >= 0.0));
        // a guessed size stops at the axis: only the 4 × 0.5 above it (the hull is 4 long)
        square.past_axis = PastAxis::DropBelow;
        let s = float_sweep(&square, &[[0.0, -0.5], [3.0, -0.5]]);
        assert!((s.iter().map(|r| area(r)).sum::<f64>() - 2.0).abs() < 1e-12);
    }
}
