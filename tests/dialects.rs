//! spec/dialects.md §7 T1–T3 end to end, the same part written for FANUC systems A, B and
//! C, and bad input that depends on the control (issue 11). Numbers computed by hand.

mod common;
use common::{latsim, temp_program};
use std::time::{Duration, Instant};

const T1: &[u8] = b"\x12&HE:%\n:0100 (FRAMING (NESTED) \"Q\" TEST) ;\nN10 G21 G99 ;\nN20 T0101 ;\nN30 G97 S800 M03 ;\nN40 ;\nN50 G00 X52. Z2. ;\nN60 G90 X46. Z-30. F0.2 ;\nN70 X42. ;\nN80 G00 X100. Z100. ;\nN90 M30 ;\n%\n\x14";

const T2: &str = "%\nO0200\nG21 G95 ;\nG92 S2500 ;\nT0101 ;\nG96 S150 M03 ;\nG90 G00 X52. Z2. ;\nG77 X46. Z-30. F0.2 ;\nX42. ;\nG94 G01 Z3. F300. ;\nG95 ;\nG91 G00 X10. Z5. ;\nG90 G00 X100. Z100. ;\nM30 ;\n%\n";

const T3: &str = "%\nO0300\nG71 ;\nG95 G90 ;\nG92 S2500 ;\nT0101 ;\nG97 S1000 M03 ;\nG00 X52. Z2. ;\nG20 X46. Z-30. F0.2 ;\nX42. ;\nG24 X20. Z-2. F0.15 ;\nG00 X100. Z100. ;\nM30 ;\n%\n";

/// `latsim expand --format csv` as (line, kind, Z, X) of each segment's end.
fn path(name: &str, text: &[u8], control: &str) -> Vec<(u32, String, f64, f64)> {
    let (_dir, prog) = temp_program(name, text);
    let out = latsim(&[
        "expand",
        prog.to_str().unwrap(),
        "--control",
        control,
        "--format",
        "csv",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    out.stdout
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (
                f[0].parse().unwrap(),
                f[2].to_string(),
                f[5].parse().unwrap(),
                f[6].parse().unwrap(),
            )
        })
        .collect()
}

/// `latsim run` with the JSON report: (exit code, report, stderr).
fn run_json(
    name: &str,
    text: &[u8],
    control: &str,
    stock: &str,
) -> (i32, serde_json::Value, String) {
    let (dir, prog) = temp_program(name, text);
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--control",
        control,
        "--stock",
        stock,
        "--tools",
        common::asset("tools/v35-sharp.toml").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ]);
    let report = std::fs::read_to_string(&json)
        .map(|t| serde_json::from_str(&t).unwrap())
        .unwrap_or(serde_json::Value::Null);
    (out.code, report, out.stderr)
}

fn expect_path(got: &[(u32, String, f64, f64)], want: &[(&str, f64, f64)]) {
    let got: Vec<(&str, f64, f64)> = got
        .iter()
        .map(|(_, k, z, x)| (k.as_str(), *z, *x))
        .collect();
    assert_eq!(got, want);
}

/// The T1 passes: (52, 2) → rapid X46 → feed Z−30 → feed X52 → rapid Z2, then at X42.
const TWO_PASSES: [(&str, f64, f64); 9] = [
    ("rapid", 2.0, 52.0),
    ("rapid", 2.0, 46.0),
    ("feed", -30.0, 46.0),
    ("feed", -30.0, 52.0),
    ("rapid", 2.0, 52.0),
    ("rapid", 2.0, 42.0),
    ("feed", -30.0, 42.0),
    ("feed", -30.0, 52.0),
    ("rapid", 2.0, 52.0),
];

/// Upper half of the final section as [z, r] rings: Φ42 from Z0 to Z−30, Φ50 to Z−60,
/// with the face step of T3 (Φ20 to Z−2) when `face` is set.
fn section(face: bool) -> stock::Shape {
    let mut ring = vec![[-60.0, 0.0], [0.0, 0.0]];
    if face {
        ring.extend([[0.0, 10.0], [-2.0, 10.0], [-2.0, 21.0]]);
    } else {
        ring.push([0.0, 21.0]);
    }
    ring.extend([[-30.0, 21.0], [-30.0, 25.0], [-60.0, 25.0]]);
    common::shape(ring)
}

