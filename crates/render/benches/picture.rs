//! How long the report picture takes for a big toolpath: SVG, then PNG (resvg), of a
//! grooving pattern with 10⁵ moves (or the count given: `cargo bench -p render --bench
//! picture -- 1000000`). Plain `Instant`, like the other benches: it prints figures and
//! asserts nothing.
#[path = "../tests/common/mod.rs"]
mod common;

use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .skip(1)
        .find_map(|a| a.parse().ok())
        .unwrap_or(100_000);
    let report = common::many_segments(n);
    let t = Instant::now();
    let svg = render::svg(&report);
    let svg_time = t.elapsed();
    let t = Instant::now();
    let png = render::png(&report).expect("renders");
    let png_time = t.elapsed();
    println!(
        "{n} moves: svg {} bytes in {svg_time:.2?}, png {} bytes in {png_time:.2?}",
        svg.len(),
        png.len()
    );
}
