#!/usr/bin/env bash
# ukb-stack.sh MMSIM ELF BOARD ROBOT OUT - the stack's headroom of a
# UKMARSBOT image measured at the deepest point of a contest: ELF on its
# emulated board searches mazes/gen-16x16-s1.txt, returns and makes its
# three speed runs; its `k` command then reports the painted RAM never
# written (hal/ukmarsbot: the stack paint), in bytes, into OUT.
# Exit 3 when mmsim fails; non-zero with no OUT when there is no report.
mmsim=$1 elf=$2 board=$3 robot=$4 out=$5
"$mmsim" --board "$board" --avr "$elf" --robot "$robot" --maze mazes/gen-16x16-s1.txt \
  --input "0.3 send=g; 240 send=k; 241 end" --json > "$out.json"; rc=$?
[ $rc -le 1 ] || { rm -f "$out.json"; exit 3; }
python3 -c 'import json, sys; \
c = json.loads(open(sys.argv[1]).read().splitlines()[-1])["console"].replace("\r", ""); \
k = [l for l in c.splitlines() if l.startswith("stack unused")]; \
k or sys.exit("ukmarsbot: no stack report in the console (the k command)"); \
print(k[-1].split(",")[0].split()[-2])' "$out.json" > "$out.tmp" && mv "$out.tmp" "$out"; rc=$?
rm -f "$out.json" "$out.tmp"; exit $rc
