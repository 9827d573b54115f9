#!/usr/bin/env python3
"""Writes the report-scaling benchmark program: N lines of G01 zig-zag on a Φ125 × 110 bar.

Back and forth along Z (Z-5 <-> Z-95) while X changes by a tiny amount every move, so no
two moves are collinear and nothing merges. By default X climbs from 126 to 130, just above
the bar (every move an air cut: the removal is cheap and the reports' own cost shows); with
`cut` X falls from 124 to 120 and every move cuts a sliver (a removal benchmark). Usage:
    scripts/zigzag.py 1000000 > /tmp/zz1e6.nc
    scripts/zigzag.py 100000 cut > /tmp/zzcut1e5.nc
    /usr/bin/time -f "%e s %M KB" target/release/latsim run /tmp/zz1e6.nc --stock 125x110 --out /tmp/zz
"""
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
cut = len(sys.argv) > 2 and sys.argv[2] == "cut"
x0, x1 = (124.0, 120.0) if cut else (126.0, 130.0)
out = sys.stdout
out.write(f"O9002;\nG99 M03 S600 T0101;\nG00 X131. Z-5.;\nG01 X{x0:.1f} F0.2;\n")
lines = []
for k in range(n):
    x = x0 + (x1 - x0) * (k + 1) / n
    z = -95.0 if k % 2 == 0 else -5.0
    lines.append(f"G01 X{x:.4f} Z{z:.1f};\n")
    if len(lines) >= 10000:
        out.write("".join(lines))
        lines.clear()
out.write("".join(lines))
out.write("G00 X131.;\nG00 Z2.;\nM30;\n")
