#!/usr/bin/env bash
# cli_step.sh - [sim] step_s per driver: the scripted driver runs at the
# config's step (2 ms: to the goal with no contact, and deterministic); the
# firmware and mms drivers tick our firmware in process at its 1 ms tick, so
# a 2 ms step is cut to 1 ms for them: the same JSON as the default step.
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/cli/lib.sh
S=${MMSIM:-build/mmsim}
M=mazes/gen-16x16-s1.txt
printf '[sim]\nstep_s = 0.002\n' >"$T/s2.ini"

want_rc 0 "scripted at the default step" "$S" --maze $M --driver scripted --json
strip "$T/out" >"$T/s1.a"
want_rc 0 "scripted at 2 ms" "$S" --maze $M --driver scripted --config "$T/s2.ini" --json
strip "$T/out" >"$T/s2.a"
python3 -c "
import json; d=json.loads(open('$T/s2.a').read()); d1=json.loads(open('$T/s1.a').read())
assert d['reached_goal'] and d['collisions'] == 0, d
assert abs(d['first_run_s'] - d1['first_run_s']) < 0.05, (d['first_run_s'], d1['first_run_s'])
" && ok "scripted at 2 ms: the goal, no contact, the first run within 50 ms of 1 ms's (11.63 s on hinges, 11.56 on spin bodies)" || bad "scripted 2 ms: $(cat "$T/s2.a")"
want_rc 0 "scripted at 2 ms again" "$S" --maze $M --driver scripted --config "$T/s2.ini" --json
strip "$T/out" | cmp -s - "$T/s2.a" && ok "scripted at 2 ms: the same JSON twice" || bad "scripted 2 ms not deterministic"

want_rc 0 "firmware at the default step" "$S" --maze $M --driver firmware --json
strip "$T/out" >"$T/fw1"
want_rc 0 "firmware with a 2 ms step" "$S" --maze $M --driver firmware --json --config "$T/s2.ini"
strip "$T/out" | cmp -s - "$T/fw1" && ok "firmware: a 2 ms step runs at its 1 ms tick (the same JSON)" || bad "firmware 2 ms differs: $(strip "$T/out" | head -c 300)"
exit $((fails > 0))
