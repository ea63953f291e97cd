#!/usr/bin/env bash
# run.sh: alone (timed: real-time runs, timed input or timeouts)
# cli_lcm.sh - LCM telemetry to a log (mmsim --lcm-log), decoded with the
# generated C types (mmlog): every channel present, counts match the rates,
# lap events equal the lap table, the last pose equals final_pose, MM_PARTS
# carries the robot's components (the paper robot's three ToF as
# MM_SENSORS has them; an IR robot's sensors), the run is the same with and
# without telemetry (the paper robot and an IR robot), a corrupt or cut
# MM_PARTS is exit 2, flag and file errors.
set -u
S=${MMSIM:-build/mmsim}
L=${MMLOG:-build/mmlog}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
one_line() { [ "$(wc -l <"$T/err")" -eq 1 ] && ok "$1: one error line" || bad "$1: error lines: $(cat "$T/err")"; }

# A firmware contest (search, then speed runs) on 5x5 with the default rate.
M=mazes/gen-5x5-s1.txt
want_rc 0 "firmware contest with --lcm-log" "$S" --maze $M --driver firmware --json --lcm-log "$T/run.lcmlog"
cp "$T/out" "$T/run.json"
want_rc 0 "mmlog summary" "$L" --json "$T/run.lcmlog"
cp "$T/out" "$T/sum.json"
for ch in POSE MOTORS SENSORS PARTS RACE RACE_EVENT BELIEF MAZE; do "$L" --dump MM_$ch "$T/run.lcmlog" >"$T/$ch.jsonl"; done

python3 - "$T" <<'EOF' && ok "channels, counts, laps, final pose, belief" || bad "log content"
import json, sys
T = sys.argv[1]
run = json.loads(open(T + "/run.json").read().splitlines()[-1])
summ = json.loads(open(T + "/sum.json").read())
dump = lambda ch: [json.loads(l) for l in open("%s/%s.jsonl" % (T, ch))]
fails = []
def check(cond, what):
    if not cond: fails.append(what)
chans = ["MM_POSE", "MM_MOTORS", "MM_SENSORS", "MM_PARTS", "MM_RACE", "MM_RACE_EVENT", "MM_BELIEF", "MM_MAZE"]
check(sorted(summ) == sorted(chans), "channels %s" % sorted(summ))
check(all(c["bad"] == 0 for c in summ.values()), "undecodable messages")
steps = round(run["sim_time_s"] * 1000)  # 1 ms physics step
def expect(period):  # multiples of the period, plus the final state
    return steps // period + (1 if steps % period else 0)
for ch in ["MM_POSE", "MM_MOTORS", "MM_SENSORS", "MM_PARTS"]:
    check(summ[ch]["count"] == expect(10), "%s count %d, want %d" % (ch, summ[ch]["count"], expect(10)))
check(summ["MM_RACE"]["count"] == expect(100), "MM_RACE count %d, want %d" % (summ["MM_RACE"]["count"], expect(100)))
check(abs(summ["MM_POSE"]["last_s"] - run["sim_time_s"]) < 1e-9, "last pose time")
pose = dump("POSE")
check([p["utime"] for p in pose] == sorted(p["utime"] for p in pose), "pose times in order")
last = pose[-1]
fp = run["final_pose"]
check((round(last["x_m"], 6), round(last["y_m"], 6), round(last["heading_rad"], 6)) == (fp["x_m"], fp["y_m"], fp["heading_rad"]),
      "final pose %s vs %s" % (last, fp))
ends = [e for e in dump("RACE_EVENT") if e["kind"] == "lap_end"]
starts = [e for e in dump("RACE_EVENT") if e["kind"] == "lap_start"]
table = [(l["lap"], l["start_s"], l["end_s"], l["run_s"]) for l in run["laps"]]
check([(e["lap"], round(e["start_s"], 3), round(e["end_s"], 3), round(e["run_s"], 3)) for e in ends] == table,
      "lap events %s vs table %s" % (ends, table))
check(len(starts) >= len(ends) and [s["lap"] for s in starts][:len(ends)] == [e["lap"] for e in ends], "lap starts")
check(len(ends) >= 2 and sum(e["best"] for e in ends) >= 1, "best lap flagged")
best = min(range(len(ends)), key=lambda i: ends[i]["run_s"])
race = dump("RACE")
check(race[-1]["laps"] == len(table) and race[-1]["best_lap"] == best + 1 and round(race[-1]["best_run_s"], 3) == run["best_run_s"],
      "final race state %s" % race[-1])
