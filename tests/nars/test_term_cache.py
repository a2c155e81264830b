"""Per-term properties and stamp operations against their plain definitions.

The engine computes these once per interned term or with C-level shortcuts; each test
recomputes the property the slow, obvious way and demands the same answer.
"""

from __future__ import annotations

from collections import Counter

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.nars import rules, terms
from robocog.nars.filters import _rejected, rejected
from robocog.nars.matchers import MATCHERS
from robocog.nars.narsese import parse_term
from robocog.nars.stamp import has_duplicate, merge, overlap
from robocog.nars.terms import F_IMAGE_ARGUMENT, Term, atom, compound, names_repeat

_ATOMS = ["a", "b", "c", "$1", "#1", "?1"]
_OPS = ["-->", "<->", "==>", "&&", "*", "|", "&", "-", "~", "/1", "{}", "[]"]


def _terms(depth: int = 3) -> st.SearchStrategy[Term]:
    leaf = st.sampled_from(_ATOMS).map(atom)
    return st.recursive(
        leaf,
        lambda inner: st.tuples(st.sampled_from(_OPS), inner, inner).map(
            lambda x: compound(x[0], (x[1], x[2]))
        ),
        max_leaves=2**depth,
    )


def _bfs_atoms(t: Term) -> list[Term]:
    out, level = [], [t]
    while level:
        nxt = []
        for x in level:
            if x.op is None:
                out.append(x)
            else:
                nxt.extend(x.args)
        level = nxt
    return out


@given(_terms())
def test_index_names_are_distinct_names_in_breadth_first_order(t: Term) -> None:
    expected = tuple(dict.fromkeys(a for a in _bfs_atoms(t) if not a.is_var))
    assert t.index_names() == expected
    assert t.level_order_atoms() == _bfs_atoms(t)


@given(_terms())
def test_names_repeat_counts_occurrences(t: Term) -> None:
    counts = Counter(a for a in t.atoms() if not a.is_var)
    assert names_repeat(t) == any(n > 1 for n in counts.values())


@given(_terms())
def test_complexity_and_flags_follow_the_components(t: Term) -> None:
    atoms = t.atoms()
    assert t.has_var == any(a.is_var for a in atoms)
    assert t.has_dep_var == any(a.name.startswith("#") for a in atoms if a.is_var)
    assert t.n_imp == sum(1 for x in t.walk() if x.op in ("==>", "<=>"))
    images = ("/1", "/2", "\\1", "\\2")
    image_argument = len(t.args) == 2 and any(a.op in images for a in t.args)
    assert bool(t.flags & F_IMAGE_ARGUMENT) == image_argument


@given(st.sampled_from(_OPS + ["=/>", "<=>", "&/", "!", "||"]), _terms(2), _terms(2))
def test_a_terms_connector_is_the_one_object_of_its_name(op: str, a: Term, b: Term) -> None:
    # the hot paths test connectors by identity: a connector spelled by a parser or a
    # caller (an equal string, not the same object) must still give the named object
    spelled = "".join(list(op))
    args = (a,) if op == "!" else (a, b)
    t = compound(spelled, args)
    assert t.op == op
    assert t.op is terms.CONNECTORS[op]
    if op == "==>":
        assert t.op is terms.IMPLICATION


def test_rejected_filters_known_cases() -> None:
    assert rejected(parse_term("<a --> a>"))
    assert rejected(parse_term("<(a * b) --> (a * c)>"))
    assert rejected(parse_term("<#1 --> a>"))
    assert rejected(parse_term("<<a --> b> ==> <a --> b>>"))
    assert not rejected(parse_term("<a --> b>"))
    assert not rejected(parse_term("<<$1 --> b> ==> <$1 --> c>>"))
    assert not _rejected(parse_term("<(a * b) --> r>"))


_stamps = st.lists(st.integers(1, 40), max_size=10, unique=True).map(tuple)


@given(_stamps, _stamps, st.integers(1, 12))
def test_merge_interleaves_and_truncates(a: tuple[int, ...], b: tuple[int, ...], k: int) -> None:
    expected: list[int] = []
    for i in range(max(len(a), len(b))):
        expected += a[i : i + 1] + b[i : i + 1]
    assert merge(a, b, k) == tuple(expected[:k])


@given(_stamps, _stamps)
def test_overlap_and_duplicates(a: tuple[int, ...], b: tuple[int, ...]) -> None:
    assert overlap(a, b) == any(x in b for x in a)
    assert has_duplicate(a + b) == overlap(a, b)


@given(st.lists(st.integers(1, 2**62), max_size=10))
def test_duplicates_among_large_ids(ids: list[int]) -> None:
    assert has_duplicate(tuple(ids)) == (len(set(ids)) < len(ids))


