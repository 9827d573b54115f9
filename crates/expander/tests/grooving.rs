//! The grooving cycles G74, G75 and G75.1: expanded moves (snapshots a reviewer can read),
//! exact landing points, and one test per alarm rule.

mod common;
use common::asset;
use expander::{expand, Increment, Machine, Options, Toolpath};

fn run_with(src: &str, machine: &Machine) -> Toolpath {
    expand(&gcode::parse(src).unwrap(), machine, &Options::default())
}

fn run(src: &str) -> Toolpath {
    run_with(src, &Machine::default())
}

fn is_c() -> Machine {
    Machine {
        increment: Increment::IsC,
        ..Machine::default()
    }
}

/// One readable line per segment, for snapshots.
fn listing(tp: &Toolpath) -> String {
    common::listing(tp, |s| format!("T{:02} {:?}", s.tool, s.hint))
}

/// The alarm of a program that must stop: (line, code).
fn alarm_of(tp: &Toolpath) -> (u32, &'static str) {
    let a = tp.alarms.first().expect("an alarm");
    (a.span.line, a.code)
}

// ---------------------------------------------------------------- G75

#[test]
fn g75_o0209_expansion() {
    insta::assert_snapshot!(listing(&run(&asset("O0209.nc"))));
}

#[test]
fn g74_o0210_expansion() {
    insta::assert_snapshot!(listing(&run(&asset("O0210.nc"))));
}

/// The last plunge lands exactly on Z, the last peck exactly on X, the pecks are
/// Δi, back e, Δi + e: the O0209 block from its start X42 Z−28.
#[test]
fn g75_pecks_and_last_plunge_land_on_the_end_point() {
    let tp = run("G0 X42 Z-28\nG75 R0.3\nG75 X32 Z-31 P1500 Q2000 F0.1\n");
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let ends: Vec<(f64, f64)> = tp.segments[1..]
        .iter()
        .map(|s| ((s.to.z * 1e9).round() / 1e9, (2e9 * s.to.r).round() / 1e9))
        .collect();
    // first plunge: 1.5 deep pecks with 0.3 back, the last one stopping at X32
    assert_eq!(
        &ends[..8],
        &[
            (-28.0, 39.0),
            (-28.0, 39.6),
            (-28.0, 36.0),
            (-28.0, 36.6),
            (-28.0, 33.0),
            (-28.0, 33.6),
            (-28.0, 32.0),
            (-28.0, 42.0)
        ]
    );
    let plunges: Vec<f64> = ends.iter().filter(|e| e.1 == 32.0).map(|e| e.0).collect();
    assert_eq!(plunges, [-28.0, -30.0, -31.0]);
    assert_eq!(*ends.last().unwrap(), (-28.0, 42.0));
    assert!(tp.segments[1..]
        .iter()
        .all(|s| s.hint == expander::ToolHint::Grooving));
}

/// IS-C: P and Q are 0.0001 mm.
#[test]
fn g75_is_c_increments() {
    let tp = run_with("G0 X42 Z-28\nG75 X32 P15000 F0.1\n", &is_c());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let xs: Vec<f64> = tp.segments[1..].iter().map(|s| 2.0 * s.to.r).collect();
    assert_eq!(xs, [39.0, 36.0, 33.0, 32.0, 42.0]);
}

/// Z omitted (or W0): one plunge, Q not needed; U incremental.
#[test]
fn g75_single_plunge_forms() {
    for src in [
        "G0 X42 Z-28\nG75 R0.5\nG75 X32 P2000 F0.1\n",
        "G0 X42 Z-28\nG75 R0.5\nG75 U-10 W0 P2000 F0.1\n",
    ] {
        let tp = run(src);
        assert!(tp.alarms.is_empty(), "{src}: {:?}", tp.alarms);
        assert!(tp.segments[1..].iter().all(|s| s.to.z == -28.0), "{src}");
        let xs: Vec<f64> = tp.segments[1..].iter().map(|s| 2.0 * s.to.r).collect();
        assert_eq!(xs, [38.0, 39.0, 34.0, 35.0, 32.0, 42.0], "{src}");
    }
}

