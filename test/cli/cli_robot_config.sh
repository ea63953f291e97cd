#!/usr/bin/env bash
# cli_robot_config.sh - the example firmware's robot constants
# (firmware/robot_config.h) agree with robots/paper.ini as mmsim loads it,
# within the tolerances test/tools/robot_config_check.py states (lengths 0.1 mm,
# derived motor figures 0.5 %, and why); and a change of one number on
# either side, in a copy, makes the check fail and name the constant.
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/cli/lib.sh
command -v python3 >/dev/null || { echo "SKIP cli_robot_config: python3 missing"; exit 77; }

python3 test/tools/robot_config_check.py "$S" >"$T/out" 2>&1 && ok "robot_config.h agrees with robots/paper.ini" ||
  bad "robot_config.h and robots/paper.ini disagree: $(grep -v '^ok' "$T/out")"

# drift HOW WANT SED FILE: a copy of FILE (robot_config.h or paper.ini) with
# SED applied must fail, naming WANT.
drift() { local how=$1 want=$2 sed=$3 file=$4 h=firmware/robot_config.h r=robots/paper.ini
  cp "$file" "$T/copy"; sed -i "$sed" "$T/copy"
  cmp -s "$file" "$T/copy" && { bad "$how: the edit '$sed' changed nothing"; return; }
  if [ "$file" = "$h" ]; then h=$T/copy; else r=$T/copy; fi
  python3 test/tools/robot_config_check.py "$S" "$h" "$r" >"$T/out" 2>&1; local rc=$?
  if [ $rc -eq 1 ] && grep -q "^FAILED: $want " "$T/out"; then ok "$how: fails on $want"
  else bad "$how (exit $rc, want 1 and FAILED: $want): $(cat "$T/out")"; fi; }

drift "firmware wheel 32.5 mm" RC_WHEEL_DIAMETER_MM 's/^#define RC_WHEEL_DIAMETER_MM 32.0f/#define RC_WHEEL_DIAMETER_MM 32.5f/' firmware/robot_config.h
drift "firmware front ToF 56 mm" RC_TOF_FRONT_Y_MM 's/^#define RC_TOF_FRONT_Y_MM 55.0f/#define RC_TOF_FRONT_Y_MM 56.0f/' firmware/robot_config.h
drift "firmware 1 % faster per command" RC_MM_S_PER_CMD 's/^#define RC_MM_S_PER_CMD 0.7804f/#define RC_MM_S_PER_CMD 0.7882f/' firmware/robot_config.h
drift "robot file right wheel 33 mm" RC_WHEEL_DIAMETER_MM 's/^wheel_right_d_mm = 32/wheel_right_d_mm = 33/' robots/paper.ini
drift "robot file track 98 mm" RC_TRACK_MM 's/^wheel_track_mm = 96/wheel_track_mm = 98/' robots/paper.ini
drift "robot file gear 30:1" RC_COUNTS_PER_REV 's/^gear_ratio = 29.86/gear_ratio = 30/' robots/paper.ini
drift "robot file motor 460 rpm" RC_MM_S_PER_CMD 's/^no_load_rpm = 450/no_load_rpm = 460/' robots/paper.ini
drift "robot file body 137 g" RC_CMD_PER_MM_S2 's/^body_mass_g = 127/body_mass_g = 137/' robots/paper.ini
exit $((fails > 0))
