#!/usr/bin/env bash
# cli_docs.sh - the figures and pictures the docs show are what the code
# gives now (`make docs` writes them): docs/VALIDATION.md's tables against
# `mmsim --validate` (tools/docs-validation --check), and docs/img's three
# pictures redrawn with the README's commands (`make docs-img` into a
# temporary folder) against the committed ones by test/tools/pngcheck.py (at most
# 0.5 % of the pixels moved by more than 16 of 255). The check must fail on
# a planted stale number and a planted stale picture. SKIPs without a
# display and without xvfb-run (the viewer's pictures need one).
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
[ -n "${DISPLAY:-}" ] || command -v xvfb-run >/dev/null || { echo "SKIP cli_docs: no display and no xvfb-run"; exit 77; }

# pngdiff A B: "N of M pixels differ (P %)"; status 1 when P > 0.5, 2 when they cannot be compared
pngdiff() { local wh n
  wh=$(python3 test/tools/pngcheck.py "$1" size) && n=$(python3 test/tools/pngcheck.py "$1" "diff:$2:16") || return 2
  awk -v n="$n" -v wh="$wh" 'BEGIN { split(wh, a, " "); p = 100 * n / (a[1] * a[2])
    printf "%d of %d pixels differ (%.3f %%)\n", n, a[1] * a[2], p; exit p > 0.5 }'; }

# ---- figures: docs/VALIDATION.md, and the same with one number planted
python3 tools/docs-validation --mmsim "$S" --check >"$T/v.out" 2>&1 && ok "docs/VALIDATION.md is --validate's output" \
  || bad "docs/VALIDATION.md is stale: $(tail -2 "$T/v.out") (make docs)"
python3 - docs/VALIDATION.md "$T/planted.md" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
i = s.index("\nno_load_speed ")  # the first table's first row: its measured figure, one digit changed
m = re.compile(r" (\d)(\d*) +rpm").search(s, i)
open(sys.argv[2], "w").write(s[:m.start()] + str((int(m.group(1)) + 1) % 10) + s[m.start() + 1:])
PY
python3 tools/docs-validation --mmsim "$S" --doc "$T/planted.md" --check >/dev/null 2>&1; rc=$?
[ $rc = 1 ] && ok "a planted stale number fails the check (exit 1)" || bad "a planted stale number: exit $rc, want 1"

# ---- pictures: redrawn, against the committed ones
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory docs-img IMG_DIR="$T/img" >"$T/make.out" 2>&1 \
  && ok "make docs-img" || { bad "make docs-img: $(tail -3 "$T/make.out")"; echo "cli_docs: $fails failed"; exit 1; }
for f in viewer report mmview; do
  r=$(pngdiff "$T/img/$f.png" docs/img/$f.png) && ok "docs/img/$f.png: $r" \
    || bad "docs/img/$f.png is stale ($r): make docs"
done
# a stale picture: the report of another run (seed 2) in report.png's place
"$S" --maze mazes/gen-16x16-s1.txt --driver firmware --seed 2 --report "$T/seed2.png" >/dev/null 2>&1
pngdiff "$T/seed2.png" docs/img/report.png >"$T/d.out"; rc=$?
[ $rc = 1 ] && ok "a planted stale picture fails the check ($(cat "$T/d.out"))" || bad "a planted stale picture: exit $rc: $(cat "$T/d.out")"
[ $fails -eq 0 ] && echo "cli_docs: all passed" || { echo "cli_docs: $fails failed"; exit 1; }
