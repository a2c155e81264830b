"""Build hook: compile the NARS engine's hot modules with Cython where the machine can.

The modules stay plain Python and are the only source of behaviour. Beside some of them
a ``.pxd`` file tells Cython alone the C layout of the engine's value classes (truth
value, term, event, implication, table, concept) and the C signatures of the small
functions the cycle calls most; the modules' own type annotations then declare their
variables, so a field is read from a struct and those calls are made in C. The pure
engine ignores the ``.pxd`` files. Compiled, the same code runs about twice as fast,
which is what a robot's cycle needs. The extensions go into
``robocog/nars/_compiled/`` beside a manifest of the sources they were built from, and
``robocog.nars`` loads them only while those sources are unchanged (so an edited module
is never shadowed by a stale build). Without Cython or a C compiler the install goes on
and the pure-Python engine runs; ``python -c "import robocog.nars as n; print(n.ENGINE)"``
says which one is in use.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

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
SOURCE_DIR = os.path.join("src", "robocog", "nars")
COMPILED = "_compiled"


def _digest(path: str) -> str:
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def _compiled_is_current() -> bool:
    """True when ``_compiled/`` beside the sources holds every engine module, built by
    this Python from the sources (and declarations) exactly as they are now."""
    folder = os.path.join(SOURCE_DIR, COMPILED)
    try:
        with open(os.path.join(folder, "manifest.json")) as f:
            manifest = json.load(f)
        built = os.listdir(folder)
    except (OSError, ValueError):
        return False
    if manifest.get("cache_tag") != sys.implementation.cache_tag:
        return False
    sources = manifest.get("sources", {})
    for m in ENGINE_MODULES:
        for name in (f"{m}.py", f"{m}.pxd"):
            path = os.path.join(SOURCE_DIR, name)
            if os.path.exists(path) and sources.get(name) != _digest(path):
                return False
        if not any(f.startswith(f"{m}.") and f.endswith((".so", ".pyd")) for f in built):
            return False
    return True


def _extensions() -> list[Extension]:
    if os.environ.get("ROBOCOG_PURE_PYTHON"):
        return []
    # an editable install uses the extensions beside the sources: when nothing in the
    # engine changed since they were built, another install need not build them again
    if "editable_wheel" in sys.argv and _compiled_is_current():
        print("robocog: the compiled NARS engine is current; it is not built again")
        return []
    print(
        f"robocog: compiling the NARS engine ({len(ENGINE_MODULES)} modules of robocog/nars) "
        "with Cython; this takes a few minutes, and a reinstall with the engine unchanged "
        "does not compile it again (set ROBOCOG_PURE_PYTHON=1 to skip it and run the "
        "pure-Python engine)"
    )
    try:
        from Cython.Build import cythonize
    except ImportError:
        print("robocog: Cython is not available; the NARS engine stays pure Python")
        return []
    # no debug information: it took most of the compile time and of the files' size
    flags = [] if sys.platform == "win32" else ["-g0"]
    exts = [
        Extension(
            f"robocog.nars.{m}",
            [os.path.join(SOURCE_DIR, f"{m}.py")],
            optional=True,
            extra_compile_args=flags,
        )
        for m in ENGINE_MODULES
    ]
    try:
        return cythonize(
            exts,
            build_dir=os.path.join("build", "cython"),
            include_path=["src"],  # the engine's .pxd files cimport each other by package
            compiler_directives={"language_level": 3},
            nthreads=os.cpu_count() or 1,
            quiet=True,
        )
    except Exception as exc:  # noqa: BLE001 - any failure leaves the pure engine
        print(f"robocog: Cython could not translate the engine ({exc}); it stays pure Python")
        return []


class BuildEngine(build_ext):
    """Puts each extension in ``_compiled/`` and writes the manifest of its sources.

    setuptools builds extensions into its build folder and, for an editable install,
    copies them beside the sources; both places get the ``_compiled`` folder here.
    """

    def initialize_options(self) -> None:
        super().initialize_options()
        self.parallel = os.cpu_count() or 1

    def get_ext_filename(self, fullname: str) -> str:
        folder, name = os.path.split(super().get_ext_filename(fullname))
        return os.path.join(folder, COMPILED, name)

    def _get_inplace_equivalent(self, build_py, ext: Extension) -> tuple[str, str]:  # noqa: ANN001
        inplace, regular = super()._get_inplace_equivalent(build_py, ext)
        folder, name = os.path.split(inplace)
        return os.path.join(folder, COMPILED, name), regular

    def copy_extensions_to_source(self) -> None:
        build_py = self.get_finalized_command("build_py")
        for ext in self.extensions:
            self.mkpath(os.path.dirname(self._get_inplace_equivalent(build_py, ext)[0]))
        super().copy_extensions_to_source()

    def run(self) -> None:
        super().run()
        build_py = self.get_finalized_command("build_py")
        places: dict[str, dict[str, str]] = {}
        for ext in self.extensions:
            module = ext.name.rsplit(".", 1)[1]
            # the module and, where it has one, the declarations it was compiled with
            digests = {}
            for name in (f"{module}.py", f"{module}.pxd"):
                path = os.path.join(SOURCE_DIR, name)
                if os.path.exists(path):
                    with open(path, "rb") as f:
                        digests[name] = hashlib.sha256(f.read()).hexdigest()
            inplace, regular = self._get_inplace_equivalent(build_py, ext)
            for path in (inplace, regular):
                if os.path.exists(path):  # an optional extension may not have compiled
                    places.setdefault(os.path.dirname(path), {}).update(digests)
        for folder, sources in places.items():
            manifest = {"cache_tag": sys.implementation.cache_tag, "sources": sources}
            tmp = os.path.join(folder, "manifest.json.tmp")
            with open(tmp, "w") as f:
                json.dump(manifest, f, indent=1, sort_keys=True)
            os.replace(tmp, os.path.join(folder, "manifest.json"))


setup(ext_modules=_extensions(), cmdclass={"build_ext": BuildEngine})
