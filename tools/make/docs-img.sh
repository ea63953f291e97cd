#!/usr/bin/env bash
# docs-img.sh MMSIM MMVIEW DIR - the README's three pictures, made with the
# README's commands into DIR: viewer.png, report.png, mmview.png (without a
# display, under xvfb-run).
mmsim=$1 mmview=$2 dir=$3
X_RUN=(); [ -n "$DISPLAY" ] || X_RUN=(xvfb-run -a -s '-screen 0 1024x768x24 -nolisten tcp')
mkdir -p "$dir"; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"${X_RUN[@]}" "$mmsim" --maze mazes/gen-16x16-s1.txt --driver firmware --screenshot "$dir/viewer.png" --at 40 --size 800x600 >/dev/null && \
"$mmsim" --maze mazes/gen-16x16-s1.txt --driver firmware --report "$tmp/report.png" >/dev/null && mv "$tmp/report.png" "$dir/report.png" && \
"$mmsim" --maze mazes/gen-16x16-s1.txt --driver firmware --lcm-log "$tmp/run.lcmlog" >/dev/null && \
"${X_RUN[@]}" "$mmview" "$tmp/run.lcmlog" --screenshot "$dir/mmview.png" --at 30 --camera 2 --size 800x600 && \
echo "$dir: viewer.png report.png mmview.png"
