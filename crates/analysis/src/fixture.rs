//! Workholding as obstacles: the chuck body, its jaws and the tailstock centre, which no
//! part of a tool may enter at any speed, and the gripped length of the blank, which no
//! cutting move may cut. Checked move by move against fixed polygons, apart from the
//! removal (the obstacles never change and are not stock).
//!
//! Geometry in the (z, r) half plane, from [`expander::Workholding`] and the blank:
//! - **chuck face** (the body): Z from `face − depth` to `face`, r from 0 to `od / 2`
//!   (solid: a spindle bore is not modelled); `face` defaults to the blank's left end;
//! - **chuck jaw**: hard jaws Z from `face` to `face + grip`, r from the gripped radius (the
//!   blank's largest radius over that Z span) to it plus `jaw`; soft jaws: the `soft_jaw`
//!   outline placed at the face. The jaws turn with the spindle, so the region is the
//!   solid of revolution their section sweeps: the same at any angle, above and below the
//!   axis;
//! - **tailstock centre**: a 60° cone (30° half angle) from `tip` on the axis widening to
//!   the quill's radius, then the quill, `length` long toward +Z;
//! - **gripped length**: the blank's section between `face` and `face + grip`.
//!
//! **The rules.** A move crashes into an obstacle when the sweep of its tool's cutting
//! outline or of its body (`stock::Body`), folded into the section like the removal's
//! sweeps, overlaps the chuck face, a jaw or the tailstock centre by more than
//! [`CRASH_MIN_AREA`] — rapid, feed or thread alike. A feed or thread move whose cutting
//! outline's sweep overlaps the gripped length (of the blank as it was before the first
//! cut) by more than [`CRASH_MIN_AREA`], reaching its outer skin ([`GRIP_SKIN`] under the
//! gripped diameter), is a crash "gripped length": the tool cuts what the jaws hold
//! (**Interpretation**: boring a bush through its gripped length is no crash while it
//! leaves a wall thicker than the skin; one thinner the jaws would crush). A rapid there is already a
//! rapid crash of the removal, and a body there is a body crash. As in the removal, a move
//! that meets the obstacle the move before it met continues that crash: one crash is
//! reported, at its first move.

use expander::{Motion, Segment, Workholding};
use geom::flat::P;
use geom::{Pt, Rect};
use stock::{
    area, boolean, float_sweep, move_path, Blank, BoolOp, Mounts, Shape, StockError, ToolTable,
    CRASH_MIN_AREA,
};

/// The chuck body's diameter beyond the jaws' outer diameter when the profile gives none, mm.
pub(crate) const DEFAULT_OD_MARGIN: f64 = 40.0;

/// How thick the skin of the gripped length is that the jaws hold, mm: a cut inside the jaws
/// that comes nearer the gripped diameter than this (turning it, or boring a wall thinner)
/// takes what holds the part.
pub(crate) const GRIP_SKIN: f64 = 0.5;

/// The name of the gripped-length rule's obstacle.
pub const GRIPPED_LENGTH: &str = "gripped length";

/// What a tool may not enter.
#[derive(Debug, Clone, PartialEq)]
pub struct Obstacle {
    /// "chuck face", "chuck jaw", "tailstock centre" or "gripped length".
    pub name: &'static str,
    /// Its section at r ≥ 0.
    pub shapes: Vec<Shape>,
    /// Only cutting moves' cutting outlines are checked against it (the gripped length).
    pub cut_only: bool,
    /// The gripped length's outer skin, [`GRIP_SKIN`] thick under the gripped diameter: a
    /// cut in the gripped length counts only when it reaches it (boring a bush through its
    /// gripped length leaves what the jaws hold).
    pub skin: Option<Vec<Shape>>,
    bbox: Rect,
    /// Its rings when each is convex and has no hole (a separating-axis test then spares
    /// the boolean for sweeps that only come near it).
    convex: Option<Vec<Vec<P>>>,
}