bel = dump("BELIEF")
check(len(bel) >= 1, "belief messages")
b = bel[-1]
check(b["width"] == 5 and b["height"] == 5 and len(b["walls"]) == 25 and len(b["cost"]) == 25, "belief map size")
check(b["path"] and b["path"][0] == b["cell"] and b["cost"][b["path"][-1]] == 0, "planned path from the mouse to the goal")
check(all(0 <= m["state"] <= 6 and 0 <= m["heading"] <= 3 for m in bel), "belief state and heading")
sens = dump("SENSORS")
check(any(not t for s in sens for t in s["tof_timeout"]), "ToF readings")
check(sens[-1]["encoder"][0] != 0 and sens[-1]["encoder"][1] != 0, "encoder counts")
mz = dump("MAZE")
check(len(mz) == 1 and mz[0]["utime"] == 0 and mz[0]["path"] == "mazes/gen-5x5-s1.txt" and mz[0]["width"] == 5
      and len(mz[0]["walls"]) == 25 and mz[0]["goals"] and "cell_m = 0.18" in mz[0]["config"], "MM_MAZE: maze, path, config")
parts = dump("PARTS")
check([p["utime"] for p in parts] == [s["utime"] for s in sens], "MM_PARTS with every MM_SENSORS")
for p, s in zip(parts, sens):
    ok = [(q["kind"], q["name"], q["units"], len(q["values"])) for q in p["parts"]] == \
         [("tof", n, "mm timeout true_mm", 3) for n in ("left", "front", "right")]
    for i, q in enumerate(p["parts"][:3]):
        mm, to, true_mm = q["values"]
        ok = ok and round(mm) == s["tof_mm"][i] and bool(to) == s["tof_timeout"][i] and \
             (true_mm == -1 if s["tof_true_m"][i] < 0 else abs(true_mm - s["tof_true_m"][i] * 1000) < 1e-9)
    ok = ok and p["battery_v"] == 6.0 and 0.99 < p["battery_soc"] <= 1 and p["emitter"] == [False] * 4
    if not ok:
        check(False, "MM_PARTS at %d vs MM_SENSORS: %s %s" % (p["utime"], p, s)); break
mot = dump("MOTORS")
check(any(m["command"][0] != 0 for m in mot) and any(abs(m["current_a"][0]) > 0 for m in mot), "motor state")
if fails:
    print("\n".join(fails)); sys.exit(1)
EOF

# Determinism: the run is the same without telemetry, and the log is the same twice.
want_rc 0 "same contest without telemetry" "$S" --maze $M --driver firmware --json
[ "$(strip "$T/out")" = "$(strip "$T/run.json")" ] && ok "telemetry does not change the run" || bad "telemetry changed the run"
"$S" --maze $M --driver firmware --json --lcm-log "$T/again.lcmlog" --lcm=memq:// >/dev/null
cmp -s "$T/run.lcmlog" "$T/again.lcmlog" && ok "same log bytes (with a live memq:// URL too)" || bad "logs differ"

# An IR robot (test/robots/ir.ini): MM_PARTS lists its ToF and IR sensors;
# its run is the same with and without telemetry.
R=test/robots/ir.ini
want_rc 0 "IR robot with --lcm-log" "$S" --maze $M --driver firmware --robot $R --json --lcm-log "$T/ir.lcmlog"
cp "$T/out" "$T/ir.json"
want_rc 0 "IR robot without telemetry" "$S" --maze $M --driver firmware --robot $R --json
[ "$(strip "$T/out")" = "$(strip "$T/ir.json")" ] && ok "IR robot: telemetry does not change the run" || bad "IR robot: telemetry changed the run"
"$L" --dump MM_PARTS "$T/ir.lcmlog" | tail -1 | python3 -c '
import json, sys
p = json.loads(sys.stdin.read())
k = [(q["kind"], q["name"], q["units"]) for q in p["parts"]]
sys.exit(0 if k == [("tof", n, "mm timeout true_mm") for n in ("left", "front", "right")] +
         [("ir", n, "dark lit lit_minus_dark") for n in ("lf", "rf", "ls", "rs")] else 1)' \
  && ok "IR robot: MM_PARTS lists its seven sensors" || bad "IR robot: MM_PARTS parts"
