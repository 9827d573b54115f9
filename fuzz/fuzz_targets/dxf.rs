//! A DXF drawing given to `--stock-file` or `--target`: read, its loops chained and made
//! the shapes of a blank.
#![no_main]
use libfuzzer_sys::fuzz_target;

include!("../bodies/dxf.rs");

fuzz_target!(|data: &[u8]| body(data));
