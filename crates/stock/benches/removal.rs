//! Removal benchmark on generated programs (plain `Instant`, not a timed test).
//!
//! `cargo bench -p stock --bench removal -- [N ...]` (default N = 100000 1000000);
//! measure peak memory with `/usr/bin/time -v`. Patterns, all on a Φ125 × 110 bar:
//! - `grooves`: G75-like pecking across the bar with a 3 mm blade (grooves stepped by
//!   2.5 mm so they overlap), pecks fed down and retracted by rapid;
//! - `roughing`: G90-like passes with a 35° insert down to a shoulder at Z-100;
//! - `taper`: the same passes ending on a 1:2 taper, so every pass leaves a step;
//! - `wobble`: like `grooves` but every peck slightly off the groove line, so that no
//!   moves merge and every sweep goes through the boolean engine.

use expander::{Feed, Motion, Pt, Segment, Span};
use std::time::Instant;
use stock::{area, simulate, Blank, Insert, SimOptions, Tool, ToolTable};

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
        feed: Feed::Rapid,
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
    println!(
        "{:<9} {:>9} {:>9} {:>12} {:>9} {:>8} {:>12}",
        "pattern", "moves", "time s", "moves/s", "vertices", "crashes", "removed mm²"
    );
    for &n in &sizes {
        let cases: Vec<(&str, Vec<Segment>, &ToolTable)> = vec![
            ("grooves", grooves(n, 0.0), &blade),
            ("wobble", grooves(n, 0.001), &blade),
            ("roughing", roughing(n, false), &v35),
            ("taper", roughing(n, true), &v35),
        ];
        for (name, segs, tools) in cases {
            if only.as_deref().is_some_and(|o| o != name) {
                continue;
            }
            let t = Instant::now();
            let sim = simulate(&blank, tools, &segs, &SimOptions::default(), &mut |_| {});
            let dt = t.elapsed().as_secs_f64();
            let verts: usize = sim
                .final_shapes
                .iter()
                .map(|s| s.outer.len() + s.holes.iter().map(Vec::len).sum::<usize>())
                .sum();
            println!(
                "{:<9} {:>9} {:>9.3} {:>12.0} {:>9} {:>8} {:>12.3}",
                name,
                segs.len(),
                dt,
                segs.len() as f64 / dt,
                verts,
                sim.crashes.len(),
                area(&blank.shapes) - area(&sim.final_shapes)
            );
        }
    }
}
