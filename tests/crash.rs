//! A rapid into the stock is a crash reported at its line; a rapid in air is not.

mod common;
use common::*;

const PROGRAM: &str = "O0100;
G99 M03 S600 T0101;
G00 X50. Z5.;
G01 X36. F0.2;
G01 Z-20.;
G01 X50.;
G00 Z5.;
G00 X30. Z-10.;
M30;
";

#[test]
fn rapid_into_stock_is_reported_at_its_line_with_area() {
    let blank = stock::Blank::bar(40.0, 50.0, 0.0, None).unwrap();
    let tools = stock::ToolTable::from_toml(&read(&asset("tools/v35-sharp.toml"))).unwrap();
    let (tp, sim) = simulate(PROGRAM, &blank, &tools);
    assert_eq!(sim.crashes.len(), 1, "{:?}", sim.crashes);
    let c = &sim.crashes[0];
    let seg = &tp.segments[c.segment];
    assert_eq!(seg.span.line, 8, "crash at the G00 X30. Z-10. block");
    // The tip plunges from (Z5, r25) to (Z-10, r15) through the Φ36 turned surface: real stock.
    assert!(c.area > 1.0, "area {}", c.area);
    assert!(
        c.at[1] <= 18.0 + 1e-6 && c.at[0] <= 0.0 + 1e-6,
        "first contact {:?}",
        c.at
    );
}

#[test]
fn cli_exit_1_and_crash_in_json() {
    let (dir, prog) = temp_program("crash.nc", PROGRAM.as_bytes());
    let json = dir.path().join("crash.json");
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--stock",
        "40x50",
        "--tools",
        asset("tools/v35-sharp.toml").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(out.stderr.contains("crash.nc:8:1: crash"), "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&read(&json)).unwrap();
    assert_eq!(v["verdict"], "crash");
    assert_eq!(v["crashes"][0]["line"], 8);
}

/// A pin parted off a Φ20 bar falls: with the 3 mm blade (reference corner on its −Z side,
/// blade toward +Z) at Z-13 the kerf Z-13…-10 goes down to the axis, the pin Z-10…0 is
/// free of the bar held at its left end. A rapid down through where the pin was then meets
/// air: no crash (before, 2 mm into the pin). The section keeps the pin where it was: the
/// removed area is the kerf alone, 3 × 10 = 30 mm². The same rapid before the part-off is a
/// crash.
#[test]
fn a_parted_off_piece_has_fallen() {
    let tools = asset("corpus/tools/shop.toml");
    let run = |program: &str| {
        report_of(
            program,
            &["--stock", "20x40", "--tools", tools.to_str().unwrap()],
        )
    };
    let j = run("G99 M03 S600 T0505\nG00 X22 Z-13\nG01 X0 F0.05\nG00 X22\nG00 Z-6\nG00 X16\nG00 X30 Z50\nM30\n");
    assert_eq!(j["verdict"], "clean", "{j:#}");
    assert!(j["crashes"].as_array().unwrap().is_empty(), "{j:#}");
    let removed = j["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - 30.0).abs() < 1e-6, "{removed}");
    // the pin is in the final section: two pieces, the pin Z-10…0 and the bar Z-40…-13
    assert_eq!(j["final"].as_array().unwrap().len(), 2, "{j:#}");
    let j = run("G99 M03 S600 T0505\nG00 X22 Z-6\nG00 X16\nG00 X30 Z50\nM30\n");
    assert_eq!(j["verdict"], "crash", "{j:#}");
}

/// Facing to the centre with a sharp V insert, 40 passes 0.5 mm apart: between passes a pip
/// stays at the axis that the next pass cuts; none of it is a part that falls: the removed
/// area is the faced slab, 20 × 62.5 = 1250 mm² (with the pips kept as fallen pieces it
/// came out smaller).
#[test]
fn facing_to_the_centre_parts_nothing_off() {
    let mut program = String::from("G98 M03 S600 T0101\nG00 X130 Z5\n");
    for k in 1..=40 {
        program += &format!(
            "G00 Z{:.2}\nG01 X0 F200\nG00 Z2\nG00 X130\n",
            -0.5 * f64::from(k)
        );
    }
    program += "M30\n";
    let tools = asset("tools/v35-sharp.toml");
    let j = report_of(
        &program,
        &["--stock", "125x110", "--tools", tools.to_str().unwrap()],
    );
    let removed = j["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - 1250.0).abs() < 1e-3, "{removed}");
}

/// A tube (Φ40, bore Φ20) is parted off when the blade reaches the bore, not the axis: at
/// X18 the ring Z-10…0 is free. A rapid down through where it was meets air; the section
/// keeps the ring, the removed area is the kerf through the wall, 3 × 10 = 30 mm².
#[test]
fn a_tube_parted_off_at_its_bore_falls() {
    let tools = asset("corpus/tools/shop.toml");
    let args = [
        "--stock",
        "40x40",
        "--bore",
        "20",
        "--tools",
        tools.to_str().unwrap(),
    ];
    let j = report_of(
        "G99 M03 S600 T0505\nG00 X42 Z-13\nG01 X18 F0.05\nG00 X42\nG00 Z-6\nG00 X30\nG00 X50 Z50\nM30\n",
        &args,
    );
    assert_eq!(j["verdict"], "clean", "{j:#}");
    assert_eq!(j["final"].as_array().unwrap().len(), 2, "{j:#}");
    let removed = j["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - 3.0 * 10.0).abs() < 1e-6, "{removed}");
}

/// Field run 7 (B): a ring parted off into the hole the program drilled falls. A Φ20 bar
/// drilled Φ16 (T8) to Z-25 by the tip, then the 3 mm blade at Z-13 down to X10, inside
/// the hole: the ring Z-10…0 is free. A rapid down through where it was meets air (it was
/// a certain 5 mm crash: the blade had to reach the blank's own bore, 0 on a bar). The
/// removed area is the hole, 8 · (25 − 8 / tan 59°) + 8 · (8 / tan 59°) / 2 = 180.772 mm²,
/// and the kerf through the wall, 2 × 3 = 6 mm².
#[test]
fn a_ring_parted_off_into_its_drilled_hole_falls() {
    let tools = asset("corpus/tools/shop.toml");
    let j = report_of(
        "G99 M03 S600 T0808\nG00 X0 Z5\nG01 Z-25 F0.1\nG00 Z5\nT0505\nG00 X22\nG00 Z-13\nG01 X10 F0.05\nG00 X22\nG00 Z-6\nG00 X17\nG00 X50 Z50\nM30\n",
        &["--stock", "20x40", "--tools", tools.to_str().unwrap()],
    );
    assert_eq!(j["verdict"], "clean", "{j:#}");
    assert!(j["crashes"].as_array().unwrap().is_empty(), "{j:#}");
    let cone = 8.0 / 59f64.to_radians().tan();
    let hand = 8.0 * (25.0 - cone) + 8.0 * cone / 2.0 + 6.0;
    let removed = j["removed_area_mm2"].as_f64().unwrap();
    assert!((removed - hand).abs() < 1e-3, "{removed} vs {hand}");
}
