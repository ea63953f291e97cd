#!/usr/bin/env bash
# board_folder.sh - our firmware on UKMARSBOT's emulated board over the
# classic folder: every EVERY-th maze in name order (default 4: the whole
# folder is ~5 hours of CPU), one board per maze (`mmsim --batch --board`),
# each contest started by the hand gesture and ended by the firmware's own
# "contest done"; bench/board_folder.py grades the results (reached, no
# front or side contact, the run path proven shortest). Record the output
# in docs/BENCHMARKS.md with the date and machine.
# Usage: bench/board_folder.sh [EVERY] [basic]   (JOBS=N, default nproc)
set -u
B=${B:-build}
EVERY=${1:-4}
SENSORS=${2:-advanced}
DIR=${SHARED:-../shared}/mazes/classic
[ -d "$DIR" ] || { echo "SKIP board_folder: $DIR not found"; exit 0; }
if [ "$SENSORS" = basic ]; then
  make --no-print-directory UKB_SENSOR_BOARD=basic firmware-ukmarsbot || exit 3
  BOARD=ukmarsbot-basic ELF=$B/ukmarsbot-basic/mouse.elf ROBOT=robots/ukmarsbot-basic-12.ini HAND=front
else
  make --no-print-directory firmware-ukmarsbot || exit 3
  BOARD=ukmarsbot ELF=$B/ukmarsbot/mouse.elf ROBOT=robots/ukmarsbot.ini HAND=lfs
fi
make --no-print-directory B="$B" "$B/mmsim" "$B/mmmaze" >/dev/null || exit 3 # the runner, the grader's solver
sample=$(mktemp -d); trap 'rm -rf "$sample"' EXIT
ls "$DIR"/*.txt | sort | awk -v n="$EVERY" '(NR - 1) % n == 0' | while read -r f; do ln -s "$(realpath "$f")" "$sample/"; done
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u '+%Y-%m-%d %H:%M UTC'); every ${EVERY}th maze: $(ls "$sample" | wc -l)"
mkdir -p "$B/bench"
out=$B/bench/board-folder-$SENSORS.jsonl
$B/mmsim --batch "$sample" --jobs "${JOBS:-$(nproc)}" --board $BOARD --avr $ELF --robot $ROBOT \
  --input "0.3 send=r; 1.0 occlude=$HAND; 900 end" --end-on "contest done" --json > "$out"
python3 bench/board_folder.py "$out" --mmmaze $B/mmmaze --table
