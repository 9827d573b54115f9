//! Chuck, jaws and tailstock (issue 15): a tool entering them, or cutting the blank inside
//! the jaws, is a crash at its line with the obstacle named; the same programs with room
//! to spare report nothing. Hand numbers in the comments.
//!
//! The tool is a 3 mm blade (reference at its left corner: z 0…3, r 0…20 from it) with a
//! stated reach, so its holder is probed too: z −2…5, r 20…120 from the reference.

mod common;
use common::*;
use serde_json::Value;

const BLADE: &str = "[[tool]]\nt = 1\nkind = \"grooving\"\nwidth = 3.0\nwidth_dir = \"+z\"\nshank_dir = \"+x\"\nreach = 20.0\n";

/// Runs `program` on the blank `stock` with `--chuck chuck` (none when empty) and returns
/// (exit code, the JSON report).
fn run(program: &str, stock: &str, chuck: &str) -> (i32, Value) {
    let (dir, prog) = temp_program("p.nc", program.as_bytes());
    let tools = dir.path().join("tools.toml");
    std::fs::write(&tools, BLADE).unwrap();
    let json = dir.path().join("r.json");
    let mut args = vec![
        "run",
        prog.to_str().unwrap(),
        "--stock",
        stock,
        "--tools",
        tools.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "-q",
    ];
    if !chuck.is_empty() {
        args.extend(["--chuck", chuck]);
    }
    let out = latsim(&args);
    assert!(out.code == 0 || out.code == 1, "{}", out.stderr);
    let v: Value = serde_json::from_str(&read(&json)).unwrap();
    (out.code, v)
}

/// (line, obstacle, body, z, x, area, depth) of each crash.
type Row = (u64, String, Option<String>, f64, f64, f64, f64);

fn crashes(v: &Value) -> Vec<Row> {
    v["crashes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["line"].as_u64().unwrap(),
                c["obstacle"].as_str().unwrap_or("").to_string(),
                c["body"].as_str().map(str::to_string),
                c["z"].as_f64().unwrap(),
                c["x"].as_f64().unwrap(),
                c["area_mm2"].as_f64().unwrap(),
                c["depth_mm"].as_f64().unwrap(),
            )
        })
        .collect()
}

fn near(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-5
}

fn rapid_along_z(x: f64, z: f64) -> String {
    format!("O0001;\nG99 M03 S500 T0101;\nG00 X{x:.1} Z5.;\nG00 Z{z:.1};\nG00 X150. Z100.;\nM30;\n")
}

#[test]
fn rapid_toward_the_chuck_past_the_stock_end_hits_the_chuck_face() {
    // Ø40 × 100 bar, face Z0, held 30 mm: the chuck face at the bar's left end Z-100,
    // jaws Z-100…-70 from r 20 to 40, body Ø(2 × 40 + 40) = Ø120 behind the face.
    // The blade at X100 (r 50…70) rapids to Z-120: it enters the body over Z-120…-100,
    // r 50…60: 200 mm², 10 mm deep across the move, first met at Z-100 X100.
    let (code, v) = run(&rapid_along_z(100.0, -120.0), "40x100", "grip=30,jaw=20");
    assert_eq!(code, 1);
    let c = crashes(&v);
    assert_eq!(c.len(), 1, "{c:?}");
    let (line, obstacle, body, z, x, area, depth) = c[0].clone();
    assert_eq!((line, obstacle.as_str(), body), (4, "chuck face", None));
    assert!(near(z, -100.0) && near(x, 100.0), "{c:?}");
    assert!(near(area, 200.0) && near(depth, 10.0), "{c:?}");
    assert_eq!(v["verdict"], "crash");
    // stopping at Z-97 (blade Z-97…-94, holder from Z-99): clean
    let (code, v) = run(&rapid_along_z(100.0, -97.0), "40x100", "grip=30,jaw=20");
    assert_eq!((code, crashes(&v).len()), (0, 0));
}

