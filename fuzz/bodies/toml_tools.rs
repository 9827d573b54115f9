// The body of the `toml_tools` fuzz target (`fuzz/fuzz_targets/toml_tools.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(table) = stock::ToolTable::from_toml(text) {
            for t in table.numbers() {
                let _ = table.outline(t);
            }
        }
    }
}
