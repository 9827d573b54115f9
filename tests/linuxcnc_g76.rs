//! `LinuxCNC`'s G76 threading cycle under `--control linuxcnc` (issue 36,
//! docs/linuxcnc-g76.md): the pass depths J·n^(1/R) to K and the spring passes, the root and
//! the flank angle of the finished thread, G7/G8, the tapers, the same thread written for
//! FANUC's two-block G76, and `LinuxCNC`'s refusals as alarms at their word.

mod common;
use common::*;
use expander::{Control, Machine, Motion, Segment, Toolpath};

fn shop() -> stock::ToolTable {
    stock::ToolTable::from_toml(&read(&asset("corpus/tools/shop.toml"))).unwrap()
}

/// `text` expanded in-process under `control` with the shop's tools, no alarm.
fn toolpath(text: &str, control: Control) -> Toolpath {
    let tp = expand(text, &Machine::for_control(control), &shop());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    tp
}

/// The thread moves of a toolpath.
fn threads(tp: &Toolpath) -> Vec<&Segment> {
    tp.segments
        .iter()
        .filter(|s| s.motion == Motion::Thread)
        .collect()
}

/// The report's one thread after `latsim run` of the asset `name` with `args`.
fn asset_thread(name: &str, args: &[&str]) -> serde_json::Value {
    let prog = asset(&format!("corpus/linuxcnc/{name}"));
    let mut all = vec!["--control", "linuxcnc", "--quiet"];
    all.extend_from_slice(args);
    let (out, report) = run_json(&prog, &all);
    let r = report.unwrap_or_else(|| panic!("{}", out.stderr));
    assert_eq!(r["verdict"], "clean", "{r}");
    let threads = r["threads"].as_array().unwrap();
    assert_eq!(threads.len(), 1, "{threads:?}");
    threads[0].clone()
}

/// Pass increments by hand: j·(√n − √(n−1)) for n = 1…`rough`, then k − j·√rough, then
/// zeros for the spring passes.
fn increments(j: f64, k: f64, rough: u32, spring: usize) -> Vec<f64> {
    let s = |n: u32| f64::from(n).sqrt();
    let mut v: Vec<f64> = (1..=rough).map(|n| j * (s(n) - s(n - 1))).collect();
    v.push(k - j * s(rough));
    v.extend(std::iter::repeat_n(0.0, spring));
    v
}

fn assert_close(got: &serde_json::Value, want: &[f64], tol: f64) {
    let got: Vec<f64> = got
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= tol, "{got:?} vs {want:?}");
    }
}

#[test]
fn outside_thread_passes_are_j_root_n_to_k_and_the_root_is_the_peak_less_k() {
    // G7: I-1 J0.5 K1.8 are diameters: 0.5, 0.25, 0.9 radius. 0.25·√n < 0.9 for n ≤ 12
    let t = asset_thread(
        "g76-od-m30-g7.nc",
        &[
            "--stock",
            "30x60",
            "--tools",
            asset("corpus/tools/shop.toml").to_str().unwrap(),
        ],
    );
    assert_eq!(t["passes"], 14);
    assert_close(&t["pass_depths_mm"], &increments(0.25, 0.9, 12, 1), 1e-6);
    assert_eq!(t["side"], "od");
    assert_eq!(t["lead_mm"], 1.5);
    // the root Φ30 − 2·0.9, the flanks of the 60° tool: 30° off radial each
    assert!(
        (t["achieved_x"].as_f64().unwrap() - 28.2).abs() < 1e-6,
        "{t}"
    );
    assert!(
        (t["included_angle_deg"].as_f64().unwrap() - 60.0).abs() < 0.01,
        "{t}"
    );
    // the last pass starts K·tan Q toward the end: Z3 − 0.9·tan 29.5°
    let z0 = 3.0 - 0.9 * 29.5f64.to_radians().tan();
    assert!((t["z_start"].as_f64().unwrap() - z0).abs() < 1e-5, "{t}");
}

#[test]
fn inside_thread_goes_away_from_the_axis_to_the_drive_line_plus_i_plus_k() {
    let t = asset_thread(
        "g76-id-m32-g8.nc",
        &[
            "--stock",
            "50x40",
            "--bore",
            "30",
            "--tools",
            asset("corpus/tools/shop2.toml").to_str().unwrap(),
        ],
    );
    assert_eq!(t["side"], "id");
    assert_eq!(t["passes"], 15);
    assert_close(&t["pass_depths_mm"], &increments(0.3, 1.1, 13, 1), 1e-6);
    // G8: radius 14.5 + 0.5 + 1.1 = 16.1
    assert!(
        (t["achieved_x"].as_f64().unwrap() - 32.2).abs() < 1e-6,
        "{t}"
    );
    assert!(
        (t["included_angle_deg"].as_f64().unwrap() - 60.0).abs() < 0.01,
        "{t}"
    );
}

