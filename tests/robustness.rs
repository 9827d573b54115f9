//! No input may panic or hang: thousands of random programs built from G-code fragments go
//! through the reader, the interpreter, the removal and the report writers.

mod common;

/// A small deterministic generator (no dependency; the same programs on every run).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[(self.next() as usize) % items.len()]
    }
}

const CODES: &[&str] = &[
    "G00", "G01", "G02", "G03", "G04", "G20", "G21", "G28", "G32", "G40", "G41", "G42", "G50",
    "G54", "G55", "G70", "G71", "G72", "G73", "G74", "G75", "G75.1", "G76", "G90", "G92", "G94",
    "G96", "G97", "G98", "G99", "M03", "M05", "M30", "M98", "M99", "T0101", "T0202", "N10", "N20",
    "O0001", "/", "(c)", ";", "\n", "G77", "G91", "G95", "G92.1", "G24", "G53", "G10 L2",
    "G10 L50", "G11", "G154", "G54.1", "G17", "G18", "G80", "G52", "G27", "G112", "M41", "M77",
    "M19", "M23", "G81", "G83", "G84", "G85", "M24", "M97",
];
const WORDS: &[&str] = &[
    "X", "Z", "U", "W", "R", "I", "K", "P", "Q", "F", "S", "H", "D", "A", "B", "L", "V", "J", "E",
];
const NUMBERS: &[&str] = &[
    "0", "1", "-1", "0.1", "10.", "-5.5", "30", "1500", "99999999", "1e5", "..", "-", "", "0.0001",
    "60",
];

fn random_program(rng: &mut Lcg) -> String {
    let mut s = String::new();
    for _ in 0..(rng.next() % 40) {
        if rng.next().is_multiple_of(3) {
            s += rng.pick(CODES);
        } else {
            s += rng.pick(WORDS);
            s += rng.pick(NUMBERS);
        }
        s += if rng.next().is_multiple_of(4) {
            "\n"
        } else {
            " "
        };
    }
    s
}

#[test]
fn random_programs_never_panic() {
    let mut rng = Lcg(0x5eed);
    let blank = stock::Blank::bar(40.0, 40.0, 0.0, None).unwrap();
    let tools = stock::ToolTable::from_toml(&common::read(&common::asset(
        "tools/seed002-face3-drill10.toml",
    )))
    .unwrap();
    let opts = expander::Options {
        max_segments: 20_000,
        max_blocks: 100_000,
        ..Default::default()
    };
    let (mut parsed, mut simulated) = (0, 0);
    // every other program under the Haas control (one-block cycles, M97, Haas drilling)
    let machines = [
        expander::Machine::default(),
        expander::Machine::for_control(expander::Control::Haas),
    ];
    for k in 0..3000 {
        let text = random_program(&mut rng);
        let Ok(p) = gcode::parse(&text) else { continue };
        parsed += 1;
        // Every control reads the same text differently; none may panic on it.
        for control in expander::Control::ALL {
            expander::expand(&p, &expander::Machine::for_control(control), &opts);
        }
        let tp = expander::expand(&p, &machines[k % 2], &opts);
        if tp.segments.len() <= 2000 {
            let sim = stock::simulate(
                &blank,
                &tools,
                &tp.segments,
                &stock::SimOptions::default(),
                &mut |_| {},
            );
            assert!(
                sim.removed_area.is_finite() && sim.removed_area >= -1e-6,
                "{text:?}"
            );
            simulated += 1;
        }
    }
    eprintln!("{parsed} of 3000 random programs parsed, {simulated} simulated");
    assert!(
        parsed > 300 && simulated > 300,
        "the generator must reach the interpreter and the removal"
    );
}

