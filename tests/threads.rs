//! G76 through the interpreter (issue 14): the two-block FANUC/GSK form on the issue's
//! M20 × 1.5 thread, with the pass depths computed by hand.

mod common;

/// `G76 P021060 Q50 R0.05` / `G76 X18.05 Z-25 P975 Q400 F1.5` from X22 Z5, IS-B:
/// m 2, r 1.0 lead, a 60°, Δdmin 0.05, d 0.05, k 0.975, Δd 0.4. Depths Δd·√n:
/// 0.4, 0.5657, 0.6928, 0.8, 0.8944, then 0.9798 > k − d = 0.925 is cut at 0.925,
/// then m = 2 passes at k: 8 passes; the last three reach the minor diameter
/// 20 − 2·0.975 = 18.05.
#[test]
fn g76_two_block_m20x1_5_passes() {
    let text = "G99 M03 S600 T0101\nG00 X22 Z5\nG76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q400 F1.5\nG00 X50 Z50\nM30\n";
    let program = gcode::parse(text).unwrap();
    let tp = expander::expand(&program, &expander::Machine::default(), &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    // the first thread move of each pass: its radius is the crest radius minus the depth
    let starts: Vec<f64> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread && s.span.line == 4)
        .filter(|s| (s.from.r - s.to.r).abs() < 1e-9)
        .map(|s| 2.0 * s.from.r)
        .collect();
    let depths = [0.4, 0.565685, 0.692820, 0.8, 0.894427, 0.925, 0.975, 0.975];
    assert_eq!(starts.len(), depths.len(), "{starts:?}");
    for (x, h) in starts.iter().zip(depths) {
        // X of a pass = 18.05 + 2·(k − h)
        let expected = 18.05 + 2.0 * (0.975 - h);
        assert!((x - expected).abs() < 2e-6, "{x} vs {expected}");
    }
    // every thread move keeps the 1.5 lead
    assert!(tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .all(|s| (s.lead - 1.5).abs() < 1e-12));
}

/// dialects.md §7 T10 (`fanuc-a`, Φ20 × 40 bar, tool 4 a sharp 60° OD insert).
const T10: &str = "G21 G99 T0404 ;\nG97 S500 M03 ;\nG00 X22. Z5. ;\nG92 X19.2 Z-20. F3. Q0 ;\nX18.6 Q0 ;\nG92 X19.2 Z-20. F3. Q180000 ;\nX18.6 Q180000 ;\nG00 X100. Z100. ;\nM30 ;\n";

fn t10(program: &str) -> (expander::Toolpath, stock::Simulation) {
    let machine = expander::Machine::for_control(expander::Control::FanucA);
    let blank = stock::Blank::bar(20.0, 40.0, 0.0, None).unwrap();
    let tools =
        stock::ToolTable::from_toml(&common::read(&common::asset("tools/thread60.toml"))).unwrap();
    common::pipeline(program, &machine, &blank, &tools)
}

/// The Z of the thread roots in the final section: the vertices of the outside at the
/// root radius (a sharp insert leaves each stamp's tip as one vertex), sorted downward.
fn roots_at(sim: &stock::Simulation, r: f64) -> Vec<f64> {
    let mut z: Vec<f64> = sim
        .final_shapes
        .iter()
        .flat_map(|s| s.outer.iter())
        .filter(|p| (p[1] - r).abs() < 1e-3 && p[0] < 0.0)
        .map(|p| p[0])
        .collect();
    z.sort_by(|a, b| b.total_cmp(a));
    z.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
    z
}

/// T10: four passes of lead 3; the Q180000 passes are stamped 1.5 mm (L·180/360) further
/// along the move. From Z5 down, the first start passes the section at Z 5 − 3k, the second
/// at Z 3.5 − 3k; in the bar (Z < 0) that is a root Φ18.6 (r 9.3) every 1.5 mm at
/// Z −1, −2.5, …, −19 (and the end stamp at Z −20). Between two roots 1.5 apart the 60°
/// V's are 2·0.7·tan 30° = 0.808 wide at the crest, so the crest Φ20 stays between them
/// (at Z −0.25 − 1.5k).
#[test]
fn t10_two_start_g92_q() {
    let (tp, sim) = t10(T10);
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    assert!(tp
        .warnings
        .iter()
        .all(|w| w.code != "LS-THREAD-Q-NOT-MODAL"));
    let passes: Vec<_> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .collect();
    assert_eq!(passes.len(), 4);
    let phases: Vec<f64> = passes.iter().map(|s| s.thread_phase).collect();
    assert_eq!(phases, [0.0, 0.0, 0.5, 0.5]);
    assert!(passes.iter().all(|s| s.lead == 3.0));
    // the two tooth sets, measured in the section: roots every 1.5 mm, a half lead apart
    let roots = roots_at(&sim, 9.3);
    let want: Vec<f64> = (0..13)
        .map(|k| -1.0 - 1.5 * k as f64)
        .chain([-20.0])
        .collect();
    assert_eq!(roots.len(), want.len(), "{roots:?}");
    for (z, w) in roots.iter().zip(&want) {
        assert!((z - w).abs() < 2e-3, "root at {z}, expected {w}: {roots:?}");
    }
    for k in 0..12 {
        let root = -1.0 - 1.5 * k as f64;
        let r =
            analysis::surface_radius_at(&sim.final_shapes, root, analysis::Surface::Outer).unwrap();
        assert!((r - 9.3).abs() < 2e-3, "root Φ{} at Z{root}", 2.0 * r);
        let crest = root + 0.75;
        let r = analysis::surface_radius_at(&sim.final_shapes, crest, analysis::Surface::Outer)
            .unwrap();
        assert!((r - 10.0).abs() < 2e-3, "crest Φ{} at Z{crest}", 2.0 * r);
    }
    let minor = analysis::deepest_radius(&sim.final_shapes, 0.0, -20.0, analysis::Surface::Outer);
    assert!((minor.unwrap() - 9.3).abs() < 2e-3, "{minor:?}");
}

