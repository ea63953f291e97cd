#!/usr/bin/env bash
# cli_arch.sh - the architecture's rules (docs/ARCHITECTURE.md, "Include
# rules") hold on this tree, and test/tools/arch_check.py catches each kind of
# break: planted in a copy of the sources, one at a time.
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/cli/lib.sh
command -v python3 >/dev/null || { echo "SKIP cli_arch: python3 missing"; exit 77; }

python3 test/tools/arch_check.py >"$T/out" 2>&1 && ok "the tree obeys its rules" || bad "the tree breaks its rules: $(cat "$T/out")"

# copy: a fresh copy of the sources in $T/tree. add FILE LINE: LINE
# appended to FILE in it. run: arch_check on it, its output in $T/out.
copy() { rm -rf "$T/tree"; mkdir -p "$T/tree"; cp -r firmware hal sim tools docs "$T/tree/"; }
add() { mkdir -p "$(dirname "$T/tree/$1")"; printf '%s\n' "$2" >>"$T/tree/$1"; }
run() { python3 test/tools/arch_check.py "$T/tree" >"$T/out" 2>&1; }
# The report of the unchanged copy: a planted line that is no break must
# leave it as it is (the tree may hold breaks that other work removes).
copy; run; cp "$T/out" "$T/base"

# plant FILE LINE WANT [FILE2 LINE2]: a copy of the tree with LINE appended
# to FILE (and LINE2 to FILE2) must fail with a new line in the report that
# names FILE (and FILE2) and contains WANT.
plant() { local file=$1 line=$2 want=$3 file2=${4:-} line2=${5:-}
  copy; add "$file" "$line"; [ -n "$file2" ] && add "$file2" "$line2"
  run; local rc=$?
  grep -vxFf "$T/base" "$T/out" | grep -F "$file" | grep -F "${file2:-$file}" >"$T/new"
  if [ $rc -eq 1 ] && grep -qF "$file:" "$T/new" && grep -qF -- "$want" "$T/new"; then ok "planted in $file${file2:+ and $file2}: $want"
  else bad "planted in $file${file2:+ and $file2} (exit $rc, want 1 and '$want'): $(cat "$T/out")"; fi; }
# harmless WHAT FILE LINE [FILE2 LINE2]: planted lines that break no rule
# leave the report as it was.
harmless() { local what=$1 file=$2 line=$3 file2=${4:-} line2=${5:-}
  copy; add "$file" "$line"; [ -n "$file2" ] && add "$file2" "$line2"
  run
  if cmp -s "$T/out" "$T/base"; then ok "no break: $what"; else bad "no break: $what: $(diff "$T/base" "$T/out")"; fi; }

