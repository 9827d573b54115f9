//! Text in any script in the PNG (issue 35): a GSK program's Chinese title, a Japanese,
//! Korean or Russian one is drawn in its own letters, not as boxes. A character the fonts
//! lack is drawn as the same box whatever it is, so two different titles of as many
//! characters give the same picture exactly when they are drawn as boxes.

mod common;

use image::RgbImage;

/// The report picture of the groove bar titled `title`.
fn picture(title: &str) -> RgbImage {
    let mut r = common::groove_bar();
    r.title = title.to_string();
    let png = render::png(&r).unwrap();
    image::load_from_memory(&png).unwrap().to_rgb8()
}

/// The pixels where `a` and `b` differ.
fn differing(a: &RgbImage, b: &RgbImage) -> Vec<(u32, u32)> {
    assert_eq!(a.dimensions(), b.dimensions());
    a.enumerate_pixels()
        .filter(|(x, y, p)| *p != b.get_pixel(*x, *y))
        .map(|(x, y, _)| (x, y))
        .collect()
}

/// Titles `a` and `b` (as many characters each) are drawn as different pictures, and differ
/// only where a title is written: in or beside a 40 × 12 px cell where `a` differs from no
/// title.
fn assert_drawn_apart(a: &str, b: &str) {
    assert_eq!(a.chars().count(), b.chars().count(), "{a} / {b}");
    static NONE: std::sync::OnceLock<RgbImage> = std::sync::OnceLock::new();
    let (pa, pb, none) = (picture(a), picture(b), NONE.get_or_init(|| picture("")));
    let apart = differing(&pa, &pb);
    assert!(
        apart.len() > 300,
        "`{a}` and `{b}` drawn alike ({} px differ): boxes?",
        apart.len()
    );
    let cell = |x: u32, y: u32| (x / 40, y / 12);
    let text: std::collections::HashSet<(u32, u32)> = differing(&pa, none)
        .into_iter()
        .map(|(x, y)| cell(x, y))
        .collect();
    let near_text = |&(x, y): &(u32, u32)| {
        let (cx, cy) = cell(x, y);
        (cx.saturating_sub(1)..=cx + 1)
            .any(|i| (cy.saturating_sub(1)..=cy + 1).any(|j| text.contains(&(i, j))))
    };
    let astray: Vec<_> = apart.iter().filter(|p| !near_text(p)).take(5).collect();
    assert!(
        astray.is_empty(),
        "`{a}` / `{b}` differ away from the text at {astray:?}"
    );
}

#[test]
fn chinese_titles_are_drawn_in_their_own_characters() {
    assert_drawn_apart("毛坯料宽40 长露出超过90", "棒料直径40 夹持长超过90");
}

#[test]
fn japanese_and_korean_titles_are_drawn_in_their_own_characters() {
    assert_drawn_apart("荒加工 外径 ひらがな", "仕上げ 内径 カタカナ");
    assert_drawn_apart("황삭 가공 외경", "정삭 가공 내경");
}

/// `DejaVu Sans` has Cyrillic: this guards it (it passed before issue 35 too).
#[test]
fn cyrillic_titles_are_drawn_in_their_own_letters() {
    assert_drawn_apart("Черновая обработка Ø40", "Чистовая обработка Ø40");
}
