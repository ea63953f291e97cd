#!/usr/bin/env bash
# cli_tof.sh - a ToF sensor's ranging profile in a robot file (docs/ROBOTS.md):
# an unknown profile is one line FILE:LINE... and exit 2; --print-robot
# shows the figures a profile sets, and a key the file gives wins;
# --validate grades the noise's budget scaling unless the file gives cv.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

ONE_ERROR_LINE=1
awk '/^\[tof.front\]/ { f = 1 } f && /^profile = / { $0 = "profile = fastest"; f = 0 } { print }' robots/paper.ini >"$T/bad.ini"
n=$(grep -n '^profile = fastest' "$T/bad.ini" | cut -d: -f1)
want_rc 2 "unknown ToF profile" "$S" --print-robot --robot "$T/bad.ini"
[ "$(cat "$T/err")" = "$T/bad.ini:$n: tof.front.profile: 'fastest' is not one of default high_accuracy long_range high_speed" ] \
  && ok "unknown ToF profile: FILE:LINE: KIND.NAME.key: the words" || bad "unknown ToF profile: $(cat "$T/err")"
ONE_ERROR_LINE=0

# the front sensor on high speed, its range given: the profile's period, cv from it (0.04 x sqrt(33 / 20)), the file's range
awk '/^\[tof.front\]/ { f = 1 } f && /^profile = / { $0 = "range_mm = 900\nprofile = high_speed"; f = 0 } { print }' robots/paper.ini >"$T/fast.ini"
want_rc 0 "high speed profile" "$S" --print-robot --robot "$T/fast.ini"
awk '/^\[tof.front\]/ { f = 1 } /^\[tof.right\]/ { f = 0 } f && /^(profile|range_mm|cv|period_ms) =/ { print $1 "=" $3 }' "$T/out" >"$T/front"
[ "$(tr '\n' ' ' <"$T/front")" = "profile=high_speed range_mm=900 cv=0.05138093031466052 period_ms=20 " ] \
  && ok "profile sets period and cv, the file's range_mm wins" || bad "front: $(tr '\n' ' ' <"$T/front")"
# the paper robot: the default profile, 30 ms, 1200 mm, cv 0.04 x sqrt(33 / 30)
want_rc 0 "paper robot" "$S" --print-robot
[ "$(grep -c '^profile = default ' "$T/out")" = 3 ] && [ "$(grep -c '^cv = 0.04195235392680607 ' "$T/out")" = 3 ] \
  && ok "paper robot: three ToF sensors on the default profile, cv 0.042" || bad "paper robot ToF: $(grep -E '^(profile|cv) =' "$T/out")"

# --validate grades the model's noise at other budgets against the datasheet; a robot file's own cv is not graded on them
want_rc 0 "validate, paper robot" "$S" --validate --json
python3 -c "
import json, sys
c = {k['name']: k for k in json.loads(open(sys.argv[1]).read().splitlines()[-1])['checks']}
for n in ('tof_sigma_66ms', 'tof_sigma_high_speed', 'tof_sigma_high_accuracy'):
    assert c[n]['kind'] == 'predicted' and c[n]['pass'] is True and 'DocID029104' in c[n]['source'], c[n]
assert c['tof_noise_cv']['kind'] == 'fitted' and c['tof_timeout_beyond_range']['kind'] == 'fitted'
" "$T/out" && ok "validate: the ToF's budget scaling predicted and passing, its cv and range fitted" || bad "validate ToF: $(head -c 300 "$T/out")"
awk '/^profile = default/ { print; print "cv = 0.05"; next } { print }' robots/paper.ini >"$T/unity.ini"
want_rc 0 "validate, the paper's cv 0.05" "$S" --validate --json --robot "$T/unity.ini"
python3 -c "
import json, sys
c = {k['name']: k for k in json.loads(open(sys.argv[1]).read().splitlines()[-1])['checks']}
assert not any(n.startswith('tof_sigma_') for n in c) and c['tof_noise_cv']['expected'] == 0.05, sorted(c)
" "$T/out" && ok "validate: a robot file's own cv: no budget predictions, its cv reproduced" || bad "validate unity: $(head -c 300 "$T/out")"
[ $fails -eq 0 ]
