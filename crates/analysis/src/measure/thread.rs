//! The surface a thread leaves in the section: the radius of the material's outer surface
//! (OD) or bore (ID) at a given Z, and its extreme over the thread's length — the achieved
//! minor diameter of an OD thread, the major diameter of an ID thread.

use super::surface::radii_at;
use expander::{Motion, Segment, Span};
use stock::{Shape, ToolTable};

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
    radii_at(shapes, &[z], surface)[0]
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
    let zs: Vec<f64> = [lo, hi]
        .into_iter()
        .chain(vertices)
        .filter(|z| (lo..=hi).contains(z))
        .collect();
    let radii = radii_at(shapes, &zs, surface).into_iter().flatten();
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
    let zs = gap_places(shapes, reference, z0, z1);
    least_gap_at(shapes, reference, &zs, surface)
}

/// The places [`least_gap`] looks at over `z0..z1`: 1e-7 mm inside both ends and beside
/// every vertex of either section.
fn gap_places(shapes: &[Shape], reference: Reference, z0: f64, z1: f64) -> Vec<f64> {
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
    [lo + eps, hi - eps]
        .into_iter()
        .chain(vertices)
        .filter(|z| (lo..=hi).contains(z))
        .collect()
}

/// The least gap between `surface` of `shapes` and `reference` at the places `zs`.
fn least_gap_at(
    shapes: &[Shape],
    reference: Reference,
    zs: &[f64],
    surface: Surface,
) -> Option<f64> {
    let references = match reference {
        Reference::Line(a, b) => zs.iter().map(|&z| Some(line_at(a, b, z))).collect(),
        Reference::Shapes(r) => radii_at(r, zs, surface),
    };
    radii_at(shapes, zs, surface)
        .into_iter()
        .zip(references)
        .filter_map(|(s, r)| {
            let (s, r) = (s?, r?);
            Some(match surface {
                Surface::Outer => s - r,
                Surface::Bore => r - s,
            })
        })
        .reduce(f64::min)
}

/// The radius at `z` of the line through the (z, r) points `a` and `b` (`a`'s on a radial
/// line).
fn line_at(a: [f64; 2], b: [f64; 2], z: f64) -> f64 {
    if (b[0] - a[0]).abs() < 1e-12 {
        a[1]
    } else {
        a[1] + (z - a[0]) / (b[0] - a[0]) * (b[1] - a[1])
    }
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
    /// Number of starts (distinct start angles among the passes); the pitch is lead / starts.
    pub starts: usize,
    /// Index of the first pass's first move in the toolpath: the stock before it is what
    /// the thread cuts into.
    pub first_move: usize,
    /// The number of moves once its last pass has run: the stock then is the thread as it
    /// cut itself, before a later tool chamfers or deburrs its first turn.
    pub done_at: usize,
}

/// The form a thread leaves in the section, measured where a thread gauge or the
/// three-wire method looks: over whole pitches in the middle of the thread.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThreadForm {
    /// The diameter at which groove and tooth are equally wide (half a pitch each), mm.
    pub pitch_diameter: f64,
    /// The groove's included angle between its flanks, degrees, from the groove's width at
    /// two heights: where it takes 35 % and 65 % of the pitch (clear of an ISO crest flat of
    /// P/8 and root flat of P/4), or 5 % inside what it takes at the root and the crest when
    /// the flats are wider; `None` when that leaves less than 10 % (a shallow thread).
    pub included_angle: Option<f64>,
}

impl Thread {
    /// The final X of the thread (diameter at the end of the deepest pass): the programmed
    /// minor diameter of an outside thread, the major of an inside one.
    pub fn x(&self) -> f64 {
        2.0 * self.root[1][1]
    }