/// T10 variant: `X18.6 ;` without Q on the last pass threads at 0° (Q is not modal): it
/// recuts the first start, is warned at its line (7), and the second start keeps its root
/// Φ19.2 (r 9.6) at Z −2.5 − 3k while the first start's is Φ18.6 at Z −1 − 3k.
#[test]
fn t10_q_not_modal_warns() {
    let (tp, sim) = t10(&T10.replace("X18.6 Q180000 ;", "X18.6 ;"));
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let warned: Vec<u32> = tp
        .warnings
        .iter()
        .filter(|w| w.code == "LS-THREAD-Q-NOT-MODAL")
        .map(|w| w.span.line)
        .collect();
    assert_eq!(warned, [7]);
    let last = tp
        .segments
        .iter()
        .rev()
        .find(|s| s.motion == expander::Motion::Thread)
        .unwrap();
    assert_eq!(last.thread_phase, 0.0);
    for k in 0..6 {
        let first = -1.0 - 3.0 * k as f64;
        let second = -2.5 - 3.0 * k as f64;
        let at = |z| {
            analysis::surface_radius_at(&sim.final_shapes, z, analysis::Surface::Outer).unwrap()
        };
        assert!((at(first) - 9.3).abs() < 2e-3, "Z{first}: r {}", at(first));
        assert!(
            (at(second) - 9.6).abs() < 2e-3,
            "Z{second}: r {}",
            at(second)
        );
    }
}

/// G32 takes Q for its own block only; a Q with a decimal point or beyond 360° is an alarm
/// at the Q word.
#[test]
fn g32_start_angle() {
    let expand = |text: &str| {
        let program = gcode::parse(text).unwrap();
        expander::expand(
            &program,
            &expander::Machine::for_control(expander::Control::FanucA),
            &Default::default(),
        )
    };
    let tp = expand("G99 M03 S500 T0404\nG00 X19.2 Z5\nG32 Z-20 F3 Q90000\nG32 Z-21\nM30\n");
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let phases: Vec<f64> = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .map(|s| s.thread_phase)
        .collect();
    assert_eq!(phases, [0.25, 0.0]);
    for bad in ["Q90.", "Q360001"] {
        let tp = expand(&format!(
            "G99 M03 S500\nG00 X19.2 Z5\nG32 Z-20 F3 {bad}\nM30\n"
        ));
        assert_eq!(tp.alarms.len(), 1, "{bad}");
        assert_eq!(tp.alarms[0].code, "LS-THREAD-Q");
        assert_eq!(tp.alarms[0].span.column, 13, "{bad}");
    }
}

/// The M20 × 1.5 G76 thread on a Φ20 bar with the sharp 60° tool 4.
const M20: &str = "G99 M03 S600 T0404\nG00 X22 Z5\nG76 P021060 Q50 R0.05\nG76 X18.05 Z-25 P975 Q400 F1.5\nG00 X50 Z50\nM30\n";

fn run_json(program: &str, extra: &[&str]) -> (i32, serde_json::Value) {
    let (dir, path) = common::temp_program("thread.nc", program.as_bytes());
    let json = dir.path().join("out.json");
    let tools = common::asset("tools/thread60.toml");
    let mut args = vec![
        "run",
        path.to_str().unwrap(),
        "--stock",
        "20x40",
        "--tools",
        tools.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ];
    args.extend_from_slice(extra);
    let out = common::latsim(&args);
    let text = std::fs::read_to_string(&json).unwrap_or_else(|_| panic!("{}", out.stderr));
    (out.code, serde_json::from_str(&text).unwrap())
}

/// The report's `threads`: line 4, lead 1.5, final X 18.05 (20 − 2·0.975), the eight pass
/// depths of `g76_two_block_m20x1_5_passes` as infeeds (0.4, 0.1657, 0.1272, 0.1072,
/// 0.0944, 0.0306, 0.05, 0), and the minor diameter reached in the section: 18.05.
#[test]
fn m20_thread_reports_its_minor() {
    let (code, j) = run_json(M20, &[]);
    assert_eq!(code, 0, "{j:#}");
    assert_eq!(j["verdict"], "clean");
    let t = &j["threads"];
    assert_eq!(t.as_array().unwrap().len(), 1, "{t:#}");
    let t = &t[0];
    assert_eq!(t["line"], 4);
    assert_eq!(t["side"], "od");
    assert_eq!(t["lead_mm"], 1.5);
    assert_eq!(t["passes"], 8);
    // the compound infeed moves each pass's start along Z: still one start
    assert_eq!(t["starts"], 1);
    let x = |k: &str| t[k].as_f64().unwrap();
    assert!((x("x") - 18.05).abs() < 1e-9);
    assert!((x("achieved_x") - 18.05).abs() < 2e-3, "{t:#}");
    assert!(x("depth_error_mm").abs() < 1e-3, "{t:#}");
    // The sharp 60° tool's last pass leaves a V from the root r9.025 (the compound infeed
    // keeps every pass on its leading flank): groove and tooth are 0.75 wide each
    // 0.75 / (2 tan 30°) = 0.649519 above the root, d2 = 2 (9.025 + 0.649519) = 19.349.
    assert!((x("pitch_diameter") - 19.349038).abs() < 2e-3, "{t:#}");
    assert!((x("included_angle_deg") - 60.0).abs() < 0.05, "{t:#}");
    // the deepest pass's threading move runs from the cycle's start Z5 to where the
    // chamfer (P..10..: 1.0 lead) pulls out, 1.5 before Z-25
    assert_eq!((x("z_start"), x("z_end")), (5.0, -23.5), "{t:#}");
    let h = [0.4, 0.565685, 0.692820, 0.8, 0.894427, 0.925, 0.975, 0.975];
    let depths: Vec<f64> = t["pass_depths_mm"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d.as_f64().unwrap())
        .collect();
    for (k, d) in depths.iter().enumerate() {
        let want = h[k] - if k == 0 { 0.0 } else { h[k - 1] };
        assert!(
            (d - want).abs() < 2e-3,
            "pass {k}: {d} vs {want}: {depths:?}"
        );
    }
}

