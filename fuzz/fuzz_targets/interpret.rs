//! Reader and interpreter: a program that reads is expanded without panic, in bounded time.
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/interpret.rs");

fuzz_target!(|data: &[u8]| body(data));