const OD: &str = "G18 G21 G7 G90 G95\nT4 M6 G43\nG97 S600 M3\nG0 X31 Z3\nG76 P1.5 Z-20 I-1 J0.5 K1.8 R2 Q29.5 H1\nG0 X50 Z20\nM2\n";

#[test]
fn g7_halves_i_j_k_g8_reads_them_as_radii_and_the_first_pass_is_where_the_source_puts_it() {
    let g7 = toolpath(OD, Control::LinuxCnc);
    let g8 = OD
        .replace("G7 G90", "G8 G90")
        .replace("X31", "X15.5")
        .replace("X50", "X25")
        .replace("I-1 J0.5 K1.8", "I-0.5 J0.25 K0.9");
    let g8 = toolpath(&g8, Control::LinuxCnc);
    let ends = |tp: &Toolpath| -> Vec<(f64, f64)> {
        tp.segments.iter().map(|s| (s.to.z, s.to.r)).collect()
    };
    assert_eq!(ends(&g7), ends(&g8));
    // pass 1, depth 0.5 + 0.25 below the drive line r15.5, shifted 0.25·tan 29.5° toward −Z:
    // back to r15.5 + (0.9 + 0.5 − 0.75) (it retracts |I| + K), in, over to the end shifted
    // (0.9 − 0.25)·tan 29.5°, out; 14 passes of 4 moves
    let t = 29.5f64.to_radians().tan();
    let s = &g7.segments;
    let at = |k: usize, z: f64, r: f64, m: Motion| {
        assert_eq!(s[k].motion, m, "move {k}");
        assert!(
            (s[k].to.z - z).abs() < 1e-9 && (s[k].to.r - r).abs() < 1e-9,
            "move {k}: {:?}",
            s[k].to
        );
    };
    at(1, 3.0 - 0.25 * t, 16.15, Motion::Rapid);
    at(2, 3.0 - 0.25 * t, 14.75, Motion::Rapid);
    at(3, -20.0 + 0.65 * t, 14.75, Motion::Thread);
    at(4, -20.0 + 0.65 * t, 16.15, Motion::Rapid);
    // the last pass ends on the drive line's end, so the cycle's last rapid has no length
    assert_eq!(s.len(), 1 + 14 * 4 + 1);
    at(55, -20.0, 14.1, Motion::Thread);
    at(56, -20.0, 15.5, Motion::Rapid);
    assert!(threads(&g7).iter().all(|s| s.lead == 1.5));
}

/// The same M30×1.5 written for FANUC's two-block G76 (m = H = 1, a = 2·Q = 60, Δdmin 0, d 0,
/// k 0.9, Δd 0.25): FANUC's passes start at A and end at the end point at full depth,
/// `LinuxCNC`'s start K·tan Q before the drive line's start, so FANUC's A is Z3 − 0.9·tan 30°.
#[test]
fn the_same_thread_written_for_fanuc_g76_cuts_the_same_passes_and_section() {
    let lcnc = OD.replace("Q29.5", "Q30");
    let fanuc = "G21 G99\nT0404\nG97 S600 M3\nG0 X31. Z2.480385\nG76 P010060 Q0 R0\nG76 X28.2 Z-20. P900 Q250 F1.5\nG0 X50. Z20.\nM30\n";
    let blank = stock::Blank::bar(30.0, 60.0, 0.0, None).unwrap();
    let tools = shop();
    let (tl, sl) = simulate_with(
        &lcnc,
        &Machine::for_control(Control::LinuxCnc),
        &blank,
        &tools,
    );
    let (tf, sf) = simulate_with(
        fanuc,
        &Machine::for_control(Control::FanucA),
        &blank,
        &tools,
    );
    let (pl, pf) = (threads(&tl), threads(&tf));
    assert_eq!(pl.len(), 14);
    assert_eq!(pl.len(), pf.len());
    for (l, f) in pl.iter().zip(&pf) {
        // the start Z rounded to 1 µm in the FANUC program
        assert!(
            l.from.dist(f.from) < 1e-6 && l.to.dist(f.to) < 1e-6,
            "{l:?} vs {f:?}"
        );
        assert_eq!(l.lead, f.lead);
    }
    let h = stock::hausdorff(&sl.final_shapes, &sf.final_shapes);
    assert!(h <= 0.01, "Hausdorff between the sections {h}");
    let area = |s: &stock::Simulation| s.removed_area;
    assert!(
        (area(&sl) - area(&sf)).abs() < 1e-3,
        "{} vs {}",
        area(&sl),
        area(&sf)
    );
    // LinuxCNC's usual Q29.5 against FANUC's 30° infeed (A at Z3 − 0.9·tan 29.5°): the rough
    // passes differ by (K − depth)·(tan 30° − tan 29.5°) in Z, the last ones coincide, and
    // every rough groove lies inside its last one: the same section
    let (t29, s29) = simulate_with(OD, &Machine::for_control(Control::LinuxCnc), &blank, &tools);
    let a29 = format!("Z{:.6}", 3.0 - 0.9 * 29.5f64.to_radians().tan());
    let (tf29, sf29) = simulate_with(
        &fanuc.replace("Z2.480385", &a29),
        &Machine::for_control(Control::FanucA),
        &blank,
        &tools,
    );
    let (p29, pf29) = (threads(&t29), threads(&tf29));
    assert!(
        p29[0].from.dist(pf29[0].from) > 1e-4,
        "the first passes differ"
    );
    assert!(
        p29[13].from.dist(pf29[13].from) < 1e-6,
        "the last passes coincide"
    );
    let h = stock::hausdorff(&s29.final_shapes, &sf29.final_shapes);
    let h30 = stock::hausdorff(&sl.final_shapes, &sf.final_shapes);
    eprintln!("Hausdorff to FANUC's section: Q30 {h30:.2e} mm, Q29.5 {h:.2e} mm");
    assert!(
        h <= 0.01,
        "Hausdorff between the Q29.5 and 30° sections {h}"
    );
}

