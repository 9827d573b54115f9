//! The HTML page's structure, read back from the generated page by an HTML parser (`tl`):
//! the reference-image tests check the picture's pixels; this checks that the page around
//! it holds what a reader uses — the title, the one inline SVG with its title block, the
//! move slider over every move, the snapshots, and one findings row per finding. (A
//! headless-browser screenshot would need a browser on the test machine; CI has cargo.)
mod common;

use render::{Report, Shape, Snapshot};
use tl::{HTMLTag, Parser, VDom};

/// The one element with this id (tl's id table misses void elements such as `<input>`,
/// so the selector is matched over the whole page).
fn by_id<'p>(dom: &'p VDom<'p>, id: &str) -> &'p HTMLTag<'p> {
    let found: Vec<&HTMLTag> = dom
        .query_selector(&format!("#{id}"))
        .expect("a valid selector")
        .filter_map(|h| h.get(dom.parser()).and_then(|n| n.as_tag()))
        .collect();
    assert_eq!(found.len(), 1, "elements with id {id}");
    found[0]
}

fn attr(t: &HTMLTag, name: &str) -> String {
    t.attributes()
        .get(name)
        .flatten()
        .map(|v| v.as_utf8_str().into_owned())
        .unwrap_or_else(|| panic!("no {name} attribute"))
}

/// The elements named `name` inside `t`.
fn inside<'p>(parser: &'p Parser<'p>, t: &'p HTMLTag<'p>, name: &str) -> Vec<&'p HTMLTag<'p>> {
    t.query_selector(parser, name)
        .expect("a valid selector")
        .filter_map(|h| h.get(parser).and_then(|n| n.as_tag()))
        .collect()
}

/// The groove bar (one crash, one gouge, one warning, 11 moves) with three snapshots.
fn report() -> Report {
    let mut r = common::groove_bar();
    let bar = |r1: f64| Shape {
        outer: vec![[-60.0, 0.0], [0.0, 0.0], [0.0, r1], [-60.0, r1]],
        holes: vec![],
    };
    r.snapshots = [(0, 20.0), (5, 18.0), (11, 18.0)]
        .into_iter()
        .map(|(after_move, r1)| Snapshot {
            after_move,
            shapes: vec![bar(r1)],
        })
        .collect();
    r
}

