//! The contour cycles G70–G73: one snapshot of each expansion, and every alarm rule at its
//! line and column.

mod common;
use common::asset;
use expander::{expand, Motion, Options, Toolpath};

fn run(src: &str) -> Toolpath {
    expand(
        &gcode::parse(src).unwrap(),
        &Default::default(),
        &Options::default(),
    )
}

/// One readable line per segment, for snapshots.
fn listing(tp: &Toolpath) -> String {
    common::listing(tp, |s| format!("F{:?}", tp.feeds.get(s.feed)))
}

#[test]
fn g73_and_g70_of_o0006() {
    insta::assert_snapshot!(listing(&run(&asset("O0006.nc"))));
}

#[test]
fn g71_type_1() {
    insta::assert_snapshot!(listing(&run(&asset("G71-type1.nc"))));
}

#[test]
fn g71_type_2_pocket() {
    insta::assert_snapshot!(listing(&run(&asset("G71-type2.nc"))));
}

#[test]
fn g72_facing() {
    insta::assert_snapshot!(listing(&run(&asset("G72-facing.nc"))));
}

/// The G73 passes of seed 003: offsets (2Δi + Δu, Δk + Δw) first, (Δu, Δw) last, d = 3.
#[test]
fn g73_pass_offsets_follow_the_seed() {
    let tp = run(&asset("O0006.nc"));
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    // each pass starts with a rapid to A_k = A + offset (A = Z10 X200), then B_k rapid (ns G00)
    let a_k: Vec<(f64, f64)> = tp
        .segments
        .iter()
        .filter(|s| s.span.line == 4 && s.motion == Motion::Rapid)
        .map(|s| ((s.to.z * 1e6).round() / 1e6, (2e6 * s.to.r).round() / 1e6))
        .collect();
    assert_eq!(
        a_k,
        vec![(11.3, 202.5), (10.8, 201.5), (10.3, 200.5), (10.0, 200.0)]
    );
    // the shape is not run again as ordinary motion: G70 follows the last rough pass
    let g70: Vec<_> = tp.segments.iter().filter(|s| s.span.line >= 5).collect();
    assert!(g70
        .iter()
        .all(|s| s.motion == Motion::Feed || s.span.line == 5 || s.span.line == 11));
}

/// d = 1 runs as two passes (seed 003); the retained Δi/Δk/d serve a second G73.
#[test]
fn g73_d1_is_two_passes_and_words_are_retained() {
    let src = "G99 M3 S500\nG0 X100 Z5\nG73 U2 W1 R1\nG73 P10 Q20 U0 W0 F0.2\nN10 G1 X50 Z0\nN20 Z-20\nG73 P10 Q20 F0.2\nM30\n";
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let ends_of = |line: u32| -> Vec<(f64, f64)> {
        tp.segments
            .iter()
            .filter(|s| s.span.line == line)
            .map(|s| ((s.to.z * 1e6).round() / 1e6, (2e6 * s.to.r).round() / 1e6))
            .collect()
    };
    // pass 1 shifted by (Δk, 2Δi) = (1, 4), pass 2 by (0, 0); the N20 block of each pass
    assert_eq!(ends_of(6)[..2], [(-19.0, 54.0), (-20.0, 50.0)]);
    // the second G73 (line 7) reuses U2 W1 R1: same shape of passes, after the shape (N10..N20 before it)
    assert_eq!(ends_of(6).len(), 4);
}