#[test]
fn rapid_over_the_bar_into_the_jaws() {
    // at X50 (r 25…45) to Z-80: the jaw (r 20…40) over Z-80…-70, r 25…40: 150 mm²,
    // 15 mm deep, met at the jaw's front Z-70, X50
    let (_, v) = run(&rapid_along_z(50.0, -80.0), "40x100", "grip=30,jaw=20");
    let c = crashes(&v);
    assert_eq!(c.len(), 1, "{c:?}");
    let (line, obstacle, _, z, x, area, depth) = c[0].clone();
    assert_eq!((line, obstacle.as_str()), (4, "chuck jaw"));
    assert!(near(z, -70.0) && near(x, 50.0) && near(area, 150.0) && near(depth, 15.0));
    // to Z-69: the blade stops 1 mm short of the jaws
    let (code, v) = run(&rapid_along_z(50.0, -69.0), "40x100", "grip=30,jaw=20");
    assert_eq!((code, crashes(&v).len()), (0, 0));
    // no --chuck: today's report, the same program clean and no obstacle field anywhere
    let (code, v) = run(&rapid_along_z(50.0, -80.0), "40x100", "");
    assert_eq!((code, crashes(&v).len()), (0, 0));
    assert!(!v.to_string().contains("obstacle"));
}

#[test]
fn the_blade_holder_meets_a_taller_jaw() {
    // jaws 25 high (r 20…45). The blade at X40 (r 20…40) runs along the bar to Z-69: the
    // blade stays 1 mm short of the jaws, but its holder (Z-71…-64, from r 40) overlaps
    // the jaw over Z-71…-70, r 40…45: 5 mm², 5 mm deep, met at Z-70 X80
    let (_, v) = run(&rapid_along_z(40.0, -69.0), "40x100", "grip=30,jaw=25");
    let c = crashes(&v);
    assert_eq!(c.len(), 1, "{c:?}");
    let (line, obstacle, body, z, x, area, depth) = c[0].clone();
    assert_eq!(
        (line, obstacle.as_str(), body.as_deref()),
        (4, "chuck jaw", Some("blade holder"))
    );
    assert!(near(z, -70.0) && near(x, 80.0) && near(area, 5.0) && near(depth, 5.0));
    // with 20 mm jaws (r ≤ 40) the holder only touches them: clean
    let (_, v) = run(&rapid_along_z(40.0, -69.0), "40x100", "grip=30,jaw=20");
    assert!(crashes(&v).is_empty());
}

/// Approach at X44 Z5, down Z to `z`, face to X`x`, retract.
fn facing(z: f64, x: f64) -> String {
    format!(
        "O0001;\nG99 M03 S500 T0101;\nG00 X44. Z5.;\nG00 Z{z:.1};\nG01 X{x:.1} F0.05;\nG00 X44.;\nG00 X150. Z100.;\nM30;\n"
    )
}

