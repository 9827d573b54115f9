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
