#!/usr/bin/env bash
# cli_docs_img.sh - the pictures in docs/img are what the code draws now:
# `make docs-img` into a temporary folder (the README's own commands), each
# picture against the committed one by test/pngdiff.py (at most 0.5 % of the
# pixels differ by more than 16 of 255). After a change that moves them:
# `make docs`. SKIPs without xvfb-run (the viewer's pictures need a display).
set -u
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
[ -n "${DISPLAY:-}" ] || command -v xvfb-run >/dev/null || { echo "SKIP cli_docs_img: no display and no xvfb-run"; exit 77; }
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory docs-img IMG_DIR="$T" >"$T/make.out" 2>&1 \
  && ok "make docs-img" || { bad "make docs-img: $(tail -3 "$T/make.out")"; echo "cli_docs_img: $fails failed"; exit 1; }
for f in viewer report mmview; do
  r=$(python3 test/pngdiff.py "$T/$f.png" docs/img/$f.png 0.5) && ok "docs/img/$f.png: $r" \
    || bad "docs/img/$f.png is stale ($r): make docs"
done
# the check can fail: a picture of another run differs
python3 test/pngdiff.py "$T/viewer.png" "$T/mmview.png" 0.5 >/dev/null && bad "pngdiff: two different pictures pass" || ok "pngdiff: two different pictures differ"
[ $fails -eq 0 ] && echo "cli_docs_img: all passed" || { echo "cli_docs_img: $fails failed"; exit 1; }