#[test]
fn facing_into_the_jaws_at_a_too_short_stick_out() {
    // Ø40 × 30, held 29 mm: jaws Z-30…-1, stick-out 1 mm. Facing 2.5 mm deep:
    // line 4, the rapid to Z-2.5 (blade Z-2.5…0.5, r 22…42) enters the jaw over Z-2.5…-1,
    // r 22…40: 27 mm², 18 mm deep, met at Z-1 X44;
    // line 5, the face cut to X0 removes the gripped length Z-2.5…-1, r 0…20: 30 mm²,
    // 1.5 mm across the move, met at Z-2.5 X40 (its jaw contact continues line 4's);
    // the retracts stay in the jaw: the same crash going on
    let (code, v) = run(&facing(-2.5, 0.0), "40x30", "grip=29,jaw=20");
    assert_eq!(code, 1);
    let c = crashes(&v);
    assert_eq!(c.len(), 2, "{c:?}");
    let (line, obstacle, _, z, x, area, depth) = c[0].clone();
    assert_eq!((line, obstacle.as_str()), (4, "chuck jaw"));
    assert!(near(z, -1.0) && near(x, 44.0) && near(area, 27.0) && near(depth, 18.0));
    let (line, obstacle, body, z, x, area, depth) = c[1].clone();
    assert_eq!((line, obstacle.as_str(), body), (5, "gripped length", None));
    assert!(near(z, -2.5) && near(x, 40.0) && near(area, 30.0) && near(depth, 1.5));
    let d = v["stock"]["description"].as_str().unwrap();
    assert!(d.ends_with(", stick-out 1 mm"), "{d}");
    // the removal itself is unchanged: 2.5 × 20
    assert!(near(v["removed_area_mm2"].as_f64().unwrap(), 50.0));
    // held 20 mm (jaws to Z-10, stick-out 10): the same facing is clean
    let (code, v) = run(&facing(-2.5, 0.0), "40x30", "grip=20,jaw=20");
    assert_eq!((code, crashes(&v).len()), (0, 0));
}

#[test]
fn facing_tool_meets_the_tailstock_centre() {
    // centre point at Z-1 (in its centre hole), 60° cone: r = (z + 1) tan 30°. Facing at
    // Z-0.5 to X0, the blade covers Z-0.5…2.5 down to the axis: the cone's section there,
    // ∫ (z + 1) tan 30° dz from -0.5 to 2.5 = tan 30° (3.5² - 0.5²) / 2 = 3.464102 mm²;
    // 3 mm across the move; of the overlap's corners, (2.5, 3.5 tan 30° = 2.020726) is the
    // nearest the move's start (-0.5, 22): X4.041452
    let (code, v) = run(&facing(-0.5, 0.0), "40x100", "grip=30,tail=-1");
    assert_eq!(code, 1);
    let c = crashes(&v);
    assert_eq!(c.len(), 1, "{c:?}");
    let (line, obstacle, _, z, x, area, depth) = c[0].clone();
    assert_eq!((line, obstacle.as_str()), (5, "tailstock centre"));
    let t30 = 30f64.to_radians().tan();
    assert!(near(area, t30 * 6.0) && near(depth, 3.0), "{c:?}");
    assert!(near(z, 2.5) && near(x, 2.0 * 3.5 * t30), "{c:?}");
    // tailstock retracted (none given): clean
    let (code, v) = run(&facing(-0.5, 0.0), "40x100", "grip=30");
    assert_eq!((code, crashes(&v).len()), (0, 0));
    // stopping short at X8 (r 4): the cone is at most 2.02 high under the blade
    let (code, v) = run(&facing(-0.5, 8.0), "40x100", "grip=30,tail=-1");
    assert_eq!((code, crashes(&v).len()), (0, 0));
}

#[test]
fn an_iso_facing_tool_meets_the_tailstock_centre() {
    // CNMG 120408 in PCLNR 2525M12 facing to X0 at Z-0.5 reaches the cone near the axis
    let tools = "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n";
    let (dir, prog) = temp_program("p.nc", facing(-0.5, 0.0).as_bytes());
    let t = dir.path().join("t.toml");
    std::fs::write(&t, tools).unwrap();
    let json = dir.path().join("r.json");
    let args = |chuck: &'static str| {
        vec![
            "run".to_string(),
            prog.display().to_string(),
            "--stock".into(),
            "40x100".into(),
            "--tools".into(),
            t.display().to_string(),
            "--json".into(),
            json.display().to_string(),
            "--chuck".into(),
            chuck.into(),
        ]
    };
    let a = args("grip=30,tail=-1");
    let out = latsim(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr
            .contains(":5:1: crash: the tool's cutting edge meets the tailstock centre"),
        "{}",
        out.stderr
    );
    let c = crashes(&serde_json::from_str(&read(&json)).unwrap());
    assert_eq!(
        (c.len(), c[0].0, c[0].1.as_str()),
        (1, 5, "tailstock centre")
    );
    let a = args("grip=30");
    let out = latsim(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(out.code, 0, "{}", out.stderr);
}

