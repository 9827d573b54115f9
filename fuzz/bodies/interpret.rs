// The body of the `interpret` fuzz target (`fuzz/fuzz_targets/interpret.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input.
pub(crate) fn body(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(program) = gcode::parse(&text) else {
        return;
    };
    for machine in [
        expander::Machine::default(),
        expander::Machine::from_toml("increment = \"is-c\"\nfeed_mode = \"g99\"\npower_on_feed = 0.2")
            .expect("a valid profile"),
    ] {
        // a smaller move budget than the CLI's 5·10^6: the instrumented build runs ~30× slower
        let opts = expander::Options {
            max_segments: 200_000,
            ..Default::default()
        };
        let _ = expander::expand(&program, &machine, &opts);
    }
}
