//! Material removal: final = blank − ⋃ sweeps, with rapid crashes as exact events.
//!
//! How it stays fast for 10⁶ moves (measured figures in `PERFORMANCE.md`):
//! - every boolean runs in `i_overlay`'s integer core on one fixed grid (see `overlay.rs`);
//! - the stock is cut into Z strips, each its own small polygon set, so a boolean call
//!   only sees the stock near the move; strips are independent, so they run in parallel;
//! - within a strip, sweeps are subtracted in batches of [`BATCH`]: one call removes the
//!   union of the batch (no sweep-by-sweep subtraction from an ever-growing polygon, no
//!   single giant call with k² tool-tool intersections); a sweep that one in the batch
//!   covers where the tile has stock is left out, and one that covers those takes their
//!   place ([`SimOptions::cover`]: a roughing's passes then make one call per tile and
//!   epoch);
//! - sweeps that cannot touch a subtree's stock box (box overlap, then a separating axis)
//!   never descend into it, and those that miss a tile's stock (air cuts) never reach a
//!   boolean call;
//! - collinear overlapping feeds (pecks) were already merged into one sweep, as were
//!   chains of nearly collinear short feeds (within [`SimOptions::merge_tol`]), and short
//!   paths of feeds are swept as one ring ([`SimOptions::feed_paths`]);
//! - in long programs, passes that repeat the one before moved by a tiny step are one
//!   sweep ([`SimOptions::pass_groups`], the `pass_group` module).
//!
//! Crashes: a rapid whose box meets a strip's stock box flushes that strip's batch (so
//! the stock is exactly the stock after every earlier move) and intersects its sweep with
//! it; the overlaps of all strips add up to the crash area.

mod batch;
mod crash;
mod epoch;
mod stitch;
#[cfg(test)]
pub(crate) mod tests;
mod tile;

pub use crash::Crash;

use crate::budget::{OverBudget, RunMemory};
use crate::overlay::{Engine, Grid, IShapes};
use crate::{area, revolved_volume, Blank, Shape, ToolTable};
pub(crate) use epoch::joined;
use epoch::Strips;
use epoch::{Cuts, Epochs};
use expander::Segment;
use geom::flat::pts;
use geom::Rect;

/// Smallest overlap (mm²) between a rapid's sweep and the stock that counts as a crash.
/// The threshold actually used for a rapid is the larger of this and 2 × grid step × the
/// sweep's perimeter, the biggest sliver rounding to the grid can create along an edge the
/// rapid shares with an earlier cut (a few 10⁻⁵ mm² for a 100 mm bar: ~0.1 nm grid step).
pub const CRASH_MIN_AREA: f64 = 1e-6;