#[test]
fn tapers_run_over_e_between_the_peak_and_the_depth_at_the_taper_pitch() {
    let t = 29.5f64.to_radians().tan();
    // L3: both ends, E0.45 < K0.9: X leads the taper, P·K/E = 3 mm along X per revolution
    let tp = toolpath(&OD.replace("H1", "H1 E0.45 L3"), Control::LinuxCnc);
    let s = &tp.segments;
    let z0 = 3.0 - 0.25 * t;
    let z1 = -20.0 + 0.65 * t;
    let pass: Vec<(Motion, f64, f64, f64)> = s[1..7]
        .iter()
        .map(|s| (s.motion, s.to.z, s.to.r, s.lead))
        .collect();
    let radial = 1.5 * 0.45f64.hypot(0.9) / 0.45;
    let want = [
        (Motion::Rapid, z0, 16.15, 0.0),
        (Motion::Thread, z0, 15.5 - 0.75 + 0.9, radial), // in to the depth less K
        (Motion::Thread, z0 - 0.45, 14.75, 3.0),         // angled in over E
        (Motion::Thread, z1 + 0.45, 14.75, 1.5),         // over
        (Motion::Thread, z1, 15.65, 3.0),                // angled out over E
        (Motion::Rapid, z1, 16.15, 0.0),
    ];
    for (g, w) in pass.iter().zip(&want) {
        assert_eq!(g.0, w.0, "{pass:?}");
        assert!(
            (g.1 - w.1).abs() < 1e-9 && (g.2 - w.2).abs() < 1e-9,
            "{pass:?}"
        );
        if g.0 == Motion::Thread {
            assert!((g.3 - w.3).abs() < 1e-9, "{pass:?}");
        }
    }
    // the report still sees one thread of 14 passes, measured on the straight moves
    let r = report_of(
        &OD.replace("H1", "H1 E0.45 L3"),
        &[
            "--control",
            "linuxcnc",
            "--stock",
            "30x60",
            "--tools",
            asset("corpus/tools/shop.toml").to_str().unwrap(),
        ],
    );
    let threads = r["threads"].as_array().unwrap();
    assert_eq!(threads.len(), 1, "{threads:?}");
    assert_eq!(threads[0]["passes"], 14);
    assert_eq!(threads[0]["lead_mm"], 1.5);
    assert!((threads[0]["achieved_x"].as_f64().unwrap() - 28.2).abs() < 1e-6);
}

/// `latsim check --control linuxcnc` of `text`: (exit code, stderr).
fn check(text: &str) -> (i32, String) {
    let (_dir, prog) = temp_program("p.ngc", text.as_bytes());
    let out = latsim(&["check", prog.to_str().unwrap(), "--control", "linuxcnc"]);
    (out.code, out.stderr)
}

