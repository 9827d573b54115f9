//! The chuck, jaws and tailstock and the tool at each crash in the picture, and the tool
//! drawn by the HTML player (issue 15).
mod common;

use render::{Fixture, Report, Shape, ToolOutline};

/// The embedded data block, parsed.
fn data(page: &str) -> serde_json::Value {
    let open = r#"<script type="application/json" id="ls-data">"#;
    let start = page.find(open).expect("data block") + open.len();
    let len = page[start..].find("</script>").expect("data block end");
    serde_json::from_str(&page[start..start + len]).expect("data block is JSON")
}

fn rect(z0: f64, z1: f64, r0: f64, r1: f64) -> Vec<[f64; 2]> {
    vec![[z0, r0], [z1, r0], [z1, r1], [z0, r1]]
}

/// The groove bar with a jaw, a blade (and holder) for moves 1–3 and another tool after,
/// and the crash's tool drawn.
fn report() -> Report {
    let mut r = common::groove_bar();
    r.fixture = vec![Fixture {
        name: "chuck jaw".into(),
        shapes: vec![Shape {
            outer: rect(-60.0, -40.0, 20.0, 40.0),
            holes: vec![],
        }],
    }];
    r.tool_outlines = vec![
        ToolOutline {
            edge: vec![rect(0.0, 3.0, 0.0, 20.0)],
            body: vec![rect(-2.0, 5.0, 20.0, 120.0)],
        },
        ToolOutline {
            edge: vec![vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]],
            body: vec![],
        },
    ];
    r.tool_runs = vec![(0, 0), (3, 1)];
    r.crashes[0].tool = vec![rect(-47.0, -44.0, 18.0, 38.0)];
    r.crashes[0].obstacle = Some("chuck jaw".into());
    r
}

#[test]
fn picture_draws_the_workholding_labelled_and_the_tool_at_the_crash() {
    let plain = render::svg(&common::groove_bar());
    assert!(!plain.contains("class=\"fixture\"") && !plain.contains("crash-tool"));
    let s = render::svg(&report());
    assert!(s.contains("class=\"fixture\"") && s.contains("class=\"fixture-mirror\""));
    assert!(s.contains(">chuck jaw<"), "the jaw is labelled");
    assert!(s.contains("class=\"crash-tool\""));
    // the crash tool's outline, in mm under the view transform, in the crash colour
    let at = s.find("class=\"crash-tool\"").unwrap();
    let g = &s[at..at + 400];
    assert!(g.contains("M-47,18L-44,18L-44,38L-47,38Z"), "{g}");
    assert!(g.contains("#7b3fe4"), "{g}");
    assert!(s.contains(">tool at crash<") && s.contains(">chuck, jaws, tailstock<"));
    render::png(&report()).expect("the PNG renders");
}

#[test]
fn player_data_holds_the_tools_their_runs_and_the_workholding() {
    let page = render::html(&report());
    let d = data(&page);
    assert_eq!(d["tool_runs"], serde_json::json!([[1, 0], [4, 1]]));
    // rings in z, x (x = diameter): the blade's 0…20 radius is 0…40 of diameter
    assert_eq!(
        d["tools"][0]["edge"],
        serde_json::json!([[0, 0, 3, 0, 3, 40, 0, 40]])
    );
    assert_eq!(d["tools"][0]["body"][0].as_array().unwrap().len(), 8);
    assert_eq!(d["tools"][1]["body"], serde_json::json!([]));
    assert_eq!(
        d["fixture"],
        serde_json::json!([[-60, 40, -40, 40, -40, 80, -60, 80]])
    );
    assert_eq!(d["crash_tools"][0][0], 14);
    assert!(page.contains("var lsTools") && page.contains("lsTools.over(ctx, data, m, X, Y)"));
    assert!(page.contains("chuck jaw") && page.contains("cutting edge in the chuck jaw"));
    // a report without them embeds empty lists and draws no tool
    let d = data(&render::html(&common::groove_bar()));
    assert_eq!(d["tools"], serde_json::json!([]));
    assert_eq!(d["fixture"], serde_json::json!([]));
}
