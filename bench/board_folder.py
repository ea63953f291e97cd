#!/usr/bin/env python3
"""board_folder.py - a folder of contests on an emulated board, summed up.

Reads `mmsim --batch DIR --board ... --end-on "contest done" --json` lines
(a file or stdin) and grades each maze:
  reachable  mmmaze solve finds a route from the start to the goal;
  reached    the JSON's reached_goal;
  no contact contacts.front == 0 and contacts.side == 0 (a board run's
             touches of walls and posts, ahead or beside);
  shortest   the firmware's console says "explore: run path proven at step
             N, cost C" and C is the true best path's cost (mmmaze solve's
             cost: the same heading-aware count of cells and turns), so
             every speed run follows a proven shortest path;
  clean      all four.
Prints the summary and, with --table, a Markdown row per maze.
Usage: bench/board_folder.py RESULTS.jsonl [--mmmaze build/mmmaze] [--table]
"""
import argparse
import json
import re
import subprocess
import sys

PROVEN = re.compile(r"explore: run path proven at step (\d+), cost (\d+)")


def truth(mmmaze, maze):
    p = subprocess.run([mmmaze, "solve", maze, "--json"], capture_output=True, text=True)
    if p.returncode not in (0, 1) or not p.stdout.strip():
        raise SystemExit("board_folder: mmmaze solve %s: exit %d: %s" % (maze, p.returncode, p.stderr.strip()))
    d = json.loads(p.stdout)
    return d["goal_reachable"], d.get("cost")


def grade(j, mmmaze):
    reachable, cost = truth(mmmaze, j["maze"])
    console = (j.get("console") or "").replace("\r", "")
    proven = PROVEN.findall(console)
    k = j.get("contacts") or {}
    row = {"maze": j["maze"].split("/")[-1], "reachable": reachable, "reached": bool(j.get("reached_goal")),
           "contacts": (k.get("front", 0), k.get("side", 0)), "true_cost": cost,
           "proven_cost": int(proven[-1][1]) if proven else None, "reason": j.get("exit_reason"),
           "first": j.get("first_run_s"), "best": j.get("best_run_s"), "sim": j.get("sim_time_s")}
    row["no_contact"] = row["contacts"] == (0, 0)
    row["shortest"] = row["proven_cost"] is not None and row["proven_cost"] == cost
    row["clean"] = reachable and row["reached"] and row["no_contact"] and row["shortest"]
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--mmmaze", default="build/mmmaze")
    ap.add_argument("--table", action="store_true")
    a = ap.parse_args()
    src = sys.stdin if a.results == "-" else open(a.results)
    rows = [grade(json.loads(l), a.mmmaze) for l in src if l.strip()]
    reach = [r for r in rows if r["reachable"]]
    n = len(reach)
    def cnt(key):
        return sum(1 for r in reach if r[key])
    pct = 100.0 * cnt("clean") / n if n else 0.0
    print("mazes %d, reachable %d: reached %d, no contact %d, proven shortest %d, clean %d (%.2f %%); simulated %.0f s" % (
        len(rows), n, cnt("reached"), cnt("no_contact"), cnt("shortest"), cnt("clean"), pct,
        sum(r["sim"] or 0 for r in rows)))
    for r in rows:
        if r["reachable"] and not r["clean"]:
            print("not clean: %s: reached %s, contacts front/side %s, proven cost %s of true %s, %s" % (
                r["maze"], r["reached"], r["contacts"], r["proven_cost"], r["true_cost"], r["reason"]))
    if a.table:
        print("\n| maze | reached | contacts front/side | proven cost / true | first run s | best run s | end |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        for r in rows:
            print("| %s | %s | %d/%d | %s / %s | %s | %s | %s |" % (
                r["maze"], "yes" if r["reached"] else ("no" if r["reachable"] else "no route"), *r["contacts"],
                r["proven_cost"], r["true_cost"], r["first"], r["best"], r["reason"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
