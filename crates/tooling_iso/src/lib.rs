//! Tools as machinists name them, and CAD profiles in and out (issue 15).
//!
//! - [`insert`]: ISO 1832 insert designations (`"CNMG 120408"`, inch `"CNMG 432"`),
//! - [`holder`]: ISO 5608 holders (`"PCLNR 2525M12"`) and boring bars (`"S20R-SCLCR09"`),
//! - [`turning_facts`]: an insert in a holder → the facts a turning tool outline needs,
//! - [`dxf_io`]: closed profiles from DXF (LINE, ARC, LWPOLYLINE and R12 POLYLINE with
//!   bulges) and half sections written as DXF.
//!
//! DXF goes through the [`dxf`](https://crates.io/crates/dxf) crate (ixmilia/dxf-rs, 0.6):
//! pure Rust, MIT, maintained since 2017 with releases into 2025, reads ASCII and binary DXF
//! from R10 to R2018 (so both R12 files and the 2000+ files CAD programs save by default)
//! and writes any of those versions, with typed entities (bulges, OCS normals) generated
//! from the DXF reference. It is the one crate on crates.io that both reads and writes.

pub mod dxf_io;
pub mod holder;
pub mod insert;

pub use holder::{Hand, Holder, Shank};
pub use insert::{Insert, Shape};

/// Everything that can go wrong in this crate.
#[derive(Debug, thiserror::Error)]
pub enum IsoError {
    /// A bad insert designation.
    #[error("insert \"{designation}\": {problem}; {}", insert::INSERT_FORM)]
    Insert {
        /// The designation as given.
        designation: String,
        /// What is wrong.
        problem: String,
    },
    /// A bad holder designation.
    #[error("holder \"{designation}\": {problem}; {}", holder::HOLDER_FORM)]
    Holder {
        /// The designation as given.
        designation: String,
        /// What is wrong.
        problem: String,
    },
    /// An insert that the holder does not take.
    #[error("insert \"{insert}\" does not fit holder \"{holder}\": {problem}")]
    Mismatch {
        /// The insert designation.
        insert: String,
        /// The holder designation.
        holder: String,
        /// What differs, naming both sides.
        problem: String,
    },
    /// A DXF file that cannot be read or written.
    #[error("DXF: {0}")]
    Dxf(String),
    /// An outline whose chain of entities does not close.
    #[error(
        "DXF: the outline is open: nothing continues from ({x}, {y}) (drawing units, within {tol})"
    )]
    Open {
        /// Drawing X of the loose end.
        x: f64,
        /// Drawing Y of the loose end.
        y: f64,
        /// The joining tolerance.
        tol: f64,
    },
    /// An outline that crosses itself.
    #[error("DXF: the outline crosses itself near ({x}, {y}) (drawing units)")]
    SelfIntersecting {
        /// Drawing X of the crossing.
        x: f64,
        /// Drawing Y of the crossing.
        y: f64,
    },
}

/// What an insert in a holder gives a turning tool (the `stock` outline's inputs).
#[derive(Debug, Clone, PartialEq)]
pub struct TurningFacts {
    /// Insert shape letter.
    pub shape: Shape,
    /// Included angle ε, degrees (360 round).
    pub included_angle: f64,
    /// Cutting edge length, mm.
    pub edge_length: f64,
    /// Nose radius, mm.
    pub nose_radius: f64,
    /// Entering angle κr, degrees.
    pub entering_angle: f64,
    /// The holder faces (end-cutting style F, K, Y).
    pub end_cutting: bool,
    /// Hand.
    pub hand: Hand,
    /// Boring bar (ID) or external (OD).
    pub internal: bool,
    /// Imaginary tip number (spec/tnrc.md): OD R 3, OD L 4, ID R 2, ID L 1, neutral 8 (OD)
    /// or 6 (ID).
    pub tip: u8,
    /// Shank section.
    pub shank: Shank,
    /// Holder length, mm, when the designation gives it.
    pub length: Option<f64>,
}

/// The imaginary tip (spec/tnrc.md) for a holder's hand, OD or ID, cutting the usual way: a
/// right-hand OD holder turns toward the chuck, nose centre above and right of the tip
/// (tip 3); left hand mirrors Z (4); a boring bar mirrors X (2, 1); a neutral holder points
/// its bisector at the part (8 OD, 6 ID).
pub fn tip_for(hand: Hand, internal: bool) -> u8 {
    match (hand, internal) {
        (Hand::R, false) => 3,
        (Hand::L, false) => 4,
        (Hand::R, true) => 2,
        (Hand::L, true) => 1,
        (Hand::N, false) => 8,
        (Hand::N, true) => 6,
    }
}

/// An insert in a holder: checks the holder takes the insert (shape, clearance, size) and
/// that the trailing edge clears the part (κr + ε < 180°), then gives the facts.
pub fn turning_facts(insert: &Insert, holder: &Holder) -> Result<TurningFacts, IsoError> {
    let mismatch = |problem: String| IsoError::Mismatch {
        insert: insert.designation.clone(),
        holder: holder.designation.clone(),
        problem,
    };
    if insert.shape != holder.shape {
        return Err(mismatch(format!(
            "the insert is shape {} ({}), the holder's pocket takes shape {} ({})",
            insert.shape.letter(),
            insert.shape.describe(),
            holder.shape.letter(),
            holder.shape.describe()
        )));
    }
    if insert.clearance != holder.clearance {
        return Err(mismatch(format!(
            "the insert has clearance letter {}, the holder takes clearance {}",
            insert.clearance, holder.clearance
        )));
    }
    if insert.edge_code() != holder.insert_size {
        return Err(mismatch(format!(
            "the insert's edge is {:.2} mm (size {:02}), the holder takes size {:02}",
            insert.edge_length,
            insert.edge_code(),
            holder.insert_size
        )));
    }
    let kr = holder.style.entering_angle;
    let eps = insert.included_angle();
    if insert.shape != Shape::R && kr + eps >= 180.0 {
        return Err(mismatch(format!(
            "style {} (κr {kr}°) with a {eps}° insert leaves the trailing edge no clearance",
            holder.style.letter
        )));
    }
    Ok(TurningFacts {
        shape: insert.shape,
        included_angle: eps,
        edge_length: insert.edge_length,
        nose_radius: insert.nose_radius,
        entering_angle: kr,
        end_cutting: holder.style.end_cutting,
        hand: holder.hand,
        internal: holder.is_internal(),
        tip: tip_for(holder.hand, holder.is_internal()),
        shank: holder.shank,
        length: holder.length,
    })
}

/// [`turning_facts`] from the two designations.
pub fn turning_facts_from(insert: &str, holder: &str) -> Result<TurningFacts, IsoError> {
    turning_facts(&Insert::parse(insert)?, &Holder::parse(holder)?)
}

/// A designation as written (trimmed, for messages) and as read: its characters without
/// spaces, in upper case.
fn normalized(text: &str) -> (String, Vec<char>) {
    let designation = text.trim().to_string();
    let chars = designation
        .chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| c.to_ascii_uppercase())
        .collect();
    (designation, chars)
}