plant firmware/maze.c '#include "world/sim.h"' "firmware may not include sim/world/sim.h"
plant firmware/flood.c '#include <ode/ode.h>' "firmware may not include <ode/ode.h> (library ode)"
plant firmware/explore.c '#include <unistd.h>' "firmware may not include <unistd.h> (system header)"
plant hal/wire/wire.c '#include "world/config.h"' "hal/wire may not include sim/world/config.h"
plant sim/world/world.c '#include "view/view.h"' "sim/world may not include sim/view/view.h"
plant sim/world/motor.c '#include "telemetry/telem.h"' "sim/world may not include sim/telemetry/telem.h"
plant sim/world/sensors/tof.c '#include "link/link.h"' "sim/world may not include sim/link/link.h"
plant sim/world/encoder.c '#include "mms/mms.h"' "sim/world may not include sim/mms/mms.h"
plant sim/world/race.c '#include "board/pil.h"' "sim/world may not include sim/board/pil.h"
plant sim/link/serial.c '#include "board/pil.h"' "sim/link may not include sim/board/pil.h"
plant sim/view/hud.c '#include "cli.h"' "sim/view may not include tools/cli.h"
plant sim/maze/solve.c '#include <GL/gl.h>' "sim/maze may not include <GL/gl.h> (library gl)"
plant sim/maze/solve.c '#include "no_such_header.h"' '"no_such_header.h" not found in the tree'
long=$(printf 'static int planted_long(void)\n{\n    int a = 0;\n'; for i in $(seq 80); do printf '    a += %d;\n' "$i"; done; printf '    return a;\n}\n')
plant sim/contest/run.c "$long" "function planted_long is 85 lines (at most 80)"
plant tools/mmsim.c "$long" "function planted_long is 85 lines (at most 80)"
# the 80-line rule in every product folder (hal/arduino's C++ too)
plant firmware/mouse.c "$long" "function planted_long is 85 lines (at most 80)"
plant hal/wire/wire.c "$long" "function planted_long is 85 lines (at most 80)"
plant hal/sim/hal_sim.c "$long" "function planted_long is 85 lines (at most 80)"
plant hal/arduino/src/MMLink.cpp "$long" "function planted_long is 85 lines (at most 80)"
plant sim/world/world.c "$long" "function planted_long is 85 lines (at most 80)"
plant sim/board/board_adc.c "$long" "function planted_long is 85 lines (at most 80)"
plant sim/view/hud.c "$long" "function planted_long is 85 lines (at most 80)"
plant sim/mms/mms.c "$long" "function planted_long is 85 lines (at most 80)"
plant tools/mmlog.c "$long" "function planted_long is 85 lines (at most 80)"
harmless "an 80-line function" sim/maze/solve.c "$(printf '%s\n' "$long" | sed '3,7d')"
# more include arrows
plant hal/sim/hal_sim.c '#include "view/view.h"' "hal/sim may not include sim/view/view.h"
plant sim/board/board_adc.c '#include "view/hud.h"' "sim/board may not include sim/view/hud.h"
plant sim/board/board_motor.c '#include <GL/gl.h>' "sim/board may not include <GL/gl.h> (library gl)"
plant sim/board/board_motor.c '#include <unicorn/unicorn.h>' "sim/board may not include <unicorn/unicorn.h> (library unicorn)"
plant sim/arm/armcore.c '#include "board/board.h"' "sim/arm may not include sim/board/board.h"
plant sim/arm/cortexm.c '#include <simavr/sim_avr.h>' "sim/arm may not include <simavr/sim_avr.h> (library simavr)"
plant sim/io/infile.c '#include "world/sim.h"' "sim/io may not include sim/world/sim.h"
# the observers read the run's state, never the in-process backend's globals
plant sim/telemetry/telem.c '#include "hal_sim.h"' "sim/telemetry may not include hal/sim/hal_sim.h"
plant sim/view/view.c '#include "hal_sim.h"' "sim/view may not include hal/sim/hal_sim.h"
# no two files that call each other: two sources; a header's static inline
# (a source and its own header are one unit); a macro's body
plant sim/maze/grid.c 'int planted_a(void) { return mazegen_generate(0, 1, 1, 1); }' \
  "the two files call each other" sim/maze/mazegen.c 'int planted_b(void) { return grid_explore(0, 0); }'
plant firmware/maze.h 'static inline int planted_m(flood_t *f) { return flood_is_target(f, 0); }' \
  "the two files call each other" firmware/flood.c 'int planted_f(void) { return maze_init(0, 1, 1); }'
plant sim/io/outfile.h '#define PLANTED_OPEN(p) infile_planted(p)' \
  "the two files call each other" sim/io/infile.c 'int infile_planted(const char *p) { return outfile_probe(p, 0, 0); }'
# ... and what is no such call: one way only; a mention in a comment or a
# string; a file's own static function of the same name; a member; the
# firmware and its backend calling each other through hal/hal.h
harmless "one file calls the other" sim/maze/grid.c 'int planted_a(void) { return mazegen_generate(0, 1, 1, 1); }'
harmless "a call in a comment or a string" sim/maze/grid.c 'int planted_a(void) { return mazegen_generate(0, 1, 1, 1); }' \
  sim/maze/mazegen.c 'const char *planted_b(void) { /* grid_explore(a, b) */ return "grid_explore(a, b)"; } // grid_sense()'
harmless "a static function of the same name" sim/maze/grid.c 'int planted_a(void) { return mazegen_generate(0, 1, 1, 1); }' \
  sim/maze/mazegen.c 'static int grid_explore(int a) { return a; } int planted_b(void) { return grid_explore(1); }'
harmless "a member of the same name" sim/maze/grid.c 'int planted_a(void) { return mazegen_generate(0, 1, 1, 1); }' \
  sim/maze/mazegen.c 'struct pl { int (*grid_explore)(void); }; int planted_b(struct pl *p) { return p->grid_explore() + (*p).grid_explore(); }'
harmless "the HAL contract both ways" hal/sim/hal_sim.c 'void planted_tick(void) { fw_tick(); }'
# the rules' own block is required, and readable
rm -rf "$T/tree"; mkdir -p "$T/tree/docs"; echo "# no rules" >"$T/tree/docs/ARCHITECTURE.md"
python3 test/tools/arch_check.py "$T/tree" >"$T/out" 2>&1; [ $? -eq 2 ] && ok "no rules block: exit 2" || bad "no rules block: $(cat "$T/out")"
copy; sed -i 's/^max-function-lines 80:/max-function-lines eighty:/' "$T/tree/docs/ARCHITECTURE.md"
run; [ $? -eq 2 ] && grep -qF "want 'max-function-lines N: FOLDER...'" "$T/out" && ok "a bad max-function-lines line: exit 2" ||
  bad "a bad max-function-lines line: $(cat "$T/out")"
exit $((fails > 0))
