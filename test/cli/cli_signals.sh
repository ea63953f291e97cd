#!/usr/bin/env bash
# cli_signals.sh - every tool at a closed pipe and under signals
# (docs/REFERENCE.md, "Signals and pipes"): a reader that has gone (`| head`)
# is one line "TOOL: stdout: Broken pipe" and exit 3, never a death by
# SIGPIPE (exit 141) or a traceback; an --lcm-log or --report run stopped by
# SIGINT, SIGTERM or SIGHUP leaves no temporary behind and dies of the
# signal; over `ulimit -f` (SIGXFSZ) it is one line, exit 3, nothing left.
set -u
S=${MMSIM:-build/mmsim}
L=${MMLOG:-build/mmlog}
M=${MMMAZE:-build/mmmaze}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"

# closed CMD...: CMD with its stdout a pipe whose reader is already closed
# (the deterministic `| head`: the first write fails); "RC|STDERR" printed
closed() { python3 - "$@" <<'PY'
import os, subprocess, sys
r, w = os.pipe(); os.close(r)
p = subprocess.run(sys.argv[1:], stdout=w, stderr=subprocess.PIPE, text=True)
print("%d|%s" % (p.returncode, p.stderr.strip()))
PY
}
# pipe_ok DESC TOOL CMD...: exit 3 and one line "TOOL: stdout: Broken pipe"
pipe_ok() { local desc=$1 tool=$2 got; shift 2
  got=$(closed "$@")
  [ "$got" = "3|$tool: stdout: Broken pipe" ] && ok "closed pipe: $desc: one line, exit 3" || bad "closed pipe: $desc: $got"; }

"$S" --maze mazes/gen-5x5-s1.txt --lcm-log "$T/a.lcmlog" >/dev/null 2>&1 || bad "an LCM log to dump"
pipe_ok "mmsim --bench-log" mmsim "$S" --bench-log fwd:3
pipe_ok "mmsim --print-robot" mmsim "$S" --print-robot
pipe_ok "mmsim --maze --json" mmsim "$S" --maze mazes/gen-5x5-s1.txt --json
pipe_ok "mmlog --dump" mmlog "$L" --dump MM_POSE "$T/a.lcmlog"
pipe_ok "mmlog" mmlog "$L" "$T/a.lcmlog"
pipe_ok "mmmaze explore" mmmaze "$M" explore mazes/gen-16x16-s1.txt
pipe_ok "mmmaze show" mmmaze "$M" show mazes/gen-16x16-s1.txt
printf 'test,measured,unit,left_counts,right_counts\nstraight,500,mm,5300,5310\n' >"$T/counts.csv"
pipe_ok "mmfit" mmfit python3 tools/mmfit --mmsim "$S" --base robots/ukmarsbot.ini --counts "$T/counts.csv" -o "$T/fit.ini"
# the Python tools' --help (argparse drops a failed help text itself): no traceback
for t in mmfit arduino-build mmplot docs-validation mmsweep; do
  got=$(closed python3 tools/$t --help)
  case $got in 0\|*|"3|$t: stdout: Broken pipe") ok "closed pipe: $t --help: no traceback" ;; *) bad "closed pipe: $t --help: $got" ;; esac
done

# a run killed while it writes its LCM log (a background job with job control,
# so SIGINT is not ignored as a script's background jobs have it): no
# NAME.lcmlog.tmp.XXXXXX left, the exit status the signal's (128 + N)
set -m
# the run started with the three signals at their default: a test runner
# started under nohup or in the background hands its children SIGHUP or
# SIGINT ignored, and a tool keeps a signal ignored that it was started with
dfl='import os, signal, sys
for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP): signal.signal(s, signal.SIG_DFL)
os.execvp(sys.argv[1], sys.argv[1:])'
killed() { local sig=$1 want=$2 desc=$3; shift 3
  rm -rf "$T/k"; mkdir "$T/k"
  python3 -c "$dfl" "$@" >/dev/null 2>"$T/k.err" & local p=$!
  for _ in $(seq 100); do ls "$T/k" | grep -q '\.tmp\.' && break; sleep 0.05; done
  ls "$T/k" | grep -q '\.tmp\.' || { bad "$desc: no temporary to see"; kill -KILL $p; wait $p 2>/dev/null; return; }
  kill -"$sig" $p; wait $p 2>/dev/null; local rc=$?
  [ $rc -eq "$want" ] && [ -z "$(ls "$T/k")" ] && ok "$desc: SIG$sig, exit $rc, nothing left" \
    || bad "$desc: SIG$sig: exit $rc (want $want), left: $(ls "$T/k" | tr '\n' ' ')"; }
for s in INT:130 TERM:143 HUP:129; do
  killed "${s%:*}" "${s#*:}" "--lcm-log" "$S" --maze mazes/gen-32x32-s1.txt --lcm-log "$T/k/run.lcmlog"
done
killed TERM 143 "--lcm-log, an mms algorithm" "$S" --maze mazes/gen-16x16-s1.txt --mms "python3 test/mms/floodfill.py 50" --lcm-log "$T/k/run.lcmlog"
set +m

# over the file size limit: SIGXFSZ is ignored, the write fails (EFBIG): one
# line, exit 3, no temporary and no partial file
ONE_ERROR_LINE=1
rm -rf "$T/k"; mkdir "$T/k"
want_rc 3 "ulimit -f: --lcm-log" bash -c 'ulimit -f 64; exec "$@"' sh "$S" --maze mazes/gen-16x16-s1.txt --lcm-log "$T/k/u.lcmlog"
grep -q "u.lcmlog: .*File too large" "$T/err" && [ -z "$(ls "$T/k")" ] && ok "ulimit -f: --lcm-log: the reason, nothing left" \
  || bad "ulimit -f: --lcm-log: $(cat "$T/err") left: $(ls "$T/k")"
rm -rf "$T/k"; mkdir "$T/k"
want_rc 3 "ulimit -f: --report" bash -c 'ulimit -f 16; exec "$@"' sh "$S" --maze mazes/gen-5x5-s1.txt --report "$T/k/r.png"
grep -q "File too large" "$T/err" && [ -z "$(ls "$T/k")" ] && ok "ulimit -f: --report: the reason, nothing left" \
  || bad "ulimit -f: --report: $(cat "$T/err") left: $(ls "$T/k")"
want_rc 3 "ulimit -f: stdout to a file" bash -c 'ulimit -f 1; exec "$@" >"$0"' "$T/k/big.csv" "$S" --bench-log fwd:3
grep -q "^mmsim: stdout: File too large" "$T/err" && ok "ulimit -f: stdout: the reason" || bad "ulimit -f: stdout: $(cat "$T/err")"
ONE_ERROR_LINE=0

[ $fails -eq 0 ] && echo "cli_signals: all passed" || { echo "cli_signals: $fails failed"; exit 1; }
