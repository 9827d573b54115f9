//! Profiles from DXF and half sections to DXF, in the ZX plane: the drawing's X is the
//! lathe's Z, the drawing's Y is the lathe's X, either as a radius or as a diameter
//! ([`XMode`]).
//!
//! Reading takes LINE, ARC, LWPOLYLINE and (R12) POLYLINE entities with bulges from the
//! model space, chains them end to end into closed loops, chords every arc within the
//! tolerance with [`geom::arc::Arc`], and rejects open or self-crossing loops. Arcs are
//! chorded in drawing units before a diameter Y is halved, so the chords stay within the
//! tolerance of the drawn curve. Writing gives closed LWPOLYLINEs on layers `PART` and
//! `INTENDED` in an `AutoCAD` 2000 file.

use crate::IsoError;
use dxf::entities::{Entity, EntityType, LwPolyline};
use dxf::enums::AcadVersion;
use dxf::tables::Layer;
use dxf::Drawing;
use dxf::LwPolylineVertex;
use geom::arc::Arc;
use geom::Pt;

/// How the drawing's Y maps to the lathe's X.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum XMode {
    /// Y is the radius (the true section: arcs are circles).
    Radius,
    /// Y is the diameter (r = Y / 2).
    Diameter,
}

impl XMode {
    fn to_r(self, y: f64) -> f64 {
        match self {
            Self::Radius => y,
            Self::Diameter => y / 2.0,
        }
    }
    fn to_y(self, r: f64) -> f64 {
        match self {
            Self::Radius => r,
            Self::Diameter => r * 2.0,
        }
    }
}

/// Options for reading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReadOptions {
    /// Y as radius or diameter.
    pub x_mode: XMode,
    /// Largest distance of a chord from its arc, drawing units (default 0.0001).
    pub chord_tol: f64,
    /// Ends closer than this join (default 0.001 drawing units).
    pub join_tol: f64,
    /// Read only entities on this layer (default: all).
    pub layer: Option<&'static str>,
    /// Without `layer`: read only this layer when the drawing has entities on it, else all
    /// (a section written by [`section_drawing`] holds the part and the intended outline on
    /// two layers whose loops share corners; each is one profile).
    pub prefer_layer: Option<&'static str>,
}

impl Default for ReadOptions {
    fn default() -> Self {
        Self {
            x_mode: XMode::Radius,
            chord_tol: 0.0001,
            join_tol: 0.001,
            layer: None,
            prefer_layer: None,
        }
    }
}

/// A piece of outline in drawing coordinates: its points from start to end (arcs chorded).
#[derive(Debug, Clone)]
struct Piece {
    pts: Vec<Pt>,
}

fn bulge_points(p0: Pt, p1: Pt, bulge: f64, tol: f64) -> Vec<Pt> {
    if bulge.abs() < 1e-12 || p0.dist(p1) < 1e-15 {
        return vec![p0, p1];
    }
    // included angle θ = 4·atan(bulge), counter-clockwise when positive; the centre lies
    // (1 − b²)/(4b) chord lengths to the left of the chord's midpoint
    let c = p1 - p0;
    let centre = (p0 + p1) / 2.0 + c.perp() * ((1.0 - bulge * bulge) / (4.0 * bulge));
    let arc = Arc::between(p0, p1, centre, bulge > 0.0);
    let mut pts = arc.flatten(tol);
    // exact ends
    pts[0] = p0;
    if let Some(last) = pts.last_mut() {
        *last = p1;
    }
    pts
}

/// The pieces of a (LW)POLYLINE, its vertices taken from its object coordinate system
/// (extrusion `normal_z`) into the drawing's.
fn polyline_pieces(v: &[(Pt, f64)], closed: bool, normal_z: f64, tol: f64, out: &mut Vec<Piece>) {
    let mut local = Vec::new();
    vertex_pieces(v, closed, tol, &mut local);
    for piece in &mut local {
        for q in &mut piece.pts {
            *q = ocs(normal_z, *q);
        }
    }
    out.extend(local);
}

