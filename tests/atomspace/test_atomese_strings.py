"""Long strings are read in memory proportional to their length, closed or not: the
token pattern once kept a backtracking mark per character (a 10 MB string took 2.7 GB)."""

from __future__ import annotations

import tracemalloc
from collections.abc import Callable

import pytest

from robocog.atomspace.atomese import AtomeseError, load
from robocog.atomspace.schemedata import SchemeError, read
from robocog.atomspace.space import AtomSpace

#: two million characters; read with the old pattern, each of these texts peaked
#: at 190 to 300 MB
N = 2_000_000


def _peak_mb(fn: Callable[[], object]) -> float:
    tracemalloc.start()
    try:
        fn()
    finally:
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    return peak / 1e6


def test_a_long_node_name_is_read_in_linear_memory() -> None:
    text = '(ConceptNode "' + "a\\" * (N // 4) + "a" * (N // 2) + '")'
    got: list = []
    assert _peak_mb(lambda: got.append(load(text, AtomSpace()))) < 40
    (atom,) = got[0]
    assert len(atom.name) == N // 4 + N // 2  # each escape read as the character it escapes


@pytest.mark.parametrize(
    "body",
    ["a" * N, "a\\b" * (N // 3), "a" * N + "\\"],
    ids=["plain", "escapes", "a-backslash-at-the-end"],
)
def test_an_unterminated_long_string_is_refused_in_linear_memory(body: str) -> None:
    text = '(ConceptNode "a")\n(ConceptNode "' + body

    def reading() -> None:
        with pytest.raises(AtomeseError, match=r"2:14: unterminated string"):
            load(text, AtomSpace())

    assert _peak_mb(reading) < 40


def test_the_scheme_reader_reads_long_strings_in_linear_memory() -> None:
    assert _peak_mb(lambda: list(read('"' + "a" * N + '"'))) < 40

    def unterminated() -> None:
        with pytest.raises(SchemeError):
            list(read('"' + "a" * N))

    assert _peak_mb(unterminated) < 40
