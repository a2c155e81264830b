"""The import rules of docs/design.md, checked on the source itself."""

from __future__ import annotations

import ast
import os
import subprocess
import sys
from collections.abc import Collection
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "robocog"
ENGINES = {"nars", "bdi", "atomspace", "planning"}
ROBOT_SIDE = {"robot", "minds", "worlds", "bridges", "experiments", "sim", "testing"}

#: package -> the robocog packages it must not import
FORBIDDEN: dict[str, set[str]] = {
    "nars": ROBOT_SIDE | {"bdi", "atomspace", "planning"},
    "bdi": ROBOT_SIDE | {"nars", "atomspace", "planning"},
    "atomspace": ROBOT_SIDE | {"nars", "bdi", "planning"},
    "planning": ROBOT_SIDE | {"nars", "bdi"},
    "robot": ENGINES | {"minds", "worlds", "bridges", "experiments"},
    "worlds": ENGINES | {"minds", "bridges", "experiments"},
    "bridges": ENGINES | {"minds", "worlds", "experiments", "sim", "testing"},
    "sim": ENGINES | {"minds", "experiments", "testing"},
    "testing": ENGINES | {"minds", "experiments", "sim"},
}
#: package -> modules of a package it must not import that it may import all the same
ALLOWED: dict[str, set[str]] = {
    # the bridges' command names its mind through the registry, which imports a mind's
    # module (and so its engine) only when that mind is made: the bridges know no engine
    "bridges": {"robocog.minds.registry"},
}


def _imported_modules(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: set[str] = set()
    for node in ast.walk(tree):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module]
        found.update(name for name in names if name.startswith("robocog."))
    return found


def _imported_packages(path: Path, allowed: Collection[str] = ()) -> set[str]:
    return {name.split(".")[1] for name in _imported_modules(path) - set(allowed)}


def test_every_package_keeps_to_its_imports() -> None:
    violations = []
    for package, forbidden in FORBIDDEN.items():
        for path in sorted((SRC / package).rglob("*.py")):
            bad = _imported_packages(path, ALLOWED.get(package, set())) & forbidden
            if bad:
                violations.append(f"{path.relative_to(SRC)} imports {sorted(bad)}")
    assert violations == []


#: modules of no package that every package may use, because they import no robocog module
SHARED_MODULES = ("argtypes.py", "atomic.py", "ona_process.py", "progress.py")


def test_the_modules_every_package_may_use_import_nothing_of_robocog() -> None:
    imports = {name: _imported_modules(SRC / name) for name in SHARED_MODULES}
    assert imports == {name: set() for name in SHARED_MODULES}


def test_the_mind_registry_loads_no_engine_until_a_mind_is_made() -> None:
    """What lets the bridges import the registry: importing it imports no engine and no
    mind's module (each factory imports its own when called)."""
    code = (
        "import sys, robocog.minds.registry\n"
        "print(' '.join(m for m in sys.modules if m.startswith('robocog.')))"
    )
    env = {**os.environ, "PYTHONPATH": str(SRC.parent)}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True
    ).stdout.split()
    loaded = {m.split(".")[1] for m in out}
    assert loaded & ENGINES == set()
    minds = sorted(m for m in out if m.startswith("robocog.minds."))
    assert minds == ["robocog.minds.registry"]


def test_the_checker_sees_a_violation(tmp_path: Path) -> None:
    module = tmp_path / "m.py"
    module.write_text("from robocog.robot import loop\nimport robocog.nars.terms\n")
    assert _imported_packages(module) == {"robot", "nars"}


