#!/usr/bin/env bash
# Report-scaling benchmark (issues 16/17): the generated G01 zig-zag (scripts/zigzag.py) at
# 10^4, 10^5 and 10^6 lines, timed with /usr/bin/time: `check`, `run --json` and `run` with
# all four reports (SVG, PNG, JSON, HTML). Not part of `cargo test`. Usage:
#   cargo build --release && scripts/bench-reports.sh [LATSIM] [SIZES...]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-target/release/latsim}
shift || true
sizes=${*:-10000 100000 1000000}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf '%-8s %-6s %8s %10s\n' lines what seconds peak_KB
for n in $sizes; do
  python3 scripts/zigzag.py "$n" >"$dir/zz$n.nc"
  t() { # label, command...
    local label=$1; shift
    /usr/bin/time -f "%e %M" -o "$dir/t" "$@" >/dev/null 2>&1 || true
    read -r s kb <"$dir/t"
    printf '%-8s %-6s %8s %10s\n' "$n" "$label" "$s" "$kb"
  }
  t check "$bin" check "$dir/zz$n.nc"
  t json "$bin" run "$dir/zz$n.nc" --stock 125x110 --json "$dir/o.json" --quiet
  t all4 "$bin" run "$dir/zz$n.nc" --stock 125x110 --out "$dir/out$n" --quiet
  ls -l "$dir/out$n" | awk -v n="$n" 'NR > 1 { printf "%-8s %-6s %s bytes\n", n, "size", $9 " " $5 }'
done
