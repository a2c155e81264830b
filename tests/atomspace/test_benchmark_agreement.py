"""robocog and hyperon find the same answers on the benchmark's facts (no timing here:
speed is measured by benchmarks/atomspace.py)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

from robocog.atomspace import query

BENCH = Path(__file__).resolve().parents[2] / "benchmarks" / "atomspace.py"


def _bench():  # noqa: ANN202 - the benchmark module
    spec = importlib.util.spec_from_file_location("atomspace_benchmark", BENCH)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def test_same_answers_as_hyperon() -> None:
    pytest.importorskip("hyperon")
    b = _bench()
    names, pairs, clears = b.facts(7)
    work = b.workload(7, len(names), 12)
    _load, space, make = b.robocog_side(names, pairs, clears)
    _hload, hspace, hmake = b.hyperon_side(names, pairs, clears)
    total = 0
    for kind in b.KINDS:
        for k in work[kind]:
            mine = len(query(space, make[kind](k)))
            theirs = len(list(hspace.query(hmake[kind](k)).iterator()))
            assert mine == theirs, (kind, k)
            total += mine
    assert total > 0


def test_benchmark_facts_are_as_specified() -> None:
    b = _bench()
    names, pairs, clears = b.facts(2021)
    assert len(pairs) == len(set(pairs)) == 7500
    assert len(clears) == len(set(clears)) == 2500
    _load, space, _make = b.robocog_side(names, pairs, clears)
    assert len(space.get_by_type("EvaluationLink")) == 10_000
