//! The modal interpreter, block by block.

mod common;
use common::asset;
use expander::{expand, Feed, Machine, Motion, Options, Pt, RapidPath, Spindle, Toolpath};

fn run_with(src: &str, machine: &Machine, opts: &Options) -> Toolpath {
    expand(&gcode::parse(src).unwrap(), machine, opts)
}

fn run(src: &str) -> Toolpath {
    run_with(src, &Machine::default(), &Options::default())
}

fn ends(tp: &Toolpath) -> Vec<(f64, f64)> {
    tp.segments
        .iter()
        .map(|s| ((s.to.z * 1e6).round() / 1e6, (2e6 * s.to.r).round() / 1e6))
        .collect()
}

/// One readable line per segment, for snapshots.
fn listing(tp: &Toolpath) -> String {
    common::listing(tp, |s| format!("T{:02}", s.tool))
}

#[test]
fn seed_004_contour_expansion() {
    let src = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/programs/seed004-contour.nc"
    ))
    .unwrap();
    insta::assert_snapshot!(listing(&run(&src)));
}

#[test]
fn absolute_incremental_and_mixed() {
    let tp = run("M3 S500\nG0 X100 Z10\nG1 U-20 W-5 F100\nX50 W-10\nG0 U10\n");
    assert_eq!(
        ends(&tp),
        vec![(10.0, 100.0), (5.0, 80.0), (-5.0, 50.0), (-5.0, 60.0)]
    );
    assert!(tp.alarms.is_empty());
}

#[test]
fn modal_motion_and_feed_carry_over() {
    let tp = run("M3 S500\nG1 X20 Z0 F150\nZ-10\nG0 X40\nZ5\n");
    let kinds: Vec<_> = tp.segments.iter().map(|s| s.motion).collect();
    assert_eq!(
        kinds,
        vec![Motion::Feed, Motion::Feed, Motion::Rapid, Motion::Rapid]
    );
    assert_eq!(tp.feeds.get(tp.segments[1].feed), Feed::PerMinute(150.0));
}

#[test]
fn arc_with_ik_centre() {
    // G02 from (Z0, X20) to (Z-10, X40) centred at (Z-10, X20): I = 0, K = -10.
    let tp = run("M3 S500\nG0 X20 Z0\nG2 X40 Z-10 I0 K-10 F100\n");
    let a = tp.segments[1].arc.unwrap();
    assert_eq!((a.center, a.ccw), (Pt::new(-10.0, 10.0), false));
    let tp = run("M3 S500\nG0 X20 Z0\nG2 X40 Z-10 I1 K-10 F100\n");
    assert_eq!(tp.alarms[0].code, "PS020");
}

#[test]
fn feed_modes_and_spindle() {
    let tp = run("G99 G96 S150 M3\nG50 S2000\nG0 X40 Z2\nG1 Z-10 F0.2\nG97 S800\nG1 Z-20\nG98 G1 Z-30 F100\n");
    assert_eq!(
        tp.feeds.get(tp.segments[1].feed),
        Feed::PerRev {
            feed: 0.2,
            spindle: Spindle::Css {
                vc: 150.0,
                max_rpm: 2000.0
            }
        }
    );
    assert_eq!(
        tp.feeds.get(tp.segments[2].feed),
        Feed::PerRev {
            feed: 0.2,
            spindle: Spindle::Rpm(800.0)
        }
    );
    assert_eq!(tp.feeds.get(tp.segments[3].feed), Feed::PerMinute(100.0));
}

#[test]
fn power_on_feed_mode_comes_from_the_profile() {
    let m = Machine {
        feed_mode: expander::FeedMode::G99,
        ..Machine::default()
    };
    let tp = run_with("M3 S500\nG1 X20 Z0 F0.1\n", &m, &Options::default());
    assert!(matches!(
        tp.feeds.get(tp.segments[0].feed),
        Feed::PerRev { .. }
    ));
}

