#!/usr/bin/env bash
# cli_validate.sh - mmsim --validate: every check passes on the default robot
# (datasheet motor, exact solver), the JSON has the documented fields, and a
# robot that breaks the models fails the checks it should.
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/lib.sh
S=${MMSIM:-build/mmsim}

want_rc 0 "validate passes on the default robot" "$S" --validate --json
cp "$T/out" "$T/default.json"
python3 - "$T/default.json" <<'PY' && ok "every named check present and passing" || bad "validate JSON: $(cat "$T/default.json")"
import json, sys
d = json.loads(open(sys.argv[1]).read().splitlines()[-1])
names = {c["name"]: c for c in d["checks"]}
need = ["no_load_speed", "no_load_current", "stall_torque", "stall_current", "step_response_1ms", "step_response_5ms",
        "encoder_counts_per_rev", "rest_creep_mm_per_min", "straight_veer_mm_4m", "tof_noise_cv",
        "tof_timeout_beyond_range", "wall_no_tunnelling", "max_efficiency_speed", "max_efficiency_current",
        "max_efficiency", "max_power", "mid_torque_current"]
missing = [n for n in need if n not in names]
failing = [n for n, c in names.items() if not c["pass"]]
fields = {"name", "expected", "measured", "unit", "tolerance_pct", "source", "pass"}
assert not missing, missing
assert not failing, failing
assert all(fields <= set(c) for c in d["checks"]), "fields"
PY

# the text table ends with the count
want_rc 0 "validate table" "$S" --validate
grep -q "^[0-9]* of [0-9]* checks pass$" "$T/out" && ok "table's last line" || bad "table: $(tail -2 "$T/out")"

# the paper's loss-free motor runs 61 % fast: the datasheet checks fail, exit 1
sed 's/^model = datasheet/model = paper/' robots/paper.ini >"$T/paper.ini"
[ "$(grep -c '^model = paper' "$T/paper.ini")" = 2 ] || bad "paper motor robot: not two model lines"
want_rc 1 "the paper's motor fails validation" "$S" --validate --json --robot "$T/paper.ini"
python3 -c "
import json,sys; d=json.loads(open('$T/out').read().splitlines()[-1]); c={k['name']:k for k in d['checks']}
assert not c['no_load_speed']['pass'] and abs(c['no_load_speed']['measured']-725)<10, c['no_load_speed']
" && ok "paper motor: no-load speed 725 rpm flagged" || bad "paper motor: $(head -c 600 "$T/out")"

# a constant friction (friction_load_a removed): the curve's predictions fail, exit 1
grep -v '^friction_load_a' robots/paper.ini >"$T/constfric.ini"
want_rc 1 "a constant friction fails the curve's predictions" "$S" --validate --json --robot "$T/constfric.ini"
python3 -c "
import json; d=json.loads(open('$T/out').read().splitlines()[-1]); c={k['name']:k for k in d['checks']}
bad = [n for n in ('max_efficiency_speed', 'max_efficiency_current', 'max_efficiency', 'mid_torque_current') if not c[n]['pass']]
assert bad == ['max_efficiency_speed', 'max_efficiency_current', 'max_efficiency', 'mid_torque_current'], bad
assert c['no_load_speed']['pass'] and c['stall_torque']['pass']
" && ok "constant friction: the four predictions flagged" || bad "constant friction: $(head -c 600 "$T/out")"

# quickstep slides a resting robot: the creep check catches it
printf '[sim]\nsolver = quickstep\n' >"$T/qs.ini"
want_rc 1 "quickstep fails the creep check" "$S" --validate --json --config "$T/qs.ini"
python3 -c "
import json; d=json.loads(open('$T/out').read().splitlines()[-1]); c={k['name']:k for k in d['checks']}
assert not c['rest_creep_mm_per_min']['pass'], c['rest_creep_mm_per_min']
" && ok "quickstep: creep flagged" || bad "quickstep: $(head -c 600 "$T/out")"

# a bad word in the config: one error line, exit 2
# a bad word in the robot file: one error line with its place, exit 2
sed 's/^model = datasheet/model = magic/' robots/paper.ini >"$T/bad.ini"
n=$(grep -n '^model = magic' "$T/bad.ini" | head -1 | cut -d: -f1)
ONE_ERROR_LINE=1 want_rc 2 "bad motor model" "$S" --validate --robot "$T/bad.ini"
[ "$(cat "$T/err")" = "$T/bad.ini:$n: motor.left.model: 'magic' is not one of paper datasheet" ] && ok "word key error" || bad "word key error: $(cat "$T/err")"
# the old config key: where it belongs now
printf '[motor]\nmotor_model = paper\n' >"$T/old.ini"
ONE_ERROR_LINE=1 want_rc 2 "motor_model in a config" "$S" --validate --config "$T/old.ini"
grep -q "old.ini:2: motor.motor_model: a robot's number: it belongs in the robot file" "$T/err" && ok "old motor_model key: to the robot file" || bad "old motor_model: $(cat "$T/err")"
exit $((fails > 0))
