//! A tool with no entry, taken for what its moves say it is (docs/field-rules.md §17):
//! - one that only cuts thread passes (G32, G92, G76) is a sharp 60° threading insert (or
//!   of the angle its first G76 states: field run 7), not the 55° turning default: that
//!   default cut a 96° thread and scraped the flank at every pull-out (field run 4, 5d).
//!   Its side is the side its passes come in from: from outside the thread (an OD insert)
//!   or from the bore (an ID one);
//! - one that only feeds along the axis at X0 (a centre drill, a G74 or G83 peck drill), or
//!   in a drilling cycle off it (an offset indexable drill, §19), is a drill: the 55°
//!   insert plunged there with its edge across the face, and the default G74 blade,
//!   standing along X, hollowed the whole part as it pecked (field run 3, D); the insert
//!   fed as an offset U-drill hollowed a cone Ø34 deep into the face (field run 6, C);
//! - one whose every finishing contour (G70–G73 shape, or a contour under G41/G42) lies in a
//!   bore is a boring bar: the default insert as an ID tool (tip 2); the OD default roughed
//!   the wall on the wrong side of an ID G71, whose contour was then read against that
//!   stock (field run 2, N2), and its rapid out of a bore it finished under G41 was a
//!   certain gouge (field run 6, E); so is one that leaves every pass along Z toward the
//!   axis (a bore turned by hand). The program is read again with it: its nose
//!   compensates as a boring bar's;
//! - one that only plunges (no facing pass) is the default grooving blade, its body away
//!   from the side it plunges from (field run 7, D: the OD default rapided into a bore for
//!   a relief groove swept the wall and the finished OD); one that only pecks a G74 face
//!   groove off the axis is a face blade, its body along +Z (field run 8, p02).
//!
//! Their size is a guess all the same, so their findings stay possible ones
//! (spec/simulation.md, "Findings from assumed tools"). For a threading insert, a drill or
//! a blade the program is not expanded again: the interpreter has compensated the tool as one with
//! no entry (the default nose), which only a thread pass or a drilling feed under G41/G42
//! would show.

use super::{AxisDir, GroovingBlade, ThreadSide, Tool, ToolTable};
use expander::{Intended, IntendedKind, Motion, Segment, ToolHint, Toolpath};

/// What a tool with no entry is taken for from its moves.
#[derive(Debug, Clone, PartialEq)]
pub struct ToolFromUse {
    /// The T number.
    pub t: u32,
    /// The tool it is taken for.
    pub tool: Tool,
    /// The index of its first cutting move.
    pub first: usize,
}

/// The drill a tool that only feeds along the axis is taken for: Ø10, the usual 118° point,
/// as long as a jobber drill's flutes.
const ASSUMED_DRILL: Tool = Tool::Drill {
    diameter: 10.0,
    point_angle: 118.0,
    reach: 60.0,
};

/// The blade a tool that only plunges is taken for: the default grooving blade (3 mm,
/// referenced at its corner toward −Z, 20 mm long), its body away from the side it plunges
/// from.
const ASSUMED_BLADE: GroovingBlade = match Tool::DEFAULT_BLADE {
    Tool::Grooving(b) => b,
    _ => unreachable!(),
};

/// The boring bar a tool whose every contour lies in a bore is taken for: the default
/// insert (55°, r0.4, 93°, 11 mm edges) as an ID tool, tip 2, cutting toward the chuck.
const ASSUMED_BORING_BAR: Tool = Tool::Turning {
    insert: super::Insert::D,
    nose_radius: toolfacts::Nose::DEFAULT.radius,
    tip: 2,
    entering_angle: 93.0,
    edge: 11.0,
};

