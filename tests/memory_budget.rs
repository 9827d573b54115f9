//! `run --max-memory SIZE` (issue 32): a run over its memory budget stops with a message
//! naming what grew and exit 2; in a batch the program holding the most stops, its verdict
//! line says so, and the others get their verdicts.

use std::process::{Command, Output};

/// A plain turning pass: four moves.
const SMALL: &str = "G21 G99\nT0101\nG0 X52 Z2 M03 S800\nG1 X48 F0.2\nZ-20\nG0 X52\nM30\n";

/// A thread cut as `passes` single G32 passes 0.001 mm apart (the CAM pattern of issue 32).
fn thread_passes(passes: usize) -> String {
    let mut text = String::from("G21 G99\nT0101\nG0 X52 Z2 M03 S800\n");
    for k in 0..passes {
        let x = 47.0 - 0.001 * k as f64;
        text.push_str(&format!(
            "G00 X{x:.3} Z0.5\nG32 Z-17.3 F1.5\nG00 X52\nZ0.5\n"
        ));
    }
    text + "M30\n"
}

/// A message as one line: the terminal's wrapping and frame taken out.
fn one_line(stderr: &[u8]) -> String {
    String::from_utf8_lossy(stderr)
        .replace('│', " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

fn latsim(dir: &std::path::Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_latsim"))
        .current_dir(dir)
        .args([
            "run",
            "--stock",
            "50x40",
            "--reports",
            "json",
            "--out",
            "out",
        ])
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

/// Any process holds more than a megabyte: the run stops, exit 2, and the message says
/// the budget, how far it got, what the run held and the flag; with room it is clean.
#[test]
fn a_run_over_its_budget_stops_with_exit_2_and_says_what_grew() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("small.nc"), SMALL).unwrap();
    let over = latsim(dir.path(), &["small.nc", "--max-memory", "1M"]);
    let stderr = one_line(&over.stderr);
    assert_eq!(over.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("over the memory budget of 1 MiB: the process held"),
        "{stderr}"
    );
    // (a program of up to 5 000 moves ends an epoch at each of the HTML player's 29 counts,
    // where the budget is looked at: here after every move)
    assert!(stderr.contains("after 1 move;"), "{stderr}");
    assert!(stderr.contains("this run's removal held"), "{stderr}");
    assert!(stderr.contains("--max-memory"), "{stderr}");
    assert!(!dir.path().join("out/small.json").exists());

    let room = latsim(dir.path(), &["small.nc", "--max-memory", "8G"]);
    assert_eq!(room.status.code(), Some(0), "{room:?}");
    assert!(dir.path().join("out/small.json").exists());

    let bad = latsim(dir.path(), &["small.nc", "--max-memory", "8X"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("unknown unit `X`"));
}

/// Two programs side by side over a budget of a megabyte: the larger stops with its own
/// verdict line, the smaller is simulated to its verdict and its report written.
#[test]
fn in_a_batch_the_program_holding_the_most_stops_and_the_others_go_on() {
    let dir = tempfile::tempdir().unwrap();
    let progs = dir.path().join("progs");
    std::fs::create_dir(&progs).unwrap();
    std::fs::write(progs.join("a-small.nc"), SMALL).unwrap();
    std::fs::write(progs.join("b-thread.nc"), thread_passes(400)).unwrap();
    let out = latsim(dir.path(), &["progs", "--max-memory", "1M"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "{stdout}");
    let line = |name: &str| {
        stdout
            .lines()
            .find(|l| l.contains(name))
            .unwrap_or_else(|| panic!("no line for {name}: {stdout}"))
            .to_string()
    };
    assert!(line("a-small.nc").contains("CLEAN"), "{stdout}");
    let thread = line("b-thread.nc");
    assert!(
        thread.contains("UNUSABLE — over the memory budget of 1 MiB"),
        "{thread}"
    );
    assert!(thread.contains("the program's 1601 moves"), "{thread}");
    assert!(dir.path().join("out/a-small.json").exists());
    assert!(!dir.path().join("out/b-thread.json").exists());
}

/// `latsim diff` simulates each program side within the same budget as `run`: over it, the
/// side's message names the budget and the flag, exit 2, and no diff is written; with room
/// the two differ (exit 1).
#[test]
fn a_diff_over_its_budget_stops_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.nc"), SMALL).unwrap();
    std::fs::write(dir.path().join("b.nc"), SMALL.replace("X48", "X47.8")).unwrap();
    let diff = |budget: &str| {
        Command::new(env!("CARGO_BIN_EXE_latsim"))
            .current_dir(dir.path())
            .args([
                "diff", "a.nc", "b.nc", "--stock", "50x40", "--json", "d.json",
            ])
            .args(["--max-memory", budget])
            .env("NO_COLOR", "1")
            .output()
            .unwrap()
    };
    let over = diff("1M");
    let stderr = one_line(&over.stderr);
    assert_eq!(over.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("a.nc: over the memory budget of 1 MiB"),
        "{stderr}"
    );
    assert!(stderr.contains("--max-memory"), "{stderr}");
    assert!(!dir.path().join("d.json").exists());
    let room = diff("8G");
    assert_eq!(room.status.code(), Some(1), "{room:?}");
    assert!(dir.path().join("d.json").exists());
}
