"""``robocog build``: compile the NARS engine with Cython, with progress, when asked.

The install does not compile anything: ``pip install`` then takes seconds and the
engine runs as plain Python. This command turns the modules on the reasoning cycle's
path into C extensions (``robocog/nars/_compiled/``), which run NARS about four times
faster, in a couple of minutes on two cores. It shows what it compiles while it does
(a bar on a terminal, a line every few seconds in a pipe), and needs Cython, setuptools
and a C compiler with Python's headers (``pip install "robocog[compile]"`` brings the
first two).

Beside some modules a ``.pxd`` file tells Cython alone the C layout of the engine's
value classes and the C signatures of the small functions the cycle calls most; the
pure engine ignores them. The extensions go beside a manifest of the sources they were
built from, and ``robocog.nars`` loads them only while those sources are unchanged, so
an edited module is never shadowed by a stale build: it runs as Python until the next
``robocog build``. A build with the sources unchanged does nothing (``--force`` builds
again). The new build replaces the old one only once every module compiled.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import multiprocessing
import os
import shutil
import subprocess
import sys
import sysconfig
import time
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from pathlib import Path

from robocog.argtypes import int_range

#: the engine modules on the reasoning cycle's path (the Narsese reader and the shell
#: spend their time in lark and in I/O, and gain nothing)
ENGINE_MODULES = (
    "terms",
    "truth",
    "stamp",
    "event",
    "table",
    "memory",
    "state",
    "unify",
    "filters",
    "rules",
    "matchers",
    "spikegroups",
    "sensorimotor",
    "links",
    "decision",
    "goalreasoning",
    "declarative",
    "memorize",
    "inference",
    "questions",
    "cycle",
    "nar",
)
COMPILED = "_compiled"
#: the CPU time a whole build took here (2 cores, Cython 3.3, gcc 12), for the estimate
CPU_SECONDS = 120.0
#: the longest single module (the generated rule matchers), which no parallelism shortens
LONGEST_SECONDS = 30.0
MAX_JOBS = 64


class BuildError(Exception):
    """Why the engine cannot be built here (a one-line message)."""


def package_dir() -> Path:
    """The folder of the installed ``robocog.nars`` package (sources and ``.pxd``)."""
    return Path(__file__).resolve().parent


def digests(here: Path, modules: tuple[str, ...] = ENGINE_MODULES) -> dict[str, str]:
    """SHA-256 of every engine module and declaration file, by file name."""
    found = {}
    for m in modules:
        for name in (f"{m}.py", f"{m}.pxd"):
            path = here / name
            if path.exists():
                found[name] = hashlib.sha256(path.read_bytes()).hexdigest()
    return found


def is_current(here: Path) -> bool:
    """True when ``_compiled/`` holds every engine module, built by this Python from the
    sources and declarations exactly as they are now."""
    folder = here / COMPILED
    try:
        manifest = json.loads((folder / "manifest.json").read_text())
        built = os.listdir(folder)
    except (OSError, ValueError):
        return False
    if not isinstance(manifest, dict) or manifest.get("cache_tag") != sys.implementation.cache_tag:
        return False
    if manifest.get("sources") != digests(here):
        return False
    return all(any(f.startswith(f"{m}.") and f.endswith((".so", ".pyd")) for f in built)
               for m in ENGINE_MODULES)  # fmt: skip


def missing_tools() -> str | None:
    """What this machine lacks to compile the engine (None: nothing)."""
    try:
        import Cython  # noqa: F401
    except ImportError:
        return 'Cython is not installed (pip install "robocog[compile]", or pip install cython)'
    try:
        import setuptools  # noqa: F401
    except ImportError:
        return 'setuptools is not installed (pip install "robocog[compile]")'
    cc = (sysconfig.get_config_var("CC") or "cc").split()[0]
    if sys.platform != "win32" and shutil.which(cc) is None:
        return f"no C compiler ({cc}) on the PATH (Debian: apt-get install gcc)"
    include = sysconfig.get_paths().get("include")
    if include and not Path(include, "Python.h").exists():
        return f"Python's headers are missing ({include}/Python.h; Debian: apt-get install python3-dev)"
    return None


def estimate(jobs: int) -> float:
    """Seconds a whole build is expected to take with ``jobs`` compilers at once."""
    return max(LONGEST_SECONDS, CPU_SECONDS / max(1, min(jobs, len(ENGINE_MODULES))))


def _compile_one(module: str, here: str, work: str) -> tuple[str, str | None, str]:
    """Translate and compile one module in a worker process: (module, the extension's
    path or None, the tail of the tools' output when it failed)."""
    log_path = Path(work) / f"{module}.log"
    with open(log_path, "w") as log:
        # the tools print to the process's own streams: keep them out of the terminal
        os.dup2(log.fileno(), 1)
        os.dup2(log.fileno(), 2)
        try:
            from Cython.Build import cythonize
            from setuptools import Distribution, Extension
            from setuptools.command.build_ext import build_ext

            flags = [] if sys.platform == "win32" else ["-g0"]  # debug info: most of the time
            ext = Extension(
                f"robocog.nars.{module}",
                [str(Path(here) / f"{module}.py")],
                extra_compile_args=flags,
            )
            [ext] = cythonize(
                [ext],
                build_dir=str(Path(work) / "c"),
                include_path=[str(Path(here).parent.parent)],  # .pxd files cimport by package
                compiler_directives={"language_level": 3},
                quiet=True,
                force=True,
            )
            command = build_ext(Distribution({"ext_modules": [ext]}))
            command.build_lib = str(Path(work) / "lib")
            command.build_temp = str(Path(work) / "tmp" / module)
            command.ensure_finalized()
            command.run()
            return module, command.get_ext_fullpath(ext.name), ""
        except BaseException as exc:  # noqa: BLE001 - reported, the build stops
            print(f"{type(exc).__name__}: {exc}", flush=True)
    lines = log_path.read_text(errors="replace").strip().splitlines()
    return module, None, " | ".join(lines[-3:])


def build(
    here: Path,
    jobs: int,
    report: Callable[[str, str], None] | None = None,
    modules: tuple[str, ...] = ENGINE_MODULES,
) -> Path:
    """Compile every engine module into a fresh folder and put it in place of
    ``here/_compiled``; returns that folder. ``report(event, module)`` is told of each
    module that ``starts`` and is ``done``. Raises BuildError, leaving the old build."""
    import tempfile

    sources = digests(here, modules)  # as they are when the build starts
    order = sorted(modules, key=lambda m: -(here / f"{m}.py").stat().st_size)
    with tempfile.TemporaryDirectory(prefix="robocog-build-") as work:
        built: dict[str, str] = {}
        # spawned, not forked: the parent runs a progress thread
        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=jobs, mp_context=context) as pool:
            pending: set[Future[tuple[str, str | None, str]]] = set()
            queue = list(order)
            while queue or pending:
                while queue and len(pending) < jobs:
                    module = queue.pop(0)
                    pending.add(pool.submit(_compile_one, module, str(here), work))
                    if report is not None:
                        report("starts", module)
                finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                for future in finished:
                    module, path, why = future.result()
                    if path is None:
                        for other in pending:
                            other.cancel()
                        raise BuildError(f"{module}.py did not compile: {why}")
                    built[module] = path
                    if report is not None:
                        report("done", module)
        fresh = Path(tempfile.mkdtemp(prefix=f"{COMPILED}.new-", dir=here))
        try:
            for path in built.values():
                shutil.copy2(path, fresh / Path(path).name)
            manifest = {"cache_tag": sys.implementation.cache_tag, "sources": sources}
            (fresh / "manifest.json").write_text(json.dumps(manifest, indent=1, sort_keys=True))
            fresh.chmod(0o777 & ~_umask())  # mkdtemp's is 0700
            target = here / COMPILED
            old = None
            if target.exists():
                old = here / f"{COMPILED}.old-{os.getpid()}"
                target.rename(old)
            fresh.rename(target)
        except BaseException:
            shutil.rmtree(fresh, ignore_errors=True)
            raise
        if old is not None:  # processes running the old build keep their loaded files
            shutil.rmtree(old, ignore_errors=True)
    return target