/// What the moves of one tool with no entry say.
struct Tally {
    t: u32,
    first: usize,
    /// Finishing contours it roughs or finishes in a bore (its shape's start point below
    /// it), and elsewhere.
    bores: usize,
    others: usize,
    /// The largest |r| its feeds reach, and the largest of its bores' shapes: a boring bar
    /// cuts nothing outside its bores (a tool that also faces the part from the OD is not).
    feed_reach: f64,
    bore_reach: f64,
    threads: usize,
    /// Drilling feeds: along the axis at X0, or a drilling cycle's off it.
    on_axis: usize,
    /// Other feeds.
    feeds: usize,
    /// Thread runs entered from outside the thread (+) or from inside it (−), and left the
    /// same way.
    outside: i64,
    /// Cutting passes along Z (a chain of feeds more along Z than X) left toward the axis,
    /// as a boring bar leaves the wall, and away from it; the largest |r| of the first.
    passes_in: usize,
    passes_out: usize,
    pass_reach: f64,
    /// The largest |r| of the chain of feeds the last feed belongs to (a chamfer fed into
    /// a bore is part of the pass that follows it).
    chain_reach: f64,
    /// Feeds (off the axis) more along X than Z, as a blade plunges; whether one is a
    /// facing pass (to the axis at the front, Z > −1: a blade parts off behind it); the
    /// radial direction of the first plunge (+1 outward, −1 inward).
    plunges: usize,
    faces: bool,
    first_plunge: i64,
    /// Pecks of a face-grooving cycle off the axis (G74's feeds along Z).
    face_plunges: usize,
}

impl Tally {
    /// What the tool is taken for; a threading one of the included angle its G76 states
    /// (`thread_angle`), else 60°.
    fn taken_for(&self, thread_angle: Option<f64>) -> Option<Tool> {
        match (self.threads, self.on_axis, self.feeds) {
            (1.., 0, 0) => Some(Tool::Threading {
                angle: thread_angle.unwrap_or(60.0),
                tip_flat: 0.0,
                // a thread that says nothing of its side is an outside one, the usual
                side: if self.outside < 0 {
                    ThreadSide::Id
                } else {
                    ThreadSide::Od
                },
            }),
            (0, 1.., 0) => Some(ASSUMED_DRILL),
            // a face groove's blade stands along Z: seed 002's, the width spanning +x from
            // its inner corner, the body toward +Z (the radial default swept 20 mm of face)
            (0, 0, n)
                if self.face_plunges > 0
                    && self.face_plunges + self.plunges == n
                    && self.plunges <= self.face_plunges =>
            {
                Some(Tool::Grooving(GroovingBlade {
                    width_dir: AxisDir::PlusX,
                    shank_dir: AxisDir::PlusZ,
                    ..ASSUMED_BLADE
                }))
            }
            (0, 0, n) if self.plunges == n && !self.faces && self.first_plunge != 0 => {
                Some(Tool::Grooving(GroovingBlade {
                    // a blade plunged outward, from a bore, is an ID one: its body toward the axis
                    shank_dir: if self.first_plunge > 0 {
                        AxisDir::MinusX
                    } else {
                        AxisDir::PlusX
                    },
                    ..ASSUMED_BLADE
                }))
            }
            (0, _, _) if self.bores_only() || self.bores_by_hand() => Some(ASSUMED_BORING_BAR),
            _ => None,
        }
    }

    /// Every finishing contour it cuts lies in a bore, and it feeds nowhere further out.
    fn bores_only(&self) -> bool {
        self.bores > 0 && self.others == 0 && self.feed_reach <= self.bore_reach + 1e-6
    }

    /// It cuts no finishing contour, and every pass along Z it cuts it leaves toward the
    /// axis, off a wall outside it (a bore turned by hand: an OD tool steps out), feeding
    /// nowhere further out (field run 6, G: the OD default cut a nut's whole wall away).
    fn bores_by_hand(&self) -> bool {
        self.bores == 0
            && self.others == 0
            && self.passes_in > 0
            && self.passes_out == 0
            && self.feed_reach <= self.pass_reach + 1e-6
    }
}

