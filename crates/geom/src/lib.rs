//! latsim's plane-geometry kernel. Everything in latsim lives in the (z, r) half plane
//! (z axial, r = X / 2); this crate is the one vocabulary for it:
//!
//! - [`Pt`]: a point or vector with arithmetic,
//! - [`Rect`]: an axis-aligned box,
//! - [`arc`]: circular arcs and the one routine that chords them,
//! - [`ring`]: closed rings (area, moments, point in ring, convex hull),
//! - [`distance`]: point–segment and point–polyline distances, Hausdorff distance,
//! - [`flat`]: convex parts, sweeps, Minkowski sums and clipping on `[f64; 2]` points.
//!
//! Algorithms come from **geo** (area, containment, hull, Hausdorff, simplification) and
//! **parry2d-f64** (projection onto polylines); boolean operations live in the `stock`
//! crate behind its `i_overlay` integration. Where a hand-written routine is kept, its doc
//! comment says why (with the measurement in ARCHITECTURE.md).

pub mod arc;
pub mod distance;
pub mod flat;
mod pt;
mod rect;
pub mod ring;

pub use pt::{orient, Pt};
pub use rect::Rect;
