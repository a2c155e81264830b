"""An open question pairs beliefs about its subject with beliefs about its predicate
(``questions._bridge``). A pair met again through another shared name is refused
without comparing the stamps again while the belief it was refused with is still
there; the inferences must be those of the plain triple loop."""

from __future__ import annotations

import itertools

import pytest

from robocog.nars import NAR, questions
from robocog.nars.event import ETERNAL
from robocog.nars.inference import Derivation, apply_double, rule_table
from robocog.nars.stamp import has_duplicate, merge, overlap


def _plain_bridge(s: NAR, question) -> None:  # type: ignore[no-untyped-def]
    """The bridge as it was written before: every pair's stamps compared each time."""
    if question.op is None or len(question.args) != 2 or question.has_var:
        return
    s_names = [a for a in question.args[0].atoms() if not a.is_var]
    p_names = [a for a in question.args[1].atoms() if not a.is_var]
    if not s_names or not p_names:
        return
    idx = s.memory.atom_index
    side_p: dict = {}
    for a in p_names:
        for c in itertools.islice(idx.get(a, ()), 50_000):
            if c.belief is not None:
                for x in questions._names(c.term):
                    side_p.setdefault(x, []).append(c)
    skip = set(s_names) | set(p_names)
    table = rule_table(s.config.semantic_inference_nal_level)
    done: set = set()
    for a in s_names:
        for c in list(itertools.islice(idx.get(a, ()), 50_000)):
            b1 = c.belief
            if b1 is None:
                continue
            for m in questions._names(c.term):
                if m in skip:
                    continue
                for d in side_p.get(m, ()):
                    b2 = d.belief
                    key = (c.id, d.id)
                    if c is d or b2 is None or key in done or overlap(b1.stamp, b2.stamp):
                        continue
                    done.add(key)
                    stamp = merge(b1.stamp, b2.stamp, s.config.stamp_size)
                    if has_duplicate(stamp):
                        continue
                    der = Derivation(s, ETERNAL, stamp, 1.0, 1.0)
                    apply_double(table, c.term, d.term, b1.truth, b2.truth, der)


LINES = [
    # the subject and the predicate share two middle names through several concepts,
    # so the same pair of concepts is met more than once; the beliefs derived in the
    # cycles share evidence, so most pairs are refused for overlapping stamps (about
    # 23,000 of 28,000 here), the others inferred from
    "<a --> m1>.",
    "<a --> m2>.",
    "<(a * m1) --> m2>.",
    "<m1 --> p>.",
    "<m2 --> p>.",
    "<(m1 * m2) --> p>.",
    "<a --> (m1 * m2)>.",
    "<(m1 & m2) --> p>.",
    "3",
]


def test_the_bridge_infers_what_the_plain_loop_infers(monkeypatch: pytest.MonkeyPatch) -> None:
    def session(bridge) -> list[str]:  # type: ignore[no-untyped-def]
        monkeypatch.setattr(questions, "_bridge", bridge)
        out: list[str] = []
        nar = NAR(seed=5)
        nar.output = out.append
        nar.config.print_derivations = True
        for line in [*LINES, "<p --> a>?", "<(p * m1) --> a>?", "2"]:
            nar.add_input(line)
        return out

    mine = session(questions._bridge)
    plain = session(_plain_bridge)
    assert mine == plain
    # the second question stays open: the bridge inferred from pairs of its beliefs
    assert "Answer: None." in mine
    assert sum(1 for line in mine if line.startswith("Derived:")) > 50
