//! Numbers as a word writes them: `[+-]? (digits [. digits*] | . digits)`, at most 20
//! characters and 9 digits before the point. Read with Clinger's fast path where the value
//! is exact (a million-line program has millions of numbers).

use super::reading::ParseError;
use crate::{address, Span};

/// Longest number text accepted; more digits than this cannot be a real coordinate.
pub(super) const MAX_NUMBER_CHARS: usize = 20;
/// Most digits before the decimal point (leading zeros aside): the largest value a
/// FANUC/GSK word holds is 9 digits (99999999.9 at IS-B is already 100 km).
pub(super) const MAX_WHOLE_DIGITS: usize = 9;
/// The help for numbers that are too long.
pub(super) const NUMBER_HELP: &str =
    "a number has at most 9 digits before the point and 20 characters in all";

/// The value of a word's number text, and whether a point was written: an error naming
/// the address where the text is no number (`foreign`'s error first, when it names what the
/// line is) or has too many digits before the point.
pub(super) fn word_value(
    text: &str,
    span: Span,
    letter: char,
    foreign: impl FnOnce() -> Option<ParseError>,
) -> Result<(f64, bool), ParseError> {
    let (value, has_point) = parse_number(text)
        .ok_or_else(|| foreign().unwrap_or_else(|| not_a_number(text, span, letter)))?;
    // digits before the point, signs and leading zeros aside
    let whole_digits = text
        .bytes()
        .take_while(|&b| b != b'.')
        .skip_while(|&b| b == b'+' || b == b'-')
        .skip_while(|&b| b == b'0')
        .count();
    if whole_digits > MAX_WHOLE_DIGITS {
        return Err(ParseError::new(
            span,
            format!(
                "number of address {} has {whole_digits} digits before the point",
                address(letter)
            ),
            NUMBER_HELP,
        ));
    }
    Ok((value, has_point))
}

/// The error for a word whose text is no number: empty, or malformed.
fn not_a_number(text: &str, span: Span, letter: char) -> ParseError {
    if text.is_empty() {
        ParseError::new(
            span,
            format!("address {} has no value", address(letter)),
            format!(
                "write a number right after {}, e.g. {}0",
                address(letter),
                address(letter)
            ),
        )
    } else {
        ParseError::new(
            span,
            format!("malformed number '{}' after {}", text, address(letter)),
            "a number is an optional sign, digits and at most one decimal point, e.g. -17.639 or 100.",
        )
    }
}

/// A number that must be whole and unpointed (N, O): the value, or the error.
pub(super) fn whole(
    value: f64,
    has_point: bool,
    span: Span,
    letter: char,
) -> Result<u32, ParseError> {
    if has_point || !(0.0..=99_999_999.0).contains(&value) {
        return Err(ParseError::new(
            span,
            format!("{letter} needs a whole number without a decimal point"),
            format!("write {letter} as digits only, e.g. {letter}14"),
        ));
    }
    Ok(value as u32)
}

/// The exact powers of ten of [`parse_number`]'s fast path.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The number at the start of `bytes` as a plain block writes it, read in one pass: an
/// optional sign, digits with at most one point, fewer than [`MAX_NUMBER_CHARS`]
/// characters and at most [`MAX_WHOLE_DIGITS`] digits before the point (leading zeros
/// aside), ended by anything but a digit, point or sign, with a value on
/// [`parse_number`]'s fast path. Its length, value (the one `parse_number` gives) and
/// whether a point was written; `None` for anything else, which the character loop reads.
#[inline]
pub(super) fn plain_number(bytes: &[u8]) -> Option<(usize, f64, bool)> {
    let mut i = usize::from(matches!(bytes.first(), Some(b'+' | b'-')));
    let (mut mantissa, mut digits, mut decimals, mut point, mut whole) =
        (0u64, 0usize, 0usize, false, 0usize);
    // a number that reaches MAX_NUMBER_CHARS characters is the character loop's
    let limit = bytes.len().min(MAX_NUMBER_CHARS);
    while i < limit {
        let b = bytes[i];
        match b {
            b'0'..=b'9' => {
                if !point && (whole > 0 || b != b'0') {
                    whole += 1;
                }
                // fewer than 20 characters: at most 19 digits, below u64::MAX
                mantissa = mantissa * 10 + u64::from(b - b'0');
                digits += 1;
                decimals += usize::from(point);
            }
            b'.' if !point => point = true,
            b'.' | b'+' | b'-' => return None,
            _ => break,
        }
        i += 1;
    }
    if i >= MAX_NUMBER_CHARS {
        return None;
    }
    if digits == 0 || whole > MAX_WHOLE_DIGITS || mantissa >= 1 << 53 {
        return None;
    }
    let value = mantissa as f64 / POW10[decimals];
    let value = if bytes[0] == b'-' { -value } else { value };
    Some((i, value, point))
}