# A crafted MM_PARTS: its part count made 0x7FFF (lcm-gen's decoder would
# malloc for it), or the log cut inside an MM_PARTS event: exit 2, one line.
python3 - "$T/run.lcmlog" "$T/badparts.lcmlog" "$T/cutparts.lcmlog" <<'PY'
import sys
good = open(sys.argv[1], 'rb').read()
d = bytearray(good)
i = d.index(b'MM_PARTS') + len('MM_PARTS')  # the payload: hash 8, utime 8, nparts 2
d[i + 16], d[i + 17] = 0x7F, 0xFF
open(sys.argv[2], 'wb').write(bytes(d))
open(sys.argv[3], 'wb').write(good[:good.index(b'MM_PARTS', i) + 30])  # the second MM_PARTS cut
PY
want_rc 2 "mmlog on a corrupt MM_PARTS" "$L" "$T/badparts.lcmlog"
one_line "corrupt MM_PARTS"; grep -q "MM_PARTS: 1 message do not decode" "$T/err" && ok "corrupt MM_PARTS named" || bad "corrupt MM_PARTS: $(cat "$T/err")"
want_rc 2 "mmlog --dump MM_PARTS on a corrupt MM_PARTS" "$L" --dump MM_PARTS "$T/badparts.lcmlog"
want_rc 2 "mmlog on a log cut inside MM_PARTS" "$L" "$T/cutparts.lcmlog"
one_line "cut MM_PARTS"; grep -q "truncated" "$T/err" && ok "cut MM_PARTS: truncated" || bad "cut MM_PARTS: $(cat "$T/err")"

# --lcm-rate: the high-rate channels follow it (scripted driver, 250 Hz = every 4 steps).
want_rc 0 "scripted run at 250 Hz" "$S" --maze $M --driver scripted --runs 1 --json --lcm-rate 250 --lcm-log "$T/r.lcmlog"
python3 - "$T/out" <(${L} --json "$T/r.lcmlog") <<'EOF' && ok "counts at --lcm-rate 250" || bad "counts at --lcm-rate 250"
import json, sys
run = json.loads(open(sys.argv[1]).read().splitlines()[-1]); s = json.loads(open(sys.argv[2]).read())
n = round(run["sim_time_s"] * 1000)
want = n // 4 + (1 if n % 4 else 0)
print(s["MM_POSE"]["count"], want, s["MM_POSE"]["rate_hz"])
sys.exit(0 if s["MM_POSE"]["count"] == want and "MM_BELIEF" not in s and abs(s["MM_POSE"]["rate_hz"] - 250) < 1 else 1)
EOF
want_rc 0 "mmlog text table" "$L" "$T/r.lcmlog"
grep -q '^channel  *count  *rate_hz  *first_s  *last_s  *bad$' "$T/out" && grep -q '^MM_POSE ' "$T/out" && ok "mmlog table" || bad "mmlog table: $(cat "$T/out")"

# MM_LINK in processor-in-the-loop runs (the Mega image in simavr, 1 Mbaud):
# 10 Hz and at the run's end, totals equal the JSON's link report, each message's
# utilisation is its window's bytes over the window's capacity.
E=${BUILD:-build}/arduino/mega2560/Mouse-5x5.elf
if [ -f "$E" ]; then
  want_rc 1 "PIL run with --lcm-log" "$S" --maze $M --avr "$E" --mcu atmega2560 --time-limit 2.05 --json --lcm-log "$T/pil.lcmlog"
  cp "$T/out" "$T/pil.json"
  "$L" --dump MM_LINK "$T/pil.lcmlog" >"$T/pil.link" 2>&1
  python3 - "$T/pil.json" "$T/pil.link" <<'EOF2' && ok "MM_LINK: rate, totals, windowed utilisation" || bad "MM_LINK in PIL"