#[test]
fn inch_mode_converts_to_mm() {
    let tp = run("G20 M3 S500\nG0 X2. Z1.\n");
    assert_eq!(ends(&tp), vec![(25.4, 50.8)]);
}

#[test]
fn g28_returns_through_the_intermediate_point_on_the_named_axes() {
    let m = Machine::default();
    let tp = run("G0 X40 Z5\nG28 U0\nG0 X40 Z5\nG28 U0 W0\n");
    let home = m.home;
    assert_eq!(tp.segments[1].to, Pt::new(5.0, home.r), "only X goes home");
    assert_eq!(tp.segments.last().unwrap().to, home);
}

#[test]
fn g50_sets_the_current_position() {
    // At (Z5, X40) declare it Z0 X0: then G0 X10 Z-1 is 5 mm radius up, 6 mm left.
    let tp = run("G0 X40 Z5\nG50 X0 Z0\nG0 X10 Z-1\n");
    assert_eq!(tp.segments[1].to, Pt::new(4.0, 25.0));
}

#[test]
fn work_offsets_from_the_profile() {
    let mut m = Machine::default();
    m.work_offsets[1] = Pt::new(-50.0, 0.0);
    let tp = run_with("G55 G0 X40 Z0\nG54 G0 X40 Z0\n", &m, &Options::default());
    assert_eq!(ends(&tp), vec![(-50.0, 40.0), (0.0, 40.0)]);
}

#[test]
fn per_axis_rapids_make_a_dog_leg() {
    let m = Machine {
        rapid_path: RapidPath::PerAxis,
        rapid_x: 5000.0,
        rapid_z: 5000.0,
        home: Pt::new(100.0, 50.0),
        ..Machine::default()
    };
    let tp = run_with("G0 X40 Z0\n", &m, &Options::default());
    // from (Z100, r50) to (Z0, r20): both axes move 30 mm together, then Z alone.
    assert_eq!(tp.segments.len(), 2);
    assert_eq!(tp.segments[0].to, Pt::new(70.0, 20.0));
}

#[test]
fn dwell_counts_time() {
    let tp = run("G04 P1500\nG04 X2.5\nG4 U1\n");
    assert!((tp.dwell_s - 5.0).abs() < 1e-9);
    // P with a decimal point: seconds (Haas; elsewhere an Interpretation, warned).
    let tp = run("G04 P1.5\n");
    assert!(tp.alarms.is_empty() && (tp.dwell_s - 1.5).abs() < 1e-9);
    assert_eq!(tp.warnings[0].code, "W-G04-P");
}

#[test]
fn subprograms_repeat_and_return() {
    let src = "O0001;\nG0 X40 Z0;\nM98 P30002;\nM98 P2 L2;\nM30;\nO0002;\nG0 W-1;\nM99;\n";
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(tp.segments.len(), 1 + 3 + 2);
    assert_eq!(tp.segments.last().unwrap().to.z, -5.0);
    assert_eq!(
        tp.segments[1].span.line, 7,
        "subprogram segments carry the subprogram's line"
    );
}

#[test]
fn m99_p_returns_to_a_sequence_number() {
    let src = "O0001;\nM98 P2;\nG0 X10;\nN50 G0 X20 Z0;\nM30;\nO0002;\nG0 X30 Z0;\nM99 P50;\n";
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(
        ends(&tp),
        vec![(0.0, 30.0), (0.0, 20.0)],
        "the X10 block is skipped"
    );
}

#[test]
fn endless_loops_are_bounded() {
    let src = "O0001;\nN1 M98 P2;\nM30;\nO0002;\nG0 W1;\nG0 W-1;\nM99 P1;\n";
    let tp = run_with(
        src,
        &Machine::default(),
        &Options {
            max_blocks: 10_000,
            ..Options::default()
        },
    );
    assert_eq!(tp.alarms[0].code, "LS-LOOP");
    let tp = run_with(
        "O1;\nM98 P9999 L9999\nM30\nO9999\nG0 W1\nG0 W-1\nM99\n",
        &Machine::default(),
        &Options {
            max_segments: 1000,
            ..Options::default()
        },
    );
    assert_eq!(tp.alarms[0].code, "LS-TOO-LONG");
}