/// `[+-]? (digits [. digits*] | . digits)`; returns the value and whether a point was written.
pub(super) fn parse_number(text: &str) -> Option<(f64, bool)> {
    let bytes = text.as_bytes();
    let body = match bytes.first() {
        Some(b'+' | b'-') => &bytes[1..],
        _ => bytes,
    };
    let mut digits = 0;
    let mut points = 0;
    // the digits as one integer and how many stand after the point
    let (mut mantissa, mut decimals) = (0u64, 0i32);
    for &b in body {
        match b {
            b'0'..=b'9' => {
                digits += 1;
                mantissa = mantissa
                    .saturating_mul(10)
                    .saturating_add(u64::from(b - b'0'));
                decimals += points;
            }
            b'.' => points += 1,
            _ => return None,
        }
    }
    if digits == 0 || points > 1 {
        return None;
    }
    // Clinger's fast path: an integer below 2^53 over an exact power of ten is one
    // correctly rounded division, the very value `str::parse` returns (a million-line
    // program has millions of numbers, and `parse` was a third of reading them)
    if mantissa < 1 << 53 && digits <= 19 && decimals <= 22 {
        let value = mantissa as f64 / POW10[decimals as usize];
        let value = if bytes[0] == b'-' { -value } else { value };
        return Some((value, points == 1));
    }
    let value: f64 = text.parse().ok()?;
    value.is_finite().then_some((value, points == 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast path gives `str::parse`'s value bit for bit, sign of zero included.
    #[test]
    fn numbers_read_as_str_parse_reads_them() {
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut fast = 0;
        for i in 0..300_000u64 {
            let r = next();
            let whole = match i % 4 {
                0 => r % 10,
                1 => r % 100_000,
                2 => r % 100_000_000,
                _ => r % 10_000_000_000_000_000,
            };
            let places = (r >> 40) % 24;
            let frac = format!(
                "{:0width$}",
                (r >> 8) % 10u64.pow(places.min(18) as u32),
                width = places as usize
            );
            let sign = ["", "-", "+"][(r >> 60) as usize % 3];
            let text = match (r >> 56) % 4 {
                0 => format!("{sign}{whole}"),
                1 => format!("{sign}{whole}."),
                2 => format!("{sign}.{frac}"),
                _ => format!("{sign}{whole}.{frac}"),
            };
            let Some((v, _)) = parse_number(&text) else {
                panic!("{text} not read");
            };
            let expect: f64 = text.parse().unwrap();
            assert_eq!(v.to_bits(), expect.to_bits(), "{text}");
            let body = text.trim_start_matches(['+', '-']).replace('.', "");
            fast += usize::from(body.len() <= 15);
        }
        assert!(fast > 100_000, "{fast}");
        for text in [
            "-0",
            "-0.000",
            "0.",
            ".5",
            "9007199254740993",
            "1.7976931348623157",
            "0.1",
            "-123.4567",
        ] {
            let (v, _) = parse_number(text).unwrap();
            assert_eq!(
                v.to_bits(),
                text.parse::<f64>().unwrap().to_bits(),
                "{text}"
            );
        }
    }

    /// [`plain_number`] reads what [`parse_number`] reads from the same characters, or
    /// leaves it to the character loop: every string of up to 5 characters of `0 5 . + - X`,
    /// and long ones at the limits.
    #[test]
    fn plain_numbers_read_as_parse_number_reads_them() {
        let alphabet = [b'0', b'5', b'.', b'+', b'-', b'X'];
        let mut texts: Vec<Vec<u8>> = vec![vec![]];
        for len in 1..=5 {
            let mut more = vec![];
            for t in texts.iter().filter(|t| t.len() == len - 1) {
                for &c in &alphabet {
                    let mut u = t.clone();
                    u.push(c);
                    more.push(u);
                }
            }
            texts.extend(more);
        }
        for long in [
            "123456789.123",
            "1234567890.",
            "0001234567.5",
            "9007199254740991",
            "9007199254740992",
            "-1234567.8901234",
            "12345678901234567.5",
            "1234567890123456789",
            "-.000000000000000001",
        ] {
            texts.push(long.as_bytes().to_vec());
        }
        for t in &texts {
            let scanned = t
                .iter()
                .take_while(|b| matches!(b, b'0'..=b'9' | b'.' | b'+' | b'-'))
                .count();
            let text = std::str::from_utf8(&t[..scanned]).unwrap();
            let reference = parse_number(text);
            let whole = text
                .bytes()
                .take_while(|&b| b != b'.')
                .skip_while(|&b| b == b'+' || b == b'-')
                .skip_while(|&b| b == b'0')
                .count();
            match plain_number(t) {
                Some((len, value, point)) => {
                    assert_eq!(len, scanned, "{text}");
                    let (v, p) = reference.unwrap_or_else(|| panic!("{text}"));
                    assert_eq!((value.to_bits(), point), (v.to_bits(), p), "{text}");
                    assert!(
                        whole <= MAX_WHOLE_DIGITS && scanned < MAX_NUMBER_CHARS,
                        "{text}"
                    );
                }
                None => {
                    let digits: String = text.chars().filter(char::is_ascii_digit).collect();
                    let slow = digits.parse::<u128>().is_ok_and(|m| m >= 1 << 53);
                    assert!(
                        reference.is_none()
                            || whole > MAX_WHOLE_DIGITS
                            || scanned >= MAX_NUMBER_CHARS
                            || slow,
                        "{text}"
                    );
                }
            }
        }
    }
}
