//! Text helpers: XML escaping, approximate text measurement, wrapping, number formats.
//!
//! Widths are estimates for `DejaVu Sans` (about 0.6 em per character); we err wide so
//! that text placed by these numbers never overlaps its neighbours. A wide character
//! (Chinese, Japanese, Korean, full-width forms: 1 em in the CJK font) counts as two
//! columns, 1.2 em; lengths below are in such columns.

use std::fmt::Write as _;

/// Average advance of one character in em for `DejaVu Sans` (mixed text is ~0.55).
const EM_PER_CHAR: f64 = 0.6;

/// Columns of `c`: 2 for an East Asian wide or full-width character, else 1.
fn columns_of(c: char) -> usize {
    let wide = matches!(c as u32,
        0x1100..=0x115F // Hangul Jamo initials
        | 0x2E80..=0x303E // CJK radicals, Kangxi, ideographic description, CJK punctuation
        | 0x3041..=0x33FF // kana, bopomofo, Hangul compatibility Jamo, CJK compatibility
        | 0x3400..=0x4DBF // CJK extension A
        | 0x4E00..=0x9FFF // CJK unified ideographs
        | 0xA000..=0xA4CF // Yi
        | 0xAC00..=0xD7A3 // Hangul syllables
        | 0xF900..=0xFAFF // CJK compatibility ideographs
        | 0xFE30..=0xFE4F // CJK compatibility forms
        | 0xFF00..=0xFF60 // full-width forms
        | 0xFFE0..=0xFFE6
        | 0x20000..=0x3FFFD // CJK extensions B and on
    );
    if wide {
        2
    } else {
        1
    }
}

/// Columns of `s` (see [`columns_of`]): its character count when it has no wide one.
pub(crate) fn columns(s: &str) -> usize {
    s.chars().map(columns_of).sum()
}

/// Escape a string for XML text and attribute values.
pub(crate) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // Control characters are not allowed in XML 1.0.
            c if (c as u32) < 0x20 && c != '\t' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// Approximate rendered width of `s` in px at `size` px.
pub(crate) fn width(s: &str, size: f64) -> f64 {
    columns(s) as f64 * size * EM_PER_CHAR
}

/// How many columns fit in `px` at `size`.
pub(crate) fn chars_fitting(px: f64, size: f64) -> usize {
    if px.is_nan() || px <= 0.0 {
        return 0;
    }
    (px / (size * EM_PER_CHAR)).floor() as usize
}

/// Cut `s` to at most `max` columns, ending with an ellipsis when cut.
pub(crate) fn truncate(s: &str, max: usize) -> String {
    if columns(s) <= max {
        return s.to_string();
    }
    if max == 0 {
        return String::new();
    }
    let mut out = String::new();
    let mut used = 1; // the ellipsis
    for c in s.chars() {
        used += columns_of(c);
        if used > max {
            break;
        }
        out.push(c);
    }
    out.push('…');
    out
}

