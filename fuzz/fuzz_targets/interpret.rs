//! Reader and interpreter: a program that reads is expanded without panic, in bounded time.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
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
});