    /// The longest stretch of the root line's Z span where the section `later` (after the
    /// moves that came later) lies deeper than `done` (the thread as it cut itself) by
    /// more than `tol`, when it is longer than two leads: a later tool cutting through the
    /// thread, not a chamfer or a deburr of its first or last turn (a 3 mm blade deburring
    /// the first turn of a 2 mm lead cuts 1.9 leads of it).
    pub fn cut_through_later(
        &self,
        done: &[Shape],
        later: &[Shape],
        tol: f64,
    ) -> Option<(f64, f64)> {
        const MOST_SAMPLES: f64 = 4_000.0;
        let (z0, z1) = self.z_span();
        let (lo, hi) = (z0.min(z1), z0.max(z1));
        let step = (self.lead / 8.0).max((hi - lo) / MOST_SAMPLES);
        if step.is_nan() || step <= 0.0 {
            return None;
        }
        let zs: Vec<f64> = (0..=((hi - lo) / step) as usize)
            .map(|k| lo + k as f64 * step)
            .collect();
        let (before, after) = (
            radii_at(done, &zs, self.surface),
            radii_at(later, &zs, self.surface),
        );
        let deeper = |k: usize| match (before[k], after[k], self.surface) {
            (Some(_), None, _) => true,
            (Some(b), Some(a), Surface::Outer) => a < b - tol,
            (Some(b), Some(a), Surface::Bore) => a > b + tol,
            _ => false,
        };
        let (mut best, mut run): (Option<(f64, f64)>, Option<f64>) = (None, None);
        for (k, &z) in zs.iter().enumerate() {
            match (deeper(k), run) {
                (true, None) => run = Some(z),
                (false, Some(from)) => {
                    let prev = zs[k - 1];
                    if best.is_none_or(|(a, b)| prev - from > b - a) {
                        best = Some((from, prev));
                    }
                    run = None;
                }
                _ => {}
            }
        }
        if let Some(from) = run {
            if best.is_none_or(|(a, b)| hi - from > b - a) {
                best = Some((from, hi));
            }
        }
        best.filter(|(a, b)| b - a > 2.0 * self.lead)
    }

    /// The Z span the thread's root is checked over.
    pub fn z_span(&self) -> (f64, f64) {
        (self.root[0][0], self.root[1][0])
    }