/// Δd: at the bottom of every plunge after the first, a feed back toward the cut side.
#[test]
fn g75_escape_at_the_bottom() {
    let tp = run("G0 X42 Z-28\nG75 X32 Z-31 P5000 Q2000 R0.5 F0.1\n");
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let ends: Vec<(f64, f64)> = tp.segments[1..]
        .iter()
        .map(|s| ((s.to.z * 1e9).round() / 1e9, (2e9 * s.to.r).round() / 1e9))
        .collect();
    assert_eq!(
        ends,
        [
            (-28.0, 32.0),
            (-28.0, 42.0),
            (-30.0, 42.0),
            (-30.0, 32.0),
            (-29.5, 32.0),
            (-29.5, 42.0),
            (-31.0, 42.0),
            (-31.0, 32.0),
            (-30.5, 32.0),
            (-30.5, 42.0),
            (-28.0, 42.0)
        ]
    );
}

/// G74 peck drilling on the axis (O0210's `G74 Z-28.0 Q5 000`): the last peck at Z−28.
#[test]
fn g74_peck_drilling_lands_on_z() {
    let tp = run("G0 X0 Z3\nG74 R0.3\nG74 Z-28.0 Q5 000 F0.1\n");
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let zs: Vec<f64> = tp.segments[1..]
        .iter()
        .map(|s| (s.to.z * 1e9).round() / 1e9)
        .collect();
    assert_eq!(
        zs,
        [
            -2.0, -1.7, -7.0, -6.7, -12.0, -11.7, -17.0, -16.7, -22.0, -21.7, -27.0, -26.7, -28.0,
            3.0
        ]
    );
    assert!(tp.segments.iter().all(|s| s.to.r == 0.0));
}

// ---------------------------------------------------------------- alarms of seed 002 §6

/// Every rule of seed 002 §6 (and the cycle's own format rules) stops at the cycle block.
#[test]
fn g74_g75_alarm_rules() {
    for (src, line, code, words) in [
        // ① X given, Δi missing / 0
        (
            "G0 X42 Z-28\nG75 X32 Z-31 Q2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "P is missing",
        ),
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P0 Q2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "P is missing",
        ),
        // ① Z travels, Δk missing / 0
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P1500 F0.1\n",
            2,
            "LS-G75-STEP",
            "shift Q is missing",
        ),
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P1500 Q0 F0.1\n",
            2,
            "LS-G75-STEP",
            "shift Q is missing",
        ),
        // ② Δk larger than |W| or negative
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P1500 Q4000 F0.1\n",
            2,
            "LS-G75-STEP",
            "larger than the Z travel",
        ),
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P1500 Q-2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "Q is negative",
        ),
        // ③ Δi larger than |U/2| or negative
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P6000 Q2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "larger than the X travel",
        ),
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P-1500 Q2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "P is negative",
        ),
        // ④ e larger than the peck
        (
            "G0 X42 Z-28\nG75 R2\nG75 X32 Z-31 P1500 Q2000 F0.1\n",
            3,
            "LS-G75-E",
            "larger than the peck",
        ),
        (
            "G0 X0 Z3\nG74 R6\nG74 Z-28 Q5000 F0.1\n",
            3,
            "LS-G75-E",
            "larger than the peck Q",
        ),
        // G74 with the roles swapped: Δk missing for the Z pecks, Δi for the X shift
        (
            "G0 X0 Z3\nG74 Z-28 F0.1\n",
            2,
            "LS-G75-STEP",
            "Q is missing",
        ),
        (
            "G0 X20 Z1\nG74 X24 Z-5 Q2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "shift P is missing",
        ),
        (
            "G0 X20 Z1\nG74 X24 Z-5 P3000 Q2000 F0.1\n",
            2,
            "LS-G75-STEP",
            "larger than the X travel",
        ),
        // format: nothing to cut, negative e, negative Δd, a bare G75, a decimal point in P
        (
            "G0 X42 Z-28\nG75 Z-31 P1500 Q2000 F0.1\n",
            2,
            "LS-G75-NO-DEPTH",
            "no X travel",
        ),
        ("G0 X42 Z-28\nG75 R-0.3\n", 2, "LS-G75-E", "negative"),
        (
            "G0 X42 Z-28\nG75 X32 Z-31 P1500 Q2000 R-1 F0.1\n",
            2,
            "LS-G75-ESCAPE",
            "negative",
        ),
        ("G0 X42 Z-28\nG75\n", 2, "LS-G75-FORMAT", "without R(e)"),
        (
            "G0 X42 Z-28\nG75 X32 P1.5 F0.1\n",
            2,
            "LS-INCREMENT",
            "no decimal point",
        ),
        // a word the format does not define
        (
            "G0 X42 Z-28\nG75 X32 P1500 J3 F0.1\n",
            2,
            "LS-WORD-UNUSED",
            "address J",
        ),
        // K is the Haas one-block word: an alarm naming the control
        (
            "G0 X42 Z-28\nG75 X32 P1500 K3 F0.1\n",
            2,
            "LS-ONE-BLOCK-FORM",
            "--control haas",
        ),
    ] {
        let tp = run(src);
        assert_eq!(alarm_of(&tp), (line, code), "{src}: {:?}", tp.alarms);
        let a = &tp.alarms[0];
        assert!(a.message.contains(words), "{src}: {}", a.message);
        assert!(!a.help.is_empty(), "{src}");
    }
}

