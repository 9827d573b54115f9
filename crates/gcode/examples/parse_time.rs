//! Times the reader alone on a program file (a measurement, not a test):
//! `cargo run --release -p gcode --example parse_time -- FILE [RUNS]` prints the fastest
//! and the median of RUNS reads (default 5), without and with custom macro B.

use gcode::{parse_with, ReadOptions};
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("usage: parse_time FILE [RUNS]");
    let runs: usize = args
        .next()
        .map_or(5, |r| r.parse().expect("RUNS is a number"));
    let text = std::fs::read_to_string(&path).expect("a UTF-8 program file");
    for (name, macros) in [("plain", None), ("macro", Some(macro_b::Dialect::Fanuc))] {
        let options = ReadOptions {
            macros,
            ..ReadOptions::default()
        };
        let mut times: Vec<f64> = (0..runs.max(1))
            .map(|_| {
                let t = Instant::now();
                let p = parse_with(&text, options).expect("the program reads");
                let secs = t.elapsed().as_secs_f64();
                drop(p);
                secs
            })
            .collect();
        times.sort_by(f64::total_cmp);
        println!(
            "{path} {name}: min {:.3} s, median {:.3} s ({} runs)",
            times[0],
            times[times.len() / 2],
            times.len()
        );
    }
}
