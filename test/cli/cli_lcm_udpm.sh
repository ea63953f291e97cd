#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_lcm_udpm.sh - live telemetry over LCM's udpm (multicast) provider,
# recorded by lcm-logger, inside a private network namespace this test
# creates (multicast never leaves it). The live log must hold every message
# of the run's own --lcm-log, and so must a replay of that log with
# `make replay` (lcm-logplayer). Skipped (exit 77) if no namespace can be made.
set -u
S=$(realpath "${MMSIM:-build/mmsim}")
L=$(realpath "${MMLOG:-build/mmlog}")
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
skip() { echo "SKIP cli_lcm_udpm.sh: $1"; exit 77; }
command -v unshare >/dev/null || skip "no unshare"
command -v lcm-logger >/dev/null || skip "no lcm-logger (liblcm-bin)"
command -v ip >/dev/null || skip "no ip (iproute2)"
unshare -n true 2>/dev/null || skip "cannot create a network namespace (needs root or user namespaces)"

# Without a multicast route: exit 3 and one error line, before any run.
env -u LCM_DEFAULT_URL unshare -n bash -c 'ip link set lo up; "$1" --maze "$2" --lcm --json' _ "$S" mazes/gen-5x5-s1.txt >"$T/out" 2>"$T/err"
rc=$?
if [ $rc -eq 3 ] && [ "$(wc -l <"$T/err")" -eq 1 ] && grep -q "no multicast route" "$T/err" && [ ! -s "$T/out" ]; then
  echo "ok: no multicast route: exit 3, one line"
else
  echo "FAILED: no multicast route: exit $rc, stderr: $(cat "$T/err")"; exit 1
fi

# Inside the namespace: only lo, with a multicast route. The run is paced at
# real time (--realtime), 4.5 s of contest, so udpm does not drop bursts.
unshare -n bash -s "$S" "$L" "$T" "$PWD/mazes/gen-5x5-s1.txt" "$PWD" <<'EOF'
S=$1 L=$2 T=$3 M=$4 R=$5
ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo || exit 77
URL='udpm://239.255.76.67:7667?ttl=0'
lcm-logger --lcm-url="$URL&recv_buf_size=4194304" -f "$T/live.lcmlog" >"$T/logger.out" 2>&1 &
logger=$!
for i in $(seq 50); do [ -e "$T/live.lcmlog" ] && break; sleep 0.1; done
sleep 0.5 # subscribed
"$S" --maze "$M" --driver scripted --runs 1 --json --realtime --lcm="$URL" --lcm-log "$T/file.lcmlog" >"$T/run.json"; rc=$?
sleep 0.5 # the last datagrams reach the logger
kill -INT $logger; wait $logger
[ $rc -eq 0 ] || exit $rc
# `make replay` itself, at twice the speed, recorded again
lcm-logger --lcm-url="$URL&recv_buf_size=4194304" -f "$T/replay.lcmlog" >"$T/logger2.out" 2>&1 &
logger=$!
for i in $(seq 50); do [ -e "$T/replay.lcmlog" ] && break; sleep 0.1; done
sleep 0.5
make -s --no-print-directory -C "$R" replay LOG="$T/file.lcmlog" SPEED=2 LCM_URL="$URL" >/dev/null || exit 5
sleep 0.5
kill -INT $logger; wait $logger
exit 0
EOF
rc=$?
[ $rc -eq 77 ] && skip "cannot set up loopback multicast in the namespace"
[ $rc -eq 0 ] || { echo "FAILED: mmsim with --lcm=udpm:// exited $rc"; cat "$T/logger.out"; exit 1; }
fails=0
"$L" --json "$T/file.lcmlog" >"$T/file.json" || { echo "FAILED: mmlog"; exit 1; }
for what in live replay; do
  "$L" --json "$T/$what.lcmlog" >"$T/$what.json" || { echo "FAILED: mmlog $what"; exit 1; }
  python3 - "$T/file.json" "$T/$what.json" "$what" <<'EOF' || fails=1
import json, sys
f = json.load(open(sys.argv[1])); l = json.load(open(sys.argv[2])); what = sys.argv[3]
print("file log:", {k: v["count"] for k, v in f.items()})
print(what, "log:", {k: v["count"] for k, v in l.items()})
ok = sorted(f) == sorted(l) and all(f[k]["count"] == l[k]["count"] and f[k]["first_s"] == l[k]["first_s"]
                                    and f[k]["last_s"] == l[k]["last_s"] and l[k]["bad"] == 0 for k in f)
print(("ok: %s udpm log equals the file log" if ok else "FAILED: %s udpm log differs from the file log") % what)
sys.exit(0 if ok else 1)
EOF
done
exit $fails
