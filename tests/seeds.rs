//! Every program in assets/ parses as printed, and the seed programs that use only the
//! foundation's codes expand without alarm.

mod common;
use common::*;

#[test]
fn every_program_in_assets_parses() {
    let mut n = 0;
    for entry in std::fs::read_dir(asset("programs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("nc") {
            continue;
        }
        let text = read(&path);
        let p = gcode::parse(&text).unwrap_or_else(|e| {
            panic!(
                "{}: {}:{} {}",
                path.display(),
                e.span.line,
                e.span.column,
                e.message
            )
        });
        assert!(p.block_count() > 0, "{}", path.display());
        n += 1;
    }
    assert!(n >= 8, "only {n} programs found");
}

#[test]
fn seed_003_annotation_is_read_as_a_note() {
    let p = gcode::parse(&read(&asset("programs/O0006.nc"))).unwrap();
    assert_eq!(p.notes.len(), 1);
    assert_eq!(p.notes[0].span.line, 8);
}

/// The cycles are recognised and reported at their word, not skipped.
#[test]
fn cycles_are_reported_as_not_implemented_at_their_word() {
    for (file, line, column, code) in [
        ("tnrc-seed004.nc", 6, 1, "G42"),
    ] {
        let p = gcode::parse(&read(&asset(&format!("programs/{file}")))).unwrap();
        let tp = expander::expand(&p, &expander::Machine::default(), &Default::default());
        let a = tp
            .alarms
            .first()
            .unwrap_or_else(|| panic!("{file}: no alarm"));
        assert_eq!(
            (a.span.line, a.span.column, a.code),
            (line, column, "LS-NOT-IMPLEMENTED"),
            "{file}: {a}"
        );
        assert!(a.message.starts_with(code), "{file}: {}", a.message);
    }
}
