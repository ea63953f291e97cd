#!/usr/bin/env bash
# cli_wheels.sh - [sim] wheels = hinge (each wheel a body on a hinge, the
# form other than the default, spin bodies; sim/world/README.md): the shipped
# robots' predicted --validate checks pass and fail as with the default
# (paper: none fails; UKMARSBOT: its two datasheet no-load figures), and the
# firmware's contest on gen-16x16-s1 reaches the goal with no contact, the
# same JSON twice.
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/cli/lib.sh
S=${MMSIM:-build/mmsim}
printf '[sim]\nwheels = hinge\n' >"$T/hinge.ini"

# failing NAMES: the predicted checks that fail in $T/out's JSON, exactly these
failing() { python3 - "$T/out" "$1" <<'PY'
import json, sys
d = json.loads(open(sys.argv[1]).read().splitlines()[-1])
bad = sorted(c["name"] for c in d["checks"] if c["pass"] is False)
assert bad == sorted(sys.argv[2].split()), bad
assert any(c["name"] == "rest_creep_mm_per_min" and c["pass"] for c in d["checks"])
PY
}
want_rc 0 "paper, hinges: every prediction passes" "$S" --validate --json --config "$T/hinge.ini"
failing "" && ok "paper, hinges: no check fails, creep included" || bad "paper hinge: $(head -c 400 "$T/out")"
want_rc 1 "ukmarsbot, hinges" "$S" --validate --json --config "$T/hinge.ini" --robot robots/ukmarsbot.ini
failing "sheet_no_load_speed sheet_no_load_current" && ok "ukmarsbot, hinges: only the two sheet no-load figures fail" \
  || bad "ukmarsbot hinge: $(head -c 400 "$T/out")"

want_rc 0 "firmware contest, hinges" "$S" --maze mazes/gen-16x16-s1.txt --driver firmware --json --config "$T/hinge.ini"
strip "$T/out" >"$T/a"
python3 -c "
import json; d = json.loads(open('$T/a').read())
assert d['reached_goal'] and d['collisions'] == 0 and d['best_run_s'] is not None, d
" && ok "firmware contest, hinges: the goal, speed runs, no contact" || bad "hinge contest: $(cat "$T/a")"
want_rc 0 "firmware contest, hinges, again" "$S" --maze mazes/gen-16x16-s1.txt --driver firmware --json --config "$T/hinge.ini"
strip "$T/out" | cmp -s - "$T/a" && ok "hinges: the same JSON twice" || bad "hinges: not deterministic"
exit $((fails > 0))
