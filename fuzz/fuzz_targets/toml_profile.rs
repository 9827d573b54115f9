//! The blank / target profile loader (castings, forgings, intended shapes).
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/toml_profile.rs");

fuzz_target!(|data: &[u8]| body(data));
