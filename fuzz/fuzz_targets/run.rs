//! Reader, interpreter and material removal on a small blank, with described tools (their
//! bodies are probed: holder designation, blade reach) and the deviation from a fixed
//! intended part. The reports themselves are covered by `tests/robustness.rs`.
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/run.rs");

fuzz_target!(|data: &[u8]| body(data));
