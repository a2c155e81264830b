"""Helpers of the standard Scheme procedures (:mod:`robocog.atomspace.schemelib`):
lists, strings, sorting, continuations and output capture."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from robocog.atomspace.scheme import (
    UNSPECIFIED,
    ControlFlow,
    Pair,
    Primitive,
    SchemeError,
    Sym,
    Throw,
    Vector,
    shorten,
    sym,
    to_text,
)

if TYPE_CHECKING:
    from robocog.atomspace.scheme import Scheme


def _w(x: Any) -> str:
    return shorten(to_text(x), 80)


def _list_of(x: Any, who: str) -> list:
    if not isinstance(x, list):
        raise SchemeError("wrong-type-arg", f"In procedure {who}: Wrong type argument: {_w(x)}")
    return x


def _equal(a: Any, b: Any) -> bool:
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, Sym) or isinstance(b, Sym):
        return a is b
    if isinstance(a, int | float | Fraction) and isinstance(b, int | float | Fraction):
        return type(a) is type(b) and a == b
    return type(a) is type(b) and a == b


def _num(x: Any, who: str) -> Any:
    if isinstance(x, bool) or not isinstance(x, int | float | Fraction):
        raise SchemeError("wrong-type-arg", f"In procedure {who}: Wrong type argument: {_w(x)}")
    return x


class _Escape(ControlFlow):
    def __init__(self, value: Any, tag: object) -> None:
        super().__init__()
        self.value = value
        self.tag = tag


def _callcc(s: Scheme, f: Any) -> Any:
    """Escaping continuations only (enough for early exits from loops)."""
    tag = object()

    def k(*vals: Any) -> Any:
        raise _Escape(vals[0] if len(vals) == 1 else list(vals), tag)

    try:
        return s.apply(f, [Primitive(k, "continuation")])
    except _Escape as e:
        if e.tag is tag:
            return e.value
        raise


def _with_output(s: Scheme, f: Any, redirect: bool = False) -> str:
    import io

    buf = io.StringIO()
    old = s.out
    try:
        if redirect:
            s.out = buf
            s.apply(f, [])
        else:
            s.apply(f, [buf])
    finally:
        s.out = old
    return buf.getvalue()


def _dynamic_wind(s: Scheme, before: Any, thunk: Any, after: Any) -> Any:
    s.apply(before, [])
    try:
        return s.apply(thunk, [])
    finally:
        s.apply(after, [])


def _hkey(k: Any) -> Any:
    if isinstance(k, list):
        return ("__list__", tuple(_hkey(x) for x in k))
    return k


def _defined(s: Scheme, name: Any) -> bool:
    try:
        s.globals.find(name)
        return True
    except SchemeError:
        return False


def _raise(key: Any, msg: Any, args: Any) -> Any:
    raise Throw(key, [msg, args])


def _bad(who: str, x: Any) -> Any:
    raise SchemeError("wrong-type-arg", f"In procedure {who}: Wrong type argument: {_w(x)}")


def _str(x: Any, who: str) -> str:
    if not isinstance(x, str) or isinstance(x, Sym):
        _bad(who, x)
    return str(x)


def _index(x: Any, c: Any) -> Any:
    i = _str(x, "string-index").find(str(c))
    return False if i < 0 else i


def _sqrt(x: Any) -> Any:
    x = _num(x, "sqrt")
    if isinstance(x, int) and x >= 0:
        r = math.isqrt(x)
        if r * r == x:
            return r
    if x < 0:
        raise SchemeError(
            "wrong-type-arg", "sqrt of a negative number (complex numbers are not supported)"
        )
    return math.sqrt(x)


def _string_to_number(x: Any, radix: int = 10) -> Any:
    from robocog.atomspace.schemedata import atom_value

    text = _str(x, "string->number").strip()
    if not text:
        return False
    if radix != 10:
        try:
            return int(text, radix)
        except ValueError:
            return False
    v = atom_value(text)
    return v if isinstance(v, int | float | Fraction) and not isinstance(v, bool) else False


def _append(*lists: Any) -> Any:
    if not lists:
        return []
    out: list = []
    for lst in lists[:-1]:
        out.extend(_list_of(lst, "append"))
    last = lists[-1]
    if isinstance(last, list):
        return out + last
    value: Any = last
    for y in reversed(out):
        value = Pair(y, value)
    return value


def _mem(x: Any, lst: Any, eq: Any) -> Any:
    lst = _list_of(lst, "member")
    for i, y in enumerate(lst):
        if eq(x, y):
            return lst[i:]
    return False


def _ass(x: Any, lst: Any, eq: Any) -> Any:
    for entry in _list_of(lst, "assoc"):
        key = (
            entry.car
            if isinstance(entry, Pair)
            else entry[0]
            if isinstance(entry, list) and entry
            else None
        )
        if key is not None and eq(x, key):
            return entry
    return False


def _assoc_ref(lst: Any, k: Any) -> Any:
    e = _ass(k, lst, _equal)
    if e is False:
        return False
    return e.cdr if isinstance(e, Pair) else e[1:]


def _delete_duplicates(lst: Any, *eq: Any) -> list:
    out: list = []
    for x in _list_of(lst, "delete-duplicates"):
        if not any(_equal(x, y) for y in out):
            out.append(x)
    return out


def _set_car(p: Any, v: Any) -> Any:
    if isinstance(p, Pair):
        p.car = v
    elif isinstance(p, list) and p:
        p[0] = v
    else:
        _bad("set-car!", p)
    return UNSPECIFIED


def _set_cdr(p: Any, v: Any) -> Any:
    if isinstance(p, Pair):
        p.cdr = v
    elif isinstance(p, list) and p and isinstance(v, list):
        del p[1:]
        p.extend(v)
    else:
        _bad("set-cdr!", p)
    return UNSPECIFIED


def _every(s: Scheme) -> Any:
    def every(f: Any, *lists: Any) -> Any:
        v: Any = True
        for xs in zip(*[_list_of(lst, "every") for lst in lists], strict=False):
            v = s.apply(f, list(xs))
            if v is False:
                return False
        return v

    return every


def _sort(s: Scheme, lst: Any, less: Any) -> list:
    import functools

    items = list(_list_of(lst, "sort")) if not isinstance(lst, Vector) else list(lst)

    def cmp(a: Any, b: Any) -> int:
        if s.apply(less, [a, b]) is not False:
            return -1
        if s.apply(less, [b, a]) is not False:
            return 1
        return 0

    return sorted(items, key=functools.cmp_to_key(cmp))


def _force(s: Scheme, p: Any) -> Any:
    from robocog.atomspace.scheme import Promise

    if not isinstance(p, Promise):
        return p
    if not p.done:
        p.value = s.evaluate(p.expr, p.env)
        p.done = True
    return p.value


def _call_with_values(s: Scheme, producer: Any, consumer: Any) -> Any:
    v = s.apply(producer, [])
    return s.apply(consumer, v if isinstance(v, list) else [v])


def _gensym() -> Any:
    n = [0]

    def gensym(prefix: Any = " g") -> Sym:
        n[0] += 1
        return sym(f"{prefix}{n[0]}")

    return gensym
