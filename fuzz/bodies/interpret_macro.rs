// The body of the `interpret_macro` fuzz target (`fuzz/fuzz_targets/interpret_macro.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    for (control, dialect, options) in [
        (
            expander::Control::FanucA,
            macro_b::Dialect::Fanuc,
            macro_b::Options::fanuc(),
        ),
        (
            expander::Control::Haas,
            macro_b::Dialect::Haas,
            macro_b::Options::haas(),
        ),
    ] {
        let read = gcode::ReadOptions {
            macros: Some(dialect),
            ..Default::default()
        };
        let Ok(program) = gcode::parse_with(&text, read) else {
            continue;
        };
        // budgets far below the CLI's: the instrumented build runs ~30× slower
        let opts = expander::Options {
            max_segments: 200_000,
            max_blocks: 200_000,
            macros: Some(options),
            ..Default::default()
        };
        let _ = expander::expand(&program, &expander::Machine::for_control(control), &opts);
    }
}
