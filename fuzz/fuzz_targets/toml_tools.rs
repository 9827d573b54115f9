//! The tool table loader.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(table) = stock::ToolTable::from_toml(text) {
            for t in table.numbers() {
                let _ = table.outline(t);
            }
        }
    }
});
