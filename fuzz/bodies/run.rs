// The body of the `run` fuzz target (`fuzz/fuzz_targets/run.rs`), also run on sample
// inputs by `tests/fuzz_bodies.rs` so that it keeps compiling. Plain comments: this
// file is `include!`d.
use std::sync::OnceLock;

const TOOLS: &str = r#"
[[tool]]
t = 1
kind = "turning"
insert = "CNMG 120408"
holder = "PCLNR 2525M12"
[[tool]]
t = 2
kind = "grooving"
width = 3.0
width_dir = "+z"
shank_dir = "+x"
reach = 8.0
[[tool]]
t = 3
kind = "turning"
insert = "VBMT 160404"
holder = "SVJBR 2525M16"
"#;

/// Programs expanding to more moves are not simulated here.
const MAX_MOVES: usize = 20_000;

/// Programs stamping a thread tool more often are not simulated here.
const MAX_STAMPS: f64 = 300.0;

/// A Φ30 shaft with a Φ20 neck: the part every program is compared with.
const TARGET: &[[f64; 2]] = &[[0.0, 0.0], [0.0, 15.0], [-10.0, 15.0], [-10.0, 10.0], [-20.0, 10.0], [-20.0, 15.0], [-30.0, 15.0], [-30.0, 0.0]];

fn fixtures() -> &'static (expander::Machine, stock::Blank, stock::ToolTable, Vec<stock::Shape>) {
    static F: OnceLock<(expander::Machine, stock::Blank, stock::ToolTable, Vec<stock::Shape>)> =
        OnceLock::new();
    F.get_or_init(|| {
        let machine = expander::Machine::from_toml("power_on_feed = 100.0").expect("a valid profile");
        let blank = stock::Blank::bar(40.0, 30.0, 0.0, None).expect("a valid blank");
        let tools = stock::ToolTable::from_toml(TOOLS).expect("a valid tool table");
        let outer: Vec<[f64; 2]> = TARGET.to_vec(); // counter-clockwise in (z, r)
        let part = vec![stock::Shape { outer, holes: vec![] }];
        (machine, blank, tools, part)
    })
}

/// One fuzz input: the whole pipeline after reading, as `latsim run` wires it
/// (`analysis::pipeline`: removal, intents, deviation, workholding, threads, verdict),
/// against the program's own shapes or, when the input's length is odd, a drawn part.
pub(crate) fn body(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let Ok(program) = gcode::parse(&text) else {
        return;
    };
    let (machine, blank, tools, part) = fixtures();
    let tp = expander::expand(&program, machine, &Default::default());
    // a move budget, like `interpret`'s: long legitimate programs (a G75 with a 0.002 mm
    // step: 58 510 moves, 0.5 s in release) exceed the 10 s timeout only under coverage
    // instrumentation; the benches and the found inputs cover large programs
    if tp.segments.len() > MAX_MOVES {
        return;
    }
    // and a stamp budget: 1 680 stamps of an 80° insert (G92 passes at the modal F0.1 of a
    // G01: lead 0.1 over 28 mm) take 2.2 s in release, > 10 s instrumented
    let stamps: f64 = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread && s.lead > 0.0)
        .map(|s| (s.to.z - s.from.z).abs() / s.lead)
        .sum();
    if stamps > MAX_STAMPS {
        return;
    }
    let intents = if data.len() % 2 == 1 {
        analysis::Intents::Target(part.clone())
    } else {
        analysis::Intents::Program
    };
    let settings = analysis::Settings { blank, tools, machine, fixture: None, tol: 0.01 };
    let (sim, findings) =
        analysis::pipeline(&tp, &intents, &settings, &Default::default(), &mut |_| {});
    let _ = stock::area(&sim.final_shapes);
    let _ = findings.verdict;
}
