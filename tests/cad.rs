//! CAD profiles on the command line (issue 15): `--stock-file`/`--target` take DXF
//! drawings of the half section, `--dxf F` writes the final section and the intended part.

mod common;
use common::*;
use std::path::Path;

/// Shoelace area of the JSON report's polygons (`stock` or `final`, points `[z, x]` with x
/// a diameter) in the half section (z, radius), mm².
fn json_area(polygons: &serde_json::Value) -> f64 {
    let ring = |r: &serde_json::Value| {
        let p: Vec<[f64; 2]> = r
            .as_array()
            .unwrap()
            .iter()
            .map(|q| [q[0].as_f64().unwrap(), q[1].as_f64().unwrap()])
            .collect();
        (0..p.len())
            .map(|i| {
                let (a, b) = (p[i], p[(i + 1) % p.len()]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>()
            .abs()
            / 4.0
    };
    polygons
        .as_array()
        .unwrap()
        .iter()
        .map(|poly| {
            let outer = ring(&poly["outer"]);
            let holes: f64 = poly["holes"]
                .as_array()
                .map_or(0.0, |h| h.iter().map(ring).sum());
            outer - holes
        })
        .sum()
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// DXF (R12 style, no header variables but the version) of a Φ40 × 40 bar's half section,
/// face at Z0, its outer corner rounded R5: LINEs and one ARC, drawing X = Z, Y = `scale`
/// × radius (1 for a radius drawing, 2 for a diameter drawing).
fn rounded_bar_dxf(scale: f64) -> String {
    let line = |a: [f64; 2], b: [f64; 2]| {
        format!(
            "  0\nLINE\n  8\n0\n 10\n{}\n 20\n{}\n 30\n0.0\n 11\n{}\n 21\n{}\n 31\n0.0\n",
            a[0],
            a[1] * scale,
            b[0],
            b[1] * scale
        )
    };
    let mut s = String::from(
        "  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1009\n  0\nENDSEC\n  0\nSECTION\n  2\nENTITIES\n",
    );
    s += &line([0.0, 0.0], [0.0, 15.0]);
    if scale == 1.0 {
        // centre (-5, 15), R5, from 0° (0, 15) counter-clockwise to 90° (-5, 20)
        s += "  0\nARC\n  8\n0\n 10\n-5.0\n 20\n15.0\n 30\n0.0\n 40\n5.0\n 50\n0.0\n 51\n90.0\n";
    } else {
        // in a diameter drawing the round is an ellipse: drawn as a bulged LWPOLYLINE would
        // be; here the corner is left square and the area below accounts for it
        s += &line([0.0, 15.0], [0.0, 20.0]);
        s += &line([0.0, 20.0], [-5.0, 20.0]);
    }
    s += &line([-5.0, 20.0], [-40.0, 20.0]);
    s += &line([-40.0, 20.0], [-40.0, 0.0]);
    s += &line([-40.0, 0.0], [0.0, 0.0]);
    s += "  0\nENDSEC\n  0\nEOF\n";
    s
}

const TURN: &[u8] = b"T0101\nM3 S1000\nG0 X30 Z2\nG1 Z-20 F200\nG0 X50\nZ2\nM30\n";

#[test]
fn a_dxf_blank_is_read_with_its_arcs_in_radius_and_diameter_drawings() {
    let (dir, prog) = temp_program("turn.nc", TURN);
    let blank = |name: &str, text: String, x: &str| {
        let dxf = dir.path().join(name);
        std::fs::write(&dxf, text).unwrap();
        let out_json = dir.path().join(format!("{name}.json"));
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock-file",
            dxf.to_str().unwrap(),
            "--dxf-x",
            x,
            "--json",
            out_json.to_str().unwrap(),
        ]);
        assert!(out.code <= 1, "{}", out.stderr);
        json(&out_json)
    };
    // Φ40 × 40 = 20 × 40 = 800 mm², less the R5 round's corner 25 − 25π/4 = 5.365 mm².
    let v = blank("radius.dxf", rounded_bar_dxf(1.0), "radius");
    let area = json_area(&v["stock"]["polygons"]);
    assert!(
        (area - (800.0 - (25.0 - 25.0 * std::f64::consts::PI / 4.0))).abs() < 0.01,
        "{area}"
    );
    // The same bar drawn with Y = diameter and a square corner: 800 mm².
    let v = blank("diameter.dxf", rounded_bar_dxf(2.0), "diameter");
    let area = json_area(&v["stock"]["polygons"]);
    assert!((area - 800.0).abs() < 1e-6, "{area}");
    // Read as a radius drawing it would be a Φ80 bar: 1600 mm².
    let v = blank("diameter-as-radius.dxf", rounded_bar_dxf(2.0), "radius");
    assert!((json_area(&v["stock"]["polygons"]) - 1600.0).abs() < 1e-6);
}

#[test]
fn dxf_round_trip_of_a_target_with_arcs_is_within_half_a_micron() {
    let dir = tempfile::tempdir().unwrap();
    let dxf = dir.path().join("section.dxf");
    let target = asset("targets/tnrc-interference.toml");
    let run = |extra: &[&str]| {
        let mut args = vec![
            "run".to_string(),
            asset("programs/tnrc-interference.nc").display().to_string(),
            "--stock".into(),
            "42x40".into(),
            "--tools".into(),
            asset("tools/seed004-v35-r1.toml").display().to_string(),
            "--quiet".into(),
        ];
        args.extend(extra.iter().map(|s| s.to_string()));
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        latsim(&args)
    };
    let json1 = dir.path().join("toml.json");
    let out = run(&[
        "--target",
        target.to_str().unwrap(),
        "--dxf",
        dxf.to_str().unwrap(),
        "--json",
        json1.to_str().unwrap(),
    ]);
    assert!(out.code <= 1, "{}", out.stderr);
    // The intended layer against the original profile with its R0.5 fillet, the arc
    // chorded 100 times finer than the check.
    let original =
        stock::profile_from_toml(&std::fs::read_to_string(&target).unwrap(), 1e-6).unwrap();
    let read = |layer: &'static str| {
        let opts = tooling_iso::dxf_io::ReadOptions {
            layer: Some(layer),
            ..Default::default()
        };
        let rings: Vec<Vec<[f64; 2]>> = tooling_iso::dxf_io::read_profile_file(&dxf, &opts)
            .unwrap()
            .into_iter()
            .map(|r| r.into_iter().map(|p| [p.z, p.r]).collect())
            .collect();
        stock::Blank::from_rings(&rings, "").shapes
    };
    let h = stock::hausdorff(&read("INTENDED"), &original);
    assert!(h <= 0.0005, "INTENDED layer off the original by {h} mm");
    // The PART layer is the report's final section.
    let v = json(&json1);
    let part = read("PART");
    let area = stock::area(&part);
    let final_area = json_area(&v["final"]);
    assert!((area - final_area).abs() < 1e-4, "{area} vs {final_area}");
    // Read back as the target, the verdict and the findings are those of the TOML target.
    let json2 = dir.path().join("dxf.json");
    let out2 = run(&[
        "--target",
        dxf.to_str().unwrap(),
        "--json",
        json2.to_str().unwrap(),
    ]);
    assert_eq!(out2.code, out.code, "{}", out2.stderr);
    let w = json(&json2);
    assert_eq!(w["verdict"], v["verdict"]);
    assert_eq!(
        w["gouges"].as_array().map(Vec::len),
        v["gouges"].as_array().map(Vec::len)
    );
}

#[test]
fn a_bad_dxf_is_a_clear_error() {
    let (dir, prog) = temp_program("turn.nc", TURN);
    let open = dir.path().join("open.dxf");
    let text = rounded_bar_dxf(1.0);
    // drop the closing LINE: the outline no longer closes
    let cut = text.rfind("  0\nLINE").unwrap();
    std::fs::write(&open, format!("{}  0\nENDSEC\n  0\nEOF\n", &text[..cut])).unwrap();
    let not_dxf = dir.path().join("notes.dxf");
    std::fs::write(&not_dxf, "this is not a drawing\n").unwrap();
    for (f, want) in [(&open, "open"), (&not_dxf, "DXF")] {
        let out = latsim(&[
            "run",
            prog.to_str().unwrap(),
            "--stock-file",
            f.to_str().unwrap(),
            "--json",
            dir.path().join("x.json").to_str().unwrap(),
        ]);
        assert_eq!(out.code, 2, "{}", out.stderr);
        assert!(out.stderr.contains(want), "{}", out.stderr);
        assert!(!dir.path().join("x.json").exists());
    }
}
