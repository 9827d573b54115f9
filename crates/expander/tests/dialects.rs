//! The control-dependent reading of codes (issue 11, spec/dialects.md §2, §3, §6): each
//! test is a small program whose motion or alarm differs by control, with the numbers
//! computed by hand.

use expander::{expand, Control, Machine, Options, Toolpath};

fn run_on(control: Control, src: &str) -> Toolpath {
    expand(
        &gcode::parse(src).unwrap(),
        &Machine::for_control(control),
        &Options::default(),
    )
}

fn run_with(machine: &Machine, src: &str) -> Toolpath {
    expand(&gcode::parse(src).unwrap(), machine, &Options::default())
}

/// End points as (Z, X diameter), rounded to µm.
fn ends(tp: &Toolpath) -> Vec<(f64, f64)> {
    tp.segments
        .iter()
        .map(|s| ((s.to.z * 1e3).round() / 1e3, (2e3 * s.to.r).round() / 1e3))
        .collect()
}

fn codes(diags: &[expander::Diagnostic]) -> Vec<&str> {
    diags.iter().map(|d| d.code).collect()
}

fn the_alarm(tp: &Toolpath) -> &expander::Diagnostic {
    assert_eq!(
        tp.alarms.len(),
        1,
        "expected one alarm, got {:?}",
        tp.alarms
    );
    &tp.alarms[0]
}

