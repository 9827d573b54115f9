// The body of the `toml_profile` fuzz target (`fuzz/fuzz_targets/toml_profile.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(blank) = stock::Blank::from_profile_toml(text, 0.001) {
            let _ = stock::area(&blank.shapes);
        }
    }
}
