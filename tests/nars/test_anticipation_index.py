"""The shape index behind anticipation finds the same precondition event as a scan."""

from __future__ import annotations

import random

from robocog.nars import NAR
from robocog.nars.narsese import parse_term
from robocog.nars.sensorimotor import source_spike, spike_groups
from robocog.nars.unify import unify


def _scan(nar: NAR, source):  # noqa: ANN001, ANN202 - reference: the plain newest-first scan
    c = nar.memory.find(source)
    best = c.belief_spike if c is not None else None
    for c2 in nar.time_index:
        b = c2.belief_spike
        if b is None or c2.term.has_var or unify(source, c2.term) is None:
            continue
        if best is None or b.occurrence_time > best.occurrence_time:
            best = b
        break
    return best


def _sources(names: list[str]) -> list:  # noqa: ANN202 - parsed terms
    sources = [parse_term(f"<$1 --> [{n}]>") for n in names]
    sources += [parse_term(f"<{n} --> [$1]>") for n in names]
    sources += [parse_term("<$1 --> $2>"), parse_term("<$1 --> [nothing]>")]
    sources += [parse_term(f"(<$1 --> [{n}]> &/ <$1 --> [{m}]>)") for n in names for m in names]
    return sources


def test_indexed_precondition_lookup_matches_scan() -> None:
    rng = random.Random(3)
    nar = NAR(seed=3)
    nar.output = lambda _line: None
    names = [f"n{i}" for i in range(8)]
    for _ in range(120):
        a, b = rng.choice(names), rng.choice(names)
        nar.add_input(f"<{a} --> [{b}]>. :|:")
    groups = spike_groups(nar)
    found = 0
    for s in _sources(names):
        want = _scan(nar, s)
        assert source_spike(nar, s, groups) is want
        found += want is not None
    assert found > len(names)  # the check compared real events, not only misses


def test_groups_follow_the_index_as_it_fills_overflows_and_loses_concepts() -> None:
    """Groups kept in step with the index agree with the scan at every step, through a
    full index dropping its oldest concepts and through evictions from memory."""
    rng = random.Random(5)
    nar = NAR(seed=5, occurrence_time_index_size=16, concepts_max=64)
    nar.output = lambda _line: None
    names = [f"n{i}" for i in range(12)]
    sources = _sources(names[:4])
    spike_groups(nar)  # built early, then only maintained
    compared = 0
    for step in range(300):
        a, b = rng.choice(names), rng.choice(names)
        nar.add_input(f"<{a} --> [{b}]>. :|:")
        if step % 10 == 0:
            for s in sources:
                want = _scan(nar, s)
                assert source_spike(nar, s) is want
                compared += want is not None
    assert len(nar.time_index) == 16
    assert nar.memory.evictions > 0
    # what was maintained is what a fresh build gives, group by group, in order
    kept = {k: list(v) for k, v in spike_groups(nar).items()}
    nar.groups = None
    assert kept == {k: list(v) for k, v in spike_groups(nar).items()}
    assert compared > 50