impl ToolTable {
    /// The tools with no entry (tool 0, no T word yet, is the table's first entry, when
    /// there is a table) that `toolpath` uses only for thread passes, only to drill, only
    /// to plunge, or only in bores.
    pub fn tools_from_use(&self, toolpath: &Toolpath) -> Vec<ToolFromUse> {
        let segments = &toolpath.segments;
        let offset_drill = OffsetDrills::of(toolpath);
        let mut tallies: Vec<Tally> = vec![];
        // the tally of the last tool looked up (`None`: it has an entry): a program's
        // moves come a tool at a time, and a million of them are read here
        let mut last: Option<(u32, Option<usize>)> = None;
        for (i, s) in segments.iter().enumerate() {
            // tool 0 (no T word yet) is the table's first entry; with no table, a tool too
            if s.motion == Motion::Rapid || (s.tool == 0 && !self.tools.is_empty()) {
                continue;
            }
            let k = match last {
                Some((t, k)) if t == s.tool => k,
                _ => {
                    let k = (self.get(s.tool).is_none() || self.tip_unstated(s.tool)).then(|| {
                        tallies
                            .iter()
                            .position(|t| t.t == s.tool)
                            .unwrap_or_else(|| {
                                tallies.push(Tally {
                                    t: s.tool,
                                    first: i,
                                    bores: 0,
                                    others: 0,
                                    feed_reach: 0.0,
                                    bore_reach: 0.0,
                                    threads: 0,
                                    on_axis: 0,
                                    feeds: 0,
                                    outside: 0,
                                    passes_in: 0,
                                    passes_out: 0,
                                    pass_reach: 0.0,
                                    chain_reach: 0.0,
                                    plunges: 0,
                                    faces: false,
                                    first_plunge: 0,
                                    face_plunges: 0,
                                });
                                tallies.len() - 1
                            })
                    });
                    last = Some((s.tool, k));
                    k
                }
            };
            let Some(k) = k else { continue };
            let tally = &mut tallies[k];
            if s.motion == Motion::Feed {
                tally.feed_reach = tally.feed_reach.max(s.from.r.abs()).max(s.to.r.abs());
                if along_axis(s) || offset_drill.feeds(s) {
                    tally.on_axis += 1;
                } else {
                    tally.feeds += 1;
                    let chained = i
                        .checked_sub(1)
                        .map(|j| &segments[j])
                        .is_some_and(|p| p.motion == Motion::Feed && p.tool == s.tool);
                    let reach = s.from.r.abs().max(s.to.r.abs());
                    tally.chain_reach = if chained {
                        tally.chain_reach.max(reach)
                    } else {
                        reach
                    };
                    count_pass(tally, s, segments.get(i + 1));
                    count_plunge(tally, s);
                }
                continue;
            }
            tally.threads += 1;
            // a thread run's ends: the move that brought the tool in, and the one out,
            // away from the axis or toward it (a rear post's moves at negative X too)
            if let Some(p) = i.checked_sub(1).map(|j| &segments[j]) {
                if p.motion != Motion::Thread {
                    tally.outside += side_of(p.from.r.abs() - s.from.r.abs());
                }
            }
            if let Some(n) = segments.get(i + 1).filter(|n| n.motion != Motion::Thread) {
                tally.outside += side_of(n.to.r.abs() - s.to.r.abs());
            }
        }
        count_contours(&mut tallies, segments, &toolpath.intended);
        tallies
            .iter()
            .filter_map(|t| {
                let angle = toolpath
                    .thread_angles
                    .iter()
                    .find(|&&(tool, _)| tool == t.t)
                    .map(|&(_, a)| a);
                let tool = match (self.get(t.t), t.taken_for(angle)?) {
                    (None, tool) => tool,
                    // an entry whose tip is unstated keeps its insert: only the tip the
                    // moves say, a boring bar's
                    (
                        Some(Tool::Turning {
                            insert,
                            nose_radius,
                            entering_angle,
                            edge,
                            ..
                        }),
                        Tool::Turning { tip: 2, .. },
                    ) => Tool::Turning {
                        insert: *insert,
                        nose_radius: *nose_radius,
                        tip: 2,
                        entering_angle: *entering_angle,
                        edge: *edge,
                    },
                    // a blade whose body's side is unstated: the side its plunges say,
                    // when they go outward from a bore (its width and reach its own)
                    (Some(Tool::Grooving(entry)), Tool::Grooving(used))
                        if entry.width_dir.is_z()
                            && used.shank_dir == AxisDir::MinusX
                            && entry.shank_dir != AxisDir::MinusX =>
                    {
                        Tool::Grooving(GroovingBlade {
                            shank_dir: AxisDir::MinusX,
                            ..*entry
                        })
                    }
                    _ => return None,
                };
                Some(ToolFromUse {
                    t: t.t,
                    tool,
                    first: t.first,
                })
            })
            .collect()
    }

    /// Whether `t` is a turning entry whose tip the table does not state (an insert alone,
    /// no `tip`, no holder): its tip is taken from its moves when they say bore (field run
    /// 9, B: a DCMT listed by its insert alone was the tip-3 default, an OD tool, and its
    /// bore a certain 12 mm gouge and 43 crashes, where no entry at all was clean).
    fn tip_unstated(&self, t: u32) -> bool {
        matches!(self.get(t), Some(Tool::Turning { .. } | Tool::Grooving(_)))
            && !self.tips.contains(&t)
    }