fn vertex_pieces(verts: &[(Pt, f64)], closed: bool, tol: f64, out: &mut Vec<Piece>) {
    let n = verts.len();
    if n < 2 {
        return;
    }
    let count = if closed { n } else { n - 1 };
    for i in 0..count {
        let (p0, b) = verts[i];
        let (p1, _) = verts[(i + 1) % n];
        if p0.dist(p1) > 0.0 {
            out.push(Piece {
                pts: bulge_points(p0, p1, b, tol),
            });
        }
    }
}

/// Mirror for an entity drawn with its extrusion along −Z (the OCS X axis flips).
fn ocs(z: f64, p: Pt) -> Pt {
    if z < 0.0 {
        Pt::new(-p.z, p.r)
    } else {
        p
    }
}

fn pieces(drawing: &Drawing, opt: &ReadOptions) -> Vec<Piece> {
    let tol = opt.chord_tol;
    let mut out = Vec::new();
    for e in drawing.entities() {
        if opt
            .layer
            .is_some_and(|l| !e.common.layer.eq_ignore_ascii_case(l))
        {
            continue;
        }
        match &e.specific {
            EntityType::Line(l) => {
                let (a, b) = (Pt::new(l.p1.x, l.p1.y), Pt::new(l.p2.x, l.p2.y));
                if a.dist(b) > 0.0 {
                    out.push(Piece { pts: vec![a, b] });
                }
            }
            EntityType::Arc(a) => {
                let c = Pt::new(a.center.x, a.center.y);
                let (s, mut e) = (a.start_angle.to_radians(), a.end_angle.to_radians());
                while e <= s {
                    e += std::f64::consts::TAU;
                }
                let arc = Arc {
                    center: c,
                    radius: a.radius,
                    start: s,
                    sweep: e - s,
                };
                let pts: Vec<Pt> = arc
                    .flatten(tol)
                    .into_iter()
                    .map(|p| ocs(a.normal.z, p))
                    .collect();
                out.push(Piece { pts });
            }
            EntityType::LwPolyline(p) => {
                let v: Vec<(Pt, f64)> = p
                    .vertices
                    .iter()
                    .map(|v| (Pt::new(v.x, v.y), v.bulge))
                    .collect();
                polyline_pieces(&v, p.is_closed(), p.extrusion_direction.z, tol, &mut out);
            }
            EntityType::Polyline(p) => {
                let v: Vec<(Pt, f64)> = p
                    .vertices()
                    .map(|v| (Pt::new(v.location.x, v.location.y), v.bulge))
                    .collect();
                polyline_pieces(&v, p.is_closed(), p.normal.z, tol, &mut out);
            }
            _ => {}
        }
    }
    out
}

/// Chains pieces into closed loops (drawing coordinates, without a repeated last point).
fn chain(mut rest: Vec<Piece>, join: f64) -> Result<Vec<Vec<Pt>>, IsoError> {
    let mut loops = Vec::new();
    while let Some(first) = rest.pop() {
        let start = first.pts[0];
        let mut ring = first.pts;
        loop {
            let end = *ring.last().unwrap_or(&start);
            if end.dist(start) <= join && ring.len() > 2 {
                ring.pop();
                break;
            }
            let next = rest.iter().position(|p| {
                p.pts[0].dist(end) <= join || p.pts.last().is_some_and(|q| q.dist(end) <= join)
            });
            let Some(i) = next else {
                return Err(IsoError::Open {
                    x: end.z,
                    y: end.r,
                    tol: join,
                });
            };
            let mut p = rest.swap_remove(i).pts;
            if p[0].dist(end) > join {
                p.reverse();
            }
            ring.extend_from_slice(&p[1..]);
        }
        loops.push(ring);
    }
    Ok(loops)
}

/// The first place a closed ring crosses or touches itself (the geometry kernel's test).
pub use geom::ring::self_intersection;

/// Reads the closed profiles of a DXF text as rings in (z, r), each counter-clockwise.
pub fn read_profile_str(text: &str, opt: &ReadOptions) -> Result<Vec<Vec<Pt>>, IsoError> {
    let drawing = Drawing::load(&mut text.as_bytes()).map_err(|e| IsoError::Dxf(e.to_string()))?;
    read_drawing(&drawing, opt)
}

