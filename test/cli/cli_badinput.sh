#!/usr/bin/env bash
# cli_badinput.sh - bad input files: a FIFO, /dev/zero or a
# directory as maze, config, log or batch entry; a crafted LCM log whose
# event declares 2 GB of data; config lines too long for libinih. Each is
# exit 2 with one error line, under a `timeout` guard so a hang fails
# (exit 124) instead of stalling the suite.
set -u
S=${MMSIM:-build/mmsim}
Z=${MMMAZE:-build/mmmaze}
L=${MMLOG:-build/mmlog}
V=${MMVIEW:-build/mmview}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/lib.sh"
ONE_ERROR_LINE=1
G="timeout 20"   # seconds: far above any run here, far below a hang's stall
says() { grep -q -- "$2" "$T/err" && ok "$1: says '$2'" || bad "$1: want '$2', got: $(cat "$T/err")"; }
M=mazes/gen-5x5-s1.txt

mkfifo "$T/fifo.txt" "$T/fifo.ini" "$T/fifo.lcmlog"
mkdir "$T/dir.txt"
for f in "$T/fifo.txt" /dev/zero "$T/dir.txt"; do
  want_rc 2 "mmsim --maze $f" $G "$S" --maze "$f"; says "mmsim --maze $f" "not a regular file"
  want_rc 2 "mmmaze check $f" $G "$Z" check "$f"; says "mmmaze check $f" "not a regular file"
done
for f in "$T/fifo.ini" /dev/zero "$T/dir.txt"; do
  want_rc 2 "mmsim --config $f" $G "$S" --maze $M --config "$f"; says "mmsim --config $f" "not a regular file"
done
for f in "$T/fifo.lcmlog" /dev/zero "$T/dir.txt"; do
  want_rc 2 "mmlog $f" $G "$L" "$f"; says "mmlog $f" "not a regular file"
  want_rc 2 "mmview $f" $G "$V" "$f"; says "mmview $f" "not a regular file"
done
# an AVR image (--avr) the same way: bad input, exit 2, as any image mmsim cannot use (cli_pil.sh)
mkfifo "$T/fifo.elf"
want_rc 2 "mmsim --avr FIFO" $G "$S" --maze $M --avr "$T/fifo.elf"; says "mmsim --avr FIFO" "fifo.elf: not a regular file (a FIFO)"
# a maze on a pipe through stdin is still read (bounded by the maze size limit)
want_rc 0 "mmmaze check from a pipe" $G bash -c "cat $M | $Z check -"

# a FIFO (or a directory) named *.txt in a batch folder: the batch is refused
# before any job starts
mkdir "$T/batch"; cp $M "$T/batch/a.txt"; mkfifo "$T/batch/b.txt"
want_rc 2 "mmsim --batch with a FIFO" $G "$S" --batch "$T/batch" --runs 1
says "mmsim --batch with a FIFO" "b.txt: not a regular file (a FIFO)"
want_rc 2 "mmmaze explore --all with a FIFO" $G "$Z" explore --all "$T/batch"
rm "$T/batch/b.txt"; mkdir "$T/batch/c.txt"
want_rc 2 "mmsim --batch with a directory" $G "$S" --batch "$T/batch" --runs 1
says "mmsim --batch with a directory" "c.txt: not a regular file (a directory)"

