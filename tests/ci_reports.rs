//! `run --junit F --sarif F` (issue 34): a batch of a clean program (its name holding a
//! space), a rapid crash, a gouge, a controller alarm and a file that does not read. The
//! `JUnit` file is read back by a strict XML parser (`roxmltree`) as a CI test reporter reads
//! it; the SARIF file is validated against the published SARIF 2.1.0 schema
//! (`tests/fixtures/sarif/`, OASIS) and its results are checked at their lines.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

/// The batch in a fresh folder `progs/`, its reports in `out/`; run from the folder.
struct Batch {
    dir: tempfile::TempDir,
    code: i32,
    stdout: String,
}

impl Batch {
    fn path(&self, rel: &str) -> PathBuf {
        self.dir.path().join(rel)
    }
}

/// A controller alarm at 4:10: Q means nothing on a G01 (LS-WORD-UNUSED).
const ALARM: &str =
    "O0001;\nG00 X42 Z2 M03 S800;\nG01 X36 Z0 F100;\nG01 Z-10 Q5;\nG00 X50;\nM30;\n";
/// Does not read: `#` without macro B (exit 2).
const BROKEN: &str = "O0001;\nG00 X42 Z2;\nG01 X3#6 F100;\n";

fn run_batch() -> Batch {
    let dir = tempfile::tempdir().unwrap();
    let progs = dir.path().join("progs");
    std::fs::create_dir(&progs).unwrap();
    let corpus = common::asset("corpus/gsk980");
    for (from, to) in [
        ("clean-leadin-face.nc", "clean lead-in.nc"),
        ("fault-face-rapid.nc", "fault-face-rapid.nc"),
        ("fault-missing-g42.nc", "fault-missing-g42.nc"),
    ] {
        std::fs::copy(corpus.join(from), progs.join(to)).unwrap();
    }
    std::fs::write(progs.join("alarm.nc"), ALARM).unwrap();
    std::fs::write(progs.join("broken.nc"), BROKEN).unwrap();
    let tools = common::asset("corpus/tools/shop.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_latsim"))
        .current_dir(dir.path())
        .args(["run", "progs", "--stock", "40x60", "--reports", "none"])
        .arg("--tools")
        .arg(&tools)
        .args(["--junit", "out/junit.xml", "--sarif", "out/latsim.sarif"])
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    Batch {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        dir,
    }
}

fn attr<'a>(n: roxmltree::Node<'a, '_>, name: &str) -> &'a str {
    n.attribute(name)
        .unwrap_or_else(|| panic!("<{}> has no {name}", n.tag_name().name()))
}

fn child<'a, 'i>(n: roxmltree::Node<'a, 'i>, name: &str) -> Option<roxmltree::Node<'a, 'i>> {
    n.children().find(|c| c.tag_name().name() == name)
}

/// One `<testcase>` per program, named by folder and file, timed; the crash, the gouge
/// and the alarm fail with each finding at `file:line:column`; the file that does not read
/// is an error; the verdict line is the system output.
#[test]
fn junit_has_a_test_case_per_program_and_fails_the_findings() {
    let b = run_batch();
    assert_eq!(
        b.code, 2,
        "the unreadable program makes the run exit 2\n{}",
        b.stdout
    );
    let text = std::fs::read_to_string(b.path("out/junit.xml")).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "testsuites");
    let suite = child(root, "testsuite").expect("a testsuite");
    for n in [root, suite] {
        assert_eq!(attr(n, "tests"), "5");
        assert_eq!(attr(n, "failures"), "3");
        assert_eq!(attr(n, "errors"), "1");
        assert!(attr(n, "time").parse::<f64>().unwrap() >= 0.0);
    }
    let cases: Vec<_> = suite
        .children()
        .filter(|c| c.tag_name().name() == "testcase")
        .collect();
    let names: Vec<&str> = cases.iter().map(|c| attr(*c, "name")).collect();
    assert_eq!(
        names,
        [
            "alarm.nc",
            "broken.nc",
            "clean lead-in.nc",
            "fault-face-rapid.nc",
            "fault-missing-g42.nc"
        ]
    );
    let case = |name: &str| *cases.iter().find(|c| attr(**c, "name") == name).unwrap();
    for c in &cases {
        assert_eq!(attr(*c, "classname"), "progs");
        assert!(attr(*c, "time").parse::<f64>().unwrap() >= 0.0);
    }
    let clean = case("clean lead-in.nc");
    assert!(child(clean, "failure").is_none() && child(clean, "error").is_none());
    let out = child(clean, "system-out").unwrap().text().unwrap();
    assert!(out.starts_with("clean lead-in.nc: CLEAN — "), "{out}");
    let failure = |name: &str| {
        let f = child(case(name), "failure").unwrap_or_else(|| panic!("{name} fails"));
        (
            attr(f, "type").to_string(),
            f.text().unwrap_or("").to_string(),
        )
    };
    let (kind, text) = failure("fault-face-rapid.nc");
    assert_eq!(kind, "crash");
    assert!(
        text.starts_with("progs/fault-face-rapid.nc:7:1: crash LS-CRASH: crash: rapid into stock"),
        "{text}"
    );
    let (kind, text) = failure("fault-missing-g42.nc");
    assert_eq!(kind, "gouge");
    assert!(text.starts_with("progs/fault-missing-g42.nc:13:"), "{text}");
    assert!(text.contains(": gouge LS-GOUGE: gouge: "), "{text}");
    let (kind, text) = failure("alarm.nc");
    assert_eq!(kind, "alarm");
    assert_eq!(
        text,
        "progs/alarm.nc:4:10: alarm LS-WORD-UNUSED: address Q has no meaning in this block"
    );
    let gouge_out = child(case("fault-missing-g42.nc"), "system-out").unwrap();
    assert!(gouge_out.text().unwrap().contains(": GOUGE — "));
    let broken = case("broken.nc");
    assert!(child(broken, "failure").is_none());
    assert_eq!(attr(child(broken, "error").unwrap(), "type"), "unusable");
}

