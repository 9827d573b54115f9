#!/usr/bin/env python3
"""The field test (issue 31): read public lathe programs with `latsim check` and compare each
reading with the triage recorded for it, so that the habit costs one command.

The public programs are not ours and never enter the repository: they live in a folder
outside it (default /work/field-programs, or $FIELD_PROGRAMS). `scripts/field-test.tsv` says
where each came from and how it was triaged:

    id <TAB> written_for <TAB> run_as <TAB> source <TAB> triage <TAB> note

- id: the file name inside the programs folder;
- written_for: the control the program was written for (haas, fanuc-0i, gsk980, linuxcnc …);
- run_as: the `--control` latsim is run with (the supported control closest to it);
- source: github:owner/repo@commit:path;
- triage: what the reading must be today: `clean` (exit 0), `own` (the program's own
  error: latsim stops at its line with a clear message), `unsupported` (a construct of a
  control latsim does not read: an alarm at the word naming it, or a refusal saying whose
  syntax it is), `bug` (a wrong reading of a supported control, not fixed yet; the note
  names the root cause).

    scripts/field-test.py gather   # copy each program out of the fetched mirrors (/work/.mirror)
    scripts/field-test.py run      # run latsim check on each and print the table; exit 1
                                   # when a reading differs from its recorded triage
    scripts/field-test.py run -v   # also print each program's first diagnostic
"""

import collections
import os
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
LIST = ROOT / "scripts" / "field-test.tsv"
PROGRAMS = pathlib.Path(os.environ.get("FIELD_PROGRAMS", "/work/field-programs"))
MIRRORS = pathlib.Path(os.environ.get("FIELD_MIRRORS", "/work/.mirror"))
LATSIM = pathlib.Path(os.environ.get("LATSIM", ROOT / "target" / "release" / "latsim"))


def rows():
    """The list, one dict a program (comments and blank lines skipped)."""
    out = []
    for n, line in enumerate(LIST.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cols = line.split("\t")
        if len(cols) < 5:
            sys.exit(f"{LIST}:{n}: expected 5 or 6 tab-separated columns")
        pid, written, run_as, source, triage = cols[:5]
        note = cols[5] if len(cols) > 5 else ""
        out.append(dict(id=pid, written=written, run_as=run_as, source=source,
                        triage=triage, note=note, line=n))
    return out


def gather():
    """Copy each listed program out of its fetched mirror, byte for byte."""
    PROGRAMS.mkdir(parents=True, exist_ok=True)
    missing = 0
    for r in rows():
        m = re.fullmatch(r"github:([^/]+)/([^@]+)@([0-9a-f]+):(.+)", r["source"])
        if not m:
            continue
        owner, repo, commit, path = m.groups()
        git_dir = MIRRORS / f"{owner}+{repo}" / "repo"
        if (git_dir / ".git").exists():
            git_dir = git_dir / ".git"
        if not git_dir.exists():
            if (PROGRAMS / r["id"]).exists():
                continue  # copied by hand from the stored file (no snapshot to fetch)
            print(f"not fetched: {owner}/{repo} (fetch it with the search tool's fetch)")
            missing += 1
            continue
        data = subprocess.run(["git", "--git-dir", str(git_dir), "show", f"{commit}:{path}"],
                              capture_output=True, check=True).stdout
        (PROGRAMS / r["id"]).write_bytes(data)
    print(f"gathered into {PROGRAMS}; {missing} missing")


def read(r):
    """Run latsim check on one program: (reading, first diagnostic line)."""
    path = PROGRAMS / r["id"]
    if not path.exists():
        return "missing", ""
    args = [str(LATSIM), "check", str(path), "--control", r["run_as"], "--quiet"]
    extra = re.search(r"flags=([^ ]+)", r["note"])
    if extra:
        args += extra.group(1).split(",")
    p = subprocess.run(args, capture_output=True, text=True, errors="replace", timeout=120)
    first = summary(p.stderr)
    reading = {0: "clean", 1: "alarm", 2: "refused"}.get(p.returncode, f"exit {p.returncode}")
    return reading, first.strip()


def summary(stderr):
    """The first diagnostic as `CODE line:col message`."""
    lines = stderr.splitlines()
    for i, l in enumerate(lines):
        if l.strip().startswith("×"):
            code = lines[i - 2].strip() if i >= 2 else ""
            message = l.strip()[1:].strip()
            j = i + 1
            # the message wrapped over lines that start with │
            while j < len(lines) and lines[j].strip().startswith("│"):
                message += " " + lines[j].strip()[1:].strip()
                j += 1
            place = next((re.search(r":(\d+:\d+)\]", m).group(1) for m in lines[j:j + 2]
                          if re.search(r":(\d+:\d+)\]", m)), "")
            return f"{code} {place} {message}"
    return next((l.strip() for l in lines if l.strip()), "")


def agrees(triage, reading, first):
    """Whether a reading is what the recorded triage says it must be. A construct of an
    unsupported control must be named: an alarm at its word, or a refusal that says whose
    syntax it is (not "unexpected character")."""
    if triage == "clean":
        return reading == "clean"
    if triage == "unsupported":
        return reading == "alarm" or (reading == "refused" and "syntax, not FANUC" in first)
    if triage in ("own", "bug"):
        return reading in ("alarm", "refused")
    return False


def run(verbose):
    table = collections.defaultdict(collections.Counter)
    causes = collections.Counter()
    differ = []
    for r in rows():
        reading, first = read(r)
        table[r["written"]]["tried"] += 1
        table[r["written"]][r["triage"]] += 1
        if r["triage"] == "bug":
            causes[r["note"].split(";")[0]] += 1
        if not agrees(r["triage"], reading, first):
            differ.append((r, reading, first))
        if verbose:
            print(f"{r['id']:<44} {r['run_as']:<8} {reading:<8} {r['triage']:<11} {first[:110]}")
    print(f"\n{'written for':<14} {'tried':>5} {'clean':>5} {'own':>5} {'unsup':>5} {'wrong':>5}")
    for ctl, c in sorted(table.items()):
        print(f"{ctl:<14} {c['tried']:>5} {c['clean']:>5} {c['own']:>5} {c['unsupported']:>5} {c['bug']:>5}")
    total = sum((c for c in table.values()), collections.Counter())
    print(f"{'all':<14} {total['tried']:>5} {total['clean']:>5} {total['own']:>5} "
          f"{total['unsupported']:>5} {total['bug']:>5}")
    for cause, n in causes.most_common():
        print(f"  wrong, {n}: {cause}")
    for r, reading, first in differ:
        print(f"DIFFERS {r['id']}: triage {r['triage']}, read {reading}: {first}")
    return 1 if differ else 0


if __name__ == "__main__":
    cmd = sys.argv[1] if len(sys.argv) > 1 else "run"
    if cmd == "gather":
        gather()
    elif cmd == "run":
        sys.exit(run("-v" in sys.argv))
    else:
        sys.exit(__doc__)
