//! The one shared vocabulary downstream of the interpreter: segments in the (z, r) half plane.

pub use gcode::Span;

/// A point in the half plane: `z` axial (mm), `r` radius (mm) = X / 2 — the geometry
/// kernel's point, re-exported so that downstream code names it `expander::Pt`.
pub use geom::Pt;

/// How the tool moves along a segment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Motion {
    /// G00 positioning: must never touch stock.
    Rapid,
    /// G01/G02/G03 or a cycle's cutting feed.
    Feed,
    /// Thread cutting (G32/G92/G76): the tool is stamped at every lead.
    Thread,
}

/// Circular interpolation data. Directions are as seen in the drawing (Z right, X up):
/// G03 is counter-clockwise, G02 clockwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc {
    /// Centre of the arc.
    pub center: Pt,
    /// Counter-clockwise (G03) when true.
    pub ccw: bool,
}

/// How the feed word is to be read when timing a segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Feed {
    /// Rapid traverse at the machine's rates.
    Rapid,
    /// mm/min (G98).
    PerMinute(f64),
    /// mm/rev (G99), with the spindle state in force.
    PerRev {
        /// Feed, mm/rev.
        feed: f64,
        /// Spindle speed mode in force.
        spindle: Spindle,
    },
}

/// Where a segment's [`Feed`] is in its toolpath's [`crate::Toolpath::feeds`]: feeds change
/// rarely, and a million segments holding an index instead of the 32-byte feed are 24 MB
/// smaller. Only cycle time reads the feed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub struct FeedId(pub u32);

/// The distinct feeds of a toolpath, each once, in order of first use.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Feeds {
    list: Vec<Feed>,
    /// The index of each feed, keyed by its bits (an `f64` is not `Hash`).
    index: std::collections::HashMap<[u64; 4], u32>,
    /// The two feeds asked for last (most recent first): a program alternates between a
    /// rapid and a feed, and these spare the hash of nearly every segment.
    recent: [Option<([u64; 4], u32)>; 2],
}

impl Feeds {
    /// The id of `feed`, added on first use. `None` past `u32::MAX` distinct feeds (more than
    /// a program can expand to).
    pub fn id(&mut self, feed: Feed) -> Option<FeedId> {
        let key = feed_bits(feed);
        match self.recent {
            [Some((k, i)), _] if k == key => return Some(FeedId(i)),
            [first, Some((k, i))] if k == key => {
                self.recent = [Some((k, i)), first];
                return Some(FeedId(i));
            }
            _ => {}
        }
        let i = match self.index.get(&key) {
            Some(&i) => i,
            None => {
                let i = u32::try_from(self.list.len()).ok()?;
                self.list.push(feed);
                self.index.insert(key, i);
                i
            }
        };
        self.recent = [Some((key, i)), self.recent[0]];
        Some(FeedId(i))
    }

    /// The feed of an id this table gave out.
    pub fn get(&self, id: FeedId) -> Feed {
        self.list[id.0 as usize]
    }

    /// The feeds, in order of first use.
    pub fn as_slice(&self) -> &[Feed] {
        &self.list
    }
}

/// A feed as bits, for the table's index (`-0.0` and `0.0`, NaNs, differ: harmless, a
/// second entry).
fn feed_bits(feed: Feed) -> [u64; 4] {
    match feed {
        Feed::Rapid => [0, 0, 0, 0],
        Feed::PerMinute(f) => [1, f.to_bits(), 0, 0],
        Feed::PerRev { feed, spindle } => match spindle {
            Spindle::Rpm(n) => [2, feed.to_bits(), n.to_bits(), 0],
            Spindle::Css { vc, max_rpm } => [3, feed.to_bits(), vc.to_bits(), max_rpm.to_bits()],
        },
    }
}

/// Spindle speed in force for a segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spindle {
    /// G97: constant rev/min.
    Rpm(f64),
    /// G96: constant surface speed m/min, clamped at `max_rpm` (G50 S; 0 = no clamp).
    Css {
        /// Surface speed, m/min.
        vc: f64,
        /// Clamp, rev/min (0 = none).
        max_rpm: f64,
    },
}

/// What a shape the program defines for itself means (spec/simulation.md, intended shape).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IntendedKind {
    /// A G75.1 trapezoid groove: a closed ring of material that must be removed.
    Groove,
    /// A G70–G73 finishing shape ns..nf: an open path from the cycle's start point A; the
    /// part lies on the side away from A, within the shape's Z span.
    FinishingContour,
    /// A contour cut under G41/G42 (the programmed path between start-up and cancel): the
    /// part lies on the side away from the tool.
    Compensated {
        /// The part is on the left of the direction of travel (G42 keeps the tool right).
        part_on_left: bool,
    },
}

/// A shape the program itself defines, with the block that defined it.
#[derive(Debug, Clone, PartialEq)]
pub struct Intended {
    /// What the points mean.
    pub kind: IntendedKind,
    /// The points, (z, r), G54 frame.
    pub points: Vec<Pt>,
    /// The cycle block.
    pub span: Span,
    /// How many segments were made before the shape's first move (of the last cycle that
    /// ran it: a G70 after its G71): the stock it works on is the stock after them (a
    /// lead-in in front of that stock is no part of the shape), and the tool of the move
    /// after them is the one that finishes it.
    pub after_move: usize,
    /// How many segments were made before the first cycle that ran the shape began (a
    /// G71's roughing before its G70; `after_move` when one cycle runs it): the contour
    /// began there.
    pub began: usize,
}

