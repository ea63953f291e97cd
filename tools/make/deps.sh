#!/usr/bin/env bash
# deps.sh PKG... - installs the Debian packages of the list that are not
# installed (make deps; idempotent): apt-get as root, else through sudo.
# Exit 3 when apt-get fails.
missing=""
for p in "$@"; do
  dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed' || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "make deps: installing$missing"
  SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
  # shellcheck disable=SC2086 # one word per package
  $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null \
    || { echo "make deps: apt-get failed" >&2; exit 3; }
fi
exit 0
