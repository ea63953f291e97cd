#!/usr/bin/env bash
# venv.sh VENV REQUIREMENTS STAMP - the project venv: Debian's python3
# (/usr/bin/python3) with its site packages visible, plus the pinned
# packages of REQUIREMENTS; STAMP touched when they are installed.
# Exit 3 when venv or pip fails.
venv=$1 reqs=$2 stamp=$3
[ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$venv" \
  || { echo "make deps: python3 -m venv failed (python3-venv)" >&2; exit 3; }
"$venv/bin/python" -m pip install -q -r "$reqs" \
  || { echo "make deps: pip install -r $reqs failed" >&2; exit 3; }
touch "$stamp"