/// Word-wrap `s` to lines of at most `max` columns, at most `max_lines` lines; the last
/// line is truncated with an ellipsis when text remains. A word longer than a line (a
/// Chinese sentence has no spaces) is broken between characters.
pub(crate) fn wrap(s: &str, max: usize, max_lines: usize) -> Vec<String> {
    let max = max.max(4);
    let mut lines: Vec<String> = Vec::new();
    let mut cur = String::new();
    for word in s.split_whitespace() {
        let wlen = columns(word);
        let clen = columns(&cur);
        if clen > 0 && clen + 1 + wlen <= max {
            cur.push(' ');
            cur.push_str(word);
            continue;
        }
        if clen > 0 {
            lines.push(std::mem::take(&mut cur));
        }
        let (mut piece, mut used) = (String::new(), 0);
        for c in word.chars() {
            let w = columns_of(c);
            if used + w > max {
                lines.push(std::mem::take(&mut piece));
                used = 0;
            }
            piece.push(c);
            used += w;
        }
        cur = piece;
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    if lines.len() > max_lines {
        lines.truncate(max_lines);
        if let Some(last) = lines.last_mut() {
            let t = truncate(last, max.saturating_sub(1));
            *last = if t.ends_with('…') {
                t
            } else {
                format!("{t}…")
            };
        }
    }
    lines
}

/// Format a number for SVG path data: up to `decimals` decimals, trailing zeros trimmed,
/// never `-0`.
pub(crate) fn num(v: f64, decimals: usize) -> String {
    let mut s = String::with_capacity(24);
    push_num(&mut s, v, decimals);
    s
}

/// Append [`num`]`(v, decimals)` to `out`, without a string of its own: the millions of
/// toolpath coordinates of a long program's HTML data went through a `String` and
/// `format!` each (11 % of a 10⁵-move contour's HTML-only run).
pub(crate) fn push_num(out: &mut String, v: f64, decimals: usize) {
    if !v.is_finite() {
        out.push('0');
    } else if !push_num_by_integer(out, v, decimals) {
        let start = out.len();
        let _ = write!(out, "{v:.decimals$}");
        if out[start..].contains('.') {
            let trimmed = out.trim_end_matches('0').trim_end_matches('.').len();
            out.truncate(trimmed);
        }
        if &out[start..] == "-0" {
            out.truncate(start);
            out.push('0');
        }
    }
}

/// [`push_num`] by integer arithmetic: `v · 10^decimals` rounded, when that product is
/// below 10¹² (its rounding error is then at most 1.2·10⁻⁴) and its fraction is not within
/// 10⁻³ of one half, so the rounding cannot differ from that of the exact decimal value
/// `format!` rounds. `false` (nothing written) otherwise, and the caller formats.
fn push_num_by_integer(out: &mut String, v: f64, decimals: usize) -> bool {
    const POW10: [f64; 7] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6];
    let Some(&scale) = POW10.get(decimals) else {
        return false;
    };
    let scaled = v * scale;
    if scaled.abs() >= 1e12 || ((scaled - scaled.trunc()).abs() - 0.5).abs() < 1e-3 {
        return false;
    }
    let r = scaled.round() as i64;
    let unit = scale as u64;
    let (whole, mut frac) = (r.unsigned_abs() / unit, r.unsigned_abs() % unit);
    // at most 13 digits, a sign and a point
    let mut buf = [0u8; 24];
    let mut at = buf.len();
    let mut digits = decimals;
    if frac > 0 {
        while frac % 10 == 0 {
            frac /= 10;
            digits -= 1;
        }
        for _ in 0..digits {
            at -= 1;
            buf[at] = b'0' + (frac % 10) as u8;
            frac /= 10;
        }
        at -= 1;
        buf[at] = b'.';
    }
    let mut w = whole;
    loop {
        at -= 1;
        buf[at] = b'0' + (w % 10) as u8;
        w /= 10;
        if w == 0 {
            break;
        }
    }
    if r < 0 {
        at -= 1;
        buf[at] = b'-';
    }
    // ASCII digits, sign and point only
    out.push_str(std::str::from_utf8(&buf[at..]).unwrap_or("0"));
    true
}

/// Format a tick label: `decimals` fixed, with a typographic minus.
pub(crate) fn tick_label(v: f64, decimals: usize) -> String {
    let s = num(v, decimals);
    match s.strip_prefix('-') {
        Some(rest) => format!("\u{2212}{rest}"),
        None => s,
    }
}

/// Group thousands with a space: `59812.4` -> `59 812`.
pub(crate) fn grouped(v: f64, decimals: usize) -> String {
    if !v.is_finite() {
        return "—".to_string();
    }
    let s = format!("{:.decimals$}", v.abs());
    let (int, frac) = match s.split_once('.') {
        Some((i, f)) => (i.to_string(), Some(f.to_string())),
        None => (s.clone(), None),
    };
    let digits: Vec<char> = int.chars().collect();
    let mut out = String::new();
    for (i, c) in digits.iter().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(' ');
        }
        out.push(*c);
    }
    if let Some(f) = frac {
        out.push('.');
        out.push_str(&f);
    }
    if v < 0.0 && out.chars().any(|c| c.is_ascii_digit() && c != '0') {
        out.insert(0, '\u{2212}');
    }
    out
}

/// An area or volume with a sensible number of decimals.
pub(crate) fn quantity(v: f64) -> String {
    let a = v.abs();
    if !v.is_finite() {
        "—".to_string()
    } else if a >= 1000.0 {
        grouped(v, 0)
    } else if a >= 10.0 {
        grouped(v, 1)
    } else if a >= 0.1 || a == 0.0 {
        grouped(v, 2)
    } else {
        grouped(v, 4)
    }
}

/// A length in mm, e.g. `0.01 mm`.
pub(crate) fn mm(v: f64) -> String {
    if !v.is_finite() {
        return "—".to_string();
    }
    let s = num(v, 4);
    format!("{s} mm")
}