fn final_shapes(report: &serde_json::Value) -> Vec<stock::Shape> {
    let ring = |r: &serde_json::Value| -> Vec<[f64; 2]> {
        r.as_array()
            .unwrap()
            .iter()
            .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap() / 2.0])
            .collect()
    };
    report["final"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| stock::Shape {
            outer: ring(&s["outer"]),
            holes: s["holes"].as_array().unwrap().iter().map(ring).collect(),
        })
        .collect()
}

fn area(report: &serde_json::Value) -> f64 {
    report["removed_area_mm2"].as_f64().unwrap()
}

#[test]
fn t1_framing_under_fanuc_a() {
    let p = path("t1.nc", T1, "fanuc-a");
    let mut want = TWO_PASSES.to_vec();
    want.push(("rapid", 100.0, 100.0));
    expect_path(&p, &want);
    let (code, report, _) = run_json("t1.nc", T1, "fanuc-a", "50x60");
    assert_eq!(code, 0);
    assert_eq!(report["title"], "O0100");
    // (25 − 21) × 30 = 120 mm²
    assert!((area(&report) - 120.0).abs() < 0.05, "{}", area(&report));
    assert!(stock::hausdorff(&final_shapes(&report), &[section(false)]) < 0.01);
    let messages = report["warnings"].to_string();
    assert!(
        messages.contains("leader skipped") && messages.contains("nested parentheses"),
        "{messages}"
    );
}

#[test]
fn t2_system_b_under_fanuc_b_and_its_alarm_under_fanuc_a() {
    let p = path("t2.nc", T2.as_bytes(), "fanuc-b");
    let mut want = TWO_PASSES.to_vec();
    // G94 G01 Z3. is a 1 mm feed at 300 mm/min; G91 G00 X10. Z5. goes (52, 3) → (62, 8).
    want.extend([
        ("feed", 3.0, 52.0),
        ("rapid", 8.0, 62.0),
        ("rapid", 100.0, 100.0),
    ]);
    expect_path(&p, &want);
    assert_eq!(p[9].0, 10, "the 1 mm feed is line 10");
    let (code, report, _) = run_json("t2.nc", T2.as_bytes(), "fanuc-b", "50x60");
    assert_eq!(code, 0);
    assert!((area(&report) - 120.0).abs() < 0.05, "{}", area(&report));
    assert!(stock::hausdorff(&final_shapes(&report), &[section(false)]) < 0.01);
    // The same file under system A stops at line 3 and names the control to try.
    let (code, _, stderr) = run_json("t2.nc", T2.as_bytes(), "fanuc-a", "50x60");
    assert_eq!(code, 1);
    assert!(stderr.contains("t2.nc:3:5"), "{stderr}");
    assert!(stderr.contains("G95 is not a system A code"), "{stderr}");
    assert!(stderr.contains("--control fanuc-b"), "{stderr}");
}

#[test]
fn t3_system_c_under_fanuc_c_and_its_alarm_under_fanuc_a() {
    let p = path("t3.nc", T3.as_bytes(), "fanuc-c");
    let mut want = TWO_PASSES.to_vec();
    // G24 from (52, 2): rapid to Z−2, feed to X20, feed to Z2, rapid to X52.
    want.extend([
        ("rapid", -2.0, 52.0),
        ("feed", -2.0, 20.0),
        ("feed", 2.0, 20.0),
        ("rapid", 2.0, 52.0),
        ("rapid", 100.0, 100.0),
    ]);
    expect_path(&p, &want);
    let (code, report, _) = run_json("t3.nc", T3.as_bytes(), "fanuc-c", "50x60");
    assert_eq!(code, 0);
    // 120 + (21 − 10) × 2 = 142 mm²
    assert!((area(&report) - 142.0).abs() < 0.05, "{}", area(&report));
    assert!(stock::hausdorff(&final_shapes(&report), &[section(true)]) < 0.01);
    // Under system A, line 3's G71 is a roughing cycle without its words.
    let (code, _, stderr) = run_json("t3.nc", T3.as_bytes(), "fanuc-a", "50x60");
    assert_eq!(code, 1);
    assert!(
        stderr.contains("t3.nc:3:1") && stderr.contains("G71"),
        "{stderr}"
    );
}