/// Reads the closed profiles of a DXF file (ASCII or binary).
pub fn read_profile_file(
    path: impl AsRef<std::path::Path>,
    opt: &ReadOptions,
) -> Result<Vec<Vec<Pt>>, IsoError> {
    let path = path.as_ref();
    let drawing =
        Drawing::load_file(path).map_err(|e| IsoError::Dxf(format!("{}: {e}", path.display())))?;
    read_drawing(&drawing, opt)
}

/// Reads the closed profiles of a loaded drawing.
pub fn read_drawing(drawing: &Drawing, opt: &ReadOptions) -> Result<Vec<Vec<Pt>>, IsoError> {
    let mut opt = *opt;
    if opt.layer.is_none() {
        opt.layer = opt.prefer_layer.filter(|l| {
            drawing
                .entities()
                .any(|e| e.common.layer.eq_ignore_ascii_case(l))
        });
    }
    let opt = &opt;
    let pieces = pieces(drawing, opt);
    if pieces.is_empty() {
        return Err(IsoError::Dxf(
            "no LINE, ARC, LWPOLYLINE or POLYLINE in the model space".into(),
        ));
    }
    let loops = chain(pieces, opt.join_tol)?;
    let mut rings = Vec::with_capacity(loops.len());
    for ring in loops {
        if let Some(x) = self_intersection(&ring) {
            return Err(IsoError::SelfIntersecting { x: x.z, y: x.r });
        }
        let mut ring: Vec<Pt> = ring
            .into_iter()
            .map(|p| Pt::new(p.z, opt.x_mode.to_r(p.r)))
            .collect();
        if geom::ring::signed_area(&ring) < 0.0 {
            ring.reverse();
        }
        rings.push(ring);
    }
    Ok(rings)
}

fn polyline(ring: &[Pt], x_mode: XMode, layer: &str) -> Entity {
    let mut p = LwPolyline {
        vertices: ring
            .iter()
            .map(|q| LwPolylineVertex {
                x: q.z,
                y: x_mode.to_y(q.r),
                ..Default::default()
            })
            .collect(),
        ..Default::default()
    };
    p.set_is_closed(true);
    let mut e = Entity::new(EntityType::LwPolyline(p));
    e.common.layer = layer.to_string();
    e
}

/// The drawing of a half section: `part` rings on layer `PART` (white), the optional
/// `intended` rings on layer `INTENDED` (red), `AutoCAD` 2000 format.
pub fn section_drawing(part: &[Vec<Pt>], intended: Option<&[Vec<Pt>]>, x_mode: XMode) -> Drawing {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    for (name, colour) in [("PART", 7u8), ("INTENDED", 1u8)] {
        let mut layer = Layer {
            name: name.to_string(),
            ..Default::default()
        };
        layer.color = dxf::Color::from_index(colour);
        d.add_layer(layer);
    }
    for ring in part.iter().filter(|r| r.len() >= 2) {
        d.add_entity(polyline(ring, x_mode, "PART"));
    }
    for ring in intended.unwrap_or(&[]).iter().filter(|r| r.len() >= 2) {
        d.add_entity(polyline(ring, x_mode, "INTENDED"));
    }
    d
}

/// [`section_drawing`] as DXF text.
pub fn write_section_string(
    part: &[Vec<Pt>],
    intended: Option<&[Vec<Pt>]>,
    x_mode: XMode,
) -> Result<String, IsoError> {
    let mut buf = Vec::new();
    section_drawing(part, intended, x_mode)
        .save(&mut buf)
        .map_err(|e| IsoError::Dxf(e.to_string()))?;
    String::from_utf8(buf).map_err(|e| IsoError::Dxf(e.to_string()))
}

/// [`section_drawing`] saved to a file.
pub fn write_section_file(
    path: impl AsRef<std::path::Path>,
    part: &[Vec<Pt>],
    intended: Option<&[Vec<Pt>]>,
    x_mode: XMode,
) -> Result<(), IsoError> {
    let path = path.as_ref();
    section_drawing(part, intended, x_mode)
        .save_file(path)
        .map_err(|e| IsoError::Dxf(format!("{}: {e}", path.display())))
}
