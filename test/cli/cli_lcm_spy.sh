#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_lcm_spy.sh - smoke test: lcm-spy (launched by `make spy`) starts
# under Xvfb with the project's types jar, finds every mmlcm type, and plays
# a telemetry log for a few seconds without an exception. Time-bounded;
# skipped (exit 77) without Xvfb, java or the jars.
set -u
S=${MMSIM:-build/mmsim}
JAR=${LCM_JAR:-build/lcmjava/mmlcm-types.jar}
T=$(mktemp -d)
xpid=""
cleanup() { [ -n "$xpid" ] && kill "$xpid" 2>/dev/null; rm -rf "$T"; }
trap cleanup EXIT
skip() { echo "SKIP cli_lcm_spy.sh: $1"; exit 77; }
command -v Xvfb >/dev/null || skip "no Xvfb (package xvfb)"
command -v java >/dev/null || skip "no java (default-jdk-headless)"
for j in /usr/share/java/lcm.jar /usr/share/java/jchart2d.jar "$JAR"; do [ -f "$j" ] || skip "no $j"; done

"$S" --maze mazes/gen-5x5-s1.txt --driver firmware --json --lcm-log "$T/run.lcmlog" >/dev/null || { echo "FAILED: mmsim"; exit 1; }
# a free display number: the first without a lock file
d=90; while [ -e /tmp/.X$d-lock ] && [ $d -lt 140 ]; do d=$((d+1)); done
Xvfb :$d -screen 0 1024x768x24 -nolisten tcp >"$T/xvfb.out" 2>&1 & xpid=$!
for i in $(seq 50); do [ -e /tmp/.X11-unix/X$d ] && break; sleep 0.1; done
[ -e /tmp/.X11-unix/X$d ] || skip "Xvfb did not start: $(head -1 "$T/xvfb.out")"
# the log (about 18 s of contest, every channel within the first 5 s) in
# real time; spy stopped after 10 s. At the end of a log LCM's Java log
# provider prints an EOFException, and make reports the timeout's SIGTERM
# (Error 143): those are not failures.
# `make spy` itself, so a broken target fails here (timeout stops make and
# the java it started: they share a process group).
DISPLAY=:$d timeout 10 make -s --no-print-directory spy LOG="$T/run.lcmlog" SPEED=1 LCM_JAR="$JAR" >"$T/spy.out" 2>&1
rc=$?
cat "$T/spy.out"
ntypes=$(ls lcm/*.lcm | wc -l)
fails=0
[ $rc -eq 124 ] && echo "ok: spy ran until stopped" || { echo "FAILED: spy exited $rc before the time limit"; fails=1; }
grep -q "^Found $ntypes LCM types" "$T/spy.out" && echo "ok: spy found the $ntypes mmlcm types" || { echo "FAILED: types not found"; fails=1; }
grep -v 'java.io.EOFException: EOF' "$T/spy.out" | grep -Ev '^make(\[[0-9]+\])?: \*\*\* .*spy\] Error 143$' | grep -qi 'exception\|error' && { echo "FAILED: spy printed an error"; fails=1; } || echo "ok: no exception"
exit $fails
