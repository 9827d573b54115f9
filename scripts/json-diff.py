#!/usr/bin/env python3
"""Compares two folders of latsim JSON reports: same fields, same strings, numbers equal to
a relative tolerance (default 1e-9). Usage: json-diff.py BEFORE AFTER [REL_TOL]"""
import json, math, os, sys

def diff(a, b, path, tol, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}.{k}: only in {'after' if k in b else 'before'}")
            else:
                diff(a[k], b[k], f"{path}.{k}", tol, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: length {len(a)} -> {len(b)}")
        for i, (x, y) in enumerate(zip(a, b)):
            diff(x, y, f"{path}[{i}]", tol, out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if not math.isclose(a, b, rel_tol=tol, abs_tol=1e-12):
            out.append(f"{path}: {a} -> {b}")
    elif a != b:
        out.append(f"{path}: {a!r} -> {b!r}")

before, after = sys.argv[1], sys.argv[2]
tol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-9
bad = 0
for name in sorted(os.listdir(before)):
    p, q = os.path.join(before, name), os.path.join(after, name)
    if not os.path.exists(q):
        print(f"{name}: missing after"); bad += 1; continue
    if name.endswith(".out"):
        if open(p).read() != open(q).read():
            print(f"{name}: console output differs"); bad += 1
        continue
    out = []
    diff(json.load(open(p)), json.load(open(q)), name, tol, out)
    for line in out[:20]:
        print(line)
    bad += bool(out)
print(f"{bad} of {len(os.listdir(before))} files differ")
sys.exit(1 if bad else 0)
