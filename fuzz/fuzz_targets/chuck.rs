//! The workholding: `--chuck` in its compact form or as a TOML file, placed against a Φ40 ×
//! 60 bar, then every obstacle checked against a few moves (a facing cut to the centre, a
//! rapid toward the chuck, a feed along the bar) with a described tool.
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/chuck.rs");

fuzz_target!(|data: &[u8]| body(data));