/// P1 Q1 over a 100 mm groove would be billions of moves: a clear alarm, at once.
#[test]
fn g75_huge_step_count_is_an_alarm_not_a_hang() {
    let tp = run("G0 X202 Z0\nG75 R0\nG75 X2 Z-100 P1 Q1 F0.1\n");
    assert_eq!(alarm_of(&tp), (3, "LS-CYCLE-TOO-LONG"));
    assert!(tp.alarms[0].message.contains("moves"));
    let tp = run("G0 X0 Z3\nG74 X200 Z-100 P1 Q1 F0.1\n");
    assert_eq!(alarm_of(&tp), (2, "LS-CYCLE-TOO-LONG"));
}

// ---------------------------------------------------------------- G75.1

/// O0008 (seed 000, IS-C) as printed: the geometry block waits, the process block runs.
#[test]
fn g75_1_o0008_expansion() {
    insta::assert_snapshot!(listing(&run_with(&asset("O0008.nc"), &is_c())));
}

/// O0008 as printed on the IS-C machine profile that gives the feed the program lacks
/// (assets/machines/gsk980tdi-isc.toml: G98, power-on feed 100 mm/min): the whole cycle
/// runs on the groove P1 Z30 X50, P2 Z20 X30, P3 Z10 X30, P4 Z-7.32 X50.
#[test]
fn g75_1_o0008_motion_on_the_isc_profile() {
    let text = std::fs::read_to_string(format!(
        "{}/../../assets/machines/gsk980tdi-isc.toml",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let machine = Machine::from_toml(&text).unwrap();
    let tp = run_with(&asset("O0008.nc"), &machine);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    insta::assert_snapshot!(listing(&tp));
}

/// O0008 with a feed and the 4 mm blade given as I4: plunges from Z20 (where the blade fits
/// at the floor inside the 45° flank) by 5 mm steps, the last with the far corner on
/// the 30° flank at the floor (reference at Z10 + 4 = Z14), then the roughing contour.
#[test]
fn g75_1_o0008_i4_expansion() {
    insta::assert_snapshot!(listing(&run_with(&asset("O0008-I4.nc"), &is_c())));
}

/// Every G75.1 alarm the spec lists, at the process block (or the geometry block's own
/// word errors there), with a message and a help line.
#[test]
fn g75_1_alarm_rules() {
    let geo = "G99 G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\n";
    for (src, line, code, words) in [
        // H, D, P or Q missing or 0 (a block without H is a process block: H missing makes
        // the first block a process block without its geometry)
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 D-10\n",
            2,
            "LS-G75.1-BLOCKS",
            "without its geometry",
        ),
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H0 D-10\n",
            2,
            "LS-G75.1-WORD",
            "H is missing or 0",
        ),
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20\n",
            2,
            "LS-G75.1-WORD",
            "D is missing or 0",
        ),
        (
            "G0 X60 Z30\nG75.1 X50 Z30 Q50000 H-20 D-10\n",
            2,
            "LS-G75.1-WORD",
            "P is missing or 0",
        ),
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q0 H-20 D-10\n",
            2,
            "LS-G75.1-WORD",
            "Q is missing or 0",
        ),
        // angles out of range
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A0\n",
            2,
            "LS-G75.1-ANGLE",
            "A0",
        ),
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 B95\n",
            2,
            "LS-G75.1-ANGLE",
            "B95",
        ),
        (
            "G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 L90\n",
            2,
            "LS-G75.1-ANGLE",
            "L90",
        ),
        // e ≥ Δi/2
        (
            &format!("{geo}G75.1 R1.5 F0.1\n"),
            3,
            "LS-G75.1-E",
            "not smaller than the peck",
        ),
        // Δv ≤ 0
        (
            &format!("{geo}G75.1 R0.5 V0 F0.1\n"),
            3,
            "LS-G75.1-WORD",
            "layer depth",
        ),
        // a chamfer larger than an edge it cuts
        (
            &format!("{geo}G75.1 R0.5 D8 E8 F0.1\n"),
            3,
            "LS-G75.1-SHAPE",
            "floor",
        ),
        // the far flank never meets the mouth (flanks and mouth do not close)
        (
            "G99 G0 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 B30 L40\nG75.1 R0.5 F0.1\n",
            3,
            "LS-G75.1-SHAPE",
            "never meets",
        ),
        // tool wider than the floor
        (
            &format!("{geo}G75.1 R0.5 I12 F0.1\n"),
            3,
            "LS-G75.1-WIDTH",
            "wider than the roughing floor",
        ),
        (
            &format!("{geo}G75.1 R0.5 I6 W2.5 F0.1\n"),
            3,
            "LS-G75.1-WIDTH",
            "wider than the roughing floor",
        ),
        // the second block missing: another geometry block, or a block in between
        (
            &format!("{geo}{geo}"),
            3,
            "LS-G75.1-BLOCKS",
            "not followed by its process block",
        ),
        (
            &format!("{geo}G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\n"),
            3,
            "LS-G75.1-BLOCKS",
            "has no process block",
        ),
        (
            &format!("{geo}G0 X60\nG75.1 R0.5 F0.1\n"),
            3,
            "LS-G75.1-BLOCKS",
            "not followed",
        ),
        // process words out of range
        (
            &format!("{geo}G75.1 R0.5 J3 F0.1\n"),
            3,
            "LS-G75.1-WORD",
            "J3",
        ),
        (
            &format!("{geo}G75.1 R0.5 A1 P0120 F0.1\n"),
            3,
            "LS-G75.1-WORD",
            "0 or 1",
        ),
        (
            &format!("{geo}G75.1 R0.5 A1 P2000 F0.1\n"),
            3,
            "LS-G75.1-WORD",
            "corner digits",
        ),
        (
            &format!("{geo}G75.1 R0.5 U-1 F0.1\n"),
            3,
            "LS-G75.1-WORD",
            "negative",
        ),
        (
            &format!("{geo}G75.1 R0.5 K1 F0.1\n"),
            3,
            "LS-WORD-UNUSED",
            "address K",
        ),
    ] {
        let tp = run_with(src, &is_c());
        assert_eq!(alarm_of(&tp), (line, code), "{src}: {:?}", tp.alarms);
        let a = &tp.alarms[0];
        assert!(a.message.contains(words), "{src}: {}", a.message);
    }
}

