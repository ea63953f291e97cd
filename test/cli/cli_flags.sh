#!/usr/bin/env bash
# cli_flags.sh - mmsim's flags and messages at their edges
# (docs/REFERENCE.md): the offending argument named (-maze, -vv); a control
# character in --input or --mms text escaped, the error one line; --input's
# numbers as strict as every flag's; a flag with no effect in its
# combination refused; --lcm with an unknown provider bad input (2); the
# unknown-key message listing every key; --board listing the boards and
# taking a board file's own name; a contest file held to its `; source:`
# rule (contests/README.md) and --print-contest giving each key's source; a
# Python mms algorithm ended at the time limit as mms ends it (no
# BrokenPipeError traceback in the run); GUIDE-firmware's --time-limit.
set -u
S=${MMSIM:-build/mmsim}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
M=mazes/gen-5x5-s1.txt
G="timeout 60"
says() { grep -q -- "$2" "$T/err" && ok "$1: says '$2'" || bad "$1: want '$2', got: $(cat "$T/err")"; }
ONE_ERROR_LINE=1

# the argument at fault, named
want_rc 2 "-maze (one dash)" $G "$S" -maze $M; says "-maze" "unknown option: '-maze'"
want_rc 2 "--maze M -vv" $G "$S" --maze $M -vv; says "-vv" "unknown option: '-vv'"
want_rc 2 "--maze without its value" $G "$S" --maze; says "--maze at the end" "--maze: missing its value"

# a newline in --input or --mms text: the error stays one line, the text escaped
want_rc 2 "--input with a newline" $G "$S" --maze $M --input $'1 bogus\ntwo'; says "--input newline" 'bogus\\x0Atwo'
ONE_ERROR_LINE=0 # the algorithm's own stderr lines ("algo: ...") come too: mmsim's line is one
want_rc 3 "--mms with a newline" $G "$S" --maze $M --mms $'no-such-algo-x\nno-such-algo-y' --time-limit 2
[ "$(grep -c '^mmsim' "$T/err")" = 1 ] && grep -q "^mmsim: mms: the algorithm 'no-such-algo-x\\\\x0Ano-such-algo-y' exited with status 127" "$T/err" \
  && ok "--mms newline: the command escaped in mmsim's line" || bad "--mms newline: $(cat "$T/err")"
grep -q "mms algorithm 'no-such-algo-x\\\\x0Ano-such-algo-y'" "$T/out" && ok "--mms newline: the headline escaped" || bad "--mms headline: $(head -1 "$T/out")"
ONE_ERROR_LINE=1

# --input numbers: plain decimals only, as every flag (0x1, 1e0, +1, 0x1p1 refused)
for i in "0x1 lift" "1e0 lift" "+1 lift" "0x1p1 lift" " 1e0 place" "1 push=1e1" "1 push=+10" "1 push=0x10" "1 push=10,1e1" \
         "1 switches=0x1" "1 switches=+1" "1 switches=1e0" "inf lift" "nan lift"; do
  want_rc 2 "--input '$i'" $G "$S" --maze $M --input "$i" --time-limit 2
done
want_rc 1 "--input '1.5 lift; 2.5 place' (plain decimals)" $G "$S" --maze $M --input "1.5 lift; 2.5 place" --time-limit 3

# a flag with no effect in its combination: one line, exit 2
want_rc 2 "--validate --maze" $G "$S" --validate --maze $M; says "--validate --maze" "not with --maze"
want_rc 2 "--bench-log --maze" $G "$S" --bench-log fwd:3 --maze $M
want_rc 2 "--at without --screenshot" $G "$S" --maze $M --at 3; says "--at" "--at SECONDS needs --screenshot"
want_rc 2 "--speed without --gui" $G "$S" --maze $M --speed 2; says "--speed" "--speed needs --gui"
want_rc 2 "--jobs without --batch" $G "$S" --maze $M --jobs 2; says "--jobs" "--jobs N needs --batch"

# --lcm with a provider liblcm does not have: bad input, before the run
want_rc 2 "--lcm=bogus://x" $G "$S" --maze $M --lcm=bogus://x; says "--lcm=bogus://x" "the provider is udpm, file, memq, tcpq or mpudpm"

