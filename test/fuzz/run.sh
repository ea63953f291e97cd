#!/usr/bin/env bash
# run.sh DIR SECONDS NAME:MAX_LEN... - each fuzzer DIR/fuzz_NAME in turn for
# SECONDS on its corpus DIR/corpus_NAME, inputs up to MAX_LEN bytes;
# findings (crash-*, leak-*) land in DIR. Exit 1 at the first finding.
cd "$1" || exit 3
secs=$2; shift 2
for t in "$@"; do
  ./fuzz_${t%%:*} -max_total_time="$secs" -max_len="${t#*:}" -malloc_limit_mb=512 "corpus_${t%%:*}" || exit 1
done
