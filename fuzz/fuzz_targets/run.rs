//! The whole run on a small blank: read, expand, remove, analyse, write every report.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let Ok(program) = gcode::parse(&text) else {
        return;
    };
    let machine = expander::Machine::from_toml("power_on_feed = 100.0").expect("a valid profile");
    let tp = expander::expand(&program, &machine, &Default::default());
    let blank = stock::Blank::bar(40.0, 30.0, 0.0, None).expect("a valid blank");
    let tools = stock::ToolTable::empty();
    let sim = stock::simulate(&blank, &tools, &tp.segments, &Default::default(), &mut |_| {});
    let _ = stock::area(&sim.final_shapes);
});