#[test]
fn block_delete_is_optional() {
    let src = "G0 X40 Z0\n/G0 X20\n";
    assert_eq!(run(src).segments.len(), 2);
    assert_eq!(
        run_with(
            src,
            &Machine::default(),
            &Options {
                block_delete: true,
                ..Options::default()
            }
        )
        .segments
        .len(),
        1
    );
}

#[test]
fn tools_are_tracked() {
    let tp = run("T0101\nG0 X40 Z0\nT0303\nG0 X50\nT0300\nT0313\nT0101\n");
    assert_eq!(tp.tools, vec![1, 3]);
    assert_eq!((tp.segments[0].tool, tp.segments[1].tool), (1, 3));
    // the offsets called, for the setup sheet: a cancel (T0300) is none
    assert_eq!(tp.tool_offsets, vec![(1, 1), (3, 3), (3, 13)]);
}

#[test]
fn cutting_with_the_spindle_stopped_is_a_warning() {
    let tp = run("G0 X40 Z2\nG1 Z-10 F100\nG1 Z-20\nM3 S500\nG1 Z-30\nM5\nG1 Z-40\n");
    let w: Vec<_> = tp
        .warnings
        .iter()
        .filter(|w| w.code == "LS-SPINDLE-STOPPED")
        .map(|w| w.span.line)
        .collect();
    assert_eq!(w, vec![2, 7]);
}

#[test]
fn conflicts_and_unused_words_are_alarms() {
    assert_eq!(run("G0 G1 X10\n").alarms[0].code, "PS010");
    assert_eq!(run("G1 X10 U5 F1\n").alarms[0].code, "LS-AXIS-TWICE");
    // a plain R on a G01: the corner round of the comma form, an error naming the key
    // (spec/dialects.md §6.5)
    let r = &run("G1 X10 R5 F1\n").alarms[0];
    assert_eq!(r.code, "LS-CORNER");
    assert!(r.help.contains("g01_cr = \"plain\""), "{}", r.help);
    assert_eq!(run("G1 X10 Q5 F1\n").alarms[0].code, "LS-WORD-UNUSED");
    assert_eq!(run("G2 X10 Z5 R5 I1 F1 M3\n").alarms[0].code, "LS-ARC");
    assert_eq!(run("G65 P1\n").alarms[0].code, "PS010");
}

#[test]
fn a_run_stops_at_the_alarm() {
    let tp = run("G0 X40 Z2\nG12\nG0 X50\n");
    assert_eq!(tp.segments.len(), 1);
    assert_eq!(tp.alarms.len(), 1);
    assert_eq!(tp.alarms[0].span.line, 2);
}

#[test]
fn g32_threads_carry_the_lead() {
    let tp = run("M3 S300\nG0 X20 Z5\nG32 Z-20 F1.5\n");
    assert_eq!(
        (tp.segments[1].motion, tp.segments[1].lead),
        (Motion::Thread, 1.5)
    );
}

#[test]
fn g75_1_geometry_block_must_be_followed_by_its_process_block() {
    let m = Machine {
        increment: expander::Increment::IsC,
        power_on_feed: 100.0,
        ..Machine::default()
    };
    let tp = run_with(
        "M3 S500\nG0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\nG0 X70\n",
        &m,
        &Options::default(),
    );
    assert_eq!(
        (tp.alarms[0].code, tp.alarms[0].span.line),
        ("LS-G75.1-BLOCKS", 4)
    );
    let tp = run_with(
        "M3 S500\nG0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\n",
        &m,
        &Options::default(),
    );
    assert_eq!(tp.alarms[0].code, "LS-G75.1-BLOCKS");
}

