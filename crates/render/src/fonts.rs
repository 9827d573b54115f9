//! The fonts the PNG draws its text with, in the order a character is looked for:
//!
//! 1. `DejaVu Sans`, shipped (`assets/fonts`): Latin, Greek, Cyrillic, the symbols;
//! 2. a subset of `Noto Sans CJK SC`, shipped (2.3 MB, SIL OFL; `scripts/cjk-font-subset.sh`
//!    says what it holds): Chinese (GB2312 level 1), Japanese kana and level-1 kanji, all
//!    Korean syllables, so that a GSK or KND program's Chinese comments read on a machine
//!    that has no CJK font at all (CI has none);
//! 3. the system's fonts, loaded only for a picture holding a character neither shipped
//!    font has (a rarer hanzi, Thai, Arabic …): the usual picture never depends on the
//!    machine, and a Latin one is drawn exactly as with `DejaVu Sans` alone.
//!
//! usvg's fallback takes, for a character the first font lacks, the first face of the
//! database that has it: the faces are loaded in the order above.

use std::collections::BTreeSet;
use std::sync::{Arc, OnceLock};

use resvg::usvg;
use skrifa::charmap::Charmap;
use skrifa::FontRef;
use usvg::fontdb::{Database, Source};

/// The main font, shipped in the repository.
static DEJAVU_SANS: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
/// The fallback for Chinese, Japanese and Korean, shipped in the repository.
static CJK_SUBSET: &[u8] = include_bytes!("../../../assets/fonts/NotoSansCJKsc-subset.otf");
/// The families of the shipped fonts; the system's faces of these families are left out
/// (a system `DejaVu Sans` of another version must not replace the shipped one).
const SHIPPED_FAMILIES: [&str; 2] = ["DejaVu Sans", "Noto Sans CJK SC"];

/// A database of the two shipped fonts, `DejaVu Sans` first.
fn shipped_database() -> Database {
    let mut db = Database::new();
    for data in [DEJAVU_SANS, CJK_SUBSET] {
        db.load_font_source(Source::Binary(Arc::new(data)));
    }
    // Generic families resolve to the main font.
    db.set_sans_serif_family(SHIPPED_FAMILIES[0]);
    db
}

/// The shipped fonts, then the system's (but their own copies of the shipped families).
fn system_database() -> Database {
    let mut db = shipped_database();
    let shipped: Vec<_> = db.faces().map(|f| f.id).collect();
    db.load_system_fonts();
    let twins: Vec<_> = db
        .faces()
        .filter(|f| !shipped.contains(&f.id))
        .filter(|f| {
            f.families
                .iter()
                .any(|(name, _)| SHIPPED_FAMILIES.contains(&name.as_str()))
        })
        .map(|f| f.id)
        .collect();
    for id in twins {
        db.remove_face(id);
    }
    db
}

fn options(db: Database) -> usvg::Options<'static> {
    let mut opt = usvg::Options {
        font_family: SHIPPED_FAMILIES[0].to_string(),
        ..usvg::Options::default()
    };
    *opt.fontdb_mut() = db;
    opt
}

/// Options drawing with the shipped fonts only (built once).
fn shipped() -> &'static usvg::Options<'static> {
    static OPT: OnceLock<usvg::Options<'static>> = OnceLock::new();
    OPT.get_or_init(|| options(shipped_database()))
}

/// Options drawing with the shipped fonts, then the system's (built once, when needed).
fn with_system() -> &'static usvg::Options<'static> {
    static OPT: OnceLock<usvg::Options<'static>> = OnceLock::new();
    OPT.get_or_init(|| options(system_database()))
}

/// The characters of `text` that no shipped font has (looked up in their character maps,
/// as usvg's fallback does).
pub(crate) fn not_shipped(text: &str) -> Vec<char> {
    let distinct: BTreeSet<char> = text
        .chars()
        .filter(|c| !c.is_ascii() && !c.is_control())
        .collect();
    if distinct.is_empty() {
        return Vec::new();
    }
    let maps: Vec<Charmap> = [DEJAVU_SANS, CJK_SUBSET]
        .iter()
        .filter_map(|data| FontRef::new(data).ok())
        .map(|font| Charmap::new(&font))
        .collect();
    distinct
        .into_iter()
        .filter(|&c| !maps.iter().any(|m| m.map(c).is_some()))
        .collect()
}

/// The options to rasterise `svg` with: the shipped fonts when they have every character
/// of it, else those followed by the system's.
pub(crate) fn options_for(svg: &str) -> &'static usvg::Options<'static> {
    if not_shipped(svg).is_empty() {
        shipped()
    } else {
        with_system()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shipped fonts alone hold the scripts CNC programmers comment in: a machine
    /// with no font of its own draws them (issue 35).
    #[test]
    fn shipped_fonts_cover_chinese_japanese_korean_and_cyrillic() {
        for text in [
            "毛坯料宽40 长露出超过90",
            "粗车外圆 精车端面 切槽 螺纹",
            "荒加工 外径 ひらがな カタカナ",
            "황삭 가공 외경 나사",
            "Черновая обработка, заготовка Ø40",
            "Ø125 × 110 — 0.5° ±0.01 mm²",
        ] {
            assert_eq!(not_shipped(text), Vec::<char>::new(), "{text}");
        }
        // a character outside both: looked for among the system's fonts
        assert_eq!(not_shipped("Thai ก"), vec!['ก']);
    }

    /// `DejaVu Sans` comes first: a Latin or Cyrillic letter, which the CJK subset has too,
    /// is drawn from it.
    #[test]
    fn dejavu_sans_is_looked_at_first() {
        let db = shipped_database();
        let faces: Vec<_> = db.faces().collect();
        assert_eq!(faces.len(), 2);
        assert_eq!(faces[0].families[0].0, "DejaVu Sans");
        assert_eq!(faces[1].families[0].0, "Noto Sans CJK SC");
        for data in [DEJAVU_SANS, CJK_SUBSET] {
            let font = FontRef::new(data).unwrap();
            assert!(Charmap::new(&font).map('Ж').is_some());
        }
    }
}