    /// The diameter the section reaches at the thread's end: the programmed final X moved by
    /// the least gap between the section's surface and the root line (negative: deeper).
    /// With `before`, the stock before the thread's first pass, only where that stock came
    /// up to the root line: a relief groove cut deeper before the thread (the run-out ends
    /// in it) is not the thread's depth.
    pub fn achieved_x(&self, shapes: &[Shape], before: Option<&[Shape]>) -> Option<f64> {
        let [a, b] = self.root;
        let mut zs = gap_places(shapes, Reference::Line(a, b), a[0], b[0]);
        if let Some(before) = before {
            let cut = radii_at(before, &zs, self.surface);
            let came_up = |z: f64, s: Option<f64>| {
                s.is_some_and(|s| match self.surface {
                    Surface::Outer => s >= line_at(a, b, z) - 1e-6,
                    Surface::Bore => s <= line_at(a, b, z) + 1e-6,
                })
            };
            zs = zs
                .into_iter()
                .zip(cut)
                .filter(|&(z, s)| came_up(z, s))
                .map(|(z, _)| z)
                .collect();
        }
        let gap = least_gap_at(shapes, Reference::Line(a, b), &zs, self.surface)?;
        Some(match self.surface {
            Surface::Outer => self.x() + 2.0 * gap,
            Surface::Bore => self.x() - 2.0 * gap,
        })
    }
    /// The pitch diameter and flank angle of the thread as cut in `shapes`, measured over
    /// whole pitches inside the root line's span and the material's, a lead clear of each
    /// end (where the tool enters and pulls out); `None` when the span holds less than one such pitch or the
    /// section has no groove of half a pitch between root and crest.
    pub fn form(&self, shapes: &[Shape]) -> Option<ThreadForm> {
        let pitch = self.lead / self.starts.max(1) as f64;
        let (z0, z1) = self.z_span();
        // where there is material: the passes start and end in the air
        let (zmin, zmax) = shapes
            .iter()
            .flat_map(|s| &s.outer)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p[0]), b.max(p[0]))
            });
        let (lo, hi) = (
            z0.min(z1).max(zmin) + self.lead,
            z0.max(z1).min(zmax) - self.lead,
        );
        let whole = ((hi - lo) / pitch).floor();
        if !(pitch > 0.0 && whole >= 1.0) {
            return None;
        }
        let window = (lo, lo + whole * pitch);
        // lines parallel to the root line (a tapered thread's too), `h` above it (radially)
        let [a, b] = self.root;
        let slope = if (b[0] - a[0]).abs() < 1e-12 {
            0.0
        } else {
            (b[1] - a[1]) / (b[0] - a[0])
        };
        let root_at = move |z: f64| b[1] + slope * (z - b[0]);
        let crest = self.lowest_crest(shapes, window, pitch, &root_at)?;
        // the groove's share of the window h above the root: small near the root, large at
        // the crest
        let groove = |h: f64| 1.0 - material_fraction(shapes, |z| root_at(z) + h, window);
        // just inside both ends (1 nm, above the grid's snapping): a line on a flat sees
        // neither flat nor air
        let nudge = 1e-6 * crest.signum();
        let (h0, h1) = (nudge, crest - nudge);
        let pitch_h = height_where(&groove, h0, h1, 0.5)?;
        // two heights on the flanks, clear of the root's and the crest's flats
        let (lo_share, hi_share) = ((groove(h0) + 0.05).max(0.35), (groove(h1) - 0.05).min(0.65));
        let included_angle = (hi_share - lo_share >= 0.1)
            .then(|| {
                let lo_h = height_where(&groove, h0, h1, lo_share)?;
                let hi_h = height_where(&groove, h0, h1, hi_share)?;
                let widening = (hi_share - lo_share) * pitch / (hi_h - lo_h).abs();
                Some(2.0 * (widening / 2.0).atan().to_degrees())
            })
            .flatten();
        Some(ThreadForm {
            pitch_diameter: 2.0 * (b[1] + pitch_h),
            included_angle,
        })
    }
}

impl Thread {
    /// The crest's height above the root line (radially; below it for a bore) at the
    /// tooth where it is lowest, over whole pitches of `window`: each pitch holds one
    /// tooth, and its highest point is at a vertex or at the pitch's ends. Above the
    /// lowest tooth's crest a line meets crests of some teeth only, and a crest turned
    /// with a 0.01 mm taper made a 60° thread read 64° (field run 6, G).
    fn lowest_crest(
        &self,
        shapes: &[Shape],
        window: (f64, f64),
        pitch: f64,
        root_at: &dyn Fn(f64) -> f64,
    ) -> Option<f64> {
        let teeth = ((window.1 - window.0) / pitch).round().max(1.0) as usize;
        let ends = (0..=teeth).map(|k| window.0 + k as f64 * pitch);
        let zs: Vec<f64> = shapes
            .iter()
            .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
            .flatten()
            .map(|p| p[0])
            .filter(|z| (window.0..=window.1).contains(z))
            .chain(ends)
            .collect();
        // heights outward from the root toward the crest: negated in a bore
        let sign = match self.surface {
            Surface::Outer => 1.0,
            Surface::Bore => -1.0,
        };
        let mut highest = vec![f64::NEG_INFINITY; teeth];
        for (r, &z) in radii_at(shapes, &zs, self.surface).into_iter().zip(&zs) {
            let Some(r) = r else { continue };
            let h = sign * (r - root_at(z));
            // a pitch's ends belong to the teeth on both sides
            let at = (z - window.0) / pitch;
            let below = (at.floor() as usize).min(teeth - 1);
            let above = (at.ceil() as usize).saturating_sub(1).min(teeth - 1);
            for k in [below, above] {
                highest[k] = highest[k].max(h);
            }
        }
        let lowest = highest.into_iter().reduce(f64::min)?;
        lowest.is_finite().then_some(sign * lowest)
    }
}

