#!/usr/bin/env bash
# build-bulebule.sh SRC DEST: Bulebots' bulebule (STM32F103, libopencm3),
# unmodified, built in a copy as ../shared/clients/README.md says: libopencm3's
# stm32/f1 target, then the firmware with newlib-nano (the full newlib
# overflows its 63 KB flash region). Files libopencm3 keeps in git but the
# snapshot lost are taken from tools/opencm3-compat only where missing.
# Exit 3 with one line when the source or a tool is missing or the build fails.
set -u
src=$1 dest=$2
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "build-bulebule: $*" >&2; exit 3; }
[ -d "$src/src" ] || fail "$src: missing (../shared/clients)"
command -v arm-none-eabi-gcc >/dev/null || fail "arm-none-eabi-gcc: not installed (make deps)"
command -v python3 >/dev/null || fail "python3: not installed (libopencm3's irq2nvic_h needs it)"
rm -rf "$dest" && mkdir -p "$(dirname "$dest")" && cp -r "$src" "$dest" && chmod -R u+w "$dest" || fail "$dest: cannot copy"
dest=$(cd "$dest" && pwd)   # libopencm3's SRCLIBDIR must be absolute
ocm=$dest/src/opencm3/libopencm3
(cd "$here/opencm3-compat" && find include lib -type f) | while read -r f; do
    [ -e "$ocm/$f" ] || { mkdir -p "$(dirname "$ocm/$f")" && cp "$here/opencm3-compat/$f" "$ocm/$f"; } || exit 1
done || fail "$ocm: cannot complete libopencm3"
# bulebule's .gitignore drops the rules file its Makefile includes (its users
# fetch it from libopencm3-examples): ours where it is missing
rules=$dest/src/opencm3/libopencm3.rules.mk
[ -e "$rules" ] || cp "$here/opencm3-compat/libopencm3.rules.mk" "$rules" || fail "$rules: cannot copy"
# irq2nvic_h's shebang is `python`, which Debian 12 leaves to python-is-python3
mkdir -p "$dest/.bin" && ln -sf "$(command -v python3)" "$dest/.bin/python"
export PATH=$dest/.bin:$PATH
log=$dest/build.log
make -s -C "$ocm" TARGETS=stm32/f1 SRCLIBDIR="$ocm/lib" >"$log" 2>&1 \
    || fail "libopencm3 stm32/f1 failed: $(grep -m1 -i error "$log" || tail -n1 "$log")"
make -s -C "$dest/src" LDFLAGS="-L./ -Lopencm3/libopencm3/lib --specs=nano.specs" >>"$log" 2>&1 \
    || fail "bulebule failed: $(grep -m1 -i error "$log" || tail -n1 "$log")"
arm-none-eabi-size "$dest/src/main.elf"
