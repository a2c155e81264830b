""".ci/apt_install.sh decides, for each package, between nothing, apt and a private
unpacked root. Its apt-get, dpkg and dpkg-query are stand-ins here that record their
calls and answer from small files, so that what the script would do to a machine is
checked without a network or root rights."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[1] / ".ci" / "apt_install.sh"
BASH = shutil.which("bash")

pytestmark = pytest.mark.skipif(BASH is None, reason="needs bash")

# apt-get: a dry run prints an Inst line for each package asked for and the lines of
# deps-NAME; download makes an empty NAME_1.0_amd64.deb in the current folder.
APT_GET = r"""#!/bin/bash
echo "apt-get $*" >> "$STUBS/log"
words=(); skip=0
for a in "$@"; do
    if [ $skip = 1 ]; then skip=0; continue; fi
    case $a in -o) skip=1 ;; -*) ;; *) words+=("$a") ;; esac
done
case ${words[0]} in
install)
    if [[ " $* " == *" -s "* ]]; then
        for p in "${words[@]:1}"; do
            echo "Inst $p (1.0 Debian:12 [amd64])"
            cat "$STUBS/deps-$p" 2>/dev/null || true
        done
    fi ;;
download) for p in "${words[@]:1}"; do : > "${p}_1.0_amd64.deb"; done ;;
esac
"""
# dpkg -x puts a library and the programs of programs-NAME (each printing its library
# path) in the root; dpkg -c lists those programs.
DPKG = r"""#!/bin/bash
echo "dpkg $*" >> "$STUBS/log"
name=$(basename "$2"); pkg=${name%%_*}
case $1 in
-x)
    mkdir -p "$3/usr/lib/x86_64-linux-gnu" "$3/usr/bin"
    : > "$3/usr/lib/x86_64-linux-gnu/$pkg.so"
    for prog in $(cat "$STUBS/programs-$pkg" 2>/dev/null); do
        printf '#!/bin/sh\necho "%s $*: $LD_LIBRARY_PATH"\n' "$prog" > "$3/usr/bin/$prog"
        chmod +x "$3/usr/bin/$prog"
    done ;;
-c)
    for prog in $(cat "$STUBS/programs-$pkg" 2>/dev/null); do
        echo "-rwxr-xr-x root/root 10 2023-01-01 00:00 ./usr/bin/$prog"
    done ;;
