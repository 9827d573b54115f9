#!/usr/bin/env python3
"""latsim against the script a user would write with shapely/GEOS, on the same sweeps.

Contour-parallel roughing of a wavy profile on a Φ125 × 110 bar: PASSES passes, each the
finished profile moved out by 0.3 mm (the last pass is the profile), a sharp 35° V insert
on a 93° holder (tip 3, 11 mm edges), MOVES/PASSES G01 moves per pass, rapids back.

The script writes the program and the tool table, times the whole `latsim run --json`
process, then builds the very sweeps latsim builds (the convex hull of the insert at both
ends of every move; the insert is convex) and times shapely's `union_all` of them and the
`difference` from the bar (the booleans alone: building the polygons is not counted).
It prints both times (wall clock and cpu), the ratios and the two removed areas.

    python3 benches/geos_compare.py [MOVES ...]        # default 10000 100000

Environment: REPORTS=all runs latsim with all four reports (`--svg --png --html` beside
`--json`: issue 32's figure); LATSIM=path times that binary instead of target/release/latsim;
RUNS=n times n pairs (latsim, then GEOS) and prints the medians and the median of the
pairs' ratios (default 1).

Needs Python 3 and shapely 2 (installed into benches/.venv from PyPI when missing).
Not part of `cargo test`.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PASSES = 50
STEP = 0.3  # mm between passes, radial
EDGE = 11.0
INSERT = [
    (0.0, 0.0),
    (EDGE * math.cos(math.radians(87)), EDGE * math.sin(math.radians(87))),
    (
        EDGE * (math.cos(math.radians(87)) + math.cos(math.radians(52))),
        EDGE * (math.sin(math.radians(87)) + math.sin(math.radians(52))),
    ),
    (EDGE * math.cos(math.radians(52)), EDGE * math.sin(math.radians(52))),
]
TOOLS = """[[tool]]
t = 1
kind = "turning"
insert = "V"
nose_radius = 0.0
tip = 3
entering_angle = 93
edge = 11.0
"""


def ensure_shapely():
    try:
        import shapely  # noqa: F401

        return sys.executable
    except ImportError:
        pass
    venv = os.path.join(ROOT, "benches", ".venv")
    py = os.path.join(venv, "bin", "python3")
    if not os.path.exists(py):
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
    subprocess.run([py, "-m", "pip", "install", "-q", "shapely>=2"], check=True)
    return py


def profile_r(z):
    """The finished profile: a wave around Φ70 from the face to Z-100."""
    return 35.0 + 3.0 * math.sin(z / 6.0) + 1.5 * math.sin(z / 2.3)


def moves(total):
    """The toolpath as (kind, z0, r0, z1, r1) in the (z, r) half plane."""
    per_pass = max(2, total // PASSES)
    out = []
    pos = (5.0, 65.0)
    for p in range(PASSES):
        off = STEP * (PASSES - 1 - p)
        start = (2.0, profile_r(0.0) + off)
        out.append(("G00", pos[0], pos[1], start[0], start[1] + 1.0))
        out.append(("G00", start[0], start[1] + 1.0, start[0], start[1]))
        prev = start
        for k in range(1, per_pass + 1):
            z = 2.0 - 102.0 * k / per_pass
            cur = (z, profile_r(min(z, 0.0)) + off)
            out.append(("G01", prev[0], prev[1], cur[0], cur[1]))
            prev = cur
        out.append(("G01", prev[0], prev[1], prev[0], 64.0))
        out.append(("G00", prev[0], 64.0, 5.0, 64.0))
        pos = (5.0, 64.0)
    return out


def program(mv):
    lines = ["O9100;", "G99 M03 S800 T0101;", "G00 X130. Z5.;"]
    last = None
    for kind, _, _, z1, r1 in mv:
        word = f"X{2 * r1:.4f} Z{z1:.4f}"
        lines.append(f"{kind} {word}" + (" F0.2;" if kind == "G01" and last != "G01" else ";"))
        last = kind
    lines.append("M30;")
    return "\n".join(lines) + "\n"


def geos_seconds(py, mv, workdir):
    data = os.path.join(workdir, "moves.txt")
    with open(data, "w") as f:
        for _, z0, r0, z1, r1 in mv:
            f.write(f"{z0} {r0} {z1} {r1}\n")
    code = f"""