/// Cycle time as `1 min 42 s`, `42 s`, `2 h 05 min 10 s`.
pub(crate) fn duration(secs: f64) -> String {
    if !secs.is_finite() || secs < 0.0 {
        return "—".to_string();
    }
    if secs < 10.0 {
        return format!("{} s", num(secs, 1));
    }
    let total = secs.round() as u64;
    let (h, m, s) = (total / 3600, (total / 60) % 60, total % 60);
    if h > 0 {
        format!("{h} h {m:02} min {s:02} s")
    } else if m > 0 {
        format!("{m} min {s} s")
    } else {
        format!("{s} s")
    }
}

/// `1 crash`, `2 crashes`.
pub(crate) fn plural(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The integer path writes what `format!` writes, on values near every rounding edge.
    #[test]
    fn num_by_integer_matches_format() {
        let slow = |v: f64, d: usize| {
            let mut s = format!("{v:.d$}");
            if s.contains('.') {
                s = s.trim_end_matches('0').trim_end_matches('.').to_string();
            }
            if s == "-0" {
                s = "0".to_string();
            }
            s
        };
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut fast_paths = 0;
        for i in 0..400_000u64 {
            let d = (i % 7) as usize;
            let r = next();
            let mag = 10f64.powi((r % 14) as i32 - 6);
            let mut v = (r >> 11) as f64 / (1u64 << 53) as f64 * mag;
            if r & 1 == 1 {
                v = -v;
            }
            if i % 3 == 0 {
                // a value on a half of the last decimal, give or take an ulp
                let k = (r >> 20) % 100_000;
                v = (k as f64 + 0.5) / 10f64.powi(d as i32);
                v = f64::from_bits(v.to_bits().wrapping_add(r % 3).wrapping_sub(1));
            }
            for v in [v, -v, v * 1e-3, 0.0, -0.0, 1e-12, -1e-12] {
                let got = num(v, d);
                assert_eq!(got, slow(v, d), "{v:e} with {d} decimals");
                fast_paths += usize::from(push_num_by_integer(&mut String::new(), v, d));
            }
        }
        assert!(fast_paths > 2_000_000, "{fast_paths}");
    }

    #[test]
    fn duration_formats() {
        assert_eq!(duration(102.0), "1 min 42 s");
        assert_eq!(duration(42.4), "42 s");
        assert_eq!(duration(3.26), "3.3 s");
        assert_eq!(duration(3725.0), "1 h 02 min 05 s");
        assert_eq!(duration(f64::NAN), "—");
    }

    #[test]
    fn numbers() {
        assert_eq!(num(1.500000, 6), "1.5");
        assert_eq!(num(-0.0000001, 6), "0");
        assert_eq!(num(f64::NAN, 6), "0");
        assert_eq!(grouped(59812.4, 0), "59 812");
        assert_eq!(grouped(1234567.25, 1), "1 234 567.2");
        assert_eq!(tick_label(-10.0, 0), "\u{2212}10");
    }

    #[test]
    fn wrapping_stays_within_limits() {
        let lines = wrap("the quick brown fox jumps over the lazy dog again", 12, 2);
        assert_eq!(lines.len(), 2);
        assert!(lines.iter().all(|l| l.chars().count() <= 12));
        assert!(lines[1].ends_with('…'));
        let lines = wrap("Ø125×110 ünïcödé", 5, 10);
        assert!(lines.iter().all(|l| l.chars().count() <= 5));
        assert_eq!(truncate("abcdef", 4), "abc…");
    }

    /// A Chinese character is as wide as two Latin ones: lines of CJK text keep within
    /// the columns they are given (issue 35), Latin text wraps as before.
    #[test]
    fn wide_characters_count_two_columns() {
        assert_eq!(columns("毛坯料宽40"), 10);
        assert_eq!(columns("Ø125×110"), 8);
        assert_eq!(width("毛", 10.0), width("ab", 10.0));
        let lines = wrap("毛坯料宽40 长露出超过90 粗车外圆", 8, 5);
        assert_eq!(lines, ["毛坯料宽", "40", "长露出超", "过90", "粗车外圆"]);
        assert!(lines.iter().all(|l| columns(l) <= 8));
        assert_eq!(truncate("毛坯料宽40", 6), "毛坯…");
        assert_eq!(truncate("毛坯料宽40", 10), "毛坯料宽40");
        assert_eq!(
            wrap("a bb ccc dddd eeeee", 5, 9),
            ["a bb", "ccc", "dddd", "eeeee"]
        );
    }

    #[test]
    fn escaping() {
        assert_eq!(esc("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
