#!/usr/bin/env bash
# Writes the JSON report of every program in assets/programs/ (with a fixed blank and tool
# table each) into OUTDIR, for before/after comparisons of a refactoring:
#   scripts/assets-json.sh /tmp/before target/release/latsim
#   scripts/assets-json.sh /tmp/after  target/release/latsim
#   python3 scripts/json-diff.py /tmp/before /tmp/after      # numbers equal to 1e-9 relative
set -uo pipefail
out=${1:?usage: assets-json.sh OUTDIR [LATSIM]}
bin=${2:-target/release/latsim}
cd "$(dirname "$0")/.."
mkdir -p "$out"
run() { # name program args...
  local name=$1 prog=$2; shift 2
  "$bin" run "assets/programs/$prog" --json "$out/$name.json" --quiet "$@" >"$out/$name.out" 2>&1
  echo "exit $?" >>"$out/$name.out"
}
. scripts/assets-runs.sh
echo "wrote $(ls "$out"/*.json 2>/dev/null | wc -l) reports into $out"
