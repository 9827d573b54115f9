//! The reader: any bytes, as text, never panic; under every option set a run can give it
//! (decimal comma or not, macro B off, FANUC or Haas rules).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    for decimal_comma in [false, true] {
        for macros in [None, Some(macro_b::Dialect::Fanuc), Some(macro_b::Dialect::Haas)] {
            let options = gcode::ReadOptions { decimal_comma, macros };
            let _ = gcode::parse_with(&text, options);
        }
    }
});
