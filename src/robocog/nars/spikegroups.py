"""The groups of the occurrence-time index, by which a precondition with variables finds
its newest instance without unifying it with every recent concept.

A concept without variables that has received an event is in one group per key of its
term: ``None`` (all of them), its connector and arity, and each of its components at
each position (a path of connector, arity and index from the top). An instance of a
precondition is in every group of the precondition's ground components, so the
smallest of those is scanned. Each group is a dict ordered oldest to newest; the
sensorimotor functions (``spike_groups``, ``note_event``, ``forget_concept``) keep them
in step with the index.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .memory import Concept
    from .terms import Term


def group_keys(t: Term, ground_only: bool = False) -> list[object]:
    """The keys of every group of ``sensorimotor.spike_groups`` that ``t`` belongs to. With
    ``ground_only``, those of its components without variables: a ground term matching
    ``t`` (a precondition with variables) is in every one of those groups, so the
    smallest of them will do for finding it."""
    keys: list[object] = [None]
    if t.op is None:
        return keys
    keys.append((t.op, len(t.args)))
    # A component's path is one string, each step "connector NUL arity NUL index SOH"
    # (no connector holds a NUL): a string keeps its hash, so a key of a path and a
    # term hashes in two reads, where a tuple of the steps would hash every step each
    # time a concept enters or leaves its groups.
    stack: list[tuple[str, Term]] = [("", t)]
    while stack:
        path, x = stack.pop()
        step = f"{x.op}\0{len(x.args)}\0"
        for i, arg in enumerate(x.args):
            sub = f"{path}{step}{i}\1"
            if not (ground_only and arg.has_var):
                keys.append((sub, arg))
            if arg.op is not None:
                stack.append((sub, arg))
    return keys


#: group key -> its members, oldest first (an alias the compiled engine reads as a dict)
Groups = dict[object, dict["Concept", None]]


def group_add(groups: Groups, c: Concept, keys: Sequence[object]) -> None:
    """Make ``c`` (its term without variables) the newest member of its groups,
    entering it or moving it to the end."""
    for k in keys:
        d = groups.get(k)
        if d is None:
            groups[k] = {c: None}
        else:
            d.pop(c, None)
            d[c] = None


def group_remove(groups: Groups, c: Concept, keys: Sequence[object]) -> None:
    """Take ``c`` (its term without variables) out of its groups, dropping groups left
    empty."""
    for k in keys:
        d = groups.get(k)
        if d is not None:
            d.pop(c, None)
            if not d and k is not None:
                del groups[k]
