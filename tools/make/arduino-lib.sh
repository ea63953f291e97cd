#!/usr/bin/env bash
# arduino-lib.sh DIR PROFILE - the installable Arduino library (copy it to
# ~/Arduino/libraries/) in DIR/Micromouse: hal/arduino plus the HAL
# contract, the wire codec and the firmware with its robot profile
# (PROFILE: the generated robot_profile.h; a build product: never committed).
set -e
lib=$1/Micromouse
rm -rf "$lib"; mkdir -p "$lib/src"
cp -r hal/arduino/library.properties hal/arduino/README.md hal/arduino/examples "$lib/"
cp hal/arduino/src/* hal/hal.h hal/wire/wire.c hal/wire/wire.h "$lib/src/"
cp firmware/*.c firmware/*.h "$2" "$lib/src/"
echo "$lib: copy it to your Arduino libraries folder (see hal/arduino/README.md)"
