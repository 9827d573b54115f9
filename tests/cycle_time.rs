//! Cycle time against a hand computation: G99 feed per revolution under G96 constant
//! surface speed with a G50 S clamp, rapids at the machine's rates, a dwell.

mod common;
use common::*;

#[test]
fn g99_g96_program_time_matches_the_hand_computation() {
    let (dir, prog) = temp_program(
        "time.nc",
        b"O0001;\nG99 G50 S2000;\nG96 S150 M03 T0101;\nG00 X50. Z2.;\nG01 Z-48. F0.2;\nG00 X60.;\nG04 P2000;\nG97 S500;\nG01 Z-58. F0.1;\nG00 X200.;\nG96 S300;\nG00 X10. Z2.;\nG01 X4. F0.1;\nM30;\n",
    );
    let json = dir.path().join("t.json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "50x60",
        "--json",
        json.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(out.code <= 1, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    let t = v["cycle_time_s"].as_f64().unwrap();
    // default machine: home (Z150, X250), rapid X 6000 mm/min (radial), Z 8000 mm/min
    let rapid = |dz: f64, dr: f64| (dz.abs() / 8000.0).max(dr.abs() / 6000.0) * 60.0;
    let pi = std::f64::consts::PI;
    let mut hand = 0.0;
    hand += rapid(148.0, 100.0); // home -> (Z2, X50)
                                 // 50 mm at Φ50 under G96 S150: n = 1000·150 / (π·50) = 954.9 rev/min, 0.2 mm/rev
    hand += 50.0 / (0.2 * (1000.0 * 150.0 / (pi * 50.0))) * 60.0;
    hand += rapid(0.0, 5.0); // X60
    hand += 2.0; // G04 P2000
    hand += 10.0 / (0.1 * 500.0) * 60.0; // G97 S500: 10 mm at 0.1 mm/rev
    hand += rapid(0.0, 70.0); // X200
    hand += rapid(60.0, 95.0); // to (Z2, X10)
                               // G96 S300 facing from Φ10 to Φ4 at 0.1 mm/rev: n = 300000/(π·D) exceeds the 2000 clamp
                               // below Φ47.7, so the whole face runs at 2000 rev/min: 3 mm / (0.1 · 2000) min
    hand += 3.0 / (0.1 * 2000.0) * 60.0;
    eprintln!("cycle time {t:.4} s, hand computation {hand:.4} s");
    assert!((t - hand).abs() < 0.01, "cycle time {t} s, hand {hand} s");
    assert!(
        v["tools"][0].as_str().unwrap().contains(" s"),
        "{}",
        v["tools"]
    );
}
