//! The fuzz targets' bodies (`fuzz/bodies/`), compiled here and run on sample inputs. The
//! fuzz crate needs nightly-only flags and is its own workspace, so `cargo test` would not
//! notice a target that no longer compiles against the crates (one did not, for two
//! sessions); its bodies are included here instead. Each must take any bytes without a
//! panic: the samples are the shipped programs and tables, and damaged copies of them.

mod common;

mod read {
    include!("../fuzz/bodies/read.rs");
}
mod interpret {
    include!("../fuzz/bodies/interpret.rs");
}
mod interpret_macro {
    include!("../fuzz/bodies/interpret_macro.rs");
}
mod run {
    include!("../fuzz/bodies/run.rs");
}
mod toml_tools {
    include!("../fuzz/bodies/toml_tools.rs");
}
mod toml_machine {
    include!("../fuzz/bodies/toml_machine.rs");
}
mod toml_profile {
    include!("../fuzz/bodies/toml_profile.rs");
}
mod chuck {
    include!("../fuzz/bodies/chuck.rs");
}
mod decode {
    include!("../fuzz/bodies/decode.rs");
}
mod dxf {
    include!("../fuzz/bodies/dxf.rs");
}

use std::path::Path;

/// The files of `dir` (relative to the repository) ending in `ext`, sorted, as bytes.
fn files(dir: &str, ext: &str) -> Vec<Vec<u8>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "no .{ext} in {}", dir.display());
    paths.iter().map(|p| std::fs::read(p).unwrap()).collect()
}

/// Each sample, and its first half, and the sample with every 7th byte flipped: damaged
/// inputs reach the error paths a fuzzer starts from.
fn with_damage(samples: Vec<Vec<u8>>) -> Vec<Vec<u8>> {
    let mut out = vec![];
    for s in samples {
        out.push(s[..s.len() / 2].to_vec());
        let mut flipped = s.clone();
        for b in flipped.iter_mut().step_by(7) {
            *b ^= 0x20;
        }
        out.push(flipped);
        out.push(s);
    }
    out
}

#[test]
fn reader_and_interpreter_bodies_take_the_programs() {
    let programs = with_damage(files("assets/programs", "nc"));
    for p in &programs {
        read::body(p);
        interpret::body(p);
        interpret_macro::body(p);
    }
}

/// Every program of the corpus (each folder, sidecars aside), whole and damaged: the
/// reader's blocks read again from the text are the blocks it read.
#[test]
fn reader_body_takes_the_corpus() {
    let programs: Vec<Vec<u8>> = common::files_under(&common::asset("corpus"), "nc", &[])
        .iter()
        .map(|p| std::fs::read(p).unwrap())
        .collect();
    assert!(programs.len() > 100, "{}", programs.len());
    for p in with_damage(programs) {
        read::body(&p);
    }
}

#[test]
fn run_body_takes_the_programs() {
    for p in with_damage(files("assets/programs", "nc")) {
        run::body(&p);
    }
}

#[test]
fn loader_bodies_take_the_tables() {
    for t in with_damage(files("assets/tools", "toml")) {
        toml_tools::body(&t);
    }
    for m in with_damage(files("assets/machines", "toml")) {
        toml_machine::body(&m);
    }
    for b in with_damage(files("assets/blanks", "toml")) {
        toml_profile::body(&b);
    }
    for c in [
        "grip=30,jaw=20",
        "grip=10",
        "grip=30,claw=2",
        "[chuck]\ngrip = 30\njaw = 20\n",
        "[chuck]\ngrip = -1\n",
        "",
    ] {
        chuck::body(c.as_bytes());
    }
}

/// Program files in other encodings than UTF-8 (the GBK program of the corpus, the seed with
/// comments in several scripts), whole and damaged, and the shipped programs.
#[test]
fn decode_body_takes_encoded_programs() {
    let mut programs = files("assets/programs", "nc");
    programs.extend(files("fuzz/seeds/decode", "nc"));
    programs.push(std::fs::read(common::asset("corpus/gsk980/gbk-comments.nc")).unwrap());
    for p in with_damage(programs) {
        decode::body(&p);
    }
}

/// The seed drawings (R12 lines, arcs and polylines, an `AutoCAD` 2000 bore, latsim's
/// layers), whole and damaged; damaged ones that are not UTF-8 go through a file.
#[test]
fn dxf_body_takes_the_seed_drawings() {
    let drawings = files("fuzz/seeds/dxf", "dxf");
    for d in &drawings {
        // each seed is a drawing the reader takes, so the fuzzer starts inside it
        let text = std::str::from_utf8(d).unwrap();
        let rings = tooling_iso::dxf_io::read_profile_str(text, &Default::default());
        assert!(rings.is_ok_and(|r| !r.is_empty()), "{text}");
    }
    for d in with_damage(drawings) {
        dxf::body(&d);
    }
    dxf::body(b"AutoCAD Binary DXF\r\n\x1a\x00\xff\xfe\x00SECTION\x00");
}

/// Found by the `run` target (issue 37): this 900-byte mutated grooving program (G75 and
/// G75.1 pairs) made the `run` body grow past 4 GB in 43 s: the certainty test of a
/// guessed tool's crash took the difference of its core's sweep with every earlier sweep
/// near it in one boolean call, whose engine splits every edge at every other's ends.
/// The earlier sweeps are now joined half by half first (0.8 s, 24 MB in release).
#[test]
fn run_body_on_a_found_g75_1_program_ends_in_bounded_memory() {
    let input = std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/findings/run-g75-1-memory.bin"),
    )
    .unwrap();
    run::body(&input);
}

/// Found by the `run` target (2026-11-27, a timeout): a 150-byte G73 (`U6 R100` over an R6
/// arc) whose holder crashes into the chuck 200 times. Each move's sweep met the chuck in
/// one boolean of all its pieces (a chord's each, overlapping the next); now only the pieces
/// near the obstacle go in (3.8 → 0.7 s in release). (The other timeout of that day, a G92
/// over a G75 part of thousands of notches, `run-g92-over-g75-timeout.bin`, is past this
/// body's move budget now; its fix, the thread measures in one sweep along Z, is tested in
/// `analysis::measure::surface`.)
#[test]
fn run_body_on_a_found_g73_crashing_into_the_chuck_ends() {
    let input = std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/findings/run-g73-chuck-timeout.bin"),
    )
    .unwrap();
    run::body(&input);
}

/// Found by the `run` target (2026-11-28, a timeout on the loaded box): a mutated grooving
/// program whose garbled `G32.X00` became a thread along X, 560 leads of 0.05 mm (a face
/// scroll), stamped 560 times into one tile. The body's stamp budget counted leads along Z
/// only; it now counts them along the longer axis, as the removal stamps, and leaves this
/// program out (1.1 s in release with the diagnosis's re-runs: heavy, not endless).
#[test]
fn run_body_on_a_found_radial_thread_ends() {
    let input = std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/findings/run-radial-thread-stamps.bin"),
    )
    .unwrap();
    run::body(&input);
}

/// Found by the `run` target on 3c53b18 (2026-11-28, sixth session; a timeout on the loaded
/// box): another mutated grooving program with a garbled `G32.X.00` and `M98` calls of
/// files that are not there. 0.39 s in release with the diagnosis's re-runs, 5.4 s in the
/// instrumented build on an idle core: heavy, not endless. Kept so that it stays so.
#[test]
fn run_body_on_a_found_mutated_grooving_program_ends() {
    let input = std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/findings/run-thread-stamps-2.bin"),
    )
    .unwrap();
    run::body(&input);
}
