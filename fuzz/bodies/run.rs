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

/// Programs expanding to more moves are not simulated here: the instrumented build runs
/// 15–20× slower than release, and a program whose every move crashes costs about 1 ms a
/// move in release with the diagnosis (a 5 258-move G75 with 1 710 crashes: 1.2 s, 15–20 s
/// here, past the 10 s timeout). Long programs are the reader's and interpreter's targets'
/// and the benchmarks'.
const MAX_MOVES: usize = 2_500;

/// Blocks a program may execute here (a macro loop): the CLI's budget is 10^7, the
/// instrumented build runs ~30× slower than release.
const MAX_BLOCKS: usize = 200_000;

/// Programs stamping a thread tool more often are not simulated here.
const MAX_STAMPS: f64 = 300.0;

/// A Φ30 shaft with a Φ20 neck: the part every program is compared with.
const TARGET: &[[f64; 2]] = &[[0.0, 0.0], [0.0, 15.0], [-10.0, 15.0], [-10.0, 10.0], [-20.0, 10.0], [-20.0, 15.0], [-30.0, 15.0], [-30.0, 0.0]];

/// A chuck gripping the bar's last 10 mm and a tailstock centre on its face (`--chuck`).
const CHUCK: &str = "grip=10,jaw=15,od=160,depth=60,tail=1,quill=30,quill_length=80";

struct Fixtures {
    machine: expander::Machine,
    blank: stock::Blank,
    tools: stock::ToolTable,
    part: Vec<stock::Shape>,
    fixture: analysis::Fixture,
}

fn fixtures() -> &'static Fixtures {
    static F: OnceLock<Fixtures> = OnceLock::new();
    F.get_or_init(|| {
        let blank = stock::Blank::bar(40.0, 30.0, 0.0, None).expect("a valid blank");
        let holding = expander::Workholding::from_compact(CHUCK).expect("a valid chuck");
        let fixture = analysis::Fixture::new(&holding, &blank)
            .expect("the chuck grips the bar")
            .expect("a chuck is given");
        Fixtures {
            machine: expander::Machine::from_toml("power_on_feed = 100.0").expect("a valid profile"),
            blank,
            tools: stock::ToolTable::from_toml(TOOLS).expect("a valid tool table"),
            // counter-clockwise in (z, r)
            part: vec![stock::Shape { outer: TARGET.to_vec(), holes: vec![] }],
            fixture,
        }
    })
}

/// Re-runs the diagnosis may make per input (of its 12): each is a whole run, and the first
/// two reach every kind of change (a tool, a split rapid, a fed rapid).
const MAX_RERUNS: usize = 2;

/// One fuzz input: the whole run as `latsim run` wires it (`src/run.rs` `run_one`,
/// `src/job.rs`, `src/rerun.rs`), after reading — the interpreter told the tool table's
/// noses and blades, then `analysis::pipeline` (removal, intents, deviation, crashes and
/// scrapes, workholding, threads, verdict) and `analysis::diagnose::diagnose` (causes, and
/// remedies checked by re-running the changed program). The input's length picks the
/// settings, so that every combination is reached: bit 0 the intended part (a drawn shaft
/// or the program's own shapes), bit 1 the workholding (a chuck and tailstock or none),
/// bit 2 custom macro B (FANUC rules) on.
pub(crate) fn body(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let f = fixtures();
    let macros = data.len() & 4 != 0;
    let Some(tp) = expanded(&text, macros, &f.tools) else {
        return;
    };
    let intents = if data.len() & 1 != 0 {
        analysis::Intents::Target(f.part.clone())
    } else {
        analysis::Intents::Program
    };
    let settings = analysis::Settings {
        blank: &f.blank,
        tools: &f.tools,
        machine: &f.machine,
        fixture: (data.len() & 2 != 0).then_some(&f.fixture),
        tol: 0.01,
    };
    let (sim, mut findings) =
        analysis::pipeline(&tp, &intents, &settings, &Default::default(), &mut |_| {});
    let rerun = Rerunner {
        text: &text,
        macros,
        intents: &intents,
        settings: &settings,
        left: std::cell::Cell::new(MAX_RERUNS),
    };
    analysis::diagnose::diagnose(&mut findings, (&tp, &sim.final_shapes, &text), &settings, &rerun);
    let _ = stock::area(&sim.final_shapes);
    let _ = findings.verdict;
}

