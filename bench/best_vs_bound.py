#!/usr/bin/env python3
"""best_vs_bound.py - each maze's best run against its physical lower bounds.

    bench/best_vs_bound.py RESULTS.jsonl [--bounds BOUNDS.jsonl] [--table]
                           [--rows NAME,NAME] [--mmsim build/mmsim]
                           [--mmmaze build/mmmaze] [--robot FILE] [--config FILE]
                           [--bins 24] [--json]

RESULTS.jsonl: `mmsim --batch DIR --json` (or single runs' --json lines):
per maze its "best_run_s" (the fastest completed lap) and "reached_goal".
The bounds are bench/lower_bound.py's, for the same robot and world (give
mmsim's --robot and --config as the batch had them): the orthogonal bound
(the best orthogonal path) and the diagonal bound (every path of the speed
run's moves, diagonals and slaloms); computed here for the results' mazes,
or read from a `lower_bound.py --json` file (--bounds) to save the time.

Per maze: best run / diagonal bound and best run / orthogonal bound (laps:
the completed laps, the search's first arrival included; with one lap the
best run is the search's). Prints
the summary (mazes with a best run, the median and the largest ratio, how
many within 1.15x), the --rows mazes (by file name without .txt) and, with
--table, a Markdown row per maze. Mazes whose goal is unreachable have no
bound and are left out; mazes reachable but without a best run are counted.
Exit 0, 2 on bad input, 3 if lower_bound.py fails.

One line for the classic folder on today's build:

    build/mmsim --batch ../shared/mazes/classic --jobs 2 --seed 1 --json >classic.jsonl && bench/best_vs_bound.py classic.jsonl --rows japan2018,japan2019
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
WITHIN = 1.15                                          # the issue's bar: best run within 1.15x of the bound


def fail(msg, code=2):
    print(msg, file=sys.stderr)
    sys.exit(code)


def read_jsonl(path):
    """The JSON objects of a file's lines (blank lines skipped)."""
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        fail(f"best_vs_bound: {path}: {e.strerror}")
    out = []
    for n, line in enumerate(lines, 1):
        if not line.strip():
            continue
        try:
            d = json.loads(line)
        except ValueError as e:
            fail(f"{path}:{n}:{e.colno}: not JSON: {e.msg}")
        if not isinstance(d, dict) or "maze" not in d:
            fail(f"{path}:{n}:1: no \"maze\" key")
        out.append(d)
    return out


def compute_bounds(a, mazes):
    """lower_bound.py --json over the mazes: {file name: its JSON}."""
    cmd = [sys.executable, os.path.join(HERE, "lower_bound.py"), "--json", "--mmsim", a.mmsim, "--mmmaze", a.mmmaze,
           "--bins", str(a.bins)]
    cmd += (["--robot", a.robot] if a.robot else []) + (["--config", a.config] if a.config else [])
    p = subprocess.run(cmd + mazes, capture_output=True, text=True)
    if p.returncode not in (0, 1):                     # 1: some goal unreachable (no bound)
        sys.stderr.write(p.stderr)
        sys.exit(p.returncode if p.returncode in (2, 3) else 3)
    return {os.path.basename(d["maze"]): d for d in map(json.loads, p.stdout.splitlines())}


def rows_of(results, bounds):
    """A row per maze with a bound: maze, best run, bounds and ratios (None without a best run)."""
    rows = []
    for r in results:
        b = bounds.get(os.path.basename(r["maze"]))
        if b is None:
            continue
        best = r.get("best_run_s") if r.get("reached_goal") else None
        row = {"maze": os.path.basename(r["maze"])[:-4] if r["maze"].endswith(".txt") else os.path.basename(r["maze"]),
               "laps": len(r.get("laps") or []), "best_run_s": best, "ortho_bound_s": b["bound_s"],
               "diag_bound_s": b["diag_bound_s"]}
        row["best_over_diag"] = round(best / b["diag_bound_s"], 3) if best and b["diag_bound_s"] > 0 else None
        row["best_over_ortho"] = round(best / b["bound_s"], 3) if best and b["bound_s"] > 0 else None
        rows.append(row)
    return rows


def summary(rows):
    """Counts, median and largest ratio, and how many within WITHIN, per bound."""
    out = {"mazes": len(rows), "with_best_run": sum(1 for r in rows if r["best_run_s"])}
    for k in ("best_over_diag", "best_over_ortho"):
        v = sorted(r[k] for r in rows if r[k] is not None)
        out[k] = {"median": round(statistics.median(v), 3) if v else None, "max": v[-1] if v else None,
                  "within_%.2fx" % WITHIN: sum(1 for x in v if x <= WITHIN)}
    return out


def fmt(x, f="%.2f"):
    return "-" if x is None else f % x


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.error = lambda msg: fail(f"best_vs_bound: {msg}")
    ap.add_argument("results")
    ap.add_argument("--bounds", help="lower_bound.py --json output for these mazes (default: computed)")
    ap.add_argument("--mmsim", default="build/mmsim")
    ap.add_argument("--mmmaze", default="build/mmmaze")
    ap.add_argument("--robot")
    ap.add_argument("--config")
    ap.add_argument("--bins", type=int, default=24)
    ap.add_argument("--rows", default="", help="mazes to print a line for (file names without .txt, comma-separated)")
    ap.add_argument("--table", action="store_true", help="a Markdown row per maze")
    ap.add_argument("--json", action="store_true", help="the summary and the rows as one JSON object")
    a = ap.parse_args()
    results = read_jsonl(a.results)
    if a.bounds:
        bounds = {os.path.basename(d["maze"]): d for d in read_jsonl(a.bounds)}
        if any("diag_bound_s" not in d for d in bounds.values()):
            fail(f"best_vs_bound: {a.bounds}: no diag_bound_s (lower_bound.py --no-diagonal?)")
    else:
        bounds = compute_bounds(a, [r["maze"] for r in results])
    rows = rows_of(results, bounds)
    s = summary(rows)
    if a.json:
        print(json.dumps({"summary": s, "rows": rows}))
        return 0
    for k, name in (("best_over_diag", "diagonal"), ("best_over_ortho", "orthogonal")):
        print(f"best run / {name} bound: {s['with_best_run']} of {s['mazes']} mazes with a best run: median "
              f"{fmt(s[k]['median'], '%.3f')}, max {fmt(s[k]['max'], '%.3f')}, within {WITHIN:.2f}x: "
              f"{s[k]['within_%.2fx' % WITHIN]}")
    want = [n for n in a.rows.split(",") if n]
    for r in rows:
        if r["maze"] in want:
            print(f"{r['maze']}: best {fmt(r['best_run_s'], '%.3f')} s, orthogonal bound {r['ortho_bound_s']:.2f} s "
                  f"({fmt(r['best_over_ortho'])}x), diagonal bound {r['diag_bound_s']:.2f} s ({fmt(r['best_over_diag'])}x)")
    if a.table:
        print("| maze | laps | best run | orthogonal bound | diagonal bound | best / orthogonal | best / diagonal |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        for r in rows:
            print(f"| {r['maze']} | {r['laps']} | {fmt(r['best_run_s'], '%.3f')} | {r['ortho_bound_s']:.2f} | {r['diag_bound_s']:.2f} | "
                  f"{fmt(r['best_over_ortho'])} | {fmt(r['best_over_diag'])} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