    /// The table with the tools `found` taken for what their moves say: still no entries
    /// ([`ToolTable::get`] has none of them, their size is not stated), but what cuts for
    /// them ([`ToolTable::outline_for`], [`ToolTable::tool_or_default`]).
    pub fn with_tools_from_use(&self, found: &[ToolFromUse]) -> Self {
        let mut out = self.clone();
        for f in found {
            match out.tools.iter_mut().find(|(n, _)| *n == f.t) {
                // an entry's tip from its moves (its tip stays unstated)
                Some((_, entry)) => *entry = f.tool.clone(),
                None => out.by_use.push((f.t, f.tool.clone())),
            }
        }
        out
    }
}

/// The warning for tool `t`, whose entry does not state the side it cuts on, taken for
/// `tool` (a boring bar, tip 2; an ID blade) from its moves.
pub fn tip_taken_note(t: u32, tool: &Tool) -> String {
    match tool {
        Tool::Grooving(_) => format!("T{t:02} states its blade but not its body's side (shank_dir), and plunges outward from a bore: taken as an ID blade (shank_dir = \"-x\"); state shank_dir to check it"),
        _ => format!("T{t:02} states its insert but not its tip, and cuts in bores only: taken as tip 2, a boring bar; state its tip (or holder) to check it"),
    }
}

/// The warning for tool `t`, which has no entry and is taken for `tool` from its moves.
pub(super) fn taken_note(t: u32, tool: &Tool) -> String {
    let what = match tool {
        Tool::Drill { .. } => "only drills: taken for a drill",
        Tool::Threading { .. } => "cuts only thread passes: taken for a threading insert",
        Tool::Grooving(_) => "only plunges: taken for a grooving blade",
        _ => "cuts in bores only: taken for a boring bar",
    };
    format!(
        "T{t:02} has no entry in the tool table and {what} ({}, its size assumed); state T{t:02} to check it",
        tool.describe()
    )
}

/// Counts the finishing contours each tool of `tallies` roughs or finishes (the tool of the
/// cycle's first move and of the shape's), in a bore or elsewhere: a G70–G73 shape or a
/// contour cut under G41/G42 (a bore finished by hand: field run 6, E).
fn count_contours(tallies: &mut [Tally], segments: &[Segment], intended: &[Intended]) {
    for shape in intended {
        let bore = match shape.kind {
            IntendedKind::FinishingContour => in_bore(shape),
            IntendedKind::Compensated { part_on_left } => part_outside(shape, part_on_left),
            IntendedKind::Groove => continue,
        };
        for k in [shape.began, shape.after_move] {
            let tool = segments.get(k).map(|s| s.tool);
            let Some(t) = tallies.iter_mut().find(|t| Some(t.t) == tool) else {
                continue;
            };
            if bore {
                t.bores += 1;
                // (a contour under G41/G42 is fed in from its start-up move's start)
                let start_up = match shape.kind {
                    IntendedKind::Compensated { .. } => segments.get(shape.after_move),
                    _ => None,
                };
                let reach = shape
                    .points
                    .iter()
                    .map(|p| p.r.abs())
                    .chain(start_up.map(|s| s.from.r.abs()))
                    .fold(0.0, f64::max);
                t.bore_reach = t.bore_reach.max(reach);
            } else {
                t.others += 1;
            }
        }
    }
}

/// The least travel along Z of a pass: shorter feeds along Z are a blade's chamfer or step
/// (a part-off's), not a turning or boring pass.
const MIN_PASS: f64 = 2.0;

/// Counts feed `s` in `tally` as a plunge when it runs more along X than Z, or less than
/// [`MIN_PASS`] along Z.
fn count_plunge(tally: &mut Tally, s: &Segment) {
    let dr = s.to.r.abs() - s.from.r.abs();
    let dz = (s.to.z - s.from.z).abs();
    // (a G75's escape runs along Z too: only a G74's moves are a face groove's)
    if s.arc.is_none() && s.hint == ToolHint::FaceGrooving && dr.abs() < dz {
        tally.face_plunges += 1;
        return;
    }
    if s.arc.is_some() || (dr.abs() < dz && dz >= MIN_PASS) {
        return;
    }
    tally.plunges += 1;
    let to_axis = s.to.r.abs() <= 1e-9 || s.to.r * s.from.r < 0.0;
    tally.faces |= to_axis && s.to.z > -1.0;
    if tally.first_plunge == 0 {
        tally.first_plunge = side_of(dr);
    }
}

