#!/usr/bin/env bash
# seeds.sh DIR MMSIM - the fuzzers' first corpora in DIR/corpus_NAME: our
# mazes, a short logged contest, --print-config and a small config, our
# robot files and --print-robot, our contest files.
set -e
d=$1 mmsim=$2
mkdir -p "$d/corpus_mazefile" "$d/corpus_wire" "$d/corpus_lcmlog" "$d/corpus_config" "$d/corpus_robot" "$d/corpus_contest"
cp -n contests/*.ini "$d/corpus_contest/" 2>/dev/null || true
cp -n mazes/*.txt "$d/corpus_mazefile/" 2>/dev/null || true
"$mmsim" --maze mazes/gen-5x5-s1.txt --driver firmware --time-limit 1 --lcm-rate 10 \
  --lcm-log "$d/corpus_lcmlog/seed.lcmlog" >/dev/null || [ $? = 1 ]
"$mmsim" --print-config >"$d/corpus_config/print-config.ini"
printf '[world]\ncell_m = 0.18 ; m\n[sim]\nstep_s = 0.0005\nsolver = quickstep\n' >"$d/corpus_config/small.ini"
cp -n robots/*.ini "$d/corpus_robot/" 2>/dev/null || true
"$mmsim" --print-robot >"$d/corpus_robot/print-robot.ini"
