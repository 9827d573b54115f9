//! Tools as machinists name them (issue 15): an ISO insert in an ISO holder cuts exactly
//! like the same tool written in the explicit fields.

mod common;
use common::*;

fn report(tools: &str) -> serde_json::Value {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("r.json");
    let out = latsim(&[
        "run",
        asset("programs/seed004-contour.nc").to_str().unwrap(),
        "--stock",
        "36x40",
        "--tools",
        asset(tools).to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(out.code <= 1, "{}", out.stderr);
    serde_json::from_str(&std::fs::read_to_string(json).unwrap()).unwrap()
}

#[test]
fn cnmg_in_pclnr_cuts_seed_004_like_the_explicit_tool() {
    let mut iso = report("tools/cnmg-pclnr.toml");
    let mut explicit = report("tools/c80-r08-95.toml");
    // the report names the designation; everything else is the same, number for number
    let tools = iso["tools"][0].as_str().unwrap().to_string();
    assert!(tools.contains("(CNMG 120408 in PCLNR 2525M12)"), "{tools}");
    assert!(tools.contains("C 80°, r0.8, tip 3, κr 95°"), "{tools}");
    iso["tools"] = serde_json::Value::Null;
    explicit["tools"] = serde_json::Value::Null;
    iso["program"] = serde_json::Value::Null;
    explicit["program"] = serde_json::Value::Null;
    assert_eq!(iso, explicit);
    assert!(iso["removed_area_mm2"].as_f64().unwrap() > 50.0);
}
