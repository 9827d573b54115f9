//! Prints what the reader makes of each file, under every reading option, so a change to
//! the reader can be checked for exactness by diffing two dumps:
//! `cargo run --release -p gcode --example dump -- OUT_DIR FILE...` writes one text per file
//! (named after its path, `/` as `%`); `-` as `OUT_DIR` prints everything to stdout.

use gcode::{parse_with, ReadOptions};
use macro_b::Dialect;
use std::fmt::Write as _;

fn main() {
    let mut args = std::env::args().skip(1);
    let Some(out) = args.next() else {
        eprintln!("usage: dump OUT_DIR|- FILE...");
        std::process::exit(2);
    };
    let options = [
        ("default", ReadOptions::default()),
        (
            "decimal_comma",
            ReadOptions {
                decimal_comma: true,
                macros: None,
                x_radius: false,
            },
        ),
        (
            "fanuc",
            ReadOptions {
                decimal_comma: false,
                macros: Some(Dialect::Fanuc),
                x_radius: false,
            },
        ),
        (
            "haas",
            ReadOptions {
                decimal_comma: true,
                macros: Some(Dialect::Haas),
                x_radius: false,
            },
        ),
    ];
    for path in args {
        let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let text = String::from_utf8_lossy(&bytes);
        let mut dump = String::new();
        for (name, o) in options {
            let _ = writeln!(dump, "== {name}\n{:#?}", parse_with(&text, o));
        }
        if out == "-" {
            print!("{dump}");
        } else {
            let name = path.trim_start_matches('/').replace('/', "%");
            std::fs::write(format!("{out}/{name}.txt"), dump).expect("write the dump");
        }
    }
}