/// Options of a removal run.
#[derive(Debug, Clone, PartialEq)]
pub struct SimOptions {
    /// Chord tolerance for arcs, mm (default 0.001).
    pub chord_tol: f64,
    /// Chains of short feed moves (same tool, no rapid in between, never turning back) are
    /// swept as one straight move while every programmed point lies within this distance
    /// of it, mm (default 0.0005; capped at `chord_tol`; 0 or not finite: only exactly
    /// collinear feeds merge). The final part then differs from the unmerged result by at
    /// most this much wherever it was cut (see the `sweep` module). Arcs take part with
    /// their chord when it lies within `chord_tol − merge_tol` of them.
    pub merge_tol: f64,
    /// Consecutive feeds of one tool (each starting where the last ended, no rapid in
    /// between, a tool without a body to probe) are swept as one path of up to 128
    /// vertices: one ring, the exact Minkowski sum of the outline with the polyline
    /// (default true). Exact either way; false sweeps each (merged) move on its own.
    pub feed_paths: bool,
    /// A ring (a path or chorded arc swept as one, see `feed_paths`) is told apart from a
    /// tile's or subtree's stock box by its edges, a few box tests for most of them
    /// (default true). Exact either way; false tries every tile its box overlaps with the
    /// ring's full edge test.
    pub ring_air: bool,
    /// A sweep that a sweep already waiting in a tile's batch covers there (inside the
    /// tile's stock box) stays out of the batch, and a sweep takes out of the batch those it
    /// covers (default true): the passes of a roughing, each lowering a flat top, then make
    /// one boolean call per tile and epoch instead of one per pass. Exact either way; false
    /// sends every sweep that touches a tile's stock to its boolean call.
    pub cover: bool,
    /// Repeated passes (each the last moved by at most `merge_tol`, every vertex on its own
    /// line) are cut as the one region they sweep together, within `merge_tol / 2` of their
    /// union (default true; see the `pass_group` module). Only in programs of more than
    /// [`crate::snapshot::EXACT_MAX_MOVES`] moves: shorter ones are cut pass by pass, so
    /// their snapshots stay exact. False cuts every pass on its own.
    pub pass_groups: bool,
    /// Move counts after which the stock is wanted (see [`Simulation::snapshots`]), taken
    /// in the same pass. Counts of 0 or of all the moves and more are ignored: those are
    /// the blank and [`Simulation::final_shapes`].
    pub snapshot_after: Vec<usize>,
    /// Move counts after which the stock is wanted exactly whatever the program's length:
    /// an epoch ends at each (a long program's [`SimOptions::snapshot_after`] are taken at
    /// the removal's own epoch ends). Few: a thread's first move and its end.
    pub snapshot_exact: Vec<usize>,
    /// The run's memory budget (`None`: no limit). Over it the removal stops where it is
    /// ([`Simulation::over_budget`]).
    pub max_memory: Option<RunMemory>,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            chord_tol: 0.001,
            merge_tol: 0.0005,
            feed_paths: true,
            ring_air: true,
            cover: true,
            pass_groups: true,
            snapshot_after: Vec::new(),
            snapshot_exact: Vec::new(),
            max_memory: None,
        }
    }
}

/// The result of a removal run.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    /// The part after every move.
    pub final_shapes: Vec<Shape>,
    /// Rapids through stock, in program order.
    pub crashes: Vec<Crash>,
    /// Area of the half section removed, mm².
    pub removed_area: f64,
    /// Volume removed (solid of revolution), mm³.
    pub removed_volume: f64,
    /// (first segment index, message): skipped moves, defaulted tools.
    pub warnings: Vec<(usize, String)>,
    /// (move count k, the stock after the first k moves) for each count asked for in
    /// [`SimOptions::snapshot_after`], ascending. A merged chain of feeds still open at k
    /// is cut up to its last move so far; the run itself goes on unchanged. Programs of more
    /// than 5 000 moves get them at the removal's epoch ends instead: k is then the first
    /// count at or after the one asked for where all tiles are flushed (one snapshot for
    /// several counts when they fall in one epoch).
    pub snapshots: Vec<(usize, Vec<Shape>)>,
    /// The run went over [`SimOptions::max_memory`]: the removal stopped there (the part is
    /// the stock as it stood), and what grew.
    pub over_budget: Option<OverBudget>,
}

/// Removes material: `blank` minus the sweep of every segment's tool outline, in order,
/// reporting rapids that run through stock as [`Crash`]es. `progress` is called now and
/// then with the number of segments processed. Never panics: moves with non-finite
/// coordinates are skipped with a warning.
pub fn simulate(
    blank: &Blank,
    tools: &ToolTable,
    segments: &[Segment],
    opts: &SimOptions,
    progress: &mut dyn FnMut(usize),
) -> Simulation {
    let mut warnings = Vec::new();
    let Some((shapes, bb)) = usable_blank(blank, &mut warnings) else {
        progress(segments.len());
        return Simulation::uncut(warnings);
    };
    // Sweeps are clipped to the blank's box plus a margin: outside it there is no stock
    // to remove, and clipping keeps huge coordinates from coarsening the grid.
    let margin = 1.0 + 1e-3 * bb.size();
    let clip = bb.grown(margin);
    let grid = Grid::new(bb.grown(2.0 * margin));
    let mut engine = Engine::new();
    let stock = grid.shapes_to_int(&shapes);
    let strips = Strips::new(&grid, &clip, &bb, &stock, &mut engine);
    let mut epochs = Epochs::new(&grid, clip, tools, segments, opts, &shapes);
    let mut cuts = epochs.cut_all(&strips, (&grid, &mut engine), opts, progress);
    warnings.append(&mut cuts.warnings);
    warnings.append(&mut epochs.builder.warnings);
    warnings.sort_by_key(|w| w.0);
    let mut snapshots = std::mem::take(&mut epochs.snapshots.out);
    // (a pinned count's snapshot comes before the epoch end's that holds fewer cut moves)
    snapshots.sort_by_key(|(k, _)| *k);
    assemble(
        &shapes,
        strips,
        cuts,
        snapshots,
        (&grid, &mut engine),
        warnings,
    )
}

