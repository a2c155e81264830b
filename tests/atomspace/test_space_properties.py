"""Frames and copy-on-write copies against a plain model: random edits on a family of
spaces must leave each one with exactly the atoms, incoming sets and type sets that a
space built from scratch with the same content would have."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.atomspace import AtomSpace, Link

from .conftest import C, ev

BLOCKS = [C(n) for n in "abcde"]
facts = st.one_of(
    st.builds(lambda a, b: ev("on", a, b), st.sampled_from(BLOCKS), st.sampled_from(BLOCKS)),
    st.builds(lambda a: ev("clear", a), st.sampled_from(BLOCKS)),
    st.builds(lambda a, b: Link("SetLink", a, b), st.sampled_from(BLOCKS), st.sampled_from(BLOCKS)),
)
ops = st.lists(
    st.tuples(
        st.sampled_from(["add", "remove", "remove-node", "copy", "child"]),
        st.integers(min_value=0, max_value=7),
        facts,
    ),
    max_size=40,
)


def closure(atoms: set) -> set:
    """The atoms with every outgoing atom, transitively."""
    out = set()
    todo = list(atoms)
    while todo:
        a = todo.pop()
        if a in out:
            continue
        out.add(a)
        todo.extend(getattr(a, "out", ()))
    return out


def check(space: AtomSpace, model: set) -> None:
    assert set(space) == model
    assert len(space) == len(model)
    reference = AtomSpace()
    for a in model:
        reference.add(a)
    for a in model:
        assert set(space.incoming(a)) == set(reference.incoming(a)), a
        assert a in space
    for t in ("ConceptNode", "PredicateNode", "EvaluationLink", "ListLink", "SetLink"):
        assert space.get_by_type(t) == reference.get_by_type(t)
    assert space.signature() == frozenset(model)


@settings(max_examples=150, deadline=None)
@given(ops)
def test_random_edits_on_frames_and_copies(operations: list) -> None:
    spaces = [AtomSpace()]
    models: list[set] = [set()]
    framed: list[bool] = [False]  # a space with frames over it is no longer edited
    for op, which, fact in operations:
        i = which % len(spaces)
        s, m = spaces[i], models[i]
        if op in ("add", "remove", "remove-node") and framed[i]:
            continue
        if op == "add":
            s.add(fact)
            m |= closure({fact})
        elif op == "remove":
            if fact in m:
                assert s.remove(fact, recursive=True)
                doomed = {fact}
                changed = True
                while changed:  # every link that holds a doomed atom goes too
                    changed = False
                    for a in list(m):
                        if a not in doomed and any(x in doomed for x in getattr(a, "out", ())):
                            doomed.add(a)
                            changed = True
                m -= doomed
            else:
                assert not s.remove(fact, recursive=True)
        elif op == "remove-node":
            node = BLOCKS[which % len(BLOCKS)]
            held = any(node in getattr(a, "out", ()) for a in m)
            assert s.remove(node) == (node in m and not held)
            if node in m and not held:
                m.discard(node)
        elif op == "copy":
            spaces.append(s.copy())
            models.append(set(m))
            framed.append(False)
        else:
            spaces.append(s.child())
            models.append(set(m))
            framed.append(False)
            framed[i] = True
        check(s, m)
    for sp, mo in zip(spaces, models, strict=True):
        check(sp, mo)
