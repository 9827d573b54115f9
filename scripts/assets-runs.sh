# The assets' runs: each program of assets/programs/ with its fixed blank and tool table.
# Sourced by scripts/assets-json.sh and scripts/assets-reports.sh, which define
# run NAME PROGRAM ARGS... (what each writes) before sourcing it.
t=assets/tools
run G71-type1 G71-type1.nc --stock 60x80 --tools $t/v35-sharp.toml
run G71-type2 G71-type2.nc --stock 60x80 --tools $t/v35-sharp.toml
run G72-facing G72-facing.nc --stock 60x80 --tools $t/v35-sharp.toml
run G75_1-cone G75_1-cone.nc --stock-file assets/blanks/cone-10deg.toml
run G75_1-corners G75_1-corners.nc --stock 70x40
run G75_1-finish-only G75_1-finish-only.nc --stock 60x80 --stock-z 40 --increment is-c --tools $t/seed000-groove4.toml
run O0002 O0002.nc --stock 125x110 --tools $t/v35-sharp.toml
run O0006-rough O0006-rough.nc --stock-file assets/blanks/o0006-casting.toml --tools $t/d55-sharp.toml
run O0006 O0006.nc --stock-file assets/blanks/o0006-casting.toml --tools $t/d55-sharp.toml
run O0008-I4 O0008-I4.nc --stock 60x80 --stock-z 40 --increment is-c --tools $t/seed000-groove4.toml
run O0008 O0008.nc --stock 60x80 --stock-z 40 --machine assets/machines/gsk980tdi-isc.toml --tools $t/seed000-groove4.toml
run O0209-chamfers O0209-chamfers.nc --stock 60x100 --tools $t/seed002-groove3.toml
run O0209 O0209.nc --stock 60x100 --tools $t/seed002-groove3.toml
run O0210 O0210.nc --stock 60x100 --tools $t/seed002-face3-drill10.toml
run g73-forum g73-forum.nc --stock 32x60 --tools $t/d55-sharp.toml
run gouge-55deg-slope gouge-55deg-slope.nc --stock 40x40 --tools $t/d55-sharp.toml
run seed004-contour seed004-contour.nc --stock 36x40 --tools $t/v35-sharp.toml
run tnrc-g70-seed004 tnrc-g70-seed004.nc --stock 36x40 --tools $t/seed004-v35-r1.toml
run tnrc-id-boring tnrc-id-boring.nc --stock 60x40 --bore 30 --tools $t/boring-r08-tip2.toml
run tnrc-interference tnrc-interference.nc --stock 42x40 --target assets/targets/tnrc-interference.toml --tools $t/seed004-v35-r1.toml
run tnrc-seed004-rough tnrc-seed004-rough.nc --stock 36x40 --tools $t/seed004-v35-r1.toml
run tnrc-seed004 tnrc-seed004.nc --stock 36x40 --tools $t/seed004-v35-r1.toml
run cone45 gouge-55deg-slope.nc --stock 40x40 --target assets/targets/cone45-valley.toml --tools $t/d55-sharp.toml