def _module_name(path: Path, root: Path) -> str:
    rel = path.relative_to(root.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def import_graph(root: Path = SRC) -> dict[str, set[str]]:
    """Every robocog module -> the robocog modules it imports, at module level or inside a
    function alike (a lazy import still ties the two modules together). Imports made
    only for type checkers (under ``if TYPE_CHECKING:``) never run and do not count."""
    modules = {_module_name(p, root): p for p in root.rglob("*.py")}
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        tree = ast.parse(path.read_text(encoding="utf-8"))
        typing_only = {
            id(inner)
            for block in ast.walk(tree)
            if isinstance(block, ast.If) and "TYPE_CHECKING" in ast.unparse(block.test)
            for stmt in block.body
            for inner in ast.walk(stmt)
        }
        for node in ast.walk(tree):
            if id(node) in typing_only:
                continue
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    anchor = package.split(".")
                    anchor = anchor[: len(anchor) - (node.level - 1)]
                    base = ".".join([*anchor, base] if base else anchor)
                # `from pkg import mod` imports the module mod when there is one
                targets = [
                    f"{base}.{alias.name}" if f"{base}.{alias.name}" in modules else base
                    for alias in node.names
                ]
            for target in targets:
                while target and target not in modules:  # `import a.b.c` of a name in a.b
                    target = target.rpartition(".")[0]
                if target and target != name:
                    graph[name].add(target)
    return graph


def import_cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected groups of more than one module (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    groups: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                groups.append(sorted(group))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return groups


def test_no_module_imports_itself_through_others() -> None:
    cycles = import_cycles(import_graph())
    assert cycles == [], "import cycles: " + "; ".join(" <-> ".join(c) for c in cycles)


def test_the_cycle_finder_sees_a_lazy_cycle(tmp_path: Path) -> None:
    package = tmp_path / "robocog" / "p"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("from robocog.p import b\n")
    (package / "b.py").write_text("def f():\n    from . import c\n")
    (package / "c.py").write_text("def g():\n    import robocog.p.a\n")
    graph = import_graph(tmp_path / "robocog")
    assert import_cycles(graph) == [["robocog.p.a", "robocog.p.b", "robocog.p.c"]]


#: the most lines a module in src/ may have: a longer one holds more than one idea and
#: is split along its seams (a package of modules where it has several)
MAX_MODULE_LINES = 800
#: modules allowed over the bound for now, each with the way it is to be split
LONG_MODULES: set[str] = set()
#: modules generated from a table, one function per row, which a reader reads through
#: their generator and the table (the bound is for modules written by hand)
GENERATED_MODULES = {"nars/matchers.py"}


def long_modules(root: Path = SRC, most: int = MAX_MODULE_LINES) -> dict[str, int]:
    """Every module under ``root`` with more than ``most`` lines -> its line count."""
    found = {}
    for path in sorted(root.rglob("*.py")):
        with path.open(encoding="utf-8") as f:
            n = sum(1 for _line in f)
        if n > most:
            found[path.relative_to(root).as_posix()] = n
    return found


def test_no_module_is_longer_than_the_bound() -> None:
    exempt = LONG_MODULES | GENERATED_MODULES
    too_long = {name: n for name, n in long_modules().items() if name not in exempt}
    assert too_long == {}, f"modules over {MAX_MODULE_LINES} lines: {too_long}"


def test_the_known_long_modules_are_still_long() -> None:
    # once one is split, it leaves the list of exceptions (so that the list only shrinks)
    split = LONG_MODULES - set(long_modules())
    assert split == set(), f"now within the bound, remove from LONG_MODULES: {sorted(split)}"


def test_the_generated_modules_are_there() -> None:
    assert all((SRC / name).exists() for name in GENERATED_MODULES), GENERATED_MODULES


def test_the_line_counter_sees_a_long_module(tmp_path: Path) -> None:
    (tmp_path / "short.py").write_text("x = 1\n" * 3)
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "long.py").write_text("x = 1\n" * 4)
    assert long_modules(tmp_path, most=3) == {"pkg/long.py": 4}


def private_reads(path: Path) -> list[str]:
    """``obj._name`` where ``obj`` is not ``self`` or ``cls`` (a dunder is no private
    name): reading another object's private state ties a module to its insides."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Attribute):
            continue
        name = node.attr
        if not name.startswith("_") or (name.startswith("__") and name.endswith("__")):
            continue
        if isinstance(node.value, ast.Name) and node.value.id in ("self", "cls"):
            continue
        found.append(f"{path.name}:{node.lineno} {ast.unparse(node)}")
    return found


def test_the_inspector_reads_no_private_attribute() -> None:
    """The inspector reads minds, worlds and engines through what they offer publicly."""
    found = [r for p in sorted((SRC / "inspector").rglob("*.py")) for r in private_reads(p)]
    assert found == []


def test_the_private_read_checker_sees_one(tmp_path: Path) -> None:
    module = tmp_path / "m.py"
    module.write_text("def f(nar):\n    return nar._priority, nar.memory, nar.__class__, self._x\n")
    assert private_reads(module) == ["m.py:2 nar._priority"]
