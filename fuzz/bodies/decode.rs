// The body of the `decode` fuzz target (`fuzz/fuzz_targets/decode.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.

/// The `--encoding` labels tried besides none (the guess): the encodings of the controls'
/// exports and editors (issue 31), a stateful one and a two-byte one.
const LABELS: &[&str] = &[
    "utf-8",
    "gbk",
    "gb18030",
    "big5",
    "shift_jis",
    "euc-kr",
    "windows-1252",
    "iso-2022-jp",
    "utf-16le",
];

/// One fuzz input: a program file's bytes decoded as `latsim` decodes them (`gcode::decode`,
/// the guess and each `--encoding`), and the guessed text read. A decoded UTF-8 file is its
/// own text; a failure names a byte of the file before which every byte is a character.
pub(crate) fn body(data: &[u8]) {
    let forced = LABELS.iter().map(|l| {
        Some(gcode::encoding::encoding_for_label(l).expect("a WHATWG label"))
    });
    for enc in std::iter::once(None).chain(forced) {
        match gcode::decode(data, enc) {
            Ok(d) => {
                if enc.is_none() {
                    if let Ok(utf8) = std::str::from_utf8(data) {
                        assert_eq!(d.text, utf8, "UTF-8 is read as it is");
                        assert!(!d.guessed);
                    }
                    let _ = gcode::parse(&d.text);
                }
            }
            Err(e) => {
                assert!(e.offset <= data.len(), "offset {} of {} bytes", e.offset, data.len());
                assert_prefix_decodes(data, e.encoding, e.offset);
            }
        }
    }
}

/// The bytes before `offset` are characters in `encoding`: the byte named is where the
/// first malformed sequence starts, not past it (it was up to two bytes past it until
/// `first_error` in `crates/gcode/src/encoding.rs` counted the bytes read after the sequence).
fn assert_prefix_decodes(data: &[u8], encoding: &'static gcode::encoding::Encoding, offset: usize) {
    let clean = |end: usize| {
        encoding
            .decode_without_bom_handling_and_without_replacement(&data[..end])
            .is_some()
    };
    assert!(
        clean(offset),
        "{}: the bytes before byte {offset}, the one named, hold a malformed sequence: {:?}",
        encoding.name(),
        &data[offset.saturating_sub(8)..(offset + 8).min(data.len())]
    );
}