/// The CLI on a few hostile files: always a clean exit code, never a panic message.
#[test]
fn hostile_files_through_the_cli() {
    let cases: &[&[u8]] = &[
        b"G0 X1e400 Z0\n",
        b"G1 X10 Z-5 F0.1 M3 S100\nG2 X10 Z-5 I0 K0\n",
        b"M3 S500\nG0 X40 Z2\nG75 R0.3\nG75 X30 Z-20 P1 Q1 F0.1\n",
        b"M3 S500\nG0 X40 Z2\nG73 U1 W1 R9999\nG73 P1 Q2 U0.5 W0.1 F0.2\nN1 G1 X30\nN2 Z-10\n",
        b"O1\nM98 P1\n",
        &[0xef, 0xbb, 0xbf, b'G', b'0', b' ', b'X', b'1', b'0', b'\n'],
        b"G0 X-100000000 Z100000000\n",
        // found/hostile-timeout shrunk: a G73 of many passes over small arcs (R9999 over 40
        // R0.5 arcs took > 60 s; here 200 passes over 10)
        b"G99 M3 S800 T0101\nG0 X64 Z2\nG73 U5 W0 R200\nG73 P10 Q20 U0 W0 F0.2\nN10 G0 X20 Z0\nG2 W-1 R0.5\nG3 W-1 R0.5\nG2 W-1 R0.5\nG3 W-1 R0.5\nG2 W-1 R0.5\nG3 W-1 R0.5\nG2 W-1 R0.5\nG3 W-1 R0.5\nG2 W-1 R0.5\nG3 W-1 R0.5\nN20 G1 X64\nM30\n",
    ];
    for (k, bytes) in cases.iter().enumerate() {
        let (dir, prog) = common::temp_program(&format!("h{k}.nc"), bytes);
        let out = common::latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock",
            "40x40",
            "--out",
            dir.path().to_str().unwrap(),
            "--quiet",
        ]);
        assert!((0..=2).contains(&out.code), "case {k}: exit {}", out.code);
        assert!(!out.stderr.contains("panicked"), "case {k}: {}", out.stderr);
    }
}

/// Haas forms on hostile input: a local subprogram calling itself, a microscopic peck, a
/// branch to itself (the loop guard ends it at once), microscopic layers and steps: an
/// alarm (exit 1); a library folder that is a file: exit 2. (No timed assertion: speed is
/// measured in benchmarks.)
#[test]
fn hostile_haas_files_through_the_cli() {
    let cases: &[&[u8]] = &[
        b"G21
M97 P1
M30
N1 M97 P1
M99
",
        b"G21 G99
G00 X0 Z5
G83 Z-3000. R2. Q0.0001 F0.1
M30
",
        b"G21
N5 G00 W0
M99 P5
",
        b"G21
G00 X52 Z2
G71 P1 Q2 D0.00001 F0.2
N1 G00 X10
N2 Z-10
M30
",
        b"G21
G00 X42 Z-5
G75 X30 Z-1000 I0.001 K0.001 F0.1
M30
",
    ];
    for (k, bytes) in cases.iter().enumerate() {
        let (dir, prog) = common::temp_program(&format!("haas{k}.nc"), bytes);
        let out = common::latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--control",
            "haas",
            "--stock",
            "40x40",
            "--out",
            dir.path().to_str().unwrap(),
            "--quiet",
        ]);
        assert_eq!(out.code, 1, "case {k}: {}", out.stderr);
        assert!(!out.stderr.contains("panicked"), "case {k}: {}", out.stderr);
    }
    let (_dir, prog) = common::temp_program(
        "lib.nc",
        b"M98 P1234
M30
",
    );
    let p = prog.to_str().unwrap();
    let out = common::latsim(&["check", p, "--control", "haas", "--lib", p]);
    assert_eq!(out.code, 2, "{}", out.stderr);
    assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
}

/// Found by the `decode` fuzz target's body on a damaged sample: the byte a decoding error
/// names is the first byte of the malformed sequence. A GBK lead byte 0xA0 before the ASCII
/// `2` is malformed at the 0xA0 (the decoder reads the `2` too, then gives it back as a
/// character), and a GB18030 four-byte start 0x81 0x30 0x81 before a space is malformed at
/// its first byte; the error named the byte after (the `2`) and two bytes after, as
/// `first_error` dropped the bytes read past the sequence (`Malformed`'s second count).
/// `latsim run --encoding gbk` meets it.
#[test]
fn decode_error_names_the_first_bad_byte() {
    let label = |l| gcode::encoding::encoding_for_label(l);
    let e = gcode::decode(b"G0 X1 (\xa02)", label("gbk")).unwrap_err();
    assert_eq!(e.offset, 7, "the 0xA0");
    let e = gcode::decode(b"(\x81\x30\x81 )", label("gb18030")).unwrap_err();
    assert_eq!(e.offset, 1, "the 0x81 that starts the four bytes");
}

/// Found by the `decode` fuzz target (a program decoded as Windows-1252, 0xFF read as `ÿ`):
/// an unreadable word before a non-ASCII character and `=` made the reader look for
/// another control's assignment, and slicing one byte past the `ÿ` panicked ("not a char
/// boundary", `crates/gcode/src/read/foreign.rs`). Now a reading error at the word.
#[test]
fn another_controls_assignment_after_a_non_ascii_character_is_an_error() {
    for text in ["G01 F0.Gÿ=1\n", "Gÿ=\n", "G1 Xÿ=2\n"] {
        let read = std::panic::catch_unwind(|| gcode::parse(text));
        assert!(read.is_ok_and(|r| r.is_err()), "{text:?}");
    }
}
