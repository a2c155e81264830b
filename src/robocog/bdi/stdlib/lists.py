"""Lists: ``.length``, ``.member``, ``.concat``, ``.nth``, ``.max``/``.min``, ``.sort``,
``.reverse``, ``.empty``, ``.delete``, the set operations, ``.range``, ``.list``."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from robocog.bdi.containers import QueueTerm, SetTerm
from robocog.bdi.logic import ActionError
from robocog.bdi.stdlib.base import (
    arg_list,
    arg_number,
    arg_text,
    bind,
    bind_each,
    internal,
    need_args,
    unifies,
)
from robocog.bdi.terms import (
    NIL,
    Cons,
    Nil,
    Term,
    Var,
    is_ground,
    is_list,
    iter_list,
    list_items,
    make_list,
    max_term,
    min_term,
    print_str,
    sort_key,
    sorted_terms,
    term_str,
)
from robocog.bdi.unifier import deref, resolve, undo, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("length")
def _length(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "length")
    v = resolve(args[0], s)
    if v.__class__ is str:
        return bind(len(v), args[1], s, trail)
    if v.__class__ is SetTerm or v.__class__ is QueueTerm:
        return bind(len(v), args[1], s, trail)
    items = list_items(v)
    if items is None:
        return False  # Jason: neither a list nor a string has no length, and says nothing
    return bind(len(items), args[1], s, trail)


@internal("member")
def _member(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    need_args(args, 2, "member")
    coll = resolve(args[1], s)
    if coll.__class__ is SetTerm or coll.__class__ is QueueTerm:
        # a set or a queue is asked at once for a ground member, as Jason does
        x = resolve(args[0], s)
        if is_ground(x):
            return iter([None] if x in coll else [])
        return bind_each(iter(coll.members()), args[0], s, trail)
    return bind_each(iter(arg_list(coll, s, "member")), args[0], s, trail)


@internal("concat")
def _concat(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    if len(args) < 2:
        raise ActionError(".concat takes at least 2 arguments")
    parts = [resolve(a, s) for a in args[:-1]]
    if not is_list(parts[0]):
        # Jason: anything but a list first is a string concatenation of the plain values
        out = resolve(args[-1], s)
        if out.__class__ is not str and out.__class__ is not Var:
            out = term_str(out)
        return bind("".join(print_str(p) for p in parts), out, s, trail)
    items: list = []
    for p in parts:
        if not is_list(p):
            raise ActionError(f".concat: {term_str(p)} is not a list")
        items.extend(iter_list(p))
    return bind(make_list(items), args[-1], s, trail)


@internal("nth")
def _nth(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    need_args(args, 3, "nth")
    v = resolve(args[1], s)
    # a string is a list of one-character strings (its UTF-8 bytes, as Jason has it)
    items = (
        [bytes([b]).decode("latin-1") for b in v.encode("utf-8")]
        if v.__class__ is str
        else arg_list(v, s, "nth")
    )
    n = deref(args[0], s)
    if n.__class__ is Var:
        return _nth_all(items, args[0], args[2], s, trail)
    k = int(arg_number(n, s, "nth"))
    if not 0 <= k < len(items):
        raise ActionError(f"nth: index {k} is out of bounds ({len(items)})", "internal_action")
    return bind(items[k], args[2], s, trail)


def _nth_all(items: list, idx: Term, target: Term, s: dict, trail: list) -> Iterator[None]:
    mark = len(trail)
    for k, v in enumerate(items):
        if unify(idx, k, s, trail) and unify(target, v, s, trail):
            yield None
        undo(s, trail, mark)


@internal("max")
def _max(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "max")
    items = arg_list(args[0], s, "max")
    if not items:
        return False
    return bind(max_term(items), args[1], s, trail)


@internal("min")
def _min(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "min")
    items = arg_list(args[0], s, "min")
    if not items:
        return False
    return bind(min_term(items), args[1], s, trail)


@internal("sort")
def _sort(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "sort")
    v = resolve(args[0], s)
    items = list_items(v)
    if items is None:
        raise ActionError(f".sort: {term_str(v)} is not a list")
    return bind(make_list(sorted_terms(items), NIL, v.ground), args[1], s, trail)


@internal("reverse")
def _reverse(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "reverse")
    v = resolve(args[0], s)
    if v.__class__ is str:
        return bind(v[::-1], args[1], s, trail)
    return bind(make_list(arg_list(v, s, "reverse")[::-1]), args[1], s, trail)


@internal("empty")
def _empty(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "empty")
    v = resolve(args[0], s)
    return v.__class__ is Nil or v == ""


@internal("delete")
def _delete(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.delete(X, L, R)`` removes what unifies with X (a substring from a string);
    with a number first, the element at that index; ``.delete(B, E, L, R)`` the range
    from B up to E (not included), as Jason does."""
    need_args(args, 3, "delete", 4)
    what = resolve(args[0], s)
    numeric = what.__class__ is int or what.__class__ is float
    rng = None
    if numeric:
        start = int(what)
        end = start + 1
        nxt = 1
        if len(args) == 4:
            e = resolve(args[1], s)
            if e.__class__ is int or e.__class__ is float:
                end, nxt = int(e), 2
        rng = (start, end)
    elif len(args) == 4:
        raise ActionError("Incorrect use of the internal action '.delete' (see documentation).")
    else:
        nxt = 1
    v = resolve(args[nxt], s)
    target = args[nxt + 1]
    if rng is not None:
        if v.__class__ is str:
            return bind(v[: rng[0]] + v[rng[1] :], target, s, trail)
        items = arg_list(v, s, "delete")
        return bind(make_list(items[: rng[0]] + items[rng[1] :]), target, s, trail)
    if v.__class__ is str or what.__class__ is str:
        return bind(arg_text(v, s).replace(arg_text(what, s), ""), target, s, trail)
    items = arg_list(v, s, "delete")
    return bind(make_list([x for x in items if not unifies(what, x)]), target, s, trail)


@internal("union")
def _union(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "union")
    out = sorted(
        set(arg_list(args[0], s, "union")) | set(arg_list(args[1], s, "union")), key=sort_key
    )
    return bind(make_list(out), args[2], s, trail)


@internal("intersection")
def _intersection(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "intersection")
    b = set(arg_list(args[1], s, "intersection"))
    out = sorted({x for x in arg_list(args[0], s, "intersection") if x in b}, key=sort_key)
    return bind(make_list(out), args[2], s, trail)


@internal("difference")
def _difference(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "difference")
    b = set(arg_list(args[1], s, "difference"))
    out = sorted({x for x in arg_list(args[0], s, "difference") if x not in b}, key=sort_key)
    return bind(make_list(out), args[2], s, trail)


@internal("range")
def _range(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    need_args(args, 3, "range", 4)
    lo = int(arg_number(args[1], s, "range"))
    hi = int(arg_number(args[2], s, "range"))
    step = int(arg_number(args[3], s, "range")) if len(args) > 3 else 1
    if step == 0:
        raise ActionError(".range: step cannot be 0")
    v = deref(args[0], s)
    if v.__class__ is not Var:
        n = arg_number(v, s, "range")
        ok = lo <= n <= hi if step > 0 else hi <= n <= lo
        return iter([None]) if ok and (n - lo) % step == 0 else iter(())
    stop = hi + (1 if step > 0 else -1)
    return bind_each(iter(range(lo, stop, step)), args[0], s, trail)


@internal("list")
def _is_list(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "list")
    v = resolve(args[0], s)
    return v.__class__ in (Cons, Nil)