#[test]
fn g75_1_hands_over_its_groove_as_intended_shape() {
    let m = Machine {
        increment: expander::Increment::IsC,
        power_on_feed: 100.0,
        ..Machine::default()
    };
    let tp = run_with(
        "M3 S500\nG0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\nG75.1 R0.5 I4\nM30\n",
        &m,
        &Options::default(),
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(tp.intended.len(), 1);
    let g = &tp.intended[0];
    assert_eq!((g.kind, g.span.line), (expander::IntendedKind::Groove, 4));
    // trapezoid P1 (30,25) P2 (20,15) P3 (10,15) P4 (−7.32,25): area = (37.32 + 10) / 2 · 10
    let ring = &g.points;
    let area: f64 = (0..ring.len())
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            a.z * b.r - b.z * a.r
        })
        .sum::<f64>()
        .abs()
        / 2.0;
    let p4 = 10.0 - 10.0 / 30f64.to_radians().tan();
    assert!(
        (area - (30.0 - p4 + 10.0) / 2.0 * 10.0).abs() < 1e-6,
        "area {area}"
    );
}

#[test]
fn the_start_tool_applies_before_the_first_t_word() {
    let opts = Options {
        start_tool: Some(4),
        ..Options::default()
    };
    let tp = run_with("G0 X40 Z2\nT0101\nG0 X50\n", &Machine::default(), &opts);
    assert_eq!((tp.segments[0].tool, tp.segments[1].tool), (4, 1));
}