esac
"""
# apt-cache show: the Depends line in depends-NAME
APT_CACHE = r"""#!/bin/bash
echo "Package: ${@: -1}"
cat "$STUBS/depends-${@: -1}" 2>/dev/null || true
"""
DPKG_QUERY = r"""#!/bin/bash
if [ -e "$STUBS/installed-$3" ]; then echo -n "install ok installed"; else exit 1; fi
"""
SUDO = '#!/bin/bash\nexec "$@"\n'


class Machine:
    """A pretend Debian: installed packages, what a dry run of each would bring."""

    def __init__(self, tmp: Path) -> None:
        self.stubs = tmp / "stubs"
        self.stubs.mkdir()
        self.root = tmp / "deb-root"
        for name, text in [
            ("apt-get", APT_GET),
            ("apt-cache", APT_CACHE),
            ("dpkg", DPKG),
            ("dpkg-query", DPKG_QUERY),
            ("sudo", SUDO),
        ]:
            path = self.stubs / name
            path.write_text(text)
            path.chmod(0o755)
        (self.stubs / "log").write_text("")

    def installed(self, *names: str) -> None:
        for name in names:
            (self.stubs / f"installed-{name}").write_text("")

    def dry_run(self, name: str, lines: list[str]) -> None:
        (self.stubs / f"deps-{name}").write_text("".join(line + "\n" for line in lines))

    def depends(self, name: str, line: str) -> None:
        (self.stubs / f"depends-{name}").write_text(f"Depends: {line}\n")

    def programs(self, name: str, *programs: str) -> None:
        (self.stubs / f"programs-{name}").write_text(" ".join(programs))

    def run(self, *packages: str, **env: str) -> str:
        environ = {
            **{k: v for k, v in os.environ.items() if k != "ROBOCOG_APT_PRIVATE"},
            "STUBS": str(self.stubs),
            "PATH": f"{self.stubs}:{os.environ['PATH']}",
            "ROBOCOG_DEB_ROOT": str(self.root),
            **env,
        }
        done = subprocess.run(
            [BASH, str(SCRIPT), *packages],
            env=environ,
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert done.returncode == 0, done.stderr
        return done.stdout

    def calls(self) -> list[str]:
        lines = (self.stubs / "log").read_text().splitlines()
        (self.stubs / "log").write_text("")
        return lines


def test_nothing_missing_calls_no_apt(tmp_path: Path) -> None:
    machine = Machine(tmp_path)
    machine.installed("valgrind", "chromium")
    out = machine.run("valgrind", "chromium")
    assert "nothing missing" in out
    assert machine.calls() == []


def test_a_package_that_would_upgrade_is_unpacked_privately(tmp_path: Path) -> None:
    machine = Machine(tmp_path)
    machine.installed("libold")
    machine.dry_run(
        "browser",
        [
            "Inst libold [0.9] (1.0 Debian:12 [amd64])",
            "Inst libc6 [2.36-9] (2.36-9+deb12u14 Debian:12 [amd64])",
            "Inst libnew (1.0 Debian:12 [amd64])",
        ],
    )
    machine.programs("browser", "browser")
    machine.depends("browser", "libc6 (>= 2.35), browser-common (= 1.0), libold (>= 1.0)")
    out = machine.run("plain", "browser")
    calls = machine.calls()
    installs = [c for c in calls if c.startswith("apt-get install") and " -s " not in c]
    # apt installs only the package whose dry run upgrades nothing, and never upgrades
    assert len(installs) == 1 and installs[0].split()[-1] == "plain"
    assert "--no-upgrade" in installs[0] and "--no-remove" in installs[0]
    assert "browser needs newer versions of installed packages (libold libc6 )" in out
    # the private root has the package, the one it pins to its version, the newer
    # library and the new one, through apt-get download and dpkg -x only (dpkg's
    # database is not touched)
    downloads = [c for c in calls if c.startswith("apt-get download")]
    assert len(downloads) == 1
    assert set(downloads[0].split()) >= {"browser", "browser-common", "libold", "libnew"}
    assert "libc6" not in downloads[0].split()
    assert all(c.split()[1] in ("-x", "-c") for c in calls if c.startswith("dpkg "))
    wrapper = machine.root / "bin" / "browser"
    shown = subprocess.run([str(wrapper), "--headless"], capture_output=True, text=True)
    name, libs = shown.stdout.split(": ", 1)
    assert name == "browser --headless"
    assert libs.split(":")[0] == str(machine.root / "usr" / "lib" / "x86_64-linux-gnu")
    # a second run finds it there and calls nothing
    machine.installed("plain")
    again = machine.run("plain", "browser")
    assert "already unpacked in" in again and "nothing missing" in again
    assert machine.calls() == []


def test_the_private_path_can_be_forced_for_an_installed_package(tmp_path: Path) -> None:
    machine = Machine(tmp_path)
    machine.installed("browser")
    machine.programs("browser", "browser")
    machine.run("browser", ROBOCOG_APT_PRIVATE="browser")
    calls = machine.calls()
    assert not [c for c in calls if c.startswith("apt-get install") and " -s " not in c]
    assert (machine.root / "bin" / "browser").exists()


def test_without_apt_it_says_so_and_changes_nothing(tmp_path: Path) -> None:
    empty = tmp_path / "empty"
    empty.mkdir()
    done = subprocess.run(
        [BASH, str(SCRIPT), "chromium"],
        env={"PATH": str(empty), "HOME": str(tmp_path)},
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0
    assert "no apt-get here" in done.stdout