#[test]
fn machine_profile_and_chuck_file_give_the_same_workholding() {
    let (dir, prog) = temp_program("p.nc", rapid_along_z(50.0, -80.0).as_bytes());
    let tools = dir.path().join("tools.toml");
    std::fs::write(&tools, BLADE).unwrap();
    let machine = dir.path().join("m.toml");
    std::fs::write(&machine, "[chuck]\ngrip = 30\njaw = 20\n").unwrap();
    let file = dir.path().join("chuck.toml");
    std::fs::write(&file, "[chuck]\ngrip = 30\njaw = 20\n").unwrap();
    let json = dir.path().join("r.json");
    let base = [
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "40x100",
        "--tools",
        tools.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ];
    let mut rows = vec![];
    for extra in [
        vec!["--machine", machine.to_str().unwrap()],
        vec!["--chuck", file.to_str().unwrap()],
        vec!["--chuck", "grip=30,jaw=20"],
    ] {
        let mut a = base.to_vec();
        a.extend(extra);
        let out = latsim(&a);
        assert_eq!(out.code, 1, "{}", out.stderr);
        rows.push(crashes(&serde_json::from_str(&read(&json)).unwrap()));
    }
    assert_eq!(rows[0], rows[1]);
    assert_eq!(rows[1], rows[2]);
    assert_eq!(rows[0][0].1, "chuck jaw");
    // --chuck replaces the profile's workholding: jaws of 30 mm held 10 mm from Z-100
    let mut a = base.to_vec();
    a.extend(["--machine", machine.to_str().unwrap(), "--chuck", "grip=10"]);
    assert_eq!(latsim(&a).code, 0);
}

#[test]
fn bad_workholding_is_a_clear_error() {
    let (dir, prog) = temp_program("p.nc", rapid_along_z(50.0, -80.0).as_bytes());
    let p = prog.to_str().unwrap();
    let out = latsim(&["run", p, "--stock", "40x100", "--chuck", "grip=30,claw=2"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("unknown key `claw`"), "{}", out.stderr);
    let out = latsim(&["run", p, "--stock", "40x100", "--chuck", "grip=30,face=20"]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("grips nothing"), "{}", out.stderr);
    let bad = dir.path().join("c.toml");
    std::fs::write(&bad, "[chuck]\ngrip = 30\njaw = -1\n").unwrap();
    let out = latsim(&[
        "run",
        p,
        "--stock",
        "40x100",
        "--chuck",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 2);
    assert!(out.stderr.contains("chuck.jaw"), "{}", out.stderr);
    assert!(out.stderr.contains(":3:"), "{}", out.stderr);
}

#[test]
fn soft_jaws_take_their_outline() {
    // soft jaws gripping Ø40 over 20 mm with a lip reaching 5 mm further forward from Ø50:
    // from the face Z-100 the lip spans Z-80…-75, r 25…45. The blade at X54 (r 27…47) to
    // Z-78 enters the lip over Z-78…-75, r 27…45: 54 mm², 18 mm deep, met at Z-75 X54.
    // Hard jaws of the same grip end at Z-80: clean.
    let (dir, prog) = temp_program("p.nc", rapid_along_z(54.0, -78.0).as_bytes());
    let tools = dir.path().join("tools.toml");
    std::fs::write(&tools, BLADE).unwrap();
    let chuck = dir.path().join("soft.toml");
    std::fs::write(
        &chuck,
        "[chuck]\ngrip = 20\nsoft_jaw = [[0, 40], [20, 40], [20, 50], [25, 50], [25, 90], [0, 90]]\n",
    )
    .unwrap();
    let json = dir.path().join("r.json");
    let run_with = |c: &str| {
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock",
            "40x100",
            "--tools",
            tools.to_str().unwrap(),
            "--json",
            json.to_str().unwrap(),
            "--chuck",
            c,
        ]);
        (
            out.code,
            crashes(&serde_json::from_str(&read(&json)).unwrap()),
        )
    };
    let (code, c) = run_with(chuck.to_str().unwrap());
    assert_eq!((code, c.len()), (1, 1), "{c:?}");
    let (line, obstacle, _, z, x, area, depth) = c[0].clone();
    assert_eq!((line, obstacle.as_str()), (4, "chuck jaw"));
    assert!(near(z, -75.0) && near(x, 54.0) && near(area, 54.0) && near(depth, 18.0));
    assert_eq!(run_with("grip=20").0, 0);
}

