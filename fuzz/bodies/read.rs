// The body of the `read` fuzz target (`fuzz/fuzz_targets/read.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    for decimal_comma in [false, true] {
        for macros in [None, Some(macro_b::Dialect::Fanuc), Some(macro_b::Dialect::Haas)] {
            let options = gcode::ReadOptions { decimal_comma, macros };
            let _ = gcode::parse_with(&text, options);
        }
    }
}
