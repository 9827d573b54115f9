//! A program file's bytes decoded as `latsim` decodes them (`--encoding`, or the guess for
//! a file that is not UTF-8) and the text read.
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/decode.rs");

fuzz_target!(|data: &[u8]| body(data));
