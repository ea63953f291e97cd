#!/usr/bin/env bash
# cli_lower_bound.sh - bench/lower_bound.py's two bounds: on every maze of
# mazes/ (and japan2018, japan2019 where the database is) the diagonal bound
# (every path of firmware/slalom.h's moves) is at most the orthogonal one
# (the best path with 90 mm turns: the diagonal graph holds that path); on a
# straight corridor, where no turn fits, the two are equal; on an open maze
# the diagonal one is lower; fewer speed bins (each a union of finer ones)
# never give a higher bound; the half-size robot in 90 mm cells turns on
# 45 mm arcs; bench/best_vs_bound.py's ratios and summary
# are the hand-computed ones; bad input is one error line and exit 2.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
MMMAZE=${MMMAZE:-$B/mmmaze}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
SHARED=${SHARED:-../shared}
LB=(python3 bench/lower_bound.py --mmsim "$MMSIM" --mmmaze "$MMMAZE")

mazes=(mazes/gen-*.txt)
for m in japan2018 japan2019; do
  [ -f "$SHARED/mazes/classic/$m.txt" ] && mazes+=("$SHARED/mazes/classic/$m.txt")
done
want_rc 0 "both bounds on ${#mazes[@]} mazes" "${LB[@]}" --json "${mazes[@]}"
python3 - "$T/out" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "diagonal above orthogonal: $(cat "$T/msg")"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
worse = [(r["maze"], r["diag_bound_s"], r["bound_s"]) for r in rows if r["diag_bound_s"] > r["bound_s"]]
assert rows and not worse, worse
print("diagonal <= orthogonal on all %d: %s" % (len(rows), ", ".join(
    "%s %.2f/%.2f" % (r["maze"].split("/")[-1][:-4], r["diag_bound_s"], r["bound_s"]) for r in rows)))
PY

# a straight corridor 1 x 6, start at the bottom, goal at the top
{ echo "o---o"; echo "| G |"; for _ in 1 2 3 4; do echo "o   o"; echo "|   |"; done; echo "o   o"; echo "| S |"; echo "o---o"; } >"$T/corridor.txt"
open_mazes "$T"
want_rc 0 "corridor and open 16x16" "${LB[@]}" --json "$T/corridor.txt" "$T/open.txt"
python3 - "$T/out" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "corridor/open: $(cat "$T/msg")"
import json, sys
c, o = [json.loads(l) for l in open(sys.argv[1])]
assert c["turns"] == 0 and c["diag_bound_s"] == c["bound_s"], c
assert c["diag_moves"] == 1 and c["diag_turns"] == {}, c
assert o["diag_bound_s"] < o["bound_s"], o
print("corridor: both %.2f s in one straight; open 16x16: diagonal %.2f < orthogonal %.2f s" % (
    c["bound_s"], o["diag_bound_s"], o["bound_s"]))
PY

# the half-size robot in 90 mm cells: turns of half a cell, the same order
want_rc 0 "kerise-v5 in 90 mm cells" "${LB[@]}" --robot robots/kerise-v5.ini --config mazes/halfsize-world.ini mazes/gen-8x8-s1.txt
grep -q "^turns: R 45 mm" "$T/out" && grep -q "S90 R 45 mm" "$T/out" && ok "half-size turns: R 45 mm (half a 90 mm cell)" \
  || bad "half-size turns: $(head -3 "$T/out")"
python3 - "$T/out" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "half-size: $(cat "$T/msg")"
import re, sys
last = open(sys.argv[1]).read().splitlines()[-1]
o, d = float(re.search(r"lower bound ([0-9.]+) s", last)[1]), float(re.search(r"diagonal bound ([0-9.]+) s", last)[1])
assert d <= o, last
print("half-size gen-8x8-s1: diagonal %.2f <= orthogonal %.2f s" % (d, o))
PY

# bins: 6 equal steps are unions of 24's (both grids hold the same limits)
for n in 6 24; do
  want_rc 0 "--bins $n on gen-16x16-s2" "${LB[@]}" --json --bins $n mazes/gen-16x16-s2.txt
  cp "$T/out" "$T/bins$n"
