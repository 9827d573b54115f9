//! The reader: any bytes, as text, never panic; under every option set a run can give it
//! (decimal comma or not, macro B off, FANUC or Haas rules).
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/read.rs");

fuzz_target!(|data: &[u8]| body(data));
