//! The finished result of one simulation, as plain data. The render crate draws and
//! serialises it; it knows nothing of how it was computed.
//!
//! Coordinates are `[z, r]` in mm (r = radius = X / 2), the simulator's half plane.
//! The JSON writer converts to program coordinates `[z, x]` (x = diameter).

/// A polygon with holes in `[z, r]`; the outer ring counter-clockwise, holes clockwise.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Shape {
    /// Outer boundary, not closed (first point not repeated).
    pub outer: Vec<[f64; 2]>,
    /// Holes, same convention.
    pub holes: Vec<Vec<[f64; 2]>>,
}

/// The kind of a toolpath polyline, for styling.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathKind {
    /// G00: drawn dashed.
    Rapid,
    /// Cutting feed: drawn solid.
    Feed,
    /// Thread cutting.
    Thread,
}

/// One programmed move (arcs already chorded), with the line that produced it.
#[derive(Debug, Clone, PartialEq)]
pub struct PathLine {
    /// Rapid, feed or thread.
    pub kind: PathKind,
    /// Source line (1-based).
    pub line: u32,
    /// The reference point's path in `[z, r]`.
    pub points: Points,
}

/// A move's points: a straight move's two are held in place, a chorded arc's in a box. A
/// million-move report holds one per move, and a vector of two points cost 48 bytes and an
/// allocation beside the line (issue 16).
#[derive(Debug, Clone, PartialEq)]
pub enum Points {
    /// A straight move: start and end.
    Two([[f64; 2]; 2]),
    /// Any other number of points.
    Many(Box<[[f64; 2]]>),
}

impl std::ops::Deref for Points {
    type Target = [[f64; 2]];
    fn deref(&self) -> &Self::Target {
        match self {
            Self::Two(p) => p,
            Self::Many(p) => p,
        }
    }
}

impl From<Vec<[f64; 2]>> for Points {
    fn from(v: Vec<[f64; 2]>) -> Self {
        match <[[f64; 2]; 2]>::try_from(v.as_slice()) {
            Ok(two) => Self::Two(two),
            Err(_) => Self::Many(v.into_boxed_slice()),
        }
    }
}

/// A rapid move that ran into stock, a tool body that met stock, or a tool that entered
/// the chuck, its jaws or the tailstock.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Crash {
    /// Source line of the rapid.
    pub line: u32,
    /// Source column.
    pub column: u32,
    /// Where the tool first met stock, z (mm).
    pub z: f64,
    /// Where the tool first met stock, r (mm radius).
    pub r: f64,
    /// Stock area the rapid swept through, mm² of the half section.
    pub area_mm2: f64,
    /// Thickness of stock removed, normal to the move, mm.
    pub depth_mm: f64,
    /// The tool's non-cutting body that met stock ("holder", "boring bar", …); `None` for
    /// a rapid's cutting edge.
    pub body: Option<String>,
    /// The workholding the tool entered ("chuck face", "chuck jaw", "tailstock centre",
    /// "gripped length": cutting the blank inside the jaws); `None`: it met stock.
    pub obstacle: Option<String>,
    /// The tool's outline where it met the obstacle or stock (cutting outline and body, as
    /// convex parts in `[z, r]`), drawn at the crash; empty when unknown (the CLI fills
    /// the first 20 crashes).
    pub tool: Vec<Vec<[f64; 2]>>,
    /// A possible crash: its tool's outline is assumed (not in the verdict); drawn hollow.
    pub assumed: bool,
    /// Why it happened (the analysis's diagnosis); `None`: not diagnosed.
    pub cause: Option<Cause>,
    /// A fix the analysis has checked by re-running the program with it.
    pub remedy: Option<Remedy>,
}

/// Why a finding happened.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Cause {
    /// `trailing-edge`, `leading-edge`, `nose`, `compensation`, `body`, `rapid`,
    /// `workholding`, `other-tool` or `program`.
    pub kind: String,
    /// One sentence for a machinist.
    pub text: String,
    /// The measured numbers it rests on, e.g. `("flank_deg", 41.0)`.
    pub numbers: Vec<(String, f64)>,
}

/// A fix the analysis has checked by re-running the program with it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Remedy {
    /// One sentence for a machinist.
    pub text: String,
    /// The tool to use instead, for a tool change.
    pub tool: Option<String>,
    /// The program line to change, for a program change.
    pub line: Option<u32>,
    /// The block(s) as they should read, for a program change.
    pub edit: Option<String>,
    /// Whether the re-run confirmed it.
    pub verified: bool,
    /// A tool change's tool as mounted: its cutting outline relative to the reference
    /// point (`[dz, dr]` rings), drawn dashed by the HTML player on the finding's line;
    /// empty for a program change.
    pub ghost: Vec<Vec<[f64; 2]>>,
}