/// The program retracts the tailstock before facing to the centre (GSK980TD M11, Haas
/// M22): the centre is no obstacle then, so the facing cut of the crash above is clean.
/// Advanced again (M10 / M21) before the cut, it crashes as before (one line later).
#[test]
fn a_retracted_tailstock_is_no_obstacle() {
    let with = |m: &str| {
        facing(-0.5, 0.0).replacen("G00 X44. Z5.;\n", &format!("{m}\nG00 X44. Z5.;\n"), 1)
    };
    let (code, v) = run(&with("M11;"), "40x100", "grip=30,tail=-1");
    assert_eq!((code, crashes(&v).len()), (0, 0), "{:?}", crashes(&v));
    // the picture draws the centre advanced: the stock's description says it moved
    let description = v["stock"]["description"].as_str().unwrap();
    assert!(
        description.ends_with("; tailstock retracted before line 4"),
        "{description}"
    );
    let (code, v) = run(&with("M11;\nM10;"), "40x100", "grip=30,tail=-1");
    assert_eq!(code, 1);
    let c = crashes(&v);
    assert_eq!(
        (c.len(), c[0].0, c[0].1.as_str()),
        (1, 7, "tailstock centre"),
        "{c:?}"
    );
    // Haas: M22 retracts, M21 advances (under GSK980TD they are unknown codes)
    for (m, crashes_expected) in [("M22;", 0), ("M22;\nM21;", 1)] {
        let (code, json) = run_with_centre(&with(m), &["--control", "haas"], "r.json");
        assert_eq!(code, crashes_expected, "{m}");
        let v: Value = serde_json::from_str(&json).unwrap();
        assert_eq!(crashes(&v).len(), crashes_expected as usize, "{m}");
    }
}

/// Runs `program` on a Ø40 × 100 bar held 30 mm, the centre's tip at Z-1, with the blade
/// table and `extra` arguments, writing the report `name` (its kind by the extension);
/// returns the exit code and the report's text.
fn run_with_centre(program: &str, extra: &[&str], name: &str) -> (i32, String) {
    let (dir, prog) = temp_program("p.nc", program.as_bytes());
    let tools = dir.path().join("tools.toml");
    std::fs::write(&tools, BLADE).unwrap();
    let report = dir.path().join(name);
    let kind = format!("--{}", name.rsplit('.').next().unwrap());
    let mut args = vec![prog.to_str().unwrap(), "--stock", "40x100"];
    args.extend([
        "--tools",
        tools.to_str().unwrap(),
        "--chuck",
        "grip=30,tail=-1",
    ]);
    args.extend([kind.as_str(), report.to_str().unwrap(), "-q"]);
    args.extend(extra);
    let out = latsim(&[&["run"], &args[..]].concat());
    assert!(out.code == 0 || out.code == 1, "{}", out.stderr);
    (out.code, read(&report))
}

