//! CAD profiles on the command line: `--stock-file` and `--target` take a DXF drawing of
//! the half section, and `--dxf F` writes the final half section (layer `PART`) with the
//! intended part (layer `INTENDED`). The geometry is `tooling_iso::dxf_io` (on the `dxf`
//! crate); this file only picks the format by extension and turns rings into shapes.

use crate::cli::DxfXArg;
use crate::diag;
use geom::Pt;
use std::path::Path;
use tooling_iso::dxf_io::{self, ReadOptions, XMode};

/// Whether a profile file is a DXF drawing (by its extension), not a profile TOML.
pub(crate) fn is_dxf(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("dxf"))
}

fn x_mode(arg: DxfXArg) -> XMode {
    match arg {
        DxfXArg::Radius => XMode::Radius,
        DxfXArg::Diameter => XMode::Diameter,
    }
}

/// Which layer of a drawing written by `--dxf` a profile flag reads.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Role {
    /// `--stock-file`: the `PART` layer when there is one.
    Blank,
    /// `--target`: the `INTENDED` layer when there is one.
    Target,
}

/// The closed outlines of a DXF half section as rings `[z, r]` that fill by the non-zero
/// rule: a loop inside an odd number of other loops is a hole, so it is turned clockwise
/// (the reader gives every loop counter-clockwise).
///
/// **Interpretation:** a drawing that has a `PART` or `INTENDED` layer (latsim's own
/// `--dxf` output) is read for that role's layer only; any other drawing, every layer.
pub(crate) fn read_rings(path: &Path, x: DxfXArg, role: Role) -> Result<Vec<Vec<[f64; 2]>>, ()> {
    let (what, layer) = match role {
        Role::Blank => ("stock file", "PART"),
        Role::Target => ("target", "INTENDED"),
    };
    let opts = ReadOptions {
        x_mode: x_mode(x),
        prefer_layer: Some(layer),
        ..ReadOptions::default()
    };
    let rings = dxf_io::read_profile_file(path, &opts).map_err(|e| {
        diag::print_plain(
            &format!("{what} {}: {e}", path.display()),
            "draw the half section as closed LINE/ARC/LWPOLYLINE loops in the drawing's XY \
             plane (X = lathe Z, Y = radius, or diameter with --dxf-x diameter)",
        );
    })?;
    let depth = |i: usize| {
        let p = rings[i][0];
        rings
            .iter()
            .enumerate()
            .filter(|&(j, r)| j != i && geom::ring::contains(r, p))
            .count()
    };
    Ok((0..rings.len())
        .map(|i| {
            let mut ring: Vec<[f64; 2]> = rings[i].iter().map(|p| [p.z, p.r]).collect();
            if depth(i) % 2 == 1 {
                ring.reverse();
            }
            ring
        })
        .collect())
}

/// The final half section and the intended part as DXF text (`AutoCAD` 2000).
pub(crate) fn section_dxf(report: &render::Report, x: DxfXArg) -> Result<Vec<u8>, String> {
    let rings = |shapes: &[render::Shape]| -> Vec<Vec<Pt>> {
        shapes
            .iter()
            .flat_map(|s| std::iter::once(&s.outer).chain(&s.holes))
            .map(|r| r.iter().map(|p| Pt::new(p[0], p[1])).collect())
            .collect()
    };
    let part = rings(&report.final_part);
    let intended = rings(&report.intended);
    dxf_io::write_section_string(
        &part,
        (!intended.is_empty()).then_some(intended.as_slice()),
        x_mode(x),
    )
    .map(String::into_bytes)
    .map_err(|e| format!("cannot write the DXF: {e}"))
}
