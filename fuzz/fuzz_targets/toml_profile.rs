//! The blank / target profile loader (castings, forgings, intended shapes).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(blank) = stock::Blank::from_profile_toml(text, 0.001) {
            let _ = stock::area(&blank.shapes);
        }
    }
});
