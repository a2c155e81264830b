"""The shape index behind anticipation finds the same precondition event as a scan."""

from __future__ import annotations

import random

from robocog.nars import NAR
from robocog.nars.narsese import parse_term
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


def test_indexed_precondition_lookup_matches_scan() -> None:
    rng = random.Random(3)
    nar = NAR(seed=3)
    nar.output = lambda _line: None
    names = [f"n{i}" for i in range(8)]
    for _ in range(120):
        a, b = rng.choice(names), rng.choice(names)
        nar.add_input(f"<{a} --> [{b}]>. :|:")
    groups = nar._ground_spikes()
    sources = [parse_term(f"<$1 --> [{n}]>") for n in names]
    sources += [parse_term(f"<{n} --> [$1]>") for n in names]
    sources += [parse_term("<$1 --> $2>"), parse_term("<$1 --> [nothing]>")]
    sources += [parse_term(f"(<$1 --> [{n}]> &/ <$1 --> [{m}]>)") for n in names for m in names]
    found = 0
    for s in sources:
        want = _scan(nar, s)
        assert nar._source_spike(s, groups) is want
        found += want is not None
    assert found > len(names)  # the check compared real events, not only misses
