"""AgentSpeak terms: variables, literals, lists, strings, numbers and expressions.

Numbers are Python ``int``/``float`` and strings are Python ``str``, so the common cases
cost nothing to build or compare. Atoms are literals without arguments. Literals are
immutable, hashable and remember whether they are ground, which lets the unifier and
the substitution skip work on the (very common) ground terms.

Printing follows Jason: integral numbers without ``.0``, strings quoted inside terms,
lists as ``[1,2]`` and annotations as ``p(a)[source(self)]``.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterable, Iterator
from typing import Any

from robocog.bdi.numbers import java_double_str, number_str  # noqa: F401 - part of this API

Term = Any  # Var | Literal | Cons | Nil | Arith | Rel | And | Or | Not | Body | str | int | float

_fresh = itertools.count(1)
_new = object.__new__


class Var:
    """A logic variable; identity (not the name) distinguishes variables."""

    __slots__ = ("name",)

    def __init__(self, name: str = "_") -> None:
        self.name = name

    def __repr__(self) -> str:
        return self.name


def fresh_var() -> Var:
    """A new variable that cannot clash with any variable written in a program."""
    return Var(f"_{next(_fresh)}")


class Literal:
    """``~functor(args)[annots]``: an atom, a structure, a belief or a goal.

    ``annots`` is a tuple kept sorted in Jason's term order and free of duplicates.
    """

    __slots__ = ("functor", "args", "annots", "neg", "ground", "_hash")

    def __init__(
        self,
        functor: str,
        args: tuple = (),
        annots: tuple = (),
        neg: bool = False,
    ) -> None:
        self.functor = functor
        self.args = args
        self.annots = annots
        self.neg = neg
        g = True
        for a in args:
            if not is_ground(a):
                g = False
                break
        if g:
            for a in annots:
                if not is_ground(a):
                    g = False
                    break
        self.ground = g
        self._hash = None

    @staticmethod
    def make(functor: str, args: tuple, annots: tuple, neg: bool, ground: bool) -> Literal:
        """Build without re-checking groundness (the caller knows it)."""
        obj = _new(Literal)
        obj.functor = functor
        obj.args = args
        obj.annots = annots
        obj.neg = neg
        obj.ground = ground
        obj._hash = None
        return obj

    @property
    def arity(self) -> int:
        """Number of arguments."""
        return len(self.args)

    @property
    def key(self) -> tuple:
        """Predicate indicator used to index beliefs and plans."""
        return (self.functor, len(self.args), self.neg)

    def is_atom(self) -> bool:
        """True for a literal without arguments, annotations or negation."""
        return not self.args and not self.annots and not self.neg

    def with_annots(self, annots: Iterable[Term]) -> Literal:
        """A copy with exactly these annotations (sorted, without duplicates)."""
        return Literal(self.functor, self.args, sort_annots(annots), self.neg)

    def add_annots(self, extra: Iterable[Term]) -> Literal:
        """A copy with ``extra`` annotations merged in."""
        extra = tuple(extra)
        if not extra:
            return self
        return Literal(self.functor, self.args, sort_annots(self.annots + extra), self.neg)

    def without_annots(self) -> Literal:
        """The same literal with no annotations."""
        if not self.annots:
            return self
        return Literal(self.functor, self.args, (), self.neg)

    def annot(self, functor: str) -> Literal | None:
        """The first annotation with this functor, if any."""
        for a in self.annots:
            if isinstance(a, Literal) and a.functor == functor:
                return a
        return None

    def sources(self) -> list[Term]:
        """The arguments of the ``source(_)`` annotations."""
        return [
            a.args[0]
            for a in self.annots
            if isinstance(a, Literal) and a.functor == "source" and len(a.args) == 1
        ]

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        if other.__class__ is not Literal:
            return False
        return (
            self.functor == other.functor
            and self.neg == other.neg
            and self.args == other.args
            and self.annots == other.annots
        )

    def __hash__(self) -> int:
        h = self._hash
        if h is None:
            h = hash((self.functor, self.neg, self.args, self.annots))
            self._hash = h
        return h

    def __repr__(self) -> str:
        return term_str(self)


class Nil:
    """The empty list ``[]``."""

    __slots__ = ()
    ground = True

    def __eq__(self, other: object) -> bool:
        return other.__class__ is Nil

    def __hash__(self) -> int:
        return 7

    def __repr__(self) -> str:
        return "[]"


NIL = Nil()


class Cons:
    """A list cell ``[head|tail]``; lists are chains of cells ending in ``NIL`` or a var.

    A list built from Python items by :func:`make_list` starts as its first cell alone,
    holding the items (``_items``): the internal actions that read a list whole
    (``.length``, ``.nth``, ``.sort``, ``.max``, ...) take them from there, and the
    other cells are built only when something walks the chain (the first read of
    ``tail``, through :meth:`__getattr__`, which Python calls only while that slot is
    still empty). A cell built any other way has ``_items`` None.
    """

    __slots__ = ("head", "tail", "ground", "_hash", "_items")

    def __init__(self, head: Term, tail: Term) -> None:
        self.head = head
        self.tail = tail
        self.ground = is_ground(head) and is_ground(tail)
        self._hash = None
        self._items = None

    def __getattr__(self, name: str) -> Term:
        # only reached for an empty slot: the tail of a list made by make_list
        if name != "tail":
            raise AttributeError(name)
        items = object.__getattribute__(self, "_items")
        rest = _cells(items, 1, NIL, True)
        self.tail = rest
        return rest

    def __eq__(self, other: object) -> bool:
        a, b = self, other
        while a.__class__ is Cons and b.__class__ is Cons:
            if a is b:
                return True
            if a.head != b.head:
                return False
            a, b = a.tail, b.tail
        return a == b if a.__class__ is not Cons else False

    def __hash__(self) -> int:
        h = self._hash
        if h is None:
            h = hash(("[]", tuple(iter_list(self)), repr(list_tail(self))))
            self._hash = h
        return h

    def __repr__(self) -> str:
        return term_str(self)


def _cells(items: tuple | list, start: int, tail: Term, g: bool) -> Term:
    """The chain of cells of ``items[start:]`` ending in ``tail`` (each cell's
    groundness carried along from the tail rather than recomputed)."""
    out = tail
    new = _new
    for k in range(len(items) - 1, start - 1, -1):
        item = items[k]
        c = item.__class__
        if g and not (c is int or c is float or c is str) and (c is Var or not item.ground):
            g = False
        cell = new(Cons)
        cell.head = item
        cell.tail = out
        cell.ground = g
        cell._hash = None
        cell._items = None
        out = cell
    return out


def make_list(items: Iterable[Term], tail: Term = NIL, ground: bool | None = None) -> Term:
    """Build a list term from Python items. A proper list (ending in ``[]``) is its
    first cell holding the items, the rest built when first walked (see :class:`Cons`);
    ``ground``, when the caller knows it, spares the check of every item."""
    items = tuple(items)
    if not items:
        return tail
    if tail.__class__ is not Nil:
        return _cells(items, 0, tail, is_ground(tail))
    if ground is None:
        ground = True
        for item in items:
            c = item.__class__
            if not (c is int or c is float or c is str) and (c is Var or not item.ground):
                ground = False
                break
    cell = _new(Cons)
    cell.head = items[0]
    cell.ground = ground
    cell._hash = None
    cell._items = items
    return cell


def list_items(t: Term) -> tuple | list | None:
    """The elements of a proper list (``None`` for anything else): the items a list
    made by :func:`make_list` holds, without walking its cells."""
    if t.__class__ is Cons:
        items = t._items
        if items is not None:
            return items
        out = []
        while t.__class__ is Cons:
            out.append(t.head)
            t = t.tail
        return out if t.__class__ is Nil else None
    if t.__class__ is Nil:
        return ()
    return None


def iter_list(t: Term) -> Iterator[Term]:
    """The elements of a list term (stops at the tail)."""
    if t.__class__ is Cons and t._items is not None:
        return iter(t._items)
    return _walk(t)


def _walk(t: Term) -> Iterator[Term]:
    while t.__class__ is Cons:
        yield t.head
        t = t.tail


def list_tail(t: Term) -> Term:
    """What ends a list: ``NIL`` for a proper list, a var or other term otherwise."""
    if t.__class__ is Cons and t._items is not None:
        return NIL
    while t.__class__ is Cons:
        t = t.tail
    return t


def is_list(t: Term) -> bool:
    """True for a proper list (ends in ``[]``)."""
    return list_tail(t).__class__ is Nil if t.__class__ in (Cons, Nil) else False


class Arith:
    """An arithmetic expression, evaluated when its variables are bound."""

    __slots__ = ("op", "left", "right")
    ground = False

    def __init__(self, op: str, left: Term, right: Term | None = None) -> None:
        self.op = op
        self.left = left
        self.right = right

    def __repr__(self) -> str:
        return term_str(self)


class Rel:
    """A relational expression: ``< <= > >= == \\== = \\= =..``."""

    __slots__ = ("op", "left", "right")
    ground = False

    def __init__(self, op: str, left: Term, right: Term) -> None:
        self.op = op
        self.left = left
        self.right = right

    def __repr__(self) -> str:
        return term_str(self)


class _Junction:
    """Two formulas joined by a connective; the subclass says which (code dispatches on
    the exact class, so the two stay distinct types)."""

    __slots__ = ("left", "right")
    ground = False

    def __init__(self, left: Term, right: Term) -> None:
        self.left = left
        self.right = right

    def __repr__(self) -> str:
        return term_str(self)


class And(_Junction):
    """Conjunction ``a & b``."""

    __slots__ = ()


class Or(_Junction):
    """Disjunction ``a | b``."""

    __slots__ = ()


class Not:
    """Negation as failure ``not a``."""

    __slots__ = ("arg",)
    ground = False

    def __init__(self, arg: Term) -> None:
        self.arg = arg

    def __repr__(self) -> str:
        return term_str(self)


class Body:
    """A plan body written as a term, ``{ +b; !g }``, e.g. the argument of ``.wait``."""

    __slots__ = ("steps", "bare")
    ground = False

    def __init__(self, steps: tuple, bare: bool = False) -> None:
        self.steps = steps
        self.bare = bare  #: one formula out of a body (``H`` of ``{H; R}``): no braces

    def __repr__(self) -> str:
        return term_str(self)


class PlanTerm:
    """A plan written as a term, ``{ +!g : c <- body }``: the argument of ``.add_plan``,
    ``.wait`` or ``tellHow``. It keeps the parsed plan (an object of
    :mod:`robocog.bdi.plans`, which sits above this module) and its text as Jason prints
    it."""

    __slots__ = ("plan", "text", "bare", "label")
    ground = False

    def __init__(self, plan: Any, text: str, bare: bool = False, label: Any = None) -> None:
        self.plan = plan
        self.text = text
        self.bare = bare  #: printed without braces (a trigger, an option's plan)
        #: the label as Jason gives it (``p__1[source(self),url(...)]``), or the plan's
        self.label = label if label is not None else getattr(plan, "label", None)

    def __repr__(self) -> str:
        return term_str(self)


class RuleTerm:
    """A rule as a term, ``{ a :- b & c }`` (``tellRule``, ``.relevant_rules``, ``+R``)."""

    __slots__ = ("head", "body")
    ground = False

    def __init__(self, head: Any, body: Any) -> None:
        self.head = head
        self.body = body

    def __eq__(self, other: object) -> bool:
        return isinstance(other, RuleTerm) and (self.head, self.body) == (other.head, other.body)

    def __hash__(self) -> int:
        return hash(("rule", term_str(self)))

    def __repr__(self) -> str:
        return term_str(self)


def is_ground(t: Term) -> bool:
    """True if ``t`` contains no variables (and no unevaluated expression)."""
    c = t.__class__
    if c is int or c is float or c is str:
        return True
    if c is Var:
        return False
    return t.ground


def atom(name: str) -> Literal:
    """The atom ``name``."""
    return Literal(name)


TRUE = Literal("true")
FALSE = Literal("false")
SELF = Literal("self")
PERCEPT = Literal("percept")
SOURCE_SELF = Literal("source", (SELF,))
SOURCE_PERCEPT = Literal("source", (PERCEPT,))


def source(name: str | Term) -> Literal:
    """The annotation ``source(name)`` (one instance per agent name: every message
    received and every belief told carries one)."""
    if name.__class__ is str:
        got = _SOURCES.get(name)
        if got is None:
            got = Literal("source", (Literal(name),))
            if len(_SOURCES) < 10_000:  # agent names: a bounded set in any real system
                _SOURCES[name] = got
        return got
    return Literal("source", (name,))


_SOURCES: dict[str, Literal] = {}


# ---------------------------------------------------------------------------
# Jason's standard order of terms (used by .sort, .max, .min, < on non-numbers)


def _kind(t: Term) -> int:
    c = t.__class__
    if c is int or c is float:
        return 0
    if c is Var:
        return 4
    if c is str:
        return 1
    if c is Cons or c is Nil:
        return 2
    return 3


def compare(a: Term, b: Term) -> int:
    """Jason's term order: numbers < strings < lists < literals (by functor, then args)."""
    ka, kb = _kind(a), _kind(b)
    if ka != kb:
        return -1 if ka < kb else 1
    if ka == 0:
        return (a > b) - (a < b)
    if ka == 1:
        return (a > b) - (a < b)
    if ka == 2:
        while a.__class__ is Cons and b.__class__ is Cons:
            c = compare(a.head, b.head)
            if c:
                return c
            a, b = a.tail, b.tail
        if a.__class__ is Cons:
            return 1
        if b.__class__ is Cons:
            return -1
        return 0
    if ka == 3 and a.__class__ is Literal and b.__class__ is Literal:
        if a.functor != b.functor:
            return -1 if a.functor < b.functor else 1
        if a.neg != b.neg:
            return 1 if a.neg else -1
        for x, y in zip(a.args, b.args, strict=False):
            c = compare(x, y)
            if c:
                return c
        if len(a.args) != len(b.args):
            return -1 if len(a.args) < len(b.args) else 1
        for x, y in zip(a.annots, b.annots, strict=False):
            c = compare(x, y)
            if c:
                return c
        return (len(a.annots) > len(b.annots)) - (len(a.annots) < len(b.annots))
    sa, sb = term_str(a), term_str(b)
    return (sa > sb) - (sa < sb)