/// Which outline cuts a segment, beyond the tool number.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum ToolHint {
    /// The tool table's entry for the segment's tool (or the documented default insert).
    #[default]
    Table,
    /// A grooving cycle (G74/G75): with no table entry the default is a 3 mm grooving blade
    /// referenced at its left corner (spec/simulation.md, Tools).
    Grooving,
    /// A G74 (face grooving, peck drilling): as [`ToolHint::Grooving`], its infeed along Z
    /// (a tool with no entry that only pecks a face groove is taken for a face blade).
    FaceGrooving,
    /// G75.1 with I: a grooving blade of this width whatever the table says, its reference
    /// corner on the start side, the blade extending toward +Z when `toward_plus_z`.
    Blade {
        /// Blade width, mm.
        width: f64,
        /// The blade spans from the reference corner toward +Z (else −Z).
        toward_plus_z: bool,
        /// The groove is cut toward −X, so the blade body runs toward +X (an OD blade);
        /// else toward −X (an ID blade). Used when the table has no grooving entry.
        shank_plus_x: bool,
    },
}

/// One tool move: a straight line or an arc from `from` to `to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Rapid, feed or thread.
    pub motion: Motion,
    /// Start point of the programmed (reference) point.
    pub from: Pt,
    /// End point.
    pub to: Pt,
    /// Present for G02/G03 arcs.
    pub arc: Option<Arc>,
    /// Tool number `tt` of the `Tttoo` in force (0: no T word yet).
    pub tool: u32,
    /// What cuts, where a cycle decides beyond the tool number.
    pub hint: ToolHint,
    /// Thread lead (mm) for [`Motion::Thread`], else 0.
    pub lead: f64,
    /// Start shift of a [`Motion::Thread`] move as a fraction of its lead (multi-start Q:
    /// a start angle of q degrees is q / 360; spec/dialects.md §4.7), else 0. The stamped
    /// tool outlines move by `thread_phase · lead` along the move.
    pub thread_phase: f64,
    /// Feed in force, for cycle time: its place in the toolpath's feeds
    /// ([`crate::Toolpath::feeds`]).
    pub feed: FeedId,
    /// The block that produced this segment.
    pub span: Span,
}

/// Smallest chord tolerance an arc is flattened with, mm (a finer one would cut a large
/// arc into tens of thousands of chords).
const MIN_CHORD_TOL: f64 = 1e-6;

impl Segment {
    /// Length of the path, mm.
    pub fn length(&self) -> f64 {
        match self.arc {
            None => self.from.dist(self.to),
            Some(a) => {
                let rad = a.center.dist(self.from);
                rad * self.sweep_angle().abs()
            }
        }
    }

    /// Signed swept angle of an arc in radians (positive counter-clockwise); 0 for lines.
    /// A full circle (start == end) sweeps ±2π.
    pub fn sweep_angle(&self) -> f64 {
        let Some(a) = self.arc else { return 0.0 };
        geom::arc::sweep_between(self.from, self.to, a.center, a.ccw)
    }

    /// How many chords [`Segment::polyline`] makes at `tol` (1 for a line), without
    /// making them.
    pub fn chord_count(&self, tol: f64) -> usize {
        self.circle()
            .map_or(1, |arc| arc.chords(tol.max(MIN_CHORD_TOL)))
    }

    /// The arc of an arc move, as the geometry kernel computes with it.
    fn circle(&self) -> Option<geom::arc::Arc> {
        self.arc
            .map(|a| geom::arc::Arc::between(self.from, self.to, a.center, a.ccw))
    }

    /// Points along the segment such that no chord strays more than `tol` mm from the
    /// true arc (lines give their two end points). Always starts at `from`, ends at `to`.
    pub fn polyline(&self, tol: f64) -> Vec<Pt> {
        let Some(arc) = self.circle() else {
            return vec![self.from, self.to];
        };
        let n = arc.chords(tol.max(MIN_CHORD_TOL));
        // the end points exactly as given; the angle (sweep · i) / n as it always was
        let mut pts = Vec::with_capacity(n + 1);
        pts.push(self.from);
        pts.extend((1..n).map(|i| arc.at_angle(arc.start + arc.sweep * i as f64 / n as f64)));
        pts.push(self.to);
        pts
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A million-move program holds a million segments: their size is a large part of a
    /// big run's peak (the feed is an index into the toolpath's feeds, not a 32-byte copy).
    #[test]
    fn segments_stay_compact() {
        assert!(
            std::mem::size_of::<Segment>() <= 120,
            "{}",
            std::mem::size_of::<Segment>()
        );
    }

    /// A feed gets one id however often it is used; each distinct feed its own.
    #[test]
    fn feeds_are_kept_once() {
        let mut feeds = Feeds::default();
        let rev = |n: f64| Feed::PerRev {
            feed: 0.2,
            spindle: Spindle::Rpm(n),
        };
        let css = Feed::PerRev {
            feed: 0.2,
            spindle: Spindle::Css {
                vc: 150.0,
                max_rpm: 2000.0,
            },
        };
        let ids: Vec<FeedId> = [
            Feed::Rapid,
            rev(600.0),
            Feed::Rapid,
            rev(800.0),
            css,
            rev(600.0),
            css,
        ]
        .into_iter()
        .map(|f| feeds.id(f).unwrap())
        .collect();
        let n: Vec<u32> = ids.iter().map(|i| i.0).collect();
        assert_eq!(n, [0, 1, 0, 2, 3, 1, 3]);
        assert_eq!(feeds.get(ids[3]), rev(800.0));
        assert_eq!(
            feeds.as_slice(),
            &[Feed::Rapid, rev(600.0), rev(800.0), css]
        );
    }
}
