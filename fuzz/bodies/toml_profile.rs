// The body of the `toml_profile` fuzz target (`fuzz/fuzz_targets/toml_profile.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input: a profile TOML as `--stock-file` reads it (chorded at 0.001 mm) and as
/// `--target` does (0.0001 mm, `src/job.rs`), and the text as `--stock` dimensions.
pub(crate) fn body(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(blank) = stock::Blank::from_profile_toml(text, 0.001) {
            let _ = stock::area(&blank.shapes);
        }
        if let Ok(part) = stock::profile_from_toml(text, 0.0001) {
            let _ = stock::area(&part);
        }
        if let Ok((d, l)) = stock::Blank::parse_dims(text) {
            let _ = stock::Blank::bar(d, l, 0.0, None);
        }
    }
}
