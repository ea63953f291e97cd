#!/usr/bin/env bash
# ukb-size.sh ELF FLASH_MAX STACK_FILE - a UKMARSBOT image's flash (limit
# FLASH_MAX: the Nano's 32 KB less its 2 KB bootloader), static RAM and the
# stack headroom measured by ukb-stack.sh. Exit 1 when the flash is over.
elf=$1 max=$2 stack=$3
avr-size "$elf" | awk -v max="$max" -v stack="$(cat "$stack")" 'NR == 2 { f = $1 + $2; r = $2 + $3; \
  printf "ukmarsbot: flash %d B of %d, static RAM %d B of 2048 (%d B left for the stack)\n", f, max, r, 2048 - r; \
  printf "ukmarsbot: stack headroom %d B: RAM never written during a contest on mazes/gen-16x16-s1.txt (measured on the emulated board)\n", stack; \
  if (f > max) { print "ukmarsbot: flash over the limit"; exit 1 } }'
