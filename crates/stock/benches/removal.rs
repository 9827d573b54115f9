//! Removal benchmark on generated programs (plain `Instant`, not a timed test).
//!
//! `cargo bench -p stock --bench removal -- [N ...]` (default N = 100000 1000000);
//! `PATTERN=name` runs one pattern, `FEED_PATHS=0` sweeps feeds one by one
//! (`SimOptions::feed_paths` off), `RING_AIR=0` tries rings on every tile their box
//! overlaps (`SimOptions::ring_air` off), `COVER=0` sends every sweep to the boolean call
//! (`SimOptions::cover` off), `PASS_GROUPS=0` cuts repeated passes one by one
//! (`SimOptions::pass_groups` off), `EXACT=1` also cuts each program with `merge_tol = 0`
//! (no merged chains, no pass groups) and prints the Hausdorff distance and the area of the
//! symmetric difference between the two final parts; measure peak memory with
//! `/usr/bin/time -v`. Patterns, on a
//! Φ125 × 110 bar (`g73` on Φ190 × 110):
//! - `grooves`: G75-like pecking across the bar with a 3 mm blade (grooves stepped by
//!   2.5 mm so they overlap), pecks fed down and retracted by rapid;
//! - `roughing`: G90-like passes with a 35° insert down to a shoulder at Z-100;
//! - `taper`: the same passes ending on a 1:2 taper, so every pass leaves a step;
//! - `wobble`: like `grooves` but every peck slightly off the groove line, so that no
//!   moves merge and every sweep goes through the boolean engine;
//! - `contour`: contour-parallel roughing of a wavy profile (the program of
//!   `benches/geos_compare.py`): 50 passes, each the finished profile moved out by 0.3 mm,
//!   n/50 short G01 moves a pass, a sharp 35° insert;
//! - `g73`: a G73-like pattern repeating cycle: an O0006-like profile (straights, a taper,
//!   an R20 arc) swept n/8 times, each pass moved by (4, 2) mm / passes toward the part,
//!   so that every pass leaves a new sliver along the whole profile (55° insert r0.4);
//! - `threads`: an M18 × 1.5 thread 17.3 mm long cut as n/4 single passes (rapid in at
//!   Z2, thread move, rapid out and back: a CAM's G32 passes, or G92's), each deeper than
//!   the last by 0.6 mm / passes, at most 0.0005, on a Φ20 × 40 bar (60° threading tool);
//! - `g76`: the same thread cut as G76 cuts it, flank infeed: pass k of n/4 at depth
//!   0.92·√(k / passes) mm, moved back along Z by the depth × tan 30°, so that every pass
//!   leaves a step on the trailing flank.

use expander::{FeedId, Motion, Pt, Segment, Span};
use std::time::Instant;
use stock::{
    area, hausdorff, simulate, symmetric_difference_area, Blank, Insert, Shape, SimOptions, Tool,
    ToolTable,
};

/// The shapes with their needles taken out (a vertex where the boundary turns straight
/// back, its two sides within 10⁻⁶ mm: the integer boolean core leaves a few, µm long and
/// 10⁻⁷ mm wide, where edges of consecutive passes meet nearly collinear; they bound no
/// area to speak of, but a Hausdorff distance sees them).
fn without_needles(shapes: &[Shape]) -> Vec<Shape> {
    let clean = |ring: &[[f64; 2]]| {
        let mut r = ring.to_vec();
        let mut changed = true;
        while changed && r.len() > 3 {
            changed = false;
            let mut i = 0;
            while i < r.len() && r.len() > 3 {
                let n = r.len();
                let (a, b, c) = (r[(i + n - 1) % n], r[i], r[(i + 1) % n]);
                let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
                let cross = u[0] * v[1] - u[1] * v[0];
                let dot = u[0] * v[0] + u[1] * v[1];
                // a turn back whose sides lie within 10⁻⁶ mm of each other
                let longer = u[0].hypot(u[1]).max(v[0].hypot(v[1]));
                if dot < 0.0 && cross.abs() <= 1e-6 * longer {
                    r.remove(i);
                    changed = true;
                } else {
                    i += 1;
                }
            }
        }
        r
    };
    shapes
        .iter()
        .map(|s| Shape {
            outer: clean(&s.outer),
            holes: s.holes.iter().map(|h| clean(h)).collect(),
        })
        .collect()
}