/// Material left that should be gone, with why.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Leftover {
    /// Its thickest place, z.
    pub z: f64,
    /// Its thickest place, r.
    pub r: f64,
    /// Area, mm² of the half section.
    pub area_mm2: f64,
    /// Its thickness there, mm.
    pub depth_mm: f64,
    /// Why it stayed.
    pub cause: Option<Cause>,
}

/// A piece of workholding drawn in the picture (light grey, labelled).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Fixture {
    /// "chuck face", "chuck jaw", "tailstock centre".
    pub name: String,
    /// Its section at r ≥ 0.
    pub shapes: Vec<Shape>,
}

/// Part material removed that should have stayed.
#[derive(Debug, Clone, PartialEq)]
pub struct Gouge {
    /// Source line whose sweep made it.
    pub line: u32,
    /// Position (deepest point), z.
    pub z: f64,
    /// Position (deepest point), r.
    pub r: f64,
    /// Area, mm² of the half section.
    pub area_mm2: f64,
    /// Largest distance from the intended boundary, mm.
    pub depth_mm: f64,
    /// A possible gouge: the tool that made it has an assumed outline (not in the
    /// verdict); drawn hatched instead of filled red.
    pub assumed: bool,
    /// Why it happened (the analysis's diagnosis); `None`: not diagnosed.
    pub cause: Option<Cause>,
    /// A fix the analysis has checked by re-running the program with it.
    pub remedy: Option<Remedy>,
}

/// Summary of final part versus intended shape.
#[derive(Debug, Clone, PartialEq)]
pub struct Deviation {
    /// Total overcut area (gouges), mm².
    pub overcut_area_mm2: f64,
    /// Total undercut area (leftovers), mm².
    pub undercut_area_mm2: f64,
    /// Deepest overcut, mm.
    pub max_overcut_mm: f64,
    /// Thickest leftover, mm.
    pub max_undercut_mm: f64,
}

/// An alarm or warning with its place in the program (line 0: not tied to a line).
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    /// 1-based line, 0 when the message concerns no line (e.g. a tool table default).
    pub line: u32,
    /// 1-based column.
    pub column: u32,
    /// Short stable code, e.g. `E-ARC-RADIUS` or `W-TOOL-DEFAULT`.
    pub code: String,
    /// What happened and what to change.
    pub message: String,
}

/// The blank, as described and as a polygon.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StockInfo {
    /// Human description, e.g. `bar Ø125 × 110, face at Z0`.
    pub description: String,
    /// The blank's half section.
    pub shapes: Vec<Shape>,
}