/// Where each alarm points: (program, line, column, code).
#[test]
fn alarms_point_at_the_offending_word() {
    let head = "G99 M3 S500\nG0 X100 Z5\nG71 U2 R0.5\n";
    let cases: &[(&str, u32, u32, &str)] = &[
        // P or Q missing
        ("G71 P10 U0.2 F0.2\nN10 G1 X50\nN20 Z-20\n", 4, 1, "PS061"),
        // ns not found
        ("G71 P11 Q20 F0.2\nN10 G1 X50\nN20 Z-20\n", 4, 5, "PS063"),
        // nf not found
        ("G71 P10 Q21 F0.2\nN10 G1 X50\nN20 Z-20\n", 4, 9, "PS063"),
        // ns written twice
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nN20 Z-20\nN10 G0 X100\n",
            7,
            1,
            "LS-SHAPE-N-TWICE",
        ),
        // ns block not G00/G01
        (
            "G71 P10 Q20 F0.2\nN10 G2 X50 Z0 R5\nN20 Z-20\n",
            5,
            5,
            "PS065",
        ),
        ("G71 P10 Q20 F0.2\nN10 X50\nN20 Z-20\n", 5, 1, "PS065"),
        // forbidden codes inside the shape
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nG50 S2000\nN20 Z-20\n",
            6,
            1,
            "LS-SHAPE-CODE",
        ),
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nM98 P1234\nN20 Z-20\n",
            6,
            1,
            "LS-SHAPE-CODE",
        ),
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nZ-10 M99\nN20 Z-20\n",
            6,
            6,
            "LS-SHAPE-CODE",
        ),
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nG90 X40 Z-10\nN20 Z-20\n",
            6,
            1,
            "LS-SHAPE-CODE",
        ),
        // not monotonic: type I goes back down in X; Z goes backwards
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nZ-10\nX40 Z-15\nN20 Z-20\n",
            7,
            1,
            "PS064",
        ),
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50 Z0\nZ-10\nW5\nN20 Z-20\n",
            7,
            1,
            "PS064",
        ),
        // arc inside the shape with a too-small R
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50\nG3 X60 Z-30 R1\nN20 Z-40\n",
            6,
            13,
            "PS020",
        ),
        // nf before ns
        (
            "G71 P20 Q10 F0.2\nN10 G1 X50\nN20 Z-20\n",
            4,
            9,
            "LS-SHAPE-ORDER",
        ),
        // a word without meaning in the shape
        (
            "G71 P10 Q20 F0.2\nN10 G1 X50 R3\nN20 Z-20\n",
            5,
            12,
            "LS-WORD-UNUSED",
        ),
    ];
    for &(tail, line, column, code) in cases {
        let tp = run(&format!("{head}{tail}M30\n"));
        let a = tp
            .alarms
            .first()
            .unwrap_or_else(|| panic!("no alarm for:\n{tail}"));
        assert_eq!(
            (a.span.line, a.span.column, a.code),
            (line, column, code),
            "{tail}: {a}"
        );
    }
}

/// Depth, count and retract rules of the first blocks (PS062) and missing first blocks.
#[test]
fn depth_and_pass_count_alarms() {
    let shape = "N10 G1 X50\nN20 Z-20\nM30\n";
    for (first, line, column, code) in [
        ("G71 U0 R0.5\n", 3, 5, "PS062"),
        ("G71 U-1 R0.5\n", 3, 5, "PS062"),
        ("G71 U1 R-0.5\n", 3, 8, "PS062"),
        ("G72 W0 R0.5\n", 3, 5, "PS062"),
        ("G73 U1 W1 R0\n", 3, 11, "PS062"),
        ("G73 U1 W1 R2.5\n", 3, 11, "PS062"),
        ("G73 U1 W1 R10000\n", 3, 11, "PS062"),
    ] {
        let code_word = &first[..3];
        let src = format!("G99 M3 S500\nG0 X100 Z5\n{first}{code_word} P10 Q20 F0.2\n{shape}");
        let tp = run(&src);
        let a = tp.alarms.first().unwrap_or_else(|| panic!("{first}"));
        assert_eq!(
            (a.span.line, a.span.column, a.code),
            (line, column, code),
            "{first}: {a}"
        );
    }
    // G71 P Q without any G71 U R before it: no depth of cut
    let tp = run(&format!(
        "G99 M3 S500\nG0 X100 Z5\nG71 P10 Q20 F0.2\n{shape}"
    ));
    assert_eq!(tp.alarms[0].code, "PS062");
    assert_eq!(tp.alarms[0].span.line, 3);
}

