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
    /// How many segments were made before the shape's first move: the stock it works on is
    /// the stock after them (a lead-in in front of that stock is no part of the shape).
    pub after_move: usize,
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
    /// Feed in force, for cycle time.
    pub feed: Feed,
    /// The block that produced this segment.
    pub span: Span,
}

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

    /// Points along the segment such that no chord strays more than `tol` mm from the
    /// true arc (lines give their two end points). Always starts at `from`, ends at `to`.
    pub fn polyline(&self, tol: f64) -> Vec<Pt> {
        let Some(a) = self.arc else {
            return vec![self.from, self.to];
        };
        let arc = geom::arc::Arc::between(self.from, self.to, a.center, a.ccw);
        let n = arc.chords(tol.max(1e-6));
        // the end points exactly as given; the angle (sweep · i) / n as it always was
        let mut pts = Vec::with_capacity(n + 1);
        pts.push(self.from);
        pts.extend((1..n).map(|i| arc.at_angle(arc.start + arc.sweep * i as f64 / n as f64)));
        pts.push(self.to);
        pts
    }
}
