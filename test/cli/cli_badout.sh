#!/usr/bin/env bash
# cli_badout.sh - outputs that fail: a write to stdout that fails (/dev/full:
# ENOSPC; a closed descriptor) is one error line with its reason and exit 3
# in every tool, never exit 0 after a half-written output.
set -u
S=${MMSIM:-build/mmsim}
M=${MMMAZE:-build/mmmaze}
L=${MMLOG:-build/mmlog}
V=${MMVIEW:-build/mmview}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
[ -w /dev/full ] || { echo "SKIP cli_badout: no /dev/full"; exit 77; }

# want_full DESC PROG CMD...: CMD with stdout on /dev/full: exit 3, the one line "PROG: stdout: No space left on device"
# (a batch's progress line before it is no error line)
want_full() { local desc=$1 prog=$2; shift 2
  "$@" >/dev/full 2>"$T/err"; local rc=$?
  [ $rc -eq 3 ] && [ "$(tr '\r' '\n' <"$T/err" | grep -v '^\[\|^$')" = "$prog: stdout: No space left on device" ] \
    && ok "stdout full: $desc" || bad "stdout full: $desc: exit $rc, stderr: $(head -3 "$T/err")"; }
want_full "mmmaze gen --size 32" mmmaze "$M" gen --size 32
want_full "mmmaze gen --size 4 (small, fails at the final flush)" mmmaze "$M" gen --size 4
want_full "mmmaze show" mmmaze "$M" show mazes/gen-16x16-s1.txt --path
want_full "mmmaze solve --json" mmmaze "$M" solve mazes/gen-16x16-s1.txt --json
want_full "mmmaze check" mmmaze "$M" check mazes/gen-5x5-s1.txt
want_full "mmmaze --help" mmmaze "$M" --help
want_full "mmsim --print-config" mmsim "$S" --print-config
want_full "mmsim --json" mmsim "$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --json
want_full "mmsim lap table" mmsim "$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1
mkdir "$T/b"; for i in 1 2 3; do cp mazes/gen-5x5-s1.txt "$T/b/m$i.txt"; done
want_full "mmsim --batch" mmsim "$S" --batch "$T/b" --jobs 2 --runs 1 --driver scripted
"$S" --maze mazes/gen-5x5-s1.txt --driver scripted --runs 1 --lcm-log "$T/run.lcmlog" >/dev/null 2>&1
want_full "mmlog summary" mmlog "$L" "$T/run.lcmlog"
want_full "mmlog --json" mmlog "$L" --json "$T/run.lcmlog"
want_full "mmlog --dump" mmlog "$L" --dump MM_POSE "$T/run.lcmlog"
want_full "mmview --help" mmview "$V" --help
# a closed stdout: the same, with its reason
"$M" gen --size 8 >&- 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && [ "$(cat "$T/err")" = "mmmaze: stdout: Bad file descriptor" ] && ok "closed stdout" || bad "closed stdout: exit $rc $(cat "$T/err")"
# and a good stdout stays exit 0 with the whole output
want_rc 0 "mmmaze gen to a file" "$M" gen --size 32 --seed 3
[ "$(wc -l <"$T/out")" -eq 65 ] && [ ! -s "$T/err" ] && ok "whole maze written" || bad "maze output: $(wc -l <"$T/out") lines"

[ $fails -eq 0 ]
