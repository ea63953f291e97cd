#!/usr/bin/env bash
# cli_ukmarsbot_contest.sh - the whole contest on the emulated UKMARSBOT:
# our firmware built for the board (make firmware-ukmarsbot: hal/ukmarsbot,
# robots/ukmarsbot.ini's [firmware], IR walls through firmware/walls.c) on
# mazes/gen-16x16-s1.txt. Armed from the console (r), started by a hand over
# the left front sensor (occlude=lfs), it searches to the centre and back,
# makes its speed runs and says "contest done": goal reached, no front or
# side contact, the stack's headroom at the end at least 400 B (command k:
# the bytes never used since power-on); 40 s of it twice give the same
# console and JSON. --end-on TEXT ends a board run when the console prints
# TEXT, also in a --batch of boards (one board per maze).
set -u
B=${BUILD:-build}
MMSIM=${MMSIM:-$B/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
command -v avr-gcc >/dev/null || { echo "SKIP cli_ukmarsbot_contest: avr-gcc not installed"; exit 77; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory B="$B" "$@"; }

want_rc 0 "make firmware-ukmarsbot" mk firmware-ukmarsbot
END_S=${UKB_CONTEST_S:-240}
HANDS="0.3 send=r; 1.0 occlude=lfs; $END_S send=k; $((END_S + 1)) end"
run() { "$MMSIM" --maze mazes/gen-16x16-s1.txt --board ukmarsbot --avr $B/ukmarsbot/mouse.elf --robot robots/ukmarsbot.ini \
  --input "$HANDS" --json; }
want_rc 0 "the contest on gen-16x16-s1 (goal reached: exit 0)" run; cp "$T/out" "$T/a.json"
python3 - "$T/a.json" <<'PY' >"$T/msg" && ok "$(cat "$T/msg")" || bad "contest: $(cat "$T/msg")"
import json, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1]); c = j["console"].replace("\r", "")
lines = c.splitlines()
assert "armed: a hand over the front sensor starts" in lines and "go" in lines, c[:300]
assert j["reached_goal"], "goal not reached"
k = j["contacts"]
assert k["front"] == 0 and k["side"] == 0, k
assert "contest done" in lines, "no 'contest done': " + " / ".join(lines[-5:])
runs = [l for l in lines if l.startswith("run ") and "reached the goal" in l]
assert len(runs) == 3, runs
stk = [l for l in lines if l.startswith("stack unused")][-1]
unused = int(stk.split()[2])
assert unused >= 400 and " overruns 0," in stk, stk
print("goal, no contact, %d speed runs, first %s s best %s s; %s" % (len(runs), j["first_run_s"], j["best_run_s"], stk))
PY
# determinism on the search's first 40 s (a whole contest twice is long under the sanitizers)
HANDS="0.3 send=r; 1.0 occlude=lfs; 40 end"
want_rc 0 "40 s of the search (the goal reached at 27 s)" run; cp "$T/out" "$T/b.json"
want_rc 0 "40 s of the search again" run
[ "$(strip "$T/b.json")" = "$(strip "$T/out")" ] && ok "deterministic: the same console and JSON twice" || bad "two runs differ"

# --end-on: the run ends at the console's "armed:" (0.3 s), not at the input's end
want_rc 1 "--end-on 'armed:' (no lap: exit 1)" "$MMSIM" --maze mazes/gen-16x16-s1.txt --board ukmarsbot --avr $B/ukmarsbot/mouse.elf \
  --robot robots/ukmarsbot.ini --input "0.3 send=r; 1.0 occlude=lfs; 40 end" --end-on "armed:" --json
python3 -c "
import json, sys
j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
assert j['exit_reason'] == 'console_end' and 0.3 < j['sim_time_s'] < 0.35, (j['exit_reason'], j['sim_time_s'])
assert j['console'].replace(chr(13), '').splitlines()[-1].startswith('armed:'), j['console'][-200:]
print('exit_reason console_end at %.3f s' % j['sim_time_s'])" "$T/out" >"$T/msg" && ok "$(cat "$T/msg")" || bad "--end-on: $(cat "$T/msg")"
# a batch of boards: each maze's run ends at "go" (the hand's start, 1 s)
mkdir "$T/two"; cp mazes/gen-16x16-s1.txt mazes/gen-16x16-s2.txt "$T/two/"
want_rc 1 "--batch with --board (each run ends at 'go': no lap, exit 1)" "$MMSIM" --batch "$T/two" --jobs 2 --board ukmarsbot \
  --avr $B/ukmarsbot/mouse.elf --robot robots/ukmarsbot.ini --input "0.3 send=r; 1.0 occlude=lfs; 40 end" --end-on go --json
python3 -c "
import json, sys
js = [json.loads(l) for l in open(sys.argv[1])]
assert [j['maze'].split('/')[-1] for j in js] == ['gen-16x16-s1.txt', 'gen-16x16-s2.txt'], js
assert all(j['exit_reason'] == 'console_end' and 1.0 < j['sim_time_s'] < 1.4 and j['driver'] == 'board' for j in js), js
print('two boards, each ended at %s s' % [j['sim_time_s'] for j in js])" "$T/out" >"$T/msg" && ok "$(cat "$T/msg")" || bad "board batch: $(cat "$T/msg")"
ONE_ERROR_LINE=1 want_rc 2 "--end-on without --board" "$MMSIM" --maze mazes/gen-16x16-s1.txt --end-on x
ONE_ERROR_LINE=1 want_rc 2 "--end-on ''" "$MMSIM" --maze mazes/gen-16x16-s1.txt --board ukmarsbot --avr $B/ukmarsbot/mouse.elf --end-on ''
ONE_ERROR_LINE=1 want_rc 2 "--batch --board with --eeprom" "$MMSIM" --batch "$T/two" --board ukmarsbot --avr $B/ukmarsbot/mouse.elf --eeprom "$T/e.bin"

[ $fails -eq 0 ] && echo "cli_ukmarsbot_contest: all ok" || { echo "cli_ukmarsbot_contest: $fails failed"; exit 1; }