/// The share of `window` (a Z interval) that lies inside the material on the straight line
/// r = `line`(z) (even-odd over every ring; an edge counts where it crosses the line
/// half-open).
fn material_fraction(shapes: &[Shape], line: impl Fn(f64) -> f64, window: (f64, f64)) -> f64 {
    let above = |p: [f64; 2]| p[1] - line(p[0]);
    let mut zs: Vec<f64> = shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flat_map(|ring| {
            (0..ring.len()).filter_map(|i| {
                let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
                let (ga, gb) = (above(a), above(b));
                ((ga > 0.0) != (gb > 0.0)).then(|| a[0] + ga / (ga - gb) * (b[0] - a[0]))
            })
        })
        .collect();
    zs.sort_by(f64::total_cmp);
    let inside: f64 = zs
        .chunks_exact(2)
        .map(|c| (c[1].min(window.1) - c[0].max(window.0)).max(0.0))
        .sum();
    inside / (window.1 - window.0)
}

/// The height between `root` and `crest` where `groove` (growing from root to crest) takes
/// `share`, by bisection; `None` when it does not pass `share` there.
fn height_where(groove: &dyn Fn(f64) -> f64, root: f64, crest: f64, share: f64) -> Option<f64> {
    let (mut a, mut b) = (root, crest);
    if !(groove(a) < share && groove(b) > share) {
        return None;
    }
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if groove(m) < share {
            a = m;
        } else {
            b = m;
        }
    }
    Some(0.5 * (a + b))
}

/// The threads of a toolpath, in program order (see [`Thread`]); `shapes` is the final
/// section, where the first pass's depth is measured from the crest.
pub fn threads(segments: &[Segment], tools: &ToolTable, shapes: &[Shape]) -> Vec<Thread> {
    ThreadPasses::of(segments, tools).measure(segments, shapes)
}

/// The index of the first move of each thread of a toolpath, in program order: where the
/// stock a thread cuts into is taken (see [`Thread::achieved_x`]).
pub fn thread_starts(segments: &[Segment], tools: &ToolTable) -> Vec<usize> {
    ThreadPasses::of(segments, tools).starts()
}

/// The passes of a toolpath's threads, found in one pass over the moves (a reader of a
/// long program's moves does it once, before the final section is known, and measures
/// them after).
#[derive(Debug, Clone, PartialEq)]
pub struct ThreadPasses(Vec<(Surface, Vec<usize>)>);

impl ThreadPasses {
    /// The threads' passes of `segments`, grouped as [`Thread`] says.
    pub fn of(segments: &[Segment], tools: &ToolTable) -> Self {
        Self(thread_groups(segments, tools))
    }

    /// The index of the first move of each thread, in program order.
    pub fn starts(&self) -> Vec<usize> {
        self.0.iter().map(|(_, passes)| passes[0]).collect()
    }

    /// The number of moves once each thread's last pass has run (its thread moves, the
    /// pull-out chamfer among them), in program order.
    pub fn ends(&self, segments: &[Segment]) -> Vec<usize> {
        self.0
            .iter()
            .map(|(_, passes)| pass_end(segments, passes[passes.len() - 1]))
            .collect()
    }

