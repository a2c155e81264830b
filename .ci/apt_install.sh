#!/usr/bin/env bash
# Install Debian packages only where they are missing, and upgrade nothing:
#   bash .ci/apt_install.sh PACKAGE...
# Each missing package is first installed in a dry run (`apt-get install -s`). Those whose
# dry run upgrades no installed package are installed through apt (`--no-upgrade
# --no-remove --no-install-recommends`, `apt-get update` first, sudo when not root).
# Debian's newer packages (chromium) may need newer versions of installed libraries, and
# apt can only get them by upgrading those; such a package is instead unpacked, with the
# packages its dry run would install or upgrade, into a private root that dpkg knows
# nothing of: ${ROBOCOG_DEB_ROOT:-${XDG_CACHE_HOME:-~/.cache}/robocog/deb-root}. Its
# programs are started through ROOT/bin/NAME, which puts the root's libraries first
# (tests/inspector finds ROOT/bin/chromium). No root rights are needed for that part.
# ROBOCOG_APT_PRIVATE="chromium ..." takes that private path for those packages even when
# they are installed or need no upgrade (to test it). Without apt it says so and stops.
set -euo pipefail

if [ "$#" -eq 0 ]; then exit 0; fi
if ! command -v apt-get >/dev/null || ! command -v dpkg-query >/dev/null; then
    echo "apt_install.sh: no apt-get here; install $* yourself (the tests that need them skip)"
    exit 0
fi
root="${ROBOCOG_DEB_ROOT:-${XDG_CACHE_HOME:-$HOME/.cache}/robocog/deb-root}"
forced=" ${ROBOCOG_APT_PRIVATE:-} "
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
unpacked=()
for package in "$@"; do
    # .unpacked/NAME marks a package unpacked in the private root by an earlier run
    if [ -e "$root/.unpacked/$package" ]; then
        unpacked+=("$package")
    elif [[ $forced == *" $package "* ]] || ! installed "$package"; then
        missing+=("$package")
    fi
done
if [ "${#unpacked[@]}" -gt 0 ]; then
    echo "apt_install.sh: already unpacked in $root: ${unpacked[*]}"
fi
if [ "${#missing[@]}" -eq 0 ]; then
    echo "apt_install.sh: nothing missing: $*"
    exit 0
fi
SUDO=""
# apt-get download as root cannot hand the files to its sandbox user: it says so; not here
sandbox=(-o APT::Sandbox::User=root)
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo" sandbox=(); fi
export DEBIAN_FRONTEND=noninteractive
options=(-q --no-install-recommends --no-upgrade --no-remove)
echo "apt_install.sh: missing: ${missing[*]} (apt-get update first)"
$SUDO apt-get update -q
# The installed packages a dry run of installing "$@" would upgrade, one line each
upgrades() { apt-get install -s "${options[@]}" "$@" | sed -n 's/^Inst \([^ ]*\) \[.*/\1/p'; }
through_apt=()
private=()
for package in "${missing[@]}"; do
    if [[ $forced == *" $package "* ]]; then
        private+=("$package")
        continue
    fi
    newer=$(upgrades "$package" | tr '\n' ' ')
    if [ -z "$newer" ]; then
        through_apt+=("$package")
    else
        echo "apt_install.sh: $package needs newer versions of installed packages ($newer);" \
            "it is unpacked privately instead of upgrading them"
        private+=("$package")
    fi
done

if [ "${#through_apt[@]}" -gt 0 ]; then
    # Each alone upgrades nothing; the dry run of them together makes sure of it
    newer=$(upgrades "${through_apt[@]}" | tr '\n' ' ')
    if [ -n "$newer" ]; then
        echo "apt_install.sh: together ${through_apt[*]} would upgrade $newer: nothing installed"
        exit 1
    fi
    count=$(apt-get install -s "${options[@]}" "${through_apt[@]}" | grep -c '^Inst ' || true)
    echo "apt_install.sh: installing ${through_apt[*]} through apt ($count packages with" \
        "their dependencies, none upgraded)"
    $SUDO apt-get install -y "${options[@]}" "${through_apt[@]}"
fi

for package in "${private[@]}"; do
    # What a system without it needs: the package, the packages it pins to its own
    # version (chromium-common: the data beside chromium's binary) and all that their dry
    # run installs or upgrades (--reinstall lists them when they are installed, as when
    # the private path is forced)
    pinned=$(apt-cache show --no-all-versions "$package" | sed -n 's/^Depends: //p' |
        tr ',' '\n' | sed -n 's/^ *\([^ ]*\) (= .*/\1/p')
    # (never the C library: it must match the system's dynamic loader, and a Debian
    # release keeps one upstream glibc, so the system's serves)
    debs=$(apt-get install -s --reinstall -q --no-install-recommends "$package" $pinned |
        sed -n 's/^Inst \([^ ]*\) .*/\1/p' | grep -vx 'libc6\|libc-bin' | sort -u)
    mkdir -p "$root/.unpacked" "$root/bin"
    download=$(mktemp -d "$root/.download.XXXXXX")
    echo "apt_install.sh: unpacking $package into $root (dpkg's database is not touched):" $debs
    (cd "$download" && apt-get download -q "${sandbox[@]}" $debs)
    for deb in "$download"/*.deb; do dpkg -x "$deb" "$root"; done
    # A wrapper in ROOT/bin for each program of the package. Debian's chromium is a shell
    # script that runs /usr/lib/chromium/chromium by its absolute path, so where the
    # package has usr/lib/NAME/NAME, that is what the wrapper runs.
    programs=$(dpkg -c "$download/${package}_"*.deb | sed -n 's|.* \./usr/bin/\([^ ]*\)$|\1|p')
    for name in $programs; do
        target="usr/bin/$name"
        if [ -x "$root/usr/lib/$name/$name" ]; then target="usr/lib/$name/$name"; fi
        cat >"$root/bin/$name" <<EOF
#!/bin/sh
# Debian's $name unpacked by robocog's .ci/apt_install.sh: its root's libraries first.
root=\$(cd "\$(dirname "\$0")/.." && pwd)
libs=""
for dir in "\$root"/usr/lib/*-linux-gnu* "\$root"/lib/*-linux-gnu* "\$root/usr/lib/$name"; do
    if [ -d "\$dir" ]; then libs="\$libs\$dir:"; fi
done
export LD_LIBRARY_PATH="\$libs\${LD_LIBRARY_PATH:-}"
exec "\$root/$target" "\$@"
EOF
        chmod +x "$root/bin/$name"
        echo "apt_install.sh: $root/bin/$name runs $package's $name"
    done
    echo "$debs" >"$root/.unpacked/$package"
    rm -rf "$download"
done
