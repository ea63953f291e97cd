#!/usr/bin/env bash
# cli_mmplot.sh - tools/mmplot draws a run's LCM log against time. The
# series it drew (--dump-data) are compared with the log itself (mmlog
# --dump): times, speed, motor volts, encoders, a ToF reading, the battery,
# the laps; a window (--from/--to) keeps exactly the log's samples inside
# it; the PNG is a PNG of a plausible size and the SVG parses as XML; a
# board run with --watch (BasicSensors) draws its watched variable and its
# IR sensors; wall contacts are drawn as the run's JSON counts them (a
# robot too long for its turns); bad input is one line and exit 2.
set -u
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
MMSIM=${MMSIM:-$B/mmsim}
MMLOG=${MMLOG:-$B/mmlog}
PY=/usr/bin/python3
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
[ -x "$PY" ] && "$PY" -c "import matplotlib" 2>/dev/null \
  || { echo "SKIP cli_mmplot: $PY has no matplotlib (Debian's python3-matplotlib: make deps)"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" SHARED="$SHARED" "$@"; }
PLOT=("$PY" tools/mmplot --mmlog "$MMLOG")

want_rc 1 "a 20 s run logged (time limit: exit 1)" "$MMSIM" --maze mazes/gen-16x16-s1.txt --time-limit 20 --lcm-log "$T/run.lcmlog"
for ch in MM_POSE MM_MOTORS MM_SENSORS MM_PARTS MM_RACE_EVENT; do "$MMLOG" --dump $ch "$T/run.lcmlog" >"$T/$ch.jsonl"; done
want_rc 0 "the whole run to PNG" "${PLOT[@]}" "$T/run.lcmlog" -o "$T/run.png" --dump-data "$T/all.json"
want_rc 0 "a window to SVG" "${PLOT[@]}" "$T/run.lcmlog" -o "$T/win.svg" --from 5 --to 8.5 --dump-data "$T/win.json"

"$PY" - "$T" <<'EOF' && ok "plotted series = the log's; the window keeps its samples; PNG and SVG valid" || bad "plotted data against the log"
import json, struct, sys, xml.etree.ElementTree as ET
T = sys.argv[1]
def msgs(ch): return [json.loads(l) for l in open("%s/%s.jsonl" % (T, ch))]
fails = []
def check(cond, what):
    if not cond: fails.append(what)
pose, mot, sen, parts, ev = (msgs(c) for c in ("MM_POSE", "MM_MOTORS", "MM_SENSORS", "MM_PARTS", "MM_RACE_EVENT"))
def tof(m, name, i):
    return next(p["values"][i] for p in m["parts"] if p["kind"] == "tof" and p["name"] == name)
want = {"pose.v_m_s": (pose, lambda m: m["v_m_s"]), "pose.omega_rad_s": (pose, lambda m: m["omega_rad_s"]),
        "motors.voltage_v.left": (mot, lambda m: m["voltage_v"][0]), "motors.current_a.right": (mot, lambda m: m["current_a"][1]),
        "motors.wheel_rad_s.left": (mot, lambda m: m["wheel_rad_s"][0]), "sensors.encoder.right": (sen, lambda m: m["encoder"][1]),
        "parts.tof.front.mm": (parts, lambda m: tof(m, "front", 0)),
        "parts.tof.right.true_mm": (parts, lambda m: None if tof(m, "right", 2) == -1 else tof(m, "right", 2)),
        "parts.battery_v": (parts, lambda m: m["battery_v"]), "parts.battery_soc": (parts, lambda m: m["battery_soc"])}
for doc, lo, hi in ((json.load(open(T + "/all.json")), -1e9, 1e9), (json.load(open(T + "/win.json")), 5.0, 8.5)):
    for name, (ms, f) in want.items():
        s = doc["series"].get(name)
        if s is None: fails.append("no series " + name); continue
        rows = [(m["utime"] / 1e6, f(m)) for m in ms if lo <= m["utime"] / 1e6 <= hi]
        check(len(rows) > 300, "%s: %d samples in [%g, %g]" % (name, len(rows), lo, hi))
        check(s["t_s"] == [r[0] for r in rows], "%s [%g, %g]: times differ from the log's" % (name, lo, hi))
        check(s["v"] == [r[1] for r in rows], "%s [%g, %g]: values differ from the log's" % (name, lo, hi))
    check(not any("timeout" in n for n in doc["series"]), "a ToF timeout flag drawn as a reading")
all_doc, win_doc = json.load(open(T + "/all.json")), json.load(open(T + "/win.json"))
check(win_doc["from_s"] == 5.0 and win_doc["to_s"] == 8.5, "window bounds %s %s" % (win_doc["from_s"], win_doc["to_s"]))
starts = [e for e in ev if e["kind"] == "lap_start"]; ends = [e for e in ev if e["kind"] == "lap_end"]
check(len(ends) >= 1, "the 20 s run ends a lap")
check([(l["lap"], l["start_t_s"], l["end_t_s"]) for l in all_doc["laps"] if l["run_s"] is not None]
      == [(e["lap"], s["utime"] / 1e6, e["utime"] / 1e6) for s, e in zip(starts, ends)], "laps: %s" % all_doc["laps"])
check(all(5.0 <= l["start_t_s"] <= l["end_t_s"] <= 8.5 for l in win_doc["laps"]), "window laps clipped: %s" % win_doc["laps"])
png = open(T + "/run.png", "rb").read()
check(png[:8] == b"\x89PNG\r\n\x1a\n", "PNG signature")
w, h = struct.unpack(">II", png[16:24]) if len(png) > 24 else (0, 0)
check(1000 <= w <= 1400 and h > 1500 and len(png) > 50000, "PNG %dx%d, %d bytes" % (w, h, len(png)))
root = ET.parse(T + "/win.svg").getroot()
check(root.tag.endswith("svg") and sum(1 for _ in root.iter()) > 100, "SVG root %s" % root.tag)
for f in fails: print("  " + f)
sys.exit(1 if fails else 0)
EOF

# A board run with --watch: BasicSensors (test/firmware/arduino/board) reads the IR
# sensors of the BASIC sensor board; timer0_millis is the Arduino core's
# millisecond count. The watched variable and the IR sensors are drawn.
IMG=$B/clients/board/BasicSensors.elf
want_rc 0 "BasicSensors builds for the Nano" mk "$IMG"
want_rc 1 "a board run with --watch logged" "$MMSIM" --maze mazes/gen-5x5-s1.txt --board ukmarsbot-basic \
  --robot robots/ukmarsbot-basic-12.ini --avr "$IMG" --time-limit 1.2 --watch timer0_millis --lcm-log "$T/w.lcmlog"
"$MMLOG" --dump MM_WATCH "$T/w.lcmlog" >"$T/MM_WATCH.jsonl"; "$MMLOG" --dump MM_PARTS "$T/w.lcmlog" >"$T/wparts.jsonl"
want_rc 0 "the board run to PNG" "${PLOT[@]}" "$T/w.lcmlog" -o "$T/w.png" --dump-data "$T/w.json"
want_rc 0 "only its watches, to SVG" "${PLOT[@]}" "$T/w.lcmlog" -o "$T/w.svg" --channels MM_WATCH --dump-data "$T/wonly.json"
"$PY" - "$T" <<'EOF' && ok "the board run's watch and IR sensors plotted as logged" || bad "board run's watch and sensors"
import json, sys
T = sys.argv[1]
w = [json.loads(l) for l in open(T + "/MM_WATCH.jsonl")]
parts = [json.loads(l) for l in open(T + "/wparts.jsonl")]
doc, only = json.load(open(T + "/w.json")), json.load(open(T + "/wonly.json"))
fails = []
s = doc["series"].get("watch.timer0_millis", {})
if s.get("panel") != "watch timer0_millis" or s.get("t_s") != [m["utime"] / 1e6 for m in w] \
   or s.get("v") != [m["value"][0] for m in w] or len(w) < 100:
    fails.append("watch.timer0_millis differs from MM_WATCH")
elif not 1150 <= max(s["v"]) <= 1200: fails.append("timer0_millis reached %s ms in 1.2 s" % max(s["v"]))
if sorted(only["series"]) != ["watch.timer0_millis"]: fails.append("--channels MM_WATCH: %s" % sorted(only["series"]))
for name in ("left", "right", "front"):
    for i, val in enumerate(("dark", "lit", "lit_minus_dark")):
        s = doc["series"].get("parts.ir.%s.%s" % (name, val), {})
        want = [None if p["values"][i] == -1 else p["values"][i] for m in parts for p in m["parts"] if p["name"] == name]
        if s.get("v") != want or s.get("unit") != "ADC counts": fails.append("parts.ir.%s.%s differs from MM_PARTS" % (name, val))
    if name != "front" and max(v for v in doc["series"]["parts.ir.%s.lit_minus_dark" % name]["v"] if v is not None) < 100:
        fails.append("the %s sensor never saw its wall" % name)
for f in fails: print("  " + f)
sys.exit(1 if fails else 0)
EOF

# A robot longer than the firmware thinks (150 mm, not 120) touches the walls
# in its turns: each contact the run's JSON counts is a CONTACT event in the
# log and a line in the plot.
sed 's/^body_l_mm *=.*/body_l_mm = 150/' robots/paper.ini >"$T/long.ini"
want_rc 1 "a run with wall contacts logged" "$MMSIM" --maze mazes/gen-5x5-s1.txt --robot "$T/long.ini" --time-limit 10 \
  --json --lcm-log "$T/long.lcmlog"
cp "$T/out" "$T/long.out"
"$MMLOG" --dump MM_RACE_EVENT "$T/long.lcmlog" >"$T/long.jsonl"
want_rc 0 "the contacts run to PNG" "${PLOT[@]}" "$T/long.lcmlog" -o "$T/long.png" --dump-data "$T/long.json"
want_rc 0 "a window around the first contact" "${PLOT[@]}" "$T/long.lcmlog" -o "$T/longw.png" --from 1.5 --to 1.96 \
  --dump-data "$T/longw.json"
"$PY" - "$T" <<'EOF2' && ok "wall contacts: the JSON's count, the log's events, the plot's lines" || bad "wall contacts"
import json, sys
T = sys.argv[1]
run = json.loads(open(T + "/long.out").read().splitlines()[-1])
ev = [json.loads(l) for l in open(T + "/long.jsonl")]
c = [e for e in ev if e["kind"] == "contact"]
doc, win = json.load(open(T + "/long.json")), json.load(open(T + "/longw.json"))
fails = []
if not (run["collisions"] > 0 and len(c) == run["collisions"]): fails.append("%d contact events, JSON %d" % (len(c), run["collisions"]))
if [e["lap"] for e in c] != list(range(1, len(c) + 1)): fails.append("contacts numbered %s" % [e["lap"] for e in c])
if doc["contacts_t_s"] != [e["utime"] / 1e6 for e in c]: fails.append("plotted contacts %s" % doc["contacts_t_s"])
if not win["contacts_t_s"] or win["contacts_t_s"] != [e["utime"] / 1e6 for e in c if 1.5 <= e["utime"] / 1e6 <= 1.96]: fails.append("window contacts %s" % win["contacts_t_s"])
for f in fails: print("  " + f)
sys.exit(1 if fails else 0)
EOF2

# Bad input: one line naming mmplot, exit 2.
ONE_ERROR_LINE=1
echo "not a log" >"$T/text.lcmlog"
for c in "a JPEG output|$T/run.lcmlog -o $T/x.jpg" "no such log|$T/none.lcmlog -o $T/x.png" \
         "not an LCM log|$T/text.lcmlog -o $T/x.png" "a window after the run|$T/run.lcmlog -o $T/x.png --from 500 --to 600" \
         "an empty window|$T/run.lcmlog -o $T/x.png --from 8 --to 5" "an unknown channel|$T/run.lcmlog -o $T/x.png --channels MM_FOO" \
         "a channel not in the log|$T/run.lcmlog -o $T/x.png --channels MM_WATCH" "a bad --from|$T/run.lcmlog -o $T/x.png --from abc" \
         "no mmlog|$T/run.lcmlog -o $T/x.png --mmlog $T/nommlog" "no -o|$T/run.lcmlog"; do
  want_rc 2 "${c%%|*}" "${PLOT[@]}" ${c#*|}
  grep -q '^mmplot: ' "$T/err" || bad "${c%%|*}: the line does not name mmplot: $(cat "$T/err")"
  grep -q Traceback "$T/err" && bad "${c%%|*}: a traceback"
done
[ -e "$T/x.png" ] && bad "an output written for bad input"

[ $fails -eq 0 ] && echo "cli_mmplot: all passed" || { echo "cli_mmplot: $fails failed"; exit 1; }
