//! Writes pictures to tests/out for a human to look at (not a check).
mod common;

#[test]
fn write_pictures() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/out");
    std::fs::create_dir_all(&dir).unwrap();
    let r = common::groove_bar();
    std::fs::write(dir.join("groove_bar.svg"), render::svg(&r)).unwrap();
    std::fs::write(dir.join("groove_bar.png"), render::png(&r).unwrap()).unwrap();
}

#[test]
fn write_more_pictures() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/out");
    std::fs::create_dir_all(&dir).unwrap();
    let r = common::many_segments(100_000);
    std::fs::write(dir.join("many.png"), render::png(&r).unwrap()).unwrap();
    let mut r = common::groove_bar();
    r.crashes.clear();
    r.gouges.clear();
    r.gouge_shapes.clear();
    r.intended.clear();
    r.deviation = None;
    r.warnings.clear();
    std::fs::write(dir.join("clean.png"), render::png(&r).unwrap()).unwrap();
    let mut r = common::groove_bar();
    for i in 0..12 {
        r.alarms.push(render::Diagnostic {
            line: 20 + i,
            column: 4,
            code: "E-ARC-RADIUS".into(),
            message: format!(
                "arc radius R{i} is smaller than half the chord; check the end point or use I/K"
            ),
        });
    }
    r.crashes.push(render::Crash {
        line: 30,
        column: 1,
        z: -55.0,
        r: 19.0,
        area_mm2: 4.0,
    });
    r.leftovers.push(render::Shape {
        outer: vec![[-40.0, 18.0], [-38.0, 18.0], [-38.0, 18.4], [-40.0, 18.4]],
        holes: vec![],
    });
    std::fs::write(dir.join("alarms.png"), render::png(&r).unwrap()).unwrap();
}