/// Everything the reports show.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Report {
    /// Program file name as given, e.g. `O0002.nc`.
    pub program: String,
    /// Program number or title, e.g. `O0002`; may be empty.
    pub title: String,
    /// The control the program was read for (`--control`), e.g. `haas`; empty in reports
    /// made without one.
    pub control: String,
    /// The text encoding the program was read in (`UTF-8`, `GBK`, …; WHATWG names);
    /// empty when unknown.
    pub encoding: String,
    /// The blank.
    pub stock: StockInfo,
    /// The final half section after all removal.
    pub final_part: Vec<Shape>,
    /// The intended part (dashed overlay); empty when none is known.
    pub intended: Vec<Shape>,
    /// The toolpath, one entry per segment; empty when only the JSON report is written,
    /// which does not list it (a million-move run saves 48 MB).
    pub toolpath: Vec<PathLine>,
    /// Rapids into stock deeper than the machine's `rapid_cut_tol`.
    pub crashes: Vec<Crash>,
    /// Rapids that scrape stock no deeper than `rapid_cut_tol` (warnings, not crashes).
    pub rapid_cuts: Vec<Crash>,
    /// Overcuts against the intended shape.
    pub gouges: Vec<Gouge>,
    /// Leftovers, drawn orange with a darker 2 px outline (areas only; no line
    /// attribution); the one [`Report::leftover_spot`] names gets a detail view after the
    /// findings and grooves, as room allows.
    pub leftovers: Vec<Shape>,
    /// The leftovers as findings (place, size, cause), in the order of
    /// [`Report::leftovers`].
    pub leftover_list: Vec<Leftover>,
    /// The largest leftover's thickest place (measured by the simulator), where its
    /// detail view looks; `None`: no leftover view.
    pub leftover_spot: Option<LeftoverSpot>,
    /// Gouge areas, drawn red with a darker 2 px outline (hatched for the gouges of
    /// [`Report::gouges`] at the same place that are `assumed`).
    pub gouge_shapes: Vec<Shape>,
    /// `None` when there is no intended shape.
    pub deviation: Option<Deviation>,
    /// Controller alarms (the run stopped or is wrong).
    pub alarms: Vec<Diagnostic>,
    /// Warnings (assumed defaults, spindle stopped, …).
    pub warnings: Vec<Diagnostic>,
    /// One line per tool used, e.g. `T01 turning V 35°, r0.4, tip 3`.
    pub tools: Vec<String>,
    /// Removed half-section area, mm².
    pub removed_area_mm2: f64,
    /// Removed volume (solid of revolution), mm³.
    pub removed_volume_mm3: f64,
    /// Number of segments simulated.
    pub segments: usize,
    /// Rapid segments among them.
    pub rapid_segments: usize,
    /// Estimated cycle time, s.
    pub cycle_time_s: f64,
    /// Deviation tolerance, mm.
    pub tolerance_mm: f64,
    /// The stock at a few points of the run, in move order, for the HTML report's move
    /// slider; empty when not recorded (the CLI fills a few dozen for small programs).
    pub snapshots: Vec<Snapshot>,
    /// The G75.1 grooves the program defines, each drawn as a zoomed detail view (after
    /// the crash and gouge details, as room allows); empty when there are none. The CLI
    /// fills it.
    pub grooves: Vec<Groove>,
    /// Custom macro B: the variables the run read or set and their final values (`None`:
    /// vacant), e.g. `("#1", Some(14.0))`.
    pub variables: Vec<(String, Option<f64>)>,
    /// Custom macro B: source lines executed more than once, with how many times.
    pub line_counts: Vec<(u32, u64)>,
    /// The threads the program cuts, checked in the final section (the CLI fills it).
    pub threads: Vec<ThreadCheck>,
    /// The chuck, jaws and tailstock centre given to the run; empty when none.
    pub fixture: Vec<Fixture>,
    /// The tools' outlines as mounted, for the HTML player to draw the tool at the current
    /// move; empty: no tool drawn.
    pub tool_outlines: Vec<ToolOutline>,
    /// Which outline each move uses: (index of the first move of a run, index into
    /// [`Report::tool_outlines`]), in move order.
    pub tool_runs: Vec<(usize, usize)>,
    /// The outcome, as the analysis decided it.
    pub verdict: Verdict,
    /// The tools for the HTML page's setup sheet, in order of first use; empty: the sheet
    /// lists [`Report::tools`] instead (the CLI fills it). Not in the JSON.
    pub tool_list: Vec<ToolEntry>,
    /// The blank's stick-out from the chuck jaws' front, mm; `None`: no chuck given.
    /// Not in the JSON (its stock description says it).
    pub stick_out_mm: Option<f64>,
}

/// One tool as the setup sheet lists it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToolEntry {
    /// T number; 0: the tool that cuts before the program's first T word.
    pub number: u32,
    /// The offset numbers the program called it with (`T0101` → 1), in order of first use.
    pub offsets: Vec<u32>,
    /// What it is, e.g. `turning C 80°, r0.8, tip 3, κr 95°`.
    pub description: String,
    /// The ISO designations the tool table gave it by, e.g. `CNMG 120408 in PCLNR 2525M12`.
    pub designation: Option<String>,
    /// The tool table does not state its size (no entry: the default tool; an insert with
    /// no edge nor ISO designation): its outline is assumed.
    pub assumed: bool,
    /// The tool table has an entry for it (with `assumed`: its size is what is missing).
    pub in_table: bool,
    /// It has no entry and is taken for what its moves say (a threading insert, a drill, a
    /// boring bar), not the default insert.
    pub from_moves: bool,
    /// The time of all its moves, s.
    pub time_s: f64,
    /// The time of its cutting (feed and thread) moves, s.
    pub cut_time_s: f64,
}

/// A tool's outline relative to its reference point, `[z, r]`: the cutting outline and the
/// body (holder, shank, bar), each as convex parts.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ToolOutline {
    /// The insert, blade or drill.
    pub edge: Vec<Vec<[f64; 2]>>,
    /// The non-cutting body (empty when the table states none).
    pub body: Vec<Vec<[f64; 2]>>,
}