/// The blank's shapes with finite coordinates, and their box; `None` when that leaves
/// nothing to cut (each with a warning).
fn usable_blank(blank: &Blank, warnings: &mut Vec<(usize, String)>) -> Option<(Vec<Shape>, Rect)> {
    let shapes: Vec<Shape> = blank
        .shapes
        .iter()
        .filter(|s| {
            s.outer
                .iter()
                .flat_map(|p| p.iter())
                .all(|v| v.is_finite() && v.abs() < 1e9)
        })
        .cloned()
        .collect();
    let bb = Rect::of(shapes.iter().flat_map(|s| pts(&s.outer)));
    if shapes.len() != blank.shapes.len() {
        warnings.push((
            0,
            "blank shapes with non-finite coordinates were ignored".to_string(),
        ));
    }
    if bb.is_empty() || area(&shapes) <= 0.0 {
        warnings.push((0, "the blank is empty: nothing to cut".to_string()));
        return None;
    }
    Some((shapes, bb))
}

/// The run's result from the cut strips: the final part (showing the pieces that fell
/// where they were parted off), the crashes, what was removed and the snapshots.
fn assemble(
    shapes: &[Shape],
    strips: Strips,
    cuts: Cuts,
    snapshots: Vec<(usize, IShapes)>,
    (grid, engine): (&Grid, &mut Engine),
    warnings: Vec<(usize, String)>,
) -> Simulation {
    let tiles = strips.into_parts();
    let stock = if cuts.fallen.is_empty() {
        epoch::joined(&tiles, engine)
    } else {
        let mut parts: Vec<IShapes> = tiles.into_iter().map(|(_, s)| s).collect();
        parts.extend(cuts.fallen.iter().map(|(_, f)| f.clone()));
        engine.union(&parts)
    };
    let final_shapes = grid.shapes_to_float(&stock);
    let crashes = crash::merge_fragments(cuts.fragments);
    let removed_area = area(shapes) - area(&final_shapes);
    let removed_volume = revolved_volume(shapes) - revolved_volume(&final_shapes);
    let snapshots = snapshots
        .iter()
        .map(|(k, s)| {
            // the pieces that fell before the snapshot, where they were parted off
            let before: Vec<&IShapes> = cuts
                .fallen
                .iter()
                .filter(|(at, _)| at < k)
                .map(|(_, f)| f)
                .collect();
            if before.is_empty() {
                return (*k, grid.shapes_to_float(s));
            }
            let mut parts = vec![s.clone()];
            parts.extend(before.into_iter().cloned());
            (*k, grid.shapes_to_float(&engine.union(&parts)))
        })
        .collect();
    Simulation {
        final_shapes,
        crashes,
        removed_area,
        removed_volume,
        warnings,
        snapshots,
        over_budget: cuts.over_budget,
    }
}

impl Simulation {
    /// The result of a run with nothing to cut.
    fn uncut(warnings: Vec<(usize, String)>) -> Self {
        Self {
            final_shapes: Vec::new(),
            crashes: Vec::new(),
            removed_area: 0.0,
            removed_volume: 0.0,
            warnings,
            snapshots: Vec::new(),
            over_budget: None,
        }
    }
}
