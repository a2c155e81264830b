#!/usr/bin/env bash
# Install Debian packages only where they are missing, and change nothing else:
#   bash .ci/apt_install.sh PACKAGE...
# Names the packages it installs, runs `apt-get update` only when it installs some,
# never upgrades a package it was asked for that is already there (it installs only the
# missing ones, with --no-upgrade); an installed library that a missing package needs in
# a newer version is named before it is upgraded (ROBOCOG_APT_NO_UPGRADE=1: refused),
# and installs no recommended extras.
set -euo pipefail

if [ "$#" -eq 0 ]; then exit 0; fi
if ! command -v apt-get >/dev/null || ! command -v dpkg-query >/dev/null; then
    echo "apt_install.sh: no apt-get here; install $* yourself (the tests that need them skip)"
    exit 0
fi
missing=()
for package in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
if [ "${#missing[@]}" -eq 0 ]; then
    echo "apt_install.sh: already installed: $*"
    exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
options=(-y -q --no-install-recommends --no-upgrade)
echo "apt_install.sh: installing ${missing[*]} (apt-get update first)"
$SUDO apt-get update -q
# A dry run first: an already installed package that the new ones would upgrade is
# named, and nothing is installed.
upgrades=$($SUDO apt-get install -s "${options[@]}" "${missing[@]}" | sed -n 's/^Inst \([^ ]*\) \[.*/\1/p')
if [ -n "$upgrades" ]; then
    # Debian's newer packages may need newer versions of libraries already there, and
    # apt cannot install them otherwise: say so, and go on unless told not to
    echo "apt_install.sh: ${missing[*]} need newer versions of installed packages:" $upgrades
    if [ -n "${ROBOCOG_APT_NO_UPGRADE:-}" ]; then
        echo "apt_install.sh: ROBOCOG_APT_NO_UPGRADE is set: nothing installed (the tests that need them skip)"
        exit 0
    fi
    echo "apt_install.sh: they are upgraded as dependencies (set ROBOCOG_APT_NO_UPGRADE=1 to refuse)"
fi
new=$($SUDO apt-get install -s "${options[@]}" "${missing[@]}" | grep -c '^Inst ' || true)
echo "apt_install.sh: $new packages in all, with dependencies"
$SUDO apt-get install "${options[@]}" "${missing[@]}"
