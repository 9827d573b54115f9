//! Reference-image tests, resvg style: render a fixed report, compare with the checked-in
//! PNG within a per-channel tolerance; on failure write `expected | diff | actual` to
//! `tests/out/` and fail. Regenerate with `LATSIM_BLESS=1 cargo test -p render`.
mod common;

use std::path::{Path, PathBuf};

use image::{Rgb, RgbImage};

/// A channel may differ by this many levels (anti-aliasing noise).
const CHANNEL_TOL: u8 = 2;
/// At most this many pixels may exceed it: the renderer is deterministic, so this only
/// absorbs rounding noise, and a single changed digit (~50 px) still fails.
const MAX_BAD_PIXELS: usize = 16;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests")
}

/// Pixels differing by more than the tolerance, and the diff picture.
fn compare(expected: &RgbImage, actual: &RgbImage) -> (usize, RgbImage) {
    let (w, h) = (
        expected.width().max(actual.width()),
        expected.height().max(actual.height()),
    );
    let mut diff = RgbImage::from_pixel(w, h, Rgb([255, 255, 255]));
    let mut bad = 0;
    for y in 0..h {
        for x in 0..w {
            let e = expected.get_pixel_checked(x, y);
            let a = actual.get_pixel_checked(x, y);
            let differs = match (e, a) {
                (Some(e), Some(a)) => {
                    e.0.iter()
                        .zip(a.0)
                        .any(|(p, q)| p.abs_diff(q) > CHANNEL_TOL)
                }
                _ => true,
            };
            if differs {
                bad += 1;
                diff.put_pixel(x, y, Rgb([230, 0, 0]));
            } else if let Some(e) = e {
                // A faint copy of the picture, for orientation.
                let g = (255 - (255 - e.0.iter().map(|&c| c as u32).sum::<u32>() / 3) / 5) as u8;
                diff.put_pixel(x, y, Rgb([g, g, g]));
            }
        }
    }
    (bad, diff)
}

fn side_by_side(parts: &[&RgbImage]) -> RgbImage {
    let w = parts.iter().map(|p| p.width()).sum::<u32>() + 8 * (parts.len() as u32 - 1);
    let h = parts.iter().map(|p| p.height()).max().unwrap_or(1);
    let mut out = RgbImage::from_pixel(w, h, Rgb([40, 40, 40]));
    let mut x0 = 0;
    for p in parts {
        image::imageops::replace(&mut out, *p, x0 as i64, 0);
        x0 += p.width() + 8;
    }
    out
}

fn decode(bytes: &[u8]) -> RgbImage {
    image::load_from_memory_with_format(bytes, image::ImageFormat::Png)
        .expect("valid PNG")
        .to_rgb8()
}

/// Render `report`, compare with `tests/reference/{name}.png`; Err(message) on mismatch.
fn check(name: &str, report: &render::Report) -> Result<(), String> {
    let png = render::png(report).map_err(|e| e.to_string())?;
    let reference = dir().join("reference").join(format!("{name}.png"));
    if std::env::var_os("LATSIM_BLESS").is_some() {
        std::fs::write(&reference, &png).map_err(|e| e.to_string())?;
        return Ok(());
    }
    let expected = std::fs::read(&reference).map_err(|e| {
        format!(
            "{}: {e} (run with LATSIM_BLESS=1 to create it)",
            reference.display()
        )
    })?;
    let (expected, actual) = (decode(&expected), decode(&png));
    let (bad, diff) = compare(&expected, &actual);
    if bad <= MAX_BAD_PIXELS && expected.dimensions() == actual.dimensions() {
        return Ok(());
    }
    let out = dir().join("out");
    std::fs::create_dir_all(&out).map_err(|e| e.to_string())?;
    let path = out.join(format!("{name}-expected-diff-actual.png"));
    side_by_side(&[&expected, &diff, &actual])
        .save(&path)
        .map_err(|e| e.to_string())?;
    Err(format!(
        "{name}: {bad} pixels differ by more than {CHANNEL_TOL} levels (allowed {MAX_BAD_PIXELS}); see {}",
        path.display()
    ))
}

#[test]
fn groove_bar_matches_reference() {
    if let Err(e) = check("groove_bar", &common::groove_bar()) {
        panic!("{e}");
    }
}

#[test]
fn groove_detail_matches_reference() {
    if let Err(e) = check("o0008_groove", &common::o0008_groove()) {
        panic!("{e}");
    }
}

#[test]
fn reference_check_catches_a_changed_digit() {
    if std::env::var_os("LATSIM_BLESS").is_some() {
        return;
    }
    let mut r = common::groove_bar();
    r.cycle_time_s = 103.0; // "1 min 42 s" -> "1 min 43 s"
    let e = check("groove_bar", &r).expect_err("a changed digit must fail the comparison");
    assert!(e.contains("pixels differ"), "{e}");
}

#[test]
fn png_is_deterministic_and_sized() {
    let r = common::groove_bar();
    let a = render::png(&r).unwrap();
    let b = render::png(&r).unwrap();
    assert_eq!(a, b);
    let img = decode(&a);
    assert_eq!(img.dimensions(), (render::WIDTH_PX, render::HEIGHT_PX));
}
