"""Questions: the best belief answering one at once, open questions kept for later.

Functions over a :class:`~robocog.nars.state.Reasoner`. ONA answers a question when it
is input; here an unanswered one stays open (``pending_questions``), the beliefs about
its names are brought back into attention, and pairs of beliefs linking its subject to
its predicate are inferred from at once, so the next cycles can derive the answer.
"""

from __future__ import annotations

import heapq
import itertools

from .event import BELIEF, ETERNAL, Event, Implication
from .inference import Derivation, apply_double, rule_table
from .memorize import raise_priority, report_answer
from .memory import Concept
from .stamp import has_duplicate, merge, overlap
from .state import Reasoner, emit
from .terms import TEMPORAL_IMPLICATION, Term
from .truth import expectation
from .unify import may_unify, unify

PENDING_QUESTIONS = 32


def answer(s: Reasoner, question: Term, tense: str | None = None) -> Event | None:
    """Answer a question at once with the best belief, printing ONA's lines."""
    emit(s, f"Input: {question}?" + (f" {tense}" if tense else ""))
    best: Event | None = None
    best_c: Concept | None = None
    best_e = -1.0
    if question.op == TEMPORAL_IMPLICATION:
        return _answer_implication(s, question)
    for c in _candidates(s, question):
        # (most candidates share only an atom with the question: a look at their
        # connector and ground components refuses them before unification does)
        if c.term is not question and (
            not may_unify(question, c.term) or unify(question, c.term, query_only=True) is None
        ):
            continue
        cands: list[Event] = []
        if tense is None:
            if c.belief is not None:
                cands.append(c.belief)
        else:
            if tense in (":|:", ":\\:") and c.belief_spike is not None:
                cands.append(c.belief_spike)
            if tense in (":|:", ":/:") and c.predicted_belief is not None:
                cands.append(c.predicted_belief)
        for b in cands:
            ex = expectation(b.projected(s.time).truth)
            if ex >= best_e:
                best, best_c, best_e = b, c, ex
    if best is None:
        emit(s, "Answer: None.")
        if tense is None:
            _pend(s, question)
        return None
    if best_c is not None:
        raise_priority(s, best_c, s.config.question_priming)
        best_c.use(s.time, False, 0)
    report_answer(s, best)
    return best


def _answer_implication(s: Reasoner, question: Term) -> Event | None:
    """``<a =/> b>?``: the best matching link in the precondition tables."""
    best: Implication | None = None
    best_e = -1.0
    for table in s.table_index.values():
        for post in table:
            if unify(question.args[1], post.term, query_only=True) is None:
                continue
            for links in post.precondition_beliefs or ():
                for imp in links.items:
                    if imp.term is question or (
                        question.has_query_var
                        and unify(question, imp.term, query_only=True) is not None
                    ):
                        ex = expectation(imp.truth)
                        if ex >= best_e:
                            best, best_e = imp, ex
    if best is None:
        emit(s, "Answer: None.")
        return None
    e = Event(best.term, BELIEF, best.truth, best.stamp, ETERNAL, best.creation_time, best.dt)
    report_answer(s, e)
    return e


def _pend(s: Reasoner, question: Term) -> None:
    """Keep an unanswered question open and bring the beliefs about its names back
    into attention, so the next cycles can derive what it asks for.

    ONA answers only at input; here an open question is answered (one more
    ``Answer:`` line) as soon as a belief for it is derived. At most
    ``PENDING_QUESTIONS`` stay open, the oldest is dropped first.
    """
    pending = s.pending_questions
    if question in pending:
        return
    pending[question] = None
    while len(pending) > PENDING_QUESTIONS:
        del pending[next(iter(pending))]
    _bridge(s, question)
    for a in dict.fromkeys(x for x in question.atoms() if not x.is_var):
        d = s.memory.atom_index.get(a)
        if not d:
            continue
        strongest = heapq.nlargest(
            2,
            (c for c in itertools.islice(d, 200) if c.belief is not None),
            key=lambda c: c.use_count,
        )
        q = s.memory.belief_events
        for c in strongest:
            if not q.contains(c.belief):  # type: ignore[arg-type]
                q.push(c.belief.copy(), 1.0)  # type: ignore[arg-type]


def _bridge(s: Reasoner, question: Term) -> None:
    """Question-guided premise choice: pair beliefs about the question's subject
    with beliefs about its predicate that share a middle term, and infer from
    each pair at once (backward chaining one link deep)."""
    if question.op is None or len(question.args) != 2 or question.has_var:
        return
    s_names = [a for a in question.args[0].atoms() if not a.is_var]
    p_names = [a for a in question.args[1].atoms() if not a.is_var]
    if not s_names or not p_names:
        return
    idx = s.memory.atom_index
    limit = 50_000
    side_p: dict[Term, list[Concept]] = {}
    for a in p_names:
        for c in itertools.islice(idx.get(a, ()), limit):
            if c.belief is not None:
                for x in _names(c.term):
                    side_p.setdefault(x, []).append(c)
    skip = set(s_names) | set(p_names)
    table = rule_table(s.config.semantic_inference_nal_level)
    stamp_size = s.config.stamp_size
    done: set[tuple[int, int]] = set()
    # (typed for the compiled engine: the pairs are millions where the subject and the
    # predicate are in thousands of concepts, most of them refused for overlapping
    # stamps, so the refusal is tested first, on the stamps read as C values, before
    # the pair's key is made)
    c: Concept
    d: Concept
    b1: Event
    b2: Event
    m: Term
    others: list
    stamp1: tuple
    for a in s_names:
        for c in list(itertools.islice(idx.get(a, ()), limit)):
            if c.belief is None:
                continue
            b1 = c.belief
            stamp1 = b1.stamp
            for m in _names(c.term):
                if m in skip:
                    continue
                found = side_p.get(m)
                if found is None:
                    continue
                others = found
                for d in others:
                    if c is d or d.belief is None:
                        continue
                    b2 = d.belief
                    if overlap(stamp1, b2.stamp):
                        continue
                    key = (c.id, d.id)
                    if key in done:
                        continue
                    done.add(key)
                    stamp = merge(b1.stamp, b2.stamp, stamp_size)
                    if has_duplicate(stamp):
                        continue
                    der = Derivation(s, ETERNAL, stamp, 1.0, 1.0)
                    apply_double(table, c.term, d.term, b1.truth, b2.truth, der)


def _candidates(s: Reasoner, question: Term) -> list[Concept]:
    if not question.has_var:
        c = s.memory.find(question)
        return [c] if c is not None else []
    names = {a for a in question.atoms() if not a.is_var}
    best: dict[Concept, None] | None = None
    for a in names:
        d = s.memory.atom_index.get(a)
        if d is None:
            return []
        if best is None or len(d) < len(best):
            best = d
    if best is None:
        return list(s.memory)
    return list(best)


def _names(t: Term) -> list[Term]:
    return [a for a in dict.fromkeys(t.atoms()) if not a.is_var]
