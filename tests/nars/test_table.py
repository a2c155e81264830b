"""Implication tables against the plain definition: a list kept sorted by expectation,
revised by scanning for the entry of the same term and kind."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.nars.event import Implication
from robocog.nars.narsese import parse_term
from robocog.nars.stamp import merge, overlap
from robocog.nars.table import Table
from robocog.nars.truth import Truth, c2w, expectation, revision

_TERMS = [
    parse_term(t) for t in ("<a =/> b>", "<c =/> b>", "<<$1 --> a> ==> <$1 --> b>>", "<d =/> b>")
]


def _reference(items: list[Implication], imp: Implication, size: int) -> list[Implication]:
    """The table after ``add_and_revise(imp)``, computed the obvious way."""
    items = list(items)

    def insert(x: Implication) -> None:
        e = expectation(x.truth)
        for i, other in enumerate(items):
            if expectation(other.truth) < e:
                items.insert(i, x)
                break
        else:
            items.append(x)
        del items[size:]

    for i, old in enumerate(items):
        if old.term is imp.term and (old.dt == 0.0) == (imp.dt == 0.0):
            del items[i]
            if imp.term.op == "==>" and overlap(old.stamp, imp.stamp):
                insert(imp if imp.truth.c > old.truth.c else old)
                return items
            w1, w2 = c2w(old.truth.c), c2w(imp.truth.c)
            dt = (w1 * old.dt + w2 * imp.dt) / (w1 + w2) if w1 + w2 > 0 else imp.dt
            insert(
                Implication(
                    imp.term,
                    revision(old.truth, imp.truth),
                    merge(old.stamp, imp.stamp, 10),
                    dt,
                    imp.creation_time,
                    imp.source,
                )
            )
            return items
    insert(imp)
    return items


_steps = st.lists(
    st.tuples(
        st.integers(0, len(_TERMS) - 1),
        st.sampled_from([0.0, 1.0, 2.0]),
        st.one_of(st.sampled_from([0.0, 0.5, 1.0]), st.floats(0.0, 1.0)),  # ties too
        st.one_of(st.sampled_from([0.3, 0.9]), st.floats(0.01, 0.95)),
        st.lists(st.integers(1, 6), max_size=3, unique=True),
        st.booleans(),  # no stamp (a failure counted by anticipation)
    ),
    max_size=40,
)


@settings(max_examples=200, deadline=None)
@given(_steps, st.integers(1, 4))
def test_table_matches_the_plain_definition(steps, size) -> None:  # noqa: ANN001
    table = Table(size)
    want: list[Implication] = []
    for k, dt, f, c, ids, evidence in steps:
        term = _TERMS[k]
        stamp = () if evidence else tuple(ids)
        imp = Implication(term, Truth(f, c), stamp, dt, 7, None)
        want = _reference(want, imp, size)
        table.add_and_revise(imp)
        assert [(x.term, x.truth, x.stamp, x.dt) for x in table.items] == [
            (x.term, x.truth, x.stamp, x.dt) for x in want
        ]
        assert len(table.items) <= size


def _state(table: Table) -> list[tuple[object, ...]]:
    """Every stored field, floats as their bits."""
    return [
        (x.term, x.truth.f.hex(), x.truth.c.hex(), x.stamp, x.dt.hex(), x.creation_time, x.source)
        for x in table.items
    ]


@settings(max_examples=200, deadline=None)
@given(_steps, st.integers(1, 4), st.integers(1, 12))
def test_a_failure_is_a_revision_by_a_stampless_link(steps, size, stamp_size) -> None:  # noqa: ANN001
    """``add_failure`` stores what ``add_and_revise`` of the stampless implication
    would, to the bit, wherever the entry sits and however long its stamp is."""
    plain, quick = Table(size), Table(size)
    for k, dt, f, c, ids, failure in steps:
        term = _TERMS[k]
        if failure:
            truth = Truth(f, c)
            plain.add_and_revise(Implication(term, truth, (), dt, 7, term), stamp_size)
            # only the term, offset, creation time and source of the link are used
            link = Implication(term, Truth(0.5, 0.5), (99,), dt, 7, term)
            quick.add_failure(link, truth, c2w(c), stamp_size)
        else:
            imp = Implication(term, Truth(f, c), tuple(ids) * 3, dt, 7, term)
            plain.add_and_revise(imp, stamp_size)
            quick.add_and_revise(imp, stamp_size)
        assert _state(quick) == _state(plain)


@settings(max_examples=200, deadline=None)
@given(
    _steps,
    st.integers(1, 4),
    st.lists(
        st.tuples(
            st.integers(0, 20), st.integers(-3, 3), st.floats(0.0, 1.0), st.floats(0.01, 0.95)
        ),
        max_size=20,
    ),
)
def test_a_failure_told_where_its_link_is_is_the_same_failure(steps, size, failures) -> None:  # noqa: ANN001
    """Told where the stored link is (anticipation walks a table in order, so it knows
    about where), one place off, or somewhere wrong, ``add_failure`` stores what it
    does when it searches for the link."""
    searched, told = Table(size), Table(size)
    for k, dt, f, c, ids, _ in steps:
        imp = Implication(_TERMS[k], Truth(f, c), tuple(ids), dt, 7, _TERMS[k])
        searched.add_and_revise(imp)
        told.add_and_revise(imp)
    for which, off, f, c in failures:
        if not told.items:
            break
        i = which % len(told.items)
        truth = Truth(f, c)
        searched.add_failure(searched.items[i], truth, c2w(c), 10)
        told.add_failure(told.items[i], truth, c2w(c), 10, i + off)
        assert _state(told) == _state(searched)
