#!/usr/bin/env bash
# Fills fuzz/corpus/<target>/ with seeds from assets/ (programs, tool tables, profiles) and
# fuzz/seeds/ (drawings).
set -euo pipefail
cd "$(dirname "$0")"
for t in read interpret interpret_macro run decode; do
  mkdir -p corpus/$t
  cp ../assets/programs/*.nc corpus/$t/ 2>/dev/null || true
  find ../assets/corpus -name '*.nc' -exec cp {} corpus/$t/ \; 2>/dev/null || true
done
# a program with comments in several scripts, in the encodings of the controls' exports
for f in seeds/decode/*.nc; do
  for enc in GBK SHIFT_JIS WINDOWS-1252 BIG5 EUC-KR UTF-16LE; do
    iconv -c -f UTF-8 -t "$enc" "$f" >"corpus/decode/$enc-$(basename "$f")" 2>/dev/null ||
      rm -f "corpus/decode/$enc-$(basename "$f")"
  done
done
mkdir -p corpus/toml_tools corpus/toml_machine corpus/toml_profile
cp ../assets/tools/*.toml corpus/toml_tools/
cp ../assets/machines/*.toml corpus/toml_machine/
cp ../assets/blanks/*.toml ../assets/targets/*.toml corpus/toml_profile/
printf '125x110' >corpus/toml_profile/dims
mkdir -p corpus/chuck
printf 'grip=30,tail=-1' >corpus/chuck/compact
printf 'grip=45,jaw=20,face=-80,od=200,depth=100,tail=1,quill=40,quill_length=150' >corpus/chuck/compact-all
cp ../assets/corpus/gsk980/jaws-grip45.toml corpus/chuck/
mkdir -p corpus/dxf
cp seeds/decode/*.nc corpus/decode/
cp seeds/dxf/*.dxf corpus/dxf/
echo "seeded: $(ls corpus | wc -l) targets"
