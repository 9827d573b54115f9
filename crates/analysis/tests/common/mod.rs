//! The library pipeline as `latsim run` wires it, for the analysis crate's own tests.

use analysis::{Findings, Intents, Settings};
use expander::{Machine, Toolpath};
use stock::{Blank, SimOptions, Simulation, ToolTable};

/// Parse, expand (the table's noses and blades, its first entry as the start tool, like the
/// CLI) and run the pipeline against the program's own shapes at `--tol 0.01`.
pub(crate) fn judge(
    text: &str,
    blank: &Blank,
    tools: &ToolTable,
) -> (Toolpath, Simulation, Findings) {
    let program = gcode::parse(text).expect("program parses");
    let machine = Machine::default();
    let opts = expander::Options {
        tools: tools.facts(),
        start_tool: tools.numbers().first().copied(),
        ..Default::default()
    };
    let tp = expander::expand(&program, &machine, &opts);
    let settings = Settings {
        blank,
        tools,
        machine: &machine,
        fixture: None,
        tol: 0.01,
    };
    let (sim, findings) = analysis::pipeline(
        &tp,
        &Intents::Program,
        &settings,
        &SimOptions::default(),
        &mut |_| {},
    );
    (tp, sim, findings)
}

/// The program line of a move.
#[allow(dead_code)] // not every test file asks
pub(crate) fn line(tp: &Toolpath, segment: usize) -> u32 {
    tp.segments[segment].span.line
}
