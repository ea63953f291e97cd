#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_connect.sh - the HUD's Connect at run time, under an Xvfb the test
# starts, driven by XTEST (build/test/xinput): in a live mmsim --gui window
# type a serial port into the Port field, press Enter (= Connect): the link
# opens and the simulator sends its sensor messages over it (a pseudo-
# terminal this script holds); a port that does not exist opens nothing and
# the run goes on; MM_LINK is logged from the Connect on. Skips without
# Xvfb or the XTEST helper.
set -u
S=${MMSIM:-build/mmsim}
X=${XINPUT:-build/test/xinput}
L=${MMLOG:-build/mmlog}
T=$(mktemp -d)
XPID= SPID= MPID=
cleanup() { for p in $SPID $MPID $XPID; do kill "$p" 2>/dev/null; done; rm -rf "$T"; }
trap cleanup EXIT
. "$(dirname "$0")/lib.sh"

[ -x "$X" ] || { echo "SKIP cli_connect.sh: $X not built (libxtst-dev or X11 headers missing)"; exit 77; }
start_xvfb cli_connect.sh

gl_cmd "$S"; SIM=("${GL[@]}")

# A pseudo-terminal pair: the simulator opens the slave by name, this end
# counts what arrives on the master (the MCU's side) for 20 s at most.
python3 - "$T" <<'PY' &
import os, pty, select, sys, time, tty
T = sys.argv[1]
m, s = pty.openpty()
tty.setraw(s)
open(T + "/pts.tmp", "w").write(os.ttyname(s)); os.rename(T + "/pts.tmp", T + "/pts")
n, end = 0, time.time() + 20
while time.time() < end and not os.path.exists(T + "/stop"):
    if select.select([m], [], [], 0.1)[0]:
        try: n += len(os.read(m, 4096))
        except OSError: break
open(T + "/mcu_bytes", "w").write(str(n))
PY
MPID=$!
for _ in $(seq 50); do [ -s "$T/pts" ] && break; sleep 0.1; done
PTS=$(cat "$T/pts")

# Port field in the side panel of an 800x600 window at (0, 0) (hud_fields: x 4..228, y 236..258;
# test_view checks the layout).
live() { # $1 = the port to type; the run's JSON in $T/$2.json
  "${SIM[@]}" --maze mazes/gen-5x5-s1.txt --driver scripted --gui --size 800x600 --json --lcm-log "$T/$2.lcmlog" >"$T/$2.json" 2>"$T/$2.err" &
  SPID=$!
  "$X" wait mmsim 30 || { bad "$2: no window"; return; }
  sleep 0.5
  "$X" click 100 247 && "$X" type "$1" && "$X" key Return || bad "$2: XTEST input failed"
  sleep 2
  "$X" key Escape   # not typing any more: closes the window
  wait $SPID; SPID=
}
live "$PTS" good
python3 - "$T/good.json" "$PTS" <<'PY' && ok "Connect opened $PTS and the simulator sent over it" || { bad "Connect: $(cat "$T/good.json" "$T/good.err" | head -5)"; }
import json, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
l = j.get("link") or {}
print("link:", {k: l.get(k) for k in ("device", "baud", "tx_bytes", "tx_msgs")})
sys.exit(0 if l.get("device") == sys.argv[2] and l.get("tx_bytes", 0) > 0 and l.get("baud") == 1000000 and j["exit_reason"] == "window_closed" else 1)
PY
"$L" --dump MM_LINK "$T/good.lcmlog" >"$T/link.jsonl" 2>&1
python3 -c "import json,sys; m=[json.loads(x) for x in open(sys.argv[1])]; sys.exit(0 if m and m[0]['utime'] > 0 and m[-1]['bytes_to_mcu'] > 0 else 1)" "$T/link.jsonl" \
  && ok "MM_LINK logged from the Connect on ($(wc -l <"$T/link.jsonl") messages)" || bad "MM_LINK after Connect: $(head -3 "$T/link.jsonl")"
touch "$T/stop"; wait $MPID; MPID=
n=$(cat "$T/mcu_bytes" 2>/dev/null); [ "${n:-0}" -gt 0 ] && ok "the MCU end received $n bytes" || bad "nothing arrived on the pty"

live "$T/no-such-tty" nodev
python3 -c "import json,sys; j=json.loads(open(sys.argv[1]).read().splitlines()[-1]); sys.exit(0 if 'link' not in j and j['exit_reason'] == 'window_closed' else 1)" "$T/nodev.json" \
  && ok "a port that does not exist: no link, the run goes on" || bad "bad port: $(cat "$T/nodev.json" "$T/nodev.err" | head -5)"

[ $fails -eq 0 ] || { echo "$fails failed"; exit 1; }
