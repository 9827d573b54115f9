#!/usr/bin/env bash
# Whole-process scaling of the issue 16 patterns at 10^4, 10^5 and 10^6 moves (or the sizes
# given): `latsim run --json` and `run` with all four reports, wall time and peak RSS from
# /usr/bin/time. Not part of `cargo test`. Usage:
#   cargo build --release && scripts/bench-sizes.sh [LATSIM] [SIZES...]
# Patterns:
#   contour   contour-parallel roughing of a wavy profile (benches/geos_compare.py's program)
#   grooving  G01 plunges stepped 0.1 mm along Z with rapid retracts (3 moves a peck)
#   zigzag    G01 back and forth along Z, every move cutting a sliver (scripts/zigzag.py cut)
#   g73       O0006's G73 on its casting with as many passes as make the size (7 moves a pass;
#             at most R9999, the control's limit: about 70 000 moves)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-target/release/latsim}
shift || true
sizes=${*:-10000 100000 1000000}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
tools="$dir/t.toml"
python3 -c "import sys; sys.path.insert(0, 'benches'); import geos_compare as g; open('$tools', 'w').write(g.TOOLS)"
printf '| pattern | segments | run --json s | peak MB | all four reports s | peak MB |\n|---|---:|---:|---:|---:|---:|\n'
for n in $sizes; do
  python3 -c "import sys; sys.path.insert(0, 'benches'); import geos_compare as g; sys.stdout.write(g.program(g.moves($n)))" >"$dir/contour.nc"
  python3 - "$n" >"$dir/grooving.nc" <<'EOF'
import sys
n = int(sys.argv[1]) // 3
out = ["O9000;", "G99 M03 S600 T0101;", "G00 X127. Z2.;"]
for k in range(n):
    z = -5.0 - 0.1 * (k % 9000)
    out.append(f"G00 Z{z:.4f};")
    out.append(f"G01 X{124.0 - 0.001 * (k // 9000):.4f} F0.1;")
    out.append("G00 X127.;")
out.append("M30;")
print("\n".join(out))
EOF
  python3 scripts/zigzag.py "$n" cut >"$dir/zigzag.nc"
  passes=$((n / 7 < 9999 ? n / 7 : 9999))
  sed "s/g73 u1.0 w1.0 r3 /g73 u1.0 w1.0 r$passes /" assets/programs/O0006.nc >"$dir/g73.nc"
  for p in contour grooving zigzag g73; do
    case $p in
      g73) stock=(--stock-file assets/blanks/o0006-casting.toml) ;;
      *) stock=(--stock 125x110 --tools "$tools") ;;
    esac
    t() {
      /usr/bin/time -f "%e %M" -o "$dir/t" "$bin" run "$dir/$p.nc" "${stock[@]}" "$@" --quiet >/dev/null 2>&1 || true
      read -r s kb < <(tail -1 "$dir/t")
      printf ' %s | %s |' "$s" "$((kb / 1024))"
    }
    json=$(t --json "$dir/o.json")
    segments=$(python3 -c "import json; print(json.load(open('$dir/o.json'))['segments'])" 2>/dev/null || echo "?")
    printf '| %s | %s |%s' "$p" "$segments" "$json"
    t --out "$dir/out"
    printf '\n'
  done
done