#[test]
fn the_same_part_in_systems_a_b_c_and_haas_gives_the_same_section() {
    let c_form = T3.replace("G24 X20. Z-2. F0.15 ;\n", "");
    // the Haas form: safe start, a one-block G71 with D to the same Φ42 × 30 step, then G70
    let haas_form = "%\nO00100 (SAME PART, HAAS)\nG18 G21 G40 G80 G99 ;\nT101 ;\nG97 S800 M03 ;\nG00 X52. Z2. ;\nG71 P10 Q20 U0. W0. D2. F0.2 ;\nN10 G00 X42. ;\nG01 Z-30. ;\nN20 X52. ;\nG70 P10 Q20 ;\nG28 U0. W0. ;\nM30 ;\n%\n";
    let finals: Vec<Vec<stock::Shape>> = [
        ("a.nc", T1.to_vec(), "fanuc-a"),
        ("b.nc", T2.as_bytes().to_vec(), "fanuc-b"),
        ("c.nc", c_form.into_bytes(), "fanuc-c"),
        ("h.nc", haas_form.as_bytes().to_vec(), "haas"),
    ]
    .iter()
    .map(|(name, text, control)| {
        let (code, report, stderr) = run_json(name, text, control, "50x60");
        assert_eq!(code, 0, "{control}: {stderr}");
        final_shapes(&report)
    })
    .collect();
    for other in &finals[1..] {
        let h = stock::hausdorff(&finals[0], other);
        assert!(h <= 0.001, "Hausdorff {h}");
    }
}