/// The name of the tailstock centre's obstacle.
pub const TAILSTOCK_CENTRE: &str = "tailstock centre";

/// The chuck and tailstock placed against a blank.
#[derive(Debug, Clone, PartialEq)]
pub struct Fixture {
    /// Obstacles in drawing order: chuck face, jaws, tailstock centre, gripped length.
    pub obstacles: Vec<Obstacle>,
    /// The blank's stick-out from the jaws (its right end minus the jaws' front), mm.
    pub stick_out: Option<f64>,
}

/// A move whose tool entered an obstacle.
#[derive(Debug, Clone, PartialEq)]
pub struct FixtureCrash {
    /// Index of the move.
    pub segment: usize,
    /// The obstacle's name ([`Obstacle::name`]).
    pub obstacle: &'static str,
    /// The tool's body that met it ("holder", …), `None` for the cutting outline.
    pub body: Option<&'static str>,
    /// The point of the overlap nearest the move's start, (z, r) in the section.
    pub at: [f64; 2],
    /// Overlap area, mm².
    pub area: f64,
    /// The overlap's extent normal to the move, mm.
    pub depth: f64,
}

fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Shape {
    Shape {
        outer: vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]],
        holes: Vec::new(),
    }
}

fn shapes_box(shapes: &[Shape]) -> Rect {
    Rect::of(
        shapes
            .iter()
            .flat_map(|s| s.outer.iter().map(|&p| Pt::from(p))),
    )
}

impl Obstacle {
    fn new(name: &'static str, shapes: Vec<Shape>, cut_only: bool) -> Self {
        let bbox = shapes_box(&shapes);
        let convex = shapes
            .iter()
            .all(|s| s.holes.is_empty() && geom::flat::is_convex(&s.outer))
            .then(|| shapes.iter().map(|s| s.outer.clone()).collect());
        Self {
            name,
            shapes,
            cut_only,
            skin: None,
            bbox,
            convex,
        }
    }

    /// The pieces of a sweep whose boxes meet this obstacle's: the only ones its
    /// intersection with the sweep can come from (an arc's sweep is a piece a chord, each
    /// overlapping the next, and the boolean of them all cost milliseconds a move).
    fn near(&self, sweep: &[Shape]) -> Vec<Shape> {
        sweep
            .iter()
            .filter(|piece| shapes_box(std::slice::from_ref(piece)).intersects(&self.bbox))
            .cloned()
            .collect()
    }

    /// Whether the sweep (convex pieces, box `sb`) may overlap it with some area: boxes,
    /// then for a convex obstacle a separating-axis test of every piece near it.
    fn may_overlap(&self, sweep: &[Shape], sb: &Rect) -> bool {
        if !sb.intersects(&self.bbox) {
            return false;
        }
        let Some(rings) = &self.convex else {
            return true;
        };
        sweep.iter().any(|piece| {
            let b = shapes_box(std::slice::from_ref(piece));
            b.intersects(&self.bbox) && rings.iter().any(|r| convex_overlap(&piece.outer, r))
        })
    }
}