/// The picture shows the part at the end of the program: a tailstock centre the program
/// leaves retracted is labelled so (and drawn back); one advanced again
/// keeps its plain label.
#[test]
fn a_centre_left_retracted_is_labelled_retracted() {
    let program = |m: &str| {
        facing(-0.5, 0.0).replacen("G00 X44. Z5.;\n", &format!("{m}\nG00 X44. Z5.;\n"), 1)
    };
    for (m, retracted) in [("M11;", true), ("M11;\nM10;", false), ("", false)] {
        let (_, text) = run_with_centre(&program(m), &[], "r.svg");
        assert!(
            text.contains(">tailstock centre"),
            "{m:?}: no tailstock label"
        );
        // on one line where there is room, else "(retracted)" on a second
        let label = text.contains(">tailstock centre (retracted)<")
            || text.contains(">tailstock centre<") && text.contains(">(retracted)<");
        assert_eq!(label, retracted, "{m:?}");
    }
}

/// A Φ40 × 40 tube (bore Φ20) in jaws from a chuck face at Z-45, 15 long: held over
/// Z-40…-30. Boring it to Φ24 through, 1 mm past its end, leaves an 8 mm wall inside the
/// jaws: no crash (**Interpretation**: the outer 0.5 mm skin under the gripped diameter is
/// what the jaws hold). Bored to Φ39.2 the wall left is 0.4 mm: the cut reaches the skin,
/// a crash "gripped length" at the boring line.
#[test]
fn boring_a_tube_through_its_gripped_length_leaves_what_the_jaws_hold() {
    let dir = tempfile::tempdir().unwrap();
    let tools = dir.path().join("t.toml");
    std::fs::write(&tools, read(&asset("tools/boring-r08-tip2.toml"))).unwrap();
    let bore = |x: f64| {
        let program = format!(
            "G99 M03 S500 T0202\nG00 X{:.1} Z2\nG01 Z-41 F0.1\nG00 X{:.1}\nG00 Z5\nM30\n",
            x,
            x - 2.0
        );
        let (pdir, prog) = temp_program("b.nc", program.as_bytes());
        let _keep = pdir;
        let json = dir.path().join("r.json");
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock",
            "40x40",
            "--bore",
            "20",
            "--tools",
            tools.to_str().unwrap(),
            "--chuck",
            "grip=15,face=-45",
            "--json",
            json.to_str().unwrap(),
            "-q",
        ]);
        let v: Value =
            serde_json::from_str(&read(&json)).unwrap_or_else(|_| panic!("{}", out.stderr));
        crashes(&v)
    };
    assert!(bore(24.0).is_empty(), "{:?}", bore(24.0));
    let c = bore(39.2);
    assert!(
        c.iter().any(|r| r.0 == 3 && r.1 == "gripped length"),
        "{c:?}"
    );
}

/// The numbers of the path inside the `<g class="fixture">` group of an SVG.
fn fixture_path_numbers(svg: &str) -> Vec<f64> {
    let g = &svg[svg.find(r#"class="fixture""#).expect("a fixture group")..];
    let d = &g[g.find(" d=\"").expect("a path") + 4..];
    let d = &d[..d.find('"').unwrap()];
    d.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter_map(|t| t.parse().ok())
        .collect()
}

/// Issue 30: a centre the program leaves retracted is drawn retracted, 5 mm back along +Z
/// (it was drawn where it stood advanced); advanced again, it is drawn in place.
#[test]
fn a_centre_left_retracted_is_drawn_retracted() {
    let program = |m: &str| {
        facing(-0.5, 0.0).replacen("G00 X44. Z5.;\n", &format!("{m}\nG00 X44. Z5.;\n"), 1)
    };
    let far = |m: &str| {
        let (_, text) = run_with_centre(&program(m), &[], "r.svg");
        fixture_path_numbers(&text)
            .into_iter()
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (advanced, retracted, again) = (far(""), far("M11;"), far("M11;\nM10;"));
    assert!(
        (retracted - advanced - 5.0).abs() < 1e-6,
        "{advanced} {retracted}"
    );
    assert_eq!(again, advanced);
}