def _umask() -> int:
    """The process's umask (read by setting it back at once; this command has no threads
    writing files)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def engine_in_a_fresh_process(here: Path) -> str:
    """What ``robocog.nars.ENGINE`` says in a new interpreter importing this package."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(here.parent.parent)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else [])
    )
    run = subprocess.run(
        [sys.executable, "-c", "import robocog.nars as n; print(n.ENGINE)"],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )
    lines = (run.stdout or run.stderr).strip().splitlines()
    return lines[-1] if lines else "unknown"


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare ``robocog build``'s arguments."""
    parser.add_argument(
        "--jobs",
        type=int_range(1, MAX_JOBS),
        default=min(os.cpu_count() or 1, MAX_JOBS),
        help=f"modules compiled at once (default: the {os.cpu_count() or 1} cores)",
    )
    parser.add_argument(
        "--force", action="store_true", help="build again even if the build is current"
    )


def run(args: argparse.Namespace) -> int:
    """Build the engine: 0 when the compiled engine is in place, 1 when it could not be."""
    from rich.console import Console

    from robocog.progress import Steps, duration, header

    console = Console()
    here = package_dir()
    if is_current(here) and not args.force:
        console.print(
            f"robocog build: the compiled NARS engine in {here / COMPILED} is current "
            "(built from these sources); nothing to do (--force builds it again)",
            markup=False,
            highlight=False,
            soft_wrap=True,
        )
        return 0
    why = missing_tools()
    if why is None and not os.access(here, os.W_OK):
        why = f"{here} is not writable (build where robocog is installed by you)"
    if why:
        console.print(
            f"robocog build: cannot compile the NARS engine here: {why}; NARS runs as pure "
            "Python meanwhile",
            markup=False,
            highlight=False,
            soft_wrap=True,
        )
        return 1
    jobs = min(args.jobs, len(ENGINE_MODULES))
    header(
        console,
        "robocog build",
        f"compiling the NARS engine's {len(ENGINE_MODULES)} modules with Cython and the C "
        f"compiler, {jobs} at a time, into {here / COMPILED}",
        f"{duration(estimate(jobs))} on {jobs} cores, longer on a busy machine",
    )
    start = time.monotonic()
    running: list[str] = []
    with Steps(console) as steps:
        modules = steps.add("modules compiled", len(ENGINE_MODULES))

        def report(event: str, module: str) -> None:
            if event == "starts":
                running.append(module)
            else:
                running.remove(module)
            steps.note(modules, "compiling " + ", ".join(running) if running else "")
            if event == "done":
                steps.advance(modules)

        try:
            target = build(here, jobs, report)
        except BuildError as exc:
            steps.say(f"robocog build: {exc}; the engine stays as it was")
            return 1
        except OSError as exc:
            steps.say(f"robocog build: cannot write the build: {exc}")
            return 1
    engine = engine_in_a_fresh_process(here)
    console.print(
        f"robocog build: done in {int(time.monotonic() - start)} s: {target}; "
        f"robocog.nars.ENGINE is now {engine!r}",
        markup=False,
        highlight=False,
        soft_wrap=True,
    )
    if os.environ.get("ROBOCOG_PURE_PYTHON"):
        console.print(
            "robocog build: ROBOCOG_PURE_PYTHON is set, so this shell still runs the pure engine",
            markup=False,
            soft_wrap=True,
        )
    return 0 if engine == "compiled" or os.environ.get("ROBOCOG_PURE_PYTHON") else 1