#[test]
fn g77_in_system_b_is_the_turning_cycle_and_g91_makes_its_end_point_incremental() {
    let src = "G95 G90 M3 S500 G0 X52 Z2\nG77 X46 Z-30 F0.2\nG91 G77 X-10 Z-20\nM30\n";
    let tp = run_on(Control::FanucB, src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(
        ends(&tp)[1..],
        [
            (2.0, 46.0),
            (-30.0, 46.0),
            (-30.0, 52.0),
            (2.0, 52.0),
            // G91: end point 10 mm smaller in diameter, 20 mm toward -Z from (Z2, X52)
            (2.0, 42.0),
            (-18.0, 42.0),
            (-18.0, 52.0),
            (2.0, 52.0),
        ]
    );
    // The same G77 under system A names the control to try, at the G word.
    let tp = run_on(Control::FanucA, src);
    let a = the_alarm(&tp);
    assert_eq!((a.code, a.span.line, a.span.column), ("LS-DIALECT", 1, 1));
    assert!(
        a.message.starts_with("G95 is not a system A code"),
        "{}",
        a.message
    );
    assert!(a.help.contains("--control fanuc-b"), "{}", a.help);
}

#[test]
fn system_c_shifts_the_multiple_cycles_and_reads_g70_g71_as_units() {
    // G71 = metric, G20 = turning cycle, G73 = stock removal (system A G71).
    let tp = run_on(
        Control::FanucC,
        "G71 G95\nM3 S500\nG0 X52 Z2\nG20 X46 Z-10 F0.2\nG73 U2 R0.5\nG73 P10 Q20 U0 W0 F0.2\nN10 G0 X40\nN20 G1 Z-5\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(
        ends(&tp)[1..5],
        [(2.0, 46.0), (-10.0, 46.0), (-10.0, 52.0), (2.0, 52.0)]
    );
    assert!(
        ends(&tp).contains(&(-5.0, 40.0)),
        "the G73 (= G71) roughing reaches the shape"
    );
    // G79 does not exist in system C.
    let a = run_on(Control::FanucC, "G79 X20 Z-2 F0.1\n").alarms[0].clone();
    assert!(
        a.message.contains("system C") && a.help.contains("fanuc-b"),
        "{a:?}"
    );
}

#[test]
fn g92_is_a_clamp_or_coordinate_set_in_b_and_a_thread_cycle_in_a() {
    // B: G92 S is only the clamp; the tool does not move and S (the speed) is unchanged.
    let tp = run_on(Control::FanucB, "G92 S2500\nG0 X40 Z2\nM30\n");
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(ends(&tp), [(2.0, 40.0)]);
    // B: G92 X Z sets coordinates. Before the first move it states the program's own frame
    // (the stock's, spec/dialects.md §2.3): the tool is at X200 Z100 there, X40 Z2 is X40 Z2,
    // and a note says where the tool starts.
    let tp = run_on(Control::FanucB, "G92 X200 Z100\nG0 X40 Z2\nM30\n");
    assert_eq!(ends(&tp), [(2.0, 40.0)]);
    assert_eq!(tp.segments[0].from, expander::Pt::new(100.0, 100.0));
    assert!(
        tp.warnings.iter().any(|w| w.code == "W-G50-START"),
        "{:?}",
        tp.warnings
    );
    // After a move it shifts the work origin, with a warning naming the shift: at X40 Z2 the
    // position becomes X50 Z10, so the next X40 Z2 is X30 Z-6 of the first frame.
    let tp = run_on(Control::FanucB, "G0 X40 Z2\nG92 X50 Z10\nG0 X40 Z2\nM30\n");
    assert_eq!(ends(&tp), [(2.0, 40.0), (-6.0, 30.0)]);
    let w = tp
        .warnings
        .iter()
        .find(|w| w.code == "W-G50-SHIFT")
        .expect("a shift warning");
    assert!(w.message.contains("ΔX-10 ΔZ-8"), "{}", w.message);
    // B: G92 X Z F is the system-A thread cycle: an error at F.
    let a = the_alarm(&run_on(Control::FanucB, "G92 X20 Z-10 F1.5\n")).clone();
    assert_eq!((a.code, a.span.column), ("LS-DIALECT", 14));
    // A: G92 S2500 is a thread without an end point, never a new S.
    let a = the_alarm(&run_on(Control::FanucA, "M3 S500\nG92 S2500\n")).clone();
    assert_eq!((a.code, a.span.line, a.span.column), ("LS-DIALECT", 2, 1));
    assert!(a.help.contains("G50 S"), "{}", a.help);
}

#[test]
fn system_b_u_w_are_incremental_with_one_warning_or_an_error_when_the_profile_says_so() {
    let src = "G0 X40 Z2\nG0 U-4\nG0 W-2\nM30\n";
    let tp = run_on(Control::FanucB, src);
    assert_eq!(ends(&tp), [(2.0, 40.0), (2.0, 36.0), (0.0, 36.0)]);
    assert_eq!(codes(&tp.warnings), ["W-UW-SYSTEM-B"]);
    let mut m = Machine::for_control(Control::FanucB);
    m.uw_incremental = false;
    let a = the_alarm(&run_with(&m, src)).clone();
    assert_eq!((a.span.line, a.span.column), (2, 4));
    // System A: U/W are plain incremental words, no warning.
    assert!(run_on(Control::FanucA, src).warnings.is_empty());
}

#[test]
fn g94_g95_are_feed_modes_in_b_and_g98_g99_the_drilling_return() {
    let tp = run_on(
        Control::FanucB,
        "M3 S500\nG0 X52 Z2\nG94 G01 Z3 F300\nG95 G99 G01 Z4 F0.2\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(
        tp.feeds.get(tp.segments[1].feed),
        expander::Feed::PerMinute(300.0)
    );
    assert!(
        matches!(tp.feeds.get(tp.segments[2].feed), expander::Feed::PerRev { feed, .. } if feed == 0.2)
    );
}

#[test]
fn safe_start_codes_are_accepted_and_live_tooling_codes_are_clear_alarms() {
    let tp = run_on(
        Control::Haas,
        "G18 G20 G40 G80 G99\nG13.1 G61 G64 G09 G22 G23 G103 P5\nG187 P2 E0.05\nG54 G113\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    for (src, col, what) in [
        ("G0 X20\nG112\n", 1, "polar"),
        ("G0 X20\nG07.1 C10\n", 1, "cylindrical"),
        ("G31 X20 Z-5 F0.1\n", 1, "probing"),
        ("G0 X20\nG88 Z-5\n", 1, "radial"),
        ("G0 X20\nG14\n", 1, "sub-spindle"),
        ("G01 X20 C90 F0.1\n", 9, "C axis"),
        ("G0 X20 Y5\n", 8, "Y axis"),
    ] {
        let tp = run_on(Control::Haas, src);
        let a = the_alarm(&tp);
        assert_eq!(a.code, "LS-NOT-SIMULATED", "{src}");
        assert_eq!(a.span.column, col, "{src}");
        assert!(a.message.contains(what), "{src}: {}", a.message);
    }
    // C0 on a positioning block is the spindle orientation: ignored, warned.
    let tp = run_on(Control::FanucA, "G0 X20 Z2 C0\nM30\n");
    assert!(tp.alarms.is_empty() && codes(&tp.warnings) == ["W-C0"]);
}

#[test]
fn g17_is_accepted_until_an_arc_needs_the_plane() {
    let tp = run_on(
        Control::Haas,
        "G21 G17\nG0 X20 Z2\nG18\nG2 X30 Z-3 R5 F0.1\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let tp = run_on(Control::Haas, "G21 G17\nG0 X20 Z2\nG2 X30 Z-3 R5 F0.1\n");
    let a = the_alarm(&tp);
    assert_eq!((a.span.line, a.code), (3, "LS-NOT-SIMULATED"));
    assert!(
        a.message.contains("plane not simulated") && a.message.contains("line 1"),
        "{}",
        a.message
    );
}

#[test]
fn g53_g28_and_g27_go_to_machine_positions_without_cutting() {
    let mut m = Machine::for_control(Control::FanucA);
    // Machine zero 300 mm from the G54 zero in Z and at X400: G53 X0 Z0 goes there.
    m.machine_zero = expander::Pt::new(300.0, 200.0);
    let tp = run_with(
        &m,
        "G0 X40 Z2\nG53 X0\nG53 X-100 Z-50\nG28\nG0 X40 Z2\nG28 U0\nG27 X40 Z2\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(
        ends(&tp),
        [
            (2.0, 40.0),
            (2.0, 400.0),
            (250.0, 300.0),
            // bare G28: both axes to the reference point (Z150, X250)
            (150.0, 250.0),
            (2.0, 40.0),
            (2.0, 250.0),
            (2.0, 40.0),
        ]
    );
    assert!(tp
        .segments
        .iter()
        .all(|s| s.motion == expander::Motion::Rapid));
}

#[test]
fn dwell_forms_by_control() {
    let tp = run_on(Control::Haas, "G04 P1.5\nG04 P1500\nG04 X2.\nG04 U0.5\n");
    assert!(
        tp.alarms.is_empty() && (tp.dwell_s - 5.5).abs() < 1e-9,
        "{tp:?}"
    );
    assert!(
        !codes(&tp.warnings).contains(&"W-G04-P"),
        "Haas P with a point is seconds"
    );
    let tp = run_on(Control::FanucA, "G04 P3.\n");
    assert!((tp.dwell_s - 3.0).abs() < 1e-9);
    assert!(codes(&tp.warnings).contains(&"W-G04-P"));
}

#[test]
fn work_offsets_from_the_profile_and_from_g10() {
    let mut m =
        Machine::from_toml("control = \"haas\"\n[work_offsets]\np3 = [-10.0, 0.0]\n").unwrap();
    m.machine_zero = expander::Pt::new(100.0, 0.0);
    m.machine_zero_stated = true;
    let tp = run_with(
        &m,
        "G21\nG154 P3\nG0 X40 Z2\nG54\nG10 L2 P1 X0 Z-95.\nG0 X40 Z2\nG10 L20 P7 X0 Z-90.\nG154 P7\nG0 Z0\nG52 Z-1.\nG0 Z0\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    // p3: Z2 is G54 Z-8; G10 L2 P1 Z-95 from machine zero Z100: G54 moves to Z5, Z2 -> 7;
    // P7 at machine Z-90 -> Z10; G52 shifts by -1.
    assert_eq!(
        ends(&tp),
        [(-8.0, 40.0), (7.0, 40.0), (10.0, 40.0), (9.0, 40.0)]
    );
    assert!(codes(&tp.warnings).contains(&"W-G10-WORK") && codes(&tp.warnings).contains(&"W-G52"));
    let a = the_alarm(&run_with(&m, "G154 P9\n")).clone();
    assert_eq!((a.code, a.span.column), ("LS-WORK-OFFSET", 6));
    let a = the_alarm(&run_on(Control::FanucA, "G54.1 P1\n")).clone();
    assert_eq!(a.code, "LS-WORK-OFFSET");
}

#[test]
fn g10_sets_the_nose_g41_uses_and_skips_parameter_blocks() {
    let mut opts = Options::default();
    opts.tools.noses.insert(
        1,
        Ok(toolfacts::Nose {
            radius: 0.4,
            tip: 3,
        }),
    );
    let prog = |g10: &str| {
        format!("G10 L50\nN1234 R5\nN5678 P1 R2\nG11\n{g10}\nG0 X20 Z2 T0101\nM3 S500 G99\nG42 G1 Z0 F0.1\nG1 X30 Z-10\nG1 Z-20\nG40 G0 X40\nM30\n")
    };
    let m = Machine::for_control(Control::FanucA);
    let run = |g10: &str| expand(&gcode::parse(&prog(g10)).unwrap(), &m, &opts);
    let (r08, r04, table) = (
        run("G10 P10001 X0 Z0 R0.8 Q3"),
        run("G10 P10001 R0.4"),
        run("G18"),
    );
    assert!(r08.alarms.is_empty(), "{:?}", r08.alarms);
    assert!(codes(&r08.warnings).contains(&"W-G10-L50"));
    assert!(
        codes(&r08.warnings).contains(&"W-G10-OFFSET"),
        "X/Z lengths are not applied"
    );
    // The compensated corner between the cone and the cylinder moves with the nose radius:
    // G10 R0.8 changes the path, G10 R0.4 (the table's) does not.
    assert_ne!(ends(&r08), ends(&table));
    assert_eq!(ends(&r04), ends(&table));
    // Without a tool entry the data is not applied, with a warning.
    let tp = run_on(Control::FanucA, "G10 P5 R0.8 Q3\nM30\n");
    assert!(tp
        .warnings
        .iter()
        .any(|w| w.message.contains("not applied")));
}

#[test]
fn m_codes_by_control_with_one_warning_per_unknown_code() {
    let tp = run_on(
        Control::Haas,
        "G21 M41 M08 M31\nM77\nG0 X20\nM77\nM88 M89 M85\nM19\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let unknown: Vec<_> = tp
        .warnings
        .iter()
        .filter(|w| w.code == "W-M-UNKNOWN")
        .collect();
    assert_eq!(unknown.len(), 1, "{:?}", tp.warnings);
    assert_eq!(unknown[0].span.line, 2);
    let mut m = Machine::for_control(Control::Haas);
    m.accept_m.push(77);
    assert!(run_with(&m, "G21\nM77\nM30\n").warnings.is_empty());
    // M98/M30 never share a block; four M codes are too many.
    let a = the_alarm(&run_on(Control::FanucA, "M98 P1 M30\n")).clone();
    assert_eq!((a.code, a.span.column), ("PS010", 8));
    let a = the_alarm(&run_on(Control::FanucA, "M08 M41 M68 M07\n")).clone();
    assert_eq!(a.span.column, 13);
    // M19 stops the spindle: cutting after it is warned.
    let tp = run_on(
        Control::FanucA,
        "M3 S500\nG0 X20 Z2\nM19\nG1 Z-5 F0.1\nM30\n",
    );
    assert!(codes(&tp.warnings).contains(&"LS-SPINDLE-STOPPED"));
    // A Haas G84 starts the spindle itself (Haas's G84 page; field run 3: a course program
    // stops it with M05 before tapping): no warning, and cutting after it still is. A
    // FANUC G84 does not.
    let tap = "G21 G99 M5 S200\nG0 X0 Z5\nG84 X0 Z-10 R2 F1.25\nG80\n";
    let tp = run_on(Control::Haas, &format!("{tap}M30\n"));
    assert!(
        !codes(&tp.warnings).contains(&"LS-SPINDLE-STOPPED"),
        "{:?}",
        tp.warnings
    );
    let tp = run_on(
        Control::Haas,
        &format!("{tap}G0 X20 Z2\nG1 Z-5 F0.1\nM30\n"),
    );
    assert!(codes(&tp.warnings).contains(&"LS-SPINDLE-STOPPED"));
    let tp = run_on(Control::FanucA, &format!("{tap}M30\n").replace("R2", "R-3"));
    assert!(
        codes(&tp.warnings).contains(&"LS-SPINDLE-STOPPED"),
        "{:?}",
        tp.warnings
    );
    // Haas M11 opens the chuck: cutting after it is warned.
    let tp = run_on(
        Control::Haas,
        "G21 M3 S500\nM11\nG0 X20 Z2\nG1 Z-5 F0.1\nM30\n",
    );
    assert!(codes(&tp.warnings).contains(&"LS-CHUCK-OPEN"));
}

#[test]
fn haas_tapers_are_i_and_k_and_r_names_them() {
    // G90 I-2: radius start minus end = -2, so the cut starts at X42 and ends at X46.
    let tp = run_on(
        Control::Haas,
        "G21 M3 S500\nG0 X52 Z2\nG90 X46 Z-20 I-2 F0.2\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert_eq!(ends(&tp)[1..3], [(2.0, 42.0), (-20.0, 46.0)]);
    let tp = run_on(
        Control::Haas,
        "G21 M3 S500\nG0 X52 Z2\nG94 X20 Z-2 K-1 F0.2\nM30\n",
    );
    assert_eq!(ends(&tp)[1], (-3.0, 52.0));
    let a = the_alarm(&run_on(
        Control::Haas,
        "G21 M3 S500\nG0 X52 Z2\nG90 X46 Z-20 R-2 F0.2\n",
    ))
    .clone();
    assert_eq!((a.code, a.span.line, a.span.column), ("LS-DIALECT", 3, 14));
    assert!(a.message.contains("takes I"), "{}", a.message);
}

#[test]
fn haas_units_and_short_t() {
    let tp = run_on(Control::Haas, "T101\nG0 X20 Z2\nM30\n");
    assert_eq!(
        codes(&tp.warnings),
        ["W-HAAS-UNITS"],
        "T101 is tool 1 offset 1, no warning"
    );
    assert_eq!(tp.tools, [1]);
    let tp = run_on(Control::FanucA, "T1\nM30\n");
    assert_eq!(tp.tools, [1], "FANUC short T: tool 1 (offset 1), warned");
    assert_eq!(codes(&tp.warnings), ["LS-T-WORD"]);
    assert!(
        run_on(Control::Gsk980, "T1\nM30\n").tools.is_empty(),
        "GSK: offset 01 of tool 00"
    );
}

#[test]
fn cycle_alarms_speak_the_program_s_codes_and_g91_can_be_the_power_on_mode() {
    // R +8 against an X travel of -5 (radius): the G90 taper alarm, worded as G77.
    let tp = run_on(Control::FanucB, "G0 X40 Z2\nG77 X30 Z-10 R8 F0.2\n");
    let a = the_alarm(&tp);
    assert!(a.message.starts_with("G77 taper"), "{}", a.message);
    let m = Machine::from_toml("control = \"fanuc-b\"\npower_on_incremental = true").unwrap();
    let tp = run_with(&m, "G0 X-10 Z-5\nG90 G0 X40 Z2\nM30\n");
    assert_eq!(ends(&tp), [(145.0, 240.0), (2.0, 40.0)]);
}

/// GSK 980TD G92 `L` (spec/dialects.md §4.6): a block cuts every start at its depth in turn,
/// the n-th shifted n/L of the lead (after Q's shift); its modal repeats keep L, a new G92
/// block starts with one.
#[test]
fn gsk_g92_l_cuts_every_start_in_turn() {
    let src = "T0404 M3 S500\nG0 X18 Z6\nG92 X15.4 Z-20 F3 L2\nX14.8\nG92 X14.4 Z-20 F3\nM30\n";
    let tp = run_on(Control::Gsk980, src);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let threads: Vec<(f64, f64)> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .map(|s| (2.0 * s.to.r, s.thread_phase))
        .collect();
    assert_eq!(
        threads,
        [
            (15.4, 0.0),
            (15.4, 0.5),
            (14.8, 0.0),
            (14.8, 0.5),
            (14.4, 0.0)
        ]
    );
    // each start is a whole pass: in X, thread, out X, back Z
    assert_eq!(
        ends(&tp)[1..9],
        [
            (6.0, 15.4),
            (-20.0, 15.4),
            (-20.0, 18.0),
            (6.0, 18.0),
            (6.0, 15.4),
            (-20.0, 15.4),
            (-20.0, 18.0),
            (6.0, 18.0)
        ]
    );
    // with Q, the starts follow the shifted first one
    let tp = run_on(
        Control::Gsk980,
        "T0404\nG0 X18 Z6\nG92 X15.4 Z-20 F3 L3 Q60000\nM30\n",
    );
    let rounded = |x: f64| (x * 1e9).round() / 1e9;
    let phases: Vec<f64> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .map(|s| rounded(s.thread_phase))
        .collect();
    assert_eq!(
        phases,
        [rounded(1.0 / 6.0), rounded(0.5), rounded(5.0 / 6.0)]
    );
}

/// GSK G92 `J` `K`: the run-out (pull-out) in X (radius) and Z, unsigned; K omitted is J;
/// J0 is none; they stay for the modal repeats.
#[test]
fn gsk_g92_j_k_run_out() {
    let tp = run_on(
        Control::Gsk980,
        "T0404\nG0 X22 Z2\nG92 X19 Z-20 F2 J1 K2\nX18.6\nG92 X18.4 Z-20 J0.5\nG92 X18.2 Z-20 J0\nM30\n",
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let threads: Vec<((f64, f64), (f64, f64))> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .map(|s| {
            let r = |v: f64| (v * 1e6).round() / 1e6;
            (
                (r(s.from.z), r(2.0 * s.from.r)),
                (r(s.to.z), r(2.0 * s.to.r)),
            )
        })
        .collect();
    assert_eq!(
        threads,
        [
            // J1 K2: thread to 2 before the end, then out 1 (radius) at the end Z
            ((2.0, 19.0), (-18.0, 19.0)),
            ((-18.0, 19.0), (-20.0, 21.0)),
            // the repeat keeps them
            ((2.0, 18.6), (-18.0, 18.6)),
            ((-18.0, 18.6), (-20.0, 20.6)),
            // J without K: K = J
            ((2.0, 18.4), (-19.5, 18.4)),
            ((-19.5, 18.4), (-20.0, 19.4)),
            // J0: no run-out
            ((2.0, 18.2), (-20.0, 18.2)),
        ]
    );
}

/// The GSK words are errors elsewhere, and bad values are alarms at the word.
#[test]
fn gsk_g92_words_are_checked() {
    for (control, src, code) in [
        (
            Control::FanucA,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 L2\n",
            "LS-WORD-UNUSED",
        ),
        (
            Control::FanucA,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 J1\n",
            "LS-WORD-UNUSED",
        ),
        (
            Control::Gsk980,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 L2.\n",
            "LS-G92-STARTS",
        ),
        (
            Control::Gsk980,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 L0\n",
            "LS-G92-STARTS",
        ),
        (
            Control::Gsk980,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 L100\n",
            "LS-G92-STARTS",
        ),
        (
            Control::Gsk980,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 J-1\n",
            "LS-G92-RUNOUT",
        ),
        (
            Control::Gsk980,
            "G0 X18 Z6\nG92 X15.4 Z-20 F3 J1 K30\n",
            "LS-G92-RUNOUT",
        ),
    ] {
        let tp = run_on(control, src);
        assert_eq!(codes(&tp.alarms), [code], "{src}");
        assert!(tp.alarms[0].span.line == 2, "{src}: {:?}", tp.alarms[0]);
    }
}

/// Field run 10 (B6): a Haas program that states no units is read in the profile's
/// (W-HAAS-UNITS); an alarm it then raises names that reading, since an inch program read in
/// mm alarms for a reason its alarm alone does not show (a 0.125 step taken as 0.125 mm
/// under a 0.8 mm nose). A program that states G20 or G21, or another control, is told
/// nothing more.
#[test]
fn a_haas_alarm_names_the_units_assumed() {
    let alarm = |control, src: &str| {
        let tp = run_on(control, src);
        assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
        tp.alarms[0].help.clone()
    };
    let help = alarm(Control::Haas, "T101\nM3 S500\nG0 X2. Z.1\nG1 Z-1.\nM30\n");
    assert!(help.contains("read in mm (W-HAAS-UNITS)"), "{help}");
    assert!(help.contains("state G20"), "{help}");
    let help = alarm(
        Control::Haas,
        "G20\nT101\nM3 S500\nG0 X2. Z.1\nG1 Z-1.\nM30\n",
    );
    assert!(!help.contains("W-HAAS-UNITS"), "{help}");
    let help = alarm(
        Control::FanucA,
        "T0101\nM3 S500\nG0 X2. Z.1\nG1 Z-1.\nM30\n",
    );
    assert!(!help.contains("W-HAAS-UNITS"), "{help}");
}

/// Field run 10 (B5): a program that writes system B's `G91` and system A's `G50 S`. Under
/// fanuc-a the G91 alarm suggested fanuc-b, under fanuc-b the G50 alarm suggested fanuc-a:
/// each help now says the program mixes both and names where the other control stops. A
/// program in one system keeps the suggestion.
#[test]
fn a_program_mixing_systems_is_told_so_not_sent_back_and_forth() {
    let mixed = "G21 G99\nG50 S3000\nG28 G91 X0 Z0\nG90 G00 X50. Z2.\nM30\n";
    let tp = run_on(Control::FanucA, mixed);
    assert_eq!(tp.alarms.len(), 1, "{:?}", tp.alarms);
    let help = &tp.alarms[0].help;
    assert!(
        help.starts_with("the program mixes G-code systems: under --control fanuc-b line 2"),
        "{help}"
    );
    let tp = run_on(Control::FanucB, mixed);
    let help = &tp.alarms[0].help;
    assert!(
        help.starts_with("the program mixes G-code systems: under --control fanuc-a line 3"),
        "{help}"
    );
    let b_only = "G21 G95\nG28 G91 X0 Z0\nG90 G00 X50. Z2.\nM30\n";
    let tp = run_on(Control::FanucA, b_only);
    assert!(
        tp.alarms[0].help.starts_with("Run with --control fanuc-b?"),
        "{:?}",
        tp.alarms
    );
}
