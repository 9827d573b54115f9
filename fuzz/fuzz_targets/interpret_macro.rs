//! Custom macro B: any bytes read with macro B on (FANUC and Haas rules) and run by the
//! interpreter — statements, expressions, calls, loops — without panic, in bounded time
//! (a small block budget ends runaway loops).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
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
});