fn sarif_validator() -> jsonschema::Validator {
    let schema: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(
            common::root().join("tests/fixtures/sarif/sarif-schema-2.1.0.json"),
        )
        .unwrap(),
    )
    .unwrap();
    // the schema is draft-04; its `uri` and `date-time` formats are checked too
    jsonschema::draft4::options()
        .should_validate_formats(true)
        .build(&schema)
        .expect("the SARIF 2.1.0 schema compiles")
}

fn region_of(result: &serde_json::Value) -> (&str, u64, Option<u64>) {
    let loc = &result["locations"][0]["physicalLocation"];
    (
        loc["artifactLocation"]["uri"].as_str().unwrap(),
        loc["region"]["startLine"].as_u64().unwrap(),
        loc["region"]["startColumn"].as_u64(),
    )
}

/// The SARIF log is valid against the published 2.1.0 schema (and the schema does reject
/// a broken log); each crash, gouge and alarm is an `error` result at its file and line,
/// relative to the working folder; rules are described once and the results point at them.
#[test]
fn sarif_is_valid_and_puts_each_finding_on_its_line() {
    let b = run_batch();
    let text = std::fs::read_to_string(b.path("out/latsim.sarif")).unwrap();
    let log: serde_json::Value = serde_json::from_str(&text).unwrap();
    let validator = sarif_validator();
    let errors: Vec<String> = validator.iter_errors(&log).map(|e| e.to_string()).collect();
    assert!(errors.is_empty(), "{errors:#?}");
    let mut broken = log.clone();
    broken["runs"][0]["results"][0]["level"] = "fatal".into();
    assert!(
        !validator.is_valid(&broken),
        "the schema rejects an unknown level"
    );
    let mut broken = log.clone();
    broken["$schema"] = "no uri".into();
    assert!(
        !validator.is_valid(&broken),
        "the schema's `uri` format is checked"
    );

    let run = &log["runs"][0];
    assert_eq!(log["version"], "2.1.0");
    assert_eq!(run["tool"]["driver"]["name"], "latsim");
    let cwd = std::fs::canonicalize(b.dir.path()).unwrap();
    let base = run["originalUriBaseIds"]["SRCROOT"]["uri"]
        .as_str()
        .unwrap();
    assert_eq!(base, format!("file://{}/", cwd.display()));
    let rules = run["tool"]["driver"]["rules"].as_array().unwrap();
    let ids: Vec<&str> = rules.iter().map(|r| r["id"].as_str().unwrap()).collect();
    let mut unique = ids.clone();
    unique.sort_unstable();
    unique.dedup();
    assert_eq!(unique.len(), ids.len(), "each rule once: {ids:?}");
    let results = run["results"].as_array().unwrap();
    for r in results {
        let i = r["ruleIndex"].as_u64().unwrap() as usize;
        assert_eq!(r["ruleId"], rules[i]["id"], "{r}");
        assert_eq!(
            r["locations"][0]["physicalLocation"]["artifactLocation"]["uriBaseId"],
            "SRCROOT"
        );
    }
    let with = |rule: &str| -> Vec<&serde_json::Value> {
        results.iter().filter(|r| r["ruleId"] == rule).collect()
    };
    let crashes = with("LS-CRASH");
    assert_eq!(crashes.len(), 1, "{crashes:?}");
    assert_eq!(crashes[0]["level"], "error");
    assert_eq!(
        region_of(crashes[0]),
        ("progs/fault-face-rapid.nc", 7, Some(1))
    );
    let gouges = with("LS-GOUGE");
    assert!(!gouges.is_empty());
    for g in &gouges {
        assert_eq!(g["level"], "error");
        let (uri, line, _) = region_of(g);
        assert_eq!((uri, line), ("progs/fault-missing-g42.nc", 13));
    }
    let alarms = with("LS-WORD-UNUSED");
    assert_eq!(alarms.len(), 1);
    assert_eq!(region_of(alarms[0]), ("progs/alarm.nc", 4, Some(10)));
    assert!(alarms[0]["message"]["text"]
        .as_str()
        .unwrap()
        .contains("address Q"));
    // leftovers and warnings are notes; the clean program's name is a URI reference
    assert!(with("LS-LEFTOVER").iter().all(|r| r["level"] == "note"));
    let uris: Vec<&str> = results.iter().map(|r| region_of(r).0).collect();
    assert!(!uris.iter().any(|u| u.contains(' ')), "{uris:?}");
    let invocation = &run["invocations"][0];
    assert_eq!(invocation["executionSuccessful"], false);
    assert_eq!(invocation["exitCode"], 2);
    let notes = invocation["toolExecutionNotifications"].as_array().unwrap();
    assert_eq!(notes.len(), 1);
    assert_eq!(
        notes[0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
        "progs/broken.nc"
    );
}

/// A single clean program: one passing test case, a valid SARIF log whose results are
/// notes only, exit 0; the reports are not written over an input.
#[test]
fn a_clean_program_passes_and_inputs_are_never_overwritten() {
    let dir = tempfile::tempdir().unwrap();
    let prog = dir.path().join("part.nc");
    std::fs::copy(common::asset("corpus/gsk980/clean-leadin-face.nc"), &prog).unwrap();
    let tools = common::asset("corpus/tools/shop.toml");
    let junit = dir.path().join("j.xml");
    let sarif = dir.path().join("s.sarif");
    let p = |p: &Path| p.to_str().unwrap().to_string();
    let args = [
        "run",
        &p(&prog),
        "--stock",
        "40x60",
        "--tools",
        &p(&tools),
        "--reports",
        "none",
        "--junit",
        &p(&junit),
        "--sarif",
        &p(&sarif),
    ];
    let out = common::latsim(&args);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let text = std::fs::read_to_string(&junit).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(attr(doc.root_element(), "failures"), "0");
    assert_eq!(attr(doc.root_element(), "tests"), "1");
    let log: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&sarif).unwrap()).unwrap();
    assert!(sarif_validator().is_valid(&log));
    let results = log["runs"][0]["results"].as_array().unwrap();
    assert!(results.iter().all(|r| r["level"] == "note"), "{results:?}");
    // the program given as the JUnit file: refused, the program left as it was
    let before = std::fs::read(&prog).unwrap();
    let args = [
        "run",
        &p(&prog),
        "--stock",
        "40x60",
        "--tools",
        &p(&tools),
        "--reports",
        "none",
        "--junit",
        &p(&prog),
    ];
    let out = common::latsim(&args);
    assert_eq!(out.code, 2);
    assert!(
        out.stderr.contains("refusing to overwrite the input file"),
        "{}",
        out.stderr
    );
    assert_eq!(std::fs::read(&prog).unwrap(), before);
}

