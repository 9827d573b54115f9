// The body of the `toml_machine` fuzz target (`fuzz/fuzz_targets/toml_machine.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = expander::Machine::from_toml(text);
    }
}
