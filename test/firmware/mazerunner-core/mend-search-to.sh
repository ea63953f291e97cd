#!/usr/bin/env bash
# mend-search-to.sh FROM TO - for tests only, never shipped: a copy in TO
# of the mazerunner-core sketch folder FROM (the -uk copy) with one firmware
# bug mended in mouse.h. search_to() checks heading_to_smallest() for
# BLOCKED before it checks for the target, and the target's cost is 0 with
# no smaller neighbour, so every search panics "ERR: no route to target" on
# entering its target (the simulator shows it). The mend: that check only
# short of the target, so the rest of the search (home, the map) can be
# tested (test/cli/cli_mazerunner_search.sh). A statement, not a setting:
# no -D or header of ours can change it, so this one copy is edited.
# Exit 1 when mouse.h has no such check (a newer mazerunner-core).
from=$1 to=$2
rm -rf "$to"; mkdir -p "$to"; cp "$from"/*.h "$from"/*.ino "$to"/
sed -i 's/^\( *\)if (newHeading == BLOCKED) {/\1if (newHeading == BLOCKED \&\& m_location != target) {/' "$to/mouse.h"
grep -q 'newHeading == BLOCKED && m_location != target' "$to/mouse.h" \
  || { echo "client-mazerunner: search_to's BLOCKED check not found in mouse.h" >&2; exit 1; }
