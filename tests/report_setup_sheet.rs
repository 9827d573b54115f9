//! The HTML report's setup sheet as `latsim run` fills it (issue 35): every tool in order of
//! first use with the offsets the program called, its ISO designation from the tool table,
//! its time in cut and in all; the chuck, the jaws and the stick-out.

mod common;
use common::*;

const PROGRAM: &str = "O0035 (SETUP SHEET)
G21 G99 G18
G00 X100. Z100.
T0101 (OD ROUGH)
M03 S800
G00 X52. Z2.
G01 X46. F0.2
G01 Z-30.
G00 X52.
G00 Z2.
G01 X44.
G01 Z-20.
G00 X100. Z100.
T0212 (GROOVE, WEAR OFFSET 12)
G00 X50. Z-15.
G01 X40. F0.05
G00 X60.
G00 X100. Z100.
M30
";

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
"#;

/// The sheet of a two-tool program run with a tool table and `--chuck`.
#[test]
fn the_sheet_names_tools_offsets_designations_times_and_the_chuck() {
    let dir = tempfile::tempdir().unwrap();
    let prog = dir.path().join("O0035.nc");
    let tools = dir.path().join("tools.toml");
    std::fs::write(&prog, PROGRAM).unwrap();
    std::fs::write(&tools, TOOLS).unwrap();
    let out = latsim(&[
        "run",
        prog.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--stock",
        "50x80",
        "--tools",
        tools.to_str().unwrap(),
        "--chuck",
        "grip=20,jaw=20",
        "--reports",
        "html",
        "--out",
        dir.path().to_str().unwrap(),
        "--quiet",
    ]);
    assert!(out.code <= 1, "{}", out.stderr);
    let page = std::fs::read_to_string(dir.path().join("O0035.html")).unwrap();
    let sheet = &page[page.find(r#"<section id="ls-sheet">"#).unwrap()..];
    let sheet = &sheet[..sheet.find("</section>").unwrap()];
    let row = |t: &str| -> Vec<String> {
        let start = sheet
            .find(&format!("<td class=\"n\">{t}</td>"))
            .unwrap_or_else(|| panic!("no row {t}\n{sheet}"));
        let tr = &sheet[start..];
        let tr = &tr[..tr.find("</tr>").unwrap()];
        // each cell's text, its tags taken out
        tr.split("</td>")
            .map(|cell| {
                let mut text = String::new();
                let mut in_tag = false;
                for c in cell.chars() {
                    match c {
                        '<' => in_tag = true,
                        '>' => in_tag = false,
                        c if !in_tag => text.push(c),
                        _ => {}
                    }
                }
                text
            })
            .filter(|c| !c.is_empty())
            .collect()
    };
    let t1 = row("T01");
    assert_eq!(t1[1], "01");
    assert_eq!(t1[2], "turning C 80°, r0.8, tip 3, κr 95°");
    assert_eq!(t1[3], "CNMG 120408 in PCLNR 2525M12");
    let t2 = row("T02");
    assert_eq!(t2[1], "12", "T0212 is tool 2 with offset 12");
    assert!(t2[2].starts_with("grooving 3 mm"), "{t2:?}");
    assert_eq!(t2[3], "—");
    // T01 feeds 3 mm in to X46, 32 mm along, 4 mm in to X44 and 22 mm along: 61 mm at
    // 0.2 mm/rev and 800 rev/min (160 mm/min) = 22.875 s in cut, shown 23 s; its rapids come
    // on top
    assert_eq!(t1[4], "23 s");
    let secs = |s: &str| s.trim_end_matches(" s").parse::<f64>().unwrap();
    assert!(secs(&t1[5]) > 23.0, "{t1:?}");
    for needle in [
        "<th scope=\"row\">chuck</th><td>face at Z\u{2212}80, body Ø130 × 100 deep</td>",
        "<th scope=\"row\">jaws</th><td>hard jaws gripping 20 mm over Ø50, 20 mm high</td>",
        "<th scope=\"row\">stick-out</th><td>60 mm</td>",
    ] {
        assert!(sheet.contains(needle), "missing {needle}\n{sheet}");
    }
}

/// A tool with no entry taken for what its moves say is named so on the sheet (it read
/// "not in the tool table: the default assumed" beside a threading insert's description).
#[test]
fn the_sheet_says_a_tool_was_taken_from_its_moves() {
    let program = "O0036\nG21 G99\nT0101\nM03 S800\nG00 X52. Z2.\nG01 X46. F0.2\nZ-30.\nG00 X60. Z50.\nT0505\nG97 S600 M03\nG00 X48. Z4.\nG92 X45.4 Z-20. F1.5\nX45.0\nX44.2\nG00 X60. Z50.\nM30\n";
    let (dir, path) = temp_program("sheet.nc", program.as_bytes());
    let html = dir.path().join("r.html");
    let out = latsim(&[
        "run",
        path.to_str().unwrap(),
        "--control",
        "fanuc-a",
        "--stock",
        "50x60",
        "--html",
        html.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(out.code <= 1, "{}", out.stderr);
    let page = std::fs::read_to_string(html).unwrap();
    assert!(
        page.contains(
            "threading 60° (not in the tool table: taken from its moves, its size assumed)"
        ),
        "{}",
        &page[..page.len().min(4000)]
    );
    assert!(page.contains("(not in the tool table: the default assumed)"));
}
