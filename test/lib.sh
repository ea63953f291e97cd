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
