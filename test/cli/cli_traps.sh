#!/usr/bin/env bash
# cli_traps.sh - the mistakes a newcomer makes get one line that says what
# to do: a report or screenshot named for a format it does not write, a
# viewer with no display; a batch talks as a log (no progress line when
# stderr is not a terminal) and always ends with a summary line; --help
# lists every board flag; make sim and make test build every tool, make help
# lists the targets.
set -u
S=${MMSIM:-build/mmsim}
V=${MMVIEW:-build/mmview}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
ONE_ERROR_LINE=1
M=mazes/gen-5x5-s1.txt

# ---- outputs named for another format: refused before the run, nothing written
want_rc 2 "--report r.jpg" "$S" --maze $M --driver scripted --runs 1 --report "$T/r.jpg"
grep -qF -- "--report $T/r.jpg: it writes a PNG: give a name ending in .png" "$T/err" && [ ! -e "$T/r.jpg" ] \
  && ok "--report r.jpg: says the format, writes nothing" || bad "--report r.jpg: $(cat "$T/err")"
want_rc 2 "--screenshot s.jpeg" "$S" --maze $M --driver scripted --runs 1 --screenshot "$T/s.jpeg"
grep -qF "give a name ending in .png" "$T/err" && ok "--screenshot s.jpeg: says the format" || bad "--screenshot: $(cat "$T/err")"
want_rc 0 "--report R.PNG (any case)" "$S" --maze $M --driver scripted --runs 1 --report "$T/R.PNG"

# ---- no display: the hint names xvfb-run
for prog in mmsim mmview; do
  if [ $prog = mmsim ]; then cmd=("$S" --maze $M --driver scripted --runs 1 --gui)
  else "$S" --maze $M --driver scripted --runs 1 --lcm-log "$T/run.lcm" >/dev/null 2>&1; cmd=("$V" "$T/run.lcm"); fi
  want_rc 3 "$prog with no display: exit 3" env -u DISPLAY -u WAYLAND_DISPLAY "${cmd[@]}"
  grep -qF "xvfb-run -a" "$T/err" && ok "$prog with no display: suggests xvfb-run -a" || bad "$prog no display: $(cat "$T/err")"
done

# ---- a batch with stderr not a terminal: no progress line, one summary line
ONE_ERROR_LINE=0
mkdir "$T/b"; for i in 1 2 3; do cp $M "$T/b/m$i.txt"; done; printf 'not a maze\n' >"$T/b/m4.txt"
"$S" --batch "$T/b" --jobs 2 --runs 1 --driver scripted >"$T/out" 2>"$T/err"
if grep -q $'\r' "$T/err"; then bad "batch: a progress line with stderr not a terminal"; else ok "batch: no progress line in a log"; fi
grep -qxF "mmsim: --batch $T/b: 4 of 4 mazes run: 3 reached the goal, 0 did not, 1 bad input, 0 failed" "$T/err" \
  && ok "batch: the summary line counts each outcome" || bad "batch summary: $(cat "$T/err")"
[ "$(grep -c '^{' "$T/out")" = 4 ] && ok "batch: one JSON line a maze" || bad "batch: $(wc -l <"$T/out") lines"

# ---- --config -: a config on standard input, as mmmaze takes a maze
"$S" --print-config >"$T/cfg.ini"
want_rc 0 "--config - (stdin)" "$S" --config - --maze $M --driver scripted --runs 1 --json <"$T/cfg.ini"
cp "$T/out" "$T/stdin.json"
want_rc 0 "--config FILE (the same)" "$S" --config "$T/cfg.ini" --maze $M --driver scripted --runs 1 --json
[ "$(strip "$T/stdin.json")" = "$(strip "$T/out")" ] && ok "--config -: the same run as the file" || bad "--config -: runs differ"
ONE_ERROR_LINE=1
printf '[world]\nbogus = 1\n' >"$T/bad.ini"
want_rc 2 "--config - with a bad key" "$S" --config - --maze $M --driver scripted --runs 1 <"$T/bad.ini"
grep -qxF "<stdin>:2: world.bogus: unknown key" "$T/err" && ok "--config -: <stdin>:LINE in the error" || bad "--config - error: $(cat "$T/err")"
want_rc 2 "--config - with --maze -" "$S" --config - --maze - </dev/null
ONE_ERROR_LINE=0

# ---- --help lists the board's flags
"$S" --help >"$T/help" 2>&1
for f in "--config FILE|-" "--console pty" "--eeprom FILE" "--watch NAME" "--gdb PORT" "--input"; do
  grep -qF -- "$f" "$T/help" && ok "--help: $f" || bad "--help lacks $f"
done

# ---- make sim and make test build every tool the README uses; make help fits a screen
for tgt in sim-run test-run; do
  got=$(env -u MAKEFLAGS -u MAKELEVEL make -n --no-print-directory $tgt B="$T/nb" 2>/dev/null | grep -o -- "-o $T/nb/mm[a-z]*" | sort -u | wc -l)
  [ "$got" = 4 ] && ok "make ${tgt%-run} builds mmsim, mmmaze, mmlog and mmview" || bad "make ${tgt%-run} builds $got of the 4 tools"
done
env -u MAKEFLAGS -u MAKELEVEL make --no-print-directory help >"$T/help.txt" 2>&1 && [ "$(wc -l <"$T/help.txt")" -le 24 ] && grep -q "^make sim " "$T/help.txt" \
  && ok "make help: $(wc -l <"$T/help.txt") lines" || bad "make help: $(head -3 "$T/help.txt")"

[ $fails -eq 0 ] && echo "cli_traps: all passed" || { echo "cli_traps: $fails failed"; exit 1; }
