#!/usr/bin/env bash
# arduino-lib.sh DIR - the installable Arduino library (copy it to
# ~/Arduino/libraries/) in DIR/Micromouse: hal/arduino plus the HAL
# contract, the wire codec and the firmware (a build product: never committed).
set -e
lib=$1/Micromouse
rm -rf "$lib"; mkdir -p "$lib/src"
cp -r hal/arduino/library.properties hal/arduino/README.md hal/arduino/examples "$lib/"
cp hal/arduino/src/* hal/hal.h hal/wire/wire.c hal/wire/wire.h "$lib/src/"
cp firmware/*.c firmware/*.h "$lib/src/"
echo "$lib: copy it to your Arduino libraries folder (see hal/arduino/README.md)"