/// G71 needs the ns block to move in X, G72 in Z; G70 without P/Q.
#[test]
fn ns_axis_and_g70_alarms() {
    let tp = run(
        "G99 M3 S500\nG0 X100 Z5\nG71 U1 R0.5\nG71 P10 Q20 F0.2\nN10 G1 Z0\nN20 X60 Z-20\nM30\n",
    );
    assert_eq!(
        (tp.alarms[0].code, tp.alarms[0].span.line),
        ("LS-SHAPE-NS", 5)
    );
    let tp =
        run("G99 M3 S500\nG0 X100 Z5\nG72 W1 R0.5\nG72 P10 Q20 F0.2\nN10 G1 X50\nN20 X0 Z0\nM30\n");
    assert_eq!(
        (tp.alarms[0].code, tp.alarms[0].span.line),
        ("LS-SHAPE-NS", 5)
    );
    let tp = run("G99 M3 S500\nG0 X100 Z5\nN10 G1 X50 F0.2\nN20 Z-20\nG70 P10\nM30\n");
    assert_eq!((tp.alarms[0].code, tp.alarms[0].span.line), ("PS061", 5));
}

/// G70 uses the shape's own F (the F in force before the first one), warns about S and
/// G41/G42 it cannot apply, and the program continues after nf when the shape follows.
#[test]
fn g70_feeds_and_warnings() {
    let src = "G98 M3 S500 F80\nG0 X60 Z2\nG70 P10 Q20\nN10 G1 X40\nG42 Z-20 F50 S900\nN20 X60\nG0 X100\nM30\n";
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    insta::assert_snapshot!(listing(&tp));
}

/// G73 with d = 9999 passes: every pass is expanded (7 moves each), the first shifted by
/// (Δk + Δw, 2Δi + Δu) and the last by (Δw, Δu). Release timing is in PERFORMANCE.md.
#[test]
fn g73_with_9999_passes() {
    let src = asset("O0006.nc").replace("r3 ;", "r9999 ;");
    let tp = run(&src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let rough: Vec<_> = tp
        .segments
        .iter()
        .filter(|s| s.span.line >= 4 && s.span.line <= 10)
        .collect();
    // 7 moves per pass, the rapid back to A, then G70's 6 shape moves (lines 5–10)
    assert_eq!(rough.len(), 9999 * 7 + 1 + 6);
    let x = |s: &expander::Segment| (2e6 * s.to.r).round() / 1e6;
    assert_eq!((rough[0].to.z, x(rough[0])), (11.3, 202.5));
    let last = 9998 * 7; // the rapid to A_9999
    assert_eq!(
        ((rough[last].to.z * 1e6).round() / 1e6, x(rough[last])),
        (10.3, 200.5)
    );
}

/// A G70 whose shape is kept after M30 (a common FANUC layout) goes on with the block after
/// the G70, as the control does: the retract and the thread after it run; the shape's own
/// blocks run only inside the G70. A shape right after its cycle block is skipped after it.
#[test]
fn g70_with_its_shape_after_m30_goes_on_after_the_g70() {
    let src = "G99 M03 S600 T0101\nG00 X30 Z2\nG70 P100 Q200\nG00 X50 Z50\nG00 X28 Z4\nG92 X23 Z-20 F2\nG00 X60\nM30\nN100 G00 X18\nG01 Z-10 F0.1\nN200 X30\n";
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!(tp.warnings.is_empty(), "{:?}", tp.warnings);
    let lines: Vec<u32> = tp.segments.iter().map(|s| s.span.line).collect();
    // rapid to A; the shape (9, 10, 11) and the rapid back to A (the G70 block, 3); 4 and 5;
    // the G92 cycle (4 moves, line 6); 7
    assert_eq!(lines, [2, 9, 10, 11, 3, 4, 5, 6, 6, 6, 6, 7], "{lines:?}");
    assert_eq!(
        tp.segments
            .iter()
            .filter(|s| s.motion == Motion::Thread)
            .count(),
        1
    );
    // the shape right after the cycle block: not run a second time as ordinary moves
    let inline = "G99 M03 S600 T0101\nG00 X30 Z2\nG70 P100 Q200\nN100 G00 X18\nG01 Z-10 F0.1\nN200 X30\nG00 X50 Z50\nM30\n";
    let lines: Vec<u32> = run(inline).segments.iter().map(|s| s.span.line).collect();
    assert_eq!(lines, [2, 4, 5, 6, 3, 7], "{lines:?}");
}
