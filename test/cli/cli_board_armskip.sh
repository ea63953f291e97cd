#!/usr/bin/env bash
# cli_board_armskip.sh - --no-skip on an ARM image on an STM32 board
# (armcore_cfg_t.no_idle_skip: WFI slept and wait loops run cycle by cycle,
# not jumped over): our firmware test/firmware/arm/boardtest.c (it sleeps
# in WFI between its SysTick ticks) driven by its button on bulebule for
# 2 simulated s, and Bulebots' bulebule itself (`make client-bulebule`,
# when ../shared has it) for 2 s, print the same JSON with and without
# --no-skip but board.skipped (and the wall-time fields), which shows
# cycles jumped over only without it. --no-skip on an AVR run, or with no
# image: one line, exit 2.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
FW=$B/arm/boardtest.elf
BULEBULE=$B/clients/bulebule/src/main.elf
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
[ -s "$FW" ] || mk "$FW" >"$T/make.out" 2>&1 || { echo "SKIP cli_board_armskip: make $FW: $(tail -1 "$T/make.out")"; exit 77; }
open_mazes "$T"
MAZE=$T/open.txt
arm() { "$MMSIM" --board bulebule --maze "$MAZE" --time-limit 2 --json "$@"; }
# same A B: the JSON lines equal but board.skipped; skipped's figures of each printed
cmp_skip() { python3 - "$1" "$2" <<'PY'
import json, sys
d = [json.loads(open(f).read().splitlines()[-1]) for f in sys.argv[1:3]]
sk = []
for x in d:
    x.pop("wall_time_s"); x.pop("real_time_factor"); sk.append(x["board"].pop("skipped"))
print(json.dumps(d[0], sort_keys=True) == json.dumps(d[1], sort_keys=True), sk[0]["sleep_cycles"] > 0,
      sk[1] == {"sleep_cycles": 0, "wait_loops": 0, "wait_loop_cycles": 0}, sk[0]["sleep_cycles"] + sk[0]["wait_loop_cycles"] > 0)
PY
}

IN="0.25 occlude=fl; 0.45 button=down; 0.95 button=up"
want_rc 1 "boardtest for 2 s" arm --firmware "$FW" --input "$IN"
cp "$T/out" "$T/skip.json"
want_rc 1 "boardtest for 2 s with --no-skip" arm --firmware "$FW" --input "$IN" --no-skip
cp "$T/out" "$T/noskip.json"
[ "$(cmp_skip "$T/skip.json" "$T/noskip.json")" = "True True True True" ] \
  && ok "boardtest: the same JSON but board.skipped, which has sleep cycles jumped over only without --no-skip" \
  || bad "boardtest: $(cmp_skip "$T/skip.json" "$T/noskip.json"): $(grep -o '"skipped":{[^}]*}' "$T/skip.json" "$T/noskip.json")"
[ "$(python3 -c 'import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); print(d["board"]["encoder_edges"]["left"] > 1000)' "$T/noskip.json")" = True ] \
  && ok "boardtest --no-skip: the robot drove (the button held)" || bad "boardtest --no-skip: no motion"

[ -d "$SHARED/clients/bulebule/src" ] && { [ -s "$BULEBULE" ] || mk client-bulebule >"$T/bb.out" 2>&1 || bad "make client-bulebule: $(tail -1 "$T/bb.out")"; }
if [ -s "$BULEBULE" ]; then
  want_rc 1 "bulebule for 2 s" arm --firmware "$BULEBULE" --input "0.4 send=x; 0.6 send=battery"
  cp "$T/out" "$T/bb.json"
  want_rc 1 "bulebule for 2 s with --no-skip" arm --firmware "$BULEBULE" --input "0.4 send=x; 0.6 send=battery" --no-skip
  python3 - "$T/bb.json" "$T/out" <<'PY' && ok "bulebule: the same JSON with and without --no-skip (but board.skipped: 0 with it)" || bad "bulebule: the JSON differs: $(grep -o '"skipped":{[^}]*}' "$T/bb.json" "$T/out")"
import json, sys
d = [json.loads(open(f).read().splitlines()[-1]) for f in sys.argv[1:3]]
for x in d: x.pop("wall_time_s"); x.pop("real_time_factor")
sk = d[1]["board"].pop("skipped"); d[0]["board"].pop("skipped")
sys.exit(0 if d[0] == d[1] and sk == {"sleep_cycles": 0, "wait_loops": 0, "wait_loop_cycles": 0} and "battery" in d[0]["console"] else 1)
PY
else
  echo "SKIP bulebule part: $SHARED/clients/bulebule not found"
fi

ONE_ERROR_LINE=1
want_rc 2 "--no-skip on an AVR board: exit 2" "$MMSIM" --board ukmarsbot --maze "$MAZE" --avr "$FW" --no-skip
grep -q "^mmsim: --no-skip needs --board NAME --firmware IMAGE.elf" "$T/err" && ok "--no-skip on an AVR run: says so" || bad "--no-skip AVR: $(cat "$T/err")"
want_rc 2 "--no-skip with no image: exit 2" "$MMSIM" --maze "$MAZE" --no-skip
ONE_ERROR_LINE=0
[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }
echo "all passed"
