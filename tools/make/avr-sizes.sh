#!/usr/bin/env bash
# avr-sizes.sh ELF... - avr-size of the images, then each one's flash
# (Program) and RAM (Data) on the ATmega328P on one line.
avr-size "$@" || exit 1
for e in "$@"; do
  echo "$e: $(avr-size -C --mcu=atmega328p "$e" | grep '^Program:\|^Data:' | tr -s ' ' | paste -sd' ')"
done
