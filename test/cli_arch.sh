#!/usr/bin/env bash
# cli_arch.sh - the architecture's rules (docs/ARCHITECTURE.md, "Include
# rules") hold on this tree, and test/arch_check.py catches each kind of
# break: planted in a copy of the sources, one at a time.
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. test/lib.sh
command -v python3 >/dev/null || { echo "SKIP cli_arch: python3 missing"; exit 77; }

python3 test/arch_check.py >"$T/out" 2>&1 && ok "the tree obeys its rules" || bad "the tree breaks its rules: $(cat "$T/out")"

# plant FILE LINE WANT: a copy of the tree with LINE appended to FILE must
# fail, and the report must name the file and contain WANT.
plant() { local file=$1 line=$2 want=$3
  rm -rf "$T/tree"; mkdir -p "$T/tree"
  cp -r firmware hal sim tools docs "$T/tree/"
  mkdir -p "$(dirname "$T/tree/$file")"; printf '%s\n' "$line" >>"$T/tree/$file"
  python3 test/arch_check.py "$T/tree" >"$T/out" 2>&1; local rc=$?
  if [ $rc -eq 1 ] && grep -qF "$file:" "$T/out" && grep -qF -- "$want" "$T/out"; then ok "planted in $file: $want"
  else bad "planted in $file (exit $rc, want 1 and '$want'): $(cat "$T/out")"; fi; }

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
# the rules' own block is required
rm -rf "$T/tree"; mkdir -p "$T/tree/docs"; echo "# no rules" >"$T/tree/docs/ARCHITECTURE.md"
python3 test/arch_check.py "$T/tree" >"$T/out" 2>&1; [ $? -eq 2 ] && ok "no rules block: exit 2" || bad "no rules block: $(cat "$T/out")"
exit $((fails > 0))
