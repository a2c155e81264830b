#!/usr/bin/env bash
# Install Debian packages only where they are missing, and change nothing else:
#   bash .ci/apt_install.sh PACKAGE...
# Names the packages it installs, runs `apt-get update` only when it installs some,
# never upgrades a package that is already there (it installs only the missing ones,
# with --no-upgrade, and stops before apt-get would upgrade one as a dependency),
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
    echo "apt_install.sh: installing ${missing[*]} would upgrade installed packages:" $upgrades
    echo "apt_install.sh: nothing installed; install them by hand if that upgrade is fine"
    exit 1
fi
new=$($SUDO apt-get install -s "${options[@]}" "${missing[@]}" | grep -c '^Inst ' || true)
echo "apt_install.sh: $new packages in all, with dependencies"
$SUDO apt-get install "${options[@]}" "${missing[@]}"