#[test]
fn g70_applies_s_t_and_feed_modes_written_in_the_shape() {
    let src = "G98 M3 S500 T0101\nG0 X62 Z2\nG70 P10 Q20\nN10 G0 X40 T0202\nG99 G96 S200 G1 Z-20 F0.2\nN20 X62\nM30\n";
    let tp = run(src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let cut = tp.segments.iter().find(|s| s.span.line == 5).unwrap();
    assert_eq!(cut.tool, 2);
    assert_eq!(
        tp.feeds.get(cut.feed),
        Feed::PerRev {
            feed: 0.2,
            spindle: Spindle::Css {
                vc: 200.0,
                max_rpm: Machine::default().max_rpm
            }
        }
    );
    assert!(tp.warnings.is_empty(), "{:?}", tp.warnings);
}

#[test]
fn g90_o0002_expansion() {
    insta::assert_snapshot!(listing(&run(&asset("O0002.nc"))));
}

#[test]
fn g94_expansion() {
    let src = "M3 S500 T0101\nG0 X55 Z5\nG94 X20 Z-2 F100\nZ-4\nG94 X20 Z-6 R-3\nM30\n";
    insta::assert_snapshot!(listing(&run(src)));
}

#[test]
fn g41_g42_switch_and_offset_00_cancel() {
    let mut tools = toolfacts::ToolFacts::default();
    tools.noses.insert(
        1,
        Ok(toolfacts::Nose {
            radius: 1.0,
            tip: 0,
        }),
    );
    let opts = Options {
        tools,
        ..Options::default()
    };
    // G42 along Z, then G41 on the way back: the switch ends the first section (its last
    // move cancels at its programmed end) and starts a new one on the other side.
    let src = "M3 S500 T0101\nG0 X40 Z2\nG42 G1 X20 Z0 F100\nG1 Z-10\nG1 X30\nG41 G1 Z-20\nG1 X40\nG40 G0 X60\n";
    let tp = run_with(src, &Machine::default(), &opts);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let on = |line: u32| {
        tp.segments
            .iter()
            .filter(move |s| s.span.line == line)
            .copied()
            .collect::<Vec<_>>()
    };
    // line 4 under G42 (tool above, +r) with the nose centre as reference (tip 0): r 11
    assert!(
        on(4)
            .iter()
            .all(|s| (s.to.r - 11.0).abs() < 1e-9 || (s.from.r - 11.0).abs() < 1e-9),
        "{:?}",
        on(4)
    );
    // line 5 ends the G42 section: its programmed end (Z-10, X30)
    assert_eq!(on(5).last().unwrap().to, Pt::new(-10.0, 15.0));
    // line 6 is the G41 start-up: it ends perpendicular to line 7's start (+r travel, the
    // left is -z), 1 mm beyond its programmed end in -Z
    assert_eq!(on(6).last().unwrap().to, Pt::new(-21.0, 15.0));
    // T0100 (offset 00) cancels: the next move is not compensated
    let src = "M3 S500 T0101\nG0 X40 Z2\nG42 G1 X20 Z0 F100\nG1 Z-10\nT0100\nG1 Z-20\nG1 X40\n";
    let tp = run_with(src, &Machine::default(), &opts);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let after = tp.segments.iter().find(|s| s.span.line == 6).unwrap();
    assert_eq!(
        (after.from, after.to),
        (Pt::new(-10.0, 10.0), Pt::new(-20.0, 10.0))
    );
}

#[test]
fn g92_expansion() {
    let src = "G97 S500 M03 T0404\nG00 X32 Z5\nG92 X29 Z-20 F2\nX28\nG92 X28 Z-20 R-1 F1.5\nM30\n";
    insta::assert_snapshot!(common::listing(&run(src), |s| format!("lead {}", s.lead)));
}

/// A long O program's blocks are read again on another thread, ahead of the run
/// (`interp::ahead`): the run is the one made from the blocks held, through calls, a jump
/// forward over a finishing shape, block delete, and (with macro B) a loop back and GOTO.
#[test]
fn blocks_read_ahead_run_as_the_blocks_held() {
    let moves = |n: usize| -> String {
        (0..n)
            .map(|k| format!("G1 X{}. Z-{:.1} F0.2\n", 100 + k % 2, (k % 50) as f64 * 0.1))
            .collect()
    };
    let plain = format!(
        "O0001\nG99 G21 M3 S500 T0101\nG0 X130. Z5.\n{a}/G0 X131.\nM98 P2000\n\
         G0 X130. Z2.\nG71 U1. R0.5\nG71 P30 Q40 U0.2 W0.1 F0.2\nN30 G0 X60.\nG1 Z-20.\n\
         X100. Z-40.\nN40 X130.\nG70 P30 Q40\n{b}M30\nO2000\n{c}M99\n",
        a = moves(9000),
        b = moves(9000),
        c = moves(9000),
    );
    let looped = format!(
        "O0001\nG99 G21 M3 S500 T0101\nG0 X130. Z5.\n#1=0\nWHILE[#1LT2]DO1\n{a}#1=#1+1\nEND1\n\
         GOTO20\n{b}N20 G0 X130.\n{c}M30\n",
        a = moves(9000),
        b = moves(100),
        c = moves(9000),
    );
    for (text, macros) in [
        (&plain, None),
        (&plain, Some(macro_b::Dialect::Fanuc)),
        (&looped, Some(macro_b::Dialect::Fanuc)),
    ] {
        for block_delete in [false, true] {
            let options = gcode::ReadOptions {
                macros,
                ..Default::default()
            };
            let opts = Options {
                block_delete,
                macros: macros.map(|_| macro_b::Options::fanuc()),
                ..Default::default()
            };
            let machine = Machine::for_control(expander::Control::FanucA);
            let read = expand(&gcode::parse_with(text, options).unwrap(), &machine, &opts);
            let held = expand(&gcode::parse_held(text, options).unwrap(), &machine, &opts);
            assert!(read.alarms.is_empty(), "{:?}", read.alarms);
            assert!(read.segments.len() > 9000 * 2);
            assert!(read == held, "{macros:?} {block_delete}");
        }
    }
}

/// Field run 5 (G): two pins cut from one bar, the first in G54, the second in G55, with
/// no G55 origin in the profile: the second was cut on top of the first, CLEAN. Switching
/// work systems after cutting needs both origins (spec/dialects.md §6: a missing work
/// offset is an error): the alarm LS-WORK-OFFSET at the G55. With the profile's G55 (or a
/// G10 L2 P2 in the program) the second pin is cut 50 mm back; a program that selects
/// G55 before it cuts anything is in one work system, the stock's frame.
#[test]
fn switching_to_a_work_system_of_unknown_origin_after_cutting_is_an_alarm() {
    let pin = "G00 X32. Z2.\nG01 X20. F0.2\nZ-15.\nX32.\nG00 X50. Z50.\n";
    let two = format!("G21 G99 M03 S500\nG54\n{pin}G55\n{pin}M30\n");
    let tp = run(&two);
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    assert_eq!(tp.alarms[0].code, "LS-WORK-OFFSET");
    assert_eq!(tp.alarms[0].span.line, 8);
    let m = Machine::from_toml("[work_offsets]\ng55 = [-50.0, 0.0]").unwrap();
    let tp = run_with(&two, &m, &Options::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let deepest = tp
        .segments
        .iter()
        .map(|s| s.to.z)
        .fold(f64::INFINITY, f64::min);
    assert!((deepest + 65.0).abs() < 1e-9, "{deepest}");
    // field run 6 (D): a G10 L2 value is a machine position; with no machine_zero in the
    // profile, G55 set by G10 alone was placed against a guessed machine zero (the second
    // part cut 110 mm in front of the bar, CLEAN): an alarm naming G10
    let set = format!("G21 G99 M03 S500\nG10 L2 P2 Z-50.\nG54\n{pin}G55\n{pin}M30\n");
    let tp = run(&set);
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    assert_eq!(tp.alarms[0].code, "LS-WORK-OFFSET");
    assert_eq!(tp.alarms[0].span.line, 9);
    assert!(
        tp.alarms[0].message.contains("G10"),
        "{}",
        tp.alarms[0].message
    );
    // G54 set by G10 too (with G54 in force) fixes machine zero: G54 stays the stock's
    // frame and G55 lies by the difference, 50 mm back, in either order (G54 moved to the
    // guessed machine zero's Z-300 before, and both parts were cut in the air)
    let deepest = |tp: &Toolpath| {
        tp.segments
            .iter()
            .map(|s| s.to.z)
            .fold(f64::INFINITY, f64::min)
    };
    for order in [
        "G10 L2 P1 Z-300.\nG10 L2 P2 Z-350.",
        "G10 L2 P2 Z-350.\nG10 L2 P1 Z-300.",
    ] {
        let both = format!("G21 G99 M03 S500\n{order}\nG54\n{pin}G55\n{pin}M30\n");
        let tp = run(&both);
        assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
        assert!((deepest(&tp) + 65.0).abs() < 1e-9, "{}", deepest(&tp));
        let first = tp
            .segments
            .iter()
            .find(|s| s.motion == expander::Motion::Feed);
        assert!((first.unwrap().to.z - 2.0).abs() < 1e-9, "{first:?}");
    }
    // a profile's machine zero places a lone G10 L2 P2: machine zero at Z300, G55 at Z-50
    let m = Machine::from_toml("machine_zero = [300.0, 200.0]").unwrap();
    let tp = run_with(&set.replace("Z-50.", "Z-350."), &m, &Options::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!((deepest(&tp) + 65.0).abs() < 1e-9, "{}", deepest(&tp));
    let only = format!("G21 G99 M03 S500\nG00 X50. Z50.\nG55\n{pin}M30\n");
    assert!(run(&only).alarms.is_empty(), "{:?}", run(&only).alarms);
    // a reset to G54 before M30, with no cut after it, is no switch (review)
    let reset = format!("G21 G99 M03 S500\nG55\n{pin}G54\nM30\n");
    assert!(run(&reset).alarms.is_empty(), "{:?}", run(&reset).alarms);
    // after cutting in an additional work system, an unknown G55 is one too
    let p1 = Machine::from_toml("[work_offsets]\np1 = [-50.0, 0.0]").unwrap();
    let extra = format!("G21 G99 M03 S500\nG54.1 P1\n{pin}G55\n{pin}M30\n");
    let tp = run_with(&extra, &p1, &Options::default());
    assert!(
        tp.alarms
            .iter()
            .any(|a| a.code == "LS-WORK-OFFSET" && a.span.line == 8),
        "{:?}",
        tp.alarms
    );
}

/// Field run 5 (B): an indexable drill offset in X (`G83 X2.`, Haas `G81 X0.0708`) with
/// the spindle turning cuts a round hole about the axis, 2 mm larger than the drill, as
/// G01 at X2 already did: it runs, warned W-OFF-AXIS-DRILL, its moves at r 1. Off the axis
/// with the spindle stopped, with the C axis engaged (Haas M154), or for a tap (G84), a
/// hole is in one place: the alarm LS-OFF-AXIS.
#[test]
fn an_offset_drill_with_the_spindle_turning_cuts_a_round_hole() {
    let fanuc = Machine::for_control(expander::Control::FanucA);
    let drill = |spindle: &str, code: &str| {
        format!("G21 G99\n{spindle}\nG00 X2. Z5.\n{code} X2. Z-20. R-3. F0.08\nG80\nG00 X50. Z50.\nM30\n")
    };
    let tp = run_with(&drill("M03 S1200", "G83"), &fanuc, &Options::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!(tp.warnings.iter().any(|w| w.code == "W-OFF-AXIS-DRILL"));
    let feeds: Vec<_> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Feed)
        .collect();
    assert!(
        !feeds.is_empty() && feeds.iter().all(|s| (s.to.r - 1.0).abs() < 1e-9),
        "{feeds:?}"
    );
    for (spindle, code) in [("M05", "G83"), ("M03 S1200", "G84")] {
        let tp = run_with(&drill(spindle, code), &fanuc, &Options::default());
        assert!(
            tp.alarms.iter().any(|a| a.code == "LS-OFF-AXIS"),
            "{spindle} {code}: {:?}",
            tp.alarms
        );
    }
    let haas = Machine::for_control(expander::Control::Haas);
    let indexed = drill("M03 S1200\nM154", "G81");
    let tp = run_with(&indexed, &haas, &Options::default());
    assert!(
        tp.alarms.iter().any(|a| a.code == "LS-OFF-AXIS"),
        "{:?}",
        tp.alarms
    );
    let free = drill("M03 S1200\nM154\nM155", "G81");
    assert!(run_with(&free, &haas, &Options::default())
        .alarms
        .is_empty());
}

/// Field run 5: under a GSK's power-on G98 (feed per minute) a program written with feeds
/// per revolution (`F0.15`) ran a 67-hour cycle time with no word: a feed per minute under
/// 1 mm/min is warned once, W-FEED-PER-MINUTE; G99, or F150 under G98, is not.
#[test]
fn a_feed_per_minute_slower_than_any_cut_is_warned() {
    let warned = |src: &str| {
        run(src)
            .warnings
            .iter()
            .filter(|w| w.code == "W-FEED-PER-MINUTE")
            .count()
    };
    assert_eq!(
        warned("M03 S800\nG00 X42 Z2\nG01 Z-20 F0.15\nX50 Z-25\nM30\n"),
        1
    );
    assert_eq!(warned("G99 M03 S800\nG00 X42 Z2\nG01 Z-20 F0.15\nM30\n"), 0);
    assert_eq!(warned("M03 S800\nG00 X42 Z2\nG01 Z-20 F150\nM30\n"), 0);
}