impl Fixture {
    /// The workholding placed against `blank`; `None` when it holds neither chuck nor
    /// tailstock. An error when the jaws grip no material of the blank.
    pub fn new(w: &Workholding, blank: &Blank) -> Result<Option<Self>, StockError> {
        if w.chuck.is_none() && w.tailstock.is_none() {
            return Ok(None);
        }
        let b = shapes_box(&blank.shapes);
        let mut obstacles = Vec::new();
        let mut stick_out = None;
        let mut grip_rule = None;
        if let Some(c) = &w.chuck {
            let face = c.face.unwrap_or(b.min.z);
            let front = face + c.grip;
            let strip = [rect(face, front, -1.0, b.max.r.max(0.0) + 1.0)];
            let gripped = boolean(&blank.shapes, &strip, BoolOp::Intersection);
            if area(&gripped) <= CRASH_MIN_AREA {
                return Err(StockError::Blank(format!(
                    "the chuck grips nothing: its jaws span Z{face}…Z{front}, the blank Z{}…Z{}",
                    b.min.z, b.max.z
                )));
            }
            let r_grip = shapes_box(&gripped).max.r;
            let jaws = match &c.soft_jaw {
                Some(ring) => {
                    let ring: Vec<P> = ring.iter().map(|p| [face + p[0], p[1] / 2.0]).collect();
                    stock::clean(&[ring])
                }
                None => vec![rect(face, front, r_grip, r_grip + c.jaw)],
            };
            let od = c.od.unwrap_or(2.0 * (r_grip + c.jaw) + DEFAULT_OD_MARGIN);
            obstacles.push(Obstacle::new(
                "chuck face",
                vec![rect(face - c.depth, face, 0.0, od / 2.0)],
                false,
            ));
            obstacles.push(Obstacle::new("chuck jaw", jaws, false));
            let skin = boolean(
                &gripped,
                &[rect(face, front, r_grip - GRIP_SKIN, r_grip + 1.0)],
                BoolOp::Intersection,
            );
            grip_rule = Some(Obstacle {
                skin: Some(skin),
                ..Obstacle::new(GRIPPED_LENGTH, gripped, true)
            });
            stick_out = Some(b.max.z - front);
        }
        if let Some(t) = &w.tailstock {
            let rq = t.quill / 2.0;
            let cone = rq / 30f64.to_radians().tan();
            let centre = Shape {
                outer: vec![
                    [t.tip, 0.0],
                    [t.tip + cone + t.length, 0.0],
                    [t.tip + cone + t.length, rq],
                    [t.tip + cone, rq],
                ],
                holes: Vec::new(),
            };
            obstacles.push(Obstacle::new(TAILSTOCK_CENTRE, vec![centre], false));
        }
        obstacles.extend(grip_rule);
        Ok(Some(Self {
            obstacles,
            stick_out,
        }))
    }

    /// The moves whose tools enter an obstacle (see the module documentation), in program
    /// order; `chord_tol` chords arcs as the removal does. `tailstock` are the program's
    /// tailstock changes (`Toolpath::tailstock`: from segment k on, advanced or not): the
    /// centre is no obstacle while it is retracted.
    pub fn check(
        &self,
        tools: &ToolTable,
        segments: &[Segment],
        chord_tol: f64,
        tailstock: &[(usize, bool)],
    ) -> Vec<FixtureCrash> {
        let mut changes = tailstock.iter().peekable();
        let mut advanced = true;
        let mut mounts = Mounts::new(tools, stock::rear_tools(segments));
        let mut all = Rect::EMPTY;
        for o in &self.obstacles {
            all = all.union(&o.bbox);
        }
        let mut out: Vec<FixtureCrash> = Vec::new();
        for (i, seg) in segments.iter().enumerate() {
            while let Some(&(_, on)) = changes.next_if(|(k, _)| *k <= i) {
                advanced = on;
            }
            let finite = [seg.from.z, seg.from.r, seg.to.z, seg.to.r]
                .iter()
                .all(|v| v.is_finite() && v.abs() < 1e9);
            if !finite {
                continue;
            }
            let m = mounts.of(seg);
            let bbox = m.bbox();
            // a quick test on boxes: the path's box plus the tool's, folded about the axis
            let mut reach = Rect::of([seg.from, seg.to]);
            if let Some(a) = seg.arc {
                let rad = a.center.dist(seg.from);
                reach = reach.union(&Rect::new(
                    Pt::new(a.center.z - rad, a.center.r - rad),
                    Pt::new(a.center.z + rad, a.center.r + rad),
                ));
            }
            let (lo, hi) = (reach.min.r + bbox.min.r, reach.max.r + bbox.max.r);
            let (rlo, rhi) = if lo >= 0.0 {
                (lo, hi)
            } else if hi <= 0.0 {
                (-hi, -lo)
            } else {
                (0.0, hi.max(-lo))
            };
            let folded = Rect::new(
                Pt::new(reach.min.z + bbox.min.z, rlo),
                Pt::new(reach.max.z + bbox.max.z, rhi),
            );
            if !folded.intersects(&all) {
                continue;
            }
            let path = move_path(seg, chord_tol);
            let parts = std::iter::once((None, &*m.edge))
                .chain(m.body.as_ref().map(|b| (Some(b.name), &b.outline)));
            let mut hit: Vec<&'static str> = Vec::new();
            for (body, outline) in parts {
                let sweep: Vec<Shape> = float_sweep(outline, &path)
                    .into_iter()
                    .map(|outer| Shape {
                        outer,
                        holes: Vec::new(),
                    })
                    .collect();
                let sb = shapes_box(&sweep);
                for o in &self.obstacles {
                    let applies = (!o.cut_only || (body.is_none() && seg.motion != Motion::Rapid))
                        && (advanced || o.name != TAILSTOCK_CENTRE);
                    if !applies || hit.contains(&o.name) || !o.may_overlap(&sweep, &sb) {
                        continue;
                    }
                    let overlap = boolean(&o.near(&sweep), &o.shapes, BoolOp::Intersection);
                    let a = area(&overlap);
                    let reaches_skin = o.skin.as_ref().is_none_or(|skin| {
                        area(&boolean(&overlap, skin, BoolOp::Intersection)) > CRASH_MIN_AREA
                    });
                    if a > CRASH_MIN_AREA && reaches_skin {
                        hit.push(o.name);
                        out.push(measure(i, o.name, body, &overlap, a, &path));
                    }
                }
            }
        }
        continues(out)
    }
}