/// One thread (a thread cycle or a run of thread passes) and its depth as cut.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThreadCheck {
    /// Source line (1-based) of its first pass.
    pub line: u32,
    /// Cut in the bore (an ID thread) rather than the outside.
    pub inside: bool,
    /// Programmed lead, mm.
    pub lead_mm: f64,
    /// Number of starts (the pitch is the lead over it); 0 or 1: one.
    pub starts: usize,
    /// Programmed final X (the deepest pass's end): minor diameter (OD), major (ID).
    pub x_mm: f64,
    /// The diameter that should be reached: `--target`'s surface over the thread, else
    /// [`ThreadCheck::x_mm`]; `None`: not measurable (no material there).
    pub expected_x_mm: Option<f64>,
    /// Radial depth of each pass, mm.
    pub pass_depths_mm: Vec<f64>,
    /// Minor (OD) / major (ID) diameter reached in the final section over the thread's
    /// length; `None`: no material there.
    pub achieved_x_mm: Option<f64>,
    /// Achieved depth minus the expected depth, radial mm (positive: too deep).
    pub depth_error_mm: Option<f64>,
    /// Pitch diameter of the thread as cut (where groove and tooth are equally wide), mm;
    /// `None`: not measurable (shorter than a pitch clear of the ends, or too shallow).
    pub pitch_diameter_mm: Option<f64>,
    /// Included angle of the groove's flanks as cut, degrees; `None`: not measurable.
    pub included_angle_deg: Option<f64>,
    /// Z where the deepest pass starts and ends (the programmed root line), mm: where the
    /// picture's thread detail looks.
    pub z_start_mm: f64,
    /// See [`ThreadCheck::z_start_mm`].
    pub z_end_mm: f64,
}

/// A G75.1 groove the program defines, as its intended outline.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Groove {
    /// Source line (1-based) of the block that defines the groove.
    pub line: u32,
    /// The groove's outline as a closed ring in `[z, r]` (first point not repeated), in
    /// the order of its corners (for the spec's trapezoid: P1, P2, P3, P4). The corner
    /// labels of the detail view are numbered in this order.
    pub ring: Vec<[f64; 2]>,
    /// The largest distance between the ring and the final part's boundary, mm (measured
    /// by the simulator; shown rounded up in the detail view's title); `None`: not
    /// measured.
    pub deviation_mm: Option<f64>,
}

/// Where the detail view of a leftover looks: its thickest place.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeftoverSpot {
    /// Which leftover (index into [`Report::leftovers`]).
    pub leftover: usize,
    /// Centre of the view, `[z, r]`.
    pub centre: [f64; 2],
    /// The leftover's thickness there, mm; `None` when no intended shape is known.
    pub thickness: Option<f64>,
    /// Where the thickness is measured, `[from, to]`, drawn as a mark; `None` when no
    /// intended shape is known.
    pub measure: Option<[[f64; 2]; 2]>,
}

/// The stock as it was part-way through the run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Snapshot {
    /// How many moves (entries of [`Report::toolpath`]) had run: 0 is the blank, and
    /// `toolpath.len()` the final part.
    pub after_move: usize,
    /// The stock's half section after those moves.
    pub shapes: Vec<Shape>,
}

/// The one-word outcome shown in the title block and the JSON (decided by the analysis).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Verdict {
    /// No alarm, crash or gouge.
    #[default]
    Clean,
    /// A controller alarm stopped or corrupted the run.
    Alarm,
    /// A rapid ran into stock, a tool's body met stock, or a tool entered the chuck, its
    /// jaws or the tailstock (or cut inside the jaws).
    Crash,
    /// Part material removed (a gouge, or a thread cut deeper than expected by more than
    /// the tolerance).
    Gouge,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A straight move's two points are held in the line (no allocation); other counts in
    /// a box; either reads as the slice of points (issue 16: a million-move report).
    #[test]
    fn points_of_a_straight_move_are_held_in_place() {
        let two = Points::from(vec![[1.0, 2.0], [3.0, 4.0]]);
        assert!(matches!(two, Points::Two(_)));
        assert_eq!(&*two, &[[1.0, 2.0], [3.0, 4.0]]);
        let three = Points::from(vec![[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]);
        assert!(matches!(three, Points::Many(_)));
        assert_eq!(three.len(), 3);
        assert!(Points::from(vec![]).is_empty());
        assert!(std::mem::size_of::<PathLine>() <= 48);
    }
}