# config lines: libinih splits a line at 199 bytes; a longer one is an error
# (a comment's tail set a key, and later line numbers were off)
python3 -c "print(';' + 'x' * 200 + ' step_s = 0.0015')" >"$T/long.ini"
want_rc 2 "a 217-byte comment line" $G "$S" --maze $M --config "$T/long.ini" --print-config
says "a 217-byte comment line" "long.ini:1: line too long (217 bytes; at most 197)"
python3 -c "print('[sim]'); print(';' + 'x' * 196); print('bogus = 1')" >"$T/edge.ini"
want_rc 2 "a 197-byte line is read whole" $G "$S" --maze $M --config "$T/edge.ini"
says "a 197-byte line is read whole" "edge.ini:3: sim.bogus: unknown key"
printf '[sim]\nstep_s = 0.001\0\n' >"$T/nul.ini"
want_rc 2 "a NUL byte in a config" $G "$S" --maze $M --config "$T/nul.ini"
says "a NUL byte in a config" "nul.ini:2: NUL byte"
head -c 1048577 /dev/zero | tr '\0' '\n' >"$T/big.ini"
want_rc 2 "a config over 1 MiB" $G "$S" --maze $M --config "$T/big.ini"
says "a config over 1 MiB" "big.ini: too large (1048577 bytes; at most 1048576)"
# an indented line (libinih hands it over as the key above's value again), a
# key given twice, and the tick that is HAL_TICK_HZ, not a key
printf '[sim]\ntime_limit_s = 7\n  1999\n' >"$T/cont.ini"
want_rc 2 "a config's indented continuation line" $G "$S" --maze $M --config "$T/cont.ini"
says "a config's indented continuation line" "^$T/cont.ini:3: sim.time_limit_s: an indented line continues its value"
printf '[sim]\ntime_limit_s = 7\n[world]\ncell_m = 0.18\n[sim]\ntime_limit_s = 8\n' >"$T/twice.ini"
want_rc 2 "a config's key given twice" $G "$S" --maze $M --config "$T/twice.ini"
says "a config's key given twice" "^$T/twice.ini:6: sim.time_limit_s: given twice (first on line 2)$"
printf '[sim]\ncontrol_hz = 1000\n' >"$T/tick.ini"
want_rc 2 "[sim] control_hz" $G "$S" --maze $M --config "$T/tick.ini"
says "[sim] control_hz" "^$T/tick.ini:2: sim.control_hz: unknown key$"
# robot files (--robot) the same way: the regular-file reader and the line scan
for f in "$T/fifo.ini" /dev/zero "$T/dir.txt"; do
  want_rc 2 "mmsim --robot $f" $G "$S" --maze $M --robot "$f"; says "mmsim --robot $f" "not a regular file"
done
{ sed -n '1,/^\[chassis/p' robots/paper.ini; python3 -c "print(';' + 'x' * 200 + ' body_w_mm = 50')"; sed '1,/^\[chassis/d' robots/paper.ini; } >"$T/long-robot.ini"
n=$(grep -n '^;xxx' "$T/long-robot.ini" | cut -d: -f1)
want_rc 2 "a 216-byte line in a robot file" $G "$S" --maze $M --robot "$T/long-robot.ini"
says "a 216-byte line in a robot file" "long-robot.ini:$n: line too long (216 bytes; at most 197)"
{ cat robots/paper.ini; printf '[gyro.g]\nx_mm = 0\0\n'; } >"$T/nul-robot.ini"
want_rc 2 "a NUL byte in a robot file" $G "$S" --maze $M --robot "$T/nul-robot.ini"
says "a NUL byte in a robot file" "nul-robot.ini:$(( $(wc -l <robots/paper.ini) + 2 )): NUL byte"
head -c 1048577 /dev/zero | tr '\0' '\n' >"$T/big-robot.ini"
want_rc 2 "a robot file over 1 MiB" $G "$S" --maze $M --robot "$T/big-robot.ini"
says "a robot file over 1 MiB" "big-robot.ini: too large (1048577 bytes; at most 1048576)"

# a crafted LCM log: its one event declares 0x7FFFFFFF bytes of data (liblcm's
# reader calloc'd that and segfaulted)
python3 -c "import struct,sys;sys.stdout.buffer.write(struct.pack('>IQQII',0xEDA1DA01,0,0,7,0x7FFFFFFF)+b'MM_MAZE'+b'x'*100)" >"$T/bad.lcmlog"
for t in "$L" "$V"; do
  want_rc 2 "$(basename "$t") on a 2 GB data length" $G "$t" "$T/bad.lcmlog"
  says "$(basename "$t") on a 2 GB data length" "bad.lcmlog: event 1 at byte 0: corrupt: data length 2147483647 bytes"
done
# a good log, then an event whose data runs past the end of the file
want_rc 1 "a 2 s logged contest (time limit: exit 1)" $G "$S" --maze $M --driver scripted --time-limit 2 --lcm-log "$T/good.lcmlog"
n=$(stat -c %s "$T/good.lcmlog")
{ cat "$T/good.lcmlog"; python3 -c "import struct,sys;sys.stdout.buffer.write(struct.pack('>IQQII',0xEDA1DA01,9,0,7,1000)+b'MM_POSE'+b'y'*10)"; } >"$T/tail.lcmlog"
want_rc 2 "mmlog on a log whose last event runs past its end" $G "$L" "$T/tail.lcmlog"
says "mmlog on a log whose last event runs past its end" "tail.lcmlog: event [0-9]* at byte $n: truncated: 1007 bytes of channel and data declared, 17 left in the file"
grep -q '^MM_POSE ' "$T/out" && ok "summary of the events before it" || bad "no summary before the bad event: $(cat "$T/out")"
[ $fails -eq 0 ]
