# lib.sh - helpers shared by the cli_*.sh tests (sourced after T, the
# temporary folder, is set). ok/bad count the checks; want_rc runs a command
# with stdout in $T/out and stderr in $T/err and checks its exit code. With
# ONE_ERROR_LINE=1 it also checks that stderr holds at most one line (bad
# input gets one clear error line), except for runs with --verbose.
fails=0
ok()  { echo "ok: $1"; }
bad() { echo "FAILED: $1"; fails=$((fails+1)); }
want_rc() { local want=$1 desc=$2; shift 2
  "$@" >"$T/out" 2>"$T/err"; local rc=$?
  if [ $rc -eq "$want" ]; then ok "$desc"; else bad "$desc: exit $rc, want $want"; head -5 "$T/err"; fi
  if [ "${ONE_ERROR_LINE:-0}" = 1 ]; then
    case " $* " in *" --verbose "*) ;; *) [ "$(wc -l <"$T/err")" -le 1 ] || bad "$desc: more than one error line: $(cat "$T/err")" ;; esac
  fi; }
# The last JSON line of a file without the wall-clock fields, keys sorted:
# two runs of the same inputs must print the same.
strip() { python3 -c "import json,sys; d=json.loads(open(sys.argv[1]).read().splitlines()[-1]); d.pop('wall_time_s'); d.pop('real_time_factor'); print(json.dumps(d, sort_keys=True))" "$1"; }
# Start an Xvfb for this test: XPID (the caller's cleanup kills it) and
# DISPLAY; without Xvfb, or if it does not start, a SKIP line and exit 77.
start_xvfb() { local name=$1
  command -v Xvfb >/dev/null || { echo "SKIP $name: Xvfb not installed"; exit 77; }
  Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$T/dpy" 2>"$T/xvfb.err" &
  XPID=$!
  for _ in $(seq 50); do [ -s "$T/dpy" ] && break; sleep 0.1; done
  [ -s "$T/dpy" ] || { echo "SKIP $name: Xvfb did not start: $(head -1 "$T/xvfb.err")"; exit 77; }
  export DISPLAY=:$(head -1 "$T/dpy"); }
# GL=(the command that runs the viewer binary $1): for a sanitized build,
# Mesa's driver preloaded (it is unloaded at exit, leaving nameless frames;
# preloaded they stay named for the GL-only leak suppressions).
gl_cmd() { GL=("$1")
  if ldd "$1" | grep -q libasan; then
    local asan dri pre=
    asan=$(ldd "$1" | awk '/libasan/ {print $3}')
    dri=$(ls /usr/lib/*/dri/swrast_dri.so 2>/dev/null | head -1)
    [ -n "$dri" ] && pre="$asan $dri"
    GL=(env "LD_PRELOAD=$pre" "LSAN_OPTIONS=suppressions=$PWD/test/tools/lsan-gl.supp" "$1")
  fi; }
# open_mazes DIR: DIR/open.txt, an open 16x16 maze (outer walls and posts
# only), and DIR/east.txt, the same with a wall east of the start cell.
open_mazes() { python3 - "$1" <<'PY'
import sys
def maze(path, east):
    n = 16; rows = ["o" + "---o" * n]
    for r in range(n):
        row = "|" + "    " * (n - 1) + "   |"
        if r == n - 1 and east: row = row[:4] + "|" + row[5:]
        rows += [row, "o" + ("---o" * n if r == n - 1 else "   o" * n)]
    open(path, "w").write("\n".join(rows) + "\n")
maze(sys.argv[1] + "/open.txt", False); maze(sys.argv[1] + "/east.txt", True)
PY
}