/// Vertices of the shapes, holes included.
fn vertices(shapes: &[Shape]) -> usize {
    shapes
        .iter()
        .map(|s| s.outer.len() + s.holes.iter().map(Vec::len).sum::<usize>())
        .sum()
}

fn seg(motion: Motion, from: Pt, to: Pt) -> Segment {
    Segment {
        motion,
        from,
        to,
        arc: None,
        tool: 1,
        hint: expander::ToolHint::Table,
        lead: 0.0,
        thread_phase: 0.0,
        feed: FeedId::default(),
        span: Span::default(),
    }
}

/// Appends a move from the current position.
struct Path {
    at: Pt,
    segs: Vec<Segment>,
}

impl Path {
    fn go(&mut self, motion: Motion, z: f64, r: f64) {
        let to = Pt::new(z, r);
        self.segs.push(seg(motion, self.at, to));
        self.at = to;
    }
}

fn grooves(n: usize, wobble: f64) -> Vec<Segment> {
    let zs: Vec<f64> = (0..)
        .map(|k| -108.0 + 2.5 * k as f64)
        .take_while(|z| z + 3.0 <= 0.0)
        .collect();
    let per_groove = n / zs.len();
    let pecks = (per_groove.saturating_sub(3) / 2).max(1);
    let (top, bottom) = (64.0, 30.0);
    let step = (62.5 - bottom) / pecks as f64;
    let retract = (step / 2.0).min(0.5);
    let mut p = Path {
        at: Pt::new(5.0, 70.0),
        segs: Vec::with_capacity(n + 100),
    };
    for &z in &zs {
        p.go(Motion::Rapid, z, top);
        p.go(Motion::Rapid, z, 63.0);
        for k in 1..=pecks {
            let zz = z + if k % 2 == 1 { wobble } else { 0.0 };
            p.go(Motion::Feed, zz, 62.5 - step * k as f64);
            p.go(Motion::Rapid, zz, 62.5 - step * k as f64 + retract);
        }
        p.go(Motion::Rapid, z, top);
    }
    p.segs
}

fn roughing(n: usize, taper: bool) -> Vec<Segment> {
    let passes = n / 4;
    let doc = (62.5 - 30.0) / passes as f64;
    let mut p = Path {
        at: Pt::new(5.0, 64.0),
        segs: Vec::with_capacity(n + 4),
    };
    for k in 1..=passes {
        let r = 62.5 - doc * k as f64;
        let zend = if taper {
            (-100.0 + 2.0 * (62.5 - r)).min(-40.0)
        } else {
            -100.0
        };
        p.go(Motion::Rapid, 5.0, r);
        p.go(Motion::Feed, zend, r);
        p.go(Motion::Feed, zend + 0.5, r + 0.5);
        p.go(Motion::Rapid, 5.0, r + 0.5);
    }
    p.segs
}

/// The contour pattern's finished profile (as in `benches/geos_compare.py`).
fn wave(z: f64) -> f64 {
    35.0 + 3.0 * (z / 6.0).sin() + 1.5 * (z / 2.3).sin()
}

