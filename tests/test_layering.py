"""The import rules of docs/design.md, checked on the source itself."""

from __future__ import annotations

import ast
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


def _imported_packages(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: set[str] = set()
    for node in ast.walk(tree):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module]
        for name in names:
            parts = name.split(".")
            if parts[0] == "robocog" and len(parts) > 1:
                found.add(parts[1])
    return found


def test_every_package_keeps_to_its_imports() -> None:
    violations = []
    for package, forbidden in FORBIDDEN.items():
        for path in sorted((SRC / package).rglob("*.py")):
            bad = _imported_packages(path) & forbidden
            if bad:
                violations.append(f"{path.relative_to(SRC)} imports {sorted(bad)}")
    assert violations == []


def test_the_checker_sees_a_violation(tmp_path: Path) -> None:
    module = tmp_path / "m.py"
    module.write_text("from robocog.robot import loop\nimport robocog.nars.terms\n")
    assert _imported_packages(module) == {"robot", "nars"}
