// The body of the `dxf` fuzz target (`fuzz/fuzz_targets/dxf.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
use tooling_iso::dxf_io::{self, ReadOptions, XMode};

/// One fuzz input: a drawing given to `--stock-file` or `--target` (`src/cad.rs`), read as
/// the binary reads it — text in memory, other bytes (binary DXF, DXB) from a file, as
/// `dxf_io::read_profile_file` takes them — for both roles and both meanings of Y, and its
/// loops made the shapes of a blank.
pub(crate) fn body(data: &[u8]) {
    for (x_mode, layer) in [(XMode::Radius, "PART"), (XMode::Diameter, "INTENDED")] {
        let opts = ReadOptions {
            x_mode,
            prefer_layer: Some(layer),
            ..ReadOptions::default()
        };
        let read = match std::str::from_utf8(data) {
            Ok(text) => dxf_io::read_profile_str(text, &opts),
            Err(_) => read_from_file(data, &opts),
        };
        let Ok(rings) = read else {
            continue;
        };
        let blank = stock::Blank::from_rings(&oriented(&rings), "");
        let _ = stock::area(&blank.shapes);
    }
}

/// The bytes read back from a file of this process (`read_profile_file`).
fn read_from_file(data: &[u8], opts: &ReadOptions) -> Result<Vec<Vec<geom::Pt>>, tooling_iso::IsoError> {
    let path = std::env::temp_dir().join(format!(
        "latsim-fuzz-dxf-{}-{:?}.dxf",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::write(&path, data).expect("a temporary file");
    let read = dxf_io::read_profile_file(&path, opts);
    let _ = std::fs::remove_file(&path);
    read
}

/// `src/cad.rs`'s rule: a loop inside an odd number of others is a hole, turned clockwise.
fn oriented(rings: &[Vec<geom::Pt>]) -> Vec<Vec<[f64; 2]>> {
    let depth = |i: usize| {
        let p = rings[i][0];
        rings
            .iter()
            .enumerate()
            .filter(|&(j, r)| j != i && geom::ring::contains(r, p))
            .count()
    };
    (0..rings.len())
        .map(|i| {
            let mut ring: Vec<[f64; 2]> = rings[i].iter().map(|p| [p.z, p.r]).collect();
            if depth(i) % 2 == 1 {
                ring.reverse();
            }
            ring
        })
        .collect()
}
