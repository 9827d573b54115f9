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