/// P1 Q1 over a 100 mm deep groove: a clear alarm, at once.
#[test]
fn g75_1_huge_step_count_is_an_alarm() {
    let tp = run("G99 G0 X260 Z0\nG75.1 X250 Z0 P1 Q1 H-200 D-100\nG75.1 F0.1\n");
    assert_eq!(alarm_of(&tp), (3, "LS-CYCLE-TOO-LONG"));
}

/// The current position is the default start point; H and D signs choose the directions
/// (here an ID groove: H positive, toward +X; D positive, toward +Z).
#[test]
fn g75_1_default_start_and_signs() {
    let tp = run("G99 G0 X20 Z-10\nG75.1 P2000 Q2000 H6 D8\nG75.1 I3 J1 F0.1\n");
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let cyc: Vec<_> = tp.segments.iter().filter(|s| s.span.line == 3).collect();
    let zmax = cyc.iter().map(|s| s.to.z).fold(f64::MIN, f64::max);
    let rmax = cyc.iter().map(|s| s.to.r).fold(f64::MIN, f64::max);
    let zmin = cyc.iter().map(|s| s.to.z).fold(f64::MAX, f64::min);
    // floor X26 (r 13); the reference corner reaches Z−10 + 8 − 3 = Z−5 on the far side
    assert!((rmax - 13.0).abs() < 1e-9, "{rmax}");
    assert!(
        (zmax - -5.0).abs() < 1e-9 && (zmin - -10.0).abs() < 1e-9,
        "{zmin} {zmax}"
    );
    assert_eq!(cyc.last().unwrap().to, expander::Pt::new(-10.0, 10.0));
    assert!(cyc.iter().all(|s| s.hint
        == expander::ToolHint::Blade {
            width: 3.0,
            toward_plus_z: true,
            shank_plus_x: false
        }));
}
