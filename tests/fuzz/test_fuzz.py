"""The fuzz harness in the normal test run: every kept case replayed, and a short
deterministic run of every target (the long run: ``python -m tests.fuzz``)."""

from __future__ import annotations

import pytest

from tests.fuzz import runner
from tests.fuzz.targets import targets

#: generous here: the suite runs on shared cores; the harness itself counts 2 s as slow
SLOW = 10.0
#: targets whose reader's bounds are not all in place yet (their cases are kept, and
#: run by ``python -m tests.fuzz``, but not asserted here)
OPEN: set[str] = set()

TARGETS = targets()
CASES = runner.regressions()


@pytest.mark.parametrize(("name", "path"), CASES, ids=[f"{n}/{p.stem}" for n, p in CASES] or None)
def test_kept_case(name: str, path) -> None:  # noqa: ANN001
    if name in OPEN:
        pytest.skip(f"{name}: its reader's bounds are not all in place yet")
    o = runner.run_one(TARGETS[name], runner.load_regression(path), slow=SLOW)
    assert o.kind in ("ok", "refused"), f"{name} {path.name}: {o.kind}: {o.message}"


@pytest.mark.parametrize("name", sorted(set(TARGETS) - OPEN))
def test_short_run(name: str) -> None:
    tally = runner.fuzz(TARGETS[name], count=40, seconds=30.0, seed=1, slow=SLOW, keep=False)
    assert tally.inputs > 0
    assert tally.failures == 0, runner.report([tally])


def test_every_reader_has_a_target() -> None:
    assert {
        "narsese",
        "nars-shell",
        "agentspeak",
        "mas2j",
        "atomese",
        "pddl-domain",
        "pddl-problem",
        "english",
        "nars-memory",
        "sqlite-atomspace",
        "inspector-api",
        "bridge",
    } <= set(TARGETS)


def test_a_crash_is_counted() -> None:
    """The harness itself: a reader raising an undocumented error is a crash, its
    documented error is a refusal, a huge allocation is big."""
    from tests.fuzz.targets import Target

    def reader(data: bytes) -> None:
        if data == b"bad":
            raise IndexError("out of range")
        if data == b"big":
            _ = bytearray(200 << 20)
        raise ValueError("refused")

    t = Target("t", reader, (ValueError,), lambda: [b"x"])
    assert runner.run_one(t, b"bad").kind == "crash"
    assert runner.run_one(t, b"x").kind == "refused"
    assert runner.run_one(t, b"big").kind == "big"
