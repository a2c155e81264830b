"""ONA 0.9.3's declarative pass, indexed: the fresh beliefs filed by the shapes of the
conditions they may instantiate, the sorted links kept between cycles, and each
belief's deductions kept while nothing they were made from has changed. The pass must
conclude exactly what a plain pass over every fresh belief and every link concludes."""

from __future__ import annotations

import random

from robocog.nars import NAR
from robocog.nars import truth as tf
from robocog.nars.declarative import (
    _condition_shape,
    _term_shapes,
    declarative_links,
    forward_eternal,
)
from robocog.nars.event import BELIEF, ETERNAL, Event, revised_or_chosen
from robocog.nars.memorize import on_new_belief
from robocog.nars.narsese import parse_term
from robocog.nars.stamp import merge
from robocog.nars.terms import NEGATION
from robocog.nars.truth import expectation
from robocog.nars.unify import apply, unify

ATOMS = ["a", "b", "c", "{x}", "[y]"]
VARS = ["$1", "$2", "#1"]


def _random_term(rng: random.Random, depth: int, variables: bool) -> str:
    k = rng.random()
    if depth == 0 or k < 0.35:
        pool = ATOMS + (VARS if variables else [])
        return rng.choice(pool)
    if k < 0.6:
        return f"<{_random_term(rng, depth - 1, variables)} --> {_random_term(rng, depth - 1, variables)}>"
    if k < 0.75:
        n = rng.choice([2, 3, 4])
        return "(" + " * ".join(_random_term(rng, depth - 1, variables) for _ in range(n)) + ")"
    if k < 0.85:
        return f"(! {_random_term(rng, depth - 1, variables)})"
    return (
        f"({_random_term(rng, depth - 1, variables)} && {_random_term(rng, depth - 1, variables)})"
    )


def test_every_condition_that_unifies_is_filed_under_a_shape_of_the_term() -> None:
    rng = random.Random(7)
    unified = 0
    for _ in range(4000):
        cond = parse_term(_random_term(rng, 3, True))
        term = parse_term(_random_term(rng, 3, False))
        # a ground instance of the condition, so that many pairs unify
        if rng.random() < 0.5 and cond.has_var:
            binding = {v: parse_term(rng.choice(ATOMS)) for v in cond.atoms() if v.is_var}
            term = apply(cond, binding)
        if term.has_var:
            continue
        if unify(cond, term) is not None:
            unified += 1
            assert _condition_shape(cond) in _term_shapes(term), (cond, term)
    assert unified > 500


def _plain_pass(s: NAR) -> None:
    """The pass as written before it was indexed: every fresh belief with every link."""
    cfg = s.config
    now = s.time
    mem = s.memory
    fresh = s.fresh_beliefs
    oldest = now - cfg.belief_last_used_tolerance
    while fresh:
        c = next(iter(fresh))
        b = c.belief
        if b is not None and b.creation_time >= oldest and mem.find(c.term) is c:
            break
        del fresh[c]
    if not fresh:
        return
    tables: dict = {}
    for link in declarative_links(s):
        lc = mem.find(link)
        if link.op == "==>" and lc is not None and lc.belief is not None:
            tables.setdefault(link.args[1], []).append((link, lc.belief))
    links = []
    for entries in tables.values():
        entries.sort(key=lambda x: -expectation(x[1].truth))
        links += entries[: cfg.top_k_declarative_implications]
    derived = []
    for c in list(fresh):
        b = c.belief
        if b is None or b.creation_time < oldest or c.term.has_var:
            continue
        for link, lb in links:
            cond, concl = link.args
            if cond.op is not None and cond.op != c.term.op:
                continue
            bind = unify(cond, c.term)
            if bind is None:
                continue
            target = apply(concl, bind)
            if target.has_var:
                continue
            t = tf.deduction(lb.truth, b.truth)
            if t.c < cfg.min_confidence:
                continue
            # (as new as the newer premise: ONA's DERIVATION_STAMP)
            made = max(b.creation_time, lb.creation_time)
            derived.append(Event(target, BELIEF, t, merge(b.stamp, lb.stamp, 10), ETERNAL, made))
    for e in derived:
        if e.term.op == NEGATION and cfg.anticipation_negated_outcomes:
            e = Event(
                e.term.args[0], BELIEF, tf.negation(e.truth), e.stamp, ETERNAL, e.creation_time
            )
        tc = mem.conceptualize(e.term, now)
        old = tc.belief
        if old is not None and old.stamp == e.stamp:
            continue
        new, _ = revised_or_chosen(old, e, cfg.stamp_size)
        if new is old:
            continue
        tc.belief = new
        s.output(f"Derived: {new.line(1.0)}")
        fresh.pop(tc, None)
        fresh[tc] = None
        on_new_belief(s, tc)


def _session(lines: list[str], plain: bool) -> list[str]:
    import robocog.nars.cycle as cycle_module

    out: list[str] = []
    nar = NAR(ona="0.9.3", seed=3)
    nar.output = out.append
    nar.config.print_derivations = True
    original = cycle_module.declarative.forward_eternal
    if plain:
        cycle_module.declarative.forward_eternal = lambda s, _cb: _plain_pass(s)
    try:
        for line in lines:
            nar.add_input(line)
    finally:
        cycle_module.declarative.forward_eternal = original
    return out


def test_the_indexed_pass_concludes_what_the_plain_pass_concludes() -> None:
    rng = random.Random(11)
    names = [f"n{i}" for i in range(12)]
    lines = [
        "<<$1 --> n1> ==> <$1 --> n2>>.",
        "<<$1 --> n2> ==> (! <$1 --> n5>)>. %0.8%",
        "<<($1 * $2) --> r> ==> <($2 * $1) --> r>>.",
        "<<(n3 * $1) --> r> ==> <$1 --> n4>>. %0.7%",
        "<<$1 --> [on]> ==> <$1 --> n6>>.",
    ]
    for _ in range(40):
        k = rng.random()
        a, b = rng.sample(names, 2)
        if k < 0.5:
            lines.append(f"<{a} --> {b}>. %{rng.choice(['1.0', '0.9', '0.6'])}%")
        elif k < 0.7:
            lines.append(f"<({a} * {b}) --> r>.")
        elif k < 0.8:
            lines.append(f"<{a} --> [on]>.")
        elif k < 0.9:
            lines.append(f"<<$1 --> {a}> ==> <$1 --> {b}>>.")
        else:
            lines.append(str(rng.randrange(1, 4)))
    lines += [f"<{n} --> n2>?" for n in names[:4]]
    # (the reference ignores the shell's stamp size only where it is 10, as here)
    assert NAR(ona="0.9.3").config.stamp_size == 10
    assert forward_eternal is not _plain_pass
    indexed = _session(lines, plain=False)
    plain = _session(lines, plain=True)
    assert indexed == plain
    assert sum(1 for line in indexed if line.startswith("Derived:")) > 50
