#!/usr/bin/env bash
# Opens a latsim HTML report in headless Chromium (Debian's `chromium`) and checks what a
# person would see (issue 35). Installs nothing: needs `chromium`, `pdftoppm` and `pdfinfo`
# (poppler-utils) and python3; on Debian `apt-get install -y chromium poppler-utils`.
# Not run by CI. Usage:
#   scripts/html-check.sh REPORT.html [OUTDIR]
# Writes into OUTDIR (default: a new temporary directory, printed):
#   page.png         the page's first 1400 × 2600 px, to look at;
#   solid.png        the 3D view alone (1000 × 600), checked: at least 3 % of its pixels
#                    differ from the white background, some of them the part's blue-grey;
#   solid-turned.png the same after a mouse drag, checked to differ from solid.png;
#   a4.pdf, letter.pdf and a4-N.png, letter-N.png: the page printed on A4 and on Letter
#                    (the setup sheet), each checked to be one or two pages;
#   timing.txt       when the page had loaded and the 3D view was drawn, ms after the
#                    navigation started (performance.now()), and Chromium's whole run, s.
# Exits 1 when a check fails. LOOK at the PNGs: the checks only catch a blank view.
set -euo pipefail
page=$(realpath "${1:?usage: html-check.sh REPORT.html [OUTDIR]}")
out=${2:-$(mktemp -d)}
mkdir -p "$out"
out=$(realpath "$out")
rm -f "$out"/a4-*.png "$out"/letter-*.png
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for tool in chromium pdftoppm pdfinfo python3; do
  command -v "$tool" >/dev/null || { echo "html-check: $tool is missing (apt-get install -y chromium poppler-utils)" >&2; exit 2; }
done

# chromium SIZE ARGS...: a headless run with a fresh profile and no network of its own
browse() {
  local profile
  profile=$(mktemp -d -p "$work")
  chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --enable-unsafe-swiftshader --use-angle=swiftshader \
    --user-data-dir="$profile" --hide-scrollbars "$@" 2>>"$work/chromium.log"
}

# inject FILE TEXT: a copy of the page with TEXT before </head> (a style) or </body>
inject() {
  python3 - "$page" "$1" "$2" <<'EOF'
import sys
page, target, text = sys.argv[1], sys.argv[2], sys.argv[3]
html = open(page, encoding="utf-8").read()
tag = "</head>" if text.startswith("<style") else "</body>"
i = html.rfind(tag)
open(target, "w", encoding="utf-8").write(html[:i] + text + html[i:])
EOF
}

# 1. The page as it opens, and how long it takes.
inject "$work/timed.html" "<script>addEventListener('load', function () { document.body.setAttribute('data-load-ms', String(Math.round(performance.now()))); });</script>"
start=$(date +%s.%N)
browse --dump-dom "file://$work/timed.html" >"$work/dom.html"
end=$(date +%s.%N)
load=$(grep -o 'data-load-ms="[0-9]*"' "$work/dom.html" | grep -o '[0-9]*' || echo "?")
solid=$(grep -o '<canvas id="ls-solid"[^>]*>' "$work/dom.html" || true)
drawn=$(echo "$solid" | grep -o 'data-drawn="[0-9]*"' | grep -o '[0-9]*' || echo "?")
took=$(echo "$solid" | grep -o 'data-took="[0-9]*"' | grep -o '[0-9]*' || echo "?")
{
  echo "page: $page ($(stat -c %s "$page") bytes)"
  echo "load event: $load ms after navigation start"
  echo "3D view drawn: $drawn ms after navigation start (set up and drawn in $took ms, after the load)"
  echo "chromium --dump-dom, whole run: $(python3 -c "print(f'{$end - $start:.2f}')") s"
} | tee "$out/timing.txt"
browse --window-size=1400,2600 --screenshot="$out/page.png" "file://$page" >/dev/null

# 2. The 3D view alone, at a known place, everything else hidden.
inject "$work/solid.html" "<style>body * { visibility: hidden !important; } #ls-solid { visibility: visible !important; position: fixed !important; left: 0; top: 0; width: 1000px !important; height: 600px !important; z-index: 99; }</style>"
browse --window-size=1000,600 --screenshot="$out/solid.png" "file://$work/solid.html" >/dev/null
# ... and turned by a drag of 120 px to the left and 30 px down, as a mouse would
python3 - "$work/solid.html" "$work/turned.html" <<'EOF'
import sys
html = open(sys.argv[1], encoding="utf-8").read()
drag = """<script>(function () {
  var c = document.getElementById('ls-solid');
  function at(type, x, y) {
    c.dispatchEvent(new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, bubbles: true }));
  }
  (function when() {  // once the view is drawn (after the page has loaded)
    if (!c.getAttribute('data-drawn')) { setTimeout(when, 20); return; }
    at('pointerdown', 500, 300); at('pointermove', 440, 315); at('pointermove', 380, 330); at('pointerup', 380, 330);
  })();
})();</script>"""
i = html.rfind("</body>")
open(sys.argv[2], "w", encoding="utf-8").write(html[:i] + drag + html[i:])
EOF
browse --window-size=1000,600 --screenshot="$out/solid-turned.png" "file://$work/turned.html" >/dev/null
if cmp -s "$out/solid.png" "$out/solid-turned.png"; then
  echo "html-check: a drag does not turn the 3D view" >&2
  exit 1
fi
python3 - "$out/solid.png" <<'EOF'
import struct, sys, zlib

def pixels(path):
    """RGB rows of an 8-bit RGB or RGBA PNG (all Chromium writes)."""
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and ctype in (2, 6), (depth, ctype)
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return rows

rows = pixels(sys.argv[1])
total = sum(len(r) for r in rows)
ink = [p for r in rows for p in r if p != (255, 255, 255)]
# the part's blue-grey: blue above red, not grey text or a white page
steel = [p for p in ink if p[2] > p[0] + 12 and 40 < p[2] < 245]
share = len(ink) / total
print(f"3D view: {len(ink)} of {total} px not background ({100 * share:.1f} %), {len(steel)} blue-grey")
if share < 0.03 or len(steel) < 0.01 * total:
    print("html-check: the 3D view is blank", file=sys.stderr)
    sys.exit(1)
EOF

# 3. The setup sheet: printed on A4 and on Letter, one or two pages each.
status=0
for paper in A4 letter; do
  name=$(echo "$paper" | tr 'A-Z' 'a-z')
  inject "$work/$name.html" "<style>@page { size: $paper; }</style>"
  browse --no-pdf-header-footer --print-to-pdf="$out/$name.pdf" "file://$work/$name.html" >/dev/null
  pages=$(pdfinfo "$out/$name.pdf" | awk '/^Pages:/ { print $2 }')
  size=$(pdfinfo "$out/$name.pdf" | awk -F': *' '/^Page size:/ { print $2 }')
  pdftoppm -r 70 -png "$out/$name.pdf" "$out/$name"
  echo "$paper: $pages page(s), $size"
  if [ "$pages" -lt 1 ] || [ "$pages" -gt 2 ]; then
    echo "html-check: the setup sheet on $paper is $pages pages (1 or 2 wanted)" >&2
    status=1
  fi
done
echo "look at: $out/page.png $out/solid.png $out/solid-turned.png $(ls "$out"/a4-*.png "$out"/letter-*.png | tr '\n' ' ')"
exit $status
