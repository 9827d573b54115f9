//! Rasterise the report SVG with resvg (tiny-skia, anti-aliased) using the fonts embedded
//! in the binary (`crate::fonts`: `DejaVu Sans`, then a CJK subset, then the system's only
//! for a character neither has), so the usual picture never depends on system fonts.

use image::ImageEncoder as _;
use resvg::{tiny_skia, usvg};

use crate::fonts::options_for;
use crate::RenderError;

/// Rasterise an SVG string at 1:1 (its own width and height in px) on white, to PNG.
pub(crate) fn rasterise(svg: &str) -> Result<Vec<u8>, RenderError> {
    let tree =
        usvg::Tree::from_str(svg, options_for(svg)).map_err(|e| RenderError::Svg(e.to_string()))?;
    let size = tree.size().to_int_size();
    let (w, h) = (size.width(), size.height());
    let mut pixmap = tiny_skia::Pixmap::new(w, h).ok_or(RenderError::Size(w, h))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    let rgb = rgb_in_place(pixmap.take());
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(&rgb, w, h, image::ExtendedColorType::Rgb8)
        .map_err(|e| RenderError::Encode(e.to_string()))?;
    Ok(out)
}

/// The RGB bytes of RGBA pixels on an opaque background (premultiplied by 255, so RGB is
/// exact), moved down in the same buffer: a second 1600 × 1000 buffer, touched page by
/// page, was 8 % of a small program's run.
fn rgb_in_place(mut px: Vec<u8>) -> Vec<u8> {
    let n = px.len() / 4;
    for i in 0..n {
        px.copy_within(4 * i..4 * i + 3, 3 * i);
    }
    px.truncate(3 * n);
    px
}
