//! The surface a thread leaves in the section: the radius of the material's outer surface
//! (OD) or bore (ID) at a given Z, and its extreme over the thread's length — the achieved
//! minor diameter of an OD thread, the major diameter of an ID thread.

use crate::{Shape, ToolTable};
use expander::{Motion, Segment, Span};

/// Which surface of the section a thread is cut in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Surface {
    /// The outside: the largest radius where material is, at a given Z.
    Outer,
    /// The bore: the smallest radius where material is, at a given Z.
    Bore,
}

/// The radius of `surface` at `z`: where the line Z = `z` crosses the section's boundaries,
/// the largest crossing (outer) or the smallest (bore); `None` where no material is.
pub fn surface_radius_at(shapes: &[Shape], z: f64, surface: Surface) -> Option<f64> {
    let crossings = shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flat_map(|ring| {
            (0..ring.len()).filter_map(move |i| {
                let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
                let (lo, hi) = (a[0].min(b[0]), a[0].max(b[0]));
                if z < lo || z > hi || hi - lo < 1e-12 {
                    return None;
                }
                Some(a[1] + (z - a[0]) / (b[0] - a[0]) * (b[1] - a[1]))
            })
        });
    match surface {
        Surface::Outer => crossings.reduce(f64::max),
        Surface::Bore => crossings.reduce(f64::min),
    }
}

/// The deepest point of `surface` between `z0` and `z1` (either order): the smallest outer
/// radius or the largest bore radius there, `None` where no material is. The surface is
/// piecewise linear, so its extreme lies at a ring vertex (or just beside one, where an edge
/// hides another) or at an end: those are the places looked at.
pub fn deepest_radius(shapes: &[Shape], z0: f64, z1: f64, surface: Surface) -> Option<f64> {
    let (lo, hi) = (z0.min(z1), z0.max(z1));
    let eps = 1e-7;
    let vertices = shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flatten()
        .map(|p| p[0])
        .filter(|z| (lo..=hi).contains(z))
        .flat_map(|z| [z - eps, z, z + eps]);
    let radii = [lo, hi]
        .into_iter()
        .chain(vertices)
        .filter(|z| (lo..=hi).contains(z))
        .filter_map(|z| surface_radius_at(shapes, z, surface));
    match surface {
        Surface::Outer => radii.reduce(f64::min),
        Surface::Bore => radii.reduce(f64::max),
    }
}

/// The least radial gap between `surface` of `shapes` and a reference over `z0..z1`: for the
/// outside, min (surface − reference), for the bore, min (reference − surface); negative
/// where the surface lies deeper than the reference. The reference is a line
/// ([`Reference::Line`]) or another section's same surface ([`Reference::Shapes`]). Both
/// are piecewise linear in Z, so the least gap lies beside a vertex of either or at an end:
/// those are the places looked at, 1e-7 mm inside (exactly at a step of the reference, its
/// riser would count). `None` where neither has material.
pub fn least_gap(
    shapes: &[Shape],
    reference: Reference,
    z0: f64,
    z1: f64,
    surface: Surface,
) -> Option<f64> {
    let (lo, hi) = (z0.min(z1), z0.max(z1));
    let eps = 1e-7;
    let ref_shapes: &[Shape] = match reference {
        Reference::Shapes(r) => r,
        Reference::Line(..) => &[],
    };
    let vertices = shapes
        .iter()
        .chain(ref_shapes)
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flatten()
        .map(|p| p[0])
        .flat_map(|z| [z - eps, z + eps]);
    let reference_at = |z: f64| match reference {
        Reference::Line(a, b) => Some(if (b[0] - a[0]).abs() < 1e-12 {
            a[1]
        } else {
            a[1] + (z - a[0]) / (b[0] - a[0]) * (b[1] - a[1])
        }),
        Reference::Shapes(r) => surface_radius_at(r, z, surface),
    };
    [lo + eps, hi - eps]
        .into_iter()
        .chain(vertices)
        .filter(|z| (lo..=hi).contains(z))
        .filter_map(|z| {
            let (s, r) = (surface_radius_at(shapes, z, surface)?, reference_at(z)?);
            Some(match surface {
                Surface::Outer => s - r,
                Surface::Bore => r - s,
            })
        })
        .reduce(f64::min)
}

