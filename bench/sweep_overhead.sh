#!/usr/bin/env bash
# sweep_overhead.sh - runs per minute of the classic folder x 4 seeds with the
# scripted driver: `mmsim --batch --jobs 2` (once per seed) against
# `tools/mmsweep --workers 2` (one sweep of the 4 seeds, its LocalCluster
# started and stopped inside the time). Run on a quiet machine; record the
# output in docs/BENCHMARKS.md with the date. Both sides' per-run results
# are compared (sim_time_s and best_run_s per maze and seed).
# Usage: bench/sweep_overhead.sh [MAZE_DIR] [TIME_LIMIT_S]
set -u
B=${B:-build}
DIR=${1:-${SHARED:-../shared}/mazes/classic}
TL=${2:-20}
[ -d "$DIR" ] || { echo "SKIP sweep_overhead: $DIR not found"; exit 0; }
tmp=$B/bench-sweep; rm -rf "$tmp"; mkdir -p "$tmp"
n=$(ls "$DIR"/*.txt | wc -l)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u '+%Y-%m-%d %H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)"
# Each side's wall time and its processes' CPU time (user + system of every
# process it waited for: the mmsim children, Dask's workers and theirs). The
# CPU figure is the one a busy machine disturbs least. ORDER=sweep-first
# runs mmsweep before the batch, so two calls make an A-B-B-A pair.
batch() {
  for s in 1 2 3 4; do
    $B/mmsim --batch "$DIR" --jobs 2 --seed $s --driver scripted --time-limit "$TL" --json > "$tmp/batch-$s.jsonl" 2>/dev/null
  done
}
sweep() {
  tools/mmsweep --mazes "$DIR" --seeds 1-4 --driver scripted --time-limit "$TL" --workers 2 \
    --mmsim "$B/mmsim" --out "$tmp/sweep.parquet" --quiet 2>"$tmp/sweep.err" || echo "mmsweep exit $?"
}
timed() { /usr/bin/time -f "%e %U %S" -o "$tmp/$1.time" bash -c "$(declare -f batch sweep); B=$B DIR=$DIR TL=$TL tmp=$tmp; $1"; }
if [ "${ORDER:-}" = sweep-first ]; then timed sweep; timed batch; else timed batch; timed sweep; fi
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
PYTHONPATH=python build/venv/bin/python - "$tmp" "$n" <<'PY'
import glob, json, os, sys
import pandas as pd
from mmsim import store
tmp, n = sys.argv[1], int(sys.argv[2])
tb, cb = (lambda e, u, s: (e, u + s))(*map(float, open(os.path.join(tmp, "batch.time")).read().split()[-3:]))
ts, cs = (lambda e, u, s: (e, u + s))(*map(float, open(os.path.join(tmp, "sweep.time")).read().split()[-3:]))
rows = {}
for s in range(1, 5):
    for line in open(os.path.join(tmp, "batch-%d.jsonl" % s)):
        d = json.loads(line)
        rows[(os.path.basename(d["maze"]), s)] = (d.get("sim_time_s"), d.get("best_run_s"), d.get("wall_time_s", 0))
df = store.read(os.path.join(tmp, "sweep.parquet"))
same = diff = 0
for _, r in df.iterrows():
    k = (os.path.basename(r["maze"]), int(r["seed"]))
    b = rows.get(k)
    if b is not None and b[0] == r.get("sim_time_s") and (b[1] == r.get("best_run_s") or (b[1] is None and pd.isna(r.get("best_run_s")))):
        same += 1
    else:
        diff += 1
nb, ns = len(rows), len(df)
wb = sum(v[2] for v in rows.values()); ws = float(df["wall_time_s"].sum()) if "wall_time_s" in df else float("nan")
print("runs: %d mazes x 4 seeds" % n)
print("mmsim --batch --jobs 2: %d runs in %.1f s = %.1f runs/min; CPU %.1f s (runs' own wall_time_s summed %.1f s)" % (nb, tb, 60 * nb / tb, cb, wb))
print("mmsweep --workers 2:    %d runs in %.1f s = %.1f runs/min; CPU %.1f s (runs' own wall_time_s summed %.1f s)" % (ns, ts, 60 * ns / ts, cs, ws))
print("CPU per run, mmsweep / batch: %.3f (%+.1f %%)" % ((cs / ns) / (cb / nb), 100 * ((cs / ns) / (cb / nb) - 1)))
print("mmsweep time per run / batch's: %.3f (Dask's overhead %+.1f %%); rows identical in sim_time_s and best_run_s: %d, different or missing: %d" % (
    (ts / ns) / (tb / nb), 100 * ((ts / ns) / (tb / nb) - 1), same, diff))
PY