/// Counts feed `s` in `tally` as the end of a pass along Z when it is one and `next` (the
/// move after it) leaves it toward the axis or away from it.
fn count_pass(tally: &mut Tally, s: &Segment, next: Option<&Segment>) {
    let along_z = |s: &Segment| (s.to.z - s.from.z).abs() > (s.to.r - s.from.r).abs();
    let Some(next) = next else { return };
    if !along_z(s)
        || (s.to.z - s.from.z).abs() < MIN_PASS
        || (next.motion == Motion::Feed && along_z(next) && next.tool == s.tool)
    {
        return;
    }
    // a move in to the axis after the pass faces the part: no bore's retract
    let faces = next.to.r.abs() <= 1e-9 || next.to.r * next.from.r < 0.0;
    match side_of(next.to.r.abs() - next.from.r.abs()) {
        -1 if faces => {}
        -1 => {
            tally.passes_in += 1;
            tally.pass_reach = tally.pass_reach.max(tally.chain_reach);
        }
        1 => tally.passes_out += 1,
        _ => {}
    }
}

/// Whether a finishing shape lies in a bore: it runs outward of its start point and
/// nowhere inward of it (the cycle's A; spec/simulation.md: the part lies on the side away
/// from A), by |X| for a rear post's shape. (Its first move alone said so for a G71; a
/// G72's first move runs along Z at A's X, and a bore faced in layers was taken for an OD
/// shape: the default insert carved a 12 mm gouge into the sleeve's wall, field run 9, A.)
fn in_bore(shape: &Intended) -> bool {
    let Some((a, rest)) = shape.points.split_first() else {
        return false;
    };
    let a = a.r.abs();
    rest.iter().all(|p| p.r.abs() >= a - 1e-9) && rest.iter().any(|p| p.r.abs() > a + 1e-9)
}

/// Whether a contour cut under G41/G42 keeps the part outside it, away from the axis (a
/// bore).
fn part_outside(shape: &Intended, part_on_left: bool) -> bool {
    outward_travel(&shape.points, part_on_left) > 1e-9
}

/// How far along Z a contour cut under G41/G42 (`part_on_left`: G42) runs with the part
/// outward of it, away from the axis, less how far with the part toward it: the part's
/// side of each move (dz, dr) in the (z, r) plane is its left (−dr, dz) for G42, its right
/// for G41 (G41 along a bore toward the chuck keeps the part outward); below the axis (a
/// rear post) outward is toward −r.
pub fn outward_travel(points: &[expander::Pt], part_on_left: bool) -> f64 {
    points
        .windows(2)
        .map(|w| {
            let dz = w[1].z - w[0].z;
            let r_toward_part = if part_on_left { dz } else { -dz };
            r_toward_part * (w[0].r + w[1].r).signum()
        })
        .sum()
}

/// The drilling cycles that run off the axis (G81/G82/G83 with the spindle turning: an
/// offset drill, warned W-OFF-AXIS-DRILL at the cycle's X word), by where that word is.
struct OffsetDrills(Vec<(u32, u32)>);

impl OffsetDrills {
    fn of(toolpath: &Toolpath) -> Self {
        let mut at: Vec<(u32, u32)> = toolpath
            .warnings
            .iter()
            .filter(|w| w.code == "W-OFF-AXIS-DRILL")
            .map(|w| (w.span.offset, w.span.line))
            .collect();
        at.sort_unstable();
        Self(at)
    }

    /// Whether feed `s` is a straight feed along Z of one of these cycles (its block holds
    /// the warned word).
    fn feeds(&self, s: &Segment) -> bool {
        if self.0.is_empty() || s.arc.is_some() || s.from.r != s.to.r || s.from.z == s.to.z {
            return false;
        }
        let k = self
            .0
            .partition_point(|&(offset, _)| offset < s.span.offset);
        self.0.get(k).is_some_and(|&(offset, line)| {
            offset < s.span.offset + s.span.len && line == s.span.line
        })
    }
}

/// Whether feed `s` runs along the axis at X0 (a drill's feed).
fn along_axis(s: &Segment) -> bool {
    const ON_AXIS: f64 = 1e-9;
    s.arc.is_none() && s.from.r.abs() <= ON_AXIS && s.to.r.abs() <= ON_AXIS && s.from.z != s.to.z
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
