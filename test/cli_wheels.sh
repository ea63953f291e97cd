#!/usr/bin/env bash
# cli_wheels.sh - [sim] wheels = spin (each wheel's spin a body of its own,
# sim/world/README.md): the shipped robots' predicted --validate checks pass
# and fail as with wheels on hinges (paper: none fails; UKMARSBOT: its two
# datasheet no-load figures), and the firmware's contest on gen-16x16-s1
# reaches the goal with no contact, the same JSON twice.
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/lib.sh
S=${MMSIM:-build/mmsim}
printf '[sim]\nwheels = spin\n' >"$T/spin.ini"

# failing NAMES: the predicted checks that fail in $T/out's JSON, exactly these
failing() { python3 - "$T/out" "$1" <<'PY'
import json, sys
d = json.loads(open(sys.argv[1]).read().splitlines()[-1])
bad = sorted(c["name"] for c in d["checks"] if c["pass"] is False)
assert bad == sorted(sys.argv[2].split()), bad
assert any(c["name"] == "rest_creep_mm_per_min" and c["pass"] for c in d["checks"])
PY
}
want_rc 0 "paper, spin bodies: every prediction passes" "$S" --validate --json --config "$T/spin.ini"
failing "" && ok "paper, spin bodies: no check fails, creep included" || bad "paper spin: $(head -c 400 "$T/out")"
want_rc 1 "ukmarsbot, spin bodies" "$S" --validate --json --config "$T/spin.ini" --robot robots/ukmarsbot.ini
failing "sheet_no_load_speed sheet_no_load_current" && ok "ukmarsbot, spin bodies: only the two sheet no-load figures fail" \
  || bad "ukmarsbot spin: $(head -c 400 "$T/out")"

want_rc 0 "firmware contest, spin bodies" "$S" --maze mazes/gen-16x16-s1.txt --driver firmware --json --config "$T/spin.ini"
strip "$T/out" >"$T/a"
python3 -c "
import json; d = json.loads(open('$T/a').read())
assert d['reached_goal'] and d['collisions'] == 0 and d['best_run_s'] is not None, d
" && ok "firmware contest, spin bodies: the goal, speed runs, no contact" || bad "spin contest: $(cat "$T/a")"
want_rc 0 "firmware contest, spin bodies, again" "$S" --maze mazes/gen-16x16-s1.txt --driver firmware --json --config "$T/spin.ini"
strip "$T/out" | cmp -s - "$T/a" && ok "spin bodies: the same JSON twice" || bad "spin bodies: not deterministic"
exit $((fails > 0))