import json, sys
j = json.load(open(sys.argv[1])); d = j["link"]; m = [json.loads(x) for x in open(sys.argv[2])]
fails = []
end_us = round(j["sim_time_s"] * 1e6)  # the time limit counts on the contest clock: the run ends after 2.05 s
want = [100000 * i for i in range(1, end_us // 100000 + 1)] + ([end_us] if end_us % 100000 else [])
if [x["utime"] for x in m] != want or end_us <= 2050000: fails.append("times %s, want %s" % ([x["utime"] for x in m], want))
last = m[-1]
if (last["bytes_to_mcu"], last["bytes_from_mcu"], last["baud"]) != (d["tx_bytes"], d["rx_bytes"], d["baud"]): fails.append("totals")
if not (last["connected"] and last["handshake"] and last["frame_errors"] == 0 and last["dropped_to_mcu"] == 0): fails.append("state")
prev_t = prev_tx = prev_rx = 0
for x in m:  # a window of w seconds at 1 Mbaud carries at most 100000*w bytes
    cap = (x["utime"] - prev_t) / 1e6 * d["baud"] / 10
    for k, b in (("util_to_mcu", x["bytes_to_mcu"] - prev_tx), ("util_from_mcu", x["bytes_from_mcu"] - prev_rx)):
        if abs(x[k] - b / cap) > 1e-9 or not 0 < x[k] < 1: fails.append("%s at %d: %s vs %s" % (k, x["utime"], x[k], b / cap))
    prev_t, prev_tx, prev_rx = x["utime"], x["bytes_to_mcu"], x["bytes_from_mcu"]
print("\n".join(fails)); sys.exit(1 if fails else 0)
EOF2
else
  echo "SKIP cli_lcm MM_LINK: $E not built (make arduino)"
fi

# Errors: one line, exit 2 for a bad flag, 3 for an output that cannot be opened; nothing left behind.
want_rc 3 "unwritable log" "$S" --maze $M --lcm-log "$T/no/such/dir/x.lcmlog"
one_line "unwritable log"; grep -q "cannot write the LCM log" "$T/err" || bad "unwritable log message: $(cat "$T/err")"
# a provider liblcm does not have is a bad flag (exit 2), refused before the run
want_rc 2 "unknown LCM provider" "$S" --maze $M --lcm=warp://x --lcm-log "$T/half.lcmlog"
one_line "unknown LCM provider"; [ ! -e "$T/half.lcmlog" ] && ok "no log left after a refused URL" || bad "log left behind"
# the log is written to a temporary and renamed at the end: a write that fails (a file size
# limit: EFBIG) or a kill leaves an existing good log as it was, byte for byte
cp "$T/r.lcmlog" "$T/good.lcmlog"; cp "$T/r.lcmlog" "$T/keep.lcmlog"
( ulimit -f 20; trap '' XFSZ; exec "$S" --maze $M --driver firmware --json --lcm-log "$T/keep.lcmlog" ) >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && one_line "log write fails" && grep -q "^mmsim: $T/keep.lcmlog: writing the LCM log failed: File too large (the file there is unchanged)$" "$T/err" \
  && ok "log write fails: exit 3, the reason" || bad "log write fails: exit $rc $(cat "$T/err")"
cmp -s "$T/keep.lcmlog" "$T/good.lcmlog" && [ -z "$(ls "$T" | grep '\.tmp\.')" ] && ok "log write fails: the old log kept, no temporary left" || bad "log write fails: old log changed or temporary left: $(ls "$T")"
"$S" --maze mazes/gen-16x16-s1.txt --driver firmware --realtime --lcm-log "$T/keep.lcmlog" >/dev/null 2>&1 & kp=$!
sleep 1; kill -KILL $kp; wait $kp 2>/dev/null
cmp -s "$T/keep.lcmlog" "$T/good.lcmlog" && ok "mmsim killed mid-run: the old log kept" || bad "mmsim killed mid-run: the old log changed"
rm -f "$T"/keep.lcmlog.tmp.*
want_rc 3 "log on /dev/full" "$S" --maze $M --driver scripted --runs 1 --lcm-log /dev/full
one_line "log on /dev/full"; grep -q "^mmsim: /dev/full: writing the LCM log failed: No space left on device$" "$T/err" || bad "log on /dev/full: $(cat "$T/err")"
mkdir "$T/dir.lcmlog"
want_rc 3 "log path is a folder" "$S" --maze $M --driver scripted --runs 1 --lcm-log "$T/dir.lcmlog"
one_line "log path is a folder"; [ ! -s "$T/out" ] && grep -q "^mmsim: $T/dir.lcmlog: cannot write the LCM log: Is a directory$" "$T/err" \
  && ok "log path is a folder: refused before the run" || bad "log path is a folder: $(cat "$T/err" "$T/out")"
# tcpq without its hub (nothing listens on loopback port 1): one error, exit 3, before the run
timeout 60 "$S" --maze $M --driver scripted --runs 1 --lcm=tcpq://127.0.0.1:1 >"$T/out" 2>"$T/err"; rc=$?
[ $rc -eq 3 ] && one_line "tcpq without a hub" && [ ! -s "$T/out" ] && grep -q "^mmsim: tcpq://127.0.0.1:1: cannot open the LCM URL: cannot connect to its hub: Connection refused$" "$T/err" \
  && ok "tcpq without a hub: one error, exit 3" || bad "tcpq without a hub: exit $rc, $(wc -l <"$T/err") lines: $(head -3 "$T/err")"
# a hub (a stand-in on loopback) that goes away after 5,000 bytes: liblcm's reconnection
# attempts silenced, one error at the end, exit 3
python3 - "$T/port" <<'EOF2' &
import socket, struct, sys
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(1); s.settimeout(60)
open(sys.argv[1] + ".tmp", "w").write(str(s.getsockname()[1])); __import__("os").rename(sys.argv[1] + ".tmp", sys.argv[1])
c, _ = s.accept(); c.settimeout(60)
c.recv(8); c.sendall(struct.pack(">II", 0x287617fa, 0x0100))  # the hub's magic and version
got = 0
while got < 5000:
    d = c.recv(65536)
    if not d: break
    got += len(d)
c.close(); s.close()
EOF2
hp=$!
for _ in $(seq 50); do [ -s "$T/port" ] && break; sleep 0.1; done
timeout 60 "$S" --maze $M --driver scripted --runs 1 --realtime --lcm=tcpq://127.0.0.1:$(cat "$T/port") >"$T/out" 2>"$T/err"; rc=$?
wait $hp
[ $rc -eq 3 ] && one_line "tcpq hub lost" && grep -q "^mmsim: tcpq://127.0.0.1:[0-9]*: the connection to the LCM hub was lost at [0-9.]* s (.*): live telemetry stopped there$" "$T/err" \
  && ok "tcpq hub lost mid-run: one error, exit 3" || bad "tcpq hub lost: exit $rc, $(wc -l <"$T/err") lines: $(head -3 "$T/err")"
want_rc 2 "URL without a provider" "$S" --maze $M --lcm=nonsense
one_line "URL without a provider"
want_rc 2 "bad rate" "$S" --maze $M --lcm-log "$T/x.lcmlog" --lcm-rate 0
want_rc 2 "bad rate text" "$S" --maze $M --lcm-log "$T/x.lcmlog" --lcm-rate fast
want_rc 2 "empty log name" "$S" --maze $M --lcm-log ""
want_rc 2 "telemetry in a batch" "$S" --batch mazes --lcm-log "$T/x.lcmlog"
printf 'not a log at all\n' >"$T/junk"
want_rc 2 "mmlog on a non-log" "$L" "$T/junk"
one_line "mmlog on a non-log"
want_rc 2 "mmlog on a missing file" "$L" "$T/none.lcmlog"
head -c $(( $(stat -c %s "$T/r.lcmlog") - 7 )) "$T/r.lcmlog" >"$T/cut.lcmlog"
want_rc 2 "mmlog on a truncated log" "$L" "$T/cut.lcmlog"
one_line "mmlog on a truncated log"; grep -q '^MM_POSE ' "$T/out" && ok "summary before the cut" || bad "summary before the cut"
want_rc 2 "mmlog bad flag" "$L" --warp "$T/r.lcmlog"
want_rc 2 "mmlog --dump of an unknown channel" "$L" --dump NOPE "$T/r.lcmlog"
one_line "mmlog --dump NOPE"; [ ! -s "$T/out" ] && grep -q "^mmlog: --dump NOPE: not a channel mmlog decodes; the channels are MM_POSE, MM_MOTORS, .*, MM_MAZE$" "$T/err" \
  && ok "unknown channel: the known ones listed" || bad "unknown channel: $(cat "$T/err")"
[ $fails -eq 0 ]
