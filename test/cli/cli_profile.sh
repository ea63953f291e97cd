#!/usr/bin/env bash
# cli_profile.sh - the firmware's robot profile from the robot file: every
# robot file with a [firmware] section makes a robot_profile.h with every
# RC_* name (tools/mkprofile.c, sim/world/fwprofile.c's table), each key
# with its `; source:` line; the figures the firmware shares with the
# physics follow the robot's own keys (a changed wheel_track_mm changes
# RC_TRACK_MM); [firmware.avr]'s values only under __AVR__. Bad input is
# one line and exit 2: an unknown key (mkprofile and mmsim's robot reader
# alike, FILE:LINE), a missing key (mkprofile, FILE:LINE of [firmware]), a
# value of the wrong kind, a shared figure with neither a key nor the
# physics to take it from, a feed-forward figure (mm_s_per_cmd,
# cmd_friction, cmd_per_mm_s2, cmd_per_arc_mm_s2) that its motor and
# chassis keys (or its [measured.*] figures) do not give; an output that cannot be written: exit 3, no file.
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
MKPROFILE=${MKPROFILE:-$B/mkprofile}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
export ONE_ERROR_LINE=1
[ -x "$MKPROFILE" ] || { echo "SKIP cli_profile: $MKPROFILE not built (make $MKPROFILE)"; exit 77; }
nkeys=$(grep -c '^    { "' sim/world/fwprofile.c)

