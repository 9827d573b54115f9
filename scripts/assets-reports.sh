#!/usr/bin/env bash
# Writes all four reports (SVG, PNG, JSON, HTML) of every program in assets/programs/ (with
# a fixed blank and tool table each) into OUTDIR/NAME/, for before/after comparisons of the
# pictures (cmp the PNGs; scripts/assets-json.sh for the numbers):
#   scripts/assets-reports.sh /tmp/before target/release/latsim
#   scripts/assets-reports.sh /tmp/after  target/release/latsim
#   for f in /tmp/before/*/*.png; do cmp -s "$f" "/tmp/after/${f#/tmp/before/}" || echo "$f"; done
set -uo pipefail
out=${1:?usage: assets-reports.sh OUTDIR [LATSIM]}
bin=${2:-target/release/latsim}
cd "$(dirname "$0")/.."
mkdir -p "$out"
run() { # name program args...
  local name=$1 prog=$2; shift 2
  "$bin" run "assets/programs/$prog" --out "$out/$name" --quiet "$@" >"$out/$name.out" 2>&1
  echo "exit $?" >>"$out/$name.out"
}
. scripts/assets-runs.sh
echo "wrote $(ls "$out"/*/*.png 2>/dev/null | wc -l) pictures into $out"