/// What [`least_gap`] measures from.
#[derive(Debug, Clone, Copy)]
pub enum Reference<'a> {
    /// The line through two (z, r) points.
    Line([f64; 2], [f64; 2]),
    /// The same surface of another section (the intended part).
    Shapes(&'a [Shape]),
}

/// One thread: the thread passes of one tool and one lead over one Z span, one after the
/// other with nothing but rapids between them (a G76 block, a G92 block and its modal
/// repeats, the starts of a multi-start thread, a run of G32 passes).
#[derive(Debug, Clone, PartialEq)]
pub struct Thread {
    /// The block of the first pass.
    pub span: Span,
    /// The surface it is cut in: the outside (the tool's body above its tip) or the bore.
    pub surface: Surface,
    /// Lead, mm.
    pub lead: f64,
    /// The deepest pass's threading move, (z, r) from and to: the programmed root line.
    pub root: [[f64; 2]; 2],
    /// Radial infeed of each pass from the one before of the same start, measured at the
    /// thread's end (the first of each start from the crest: the final section's highest
    /// outside, or lowest bore, within a lead of the end; 0 with no material there), mm.
    pub pass_depths: Vec<f64>,
    /// The passes go deeper away from the tool's side: outward (an inside thread) with an
    /// OD insert, or inward with an ID insert, whose body then sweeps through the wall or
    /// the core. Known only from two passes at different depths.
    pub wrong_side: bool,
}

impl Thread {
    /// The final X of the thread (diameter at the end of the deepest pass): the programmed
    /// minor diameter of an outside thread, the major of an inside one.
    pub fn x(&self) -> f64 {
        2.0 * self.root[1][1]
    }

    /// The Z span the thread's root is checked over.
    pub fn z_span(&self) -> (f64, f64) {
        (self.root[0][0], self.root[1][0])
    }

    /// The diameter the section reaches at the thread's end: the programmed final X moved by
    /// the least gap between the section's surface and the root line (negative: deeper).
    pub fn achieved_x(&self, shapes: &[Shape]) -> Option<f64> {
        let [a, b] = self.root;
        let gap = least_gap(shapes, Reference::Line(a, b), a[0], b[0], self.surface)?;
        Some(match self.surface {
            Surface::Outer => self.x() + 2.0 * gap,
            Surface::Bore => self.x() - 2.0 * gap,
        })
    }
}