done
python3 - "$T/bins6" "$T/bins24" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "bins: $(cat "$T/msg")"
import json, sys
a, b = (json.loads(open(f).read()) for f in sys.argv[1:3])
assert a["diag_bound_s"] <= b["diag_bound_s"] <= b["diag_path_s"], (a, b)
print("6 bins %.2f <= 24 bins %.2f <= that path's own time %.2f s" % (a["diag_bound_s"], b["diag_bound_s"], b["diag_path_s"]))
PY

# the same inputs print the same
want_rc 0 "again on gen-8x8-s1" "${LB[@]}" --json mazes/gen-8x8-s1.txt; cp "$T/out" "$T/a"
want_rc 0 "and again" "${LB[@]}" --json mazes/gen-8x8-s1.txt
cmp -s "$T/a" "$T/out" && ok "the same JSON twice" || bad "two runs differ"

# best_vs_bound.py on known figures: four results against a bounds file
cat >"$T/bounds.jsonl" <<'JSON'
{"maze": "x/a.txt", "bound_s": 10.0, "diag_bound_s": 8.0}
{"maze": "x/b.txt", "bound_s": 20.0, "diag_bound_s": 16.0}
{"maze": "x/c.txt", "bound_s": 5.0, "diag_bound_s": 4.0}
JSON
cat >"$T/results.jsonl" <<'JSON'
{"maze": "y/a.txt", "reached_goal": true, "best_run_s": 9.0}
{"maze": "y/b.txt", "reached_goal": true, "best_run_s": 30.0}
{"maze": "y/c.txt", "reached_goal": false, "best_run_s": null}
{"maze": "y/d.txt", "reached_goal": false, "best_run_s": null}
JSON
want_rc 0 "best_vs_bound.py on known figures" python3 bench/best_vs_bound.py "$T/results.jsonl" --bounds "$T/bounds.jsonl" --json
python3 - "$T/out" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "best_vs_bound: $(cat "$T/msg")"
import json, sys
d = json.loads(open(sys.argv[1]).read())
s, rows = d["summary"], {r["maze"]: r for r in d["rows"]}
assert sorted(rows) == ["a", "b", "c"], rows                     # d: no bound (unreachable)
assert rows["a"]["best_over_diag"] == 1.125 and rows["a"]["best_over_ortho"] == 0.9, rows["a"]
assert rows["b"]["best_over_diag"] == 1.875 and rows["b"]["best_over_ortho"] == 1.5, rows["b"]
assert rows["c"]["best_over_diag"] is None, rows["c"]
assert s["mazes"] == 3 and s["with_best_run"] == 2, s
assert s["best_over_diag"] == {"median": 1.5, "max": 1.875, "within_1.15x": 1}, s
assert s["best_over_ortho"] == {"median": 1.2, "max": 1.5, "within_1.15x": 1}, s
print("best_vs_bound.py: ratios, medians, maxima and the counts within 1.15x as computed by hand")
PY

ONE_ERROR_LINE=1
want_rc 2 "a missing maze: exit 2" "${LB[@]}" "$T/none.txt"
printf 'o---o\n| S x\n' >"$T/bad.txt"
want_rc 2 "a malformed maze: exit 2" "${LB[@]}" "$T/bad.txt"
echo "int x;" >"$T/slalom.c"
want_rc 2 "a slalom table without turns: exit 2" "${LB[@]}" --slalom "$T/slalom.c" mazes/gen-5x5-s1.txt
grep -q "slalom.c:1:1: no turns" "$T/err" && ok "it names the file" || bad "error line: $(cat "$T/err")"
want_rc 2 "--bins 0: exit 2" "${LB[@]}" --bins 0 mazes/gen-5x5-s1.txt
echo "not json" >"$T/junk.jsonl"
want_rc 2 "best_vs_bound.py on a line that is not JSON: exit 2" python3 bench/best_vs_bound.py "$T/junk.jsonl" --bounds "$T/bounds.jsonl"
grep -q "junk.jsonl:1:" "$T/err" && ok "it names the file and line" || bad "error line: $(cat "$T/err")"
unset ONE_ERROR_LINE

[ $fails -eq 0 ] && echo "cli_lower_bound: all ok" || { echo "cli_lower_bound: $fails failed"; exit 1; }