    /// The threads measured in the final section `shapes` (see [`threads`]); `segments`
    /// are the moves the passes were found in.
    pub fn measure(&self, segments: &[Segment], shapes: &[Shape]) -> Vec<Thread> {
        // the passes as the section sees them: a rear post's at negative X folded about the
        // axis (spec/simulation.md, "Tools past the axis"; at signed X a rear OD thread went
        // "deeper outward", the alarm LS-THREAD-SIDE; field run 6, B)
        let fold = |s: &Segment| {
            let mut f = *s;
            f.from.r = f.from.r.abs();
            f.to.r = f.to.r.abs();
            f
        };
        let groups: Vec<(Surface, Vec<Segment>, usize, usize)> = self
            .0
            .iter()
            .zip(self.ends(segments))
            .map(|(&(surface, ref passes), done_at)| {
                let first = passes[0];
                (
                    surface,
                    passes.iter().map(|&i| fold(&segments[i])).collect(),
                    first,
                    done_at,
                )
            })
            .collect();
        groups
            .into_iter()
            .map(|(surface, folded, first_move, done_at)| {
                let passes: Vec<&Segment> = folded.iter().collect();
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
                // two leads back from the end: the stamps are a lead apart from the pass's
                // start, so the lead at the end may hold only the narrow ridge between the
                // last stamp and the end; two hold a whole crest (within the pass)
                let back = (deepest.from.z - end.z).abs().min(2.0 * deepest.lead);
                let toward_start = (deepest.from.z - end.z).signum() * back;
                let crest = crest_radius(shapes, end.z, end.z + toward_start, surface);
                // each start goes down from the crest on its own; a thread cut in the air
                // has no crest, and its first depth is 0
                let (start_of, starts) = starts_of(&passes);
                let mut before: Vec<Option<f64>> = vec![None; starts];
                let pass_depths = passes
                    .iter()
                    .zip(&start_of)
                    .map(|(p, &k)| {
                        let last = before[k].or(crest).unwrap_or(p.to.r);
                        before[k] = Some(p.to.r);
                        (last - p.to.r).abs()
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
                    first_move,
                    done_at,
                    starts,
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
}

/// Passes of one start angle whose start points lie this far apart along the thread (a
/// fraction of the lead, around the circle) or more may cut different starts; see
/// [`starts_of`]. A compound (flank) infeed moves each pass's start along Z by its infeed
/// × tan 30°: from one pass to the next a few hundredths of a lead.
const START_GAP: f64 = 0.04;

/// Which start each pass cuts (numbered in the order the starts are first cut), and how
/// many there are. Passes of different start angles (multi-start Q, GSK L) cut different
/// starts. Among passes of one start angle, the start is where its stamps fall along the
/// thread, modulo the lead: two FANUC two-block G76 run from start points half a lead
/// apart cut two starts as surely as a Q does. Those places are grouped around the
/// circle: the gaps between starts are the widest (1/n of the lead, less the flank
/// infeed's spread of about 0.35 of the pitch), so a gap of half the widest one, and at
/// least [`START_GAP`], separates two starts; a single start's widest gap is the rest of
/// the circle.
fn starts_of(passes: &[&Segment]) -> (Vec<usize>, usize) {
    let angle = |k: usize| passes[k].thread_phase.rem_euclid(1.0);
    // the passes by start angle, each angle's grouped by start place (linear after a sort:
    // a CAM program may give every pass its own Q)
    let mut by_angle: Vec<usize> = (0..passes.len()).collect();
    by_angle.sort_by(|&a, &b| angle(a).total_cmp(&angle(b)));
    let mut group = vec![(0u64, 0usize); passes.len()];
    for own in by_angle.chunk_by(|&a, &b| angle(a) == angle(b)) {
        let place: Vec<f64> = own.iter().map(|&k| start_place(passes[k])).collect();
        for (&k, g) in own.iter().zip(places_grouped(&place)) {
            group[k] = (angle(k).to_bits(), g);
        }
    }
    // number the starts in program order
    let mut seen: std::collections::HashMap<(u64, usize), usize> = Default::default();
    let start_of = group
        .iter()
        .map(|g| {
            let next = seen.len();
            *seen.entry(*g).or_insert(next)
        })
        .collect();
    (start_of, seen.len())
}

/// The group of each of `place` (fractions of the lead on a circle), cut after each gap of
/// half the widest one or more (and at least [`START_GAP`]).
fn places_grouped(place: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..place.len()).collect();
    order.sort_by(|&a, &b| place[a].total_cmp(&place[b]));
    let gap_after = |k: usize| {
        let (a, b) = (place[order[k]], place[order[(k + 1) % order.len()]]);
        let gap = (b - a).rem_euclid(1.0);
        // one place alone (or all at one) has the whole circle after it
        if order.len() == 1 || gap == 0.0 && k + 1 == order.len() {
            1.0
        } else {
            gap
        }
    };
    let widest = (0..order.len()).map(gap_after).fold(0.0, f64::max);
    let cuts: Vec<usize> = (0..order.len())
        .filter(|&k| gap_after(k) >= (widest / 2.0).max(START_GAP))
        .collect();
    let mut group = vec![0; place.len()];
    if cuts.len() > 1 {
        for (g, w) in cuts.iter().enumerate() {
            let next = cuts[(g + 1) % cuts.len()];
            let mut k = (w + 1) % order.len();
            loop {
                group[order[k]] = g;
                if k == next {
                    break;
                }
                k = (k + 1) % order.len();
            }
        }
    }
    group
}

/// Where thread move `p` starts along its main axis, as a fraction of the lead: with its
/// start angle, where its stamps fall (`stock`'s thread stamps: from its start point every
/// lead, shifted by the start angle, toward its end).
fn start_place(p: &Segment) -> f64 {
    let (dz, dr) = (p.to.z - p.from.z, p.to.r - p.from.r);
    let at = if dz.abs() >= dr.abs() {
        p.from.z
    } else {
        p.from.r
    };
    (at / p.lead).rem_euclid(1.0)
}

/// The threads' passes, each by the index of its main thread move (of a run of thread
/// moves, the one most nearly along Z: a chamfer pull-out or a `LinuxCNC` G76 taper before
/// or after it belongs to the same pass), grouped as [`Thread`] says.
fn thread_groups(segments: &[Segment], tools: &ToolTable) -> Vec<(Surface, Vec<usize>)> {
    let mut groups: Vec<(Surface, Vec<usize>)> = vec![];
    let mut open = false;
    let mut i = 0;
    while i < segments.len() {
        match segments[i].motion {
            Motion::Rapid => i += 1,
            Motion::Feed => {
                open = false;
                i += 1;
            }
            Motion::Thread => {
                let run = segments[i..]
                    .iter()
                    .position(|s| s.motion != Motion::Thread)
                    .map_or(segments.len(), |k| i + k);
                let main = main_move(segments, i, run);
                let s = &segments[main];
                let surface = match tools.outline_for(s.tool, s.hint).0.bbox() {
                    Some((lo, hi)) if hi[1] < -lo[1] => Surface::Bore,
                    _ => Surface::Outer,
                };
                let joins = open
                    && groups.last().is_some_and(|(surf, passes)| {
                        let p = &segments[passes[0]];
                        let (a, b) = (p.from.z.min(p.to.z), p.from.z.max(p.to.z));
                        *surf == surface
                            && p.tool == s.tool
                            && p.lead == s.lead
                            && s.from.z.max(s.to.z) > a
                            && s.from.z.min(s.to.z) < b
                    });
                if joins {
                    groups.last_mut().expect("joins an open group").1.push(main);
                } else {
                    groups.push((surface, vec![main]));
                }
                open = true;
                i = run;
            }
        }
    }
    groups
}

/// The number of moves once the pass whose main move is `main` has run: past the thread
/// moves of its run.
fn pass_end(segments: &[Segment], main: usize) -> usize {
    segments[main..]
        .iter()
        .position(|s| s.motion != Motion::Thread)
        .map_or(segments.len(), |k| main + k)
}

/// Of the thread moves `from..to` (one pass), the one most nearly along Z (the first of
/// equals): the thread itself, not a chamfer pull-out or a taper, however long they are.
fn main_move(segments: &[Segment], from: usize, to: usize) -> usize {
    let slope = |k: usize| {
        let s = &segments[k];
        let dz = (s.to.z - s.from.z).abs();
        if dz > 0.0 {
            (s.to.r - s.from.r).abs() / dz
        } else {
            f64::INFINITY
        }
    };
    (from..to).fold(
        from,
        |best, k| if slope(k) < slope(best) { k } else { best },
    )
}

/// The crest of a thread between `z0` and `z1`: the highest outside or the lowest bore.
fn crest_radius(shapes: &[Shape], z0: f64, z1: f64, surface: Surface) -> Option<f64> {
    // piecewise linear: the extreme lies at a vertex or an end
    let (lo, hi) = (z0.min(z1), z0.max(z1));
    let zs: Vec<f64> = shapes
        .iter()
        .flat_map(|s| std::iter::once(&s.outer).chain(s.holes.iter()))
        .flatten()
        .map(|p| p[0])
        .filter(|z| (lo..=hi).contains(z))
        .chain([lo, hi])
        .collect();
    radii_at(shapes, &zs, surface)
        .into_iter()
        .flatten()
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

    /// A bar Φ20 × 20 with 60° V grooves every `pitch` from Z−2 down to Z−18.5, sharp
    /// roots at radius `root`: the section a sharp threading tool leaves.
    fn v_threaded(pitch: f64, root: f64, half_angle_deg: f64) -> Vec<Shape> {
        v_threaded_on_taper(pitch, root, half_angle_deg, 0.0)
    }

    /// [`v_threaded`] on a crest turned with a taper: radius 10 at Z0, 10 − `taper` at
    /// Z−20; each flank ends exactly on it.
    fn v_threaded_on_taper(pitch: f64, root: f64, half_angle_deg: f64, taper: f64) -> Vec<Shape> {
        let k = half_angle_deg.to_radians().tan();
        let t = taper / 20.0;
        let crest = |z: f64| 10.0 + t * z;
        let mut outer = vec![[-20.0, 0.0], [0.0, 0.0], [0.0, 10.0]];
        let mut c = -2.0;
        while c > -18.6 {
            // r = root + |z − c| / k meets r = 10 + t z
            let up = (10.0 - root + c / k) / (1.0 / k - t);
            let down = (10.0 - root - c / k) / (-1.0 / k - t);
            outer.extend([[up, crest(up)], [c, root], [down, crest(down)]]);
            c -= pitch;
        }
        outer.push([-20.0, crest(-20.0)]);
        vec![Shape {
            outer,
            holes: vec![],
        }]
    }

    /// A thread move from `(z0, r0)` to `(z1, r1)`.
    fn thread_move(z0: f64, r0: f64, z1: f64, r1: f64) -> Segment {
        Segment {
            motion: Motion::Thread,
            from: expander::Pt::new(z0, r0),
            to: expander::Pt::new(z1, r1),
            arc: None,
            tool: 4,
            hint: expander::ToolHint::Table,
            lead: 1.5,
            thread_phase: 0.0,
            feed: expander::FeedId::default(),
            span: Span::default(),
        }
    }

    #[test]
    fn the_main_move_of_a_pass_is_the_one_most_nearly_along_z() {
        // a short thread and a long 45° pull-out: the thread, however short
        let pass = [
            thread_move(2.0, 9.5, -1.0, 9.5),
            thread_move(-1.0, 9.5, -9.0, 17.5),
        ];
        assert_eq!(main_move(&pass, 0, 2), 0);
        // LinuxCNC's tapered pass: radial in, taper in, thread, taper out
        let pass = [
            thread_move(3.0, 16.3, 3.0, 16.0),
            thread_move(3.0, 16.0, 2.5, 15.4),
            thread_move(2.5, 15.4, -19.5, 15.4),
            thread_move(-19.5, 15.4, -20.0, 16.3),
        ];
        assert_eq!(main_move(&pass, 0, 4), 2);
    }

    fn thread_along(root: f64, lead: f64, starts: usize) -> Thread {
        Thread {
            span: Span::default(),
            surface: Surface::Outer,
            lead,
            root: [[5.0, root], [-19.0, root]], // from the air in front of the face
            pass_depths: vec![],
            wrong_side: false,
            starts,
            first_move: 0,
            done_at: 0,
        }
    }

    #[test]
    fn pitch_diameter_and_flank_angle_of_a_sharp_v_thread() {
        // M20 × 1.5 cut to X18.05 by a sharp 60° tool: the groove is as wide as the tooth
        // (0.75) where it is 0.75 / (2 tan 30°) = 0.649519 above the root:
        // d2 = 2 (9.025 + 0.649519) = 19.349038.
        let shapes = v_threaded(1.5, 9.025, 30.0);
        let form = thread_along(9.025, 1.5, 1).form(&shapes).unwrap();
        assert!((form.pitch_diameter - 19.349038).abs() < 1e-5, "{form:?}");
        assert!(
            (form.included_angle.unwrap() - 60.0).abs() < 1e-6,
            "{form:?}"
        );
        // a 55° (Whitworth) tool: d2 = 2 (9.025 + 0.75 / (2 tan 27.5°))
        let shapes = v_threaded(1.5, 9.025, 27.5);
        let form = thread_along(9.025, 1.5, 1).form(&shapes).unwrap();
        let d2 = 2.0 * (9.025 + 0.75 / (2.0 * 27.5f64.to_radians().tan()));
        assert!((form.pitch_diameter - d2).abs() < 1e-5, "{form:?} vs {d2}");
        assert!(
            (form.included_angle.unwrap() - 55.0).abs() < 1e-6,
            "{form:?}"
        );
        // two starts of lead 3 cut the same grooves: the pitch is 1.5 again
        let shapes = v_threaded(1.5, 9.025, 30.0);
        let form = thread_along(9.025, 3.0, 2).form(&shapes).unwrap();
        assert!((form.pitch_diameter - 19.349038).abs() < 1e-5, "{form:?}");
        // grooves 0.6 of the pitch wide at the crest: the angle from 35 % to 55 %
        let root = 10.0 - 0.9 / (2.0 * 30f64.to_radians().tan());
        let form = thread_along(root, 1.5, 1)
            .form(&v_threaded(1.5, root, 30.0))
            .unwrap();
        assert!(
            (form.included_angle.unwrap() - 60.0).abs() < 1e-6,
            "{form:?}"
        );
        // 0.54 wide at the crest: the angle from 35 % to 49 %
        let root = 10.0 - 0.81 / (2.0 * 30f64.to_radians().tan());
        let form = thread_along(root, 1.5, 1)
            .form(&v_threaded(1.5, root, 30.0))
            .unwrap();
        assert!(
            (form.included_angle.unwrap() - 60.0).abs() < 1e-6,
            "{form:?}"
        );
        assert!(
            (form.pitch_diameter - 2.0 * (root + 0.75 / (2.0 * 30f64.to_radians().tan()))).abs()
                < 1e-6
        );
        // on a crest turned with a 0.01 mm radial taper over 20 mm (field run 6, G: the
        // highest crest set the top of the flanks, and it read 64.3°)
        let root = 10.0 - 0.82;
        let form = thread_along(root, 1.5, 1)
            .form(&v_threaded_on_taper(1.5, root, 30.0, 0.01))
            .unwrap();
        assert!(
            (form.included_angle.unwrap() - 60.0).abs() < 1e-6,
            "{form:?}"
        );
        // no groove as wide as half the pitch between root and crest: a scratch
        let shapes = v_threaded(1.5, 9.9, 30.0);
        assert_eq!(thread_along(9.9, 1.5, 1).form(&shapes), None);
    }
}
