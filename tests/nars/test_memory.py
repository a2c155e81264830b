"""Concept memory: eviction picks the least useful concepts, in order, ties to the oldest."""

from __future__ import annotations

import pickle

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.nars.memory import Concept, Memory
from robocog.nars.terms import atom, compound


def _expected_victims(mem: Memory, now: int) -> list[Concept]:
    """The eviction batch by definition: every concept ranked by usefulness at ``now``,
    a stable sort over the memory's order, the first ``capacity/16``."""
    cs = list(mem.concepts.values())
    ranked = sorted(cs, key=lambda c: c.usefulness(now))
    return ranked[: max(1, mem.capacity // 16)]


# one step: make a new concept (0), use a concept (1, 2 with an input boost), remove one
# (3); mostly new ones, so the memory of 32 fills and evicts many times
_steps = st.lists(
    st.tuples(st.sampled_from((0, 0, 0, 1, 2, 3)), st.integers(0, 10_000), st.integers(0, 2)),
    min_size=60,
    max_size=400,
)


def _run(steps: list[tuple[int, int, int]], reload_at: int | None = None) -> None:
    mem = Memory(capacity=32, operations=10, table_size=20, events_max=40)
    removed: list[Concept] = []
    mem.on_remove = removed.append
    now = 1
    made = 0
    for i, (kind, pick, advance) in enumerate(steps):
        if reload_at is not None and i == reload_at:
            mem = pickle.loads(pickle.dumps(mem))
            mem.on_remove = removed.append
        now += advance
        live = list(mem.concepts.values())
        if kind == 0 or not live:
            term = compound("-->", (atom(f"m{made}"), atom(f"m{made % 7}")))
            made += 1
            full = len(mem.concepts) >= mem.capacity
            expected = _expected_victims(mem, now) if full else []
            removed.clear()
            c = mem.conceptualize(term, now)
            assert removed == expected
            assert mem.find(term) is c
            for gone in expected:
                assert mem.find(gone.term) is None
        elif kind in (1, 2):
            live[pick % len(live)].use(now, kind == 2, 1000)
        else:
            victim = live[pick % len(live)]
            mem.remove(victim)
            assert mem.find(victim.term) is None


@settings(max_examples=60, deadline=None)
@given(_steps)
def test_eviction_takes_the_least_useful_oldest_first(steps: list[tuple[int, int, int]]) -> None:
    _run(steps)


@settings(max_examples=30, deadline=None)
@given(_steps, st.integers(0, 400))
def test_eviction_after_reloading_a_saved_memory(
    steps: list[tuple[int, int, int]], reload_at: int
) -> None:
    _run(steps, reload_at)


def test_a_filled_memory_evicts_in_batches() -> None:
    mem = Memory(capacity=64, operations=10, table_size=20, events_max=40)
    for i in range(200):
        mem.conceptualize(compound("-->", (atom(f"e{i}"), atom("top"))), i + 1)
    assert len(mem) <= 64
    assert mem.evictions == 200 - len(mem)
    assert len(mem.atom_index[atom("top")]) == len(mem)
