//! Whole-pipeline benchmark on generated programs: text -> parse -> expand -> remove ->
//! report. Run: `cargo bench --bench pipeline -- 100000 1000000` (moves per program).
//! Prints the time of each stage; figures go into PERFORMANCE.md. Not a test: no assertions.

use std::fmt::Write;
use std::time::Instant;

/// A G75-like wide groove made of pecks: 3 mm blade on a Φ125 × 110 bar, plunges every
/// `step` mm of Z, each plunge pecking down to Φ60 with a 0.3 mm chip-break retract.
fn grooving_program(moves: usize) -> String {
    let plunges = 400usize;
    let pecks_per_plunge = (moves / plunges / 2).max(1);
    let depth = (125.0 - 60.0) / 2.0;
    let peck = depth / pecks_per_plunge as f64;
    let mut s = String::with_capacity(moves * 16);
    s += "O9000;\nG99 M03 S600 T0101;\nG00 X127. Z2.;\n";
    for p in 0..plunges {
        let z = -5.0 - 95.0 * p as f64 / plunges as f64;
        let _ = writeln!(s, "G00 Z{z:.4};");
        let mut r = 62.5;
        for _ in 0..pecks_per_plunge {
            r -= peck;
            let _ = writeln!(s, "G01 X{:.4} F0.1;", 2.0 * r);
            let _ = writeln!(s, "G00 U0.6;");
        }
        s += "G00 X127.;\n";
    }
    s += "G00 X130. Z2.;\nM30;\n";
    s
}

/// CAM-style profiling: 50 passes, each a wavy contour of tiny G01 moves (no two collinear),
/// stepping 0.5 mm deeper per pass, with a 35° insert.
fn profiling_program(moves: usize) -> String {
    let passes = 50usize;
    let per_pass = (moves / passes).max(2);
    let mut s = String::with_capacity(moves * 24);
    s += "O9001;\nG99 M03 S600 T0202;\nG00 X130. Z2.;\n";
    for p in 0..passes {
        let base = 61.0 - 0.5 * p as f64;
        let _ = writeln!(s, "G00 X{:.4} Z1.;", 2.0 * (base + 2.0));
        for k in 0..per_pass {
            let z = -100.0 * k as f64 / (per_pass - 1) as f64;
            let r = base + 1.5 * (z / 4.0).sin();
            let _ = writeln!(s, "G01 X{:.4} Z{z:.4} F0.2;", 2.0 * r);
        }
        s += "G01 X130.;\nG00 Z1.;\n";
    }
    s += "M30;\n";
    s
}

const TOOLS: &str = "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\n\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"V\"\nnose_radius = 0.4\ntip = 3\n";

fn main() {
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if sizes.is_empty() {
        vec![100_000, 1_000_000]
    } else {
        sizes
    };
    let tools = stock::ToolTable::from_toml(TOOLS).expect("tool table");
    let blank = stock::Blank::bar(125.0, 110.0, 0.0, None).expect("blank");
    for (name, n, text) in sizes.iter().flat_map(|&n| {
        [
            ("grooving", n, grooving_program(n)),
            ("profiling", n, profiling_program(n)),
        ]
    }) {
        let t0 = Instant::now();
        let program = gcode::parse(&text).expect("parses");
        let t1 = Instant::now();
        let tp = expander::expand(
            &program,
            &expander::Machine::default(),
            &expander::Options::default(),
        );
        assert!(tp.alarms.is_empty(), "{:?}", tp.alarms.first());
        let t2 = Instant::now();
        // the library pipeline `latsim run` calls: the removal with the analysis beside and
        // after it (the program's own shapes, default machine, no workholding)
        let machine = expander::Machine::default();
        let settings = analysis::Settings {
            blank: &blank,
            tools: &tools,
            machine: &machine,
            fixture: None,
            tol: 0.01,
        };
        let (sim, findings) = analysis::pipeline(
            &tp,
            &analysis::Intents::Program,
            &settings,
            &stock::SimOptions::default(),
            &mut |_| {},
        );
        let t3 = Instant::now();
        let vertices: usize = sim
            .final_shapes
            .iter()
            .map(|s| s.outer.len() + s.holes.iter().map(Vec::len).sum::<usize>())
            .sum();
        println!(
            "{name:>9} {n:>8} moves requested, {:>8} segments: parse {:>6.3} s, expand {:>6.3} s, removal+analysis {:>6.3} s, total {:>6.3} s; {} crashes, final {} vertices, removed {:.1} mm², {:?}",
            tp.segments.len(),
            (t1 - t0).as_secs_f64(),
            (t2 - t1).as_secs_f64(),
            (t3 - t2).as_secs_f64(),
            (t3 - t0).as_secs_f64(),
            findings.crashes.len(),
            vertices,
            sim.removed_area,
            findings.verdict
        );
    }
}
