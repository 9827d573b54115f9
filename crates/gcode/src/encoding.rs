//! Program files that are not UTF-8 (issue 31): a GSK program with Chinese comments saved
//! in GBK by the control's USB export or a Chinese editor, a Windows-1252 file with `Ø` or
//! `°`, a Shift-JIS file from a Japanese control. The bytes are decoded to UTF-8 text
//! before reading, so every column a diagnostic names counts characters of that text.
//!
//! `encoding_rs` decodes (the WHATWG encodings, as browsers do) and `chardetng` guesses the
//! encoding of bytes that are not UTF-8 (Firefox's detector: GBK, Big5, Shift-JIS, EUC-KR,
//! the Windows code pages). Both are small, maintained by Mozilla and have no other
//! dependencies.

pub use encoding_rs::Encoding;

/// A program's text and the encoding it was read in.
#[derive(Debug, Clone)]
pub struct Decoded {
    /// The text, UTF-8.
    pub text: String,
    /// The encoding the bytes were decoded from.
    pub encoding: &'static Encoding,
    /// `true` when the encoding was guessed (the file is not UTF-8 and none was forced).
    pub guessed: bool,
}

/// Why bytes could not be read as text: the byte offset of the first one that is no
/// character in the encoding tried, and that encoding.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DecodeError {
    /// Offset of the first byte that is not a character.
    pub offset: usize,
    /// The encoding tried.
    pub encoding: &'static Encoding,
}

/// The encoding a `--encoding` label names (`gbk`, `windows-1252`, `shift_jis`, `utf-8`, …:
/// the WHATWG labels), or `None`.
pub fn encoding_for_label(label: &str) -> Option<&'static Encoding> {
    Encoding::for_label(label.trim().as_bytes())
}

/// Decode a program file: with `forced`, in that encoding; else UTF-8 when the bytes are
/// UTF-8 (a BOM is kept for the reader to drop), else the encoding `chardetng` guesses.
pub fn decode(bytes: &[u8], forced: Option<&'static Encoding>) -> Result<Decoded, DecodeError> {
    let (encoding, guessed) = match forced {
        Some(e) => (e, false),
        None if std::str::from_utf8(bytes).is_ok() => (encoding_rs::UTF_8, false),
        None => {
            let mut detector = chardetng::EncodingDetector::new();
            detector.feed(bytes, true);
            (detector.guess(None, false), true)
        }
    };
    let (text, had_errors) = encoding.decode_without_bom_handling(bytes);
    if had_errors {
        return Err(DecodeError {
            offset: first_error(bytes, encoding),
            encoding,
        });
    }
    Ok(Decoded {
        text: text.into_owned(),
        encoding,
        guessed,
    })
}

/// The offset of the first byte the encoding cannot decode: where the malformed sequence
/// starts, before the bytes the decoder read past it to see it was malformed (a GBK lead
/// byte before an ASCII byte: the lead byte, not the ASCII one).
fn first_error(bytes: &[u8], encoding: &'static Encoding) -> usize {
    let mut decoder = encoding.new_decoder_without_bom_handling();
    let mut out = vec![0u8; bytes.len() * 3 + 16];
    let (result, read, _) = decoder.decode_to_utf8_without_replacement(bytes, &mut out, true);
    match result {
        encoding_rs::DecoderResult::Malformed(bad, after) => {
            read.saturating_sub(bad as usize + after as usize)
        }
        _ => read,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_stays_utf8() {
        let d = decode("G0 X1 (Ø20)".as_bytes(), None).unwrap();
        assert_eq!(d.encoding, encoding_rs::UTF_8);
        assert!(!d.guessed);
    }

    #[test]
    fn gbk_comments_are_guessed_and_decoded() {
        let (bytes, _, _) = encoding_rs::GBK
            .encode("O0001 (外圆粗车)\nG0 X50. Z2. (快速定位到起点)\nG1 X45. F0.2 (车外圆)\nM30\n");
        let d = decode(&bytes, None).unwrap();
        assert!(d.guessed);
        assert_eq!(d.encoding, encoding_rs::GBK);
        assert!(d.text.contains("外圆粗车"));
    }

    #[test]
    fn windows_1252_and_shift_jis() {
        let (bytes, _, _) = encoding_rs::WINDOWS_1252.encode("O1 (WELLE Ø20, FASE 45°)\nG0 X20.\n");
        let d = decode(&bytes, None).unwrap();
        assert!(
            d.text.contains("Ø20") && d.text.contains("45°"),
            "{}",
            d.encoding.name()
        );
        let (bytes, _, _) = encoding_rs::SHIFT_JIS.encode("O1 (外径荒加工 バイト)\nG0 X20.\n");
        let d = decode(&bytes, None).unwrap();
        assert_eq!(d.encoding, encoding_rs::SHIFT_JIS);
        assert!(d.text.contains("バイト"));
    }

    #[test]
    fn forced_encoding_wins_and_reports_the_bad_byte() {
        let d = decode(b"G0 X1 (\xd8)", encoding_for_label("windows-1252")).unwrap();
        assert_eq!(d.text, "G0 X1 (Ø)");
        let e = decode(b"G0 X1 (\xff)", encoding_for_label("utf-8")).unwrap_err();
        assert_eq!(e.offset, 7);
        assert!(encoding_for_label("no-such").is_none());
    }
}