/// The picture zooms on the thread's teeth: an inset titled with what was reached, the
/// expected minor diameter and the pitch diameter labelled on their lines.
#[test]
fn m20_thread_gets_a_detail_view() {
    let (dir, path) = common::temp_program("thread.nc", M20.as_bytes());
    let svg = dir.path().join("out.svg");
    let tools = common::asset("tools/thread60.toml");
    let out = common::latsim(&[
        "run",
        path.to_str().unwrap(),
        "--stock",
        "20x40",
        "--tools",
        tools.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "--quiet",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let s = std::fs::read_to_string(&svg).unwrap();
    assert!(
        s.contains("detail 1: thread line 4, lead 1.5: X18.05 reached, 60°</text>"),
        "{}",
        s.lines()
            .filter(|l| l.contains("detail"))
            .collect::<Vec<_>>()
            .join("\n")
    );
    assert!(s.contains("expected Φ18.05") && s.contains("pitch Φ19.349"));
}

/// The same program cut to X17.65 against a target drawing the thread's minor at Φ18.05
/// (Z0 to Z−25, Φ20 behind it): 0.2 mm too deep (radial, (18.05 − 17.65)/2), a thread depth
/// error at line 4, and the run fails like a gouge.
#[test]
fn thread_too_deep_is_a_finding() {
    let (dir, target) = common::temp_program(
        "m20.toml",
        b"start = [0.0, 0.0]\npath = [\n  { to = [0.0, 18.05] },\n  { to = [-25.0, 18.05] },\n  { to = [-25.0, 20.0] },\n  { to = [-40.0, 20.0] },\n  { to = [-40.0, 0.0] },\n]\n",
    );
    let _keep = dir;
    let deep = M20.replace("X18.05 Z-25", "X17.65 Z-25");
    let (code, j) = run_json(&deep, &["--target", target.to_str().unwrap()]);
    let t = &j["threads"][0];
    let x = |k: &str| t[k].as_f64().unwrap();
    assert!((x("achieved_x") - 17.65).abs() < 2e-3, "{t:#}");
    assert!((x("expected_x") - 18.05).abs() < 2e-3, "{t:#}");
    assert!((x("depth_error_mm") - 0.2).abs() < 1e-3, "{t:#}");
    assert_eq!(j["verdict"], "gouge", "{j:#}");
    assert_eq!(code, 1);
    let warned = j["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w["code"] == "LS-THREAD-DEPTH" && w["line"] == 4);
    assert!(warned, "{:#}", j["warnings"]);
    // the program's own X18.05 against the same target is clean
    let (code, j) = run_json(M20, &["--target", target.to_str().unwrap()]);
    assert!(j["threads"][0]["depth_error_mm"].as_f64().unwrap().abs() < 1e-3);
    assert_eq!(code, 0, "{j:#}");
}

/// An ID M30 × 2 thread in a Φ27.9 bore of a Φ40 tube (Z0…−40): G76 from X24 to X30 at
/// Z−20, height k 1.05 ((30 − 27.9)/2), Δd 0.3.
const M30_ID: &str = "G99 M03 S400 T0404\nG00 X24 Z5\nG76 P011060 Q50 R0.05\nG76 X30 Z-20 P1050 Q300 F2\nG00 X26 Z50\nM30\n";

fn run_id(side: &str) -> (i32, serde_json::Value) {
    let (dir, tools) = common::temp_program(
        "id.toml",
        format!("[[tool]]\nt = 4\nkind = \"threading\"\nangle = 60\nside = \"{side}\"\n")
            .as_bytes(),
    );
    let _keep = dir;
    let (pdir, path) = common::temp_program("m30.nc", M30_ID.as_bytes());
    let json = pdir.path().join("out.json");
    let out = common::latsim(&[
        "run",
        path.to_str().unwrap(),
        "--stock",
        "40x40",
        "--bore",
        "27.9",
        "--tools",
        tools.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ]);
    let text = std::fs::read_to_string(&json).unwrap_or_else(|_| panic!("{}", out.stderr));
    (out.code, serde_json::from_str(&text).unwrap())
}

/// With an ID insert the wall stays: the outside is Φ40 everywhere (Z0…−40), the bore is
/// Φ27.9 behind the thread (Z−30), and the thread reaches its major Φ30 (root r 15) over
/// Z0…−20, teeth 2 mm apart. With the table saying OD for the same program, the OD body
/// sweeps through the wall: an alarm at the thread's line says so.
#[test]
fn id_thread_in_a_bore() {
    let (code, j) = run_id("id");
    assert_eq!(code, 0, "{j:#}");
    assert!(
        j["crashes"].as_array().unwrap().is_empty(),
        "{:#}",
        j["crashes"]
    );
    let t = &j["threads"][0];
    assert_eq!(t["side"], "id", "{t:#}");
    assert!((t["x"].as_f64().unwrap() - 30.0).abs() < 1e-9);
    assert!(
        (t["achieved_x"].as_f64().unwrap() - 30.0).abs() < 2e-3,
        "{t:#}"
    );
    // The V of the sharp 60° tool from the root r15: groove and tooth are 1.0 wide each
    // 1 / (2 tan 30°) = 0.866025 below it, D2 = 2 (15 − 0.866025) = 28.268 (ISO basic
    // D2 28.701: a sharp V at the programmed major leaves the thread small). At the bore
    // (r13.95) the groove is 2 · 1.05 tan 30° = 1.212 wide, 61 % of the pitch: the angle is
    // measured between 35 % and 56 %.
    assert!(
        (t["pitch_diameter"].as_f64().unwrap() - 28.267949).abs() < 2e-3,
        "{t:#}"
    );
    assert!(
        (t["included_angle_deg"].as_f64().unwrap() - 60.0).abs() < 0.05,
        "{t:#}"
    );
    // the final section, read back from the report (x is the diameter)
    let shapes: Vec<stock::Shape> = j["final"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| stock::Shape {
            outer: p["outer"]
                .as_array()
                .unwrap()
                .iter()
                .map(|q| [q[0].as_f64().unwrap(), q[1].as_f64().unwrap() / 2.0])
                .collect(),
            holes: vec![],
        })
        .collect();
    let at = |z: f64, s| analysis::surface_radius_at(&shapes, z, s).unwrap();
    for k in 0..40 {
        let z = -0.5 - k as f64;
        assert!(
            (at(z, analysis::Surface::Outer) - 20.0).abs() < 1e-6,
            "wall cut at Z{z}"
        );
    }
    assert!((at(-30.0, analysis::Surface::Bore) - 13.95).abs() < 1e-6);
    let major = analysis::deepest_radius(&shapes, -1.0, -19.0, analysis::Surface::Bore).unwrap();
    assert!((major - 15.0).abs() < 2e-3, "{major}");
    // teeth: between two roots 2 apart a crest of the bore stays (r 13.95)
    let crest = (0..200)
        .map(|i| at(-3.0 - 0.01 * i as f64, analysis::Surface::Bore))
        .fold(f64::INFINITY, f64::min);
    assert!((crest - 13.95).abs() < 1e-6, "{crest}");

    let (code, j) = run_id("od");
    assert_eq!(code, 1, "{j:#}");
    // the OD body's rapids back through the wall are crashes too
    assert!(!j["crashes"].as_array().unwrap().is_empty());
    let alarm = j["alarms"]
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["code"] == "LS-THREAD-SIDE")
        .unwrap_or_else(|| panic!("{:#}", j["alarms"]));
    assert_eq!(alarm["line"], 4);
    assert!(alarm["message"].as_str().unwrap().contains("side = \"id\""));
}

/// A tapered thread by G92 R on a cone blank (Φ18 at Z0 to Φ20 at Z−20, radius +0.05 per mm
/// toward −Z, then Φ20 to Z−40): `G92 X17.8 Z-20 F2` from Z5 follows the same cone
/// (R = start − end radius over the 25 mm from Z5: −0.05·25), 1.1 mm below it. Roots
/// (stamps at Z 5 − 2k) at Z −1 − 2k on the root cone r = 8.9 − 0.05·(Z + 20); the crests
/// midway (Z −2k) stay on the blank's cone r = 9 − 0.05·Z (the V's are 2·1.1·tan 30° =
/// 1.27 wide there, the lead 2).
#[test]
fn tapered_thread_crests_on_the_cone() {
    let machine = expander::Machine::for_control(expander::Control::FanucA);
    let blank = stock::Blank::from_profile_toml(
        "start = [0.0, 0.0]\npath = [\n  { to = [0.0, 18.0] },\n  { to = [-20.0, 20.0] },\n  { to = [-40.0, 20.0] },\n  { to = [-40.0, 0.0] },\n]\n",
        0.001,
    )
    .unwrap();
    let tools =
        stock::ToolTable::from_toml(&common::read(&common::asset("tools/thread60.toml"))).unwrap();
    let (tp, sim) = common::pipeline(
        "G21 G99 T0404 ;\nG97 S500 M03 ;\nG00 X22. Z5. ;\nG92 X17.8 Z-20. R-1.25 F2. ;\nG00 X100. Z100. ;\nM30 ;\n",
        &machine,
        &blank,
        &tools,
    );
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let at = |z: f64| {
        analysis::surface_radius_at(&sim.final_shapes, z, analysis::Surface::Outer).unwrap()
    };
    for k in 1..9 {
        let crest = -2.0 * k as f64;
        let cone = 9.0 - 0.05 * crest;
        assert!(
            (at(crest) - cone).abs() < 2e-3,
            "crest Z{crest}: r {} vs {cone}",
            at(crest)
        );
        let root = crest + 1.0;
        let line = 8.9 - 0.05 * (root + 20.0);
        assert!(
            (at(root) - line).abs() < 2e-3,
            "root Z{root}: r {} vs {line}",
            at(root)
        );
    }
    // Pitch diameter at the thread's end (Z−20, root r8.9), measured along lines parallel to
    // the root cone (slope k = −0.05): the V's flanks (±30°) meet such a line h above the apex
    // 2h tan 30° / (1 − k² tan² 30°) apart, so half the lead (1.0) is reached at
    // h = 0.866025 (1 − 0.000833) = 0.865304: d2 = 2 (8.9 + 0.865304) = 19.530608; the
    // angle 2 atan(tan 30° / (1 − 0.000833)) = 60.041°.
    let threads = analysis::threads(&tp.segments, &tools, &sim.final_shapes);
    let form = threads[0].form(&sim.final_shapes).unwrap();
    assert!((form.pitch_diameter - 19.530608).abs() < 2e-3, "{form:?}");
    assert!(
        (form.included_angle.unwrap() - 60.041).abs() < 0.005,
        "{form:?}"
    );
}

/// M20 × 1.5 by G92 whose last lead runs out into a relief groove plunged to X16.6 before
/// (a 3 mm blade at Z−22 … −25): the depth is measured where the stock came up to the root
/// when the thread began, so the relief is not the thread's depth: X18.05 reached, no
/// LS-THREAD-DEPTH, clean. (Measured over the relief too it read X16.6, 0.725 mm "too
/// deep", and failed the run.)
#[test]
fn a_relief_cut_before_the_thread_is_not_its_depth() {
    let (tdir, tools) = common::temp_program(
        "t.toml",
        b"[[tool]]\nt = 4\nkind = \"threading\"\nangle = 60\n\n[[tool]]\nt = 5\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"-z\"\nshank_dir = \"+x\"\nreach = 8.0\n",
    );
    let _keep = tdir;
    let program = "G99 M03 S500 T0505\nG00 X22 Z-22\nG01 X16.6 F0.05\nG00 X22\nT0404\nG00 X22 Z5\nG92 X19.4 Z-23 F1.5\nX18.8\nX18.4\nX18.15\nX18.05\nG00 X50 Z50\nM30\n";
    let j = common::report_of(
        program,
        &["--stock", "20x40", "--tools", tools.to_str().unwrap()],
    );
    let t = &j["threads"][0];
    let achieved = t["achieved_x"].as_f64().unwrap();
    assert!((achieved - 18.05).abs() < 2e-3, "{t:#}");
    assert!(
        j["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .all(|w| w["code"] != "LS-THREAD-DEPTH"),
        "{j:#}"
    );
    assert_eq!(j["verdict"], "clean", "{j:#}");
}

/// Haas G92 M16 × 2 with M23 (the pull-out chamfer, Setting 95 = 1 lead at Setting 96 =
/// 45°): each pass threads to Z-18 and pulls out to Z-20, 2 mm off the root, still
/// threading. The section sees the sharp 60° tool every lead from Z5 as one pass, the
/// chamfer included: V grooves at Z-1 … -17 (nine, 0.8 deep: 0.8² tan 30° each) and one
/// at Z-19 on the chamfer, apex r8.2, outside the Φ16 bar: 9 × 0.369504 = 3.3255 mm². With
/// M24 each pass runs to Z-20 at full depth: the grooves at Z-19 and the pass end Z-20 come
/// in (4.065 mm²). (Stamped at the joint Z-18 as well, the chamfer added a tenth groove.)
#[test]
fn haas_g92_pulls_out_under_m23_and_stamps_on_across_the_chamfer() {
    let run = |m: &str| {
        let program = format!(
            "G18 G21 G40 G99\n{m}\nG97 S500 M03 T404\nG00 X18. Z5.\nG92 X15.4 Z-20. F2.\nX14.8\nX14.4\nG00 X50 Z50\nM30\n"
        );
        let tools = common::asset("corpus/tools/shop.toml");
        let args = [
            "--control",
            "haas",
            "--stock",
            "16x40",
            "--tools",
            tools.to_str().unwrap(),
        ];
        common::report_of(&program, &args)["removed_area_mm2"]
            .as_f64()
            .unwrap()
    };
    let v = 0.8f64.powi(2) * 30f64.to_radians().tan();
    let m23 = run("M23");
    assert!((m23 - 9.0 * v).abs() < 2e-3, "{m23} vs {}", 9.0 * v);
    let m24 = run("M24");
    assert!((m24 - 4.065).abs() < 2e-3, "{m24}");
}

/// The same M16 × 2 on a FANUC whose profile sets `g92_chamfer_leads = 1` (spec/dialects.md
/// §4.7, at 45°): the same pull-out, the same nine grooves; without the key none.
#[test]
fn a_fanuc_g92_pulls_out_by_its_profile() {
    let (mdir, machine) = common::temp_program("m.toml", b"g92_chamfer_leads = 1.0\n");
    let _keep = mdir;
    let run = |profile: bool| {
        let program = "G21 G40 G99\nG97 S500 M03 T0404\nG00 X18. Z5.\nG92 X15.4 Z-20. F2.\nX14.8\nX14.4\nG00 X50 Z50\nM30\n";
        let tools = common::asset("corpus/tools/shop.toml");
        let mut args = vec![
            "--control",
            "fanuc-a",
            "--stock",
            "16x40",
            "--tools",
            tools.to_str().unwrap(),
        ];
        if profile {
            args.extend(["--machine", machine.to_str().unwrap()]);
        }
        common::report_of(program, &args)["removed_area_mm2"]
            .as_f64()
            .unwrap()
    };
    let v = 0.8f64.powi(2) * 30f64.to_radians().tan();
    let chamfered = run(true);
    assert!((chamfered - 9.0 * v).abs() < 2e-3, "{chamfered}");
    assert!((run(false) - 4.065).abs() < 2e-3);
}

/// Field run 4 (5d), in its style: T01 turns Φ34, and T05 (`(THREAD 16ER 1.5ISO)` in a
/// comment only) cuts an M34 × 1.5 by G92 from Z4 to Z−18. The table lists T01 alone.
const G92_NO_ENTRY: &str = "O6002\nG21 G40 G99\nT0101\nG96 S200 M03\nG00 X36. Z2.\nG01 Z0. F0.1\nX34. Z-1.\nZ-25.\nX42.\nG28 U0. W0.\nT0505 (THREAD 16ER 1.5ISO)\nG97 S1000 M03\nG00 X36. Z4.\nG92 X33.4 Z-18. F1.5\nX33.0\nX32.7\nX32.45\nX32.25\nX32.16\nG00 X40.\nG28 U0. W0.\nM30\n";

fn run_no_entry(program: &str, table: Option<&str>, stock: &[&str]) -> serde_json::Value {
    let (dir, path) = common::temp_program("no-entry.nc", program.as_bytes());
    let json = dir.path().join("out.json");
    let tools = dir.path().join("tools.toml");
    let mut args = vec!["run", path.to_str().unwrap(), "--control", "fanuc-a"];
    args.extend_from_slice(stock);
    if let Some(t) = table {
        std::fs::write(&tools, t).unwrap();
        args.extend_from_slice(&["--tools", tools.to_str().unwrap()]);
    }
    args.extend_from_slice(&["--json", json.to_str().unwrap(), "--quiet"]);
    let out = common::latsim(&args);
    assert_eq!(out.code, 0, "{}", out.stderr);
    serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap()
}

fn warnings<'a>(j: &'a serde_json::Value, code: &str) -> Vec<&'a str> {
    common::warning_messages(j, code)
}

/// A tool with no entry that cuts only thread passes is taken for a sharp 60° threading
/// insert (docs/field-rules.md §17), with or without a table: the thread reads 60°, not
/// the 96.3° the 55° turning default cut, and its pull-outs scrape nothing (the default's
/// trailing edge made five LS-RAPID-SCRAPE warnings). Its first pass is 0.3 deep (Φ34 to
/// X33.4), measured from a whole crest: the pass ends 14⅔ leads from its start, and the
/// lead at its end holds only the ridge between the last two stamps, 0.054 below the crest.
#[test]
fn a_thread_tool_with_no_entry_is_a_60_degree_threading_insert() {
    let turning = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    for table in [Some(turning), None] {
        let j = run_no_entry(G92_NO_ENTRY, table, &["--stock", "40x60"]);
        assert_eq!(j["verdict"], "clean", "{j:#}");
        let t = &j["threads"][0];
        assert_eq!(t["side"], "od", "{t:#}");
        let x = |k: &str| t[k].as_f64().unwrap();
        assert!((x("included_angle_deg") - 60.0).abs() < 0.05, "{t:#}");
        assert!((x("achieved_x") - 32.16).abs() < 2e-3, "{t:#}");
        assert!(
            (t["pass_depths_mm"][0].as_f64().unwrap() - 0.3).abs() < 1e-3,
            "{t:#}"
        );
        assert!(warnings(&j, "LS-RAPID-SCRAPE").is_empty(), "{j:#}");
        let stock = warnings(&j, "LS-STOCK");
        assert!(
            stock
                .iter()
                .any(|m| m.contains("T05") && m.contains("taken for a threading insert")),
            "{stock:?}"
        );
    }
}

/// Field run 7: a tool with no entry is taken for a threading insert of the angle its G76
/// states (P's last two digits), not always 60°: a 55° BSP-style thread by `G76 P010055`
/// reads 55°, and its pitch diameter is the 55° one's. A of 00 (straight infeed, any
/// insert) says nothing of the insert: 60°. A stated tool keeps its own angle.
#[test]
fn a_thread_tool_with_no_entry_takes_the_angle_its_g76_states() {
    let program = |a: &str| {
        format!("O0001\nG21 G99\nT0101\nG97 S800 M03\nG00 X32. Z5.\nG76 P0100{a} Q50 R0.05\nG76 X27.4 Z-22. P1300 Q400 F2.\nG00 X150. Z100.\nM30\n")
    };
    let angle = |j: &serde_json::Value| j["threads"][0]["included_angle_deg"].as_f64().unwrap();
    let j = run_no_entry(&program("55"), None, &["--stock", "30x40"]);
    assert!((angle(&j) - 55.0).abs() < 0.05, "{:#}", j["threads"]);
    let stock = warnings(&j, "LS-STOCK");
    assert!(
        stock.iter().any(|m| m.contains("threading 55°")),
        "{stock:?}"
    );
    let j = run_no_entry(&program("00"), None, &["--stock", "30x40"]);
    assert!((angle(&j) - 60.0).abs() < 0.05, "{:#}", j["threads"]);
    let stated = "[[tool]]\nt = 1\nkind = \"threading\"\nangle = 60\ntip_flat = 0.0\n";
    let j = run_no_entry(&program("55"), Some(stated), &["--stock", "30x40"]);
    assert!((angle(&j) - 60.0).abs() < 0.05, "{:#}", j["threads"]);
}

/// The side is the one the passes come in from: an internal M30 × 2 by G76 in a Φ27.9
/// bore with no table is an ID insert (the wall stays, the thread reaches its major Φ30),
/// not the OD guess that warned "state T04 with side = id"; a tool with no entry that
/// also turns keeps the 55° turning default.
#[test]
fn a_thread_tool_with_no_entry_takes_the_side_its_passes_come_from() {
    let j = run_no_entry(M30_ID, None, &["--stock", "40x40", "--bore", "27.9"]);
    assert_eq!(j["verdict"], "clean", "{j:#}");
    let t = &j["threads"][0];
    assert_eq!(t["side"], "id", "{t:#}");
    assert!(
        (t["achieved_x"].as_f64().unwrap() - 30.0).abs() < 2e-3,
        "{t:#}"
    );
    assert!(warnings(&j, "LS-ASSUMED-TOOL").is_empty(), "{j:#}");
    let turned_too = M30_ID.replace("G00 X26 Z50", "G00 X26 Z50\nG01 Z40 F0.2");
    let j = run_no_entry(&turned_too, None, &["--stock", "40x40", "--bore", "27.9"]);
    let stock = warnings(&j, "LS-STOCK");
    assert!(
        stock.iter().any(|m| m.contains("turning D 55°")),
        "{stock:?}"
    );
}

/// Field run 4 (4): a FANUC two-block G76 has no start angle, so a two-start thread is cut
/// as two G76 run from start points half a lead apart (Z5, then Z6.5 for lead 3). Each
/// pass's helix is where its stamps fall modulo the lead: two starts, pitch 1.5, the 60°
/// of the tool (it read one start at 98.2°, the two grooves of a lead taken for one), and
/// the second start's first pass 0.25 deep from the crest (it read 0.67, from the first
/// start's root).
#[test]
fn two_g76_half_a_lead_apart_are_two_starts() {
    let cycle = "G76 P010060 Q50 R0.02\nG76 X18.16 Z-20. P920 Q250 F3.0\n";
    let program = format!(
        "G99 M03 S600 T0404\nG00 X22. Z5.\n{cycle}G00 X22. Z6.5\n{cycle}G00 X50. Z50.\nM30\n"
    );
    let (code, j) = run_json(&program, &[]);
    assert_eq!(code, 0, "{j:#}");
    let t = &j["threads"];
    assert_eq!(t.as_array().unwrap().len(), 1, "{t:#}");
    let t = &t[0];
    assert_eq!(t["starts"], 2, "{t:#}");
    assert!(
        (t["included_angle_deg"].as_f64().unwrap() - 60.0).abs() < 0.05,
        "{t:#}"
    );
    // sharp 60° V to the root r9.08, pitch 1.5: d2 = 2 (9.08 + 0.75 / (2 tan 30°))
    let d2 = 2.0 * (9.08 + 0.75 / (2.0 * 30f64.to_radians().tan()));
    assert!(
        (t["pitch_diameter"].as_f64().unwrap() - d2).abs() < 2e-3,
        "{t:#}"
    );
    let depths = t["pass_depths_mm"].as_array().unwrap();
    let half = depths.len() / 2;
    assert_eq!(depths.len(), 2 * half, "{t:#}");
    for k in 0..half {
        let (a, b) = (
            depths[k].as_f64().unwrap(),
            depths[half + k].as_f64().unwrap(),
        );
        assert!((a - b).abs() < 1e-6, "pass {k}: {a} vs {b}: {t:#}");
    }
    assert!((depths[0].as_f64().unwrap() - 0.25).abs() < 1e-3, "{t:#}");
}

/// Field run 2 (N2) with the fifth run's binary: a sleeve with no tool table, its bore
/// roughed and finished by G71/G70 (T03, the default insert) and then an internal
/// M30 × 1.5 by G76 (T04, taken for an ID threading insert). The default insert's wall cut
/// is a possible gouge; it was certain (GOUGE, exit 1) because the G70's path along the
/// Ø28.4 bore ran through the thread's band, where no intent speaks and the "part" is
/// the blank: the reference point counts only where it enters what an intent keeps.
#[test]
fn an_inside_thread_band_is_no_place_the_reference_point_enters_the_part() {
    let program = "O0301\nG18 G21 G40 G80 G99\nT0303\nG96 S150 M03\nG00 X18. Z2.\nG71 U1.5 R0.5\nG71 P30 Q40 U-0.4 W0.1 F0.2\nN30 G00 X32.\nG01 X28.4 Z-0.8 F0.1\nZ-25.\nN40 X18.\nG70 P30 Q40\nG00 Z5.\nG28 U0. W0.\nT0404\nG97 S700 M03\nG00 X26. Z5.\nG76 P010060 Q50 R0.05\nG76 X30. Z-22. P812 Q250 F1.5\nG00 Z10.\nG28 U0. W0.\nM30\n";
    let j = run_no_entry(program, None, &["--stock", "50x40", "--bore", "20"]);
    assert_eq!(j["verdict"], "clean", "{j:#}");
    let gouges = j["gouges"].as_array().unwrap();
    assert!(
        gouges.iter().all(|g| g["assumed_tool"] == true),
        "{gouges:#?}"
    );
    assert_eq!(j["threads"][0]["side"], "id", "{j:#}");
    // T03 roughs and finishes the bore only: a boring bar (tip 2), not the OD default that
    // cut the wall away on the wrong side of its ID G71 (372 mm² removed; the bore Ø20 →
    // Ø28.4 over 25 mm and the thread are about 110)
    let removed = j["removed_area_mm2"].as_f64().unwrap();
    assert!(removed < 115.0, "{removed}");
    assert!(gouges.is_empty(), "{gouges:#?}");
    let stock = warnings(&j, "LS-STOCK");
    assert!(
        stock
            .iter()
            .any(|m| m.contains("T03") && m.contains("boring bar")),
        "{stock:?}"
    );
}

/// Field run 5 (D), in the style of a CAM job sheet's "clip thread" operation: an
/// M30 × 2 by G92 to X27.6, then a 3 mm blade chamfers the first turn down to X26. The
/// thread is measured as it cut itself, once its last pass ran: X27.6 reached, no depth
/// error, 60°. It read "0.800 mm too deep (X26.000 reached)", the blade's chamfer taken
/// for the thread's depth, and a thread too deep fails the run: GOUGE with 0 gouges.
#[test]
fn a_thread_deburred_later_is_measured_as_it_cut_itself() {
    let table = "[[tool]]\nt = 7\nkind = \"threading\"\n[[tool]]\nt = 9\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"-z\"\nshank_dir = \"+x\"\nreach = 20.0\n";
    let program = "O5010\nG21 G40 G99\nT0707\nG97 S600 M03\nG00 X32. Z5.\nG92 X29.3 Z-20. F2.\nX28.8\nX28.4\nX28.0\nX27.7\nX27.6\nG00 X50. Z50.\nT0909\nG97 S600 M03\nG00 X32. Z2.\nG01 X26. Z-1. F0.05\nG00 X32.\nG00 X50. Z50.\nM30\n";
    let j = run_no_entry(program, Some(table), &["--stock", "30x40"]);
    assert_eq!(j["verdict"], "clean", "{j:#}");
    let t = &j["threads"][0];
    let x = |k: &str| t[k].as_f64().unwrap();
    assert!((x("achieved_x") - 27.6).abs() < 2e-3, "{t:#}");
    assert!(x("depth_error_mm").abs() < 1e-3, "{t:#}");
    assert!((x("included_angle_deg") - 60.0).abs() < 0.05, "{t:#}");
    assert!(warnings(&j, "LS-THREAD-DEPTH").is_empty(), "{j:#}");
    // a deburred first turn is no cut through the thread
    assert!(warnings(&j, "LS-THREAD-CUT").is_empty(), "{j:#}");
    // the same after 5 100 moves in the air (review: past 5 000 moves the stock after the
    // thread was not kept, and the deburred thread was "0.8 too deep" again)
    let air: String = (0..5_100)
        .map(|k| format!("G00 X{}. Z20.\n", 40 + k % 2))
        .collect();
    let long = program.replacen("T0707\n", &format!("T0707\n{air}"), 1);
    let j = run_no_entry(&long, Some(table), &["--stock", "30x40"]);
    assert_eq!(j["verdict"], "clean", "{:#}", j["threads"]);
    assert!(j["segments"].as_u64().unwrap() > 5_000);
}

/// A thread cut 0.2 too deep against its drawing fails the run as a gouge does; the verdict
/// line names it (it read "GOUGE … 0 gouge(s)", a contradiction; field run 5, D).
#[test]
fn a_thread_too_deep_is_named_on_the_verdict_line() {
    let (dir, target) = common::temp_program(
        "m20.toml",
        b"start = [0.0, 0.0]\npath = [\n  { to = [0.0, 18.05] },\n  { to = [-25.0, 18.05] },\n  { to = [-25.0, 20.0] },\n  { to = [-40.0, 20.0] },\n  { to = [-40.0, 0.0] },\n]\n",
    );
    let (pdir, path) = common::temp_program(
        "deep.nc",
        M20.replace("X18.05 Z-25", "X17.65 Z-25").as_bytes(),
    );
    let _keep = (dir, pdir);
    let tools = common::asset("tools/thread60.toml");
    let out = common::latsim(&[
        "run",
        path.to_str().unwrap(),
        "--stock",
        "20x40",
        "--tools",
        tools.to_str().unwrap(),
        "--target",
        target.to_str().unwrap(),
        "--reports",
        "none",
        "--quiet",
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    let line = out.stdout.lines().last().unwrap_or_default();
    assert!(
        line.contains("GOUGE") && line.ends_with("0 gouge(s), 1 thread(s) too deep"),
        "{line}"
    );
}

/// Field run 5 (F): under G20 a FANUC G76's P and Q are in the inch increment, 0.0001 in
/// (cycles.md: least input increments), not 0.001 mm: `P0479 Q0100` is k = 0.0479 in and
/// Δd = 0.0100 in, so a 1/2-13 to X0.4056 starts at X0.4056 + 2 (0.0479 − 0.0100) =
/// 0.4814 in (12.22756 mm). It started at X0.4056 + 2 (0.479 − 0.100) mm, 0.758 mm higher,
/// with a 0.82 mm first chip; a G75's P and Q the same.
#[test]
fn inch_g76_p_and_q_are_in_the_inch_increment() {
    let text = "G20 G99 M03 S800 T0303\nG00 X0.6 Z0.25\nG76 P010060 Q0020 R0.001\nG76 X0.4056 Z-1.0 P0479 Q0100 F0.076923\nG00 X0.8\nM30\n";
    let program = gcode::parse(text).unwrap();
    let machine = expander::Machine::for_control(expander::Control::FanucA);
    let tp = expander::expand(&program, &machine, &Default::default());
    assert!(tp.alarms.is_empty(), "{:?}", tp.alarms);
    let first = tp
        .segments
        .iter()
        .find(|s| s.motion == expander::Motion::Thread)
        .unwrap();
    assert!(
        (2.0 * first.from.r - 0.4814 * 25.4).abs() < 1e-6,
        "{first:?}"
    );
    let deepest = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread)
        .map(|s| 2.0 * s.to.r)
        .fold(f64::INFINITY, f64::min);
    assert!((deepest - 0.4056 * 25.4).abs() < 1e-6, "{deepest}");
}

/// Review of the threading insert taken by use: a rear-post tool with no entry threads at
/// negative X (M04), its passes entered from X-32, farther from the axis: an OD insert, as
/// at +X (5.131 mm², the corpus `thread-tool-not-in-table` mirrored). The side was read from
/// the signed X: "from inside", an ID insert, whose body hollowed the bar in a certain crash.
#[test]
fn a_rear_post_thread_tool_with_no_entry_is_an_od_insert() {
    let program = "O6010\nG21 G40 G99\nT0505\nG97 S900 M04\nG00 X-32. Z3.\nG92 X-29.4 Z-15. F1.5\nX-29.\nX-28.7\nX-28.45\nX-28.25\nX-28.16\nG00 X-40.\nM30\n";
    let j = run_no_entry(program, None, &["--stock", "30x40"]);
    assert_eq!(j["verdict"], "clean", "{j:#}");
    let removed = j["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - 5.131).abs() < 0.005, "{removed}");
    let stock = warnings(&j, "LS-STOCK");
    assert!(
        stock.iter().any(|m| m.contains("threading 60°")),
        "{stock:?}"
    );
}

/// Review of the thread starts: ten starts by a GSK `G92 … L10` (start angles 36° apart,
/// 0.1 of the lead) and six by six FANUC G76 run a pitch apart (start points 1/6 of the
/// lead apart, each spread by its own flank infeed) are ten and six starts. The first read
/// one start (the places within a fixed 0.125 of the lead), the second one start at 147.8°.
#[test]
fn many_starts_by_start_angle_or_by_start_point() {
    let l10 = "G21 G99 M03 S200 T0404\nG00 X24. Z5.\nG92 X19.4 Z-20. F10 L10\nX19.0\nX18.8\nG00 X50. Z50.\nM30\n";
    let (code, j) = run_json(l10, &["--control", "gsk980"]);
    assert_eq!(code, 0, "{j:#}");
    assert_eq!(j["threads"][0]["starts"], 10, "{:#}", j["threads"]);
    let cycle = "G76 P010060 Q30 R0.02\nG76 X18.8 Z-20. P600 Q150 F6\n";
    let six: String = (0..6)
        .map(|k| format!("G00 X24. Z{}.\n{cycle}", 5 + k))
        .collect();
    let (code, j) = run_json(
        &format!("G21 G99 M03 S300 T0404\n{six}G00 X50. Z50.\nM30\n"),
        &["--control", "fanuc-a"],
    );
    assert_eq!(code, 0, "{j:#}");
    let t = &j["threads"][0];
    assert_eq!(t["starts"], 6, "{t:#}");
    assert!(
        (t["included_angle_deg"].as_f64().unwrap() - 60.0).abs() < 0.05,
        "{t:#}"
    );
}

/// Review: measured as it cut itself, a thread that a later tool turns 0.3 below its root
/// over four leads (T01 at X27 from Z2 to Z-8 after an M30 × 2 to X27.6) was CLEAN with no
/// word of it (no intent speaks within a thread's band): the warning LS-THREAD-CUT at the
/// turning line names the stretch cut through.
#[test]
fn a_later_cut_through_a_thread_is_warned() {
    let program = "O5020\nG21 G40 G99\nT0707\nG97 S600 M03\nG00 X32. Z5.\nG92 X29.3 Z-20. F2.\nX28.8\nX28.4\nX28.0\nX27.7\nX27.6\nG00 X50. Z50.\nT0101\nG96 S180 M03\nG00 X27. Z2.\nG01 Z-8. F0.2\nX32.\nG00 X50. Z50.\nM30\n";
    let table = "[[tool]]\nt = 7\nkind = \"threading\"\n[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let j = run_no_entry(program, Some(table), &["--stock", "30x40"]);
    let cut: Vec<&serde_json::Value> = j["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == "LS-THREAD-CUT")
        .collect();
    assert_eq!(cut.len(), 1, "{j:#}");
    assert_eq!(cut[0]["line"], 16, "{cut:?}");
    assert!(
        cut[0]["message"].as_str().unwrap().contains("to Z-7.7"),
        "{cut:?}"
    );
}

/// Review: with no tool table and no T word (tool 0), a program that only threads is cut
/// by a 60° threading insert too (it read 96.3°, the 55° default's form).
#[test]
fn a_thread_with_no_t_word_and_no_table_is_cut_by_a_threading_insert() {
    let program = "G21 G99 M03 S500\nG00 X32. Z3.\nG92 X29.4 Z-15. F1.5\nX29.\nX28.7\nX28.45\nX28.25\nX28.16\nG00 X40.\nM30\n";
    let j = run_no_entry(program, None, &["--stock", "30x40"]);
    let angle = j["threads"][0]["included_angle_deg"].as_f64().unwrap();
    assert!((angle - 60.0).abs() < 0.05, "{angle}");
}

/// Field run 6 (B), in a gang-tool lathe's style: every tool behind the centre (X
/// negative), an M20 × 1.5 by G92 with a stated OD threading insert. Its passes read "deeper
/// outward" at signed X, the alarm LS-THREAD-SIDE, and "18.780 mm too shallow (X-19.400
/// expected)": the section sees them folded about the axis, an OD thread to X18.16, 60°.
#[test]
fn a_thread_behind_the_centre_is_measured_in_the_section() {
    let table = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"DNMG 110404\"\ntip = 3\nentering_angle = 93\n[[tool]]\nt = 4\nkind = \"threading\"\nangle = 60\nside = \"od\"\n";
    let program = "O7604\nG21 G99 G40\nT0101\nG96 S180 M03\nG0 X-22. Z2.\nG1 X-19.8 F.2\nZ-25.\nX-22.\nG0 Z5.\nT0404\nG97 S800 M03\nG0 X-22. Z4.\nG92 X-19.4 Z-20. F1.5\nX-18.9\nX-18.5\nX-18.25\nX-18.16\nG0 X-30. Z50.\nM30\n";
    let j = run_no_entry(program, Some(table), &["--stock", "25x40"]);
    assert_eq!(j["verdict"], "clean", "{j:#}");
    let t = &j["threads"][0];
    let x = |k: &str| t[k].as_f64().unwrap();
    assert!((x("achieved_x") - 18.16).abs() < 2e-3, "{t:#}");
    assert!((x("included_angle_deg") - 60.0).abs() < 0.05, "{t:#}");
    assert_eq!(t["side"], "od", "{t:#}");
}