def test_the_remembered_premise_pairs_shrink_for_new_pairs_and_grow_for_old_ones(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(rules, "REMEMBERED_PAIRS", 64)
    monkeypatch.setattr(rules, "REMEMBERED_PAIRS_LEAST", 16)
    table = rules.RuleTable(6, MATCHERS)
    fresh = rules.RuleTable(6, MATCHERS)
    assert table.pairs_limit == 64
    # a stream of statements never seen before: every pair is new
    for i in range(400):
        t1 = parse_term(f"<p{i} --> q{i}>")
        t2 = parse_term(f"<q{i} --> r{i}>")
        assert table.conclusions(t1, t2) == fresh.conclusions(t1, t2)
    assert table.pairs_limit == 16
    # a few pairs met again and again (a robot's loop): remembered in full again
    pairs = [(parse_term(f"<s{i} --> t{i}>"), parse_term(f"<t{i} --> u>")) for i in range(6)]
    for _ in range(40):
        for t1, t2 in pairs:
            assert table.conclusions(t1, t2) == fresh.conclusions(t1, t2)
        for i in range(3):
            table.conclusions(parse_term(f"<v{_} --> w{i}>"), parse_term(f"<w{i} --> x>"))
    assert table.pairs_limit == 64


def test_sweep_drops_unreferenced_subtrees_in_one_pass_and_keeps_held_terms() -> None:
    from robocog.nars import terms

    held = compound("-->", (atom("sweep_x"), compound("*", (atom("sweep_a"), atom("sweep_b")))))

    def chain(i: int) -> None:
        t = atom(f"sweep_z{i}")
        for j in range(5):
            t = compound("*", (t, atom(f"sweep_w{i}_{j}")))

    for i in range(200):
        chain(i)
    before = terms.interned_count()
    terms._sweep()
    gone = before - terms.interned_count()
    assert gone >= 200 * 11  # every chain: 6 names and 5 products
    assert compound("*", (atom("sweep_a"), atom("sweep_b"))) is held.args[1]
    assert str(held) == "<sweep_x --> (sweep_a * sweep_b)>"
    # what the sweep dropped is made again on demand, as a new interned term
    again = compound("*", (atom("sweep_z0"), atom("sweep_w0_0")))
    assert again is compound("*", (atom("sweep_z0"), atom("sweep_w0_0")))


def test_a_term_whose_variable_form_is_itself_is_still_swept() -> None:
    """The forms kept on a term must not hold the term itself, or the sweep, which
    drops terms only the table holds, would keep it forever."""
    from robocog.nars import terms
    from robocog.nars.rules import variable_forms

    def make() -> None:
        t = compound("-->", (atom("swept_self_a"), atom("swept_self_b")))
        assert variable_forms(t) == (t,)
        assert variable_forms(t) == (t,)  # read back from the term

    make()
    key = ("-->", (atom("swept_self_a"), atom("swept_self_b")))
    terms._sweep()
    assert key not in terms._TABLE
    # an implication keeps its forms with variables, which are other terms
    imp = parse_term("<<s1 --> p> =/> <s2 --> p>>")
    assert all(v is not imp for v in variable_forms(imp))


def test_a_dead_terms_variable_forms_go_in_the_same_sweep() -> None:
    """A term's variable forms are interned after it, so the sweep's newest-first pass
    meets them while the term still holds them; they, and the components only they
    hold, must still go in that sweep, not one later (the table would otherwise reach
    twice its size before they go)."""
    from robocog.nars import terms
    from robocog.nars.rules import variable_forms

    def make() -> list[str]:
        imp = parse_term("<<swept_form_s1 --> swept_form_p> =/> <swept_form_s2 --> swept_form_p>>")
        forms = variable_forms(imp)
        assert forms and all(v is not imp for v in forms)
        # the forms and their new components: <swept_form_s1 --> $1> and the other side
        return [str(x) for v in forms for x in (v, *v.args)]

    made = make()
    assert any("$1" in x for x in made)
    terms._sweep()
    left = {str(t) for t in terms._TABLE.values()}
    assert not left & set(made)


def test_an_early_sweep_waits_for_half_the_room_then_sweeps(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """``sweep_early`` (a robot's between-cycles sweep) sweeps once the table has grown
    half-way from its size after the last sweep to the size at which interning would
    sweep it, and not before: a table of live terms is not swept at every call."""
    from robocog.nars import terms

    monkeypatch.setattr(terms, "_SWEPT_TO", [0])
    terms._sweep()
    base = terms.interned_count()
    assert terms._SWEPT_TO[0] == base
    monkeypatch.setattr(terms, "_SWEEP_AT", [base + 100])
    for i in range(40):
        atom(f"early_sweep_{i}")  # held by nothing: dead at once
    assert terms.sweep_early() == 0
    assert terms.interned_count() == base + 40
    for i in range(40, 60):
        atom(f"early_sweep_{i}")
    assert terms.sweep_early() >= 60
    assert terms.interned_count() <= base
    # right after it, nothing is due, however full the table is of live terms
    assert terms.sweep_early() == 0