# the unknown-key message lists every key of the section (the chassis' last one too)
printf '[chassis.body]\nbogus_key = 1\n' >"$T/r.ini"
want_rc 2 "an unknown chassis key" $G "$S" --print-robot --robot "$T/r.ini"
last=$(tail -c 80 "$T/err")
grep -q "unknown key (a chassis has: body_w_mm .* body_yaw_inertia_kgm2)$" "$T/err" && ok "unknown key: every chassis key, to the last" \
  || bad "unknown key: cut: ...$last"

# --board: the boards listed; the board file's own name taken
want_rc 2 "--board nosuch" $G "$S" --board nosuch --avr "$T/none.elf" --maze $M
says "--board nosuch" "the boards there: .*ukmarsbot-v1.3"
want_rc 2 "--board bulebule (an STM32 board)" $G "$S" --board bulebule --avr "$T/none.elf" --maze $M
says "--board bulebule" "is an STM32 board: give its image with --firmware IMAGE.elf"
for b in ukmarsbot ukmarsbot-v1.3 ukmarsbot-basic-v1.3; do
  want_rc 2 "--board $b (then the missing image)" $G "$S" --board $b --avr "$T/none.elf" --maze $M
  says "--board $b" "none.elf"
done

# a contest file without its `; source:` lines: refused at the key (contests/README.md)
grep -v '^; source' contests/classic-uk.ini >"$T/nosrc.ini"
want_rc 2 "a contest file without sources" $G "$S" --print-contest --contest "$T/nosrc.ini"
says "contest without sources" "nosrc.ini:[0-9]*:1: maze.max_width: no '; source:' line above it"
python3 -c "import re,sys; sys.stdout.write(re.sub(r'; source:[^\n]*\n(time_limit_s)', r'\1', open(sys.argv[1]).read()))" \
  contests/classic-uk.ini >"$T/onesrc.ini"
want_rc 2 "a contest file with one key's source missing" $G "$S" --print-contest --contest "$T/onesrc.ini"
says "one source missing" "rules.time_limit_s: no '; source:' line above it"
want_rc 0 "--print-contest classic-uk" $G "$S" --print-contest --contest classic-uk
n_keys=$(grep -c '^[a-z_]* = ' "$T/out"); n_src=$(grep -c '^; source: ' "$T/out")
[ "$n_keys" -gt 10 ] && [ "$n_keys" = "$n_src" ] && grep -q '^; source: UKR 1.1: 18 cm unit squares$' "$T/out" \
  && ok "--print-contest: each of $n_keys keys with its file's source" || bad "--print-contest: $n_keys keys, $n_src sources"

# a Python mms algorithm under way when the time limit ends the run: mmsim
# kills it as mms does (QProcess::kill, its pipes still open), so it never
# sees a closed pipe (no EOF, no BrokenPipeError traceback in the run)
cat >"$T/naive.py" <<'PY'
import os, sys
def cmd(c):
    try:
        print(c, flush=True)
    except BrokenPipeError:  # said at once (os.write), before a traceback could be
        os.write(2, b"closed pipe: BrokenPipeError\n")
        raise
    r = sys.stdin.readline()
    if not r:
        os.write(2, b"closed pipe: EOF on stdin\n")
    return r.strip()
while True:
    print("setColor 0 0 G", flush=True)
    cmd("moveForward") if cmd("wallFront") == "false" else cmd("turnRight")
PY
ONE_ERROR_LINE=0
tb=0
for i in 1 2 3; do
  $G "$S" --maze mazes/gen-16x16-s1.txt --mms "python3 $T/naive.py" --time-limit 2 >/dev/null 2>"$T/mms.err"
  grep -q "closed pipe\|Traceback" "$T/mms.err" && tb=$((tb+1))
done
[ $tb -eq 0 ] && ok "mms at the time limit: no traceback from the algorithm (3 runs)" || bad "mms at the time limit: $tb of 3 runs with a traceback: $(head -3 "$T/mms.err")"

# GUIDE-firmware: --time-limit counts on the contest clock, from leaving the start
grep -q 'time-limit` (simulation seconds)' docs/GUIDE-firmware.md && bad "GUIDE-firmware: --time-limit called simulation seconds" \
  || ok "GUIDE-firmware: --time-limit on the contest clock"
grep -q 'contest clock' docs/GUIDE-firmware.md || bad "GUIDE-firmware: no word of the contest clock"

[ $fails -eq 0 ] && echo "cli_flags: all passed" || { echo "cli_flags: $fails failed"; exit 1; }