class _Key:
    __slots__ = ("t",)

    def __init__(self, t: Term) -> None:
        self.t = t

    def __lt__(self, other: _Key) -> bool:
        return compare(self.t, other.t) < 0


def sort_key(t: Term) -> tuple:
    """A key for ``sorted`` that follows :func:`compare`: (kind, the number or string
    itself) for numbers and strings, which Python then compares in C, and (kind, a key
    calling :func:`compare`) for the rest; kinds are compared first, so the two never meet."""
    c = t.__class__
    if c is int or c is float:
        return (0, t)
    if c is str:
        return (1, t)
    return (_kind(t), _Key(t))


_NUMBERS = frozenset((int, float))
_STRINGS = frozenset((str,))


def _plain(items: tuple | list) -> bool:
    """True when ``items`` are all numbers or all strings: then Python's own order is
    :func:`compare`'s, and a sort or a maximum needs no key per item."""
    kinds = set(map(type, items))
    return kinds <= _NUMBERS or kinds == _STRINGS


def sorted_terms(items: tuple | list) -> list:
    """``items`` sorted in Jason's term order (stable)."""
    if _plain(items):
        return sorted(items)
    return sorted(items, key=sort_key)


def max_term(items: tuple | list) -> Term:
    """The first greatest of ``items`` (not empty) in Jason's term order."""
    return max(items) if _plain(items) else max(items, key=sort_key)


