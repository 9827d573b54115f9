//! Custom macro B: any bytes read with macro B on (FANUC and Haas rules) and run by the
//! interpreter — statements, expressions, calls, loops — without panic, in bounded time
//! (a small block budget ends runaway loops).
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/interpret_macro.rs");

fuzz_target!(|data: &[u8]| body(data));