import time, shapely
from shapely.geometry import MultiPoint, box
insert = {INSERT!r}
polys = []
for line in open({data!r}):
    z0, r0, z1, r1 = map(float, line.split())
    pts = [(z0 + a, r0 + b) for a, b in insert] + [(z1 + a, r1 + b) for a, b in insert]
    polys.append(MultiPoint(pts).convex_hull)
bar = box(-110.0, 0.0, 0.0, 62.5)
t, c = time.perf_counter(), time.process_time()
cut = shapely.union_all(polys)
final = bar.difference(cut)
dt, dc = time.perf_counter() - t, time.process_time() - c
print(dt, dc, bar.area - final.area)
"""
    out = subprocess.run([py, "-c", code], check=True, capture_output=True, text=True).stdout
    dt, dc, removed = out.split()
    return float(dt), float(dc), float(removed)


def latsim_seconds(nc, tools, workdir):
    binary = os.environ.get("LATSIM") or os.path.join(ROOT, "target", "release", "latsim")
    if not os.path.exists(binary):
        subprocess.run(["cargo", "build", "--release", "--locked"], cwd=ROOT, check=True)
    js = os.path.join(workdir, "out.json")
    args = [binary, "run", nc, "--stock", "125x110", "--tools", tools, "--json", js, "--quiet"]
    if os.environ.get("REPORTS") == "all":
        out = os.path.join(workdir, "out")
        args += ["--svg", out + ".svg", "--png", out + ".png", "--html", out + ".html"]
    import json
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    subprocess.run(args, check=False, capture_output=True)
    dt = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    dc = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(js) as f:
        return dt, dc, json.load(f)["removed_area_mm2"]


def main():
    if shutil.which("python3") is None and not sys.executable:
        print("geos_compare: no Python here, skipped")
        return
    sizes = [int(a) for a in sys.argv[1:]] or [10_000, 100_000]
    py = ensure_shapely()
    print(
        "| moves | latsim (whole process) wall / cpu s | GEOS booleans wall / cpu s "
        "| ratio wall / cpu | removed latsim / GEOS mm² |"
    )
    print("|---:|---:|---:|---:|---|")
    for n in sizes:
        with tempfile.TemporaryDirectory() as d:
            mv = moves(n)
            nc = os.path.join(d, "rough.nc")
            tools = os.path.join(d, "tools.toml")
            with open(nc, "w") as f:
                f.write(program(mv))
            with open(tools, "w") as f:
                f.write(TOOLS)
            # in turn, latsim then GEOS, so a box whose speed drifts slows both of a pair;
            # each figure is a median, each ratio the median of the pairs' ratios
            runs = int(os.environ.get("RUNS", "1"))
            pairs = [(latsim_seconds(nc, tools, d), geos_seconds(py, mv, d)) for _ in range(runs)]

            def median(values):
                return sorted(values)[runs // 2]

            lw, lc = median(l[0] for l, _ in pairs), median(l[1] for l, _ in pairs)
            gw, gc = median(g[0] for _, g in pairs), median(g[1] for _, g in pairs)
            rw = median(g[0] / l[0] for l, g in pairs)
            rc = median(g[1] / l[1] for l, g in pairs)
            a_l, a_g = pairs[0][0][2], pairs[0][1][2]
            print(
                f"| {len(mv)} | {lw:.3f} / {lc:.3f} | {gw:.3f} / {gc:.3f} "
                f"| {rw:.1f}× / {rc:.1f}× | {a_l:.2f} / {a_g:.2f} |"
            )


if __name__ == "__main__":
    main()
