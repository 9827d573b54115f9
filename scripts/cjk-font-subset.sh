#!/usr/bin/env bash
# Makes assets/fonts/NotoSansCJKsc-subset.otf, the PNG's shipped fallback for Chinese,
# Japanese and Korean text (render::png), from Debian's fonts-noto-cjk package (Noto Sans
# CJK SC 2.004, SIL OFL 1.1) with fontTools' pyftsubset. Not run by the build or CI; run it
# again only to change the character set. Needs apt (to download the .deb; nothing is
# installed) and `pip install fonttools` (4.68 made the committed file).
#
# Characters kept (17 055 glyphs, 2 314 800 bytes):
#   GB2312 level 1 (3 755 hanzi, rows 16-55) and its symbol rows 1-9 (682: CJK
#   punctuation, full-width forms, kana, Greek, Cyrillic, box drawing);
#   JIS X 0208 level-1 kanji not already among them (1 254, drawn in the SC forms);
#   hiragana and katakana U+3040-30FF, CJK punctuation U+3000-303F, full-width forms
#   U+FF00-FFEF; all 11 172 Hangul syllables U+AC00-D7A3.
# Dropped: hinting, OpenType layout features (resvg shapes CJK without them), the vertical
# metrics. Latin, Greek and Cyrillic are drawn by DejaVu Sans first, so they never come
# from this font.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
(cd "$work" && apt-get download fonts-noto-cjk >/dev/null 2>&1 && dpkg-deb -x fonts-noto-cjk_*.deb deb)
python3 - "$work" <<'EOF'
import sys
from fontTools.ttLib import TTCollection

work = sys.argv[1]
ttc = TTCollection(
    f"{work}/deb/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc", recalcTimestamp=False
)
sc = next(f for f in ttc.fonts if f["name"].getDebugName(1) == "Noto Sans CJK SC")
sc.save(f"{work}/sc.otf")

def decoded(codec, rows, cells):
    for b1 in rows:
        for b2 in cells:
            try:
                yield bytes([b1, b2]).decode(codec)
            except UnicodeDecodeError:
                pass

gb_symbols = set(decoded("gb2312", range(0xA1, 0xAA), range(0xA1, 0xFF)))
gb_level1 = set(decoded("gb2312", range(0xB0, 0xD8), range(0xA1, 0xFF)))
jis_level1 = set(decoded("euc_jp", range(0xB0, 0xD0), range(0xA1, 0xFF)))
ranges = [(0x3000, 0x3100), (0xFF00, 0xFFF0), (0xAC00, 0xD7A4)]
chars = gb_symbols | gb_level1 | jis_level1
for lo, hi in ranges:
    chars |= {chr(c) for c in range(lo, hi)}
with open(f"{work}/chars.txt", "w", encoding="utf-8") as f:
    f.write("".join(sorted(chars)))
EOF
pyftsubset "$work/sc.otf" --text-file="$work/chars.txt" --no-hinting --layout-features='' \
  --drop-tables+=vhea,vmtx,VORG,DSIG --name-IDs='*' --no-recalc-timestamp \
  --output-file=assets/fonts/NotoSansCJKsc-subset.otf
ls -l assets/fonts/NotoSansCJKsc-subset.otf