def min_term(items: tuple | list) -> Term:
    """The first least of ``items`` (not empty) in Jason's term order."""
    return min(items) if _plain(items) else min(items, key=sort_key)


class AnnotTail:
    """The ``|T`` ending a pattern's annotations (``p[a|T]``): matched against a literal,
    ``T`` takes the list of the annotations the pattern's others leave. It is always
    the last of a literal's annotations."""

    __slots__ = ("var",)
    ground = False

    def __init__(self, var: Term) -> None:
        self.var = var

    def __eq__(self, other: object) -> bool:
        return other.__class__ is AnnotTail and other.var == self.var  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash(("|", self.var))

    def __repr__(self) -> str:
        return "|" + term_str(self.var)


def sort_annots(annots: Iterable[Term]) -> tuple:
    """Annotations in Jason's order, without duplicates (a tail ``|T`` last)."""
    seen: list[Term] = []
    tail = None
    # a set of the annotations seen keeps this linear (a list's ``in`` made 20,000
    # annotations take half a minute); terms are hashable, equal ones hash equally
    known: set[Term] = set()
    for a in annots:
        if a.__class__ is AnnotTail:
            tail = a
        elif a not in known:
            known.add(a)
            seen.append(a)
    if len(seen) > 1:
        seen.sort(key=_Key)
    if tail is not None:
        seen.append(tail)
    return tuple(seen)