fn contour(n: usize) -> Vec<Segment> {
    let passes = 50;
    let per_pass = (n / passes).saturating_sub(4).max(2);
    let mut p = Path {
        at: Pt::new(5.0, 65.0),
        segs: Vec::with_capacity(n + 8),
    };
    for k in 0..passes {
        let off = 0.3 * (passes - 1 - k) as f64;
        p.go(Motion::Rapid, 2.0, wave(0.0) + off + 1.0);
        p.go(Motion::Rapid, 2.0, wave(0.0) + off);
        for j in 1..=per_pass {
            let z = 2.0 - 102.0 * j as f64 / per_pass as f64;
            p.go(Motion::Feed, z, wave(z.min(0.0)) + off);
        }
        let z = p.at.z;
        p.go(Motion::Feed, z, 64.0);
        p.go(Motion::Rapid, 5.0, 64.0);
    }
    p.segs
}

fn g73(n: usize) -> Vec<Segment> {
    let passes = (n / 8).max(1);
    let mut p = Path {
        at: Pt::new(10.0, 100.0),
        segs: Vec::with_capacity(n + 8),
    };
    for k in 0..passes {
        let t = 1.0 - (k + 1) as f64 / passes as f64;
        let (dz, dr) = (4.0 * t, 2.0 * t);
        p.go(Motion::Rapid, dz + 2.0, 40.0 + dr);
        p.go(Motion::Feed, dz, 40.0 + dr);
        p.go(Motion::Feed, dz - 20.0, 40.0 + dr);
        p.go(Motion::Feed, dz - 30.0, 60.0 + dr);
        p.go(Motion::Feed, dz - 50.0, 60.0 + dr);
        // an R20 quarter-ish arc up to r 80 over 20 mm of Z (centre on the chord's right)
        let (from, to) = (p.at, Pt::new(dz - 70.0, 80.0 + dr));
        let mut arc = seg(Motion::Feed, from, to);
        arc.arc = Some(expander::Arc {
            center: Pt::new(dz - 70.0, 60.0 + dr),
            ccw: false,
        });
        p.segs.push(arc);
        p.at = to;
        p.go(Motion::Feed, dz - 80.0, 96.0 + dr); // out past the bar's r 95
        p.go(Motion::Rapid, dz - 80.0, 100.0);
        p.go(Motion::Rapid, 10.0, 100.0);
    }
    p.segs
}

