//! The gouge regression suite: programs in assets/ with their expected verdicts.

mod common;
use common::*;

fn run_json(args: &[&str]) -> (Out, serde_json::Value) {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("r.json");
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--json", json.to_str().unwrap(), "--quiet"]);
    let out = latsim(&all);
    let v = std::fs::read_to_string(&json)
        .map(|t| serde_json::from_str(&t).unwrap())
        .unwrap_or(serde_json::Value::Null);
    (out, v)
}

fn a(p: &str) -> String {
    asset(p).to_str().unwrap().to_string()
}

/// `program` run as `name` under FANUC system A on a `stock` bar with the tool table `tools`.
fn run_fanuc(name: &str, program: &str, tools: &str, stock: &str) -> (Out, serde_json::Value) {
    run_program(name, program, "fanuc-a", Some(tools), &["--stock", stock])
}

/// `program` run as `name` under `control` on the blank `blank` (`--stock` and such) with
/// the tool table `tools` (none: no table).
fn run_program(
    name: &str,
    program: &str,
    control: &str,
    tools: Option<&str>,
    blank: &[&str],
) -> (Out, serde_json::Value) {
    let (dir, path) = temp_program(name, program.as_bytes());
    let table = dir.path().join("tools.toml");
    let mut args = vec!["run", path.to_str().unwrap(), "--control", control];
    args.extend(blank);
    if let Some(tools) = tools {
        std::fs::write(&table, tools).unwrap();
        args.extend(["--tools", table.to_str().unwrap()]);
    }
    run_json(&args)
}

/// The one gouge of a run that fails on it (exit 1), at `line`, `depth` mm deep (within
/// the tolerance given beside it).
fn the_gouge<'a>(
    out: &Out,
    v: &'a serde_json::Value,
    line: u32,
    (depth, tol): (f64, f64),
) -> &'a serde_json::Value {
    assert_eq!(out.code, 1, "{}", out.stderr);
    let gouges = v["gouges"].as_array().unwrap();
    assert_eq!(gouges.len(), 1, "{gouges:#?}");
    let gouge = &gouges[0];
    assert_eq!(gouge["line"], line, "{gouge:#}");
    let found = gouge["depth_mm"].as_f64().unwrap();
    assert!((found - depth).abs() < tol, "{gouge:#}");
    gouge
}

/// That a run is clean: exit 0, no crash, no gouge.
fn assert_clean(out: &Out, v: &serde_json::Value) {
    assert_eq!(
        (out.code, v["verdict"].as_str()),
        (0, Some("clean")),
        "{:#} {:#}",
        v["crashes"],
        v["gouges"]
    );
}

/// The report's warnings of this code.
fn warnings<'a>(v: &'a serde_json::Value, code: &str) -> Vec<&'a serde_json::Value> {
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == code)
        .collect()
}

