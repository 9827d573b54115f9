//! The machine profile loader.
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/toml_machine.rs");

fuzz_target!(|data: &[u8]| body(data));
