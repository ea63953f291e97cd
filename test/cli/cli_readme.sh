#!/usr/bin/env bash
# cli_readme.sh - README.md's quick start holds what it promises: it is at
# most 40 lines (from the top to the first `## ` section after
# `## Quick start`); every command in it (the indented lines that start with
# build/, make, cp or xvfb-run, with their `\` continuations) runs as written
# verbatim and exits as documented (0, or 1 for a run its --time-limit
# cut short before the goal); `make test`,
# `make sim` and GUI-only commands are not run. Every docs/*.md link and
# every picture in README.md exists; every link of README, the guides and
# REFERENCE.md leads to a file and section that exist.
# The commands run in a scratch folder holding links to the tree's folders
# (so what they write stays there); `../shared` is $SHARED (the maze
# database and mazerunner-core's clone). MMSIM, MMMAZE, MMLOG and MMVIEW
# replace build/mmsim... when set (make test: the sanitized tools); the
# viewer commands under xvfb-run keep build/'s plain tools.
set -u
cd "$(dirname "$0")/../.."
ROOT=$PWD
B=${BUILD:-build}
SHARED=${SHARED:-../shared}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
. test/cli/lib.sh
abs() { case $1 in /*) echo "$1" ;; *) echo "$ROOT/$1" ;; esac; }
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -C "$ROOT" --no-print-directory B="$B" "$@"; }

# ---- the quick start's length
qs_end=$(awk '/^## Quick start/ { q = 1; next } q && /^## / { print NR - 1; exit }' README.md)
[ -n "$qs_end" ] || { bad "README.md: no '## Quick start' followed by a '## ' section"; qs_end=9999; }
[ "$qs_end" -le 40 ] && ok "quick start: $qs_end lines (at most 40)" || bad "quick start: $qs_end lines, more than 40"

# ---- every docs/*.md link and docs/img picture exists
for f in $(grep -o 'docs/[A-Za-z0-9_./-]*\.\(md\|png\)' README.md | sort -u); do
  [ -f "$f" ] && ok "README links $f" || bad "README links $f: no such file"
done
for f in $(grep -o '](docs/[^)#]*' README.md | sed 's/^](//' | sort -u); do
  [ -e "$f" ] || bad "README's link $f: no such file"
done

# ---- the guides' and REFERENCE's links, with their #anchors, lead somewhere
python3 - README.md docs/GUIDE-*.md docs/REFERENCE.md >"$T/links" <<'PY'
import os, re, sys
def anchors(p):  # GitHub's: lower case, punctuation dropped, spaces to '-'
    return {re.sub(r"[^\w\- ]", "", l.lstrip("#").strip().lower()).replace(" ", "-")
            for l in open(p) if l.startswith("#")}
for f in sys.argv[1:]:
    for u in re.findall(r"\]\(([^)]+)\)", open(f).read()):
        if u.startswith(("http:", "https:")): continue
        path, _, a = u.partition("#")
        tp = os.path.normpath(os.path.join(os.path.dirname(f), path)) if path else f
        if not os.path.exists(tp): print(f"{f}: link {u}: no such file")
        elif a and a not in anchors(tp): print(f"{f}: link {u}: no such section")
PY
[ -s "$T/links" ] && bad "links: $(cat "$T/links")" || ok "every link in README, the guides and REFERENCE leads somewhere"

# ---- the quick start's commands
head -n "$qs_end" README.md | python3 -c '
import sys
lines, cmds, cur = sys.stdin.read().splitlines(), [], None
for l in lines:
    s = l.strip()
    if cur is not None:
        cur += " " + s.rstrip("\\").strip()
        if not s.endswith("\\"): cmds.append(cur); cur = None
        continue
    if not l.startswith("    ") or not s.startswith(("build/", "make ", "cp ", "xvfb-run ")): continue
    s = s.split("  #")[0].strip()
    if s.endswith("\\"): cur = s.rstrip("\\").strip()
    else: cmds.append(s)
for c in cmds: print(c)' >"$T/cmds"
[ -s "$T/cmds" ] && ok "quick start: $(wc -l <"$T/cmds") commands found" || bad "quick start: no commands found"

mkdir -p "$T/w"
ln -s "$(abs "$B")" "$T/w/build"
for d in mazes robots boards tools test firmware; do ln -s "$ROOT/$d" "$T/w/$d"; done
ln -s "$(cd "$ROOT" && realpath -m "$SHARED")" "$T/shared"
missing_outside=
n=0
while IFS= read -r cmd; do
  n=$((n+1))
  case "$cmd" in
    "make test"*|"make sim"*|*GUI=1*|*" --gui"*) echo "not run (make test/sim or GUI): $cmd"; continue ;;
  esac
  mapfile -d '' -t argv < <(python3 -c 'import shlex, sys; sys.stdout.write("".join(a + "\0" for a in shlex.split(sys.argv[1])))' "$cmd")
  xvfb=0
  if [ "${argv[0]}" = xvfb-run ]; then
    command -v xvfb-run >/dev/null || { echo "not run (xvfb-run not installed): $cmd"; missing_outside="xvfb-run not installed"; continue; }
    xvfb=1
  fi
  # the tools: the caller's (make test: sanitized) unless under xvfb-run
  if [ $xvfb = 0 ]; then
    case "${argv[0]}" in
      build/mmsim) argv[0]=$(abs "${MMSIM:-$B/mmsim}") ;;
      build/mmmaze) argv[0]=$(abs "${MMMAZE:-$B/mmmaze}") ;;
      build/mmlog) argv[0]=$(abs "${MMLOG:-$B/mmlog}") ;;
      build/mmview) argv[0]=$(abs "${MMVIEW:-$B/mmview}") ;;
    esac
  fi
  # a contest run (its exit 1 is "goal not reached": documented for a run its --time-limit cuts)
  is_run=0
  for a in "${argv[@]}"; do case "$a" in --maze|--batch) is_run=1 ;; esac; done
  # mazerunner-core's images exist only when its clone is in $SHARED/clients
  if [[ " ${argv[*]} " == *" build/clients/mazerunner-core"* ]] && ! [ -d "$T/shared/clients/mazerunner-core" ]; then
    missing_outside="mazerunner-core's clone not in $SHARED/clients"; echo "not run ($missing_outside): $cmd"; continue
  fi
  if [ "${argv[0]}" = make ]; then
    run=(mk "${argv[@]:1}" SHARED="$SHARED")
  else
    run=("${argv[@]}")
  fi
  (cd "$T/w" && "${run[@]}") </dev/null >"$T/out.$n" 2>"$T/err.$n"; rc=$?
  case "$rc:${argv[0]}:$is_run" in
    0:*) ok "exit 0: $cmd" ;;
    1:*mmsim:1|1:xvfb-run:1) ok "exit 1 (goal not reached within its --time-limit): $cmd" ;;
    *) bad "exit $rc: $cmd"; tail -5 "$T/err.$n" ;;
  esac
  # what a command names with --screenshot or --report must be written
  for i in "${!argv[@]}"; do
    case "${argv[$i]}" in
      --screenshot|--report) f=${argv[$((i+1))]}
        if [ -s "$T/w/$f" ]; then ok "wrote $f"; else bad "$cmd: no $f"; fi ;;
    esac
  done
done <"$T/cmds"

if [ $fails -ne 0 ]; then echo "cli_readme: $fails failed"; exit 1; fi
if [ -n "$missing_outside" ]; then echo "SKIP cli_readme: $missing_outside (every other check passed)"; exit 77; fi
echo "cli_readme: all passed"
