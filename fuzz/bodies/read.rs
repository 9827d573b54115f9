// The body of the `read` fuzz target (`fuzz/fuzz_targets/read.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
/// One fuzz input: read under every option, and the blocks read again from the text
/// (`gcode::Blocks`) must be the blocks the reader held, also with shifted spans.
pub(crate) fn body(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    for decimal_comma in [false, true] {
        for macros in [None, Some(macro_b::Dialect::Fanuc), Some(macro_b::Dialect::Haas)] {
            let options = gcode::ReadOptions { decimal_comma, macros, ..Default::default() };
            let read = gcode::parse_with(&text, options);
            let held = gcode::parse_held(&text, options);
            assert_eq!(read, held, "blocks read again differ from the blocks read");
            if let (Ok(mut read), Ok(mut held)) = (read, held) {
                // the blocks read again with one reader, as a chunk read ahead is
                for (r, h) in read.programs.iter().zip(&held.programs) {
                    assert_eq!(r.blocks.read(0..r.blocks.len()), h.blocks.all());
                }
                read.shift_spans(1000);
                held.shift_spans(1000);
                assert_eq!(read, held, "shifted blocks read again differ");
            }
        }
    }
}
