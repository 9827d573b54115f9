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

/// The one-block G76 (Haas / FANUC 10/11/15) is recognised and reported at its K word (the
/// word that makes it the one-block form) under the default control, naming the control to
/// use, not skipped.
#[test]
fn one_block_g76_is_an_alarm_at_its_word() {
    let p = gcode::parse("M3 S300\nG0 X30 Z5\n  G76 X27.4 Z-20 K1.3 D300 F2\n").unwrap();
    let tp = expander::expand(&p, &expander::Machine::default(), &Default::default());
    let a = tp.alarms.first().expect("an alarm");
    assert_eq!(
        (a.span.line, a.span.column, a.code),
        (3, 18, "LS-ONE-BLOCK-FORM"),
        "{a}"
    );
    assert!(a.message.contains("--control haas"), "{a}");
}
