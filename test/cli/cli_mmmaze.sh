#!/usr/bin/env bash
# cli_mmmaze.sh - the mmmaze command line: outputs, JSON keys, exit codes,
# one-line errors. MMMAZE names the binary (make test passes the sanitized one).
set -u
M=${MMMAZE:-build/mmmaze}
DB=${SHARED:-../shared}/mazes
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
json() { python3 -c "import json,sys; d=json.load(open('$T/out')); print($1)"; }

# gen: deterministic, valid, different seeds differ
want_rc 0 "gen 8x8" "$M" gen --size 8 --seed 7; cp "$T/out" "$T/a.txt"
"$M" gen --size 8 --seed 7 >"$T/b.txt"; cmp -s "$T/a.txt" "$T/b.txt" && ok "gen deterministic" || bad "gen deterministic"
"$M" gen --size 8 --seed 8 >"$T/c.txt"; cmp -s "$T/a.txt" "$T/c.txt" && bad "seeds differ" || ok "seeds differ"
want_rc 0 "check generated" "$M" check "$T/a.txt"
grep -q '8x8, start (0,0) N, goal (3,3)-(4,4) 4 cells' "$T/out" && ok "check line" || bad "check line: $(cat "$T/out")"
want_rc 0 "gen 5x9" "$M" gen --width 5 --height 9 --seed 1
[ "$(wc -l <"$T/out")" -eq 19 ] && ok "5x9 has 19 lines" || bad "5x9 lines"

# bad flags: exit 2, one line on stderr, nothing on stdout
for args in "gen --size 3" "gen --size 33" "gen --size x" "gen --size 8 --seed -1" "gen" "frobnicate" "solve" "explore --bogus f" \
  "gen --size 0x10" "gen --size +8" "gen --size ' 8'" "gen --width 8 --height 0x8" "gen --size 8 --seed ' 1'" "gen --size 8 --seed 0x1"; do
  eval "set -- $args"
  want_rc 2 "bad args: $args" "$M" "$@"
  [ "$(wc -l <"$T/err")" -eq 1 ] && ok "one error line: $args" || bad "one error line: $args: $(cat "$T/err")"
  [ -s "$T/out" ] && bad "stdout empty: $args" || ok "stdout empty: $args"
done

# malformed file: FILE:LINE:COL
printf 'o---o\n|   |\no---x\n' >"$T/bad.txt"
want_rc 2 "check malformed" "$M" check "$T/bad.txt"
grep -q "^$T/bad.txt:3:5: " "$T/err" && ok "error has line:col" || bad "error has line:col: $(cat "$T/err")"
want_rc 2 "missing file" "$M" check "$T/none.txt"
grep -q "none.txt: cannot open" "$T/err" && ok "cannot open message" || bad "cannot open message: $(cat "$T/err")"
want_rc 2 "solve malformed" "$M" solve --json "$T/bad.txt"

# solve / show / explore on a small generated maze
"$M" gen --size 6 --seed 3 >"$T/m6.txt"
want_rc 0 "solve json" "$M" solve --json "$T/m6.txt"
[ "$(json "sorted(d.keys())")" = "['cells', 'cost', 'goal_reachable', 'min_cells', 'path', 'turns']" ] && ok "solve keys" || bad "solve keys"
[ "$(json "d['cost'] == d['cells'] + d['turns'] and d['path'][0] == [0,0] and len(d['path']) == d['cells'] + 1")" = True ] && ok "solve consistent" || bad "solve consistent"
want_rc 0 "show --path" "$M" show --path "$T/m6.txt"
grep -q '\*' "$T/out" && ok "path drawn" || bad "path drawn"
want_rc 0 "explore json" "$M" explore --json "$T/m6.txt"
for k in steps steps_forward steps_left steps_right steps_back cells_visited proven_at_step final_path_optimal goal_reachable; do
  [ "$(json "'$k' in d")" = True ] || bad "explore key $k"
done
[ "$(json "d['final_path_optimal'] and d['goal_reachable'] and d['steps'] == d['steps_forward']+d['steps_left']+d['steps_right']+d['steps_back']")" = True ] && ok "explore result" || bad "explore result"
want_rc 0 "explore --all mazes/" "$M" explore --all mazes
grep -q 'final path not the true shortest: 0' "$T/out" && ok "all optimal" || bad "all optimal: $(cat "$T/out")"

# mms numeric round trip through the parser: a 2x2 file
printf '0 0 0 0 1 1\n0 1 1 0 0 1\n1 0 0 1 1 0\n1 1 1 1 0 0\n' >"$T/mms.txt"
want_rc 0 "mms numeric check" "$M" check "$T/mms.txt"

if [ -d "$DB" ]; then
  want_rc 0 "solve japan2018" "$M" solve --json "$DB/classic/japan2018.txt"
  [ "$(json "(d['cost'], d['cells'], d['turns'], d['min_cells'])")" = "(108, 86, 22, 84)" ] && ok "japan2018 108/86/22" || bad "japan2018: $(cat "$T/out")"
  want_rc 1 "solve unreachable" "$M" solve --json "$DB/classic/001.txt"
  [ "$(json "d['goal_reachable']")" = False ] && ok "unreachable flagged" || bad "unreachable flagged"
  want_rc 0 "check unreachable warns" "$M" check "$DB/classic/001.txt"
  grep -q 'warning: goal unreachable' "$T/err" && ok "warning line" || bad "warning line"
  want_rc 2 "check --strict unreachable" "$M" check --strict "$DB/classic/001.txt"
  want_rc 1 "explore unreachable" "$M" explore --json "$DB/classic/001.txt"
  [ "$(json "(d['goal_reachable'], d['proven_at_step'])")" = "(False, None)" ] && ok "explore unreachable json" || bad "explore unreachable json"
  want_rc 0 "check CRLF file" "$M" check "$DB/classic/br2025-robochallenge-day1.txt"
else
  echo "SKIP cli_mmmaze database part: $DB not found"
fi
[ $fails -eq 0 ]