# ---------------------------------------------------------------------------
# Printing, as Jason's toString


_PLAIN_ATOM = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.")


def string_str(s: str) -> str:
    """A string as Jason prints it inside a term: quoted, with escapes."""
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def term_str(t: Term) -> str:
    """Jason's text for a term."""
    out: list[str] = []
    _write(t, out)
    return "".join(out)


#: functors written as they are; any other (``'Quoted atom'``) is written in quotes
#: what joins a namespace to a functor: ``ns::b`` is the literal ``b`` of namespace ``ns``
#: (the default namespace is written without one)
NS_SEP = "::"
_PLAIN_FUNCTOR = re.compile(r"\.?[a-z~][a-zA-Z0-9_]*(\.[a-zA-Z_][a-zA-Z0-9_]*)*\Z|[+\-*/<>=\\]+\Z")


def _write(t: Term, out: list[str]) -> None:
    c = t.__class__
    if c is Literal:
        if t.neg:
            out.append("~")
        f = t.functor
        if NS_SEP in f and not f.startswith("'"):
            ns, _sep, f = f.rpartition(NS_SEP)
            out.append(ns + NS_SEP)
        out.append(f if _PLAIN_FUNCTOR.match(f) else "'" + f + "'")
        if t.args:
            out.append("(")
            first = True
            for a in t.args:
                if not first:
                    out.append(",")
                first = False
                _write(a, out)
            out.append(")")
        if t.annots:
            out.append("[")
            first = True
            for a in t.annots:
                if a.__class__ is AnnotTail:
                    out.append("|")
                    a = a.var
                elif not first:
                    out.append(",")
                first = False
                _write(a, out)
            out.append("]")
    elif c is int or c is float:
        out.append(number_str(t))
    elif c is str:
        out.append(string_str(t))
    elif c is Var:
        out.append(t.name)
    elif c is Cons or c is Nil:
        out.append("[")
        first = True
        while t.__class__ is Cons:
            if not first:
                out.append(",")
            first = False
            _write(t.head, out)
            t = t.tail
        if t.__class__ is not Nil:
            out.append("|")
            _write(t, out)
        out.append("]")
    elif c is Arith:
        if t.op == "call":
            _write(t.left, out)
        elif t.right is None:
            out.append("(" + t.op)
            _write(t.left, out)
            out.append(")")
        else:
            out.append("(")
            _write(t.left, out)
            out.append(t.op if t.op not in ("div", "mod") else f" {t.op} ")
            _write(t.right, out)
            out.append(")")
    elif c is Rel:
        out.append("(")
        _write(t.left, out)
        out.append(f" {t.op} ")
        _write(t.right, out)
        out.append(")")
    elif c is And or c is Or:
        out.append("(")
        _write(t.left, out)
        out.append(" & " if c is And else " | ")
        _write(t.right, out)
        out.append(")")
    elif c is Not:
        out.append("not (")
        _write(t.arg, out)
        out.append(")")
    elif c is Body:
        if t.bare:
            out.append("; ".join(str(s) for s in t.steps))
        else:
            out.append("{ " + "; ".join(str(s) for s in t.steps) + " }")
    elif c is PlanTerm:
        out.append(t.text if t.bare else "{ " + t.text + " }")
    elif c is RuleTerm:
        out.append("{ ")
        _write(t.head, out)
        out.append(" :- ")
        _write(t.body, out)
        out.append(" }")
    else:
        out.append(str(t))


def print_str(t: Term) -> str:
    """How ``.print`` shows one argument: strings bare, everything else as a term."""
    if t.__class__ is str:
        return t
    if t.__class__ is Var:
        return t.name + "<no-value>"
    return term_str(t)