/// Whether two convex polygons (either orientation) share interior: no edge normal of
/// either separates them (touching counts as separated; the boolean measures the rest).
fn convex_overlap(a: &[P], b: &[P]) -> bool {
    let separated = |p: &[P], q: &[P]| {
        (0..p.len()).any(|i| {
            let (u, v) = (p[i], p[(i + 1) % p.len()]);
            let axis = [u[1] - v[1], v[0] - u[0]];
            let tol = 1e-9 * axis[0].hypot(axis[1]);
            let span = |x: &[P]| {
                x.iter()
                    .map(|w| axis[0] * w[0] + axis[1] * w[1])
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), t| {
                        (lo.min(t), hi.max(t))
                    })
            };
            let ((plo, phi), (qlo, qhi)) = (span(p), span(q));
            phi <= qlo + tol || qhi <= plo + tol
        })
    };
    a.len() >= 3 && b.len() >= 3 && !separated(a, b) && !separated(b, a)
}

/// The crash's contact point (the overlap's point nearest the move's start, folded) and
/// depth (the overlap's extent normal to the move).
fn measure(
    segment: usize,
    obstacle: &'static str,
    body: Option<&'static str>,
    overlap: &[Shape],
    area: f64,
    path: &[P],
) -> FixtureCrash {
    let (s, e) = (path[0], path[path.len() - 1]);
    let below = s[1] + e[1] < 0.0;
    let start = [s[0], s[1].abs()];
    let (dz, dr) = (e[0] - s[0], if below { s[1] - e[1] } else { e[1] - s[1] });
    let len = dz.hypot(dr);
    let pts = overlap.iter().flat_map(|s| s.outer.iter().copied());
    let mut at = start;
    let mut best = f64::INFINITY;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in pts {
        let d = (p[0] - start[0]).hypot(p[1] - start[1]);
        if d < best {
            (best, at) = (d, p);
        }
        let across = if len > 0.0 {
            (-dr * p[0] + dz * p[1]) / len
        } else {
            p[1]
        };
        lo = lo.min(across);
        hi = hi.max(across);
    }
    FixtureCrash {
        segment,
        obstacle,
        body,
        at,
        area,
        depth: (hi - lo).max(0.0),
    }
}