for r in $(grep -l '^\[firmware\]' robots/*.ini); do
  n=$(basename "$r" .ini)
  mkdir -p "$T/$n"
  want_rc 0 "$n: mkprofile" "$MKPROFILE" "$r" "$T/$n/robot_profile.h"; cp "$T/$n/robot_profile.h" "$T/$n.h"
  d=$(grep -c '^#define RC_' "$T/$n.h"); u=$(grep '^#define RC_' "$T/$n.h" | awk '{print $2}' | sort -u | wc -l)
  [ "$u" -eq "$nkeys" ] && ok "$n: all $nkeys RC_ names ($d #defines)" || bad "$n: $u RC_ names, want $nkeys"
  python3 - "$r" <<'PY' && ok "$n: each [firmware] key with its source line" || bad "$n: a [firmware] key without a source line"
import sys
lines = open(sys.argv[1]).read().splitlines()
sec = ""
for i, l in enumerate(lines):
    if l.startswith("["): sec = l
    elif sec.startswith("[firmware") and l and not l.startswith(";") and "=" in l:
        assert lines[i - 1].startswith("; source: "), l
PY
  echo "int main(void) { return 0; }" >"$T/c.c"
  for avr in "" "-D__AVR__"; do
    cc -std=c99 -Wall -Werror $avr -Ifirmware -I"$T/$n" -include robot_config.h -fsyntax-only "$T/c.c" 2>"$T/cc" \
      && ok "$n: compiles ${avr:-(host)}" || bad "$n $avr: $(head -3 "$T/cc")"
  done
done

# the physics' figures: track, wheels, encoder x gear, the ToF poses
grep -q '^#define RC_TRACK_MM 96.0f$' "$T/paper.h" && grep -q '^#define RC_COUNTS_PER_REV 358.32f$' "$T/paper.h" \
  && grep -q '^#define RC_TOF_FRONT_Y_MM 55.0f$' "$T/paper.h" && ok "paper: track, counts per turn, front ToF from the physics keys" \
  || bad "paper: $(grep -E 'RC_(TRACK_MM|COUNTS_PER_REV|TOF_FRONT_Y_MM) ' "$T/paper.h")"
# (the yaw's feed-forward follows the track: mkprofile checks cmd_per_arc_mm_s2 against it)
sed -e 's/^wheel_track_mm = 96$/wheel_track_mm = 98/' -e 's/^cmd_per_arc_mm_s2 = 0.0791$/cmd_per_arc_mm_s2 = 0.0777/' robots/paper.ini >"$T/track.ini"
want_rc 0 "paper, track 98 mm" "$MKPROFILE" "$T/track.ini" "$T/track.h"
grep -q '^#define RC_TRACK_MM 98.0f$' "$T/track.h" && ok "wheel_track_mm 98 -> RC_TRACK_MM 98.0f" || bad "track: $(grep RC_TRACK_MM "$T/track.h")"
grep -q '^#define RC_MM_PER_COUNT_LEFT (500.0f / 1918.0f)$' "$T/ukmarsbot.h" && ok "ukmarsbot: calibrated mm per count" \
  || bad "ukmarsbot: $(grep RC_MM_PER_COUNT_LEFT "$T/ukmarsbot.h")"
python3 - "$T/paper.h" <<'PY' && ok "paper: run_mm_s 650, 600 under __AVR__ ([firmware.avr])" || bad "paper: [firmware.avr]"
import sys
t = open(sys.argv[1]).read()
assert "#ifdef __AVR__\n#define RC_RUN_MM_S 600.0f\n#else\n#define RC_RUN_MM_S 650.0f\n#endif\n" in t
PY

# bad input: one line, exit 2
line() { grep -n "$2" "$1" | head -1 | cut -d: -f1; }

# the feed-forward's motor figures against the robot's own keys (within
# 0.5 %; the friction within half a command step too): a changed figure
# on either side, in a copy, is one line at the [firmware] key's line
# naming it. drift HOW ROBOT KEY SED: a copy of robots/ROBOT.ini with SED.
drift() { local how=$1 r=$2 key=$3 sed=$4
  sed "$sed" "robots/$r.ini" >"$T/drift.ini"
  cmp -s "robots/$r.ini" "$T/drift.ini" && { bad "$how: the edit '$sed' changed nothing"; return; }
  local L; L=$(awk -v k="$key" '/^\[/{s=$0} s=="[firmware]" && index($0, k " = ")==1 {print NR; exit}' "$T/drift.ini")
  want_rc 2 "$how" "$MKPROFILE" "$T/drift.ini" "$T/x.h"
  grep -q "^$T/drift.ini:$L: firmware.$key = .*, the robot's keys give .* apart" "$T/err" && ok "$how: $(cat "$T/err")" \
    || bad "$how (want $T/drift.ini:$L: firmware.$key): $(cat "$T/err")"; }
drift "paper: firmware 1 % faster per command" paper mm_s_per_cmd 's/^mm_s_per_cmd = 0.7804$/mm_s_per_cmd = 0.7882/'
drift "paper: motor 460 rpm" paper mm_s_per_cmd 's/^no_load_rpm = 450$/no_load_rpm = 460/'
drift "paper: friction 58 steps" paper cmd_friction 's/^cmd_friction = 56.8$/cmd_friction = 58/'
drift "paper: body 137 g" paper cmd_per_mm_s2 's/^body_mass_g = 127$/body_mass_g = 137/'
drift "paper: command full scale 6.1 V" paper mm_s_per_cmd 's/^cmd_max_v = 6$/cmd_max_v = 6.1/'
drift "kerise: driver 0 ohm" kerise-v5 cmd_friction 's/^driver_r_ohm = 0.305$/driver_r_ohm = 0/'
drift "ukmarsbot: ORION's forward Km 490" ukmarsbot mm_s_per_cmd 's/^fwd_km_mm_s_v = 475$/fwd_km_mm_s_v = 490/'
drift "ukmarsbot: ORION's forward time constant 0.2 s" ukmarsbot cmd_per_mm_s2 's/^fwd_tm_s = 0.190$/fwd_tm_s = 0.200/'
# the yaw's feed-forward: the measured spin where a [measured.*] section has it, else the chassis' yaw inertia
drift "ukmarsbot: ORION's rotation time constant 0.25 s" ukmarsbot cmd_per_arc_mm_s2 's/^rot_tm_s = 0.210$/rot_tm_s = 0.250/'
drift "paper: caster 25 mm behind the axle" paper cmd_per_arc_mm_s2 's/^caster_y_mm = -55$/caster_y_mm = -25/'
drift "basic-12: the body's yaw inertia doubled" ukmarsbot-basic-12 cmd_per_arc_mm_s2 's/^body_yaw_inertia_kgm2 = 2.213e-4$/body_yaw_inertia_kgm2 = 4.426e-4/'
sed 's/^model = datasheet$/model = paper/' robots/paper.ini >"$T/model.ini"
want_rc 2 "mkprofile: the motor model paper cannot check the figures" "$MKPROFILE" "$T/model.ini" "$T/x.h"
grep -q "are checked against a \[motor.left\] of model datasheet" "$T/err" && ok "mkprofile: $(cat "$T/err")" || bad "model: $(cat "$T/err")"
sed 's/^cmd_max_v = .*$//' robots/ukmarsbot.ini >"$T/nofull.ini"
want_rc 2 "mkprofile: no cmd_max_v" "$MKPROFILE" "$T/nofull.ini" "$T/x.h"
grep -q "firmware.cmd_max_v, cmd_max: missing" "$T/err" && ok "mkprofile: $(cat "$T/err")" || bad "nofull: $(cat "$T/err")"
cp robots/paper.ini "$T/unknown.ini"; sed -i '/^\[firmware\]$/a bogus_mm = 1' "$T/unknown.ini"
L=$(line "$T/unknown.ini" '^bogus_mm = 1$')
want_rc 2 "mkprofile: unknown key" "$MKPROFILE" "$T/unknown.ini" "$T/x.h"
grep -q "^$T/unknown.ini:$L: firmware.bogus_mm: unknown key" "$T/err" && ok "mkprofile: $(cat "$T/err")" || bad "unknown: $(cat "$T/err")"
[ ! -e "$T/x.h" ] && ok "mkprofile: no output on bad input" || bad "mkprofile wrote $T/x.h"
want_rc 2 "mmsim --robot: unknown [firmware] key" "$MMSIM" --print-robot --robot "$T/unknown.ini"
grep -q "$T/unknown.ini:$L: firmware.bogus_mm: unknown key" "$T/err" && ok "mmsim: $(cat "$T/err")" || bad "mmsim unknown: $(cat "$T/err")"
sed 's/^search_mm_s = .*$//' robots/paper.ini >"$T/missing.ini"
L=$(line "$T/missing.ini" '^\[firmware\]$')
want_rc 2 "mkprofile: missing key" "$MKPROFILE" "$T/missing.ini" "$T/x.h"
grep -q "^$T/missing.ini:$L: firmware.search_mm_s: missing key" "$T/err" && ok "mkprofile: $(cat "$T/err")" || bad "missing: $(cat "$T/err")"
sed 's/^walls_ir = 0$/walls_ir = no/' robots/paper.ini >"$T/value.ini"
want_rc 2 "mkprofile: walls_ir = no" "$MKPROFILE" "$T/value.ini" "$T/x.h"
grep -q "firmware.walls_ir: expected a whole number, got 'no'" "$T/err" && ok "mkprofile: $(cat "$T/err")" || bad "value: $(cat "$T/err")"
want_rc 2 "mmsim --robot: walls_ir = no" "$MMSIM" --print-robot --robot "$T/value.ini"
sed 's/^tof_front_y_mm = .*$//' robots/ukmarsbot.ini >"$T/notof.ini"
want_rc 2 "mkprofile: no tof_front_y_mm and no [tof.front]" "$MKPROFILE" "$T/notof.ini" "$T/x.h"
grep -q "firmware.tof_front_y_mm: missing key (and no \[tof.front\] y_mm to take it from)" "$T/err" && ok "mkprofile: $(cat "$T/err")" \
  || bad "notof: $(cat "$T/err")"
want_rc 2 "mkprofile: a robot file without [firmware]" "$MKPROFILE" robots/bulebule.ini "$T/x.h"
want_rc 2 "mkprofile: no such file" "$MKPROFILE" "$T/none.ini" "$T/x.h"
want_rc 3 "mkprofile: output folder missing" "$MKPROFILE" robots/paper.ini "$T/no/such/dir/x.h"
want_rc 2 "mkprofile: usage" "$MKPROFILE"
exit $((fails > 0))