/// Each bad input: exit status, where the alarm points and what it says, under a second.
#[test]
fn bad_input_that_depends_on_the_control() {
    let cases: &[(&str, &str, i32, &str, &[&str])] = &[
        // a system-B code under system A
        (
            "fanuc-a",
            "G21 G99\nM3 S500\nG0 X52 Z2\nG77 X46 Z-30 F0.2\nM30\n",
            1,
            "b.nc:4:1",
            &["G77 is not a system A code", "--control fanuc-b"],
        ),
        // G17 then an arc
        (
            "haas",
            "G21 G17\nM3 S500\nG0 X20 Z2\nG2 X30 Z-3 R5 F0.1\nM30\n",
            1,
            "b.nc:4:1",
            &["plane not simulated"],
        ),
        // a C-axis word
        (
            "fanuc-a",
            "M3 S500\nG0 X20 Z2\nG1 Z-5 C90. F0.1\nM30\n",
            1,
            "b.nc:3:8",
            &["C90 is not simulated", "C axis"],
        ),
        // M98 and M30 in one block
        (
            "fanuc-a",
            "M3 S500\nG0 X20 Z2\nM98 P1 M30\n",
            1,
            "b.nc:3:8",
            &["M30 cannot share a block with M98"],
        ),
        // Haas R taper
        (
            "haas",
            "G21\nM3 S500\nG0 X52 Z2\nG90 X46 Z-20 R-1 F0.2\nM30\n",
            1,
            "b.nc:4:14",
            &["R is not a Haas taper word"],
        ),
    ];
    for &(control, text, code, place, says) in cases {
        let t = Instant::now();
        let (got, _, stderr) = run_json("b.nc", text.as_bytes(), control, "50x60");
        assert!(
            t.elapsed() < Duration::from_secs(1),
            "{text}: {:?}",
            t.elapsed()
        );
        assert_eq!(got, code, "{text}: {stderr}");
        assert!(stderr.contains(place), "{text}: {stderr}");
        for s in says {
            assert!(stderr.contains(s), "{text}: {s}: {stderr}");
        }
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn an_unknown_m_code_is_one_warning() {
    let text = "G21 G99\nM3 S500 M77\nG0 X52 Z2\nM77\nG90 X48 Z-10 F0.2\nM77\nM30\n";
    let (code, report, _) = run_json("m.nc", text.as_bytes(), "fanuc-a", "50x60");
    assert_eq!(code, 0);
    let unknown: Vec<_> = report["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["code"] == "W-M-UNKNOWN")
        .collect();
    assert_eq!(unknown.len(), 1, "{unknown:?}");
    assert_eq!(unknown[0]["line"], 2);
}

/// Field run 6 (F): a GSK 980TD program in custom macro A (`G65 H01 P#101 Q30000`: #101 =
/// 30000) is refused at its `G65 H`, naming macro A, under each setting. It read "`#` needs
/// custom macro B: … --macro on", and with `--macro on` the block became a macro B call of
/// program #101: "G65 P: the variable is vacant".
#[test]
fn gsk_macro_a_is_refused_at_its_h_word() {
    let with_hash =
        "O0457\nN10 G99 T0101\nN20 M03 S900\nN30 G00 X32 Z2\nN40 G65 H01 P#101 Q30000\nN50 G00 X#101\nN60 M30\n";
    let plain =
        "O0457\nN10 G99 T0101\nN20 M03 S900\nN30 G00 X32 Z2\nN40 G65 H01 P101 Q30000\nN60 M30\n";
    for (program, macros, code, at) in [
        (with_hash, "off", 2, "gsk.nc:5:14"),
        (with_hash, "on", 1, "gsk.nc:5:9"),
        (plain, "off", 1, "gsk.nc:5:9"),
    ] {
        let (dir, path) = temp_program("gsk.nc", program.as_bytes());
        let out = latsim(&[
            "run",
            path.to_str().unwrap(),
            "--control",
            "gsk980",
            "--macro",
            macros,
            "--stock",
            "30x70",
            "--json",
            dir.path().join("r.json").to_str().unwrap(),
            "--quiet",
        ]);
        assert_eq!(out.code, code, "{}", out.stderr);
        assert!(out.stderr.contains("custom macro A"), "{}", out.stderr);
        assert!(out.stderr.contains(at), "{}", out.stderr);
        assert!(!out.stderr.contains("vacant"), "{}", out.stderr);
    }
}

/// Field run 10 (B2): a FANUC punch-out lists its programs in number order, so the edge-break
/// subprogram O0020 (ending M99) stands before the main program O0010 that calls it. The main
/// program is O0010 (LS-MAIN-PROGRAM says so): its turning runs, then the call, clean. Read as
/// the main program, O0020 rapided from the machine's home diagonally into the Ø44 bar: a
/// false crash, and the part was never turned.
#[test]
fn a_subprogram_listed_before_its_caller_is_not_run_as_the_main_program() {
    let text = "%\nO0020 (EDGE BREAK)\nG00 X42. Z-38.\nG01 X39. Z-39.5 F0.08\nG00 U6.\nM99\n\
                O0010 (SHAFT)\nG21 G40 G99\nT0101\nG96 S180 M03\nG00 X44. Z2.\n\
                G90 X40. Z-40. F0.25\nG00 X44. Z-38.\nM98 P0020\nG00 X100. Z100.\nM30\n%\n";
    let (code, v, stderr) = run_json("sub-first.nc", text.as_bytes(), "fanuc-a", "44x60");
    assert_eq!(code, 0, "{stderr}");
    let main = &v["warnings"][0];
    assert!(
        main["code"] == "LS-MAIN-PROGRAM" && main["line"] == 7,
        "{main}"
    );
    assert_eq!(v["title"], "O0010", "{}", v["title"]);
    // the G90 took Ø44 down to Ø40 over 40 mm: 80 mm² of the half section, and the edge break
    let removed = v["removed_area_mm2"].as_f64().unwrap();
    assert!(removed > 80.0 && removed < 82.0, "{removed}");
}