/// The program read and expanded as `src/input.rs` `load_program` does, with this target's
/// budgets: `None` when it cannot be read or is past them.
fn expanded(text: &str, macros: bool, tools: &stock::ToolTable) -> Option<expander::Toolpath> {
    let read = gcode::ReadOptions {
        macros: macros.then_some(macro_b::Dialect::Fanuc),
        ..Default::default()
    };
    let program = gcode::parse_with(text, read).ok()?;
    let opts = expander::Options {
        tools: tools.facts(),
        start_tool: tools.numbers().first().copied(),
        max_segments: MAX_MOVES + 1,
        max_blocks: MAX_BLOCKS,
        macros: macros.then(|| {
            let mut o = macro_b::Options::fanuc();
            o.limits.max_blocks = MAX_BLOCKS as u64;
            o
        }),
        ..Default::default()
    };
    let tp = expander::expand(&program, &fixtures().machine, &opts);
    // a move budget, like `interpret`'s: long legitimate programs (a G75 with a 0.002 mm
    // step: 58 510 moves, 0.5 s in release) exceed the timeout only under coverage
    // instrumentation; the benches and the found inputs cover large programs
    if tp.segments.len() > MAX_MOVES {
        return None;
    }
    // and a stamp budget: 1 680 stamps of an 80° insert (G92 passes at the modal F0.1 of a
    // G01: lead 0.1 over 28 mm) take 2.2 s in release, > 10 s instrumented. Leads counted
    // along the longer axis, as the removal stamps (`stock::sweep::thread`): a G32 along X
    // (a face scroll) of 560 leads of 0.05 mm slipped past a count along Z (1.1 s in
    // release with the diagnosis's re-runs, past the timeout on the loaded box)
    let stamps: f64 = tp
        .segments
        .iter()
        .filter(|s| s.motion == expander::Motion::Thread && s.lead > 0.0)
        .map(|s| (s.to.z - s.from.z).abs().max((s.to.r - s.from.r).abs()) / s.lead)
        .sum();
    (stamps <= MAX_STAMPS).then_some(tp)
}

/// `src/rerun.rs`'s re-run: the program's text changed, or the table with one tool
/// replaced, read and run again on the same blank, machine and intents.
struct Rerunner<'a> {
    text: &'a str,
    macros: bool,
    intents: &'a analysis::Intents,
    settings: &'a analysis::Settings<'a>,
    /// Re-runs left for this input ([`MAX_RERUNS`]).
    left: std::cell::Cell<usize>,
}

impl analysis::diagnose::Rerun for Rerunner<'_> {
    fn rerun(&self, change: &analysis::diagnose::Change) -> Option<analysis::diagnose::Rerunning> {
        use analysis::diagnose::Change;
        self.left.set(self.left.get().checked_sub(1)?);
        let tools = self.settings.tools;
        let (text, tools) = match change {
            Change::Tool { t, entry } => (self.text.to_string(), tools.replaced(*t, entry).ok()?),
            program => (program.edited(self.text)?, tools.clone()),
        };
        let toolpath = expanded(&text, self.macros, &tools)?;
        let settings = analysis::Settings {
            tools: &tools,
            ..*self.settings
        };
        let (sim, findings) =
            analysis::pipeline(&toolpath, self.intents, &settings, &Default::default(), &mut |_| {});
        Some(analysis::diagnose::Rerunning {
            findings,
            part: sim.final_shapes,
            alarms: toolpath.alarms.len(),
        })
    }
}

