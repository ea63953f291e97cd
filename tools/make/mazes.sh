#!/usr/bin/env bash
# mazes.sh DIR - the micromouseonline maze database cloned into DIR (once).
# Exit 3 when the clone fails.
dir=$1
if [ -d "$dir" ]; then echo "$dir exists"; else
  git clone --depth 1 https://github.com/micromouseonline/mazefiles "$dir" || \
  { echo "make mazes: clone failed (needs internet)" >&2; exit 3; }; fi