/// The threads of a toolpath, in program order (see [`Thread`]); `shapes` is the final
/// section, where the first pass's depth is measured from the crest.
pub fn threads(segments: &[Segment], tools: &ToolTable, shapes: &[Shape]) -> Vec<Thread> {
    // each pass: the index of its first thread move (a chamfer pull-out continues it)
    let mut groups: Vec<(Surface, Vec<&Segment>)> = vec![];
    let mut open = false;
    for (i, s) in segments.iter().enumerate() {
        match s.motion {
            Motion::Rapid => {}
            Motion::Feed => open = false,
            Motion::Thread => {
                if i > 0 && segments[i - 1].motion == Motion::Thread {
                    continue; // the pull-out of the same pass
                }
                let surface = match tools.outline_for(s.tool, s.hint).0.bbox() {
                    Some((lo, hi)) if hi[1] < -lo[1] => Surface::Bore,
                    _ => Surface::Outer,
                };
                let joins = open
                    && groups.last().is_some_and(|(surf, passes)| {
                        let p = passes[0];
                        let (a, b) = (p.from.z.min(p.to.z), p.from.z.max(p.to.z));
                        *surf == surface
                            && p.tool == s.tool
                            && p.lead == s.lead
                            && s.from.z.max(s.to.z) > a
                            && s.from.z.min(s.to.z) < b
                    });
                if joins {
                    groups.last_mut().unwrap().1.push(s);
                } else {
                    groups.push((surface, vec![s]));
                }
                open = true;
            }
        }
    }
    groups
        .into_iter()
        .map(|(surface, passes)| {
            let deeper = |a: f64, b: f64| match surface {
                Surface::Outer => a < b,
                Surface::Bore => a > b,
            };
            let deepest = passes
                .iter()
                .copied()
                .reduce(|d, p| if deeper(p.to.r, d.to.r) { p } else { d })
                .expect("a thread has a pass");
            let end = deepest.to;
            let toward_start = (deepest.from.z - end.z).signum() * deepest.lead;
            let crest = crest_radius(shapes, end.z, end.z + toward_start, surface);
            // each start (multi-start: each phase) goes down from the crest on its own; a
            // thread cut in the air has no crest, and its first depth is 0
            let mut before: Vec<(f64, f64)> = vec![];
            let pass_depths = passes
                .iter()
                .map(|p| {
                    let k = match before.iter().position(|b| b.0 == p.thread_phase) {
                        Some(k) => k,
                        None => {
                            before.push((p.thread_phase, crest.unwrap_or(p.to.r)));
                            before.len() - 1
                        }
                    };
                    let d = (before[k].1 - p.to.r).abs();
                    before[k].1 = p.to.r;
                    d
                })
                .collect();
            // the infeed direction: from the first pass to the last
            let (first, last) = (passes[0].to.r, passes[passes.len() - 1].to.r);
            let wrong_side = (last - first).abs() > 1e-9
                && match surface {
                    Surface::Outer => last > first,
                    Surface::Bore => last < first,
                };
            Thread {
                wrong_side,
                span: passes[0].span,
                surface,
                lead: deepest.lead,
                root: [[deepest.from.z, deepest.from.r], [end.z, end.r]],
                pass_depths,
            }
        })
        .collect()
}

/// The crest of a thread between `z0` and `z1`: the highest outside or the lowest bore.
fn crest_radius(shapes: &[Shape], z0: f64, z1: f64, surface: Surface) -> Option<f64> {
    // piecewise linear: the extreme lies at a vertex or an end
    let (lo, hi) = (z0.min(z1), z0.max(z1));
    shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flatten()
        .map(|p| p[0])
        .filter(|z| (lo..=hi).contains(z))
        .chain([lo, hi])
        .filter_map(|z| surface_radius_at(shapes, z, surface))
        .reduce(match surface {
            Surface::Outer => f64::max,
            Surface::Bore => f64::min,
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tube_with_a_v_notch() {
        // Φ20 tube, bore Φ10, Z −10..0, one 60° V notch 0.5 deep at Z −5 in the outside.
        let h = 0.5 * (30f64).to_radians().tan();
        let outer = vec![
            [-10.0, 5.0],
            [0.0, 5.0],
            [0.0, 10.0],
            [-5.0 + h, 10.0],
            [-5.0, 9.5],
            [-5.0 - h, 10.0],
            [-10.0, 10.0],
        ];
        let shapes = [Shape {
            outer,
            holes: vec![],
        }];
        assert_eq!(surface_radius_at(&shapes, -2.0, Surface::Outer), Some(10.0));
        assert_eq!(surface_radius_at(&shapes, -2.0, Surface::Bore), Some(5.0));
        let mid = surface_radius_at(&shapes, -5.0 + h / 2.0, Surface::Outer).unwrap();
        assert!((mid - 9.75).abs() < 1e-12, "{mid}");
        assert_eq!(surface_radius_at(&shapes, 1.0, Surface::Outer), None);
        let d = deepest_radius(&shapes, -8.0, -1.0, Surface::Outer).unwrap();
        assert!((d - 9.5).abs() < 1e-12, "{d}");
        assert_eq!(
            deepest_radius(&shapes, -8.0, -1.0, Surface::Bore),
            Some(5.0)
        );
    }
}
