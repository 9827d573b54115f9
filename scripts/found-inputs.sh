#!/usr/bin/env bash
# Runs every input of ../shared/found/ (or $1) with the command line its README gives,
# under a 60 s and 4 GB limit, and prints one line per input: exit status, wall time, peak
# RSS. Usage (from the project root, after `cargo build --release`):
#   scripts/found-inputs.sh [FOUND_DIR] [BINARY]
set -u
found=${1:-../shared/found}
bin=${2:-target/release/latsim}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grep -E '^[^#].*: run ' "$found/README.txt" | while IFS= read -r line; do
    file=${line%%: run *}
    args=${line#*: run }
    input="$work/$(basename "${file%.gz}")"
    if [[ $file == *.gz ]]; then gunzip -c "$found/$file" >"$input"; else cp "$found/$file" "$input"; fi
    # the README names the input m.nc / in.toml, or by its own short name
    args=${args//m.nc/$input}
    args=${args//in.toml/$input}
    for word in $args; do
        if [[ $word == *.nc && ! -e $word && $word != */* ]]; then args=${args//$word/$input}; fi
    done
    args=${args//--out out/--out $work/out}
    args=${args//--out DIR/--out $work/out}
    rm -rf "$work/out"
    start=$(date +%s.%N)
    ( ulimit -v 4194304; timeout 60 /usr/bin/time -f "%M" -o "$work/rss" "$bin" run $args >"$work/stdout" 2>"$work/stderr" )
    code=$?
    end=$(date +%s.%N)
    rss=$(tail -1 "$work/rss" 2>/dev/null)
    printf '%-48s exit %3s  %6.2f s  %6s MB\n' "$file" "$code" "$(echo "$end - $start" | bc)" "$(( ${rss:-0} / 1024 ))"
    rm -f "$input"
done