/// A gouge made by a tool latsim had to assume (issue 38: T03 is not in the table) is
/// possible, not in the verdict: the test case passes (exit 0), and the SARIF log has it as
/// a `warning` (`LS-POSSIBLE-GOUGE`) at its line, with the `LS-ASSUMED-TOOL` note.
#[test]
fn a_possible_gouge_of_an_assumed_tool_does_not_fail() {
    let dir = tempfile::tempdir().unwrap();
    let prog = dir.path().join("partoff.nc");
    std::fs::write(&prog, "G99 M03 S600\nT0101\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X30\nG01 Z-30\nN20 X42\nG70 P10 Q20\nG00 X100 Z100\nT0303\nG00 X42 Z-33\nG01 X2 F0.05\nG00 X50\nM30\n").unwrap();
    let tools = dir.path().join("t01.toml");
    std::fs::write(
        &tools,
        // T03 a turning tool whose size is not stated (with no entry at all, a tool that
        // only plunges is taken for a blade, which cuts nothing of the contour here)
        "[[tool]]\nt = 1\nkind = \"turning\"\ninsert = \"CNMG 120408\"\nholder = \"PCLNR 2525M12\"\n[[tool]]\nt = 3\nkind = \"turning\"\n",
    )
    .unwrap();
    let (junit, sarif) = (dir.path().join("j.xml"), dir.path().join("s.sarif"));
    let p = |p: &Path| p.to_str().unwrap().to_string();
    let args = [
        "run",
        &p(&prog),
        "--stock",
        "40x60",
        "--tools",
        &p(&tools),
        "--reports",
        "none",
        "--junit",
        &p(&junit),
        "--sarif",
        &p(&sarif),
    ];
    let out = common::latsim(&args);
    assert_eq!(out.code, 0, "{}\n{}", out.stdout, out.stderr);
    let text = std::fs::read_to_string(&junit).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(attr(doc.root_element(), "failures"), "0");
    let log: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&sarif).unwrap()).unwrap();
    assert!(sarif_validator().is_valid(&log));
    let results = log["runs"][0]["results"].as_array().unwrap();
    let possible: Vec<_> = results
        .iter()
        .filter(|r| r["ruleId"] == "LS-POSSIBLE-GOUGE")
        .collect();
    assert_eq!(possible.len(), 1, "{results:?}");
    assert_eq!(possible[0]["level"], "warning");
    assert_eq!(region_of(possible[0]).1, 13);
    assert!(results.iter().any(|r| r["ruleId"] == "LS-ASSUMED-TOOL"));
    assert!(
        !results.iter().any(|r| r["level"] == "error"),
        "{results:?}"
    );
}
