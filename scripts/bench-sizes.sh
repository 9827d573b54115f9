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
#   threads   issue 32's CAM thread: an M18 x 1.5 thread 17.3 mm long as single G32 passes
#             (4 moves a pass), each 0.001 mm deeper on the diameter (less where 2 mm would
#             not hold them all), Φ20 bar, fanuc-a, the default tool
#   g73arcs   a G73 over a profile of 40 R1.2 arcs in a row (44 moves a pass, at most R9999:
#             about 440 000 moves)
# THREADS_MAX (default 1000000) and ARCS_MAX (default 1000000) skip those two patterns above
# that many moves (a thread pass costs about 0.12 ms of cpu: 10^6 moves take about 30 s).
# PATTERNS (default all six, space-separated) runs only those.
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
  python3 - "$n" >"$dir/threads.nc" <<'EOF'
import sys
passes = max(1, int(sys.argv[1]) // 4)
step = min(0.001, 2.0 / passes)
out = ["G21 G99", "T0101", "G0 X20 Z2 M03 S600"]
for k in range(passes):
    out += [f"G00 X{17.0 - step * k:.4f} Z0.5", "G32 Z-17.3 F1.5", "G00 X20", "Z0.5"]
out.append("M30")
print("\n".join(out))
EOF
  python3 - "$n" >"$dir/g73arcs.nc" <<'EOF'
import sys
passes = max(1, min(9999, int(sys.argv[1]) // 44))
out = ["O9100;", "G21 G99 M03 S800 T0101;", "G00 X130. Z5.;",
       f"G73 U4.0 W0.0 R{passes};", "G73 P10 Q20 U0.2 W0.05 F0.2;",
       "N10 G00 X60. Z2.;", "G01 Z0.;"]
out += [f"G03 X60. Z{-(i + 1) * 2.0:.1f} R1.2;" for i in range(40)]
out += ["N20 G01 X130.;", "G00 Z5.;", "M30;"]
print("\n".join(out))
EOF
  passes=$((n / 7 < 9999 ? n / 7 : 9999))
  sed "s/g73 u1.0 w1.0 r3 /g73 u1.0 w1.0 r$passes /" assets/programs/O0006.nc >"$dir/g73.nc"
  for p in ${PATTERNS:-contour grooving zigzag g73 threads g73arcs}; do
    if { [ "$p" = threads ] && [ "$n" -gt "${THREADS_MAX:-1000000}" ]; } ||
      { [ "$p" = g73arcs ] && [ "$n" -gt "${ARCS_MAX:-1000000}" ]; }; then
      continue
    fi
    case $p in
      g73) stock=(--stock-file assets/blanks/o0006-casting.toml) ;;
      threads) stock=(--control fanuc-a --stock 20x40) ;;
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
