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
        let _ = expander::expand(&program, &machine, &Default::default());
    }
});