#[test]
fn what_linuxcnc_refuses_in_g76_is_an_alarm_at_its_word() {
    let head = "G7 G21 T4 M6 M3 S500\nG0 X31 Z3\n";
    for (block, col, says) in [
        ("G76 Z-20 I-1 J0.5 K1.8", 1, "P word missing with G76"),
        ("G76 P1.5 Z-20 I-1 K1.8", 1, "I J or K words missing"),
        ("G76 P1.5 Z-20 I0 J0.5 K1.8", 15, "I must not be 0"),
        ("G76 P1.5 Z-20 I-1 J0 K1.8", 19, "J must be greater than 0"),
        (
            "G76 P1.5 Z-20 I-1 J0.5 K0.5",
            24,
            "K must be greater than J",
        ),
        ("G76 P0 Z-20 I-1 J0.5 K1.8", 5, "P must be positive"),
        ("G76 P1.5 Z-20 I-1 J0.5 K1.8 Q90", 29, "less than 90"),
        ("G76 P1.5 Z-20 I-1 J0.5 K1.8 H-1", 29, "whole number"),
        ("G76 P1.5 Z-20 I-1 J0.5 K1.8 L1.5", 29, "whole number"),
        ("G76 P1.5 Z-20 I-1 J0.0001 K1.8 R4", 1, "passes"),
    ] {
        let (code, err) = check(&format!("{head}{block}\nM2\n"));
        assert_eq!(code, 1, "{block}: {err}");
        assert!(err.contains(says), "{block}: {err}");
        assert!(err.contains(&format!("p.ngc:3:{col}")), "{block}: {err}");
    }
    // G76 is modal in LinuxCNC: a block of axis words after it repeats it, without P
    let (code, err) = check(&format!("{head}G76 P1.5 Z-20 I-1 J0.5 K1.8\nZ5\nM2\n"));
    assert_eq!(code, 1);
    assert!(
        err.contains("P word missing") && err.contains("p.ngc:4"),
        "{err}"
    );
    // compensation on, spindle stopped
    let (code, err) =
        check("G7 T4 M6 M3 S500\nG0 X31 Z3\nG42.1 D0.8 L2\nG76 P1.5 Z-20 I-1 J0.5 K1.8\nM2\n");
    assert_eq!(code, 1);
    assert!(err.contains("LS-G76-COMP"), "{err}");
    let (code, err) = check("G7 T4 M6\nG0 X31 Z3\nG76 P1.5 Z-20 I-1 J0.5 K1.8\nM2\n");
    assert_eq!(code, 1);
    assert!(err.contains("LS-G76-SPINDLE"), "{err}");
    // what LinuxCNC corrects without a word is a warning: R below 1 cuts as R1
    let (code, err) = check(&format!(
        "{head}G76 P1.5 Z-20 I-1 J0.5 K1.8 R0.5\nG0 X50\nM2\n"
    ));
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("LinuxCNC cuts with R1"), "{err}");
}

/// The reference's own example (inch, G8): `G0 Z-0.5 X0.2` / `G76 P0.05 Z-1 I-.075 J0.008
/// K0.045 Q29.5 L2 E0.045`. Without R the depth grows by J a pass: 0.008·n < 0.045 for
/// n ≤ 5, then one pass at K (no H): 6 passes, each threading to E before its end and tapering
/// out to the peak. Under G91 its Z is from the start: the same cycle.
#[test]
fn the_references_inch_example_and_its_incremental_twin() {
    let abs = "G20 G18 G8 G90\nT4 M6\nS800 M3\nG0 Z-0.5 X0.2\nG76 P0.05 Z-1 I-.075 J0.008 K0.045 Q29.5 L2 E0.045\nM2\n";
    let tp = toolpath(abs, Control::LinuxCnc);
    let t = threads(&tp);
    assert_eq!(t.len(), 12, "6 passes, each a thread and its exit taper");
    let inch = 25.4;
    let (over, out) = (t[10], t[11]);
    assert!((over.to.z - (-1.0 + 0.045) * inch).abs() < 1e-9, "{over:?}");
    assert!(
        (over.to.r - (0.2 - 0.075 - 0.045) * inch).abs() < 1e-9,
        "{over:?}"
    );
    assert!((out.to.z + inch).abs() < 1e-9 && (out.to.r - 0.125 * inch).abs() < 1e-9);
    // the straight threads at P, the tapers at P·K/E along X (E = K: 45°, also P)
    assert!(t.iter().all(|s| (s.lead - 0.05 * inch).abs() < 1e-12));
    // pass 2 is 0.016 below the peak, shifted 0.016·tan 29.5° toward −Z from Z−0.5
    let shift = 0.016 * 29.5f64.to_radians().tan();
    assert!(
        (t[2].from.z - (-0.5 - shift) * inch).abs() < 1e-9,
        "{:?}",
        t[2]
    );
    assert!((t[2].from.r - (0.2 - 0.075 - 0.016) * inch).abs() < 1e-9);
    let inc = abs.replace("G76 P0.05 Z-1", "G91 G76 P0.05 Z-0.5");
    let ends = |tp: &Toolpath| -> Vec<(f64, f64)> {
        tp.segments.iter().map(|s| (s.to.z, s.to.r)).collect()
    };
    assert_eq!(ends(&toolpath(&inc, Control::LinuxCnc)), ends(&tp));
}
