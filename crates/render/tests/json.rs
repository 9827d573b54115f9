//! The JSON contract: field names, program coordinates (x = 2r), null deviation, verdict.
mod common;

use serde_json::Value;

fn parse(r: &render::Report) -> Value {
    serde_json::from_str(&render::json(r)).expect("valid JSON")
}

#[test]
fn field_names_are_the_contract() {
    let v = parse(&common::groove_bar());
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    for k in [
        "program",
        "title",
        "stock",
        "final",
        "removed_area_mm2",
        "removed_volume_mm3",
        "segments",
        "cycle_time_s",
        "alarms",
        "warnings",
        "crashes",
        "gouges",
        "deviation",
        "verdict",
        "tools",
        "tolerance_mm",
    ] {
        assert!(keys.contains(&k), "missing {k} in {keys:?}");
    }
    assert_eq!(v["stock"]["description"], "bar Ø40 × 60, face at Z0");
    assert!(v["stock"]["polygons"][0]["outer"].is_array());
    assert!(v["final"][0]["holes"].is_array());
    let w = &v["warnings"][0];
    assert_eq!(w["line"], 9);
    assert_eq!(w["column"], 1);
    assert_eq!(w["code"], "W-TOOL-DEFAULT");
    assert!(w["message"].as_str().unwrap().starts_with("T02"));
    let c = &v["crashes"][0];
    for k in ["line", "column", "z", "x", "area_mm2"] {
        assert!(!c[k].is_null(), "crash.{k}");
    }
    let g = &v["gouges"][0];
    for k in ["line", "z", "x", "area_mm2", "depth_mm"] {
        assert!(!g[k].is_null(), "gouge.{k}");
    }
    let d = &v["deviation"];
    for k in [
        "overcut_area_mm2",
        "undercut_area_mm2",
        "max_overcut_mm",
        "max_undercut_mm",
    ] {
        assert!(d[k].is_number(), "deviation.{k}");
    }
    assert_eq!(v["segments"], 11);
    assert_eq!(v["cycle_time_s"], 102.0);
    assert_eq!(v["tools"][0], "T01 turning D 55°, r0.4, tip 3");
}

#[test]
fn coordinates_are_program_diameters() {
    let v = parse(&common::groove_bar());
    // The blank's corner [z, r] = [0, 20] is [0, 40] in program coordinates.
    let outer = &v["stock"]["polygons"][0]["outer"];
    assert_eq!(outer[2][0], 0.0);
    assert_eq!(outer[2][1], 40.0);
    // The groove bottom r 14 -> X28.
    assert_eq!(v["final"][0]["outer"][5][1], 28.0);
    assert_eq!(v["crashes"][0]["x"], 36.0);
    assert_eq!(v["crashes"][0]["z"], -46.667);
    assert_eq!(v["gouges"][0]["x"], 28.0);
}

#[test]
fn rounding_to_six_decimals() {
    let mut r = common::groove_bar();
    r.final_part[0].outer[0] = [-60.123_456_789, 0.333_333_333_3];
    let v = parse(&r);
    assert_eq!(v["final"][0]["outer"][0][0], -60.123457);
    assert_eq!(v["final"][0]["outer"][0][1], 0.666667);
}

/// The JSON writes the verdict it is given (the analysis decides it, whatever the lists
/// hold), and a null deviation as `null`.
#[test]
fn deviation_null_and_verdicts() {
    let mut r = common::groove_bar();
    assert_eq!(parse(&r)["verdict"], "crash");
    for (v, word) in [
        (render::Verdict::Gouge, "gouge"),
        (render::Verdict::Alarm, "alarm"),
        (render::Verdict::Clean, "clean"),
    ] {
        r.verdict = v;
        assert_eq!(parse(&r)["verdict"], word);
    }
    r.deviation = None;
    let v = parse(&r);
    assert!(v["deviation"].is_null());
    assert!(v.as_object().unwrap().contains_key("deviation"));
}

#[test]
fn nan_never_makes_invalid_json() {
    let mut r = common::groove_bar();
    r.final_part[0].outer[1] = [f64::NAN, f64::INFINITY];
    r.cycle_time_s = f64::NAN;
    r.crashes[0].z = f64::NEG_INFINITY;
    let v = parse(&r);
    assert!(v["cycle_time_s"].is_null());
    assert!(v["final"][0]["outer"][1][0].is_null());
    assert!(v["crashes"][0]["z"].is_null());
    let empty = parse(&render::Report::default());
    assert_eq!(empty["final"], Value::Array(vec![]));
    assert_eq!(empty["verdict"], "clean");
}

#[test]
fn grooves_are_listed_in_program_coordinates() {
    let v = parse(&common::o0008_groove());
    let g = &v["grooves"][0];
    assert_eq!(g["line"], 2);
    assert_eq!(g["ring"][0], serde_json::json!([30.0, 50.0]));
    assert_eq!(g["ring"][3], serde_json::json!([-7.32, 50.0]));
    assert_eq!(
        parse(&common::groove_bar())["grooves"],
        serde_json::json!([])
    );
}