#[test]
fn page_holds_title_picture_slider_snapshots_and_findings() {
    let r = report();
    let page = render::html(&r);
    let dom = tl::parse(&page, tl::ParserOptions::default()).expect("parses");
    let parser = dom.parser();
    let all = |name: &str| -> Vec<&HTMLTag> {
        dom.query_selector(name)
            .expect("a valid selector")
            .filter_map(|h| h.get(parser).and_then(|n| n.as_tag()))
            .collect()
    };

    // The title names the program and the blank.
    let title = all("title");
    assert_eq!(title.len(), 1);
    let title = title[0].inner_text(parser);
    assert!(
        title.contains("O0042.nc") && title.contains("bar Ø40 × 60, face at Z0"),
        "{title}"
    );
    let h1 = all("h1");
    assert_eq!(h1.len(), 1);
    assert!(
        h1[0].inner_text(parser).contains("O0042.nc"),
        "page heading"
    );
    // The verdict under the heading, and again in the summary table.
    let verdicts = all(".verdict");
    assert_eq!(verdicts.len(), 2);
    for v in verdicts {
        assert!(v.inner_text(parser).starts_with("CRASH"));
    }

    // One SVG, inside the picture section, with its title block and the toolpath.
    let picture = by_id(&dom, "ls-picture");
    let svgs = inside(parser, picture, "svg");
    assert_eq!(svgs.len(), 1, "one inline SVG in the picture section");
    assert_eq!(all("svg").len(), 1, "and no other");
    assert_eq!(
        attr(svgs[0], "width"),
        render::WIDTH_PX.to_string(),
        "picture width"
    );
    let block = by_id(&dom, "title-block");
    assert!(block.inner_text(parser).contains("1 min 42 s"));
    by_id(&dom, "toolpath");

    // The move slider spans every move and starts at the last.
    let slider = by_id(&dom, "ls-slider");
    assert_eq!(attr(slider, "type"), "range");
    assert_eq!(attr(slider, "min"), "0");
    assert_eq!(attr(slider, "max"), r.toolpath.len().to_string());
    assert_eq!(attr(slider, "value"), r.toolpath.len().to_string());
    by_id(&dom, "ls-canvas");
    for id in ["ls-first", "ls-prev", "ls-play", "ls-next", "ls-last"] {
        assert_eq!(attr(by_id(&dom, id), "type"), "button", "{id}");
    }

    // The snapshots, in the embedded data block.
    let data = by_id(&dom, "ls-data");
    assert_eq!(attr(data, "type"), "application/json");
    let json: serde_json::Value =
        serde_json::from_str(&data.inner_text(parser)).expect("the data block is JSON");
    let snapshots = json["snapshots"].as_array().expect("snapshots");
    assert_eq!(snapshots.len(), r.snapshots.len());

    // The findings: one row per crash, gouge and warning, each naming its line.
    let findings = by_id(&dom, "ls-findings");
    let rows = |class: &str| -> Vec<String> {
        inside(parser, findings, &format!("table.{class}"))
            .into_iter()
            .flat_map(|t| inside(parser, t, "tr"))
            .filter_map(|tr| tr.attributes().get("data-line").flatten())
            .map(|v| v.as_utf8_str().into_owned())
            .collect()
    };
    assert_eq!(rows("crash"), ["14"]);
    assert_eq!(rows("gouge"), ["11"]);
    assert_eq!(rows("warning"), ["9"]);
    assert!(rows("alarm").is_empty());
    for (id, n) in [
        ("ls-alarms", 0),
        ("ls-crashes", 1),
        ("ls-gouges", 1),
        ("ls-warnings", 1),
    ] {
        let head = by_id(&dom, id).inner_text(parser);
        assert!(head.ends_with(&format!("({n})")), "{id}: {head}");
    }
}

/// A program that cuts a thread gets a threads table, one row per thread with what was
/// measured ("—" where nothing could be); one that cuts none gets no such section.
#[test]
fn threads_are_listed_with_their_pitch_diameter() {
    let mut r = report();
    let page = render::html(&r);
    assert!(!page.contains("ls-threads"), "no thread, no table");
    r.threads = vec![
        render::ThreadCheck {
            line: 4,
            inside: false,
            lead_mm: 1.5,
            starts: 1,
            x_mm: 18.05,
            expected_x_mm: Some(18.05),
            pass_depths_mm: vec![0.4, 0.3, 0.275],
            achieved_x_mm: Some(18.05),
            depth_error_mm: Some(-1e-7),
            pitch_diameter_mm: Some(19.349038),
            included_angle_deg: Some(60.0),
            z_start_mm: -2.0,
            z_end_mm: -30.0,
        },
        render::ThreadCheck {
            line: 9,
            inside: true,
            lead_mm: 2.0,
            starts: 2,
            x_mm: 30.0,
            ..Default::default()
        },
    ];
    let page = render::html(&r);
    let dom = tl::parse(&page, tl::ParserOptions::default()).expect("parses");
    let parser = dom.parser();
    let head = by_id(&dom, "ls-threads").inner_text(parser);
    assert!(head.ends_with("(2)"), "{head}");
    let findings = by_id(&dom, "ls-findings");
    let rows: Vec<Vec<String>> = inside(parser, findings, "table.thread")
        .into_iter()
        .flat_map(|t| inside(parser, t, "tr"))
        .filter(|tr| tr.attributes().get("data-line").is_some())
        .map(|tr| {
            inside(parser, tr, "td")
                .into_iter()
                .map(|td| td.inner_text(parser).into_owned())
                .collect()
        })
        .collect();
    assert_eq!(
        rows[0],
        ["4", "OD", "1.5", "3", "18.05", "18.05", "18.05", "0.000", "19.349", "60.00"]
    );
    assert_eq!(
        rows[1],
        [
            "9",
            "ID",
            "2 (2 starts)",
            "0",
            "30",
            "—",
            "—",
            "—",
            "—",
            "—"
        ]
    );
}