/// A thread's passes (see the module documentation): `flank` moves each pass back along Z
/// by its depth × tan 30° (G76's flank infeed), else every pass is a radial plunge.
fn threads(n: usize, flank: bool) -> Vec<Segment> {
    let passes = (n / 4).max(1);
    let mut p = Path {
        at: Pt::new(2.0, 10.5),
        segs: Vec::with_capacity(n + 4),
    };
    let tan30 = 30f64.to_radians().tan();
    for k in 1..=passes {
        let (depth, dz) = if flank {
            let d = 0.92 * (k as f64 / passes as f64).sqrt();
            (d, -d * tan30)
        } else {
            ((0.6 / passes as f64).min(0.0005) * k as f64, 0.0)
        };
        p.go(Motion::Rapid, 2.0 + dz, 8.5 - depth);
        let from = p.at;
        let to = Pt::new(-17.3 + dz, from.r);
        let mut t = seg(Motion::Thread, from, to);
        t.lead = 1.5;
        p.segs.push(t);
        p.at = to;
        p.go(Motion::Rapid, to.z, 10.5);
        p.go(Motion::Rapid, 2.0 + dz, 10.5);
    }
    p.segs
}

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if args.is_empty() {
        vec![100_000, 1_000_000]
    } else {
        args
    };
    let only = std::env::var("PATTERN").ok();
    let blank = Blank::bar(125.0, 110.0, 0.0, None).expect("bar");
    let blade = ToolTable::from_tools(vec![(1, Tool::DEFAULT_BLADE)]);
    let v35 = ToolTable::from_tools(vec![(
        1,
        Tool::Turning {
            insert: Insert::V,
            nose_radius: 0.4,
            tip: 3,
            entering_angle: 93.0,
            edge: 11.0,
        },
    )]);
    let v35_sharp = ToolTable::from_tools(vec![(
        1,
        Tool::Turning {
            insert: Insert::V,
            nose_radius: 0.0,
            tip: 3,
            entering_angle: 93.0,
            edge: 11.0,
        },
    )]);
    let d55 = ToolTable::from_tools(vec![(1, Tool::DEFAULT)]);
    let big = Blank::bar(190.0, 110.0, 0.0, None).expect("bar");
    let m18 = Blank::bar(20.0, 40.0, 0.0, None).expect("bar");
    let thread60 = ToolTable::from_tools(vec![(
        1,
        Tool::Threading {
            angle: 60.0,
            tip_flat: 0.0,
            side: stock::ThreadSide::Od,
        },
    )]);
    println!(
        "{:<9} {:>9} {:>9} {:>12} {:>9} {:>8} {:>12}",
        "pattern", "moves", "time s", "moves/s", "vertices", "crashes", "removed mm²"
    );
    for &n in &sizes {
        let names = [
            "grooves", "wobble", "roughing", "taper", "contour", "g73", "threads", "g76",
        ];
        for name in names {
            if only.as_deref().is_some_and(|o| o != name) {
                continue;
            }
            // generated one at a time: at 10^6 moves each list is ~100 MB
            let (segs, tools, blank) = match name {
                "grooves" => (grooves(n, 0.0), &blade, &blank),
                "wobble" => (grooves(n, 0.001), &blade, &blank),
                "roughing" => (roughing(n, false), &v35, &blank),
                "taper" => (roughing(n, true), &v35, &blank),
                "contour" => (contour(n), &v35_sharp, &blank),
                "g73" => (g73(n), &d55, &big),
                "threads" => (threads(n, false), &thread60, &m18),
                _ => (threads(n, true), &thread60, &m18),
            };
            let opts = SimOptions {
                feed_paths: std::env::var("FEED_PATHS").map_or(true, |v| v != "0"),
                ring_air: std::env::var("RING_AIR").map_or(true, |v| v != "0"),
                cover: std::env::var("COVER").map_or(true, |v| v != "0"),
                pass_groups: std::env::var("PASS_GROUPS").map_or(true, |v| v != "0"),
                ..SimOptions::default()
            };
            let t = Instant::now();
            let sim = simulate(blank, tools, &segs, &opts, &mut |_| {});
            let dt = t.elapsed().as_secs_f64();
            println!(
                "{:<9} {:>9} {:>9.3} {:>12.0} {:>9} {:>8} {:>12.3}",
                name,
                segs.len(),
                dt,
                segs.len() as f64 / dt,
                vertices(&sim.final_shapes),
                sim.crashes.len(),
                area(&blank.shapes) - area(&sim.final_shapes)
            );
            if std::env::var("EXACT").is_ok_and(|v| v == "1") {
                let exact_opts = SimOptions {
                    merge_tol: 0.0,
                    ..opts
                };
                let exact = simulate(blank, tools, &segs, &exact_opts, &mut |_| {});
                let (ours, exact_shapes) = (
                    without_needles(&sim.final_shapes),
                    without_needles(&exact.final_shapes),
                );
                println!(
                    "  needle vertices: {} here, {} with merge_tol = 0",
                    vertices(&sim.final_shapes) - vertices(&ours),
                    vertices(&exact.final_shapes) - vertices(&exact_shapes)
                );
                println!(
                    "  longest needle here: {:.6} mm",
                    hausdorff(&sim.final_shapes, &ours)
                );
                println!(
                    "  against merge_tol = 0: hausdorff {:.6} mm ({:.6} without needles), symmetric difference {:.6} mm², crashes {} / {}",
                    hausdorff(&sim.final_shapes, &exact.final_shapes),
                    hausdorff(&ours, &exact_shapes),
                    symmetric_difference_area(&sim.final_shapes, &exact.final_shapes),
                    sim.crashes.len(),
                    exact.crashes.len()
                );
            }
        }
    }
}