/// O0008 with the blade referenced at the wrong corner: the groove lands a blade width
/// (4 mm) toward +Z — a gouge along the 45° flank and a leftover along the 30° flank, each
/// 4 mm × 10 mm = 40 mm², 4·sin 45° and 4·sin 30° deep.
#[test]
fn g75_1_wrong_reference_corner_is_a_gouge_and_a_leftover() {
    let dir = tempfile::tempdir().unwrap();
    let wrong = dir.path().join("wrong.toml");
    std::fs::write(
        &wrong,
        read(&asset("tools/seed000-groove4.toml"))
            .replace("width_dir = \"-z\"", "width_dir = \"+z\""),
    )
    .unwrap();
    let (out, v) = run_json(&[
        "run",
        &a("programs/O0008.nc"),
        "--stock",
        "50x60",
        "--stock-z",
        "40",
        "--tools",
        wrong.to_str().unwrap(),
        "--machine",
        &a("machines/gsk980tdi-isc.toml"),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(v["verdict"], "gouge");
    let d = &v["deviation"];
    let f = |k: &str| d[k].as_f64().unwrap();
    assert!((f("overcut_area_mm2") - 40.0).abs() < 0.01, "{d}");
    assert!((f("undercut_area_mm2") - 40.0).abs() < 0.01, "{d}");
    assert!(
        (f("max_overcut_mm") - 4.0 * 45f64.to_radians().sin()).abs() < 0.01,
        "{d}"
    );
    assert!(
        (f("max_undercut_mm") - 4.0 * 30f64.to_radians().sin()).abs() < 0.01,
        "{d}"
    );
    assert_eq!(v["gouges"][0]["line"], 4);
    assert!(v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w["code"] == "LS-G75.1-CORNER"));
}

#[test]
fn g75_1_right_reference_corner_is_clean() {
    let (out, v) = run_json(&[
        "run",
        &a("programs/O0008.nc"),
        "--stock",
        "50x60",
        "--stock-z",
        "40",
        "--tools",
        &a("tools/seed000-groove4.toml"),
        "--machine",
        &a("machines/gsk980tdi-isc.toml"),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(v["verdict"], "clean");
    assert_eq!(v["deviation"]["overcut_area_mm2"], 0.0);
    assert_eq!(v["deviation"]["undercut_area_mm2"], 0.0);
    // the groove is handed to the report for its detail view: P1 (Z30, Φ50) first
    let g = &v["grooves"][0];
    assert_eq!(g["line"], 4);
    assert_eq!(g["ring"][0], serde_json::json!([30.0, 50.0]), "{g}");
    assert!(g["ring"].as_array().unwrap().len() >= 4);
}

/// A 55° insert (trailing edge at 32°) descending a 45° cone: its flank gouges the cone,
/// 11 mm of edge × sin(45° − 32°) = 2.474 mm deep, made by the descending move (line 7).
#[test]
fn steep_descent_with_a_55_degree_insert_gouges_at_its_line() {
    let (out, v) = run_json(&[
        "run",
        &a("programs/gouge-55deg-slope.nc"),
        "--stock",
        "40x30",
        "--tools",
        &a("tools/d55-sharp.toml"),
        "--target",
        &a("targets/cone45-valley.toml"),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(v["verdict"], "gouge");
    let g = &v["gouges"].as_array().unwrap()[0];
    assert_eq!(g["line"], 7, "{g}");
    let depth = g["depth_mm"].as_f64().unwrap();
    let hand = 11.0 * 13f64.to_radians().sin();
    eprintln!("55° insert on a 45° cone: gouge {depth:.4} mm deep, hand computation {hand:.4} mm");
    assert!(
        (depth - hand).abs() <= 0.1 * hand,
        "depth {depth}, hand {hand}"
    );
}

/// The same cone with a 35° insert (trailing edge at 52°): no gouge.
#[test]
fn the_same_descent_with_a_35_degree_insert_is_clean() {
    let (out, v) = run_json(&[
        "run",
        &a("programs/gouge-55deg-slope.nc"),
        "--stock",
        "40x30",
        "--tools",
        &a("tools/v35-sharp.toml"),
        "--target",
        &a("targets/cone45-valley.toml"),
    ]);
    assert_eq!(v["gouges"].as_array().unwrap().len(), 0, "{}", out.stderr);
    assert_ne!(v["verdict"], "gouge");
}

/// A parting blade's rapid into the stock: a crash at its line.
#[test]
fn parting_blade_rapid_into_stock_is_a_crash_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let prog = dir.path().join("part.nc");
    std::fs::write(&prog, "O0300;\nG99 M03 S500 T0202;\nG00 X45. Z-20.;\nG00 X30.;\nG01 X0. F0.05;\nG00 X45.;\nM30;\n").unwrap();
    let (out, v) = run_json(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "40x50",
        "--tools",
        &a("tools/seed002-groove3.toml"),
        "--tool",
        "2",
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(v["verdict"], "crash");
    assert_eq!(v["crashes"][0]["line"], 4, "{}", v["crashes"]);
}

/// The finishing shape of G73/G70 is the intent: after G73 alone the leftover is the
/// allowance (Δu/2 = 0.25 in X, Δw = 0.3 in Z: at most √(0.25² + 0.3²) = 0.39 mm at a
/// corner), after G70 the part is clean.
#[test]
fn o0006_finishing_shape_is_the_intent() {
    let (out, v) = run_json(&[
        "run",
        &a("programs/O0006-rough.nc"),
        "--stock-file",
        &a("blanks/o0006-casting.toml"),
        "--tools",
        &a("tools/v35-sharp.toml"),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let d = &v["deviation"];
    let under = d["max_undercut_mm"].as_f64().unwrap();
    assert!(under > 0.25 && under <= (0.25f64.hypot(0.3)) + 0.01, "{d}");
    assert_eq!(d["overcut_area_mm2"], 0.0);
    let (out, v) = run_json(&[
        "run",
        &a("programs/O0006.nc"),
        "--stock-file",
        &a("blanks/o0006-casting.toml"),
        "--tools",
        &a("tools/v35-sharp.toml"),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        v["deviation"]["undercut_area_mm2"], 0.0,
        "{}",
        v["deviation"]
    );
    assert_eq!(v["deviation"]["overcut_area_mm2"], 0.0);
}

/// A nose radius 1 on a concave R0.5 fillet under G42: interference alarm PS041 at the
/// fillet's line, and the report shows the overcut that ignoring it causes.
#[test]
fn tnrc_interference_is_an_alarm_and_its_overcut_is_shown() {
    let (out, v) = run_json(&[
        "run",
        &a("programs/tnrc-interference.nc"),
        "--stock",
        "40x30",
        "--tools",
        &a("tools/seed004-v35-r1.toml"),
        "--target",
        &a("targets/tnrc-interference.toml"),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(v["verdict"], "alarm");
    assert_eq!(
        (
            v["alarms"][0]["code"].as_str(),
            v["alarms"][0]["line"].as_u64()
        ),
        (Some("PS041"), Some(8))
    );
    let g = v["gouges"].as_array().unwrap();
    assert!(
        !g.is_empty() && g[0]["depth_mm"].as_f64().unwrap() > 0.1,
        "{g:?}"
    );
}

/// A contour cut under G41/G42 is an intended shape: seed 004 with G42 and a r1 nose is
/// clean but for the nose's fillet in the inside corner at Z−35, a leftover as high as the
/// 0.043 mm step (Φ35.914 to the Φ36 bar).
#[test]
fn a_compensated_contour_is_the_intent() {
    let (out, v) = run_json(&[
        "run",
        &a("programs/tnrc-seed004-rough.nc"),
        "--stock",
        "36x40",
        "--tools",
        &a("tools/seed004-v35-r1.toml"),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let d = &v["deviation"];
    assert_eq!(d["overcut_area_mm2"], 0.0, "{d}");
    let under = d["max_undercut_mm"].as_f64().unwrap();
    assert!((under - (36.0 - 35.914) / 2.0).abs() < 0.002, "{d}");
}

/// The leftover detail view gives the depth the summary gives. Haas `inch-pin-g76`: the
/// r0.4 finishing nose leaves its fillet in the sharp inside corner at the Φ22.86 shoulder
/// (at most r(1 − 1/√2) = 0.117 mm from the corner's two edges, sampled on the chords).
/// The finishing shape's retract up that wall is no part of the profile, so a measure
/// against the drawn outline (which lacks the wall) said 0.397 mm, the fillet's height.
#[test]
fn the_leftover_detail_gives_the_summarys_depth() {
    let dir = tempfile::tempdir().unwrap();
    let (json, svg) = (dir.path().join("r.json"), dir.path().join("r.svg"));
    let out = latsim(&[
        "run",
        &a("corpus/haas/inch-pin-g76.nc"),
        "--control",
        "haas",
        "--stock",
        "25.4x60",
        "--tools",
        &a("corpus/tools/shop.toml"),
        "--json",
        json.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    let max = v["deviation"]["max_undercut_mm"].as_f64().unwrap();
    let hand = 0.4 * (1.0 - 1.0 / 2f64.sqrt());
    assert!(max <= hand + 1e-3 && max > hand - 0.01, "{max}");
    let svg = read(&svg);
    let title = svg
        .split("leftover up to ")
        .nth(1)
        .and_then(|t| t.split(" mm").next())
        .expect("a leftover detail view");
    let shown: f64 = title.parse().unwrap();
    assert!(
        (shown - max).abs() <= 0.0005,
        "detail says {title} mm, summary {max} mm"
    );
}

/// A Φ18 pin finished by G71 (T1) and G70 (T2), then an O-ring groove plunged 1.5 mm deep
/// with the 3 mm blade (T5): the groove is the later operation's own cut, not a gouge of
/// the finished diameter (**Interpretation**): clean, with one LS-LATER-CUT warning at the
/// plunge naming its 3 × 1.5 = 4.5 mm². The same plunge with the tool that finished the
/// diameter (T2) is judged: a gouge at its line; so is the plunge of a turning tool (T1),
/// which cuts no groove, hole or relief of its own.
#[test]
fn a_groove_cut_after_the_finish_by_another_tool_is_its_own() {
    let program = |groove_tool: &str| {
        format!(
            "O0311\nG40 G97 G99 G21\nT0101\nM03 S800\nG00 X32. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 G42 X12.\nG01 X18. Z-1. F0.1\nZ-25.\nX26.\nN20 X32.\nG40 G00 X100. Z100.\nT0202\nG00 X32. Z2.\nG70 P10 Q20\nG40 G00 X100. Z100.\n{groove_tool}\nG00 X20. Z-15.\nG01 X15. F0.05\nG00 X20.\nG00 X100. Z100.\nM30\n"
        )
    };
    let run = |groove_tool: &str| {
        let (dir, path) = temp_program("pin.nc", program(groove_tool).as_bytes());
        let _keep = dir;
        run_json(&[
            "run",
            path.to_str().unwrap(),
            "--stock",
            "30x50",
            "--tools",
            &a("corpus/tools/shop.toml"),
        ])
    };
    let (out, v) = run("T0505");
    assert_eq!(out.code, 0, "{v:#}");
    assert_eq!(v["verdict"], "clean", "{v:#}");
    let later: Vec<&serde_json::Value> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == "LS-LATER-CUT")
        .collect();
    assert_eq!(later.len(), 1, "{v:#}");
    assert_eq!(later[0]["line"], 20);
    let message = later[0]["message"].as_str().unwrap();
    assert!(
        message.starts_with("T05 cuts 4.500 mm² (1.500 mm deep"),
        "{message}"
    );
    let (out, v) = run("T0202");
    assert_eq!(out.code, 1, "{v:#}");
    assert_eq!(v["verdict"], "gouge", "{v:#}");
    assert!(
        v["gouges"]
            .as_array()
            .unwrap()
            .iter()
            .all(|g| g["line"] == 20),
        "{v:#}"
    );
    // a turning tool's plunge into the finished diameter is no feature of its own: a gouge
    let (out, v) = run("T0101");
    assert_eq!(out.code, 1, "{v:#}");
    assert_eq!(v["verdict"], "gouge", "{v:#}");
}

/// Face, G71/G70 to Φ20, a G76 thread, then a Φ8 drill 15 deep on the axis (a field
/// program's sequence): the hole is the drill's own cut whatever the bar's length. The
/// facing pass runs along the face above the hole, and its sweep met the hole only by the
/// booleans' rounding along that edge; on a 70 mm bar that rounding made it the hole's
/// maker, a 4 mm gouge at the facing line (on 60 mm it did not).
#[test]
fn a_hole_drilled_below_the_faced_end_is_the_drills_whatever_the_bar() {
    let program = "O0703\nG21 G40 G99\nT0101\nG50 S3000\nG96 S200 M03\nG00 X44. Z0.\nG01 X-1.6 F0.15\nG00 Z2.\nG00 X42.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.3\nN10 G00 X14.\nG01 X20. Z-1. F0.1\nZ-20.\nN20 X42.\nG70 P10 Q20\nG28 U0.\nG28 W0.\nT0404\nG97 S1200 M03\nG00 X22. Z5.\nG76 P010060 Q50 R0.05\nG76 X18.16 Z-17. P920 Q300 F1.5\nG00 X44.\nG28 U0.\nG28 W0.\nT0505\nG97 S1200 M03\nG00 X0. Z2.\nG74 R0.5\nG74 Z-15. Q3000 F0.08\nG00 Z5.\nG28 U0.\nG28 W0.\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 4\nkind = \"threading\"\nangle = 60\ntip_flat = 0.0\n[[tool]]\nt = 5\nkind = \"drill\"\ndiameter = 8.0\npoint_angle = 118\nreach = 60.0\n";
    for stock in ["40x60", "40x70"] {
        let (out, v) = run_fanuc("o0703.nc", program, tools, stock);
        assert_eq!(v["verdict"], "clean", "{stock}: {v:#}");
        assert_eq!(out.code, 0, "{stock}");
        // the OD contour states no core: the hole is not judged at all (field-rules §21;
        // it was noted LS-LATER-CUT before)
        assert!(warnings(&v, "LS-LATER-CUT").is_empty(), "{stock}: {v:#}");
        assert!(v["gouges"].as_array().unwrap().is_empty(), "{stock}: {v:#}");
    }
}

/// Field run 3 (a public brass bush: face, G71, G74 drill, G70): a hole drilled between a
/// G71 and its G70, or before the contour (face, centre drill, turn), is the drill's own
/// cut: the contour began with its G71, and an OD contour says nothing of the core under
/// it. Each was a certain 4 mm gouge "into the part". A turning tool's plunge along the
/// axis stays a gouge.
#[test]
fn a_hole_drilled_before_the_finish_is_the_drills() {
    let face = "G00 X44. Z0.\nG01 X-1.6 F0.15\nG00 Z2.\n";
    let drill =
        "T0303\nG97 S1500 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-25. Q5000 F0.1\nG00 Z5.\nG28 U0. W0.\n";
    let rough = "T0101\nG96 S200 M03\nG00 X44. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z-20.\nX30.\nZ-35.\nN20 X44.\nG28 U0. W0.\n";
    let finish = "T0202\nG96 S250 M03\nG00 X44. Z2.\nG70 P10 Q20 F0.08\nG28 U0. W0.\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"turning\"\ninsert = \"VBMT 160404\"\nholder = \"SVJBR 2525M16\"\n[[tool]]\nt = 3\nkind = \"drill\"\ndiameter = 8.0\n[[tool]]\nt = 4\nkind = \"turning\"\ninsert = \"D\"\nnose_radius = 0.4\ntip = 2\nentering_angle = 93\nedge = 11\n";
    let run = |name: &str, body: String| {
        let program =
            format!("O0106\nG21 G40 G99 G18\nG28 U0. W0.\nT0101\nG96 S200 M03\n{body}M30\n");
        let (out, v) = run_fanuc(name, &program, tools, "40x60");
        (out.code, v)
    };
    let later = |v: &serde_json::Value| warnings(v, "LS-LATER-CUT").len();
    for (name, body) in [
        (
            "rough-drill-finish.nc",
            format!("{face}{rough}{drill}{finish}"),
        ),
        (
            "drill-rough-finish.nc",
            format!("{face}{drill}{rough}{finish}"),
        ),
    ] {
        let (code, v) = run(name, body);
        assert_eq!(v["verdict"], "clean", "{name}: {v:#}");
        assert_eq!(code, 0, "{name}");
        // no stated surface meets the hole (field-rules §21): not judged, not noted
        assert_eq!(later(&v), 0, "{name}: {v:#}");
    }
    // a turning tool's plunge along the axis before the contour is no hole of its own: the
    // finishing V (T02) down the axis 10 mm takes its whole width out of the part
    let plunge = "T0202\nG97 S1500 M03\nG00 X0. Z3.\nG01 Z-10. F0.1\nG00 Z5.\nG28 U0. W0.\n";
    let (code, v) = run("plunge.nc", format!("{face}{plunge}{rough}{finish}"));
    assert_eq!(v["verdict"], "gouge", "{v:#}");
    assert_eq!(code, 1);
}

/// Field run 3: G71/G70 to a diameter ending at Z-40, then a part-off with a 3 mm blade
/// referenced at its left corner at Z-40: its slot is the blade's own cut (LS-LATER-CUT)
/// whatever the diameter. The finishing pass leaves the diameter 5·10⁻⁵ mm under size (the
/// nose's chords), a band joined to the slot; on Ø38.08, 38.1, 38.2 and 44.7 that band made
/// the G70's last move the slot's maker, a 9.55 mm gouge "into the part".
#[test]
fn a_part_off_at_the_shapes_end_is_the_blades_whatever_the_diameter() {
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 6\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\nreach = 25.0\n";
    for d in ["38.0", "38.08", "38.1", "38.2", "44.7"] {
        let program = format!("O0115\nG21 G40 G99 G18\nT0101\nG96 S200 M03\nG50 S3000\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z-20.\nX{d}\nZ-40.\nN20 X52.\nG70 P10 Q20 F0.1\nG28 U0. W0.\nT0606\nG96 S120 M03\nG00 X52. Z-40.\nG01 X8. F0.05\nG00 X52.\nG28 U0. W0.\nM30\n");
        let (out, v) = run_fanuc("partoff.nc", &program, tools, "50x70");
        assert_eq!(v["verdict"], "clean", "Ø{d}: {v:#}");
        assert_eq!(out.code, 0, "Ø{d}");
        assert!(
            warnings(&v, "LS-LATER-CUT").iter().any(|w| w["line"] == 19),
            "Ø{d}: {v:#}"
        );
    }
}

/// A Haas G71/G70 whose shape ends with the return to the start (`N20 G00 G40 Z2.54`,
/// docs/field-rules.md §3) and a W allowance: the G70's intended shape kept the return, and
/// its run back along the bar's diameter closed the part against the roughed stock, leaving
/// a band W (0.127 mm) wide through the part's core, from the axis to Φ12.7: a 0.81 mm²
/// leftover (field run: 18 of 33 Haas programs end their shapes so). Only the r0.8 nose's
/// fillet in the shoulder stays, 0.8² (1 − π/4) = 0.137 mm².
#[test]
fn a_haas_shape_return_leaves_no_band_through_the_core() {
    let program = "%\nO2007\nG00 G18 G21 G40 G99\nT0101\nG50 S2500\nG96 S900 M03\nG00 G54 X38.1 Z2.54\nG71 P10 Q20 U0.254 W0.127 D1.27 F0.25\nN10 G00 G42 X-1.575 Z2.54\nG01 Z0.\nX10.904\nX12.7 Z-0.898\nZ-53.264\nX38.1\nN20 G00 G40 Z2.54\nG70 P10 Q20 F0.2\nG00 Z2.54\nM30\n%\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let (out, v) = run_program(
        "o2007.nc",
        program,
        "haas",
        Some(tools),
        &["--stock", "38.1x101.6"],
    );
    assert_eq!(out.code, 0, "{v:#}");
    let leftovers = v["leftovers"].as_array().unwrap();
    let area: f64 = leftovers
        .iter()
        .map(|l| l["area_mm2"].as_f64().unwrap())
        .sum();
    assert!(
        (area - 0.137).abs() < 0.005,
        "{area} mm² left: {leftovers:#?}"
    );
}

/// Field run 4 (5e): a face cut 0.3 too deep before a G71/G70 shape whose chamfer starts at
/// X20 Z0 is a gouge 0.3 deep, 3.045 mm² (r 10 → 10.3 over 0.3), made by the programmed
/// path (the facing feed, line 11), whatever the bar's face stock: with 0.5 or 1 mm it read
/// 0.8 or 1.3 deep (measured from the bar's face), blamed on a nose "not compensated".
/// (With none the shape's start is read where the over-faced stock begins, as a CAM
/// lead-in extended to the bar's face is: no gouge; docs/field-rules.md §15.)
#[test]
fn a_face_cut_too_deep_is_as_deep_as_it_cuts_below_the_shape() {
    let program = common::asset("corpus/fanuc-a/overfaced-with-face-stock.nc");
    let tools = common::asset("corpus/tools/shop.toml");
    for stock_z in ["0.5", "1"] {
        let (out, v) = run_json(&[
            "run",
            program.to_str().unwrap(),
            "--control",
            "fanuc-a",
            "--stock",
            "40x50",
            "--stock-z",
            stock_z,
            "--tools",
            tools.to_str().unwrap(),
        ]);
        assert_eq!(out.code, 1, "stock-z {stock_z}: {v:#}");
        let g = v["gouges"].as_array().unwrap();
        assert_eq!(g.len(), 1, "stock-z {stock_z}: {g:#?}");
        assert_eq!(g[0]["line"], 11);
        assert!(
            (g[0]["depth_mm"].as_f64().unwrap() - 0.3).abs() < 1e-3,
            "{stock_z}: {g:#?}"
        );
        assert!(
            (g[0]["area_mm2"].as_f64().unwrap() - 3.045).abs() < 2e-3,
            "{stock_z}: {g:#?}"
        );
        assert_eq!(g[0]["cause"]["kind"], "program", "{stock_z}: {g:#?}");
    }
}

/// Field run 5 (C), in the style of a tooling maker's job sheet: a Ø40 pin turned by
/// G71/G70 to Z-16, then parted off at Z-13 by T09, which chamfers the back edge under G42
/// first; no tool table. The blade is the default insert, so what its outline cuts into
/// the pin is a possible gouge only (it was a certain 3.2 mm GOUGE: the part-off's own
/// G42 chamfer, which begins after the plunge, claimed the place); and the back chamfer's
/// intent speaks of the stock within its own Z span, not of the bar toward the chuck (it
/// drew a 118 mm² leftover band the length of the bar).
#[test]
fn a_part_off_chamfering_under_g42_with_no_table_is_clean() {
    let program = "O0519\nG21 G40 G99\nT0101\nG96 S200 M03\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X36.\nG01 Z0. F0.1\nX40. Z-2.\nZ-16.\nN20 X52.\nG70 P10 Q20\nG28 U0. W0.\nT0909\nG96 S120 M03\nG00 X52. Z-14.1\nG01 X50. F0.1\nX48. Z-13.\nX39.5\nX43.\nZ-12.3\nG42 X40.6\nX39.1 Z-13.\nX30.\nG00 G40 X52.\nG28 U0. W0.\nM30\n";
    let (out, v) = run_program(
        "partoff.nc",
        program,
        "fanuc-a",
        None,
        &["--stock", "50x40"],
    );
    assert_eq!(out.code, 0, "{v:#}");
    let gouges = v["gouges"].as_array().unwrap();
    assert!(
        gouges.iter().all(|g| g["assumed_tool"] == true),
        "{gouges:#?}"
    );
    let left: f64 = v["leftovers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["area_mm2"].as_f64().unwrap())
        .sum();
    assert!(left < 1.0, "{left}: {:#}", v["leftovers"]);
    // faced first by a G72 shape on a bar with 1.5 of face stock: the back face's part ends
    // at the finished part's front, not in the face stock (a certain 1.5 mm gouge at Z0)
    let faced = program.replacen(
        "G00 X52. Z2.\nG71",
        "G00 X52. Z2.\nG72 W1.2 R0.5\nG72 P1 Q2 U0.2 W0.3 F0.25\nN1 G00 Z0.\nG01 X-1.6 F0.1\nN2 Z2.\nG00 X52. Z2.\nG71",
        1,
    );
    assert_ne!(faced, program);
    let (out, v) = run_program(
        "partoff-faced.nc",
        &faced,
        "fanuc-a",
        None,
        &["--stock", "50x40", "--stock-z", "1.5"],
    );
    assert_eq!(out.code, 0, "{:#}", v["gouges"]);
    let gouges = v["gouges"].as_array().unwrap();
    assert!(
        gouges.iter().all(|g| g["assumed_tool"] == true),
        "{gouges:#?}"
    );
}

/// Field run 6 (A): a bush, its OD by G71/G70 started on the bar (X50) with the shape's
/// exit above it (`N20 X52.`), then its bore by G71/G70. The OD shape was read as a face
/// (the start point below the shape's top), which kept nothing of the OD: the OD's whole
/// removal was a certain 3 mm gouge. The side is the shape's first move's: CLEAN.
#[test]
fn an_od_shape_leaving_above_its_start_is_still_an_od_shape() {
    let program = "O0601\nG21 G99\nT0101\nG97 S1000 M03\nG0 X50. Z2.\nG71 U2. R.5\nG71 P10 Q20 U.4 W.1 F.25\nN10 G0 X44.\nG1 Z-30.\nN20 X52.\nG70 P10 Q20 F.1\nG0 X100. Z100.\nT0303\nG97 S900 M03\nG0 X16. Z2.\nG71 U1. R.5\nG71 P30 Q40 U-.3 W.1 F.2\nN30 G0 X24.\nG1 Z-30.\nN40 X16.\nG70 P30 Q40 F.1\nG0 Z2.\nX100. Z100.\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DNMG 110404\"\ntip = 2\nentering_angle = 93\n";
    let (out, v) = run_program(
        "bush.nc",
        program,
        "fanuc-a",
        Some(tools),
        &["--stock", "50x60", "--bore", "18"],
    );
    assert_eq!(out.code, 0, "{:#}", v["gouges"]);
    assert!(
        v["gouges"].as_array().unwrap().is_empty(),
        "{:#}",
        v["gouges"]
    );
}

/// Field run 7 (A), the standard shop bush: the OD turned by G90 (no contour states it),
/// the bore by G71/G70 on a tube Φ40 / Φ20. The bore contour states the bore, not the OD:
/// the G90's 2.2 mm was a certain gouge of 48.3 mm² (with or without a tool table) as soon
/// as the bore had a contour (docs/field-rules.md §21). A dig 0.8 mm past the bore's own
/// surface after the G70 is still a gouge, 0.8 deep, at its line.
#[test]
fn a_bore_contour_does_not_state_the_od() {
    let bush = "O7002 (BUSH - OD BY G90, ID BY G71/G70)\nG21 G40 G99\nT0101\nG96 S200 M03\nG00 X42. Z2.\nG90 X38. Z-22. F0.2\nX36.4\nX35.6 F0.1\nG00 X80. Z50.\nT0303\nG96 S140 M03\nG00 X18. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U-0.3 W0.05 F0.15\nN10 G00 X24.\nG01 Z0. F0.08\nX22.4 Z-0.8\nZ-22.\nN20 X18.\nG70 P10 Q20\nG00 Z50.\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DCMT 070204\"\ntip = 2\nentering_angle = 93\nshank = 16.0\n";
    let run = |program: &str| {
        let blank = ["--stock", "40x30", "--bore", "20"];
        let (out, v) = run_program("bush.nc", program, "fanuc-a", Some(tools), &blank);
        (out.code, v)
    };
    let (code, v) = run(bush);
    assert_eq!(
        (code, v["verdict"].as_str()),
        (0, Some("clean")),
        "{:#}",
        v["gouges"]
    );
    // a dig into the bore's wall after the finish: the bore contour's own surface
    let dig = bush.replace(
        "G70 P10 Q20\nG00 Z50.\n",
        "G70 P10 Q20\nG00 X20. Z-10.\nG01 X24. F0.05\nX20.\nG00 Z50.\n",
    );
    let (code, v) = run(&dig);
    assert_eq!(code, 1, "{v:#}");
    let gouges = v["gouges"].as_array().unwrap();
    assert_eq!(gouges.len(), 1, "{gouges:#?}");
    assert_eq!(gouges[0]["line"], 22, "{gouges:#?}");
    let depth = gouges[0]["depth_mm"].as_f64().unwrap();
    assert!((depth - 0.8).abs() < 0.01, "{gouges:#?}");
}

/// Field run 8 (B, A): what a later blade cuts of part material that is gone is judged
/// apart from the rest. A skim 0.4 mm under the finished Φ29.8 (G01 Z-20 at X29), then a
/// relief groove by the 3 mm blade at Z-22: the skim is a gouge 0.4 deep at its own line (as
/// without the groove), the groove the blade's own cut (LS-LATER-CUT, 1.9 deep); judged as
/// one region it was a 1.9 mm gouge at the groove's bottom with no cause. And a bush (OD by
/// G90, bore by G71/G70) parted off into its bore: the slot joined the G90's OD, which no
/// contour states, to the bore contour; it was a certain 3 mm gouge at the G90.
#[test]
fn a_later_blade_cut_is_judged_apart_from_the_gouge_beside_it() {
    let skim = "O0005 (SKIM PASS 0.4 UNDER 29.8, THEN A RELIEF GROOVE)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X48. Z2.\nG71 U2. R0.5\nG71 P100 Q200 U0.4 W0.1 F0.25\nN100 G00 G42 X26.\nG01 Z0. F0.15\nX29.8 Z-1.9\nZ-25.\nX38.\nX40. Z-26.\nZ-45.\nN200 G01 G40 X48.\nG70 P100 Q200\nG00 X29. Z2.\nG01 Z-20. F0.1\nG00 X48.\nG00 X150. Z100.\nT0303\nG97 S600 M03\nG00 X42. Z-22.\nG01 X26. F0.05\nG00 X42.\nG00 X150. Z100.\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 3\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"-z\"\nshank_dir = \"+x\"\nreach = 15.0\n";
    let (out, v) = run_fanuc("skim.nc", skim, tools, "45x60");
    the_gouge(&out, &v, 18, (0.4, 1e-3));
    let later = warnings(&v, "LS-LATER-CUT");
    assert!(later.iter().any(|w| w["line"] == 24), "{later:#?}");

    let bush = "O0006 (BUSH - OD BY G90, BORE BY G71/G70, PART-OFF INTO THE BORE)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X44. Z2.\nG90 X39. Z-28. F0.25\nX36.\nG00 X150. Z100.\nT0303\nG96 S150 M03\nG00 X24. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U-0.3 W0.05 F0.15\nN10 G00 X30.\nG01 Z-27. F0.08\nN20 X24.\nG70 P10 Q20\nG00 Z5.\nG00 X150. Z100.\nT0505\nG97 S600 M03\nG00 X44. Z-26.\nG01 X28. F0.05\nG00 X44.\nG00 X150. Z100.\nM30\n";
    let bush_tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DCMT 070204\"\ntip = 2\nentering_angle = 93\nshank = 16.0\n[[tool]]\nt = 5\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\nreach = 20.0\n";
    let (out, v) = run_program(
        "bush.nc",
        bush,
        "fanuc-a",
        Some(bush_tools),
        &["--stock", "42x40", "--bore", "24"],
    );
    assert_clean(&out, &v);
    let later = warnings(&v, "LS-LATER-CUT");
    assert!(later.iter().any(|w| w["line"] == 23), "{later:#?}");
}

/// Field run 8 (I): a bore finished by hand under G42 with a boring bar whose tip the table
/// states (tip 2: the part lies outside its path). The control offsets the r0.4 nose into
/// the wall: the bore comes out Ø31.6 for Ø30, 0.8 deep over 27 mm (21.6 mm²). It was CLEAN
/// (the contour read as an OD one, its part inside the path), or a 3 mm gouge blamed on the
/// roughing G90. Now the gouge is at the finishing pass, 0.8 deep, with LS-COMP-SIDE at the
/// contour; the same program under G41 is clean.
#[test]
fn a_bore_finished_under_g42_is_a_gouge_at_the_finishing_pass() {
    let program = |code: &str| {
        format!("O0013 (BORE FINISH BY HAND)\nG21 G40 G99\nT0202\nG97 S600 M03\nG00 X0. Z5.\nG74 R1.\nG74 Z-35. Q5000 F0.1\nG00 X150. Z100.\nT0303\nG96 S150 M03\nG00 X24. Z2.\nG90 X27. Z-27. F0.2\nX29.\nG00 X32. Z2.\n{code} G00 X30. Z4.\nG01 Z0. F0.1\nZ-27.\nG40 G01 X24.\nG00 Z5.\nG00 X150. Z100.\nM30\n")
    };
    let tools = "[[tool]]\nt = 2\nkind = \"drill\"\ndiameter = 24.0\npoint_angle = 118\nreach = 80.0\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DCMT 070204\"\ntip = 2\nentering_angle = 93\nshank = 16.0\n";
    let (out, v) = run_fanuc("g42.nc", &program("G42"), tools, "40x40");
    let gouge = the_gouge(&out, &v, 16, (0.8, 1e-3));
    let area = gouge["area_mm2"].as_f64().unwrap();
    assert!((area - 21.6).abs() < 0.01, "{gouge:#}");
    let side = warnings(&v, "LS-COMP-SIDE");
    assert_eq!(side.len(), 1, "{:#}", v["warnings"]);
    assert_eq!(side[0]["line"], 16);
    let (out, v) = run_fanuc("g41.nc", &program("G41"), tools, "40x40");
    assert_clean(&out, &v);
    assert!(warnings(&v, "LS-COMP-SIDE").is_empty());
}

/// Field run 8 (C): a skim 0.4 mm under the finished Φ29.8 (G01 Z-20 at X29), then an
/// M30×2 thread cut into that diameter by G76. The skim is the turning tool's cut, judged
/// as before: a gouge 0.4 deep from the chamfer to Z-20, 7.2 mm², at the skim's line, as
/// without the thread. The thread's band (its passes up to the tool's full width) hid it:
/// the part, whose crest is 0.8 mm small, was CLEAN. The same skim at X29.8 is clean: the
/// thread's own teeth stay no gouge.
#[test]
fn a_skim_under_a_thread_crest_is_a_gouge_at_the_skim() {
    let program = |skim: &str| {
        format!("O0002 (M30X2 SHAFT: HAND SKIM, THEN THREAD)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X48. Z2.\nG71 U2. R0.5\nG71 P100 Q200 U0.4 W0.1 F0.25\nN100 G00 G42 X26.\nG01 Z0. F0.15\nX29.8 Z-1.9\nZ-25.\nX38.\nX40. Z-26.\nZ-45.\nN200 G01 G40 X48.\nG70 P100 Q200\nG00 X{skim} Z2.\nG01 Z-20. F0.1\nG00 X48.\nG00 X150. Z100.\nT0404\nG97 S600 M03\nG00 X32. Z5.\nG76 P020060 Q50 R0.05\nG76 X27.4 Z-22. P1300 Q400 F2.\nG00 X150. Z100.\nM30\n")
    };
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 4\nkind = \"threading\"\nangle = 60\ntip_flat = 0.0\n";
    let (out, v) = run_fanuc("crest.nc", &program("29."), tools, "45x60");
    let gouge = the_gouge(&out, &v, 18, (0.4, 1e-3));
    // 0.4 mm × 18.3 mm (from the chamfer's Φ29 at Z-1.7 to Z-20), less the skim's r0.8 nose's fillet at Z-20 and the chamfer's triangle
    let area = gouge["area_mm2"].as_f64().unwrap();
    assert!((area - 7.2).abs() < 0.05, "{gouge:#}");

    let (out, v) = run_fanuc("crest-ok.nc", &program("29.8"), tools, "45x60");
    assert_clean(&out, &v);
}

/// Field run 8 (J): an OD finished by hand under G42 whose start-up move ends on the part's
/// corner (`G00 X26. Z2.` / `G42 G01 X30. Z0.`): the r0.8 nose, offset along that move,
/// cuts 0.107 mm into the corner. The gouge is real; its cause named G41 (the code for the
/// start-up move's own direction), the opposite of the right code the program has. The
/// cause now names the start-up; the same contour started in the air is clean.
#[test]
fn a_nick_at_the_compensation_start_up_names_the_start_up() {
    let program = |start: &str| {
        format!("O0014 (OD FINISH BY HAND UNDER G42)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X44. Z2.\nG90 X41. Z-27. F0.2\nG00 X26. Z2.\n{start}Z-27.\nG40 G01 X44.\nG00 X150. Z100.\nM30\n")
    };
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let (out, v) = run_fanuc(
        "nick.nc",
        &program("G42 G01 X30. Z0. F0.1\n"),
        tools,
        "42x40",
    );
    let gouge = the_gouge(&out, &v, 8, (0.107, 0.002));
    let cause = gouge["cause"]["text"].as_str().unwrap();
    assert!(cause.contains("starts the compensation"), "{cause}");
    assert!(!cause.contains("G41"), "{cause}");

    let air = program("G42 G00 X30. Z2.\nG01 Z0. F0.1\n");
    let (out, v) = run_fanuc("air.nc", &air, tools, "42x40");
    assert_clean(&out, &v);

    // the same start-up inside a G71/G70 shape (review 1128g, #4: it still said G41)
    let g70 = "O0016 (OD G71/G70, COMPENSATION STARTED ONTO THE CORNER)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X44. Z2.\nG71 U1.5 R0.5\nG71 P100 Q200 U0.4 W0.1 F0.2\nN100 G00 X26.\nG42 G01 X30. Z0. F0.1\nZ-27.\nN200 G40 G01 X44.\nG70 P100 Q200\nG00 X150. Z100.\nM30\n";
    let (out, v) = run_fanuc("nick-g70.nc", g70, tools, "42x40");
    assert_eq!(out.code, 1, "{}", out.stderr);
    let gouges = v["gouges"].as_array().unwrap();
    assert_eq!(gouges.len(), 1, "{gouges:#?}");
    let cause = gouges[0]["cause"]["text"].as_str().unwrap();
    assert!(cause.contains("starts the compensation"), "{cause}");
}

/// Field run 7 (E), no table: T03 drills with G74 (taken for a Ø10 drill), T04 roughs a
/// stepped bore by G71 from X15 (taken for a boring bar; W0.05 left on the Ø18 shoulder's
/// face at Z-20), finishes by hand under G41 down that face to X18 and cancels with
/// `G40 G00 X15.` along Z-20. The programmed point runs along the face, through the 0.05 mm
/// the roughing left: a scrape by itself. The 0.149 mm crash is the outlines': the assumed
/// bar meeting the stock the assumed Ø10 drill left below the face (with a stated drill of
/// Ø12 or more there is no crash at all). It is possible: clean, exit 0. The same tool
/// rapiding on 2 mm into that face (`G00 Z-22.` at X15) stays certain: the point itself
/// goes 2 mm into the stock.
#[test]
fn a_rapid_grazing_a_face_guessed_tools_left_is_a_possible_crash() {
    let program = |exit: &str| {
        format!("O7006 (STEPPED BORE, NO TOOL TABLE)\nG21 G40 G99\nT0303\nG97 S700 M03\nG00 X0. Z5.\nG74 R0.5\nG74 Z-34. Q6000 F0.12\nG00 Z50.\nT0404\nG96 S160 M03\nG00 X15. Z3.\nG71 U1. R0.5\nG71 P10 Q20 U-0.4 W0.05 F0.15\nN10 G00 X30.\nG01 Z0.\nX28. Z-1.\nZ-20.\nX18.\nN20 X15.\nG00 Z50.\nG00 X32. Z3.\nG41 G01 X30. Z1. F0.08\nZ0.\nX28. Z-1.\nZ-20.\nX18.\n{exit}Z50.\nM30\n")
    };
    let (out, v) = run_program(
        "bore.nc",
        &program("G40 G00 X15.\n"),
        "fanuc-a",
        None,
        &["--stock", "40x40"],
    );
    assert_clean(&out, &v);
    let crashes = v["crashes"].as_array().unwrap();
    assert_eq!(crashes.len(), 1, "{crashes:#?}");
    assert_eq!(crashes[0]["line"], 27, "{crashes:#?}");
    assert_eq!(crashes[0]["assumed_tool"], true, "{crashes:#?}");

    let (out, v) = run_program(
        "deep.nc",
        &program("G40 G00 X15.\nG00 Z-22.\n"),
        "fanuc-a",
        None,
        &["--stock", "40x40"],
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    let certain: Vec<_> = v["crashes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["assumed_tool"] != true)
        .collect();
    assert_eq!(certain.len(), 1, "{certain:#?}");
    assert_eq!(certain[0]["line"], 28, "{certain:#?}");

    // a shop whose machine calls any rapid contact a crash (rapid_cut_tol = 0): the point
    // 2 mm into the face is certain, and so is the graze (review 1128g, #2: both were
    // possible, the gate passed)
    let dir = tempfile::tempdir().unwrap();
    let machine = dir.path().join("strict.toml");
    std::fs::write(&machine, "rapid_cut_tol = 0.0\n").unwrap();
    for (exit, line) in [("G40 G00 X15.\nG00 Z-22.\n", 28), ("G40 G00 X15.\n", 27)] {
        let (out, v) = run_program(
            "strict.nc",
            &program(exit),
            "fanuc-a",
            None,
            &["--stock", "40x40", "--machine", machine.to_str().unwrap()],
        );
        assert_eq!(out.code, 1, "{}", out.stderr);
        let certain: Vec<_> = v["crashes"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["assumed_tool"] != true)
            .collect();
        assert!(certain.iter().any(|c| c["line"] == line), "{certain:#?}");
    }
}

/// Field run 8 (I): an OD finished by hand under G41 with a CNMG r0.8 in a PCLNR (tip 3,
/// from the holder's hand). The programmed path runs on Ø30; the control offsets the nose
/// to the part's side, and it cuts 2 × 0.8 = 1.6 mm below the surface over 27 mm. The
/// gouge's cause said "the programmed path itself cuts 1.600 mm below the intended
/// surface", which sent the programmer to a path that is right; it now names the code that
/// is wrong and the one to write, and offers that change, checked by re-running.
#[test]
fn a_gouge_from_the_wrong_compensation_side_names_the_code() {
    let program = "O0015 (OD FINISH BY HAND UNDER G41)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X44. Z2.\nG90 X36. Z-27. F0.2\nX31.\nG00 X30. Z4.\nG41 G01 Z2. F0.1\nZ-27.\nG40 G01 X44.\nG00 X150. Z100.\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let (out, v) = run_fanuc("g41-od.nc", program, tools, "40x40");
    assert_eq!(out.code, 1, "{}", out.stderr);
    let gouges = v["gouges"].as_array().unwrap();
    assert_eq!(gouges.len(), 1, "{gouges:#?}");
    let depth = gouges[0]["depth_mm"].as_f64().unwrap();
    assert!((depth - 1.6).abs() < 1e-3, "{gouges:#?}");
    let cause = gouges[0]["cause"]["text"].as_str().unwrap();
    assert!(cause.starts_with("G41 from line 9"), "{cause}");
    assert!(cause.contains("write G42"), "{cause}");
    assert!(!cause.contains("programmed path"), "{cause}");
    // the fix, checked by re-running the program with G42 there: the gouge is gone
    let remedy = &gouges[0]["remedy"];
    assert_eq!(
        remedy["text"], "write G42 instead of G41 at line 9",
        "{remedy:#}"
    );
    assert_eq!(remedy["line"], 9, "{remedy:#}");
    assert_eq!(remedy["verified"], true, "{remedy:#}");
}

/// Field run 9 (C): a bush whose bore is roughed by G71 with U+ instead of U− (the
/// allowance on the bore's wall side: the roughing cuts 0.2 mm into the wall). The cause
/// said "T03 (line 31) cuts into the contour T01 finished (from line 9)": the OD contour's
/// zone spans the bore's gouge, but the gouge is measured from the bore's surface, which
/// T03 finishes itself. The contour named is the one the gouge is measured from.
#[test]
fn a_gouge_in_a_bore_is_not_blamed_on_the_od_contours_tool() {
    let program = "O0902 (BUSH - BORE G71 WITH U+ INSTEAD OF U-)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.3 W0.05 F0.25\nN10 G00 X44.\nG01 Z0. F0.1\nX48. Z-2.\nZ-42.\nN20 X52.\nG70 P10 Q20\nG00 X100. Z100.\nT0202\nG97 S600 M03\nG00 X0. Z3.\nG74 R0.5\nG74 Z-50. Q5000 F0.1\nG00 Z5.\nG00 X100. Z100.\nT0303\nG96 S150 M03\nG00 X23. Z2.\nG71 U1. R0.5\nG71 P30 Q40 U0.4 W0.05 F0.15\nN30 G00 G41 X36.\nG01 Z0. F0.1\nX32. Z-2.\nZ-40.\nN40 X23.\nG70 P30 Q40\nG40 G00 Z5.\nX100. Z100.\nM30\n";
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 2\nkind = \"drill\"\ndiameter = 24.0\npoint_angle = 118\nreach = 80.0\n[[tool]]\nt = 3\nkind = \"turning\"\ninsert = \"DCMT 070204\"\ntip = 2\nentering_angle = 93\nshank = 16.0\n";
    let (out, v) = run_program(
        "uplus.nc",
        program,
        "fanuc-a",
        Some(tools),
        &["--stock", "50x50", "--stock-z", "0.5"],
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    let gouges = v["gouges"].as_array().unwrap();
    assert!(!gouges.is_empty(), "{gouges:#?}");
    for g in gouges {
        let cause = g["cause"]["text"].as_str().unwrap();
        assert!(!cause.contains("T01"), "{cause}");
    }
}

/// Field run 10 (B1): no tool table. A shoulder turned by hand, Ø36 to Z-30, then a concave
/// R4 fillet (`G02 X44. Z-34. R4.`, centre Z-30 Ø44) up to Ø44; a blade's rapid then runs
/// along Ø36 from Z-22 to Z-32, its programmed point ending 22 − √(16 − 2²) − 18 = 0.536 mm
/// inside the fillet's stock. Nothing has drilled the solid bar, so no earlier tool can be a
/// boring bar that cut below the fillet: the point enters uncut stock whatever the tools, a
/// certain crash (it was possible, the default insert's mirror image "maybe" having cut
/// there, and the run CLEAN). Drilled first, the same rapid stays possible: a boring bar
/// fed along that fillet could have taken the stock below it.
#[test]
fn a_rapid_into_a_fillet_of_a_solid_bar_is_certain_with_no_table() {
    let program = |drill: &str| {
        format!(
            "G21 G99\nT0101\nG96 S180 M03\n{drill}G00 X46. Z2.\nG01 Z-45. F0.25\nG00 X48. Z2.\n\
             G00 X40.\nG01 Z-30. F0.25\nG00 X46. Z2.\nG00 X36.\nG01 Z-30. F0.15\n\
             G02 X44. Z-34. R4.\nG01 X52.\nG00 X60. Z50.\nT0303\nG97 S700 M03\n\
             G00 X40. Z-22.\nG00 X36.\nG00 Z-32.\nG00 X60.\nM30\n"
        )
    };
    let certain = |v: &serde_json::Value| -> Vec<u64> {
        v["crashes"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["assumed_tool"] != true)
            .map(|c| c["line"].as_u64().unwrap())
            .collect()
    };
    let (out, v) = run_program(
        "fillet.nc",
        &program(""),
        "fanuc-a",
        None,
        &["--stock", "50x60"],
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert_eq!(certain(&v), [19], "{:#}", v["crashes"]);
    let drilled = program("T0505\nG97 S900 M03\nG00 X0. Z5.\nG01 Z-30. F0.1\nG00 Z5.\nT0101\n");
    let (out, v) = run_program(
        "drilled.nc",
        &drilled,
        "fanuc-a",
        None,
        &["--stock", "50x60"],
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(certain(&v).is_empty(), "{:#}", v["crashes"]);
}