/// Drops crashes that continue one of the move before into the same obstacle.
fn continues(crashes: Vec<FixtureCrash>) -> Vec<FixtureCrash> {
    let mut kept: Vec<FixtureCrash> = Vec::with_capacity(crashes.len());
    let mut prev: Vec<(usize, &'static str)> = Vec::new();
    for c in crashes {
        let cont = prev
            .iter()
            .any(|&(s, o)| o == c.obstacle && s + 1 == c.segment);
        prev.retain(|&(s, _)| s + 1 >= c.segment);
        prev.push((c.segment, c.obstacle));
        if !cont {
            kept.push(c);
        }
    }
    kept
}

#[cfg(test)]
mod tests {
    use super::*;
    use expander::{Chuck, Tailstock};

    fn chuck(grip: f64) -> Chuck {
        Chuck {
            face: None,
            grip,
            jaw: 20.0,
            od: None,
            depth: 100.0,
            soft_jaw: None,
        }
    }

    #[test]
    fn hard_jaws_sit_on_the_blank_from_its_left_end() {
        let blank = Blank::bar(40.0, 100.0, 0.0, None).unwrap();
        let w = Workholding {
            chuck: Some(chuck(30.0)),
            tailstock: Some(Tailstock {
                tip: 1.0,
                quill: 40.0,
                length: 150.0,
            }),
        };
        let f = Fixture::new(&w, &blank).unwrap().unwrap();
        let names: Vec<_> = f.obstacles.iter().map(|o| o.name).collect();
        assert_eq!(
            names,
            [
                "chuck face",
                "chuck jaw",
                "tailstock centre",
                "gripped length"
            ]
        );
        assert_eq!(f.stick_out, Some(70.0));
        let jaw = shapes_box(&f.obstacles[1].shapes);
        assert_eq!(
            (jaw.min.z, jaw.max.z, jaw.min.r, jaw.max.r),
            (-100.0, -70.0, 20.0, 40.0)
        );
        let body = shapes_box(&f.obstacles[0].shapes);
        // od = 2 × (20 + 20) + 40 = 120
        assert_eq!((body.min.z, body.max.z, body.max.r), (-200.0, -100.0, 60.0));
        // the cone reaches r 20 at 20 / tan 30° = 34.641 behind the tip
        let c = &f.obstacles[2].shapes[0].outer;
        assert!((c[3][0] - (1.0 + 20.0 * 3f64.sqrt())).abs() < 1e-9, "{c:?}");
        assert!((area(&f.obstacles[3].shapes) - 600.0).abs() < 1e-6);
    }

    #[test]
    fn separating_axes_tell_touching_from_overlapping() {
        let sq = |z: f64, r: f64| vec![[z, r], [z + 1.0, r], [z + 1.0, r + 1.0], [z, r + 1.0]];
        assert!(
            !convex_overlap(&sq(0.0, 0.0), &sq(1.0, 0.0)),
            "sharing an edge"
        );
        assert!(
            !convex_overlap(&sq(0.0, 0.0), &sq(1.0, 1.0)),
            "sharing a corner"
        );
        assert!(convex_overlap(&sq(0.0, 0.0), &sq(0.999, 0.5)));
        // a triangle whose hypotenuse only passes the square's corner
        let tri = vec![[1.0, 1.0], [3.0, 1.0], [1.0, 3.0]];
        assert!(!convex_overlap(&sq(0.0, 0.0), &tri));
        let tri = vec![[0.5, 0.5], [3.0, 1.0], [1.0, 3.0]];
        assert!(convex_overlap(&sq(0.0, 0.0), &tri));
    }

    #[test]
    fn jaws_past_the_blank_are_an_error() {
        let blank = Blank::bar(40.0, 100.0, 0.0, None).unwrap();
        let mut c = chuck(10.0);
        c.face = Some(5.0);
        let w = Workholding {
            chuck: Some(c),
            tailstock: None,
        };
        assert!(Fixture::new(&w, &blank).is_err());
        assert!(Fixture::new(&Workholding::default(), &blank)
            .unwrap()
            .is_none());
    }
}
