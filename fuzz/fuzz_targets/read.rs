//! The reader: any bytes, as text, never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    for decimal_comma in [false, true] {
        let _ = gcode::parse_with(&text, gcode::ReadOptions { decimal_comma });
    }
});
