#!/usr/bin/env bash
# cli_sweep.sh - python/mmsim and tools/mmsweep under pytest
# (test/python/test_sweep.py): Dask sweeps against runs one by one, a worker
# killed, a sweep stopped and started again, a scheduler and workers as
# separate processes, a bad --vary key, mmsweep plot's numbers. It runs on
# Debian's python3 through the project venv (make deps: build/venv, with
# pyarrow); SKIP only when those are not installed.
set -u
B=${BUILD:-build}
PY=$B/venv/bin/python
[ -x "$PY" ] || { echo "SKIP cli_sweep: no $PY (make deps makes the venv)"; exit 77; }
for m in dask distributed pandas pyarrow pytest matplotlib; do
  "$PY" -c "import $m" 2>/dev/null || { echo "SKIP cli_sweep: $PY cannot import $m (make deps)"; exit 77; }
done
export MMSIM=${MMSIM:-$B/mmsim}
case $MMSIM in /*) ;; *) MMSIM=$PWD/$MMSIM ;; esac
exec "$PY" -m pytest -q -p no:cacheprovider -p no:logging test/python/test_sweep.py
