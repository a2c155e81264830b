"""Interned Narsese terms.

Every term is built through :func:`atom` or :func:`compound`, which return the one
object standing for that term, so equality is identity and hashing is by address:
both O(1), which is what the hot path (concept lookup, unification, stamps of rule
matches) needs. The interning table holds terms weakly, so a stream of ever new
names does not grow memory beyond the terms still referenced by the reasoner.

Printing is ONA's canonical form (``<S --> P>``, ``(A * B)``, ``{a b}``, ``(! a)``),
so answers can be compared as text with ONA's output.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator

try:
    import cython
except ImportError:  # the pure engine without Cython installed
    from . import cy as cython

#: statement copulas, printed ``<S cop P>``
STATEMENT_COPULAS = frozenset({"-->", "<->", "==>", "<=>", "=/>", "|->"})
#: binary infix compound connectors, printed ``(A op B)``
INFIX_OPS = frozenset({"*", "&", "|", "-", "~", "&&", "||", "&/", "/1", "/2", "\\1", "\\2"})
#: unary connectors printed ``(op A)``
UNARY_OPS = frozenset({"!", "*", "+", "="})
#: set connectors
SETS = {"{}": ("{", "}"), "[]": ("[", "]")}

INHERITANCE = "-->"
SIMILARITY = "<->"
IMPLICATION = "==>"
EQUIVALENCE = "<=>"
TEMPORAL_IMPLICATION = "=/>"
SEQUENCE = "&/"
CONJUNCTION = "&&"
DISJUNCTION = "||"
NEGATION = "!"
PRODUCT = "*"
EXT_INTERSECTION = "&"
INT_INTERSECTION = "|"
EXT_SET = "{}"
INT_SET = "[]"
EXT_IMAGE1 = "/1"
EXT_IMAGE2 = "/2"
INT_IMAGE1 = "\\1"
INT_IMAGE2 = "\\2"

#: each connector's one string object. A term's ``op`` is always this object (see
#: ``_make_compound``), so a hot path may test a term's connector by identity
#: (``t.op is IMPLICATION``, with the names above): compiled, that is one pointer
#: comparison, where ``==`` of two different strings calls a string comparison.
CONNECTORS: dict[str, str] = {
    c: c
    for c in (
        INHERITANCE,
        SIMILARITY,
        IMPLICATION,
        EQUIVALENCE,
        TEMPORAL_IMPLICATION,
        SEQUENCE,
        CONJUNCTION,
        DISJUNCTION,
        NEGATION,
        PRODUCT,
        EXT_INTERSECTION,
        INT_INTERSECTION,
        EXT_SET,
        INT_SET,
        EXT_IMAGE1,
        EXT_IMAGE2,
        INT_IMAGE1,
        INT_IMAGE2,
    )
}
for _c in sorted(STATEMENT_COPULAS | INFIX_OPS | UNARY_OPS | set(SETS)):
    CONNECTORS.setdefault(_c, _c)
del _c

_VAR_PREFIXES = "$#?"


# Compiled, a term is left out of Python's cycle collector (``no_gc``): terms form no
# cycle (a term refers only to smaller terms, and to its variable forms, which have more
# variables; anticipation's record is taken off when its call ends), and a full memory
# holds hundreds of thousands of them, which every collection would otherwise walk.
@cython.no_gc
@cython.cclass
class Term:
    """One Narsese term; never build directly, use :func:`atom` / :func:`compound`."""

    __slots__ = (
        "op",
        "name",
        "args",
        "complexity",
        "_str",
        "has_var",
        "has_query_var",
        "has_indep_var",
        "has_dep_var",
        "is_var",
        "is_op",
        "cache",
        "flags",
        "n_imp",
        "n_temp",
        "_names",
        "hol",
        "forms",
        "anticipated",
        "keys",
    )

    op: str | None
    name: str | None
    args: tuple[Term, ...]

    def __reduce__(self) -> tuple[Callable[..., Term], tuple[object, ...]]:
        """Pickle as a re-interning call, so loaded terms are the interned objects."""
        if self.op is None:
            return (atom, (self.name,))
        return (compound, (self.op, self.args))

    def __repr__(self) -> str:
        return f"Term({self})"

    def __str__(self) -> str:
        s = self._str
        if s is None:
            s = self._str = _render(self)
        return s

    # ------------------------------------------------------------------ queries
    @property
    def is_atom(self) -> bool:
        """True for names and variables."""
        return self.op is None

    @property
    def is_statement(self) -> bool:
        """True for copula terms (``-->``, ``<->``, ``==>``, ``<=>``, ``=/>``, ``|->``)."""
        return self.op in STATEMENT_COPULAS

    @property
    def subject(self) -> Term:
        """First argument of a binary term."""
        return self.args[0]

    @property
    def predicate(self) -> Term:
        """Second argument of a binary term."""
        return self.args[1]

    def walk(self) -> Iterator[Term]:
        """All subterms, depth first, the term itself first."""
        yield self
        for a in self.args:
            yield from a.walk()

    def atoms(self) -> list[Term]:
        """All atom occurrences (with repetition)."""
        if self.op is None:
            return [self]
        out: list[Term] = []
        stack = list(self.args)
        pop = stack.pop
        while stack:
            x = pop()
            if x.op is None:
                out.append(x)
            else:
                stack.extend(x.args)
        return out

    def index_names(self) -> tuple[Term, ...]:
        """Distinct non-variable atoms in ONA's array order (computed once per term)."""
        if self.op is None:
            return () if self.is_var else (self,)  # not cached: no self-reference for atoms
        got = self._names
        if got is None:
            args = self.args
            a: Term
            b: Term
            x: Term
            simple = False
            if len(args) == 2:
                a, b = args
                simple = a.op is None and b.op is None
            if simple:  # ``<a --> b>``: the most common shape, no walk needed
                if a.is_var:
                    got = () if b.is_var else (b,)
                elif b.is_var or a is b:
                    got = (a,)
                else:
                    got = (a, b)
            else:
                # breadth first over the binary tree, as ``level_order_atoms``, in one
                # pass; a term has a few names, so a repeat is found by comparing
                # addresses with those found so far, which costs less than a dict
                out: list[Term] = []
                level: list[Term] = list(args)
                while level:
                    nxt: list[Term] = []
                    for x in level:
                        if x.op is None:
                            if not x.is_var:
                                for y in out:
                                    if y is x:
                                        break
                                else:
                                    out.append(x)
                        else:
                            for y in x.args:
                                nxt.append(y)
                    level = nxt
                got = tuple(out)
            self._names = got
        return got

    def level_order_atoms(self) -> list[Term]:
        """Atom occurrences in ONA's array order (breadth first over the binary tree)."""
        if self.op is None:
            return [self]
        out: list[Term] = []
        level: list[Term] = list(self.args)
        while level:
            nxt: list[Term] = []
            for t in level:
                if t.op is None:
                    out.append(t)
                else:
                    for a in t.args:
                        nxt.append(a)
            level = nxt
        return out


#: structural flags kept on every term so conclusion filters are O(1)
F_IMP = 1  # count of ==>/<=> is kept separately; these are presence bits
F_JUNCTION_RIGHT_NESTED = 2  # some && or || has && or || as right component
F_COMPOSED = 4  # contains - ~ & |
F_IMAGE = 8  # contains /1 /2 \1 \2
#: a binary term with an image as a component, at the top only (not passed on to the
#: terms containing it): a derived belief of such a term needs an existing concept
F_IMAGE_ARGUMENT = 16
#: the term is an image itself (not passed on either): what ``F_IMAGE_ARGUMENT`` of the
#: terms made from it is read from, without comparing its connector with four strings
F_IS_IMAGE = 32
#: the bits a term does not pass on to the terms containing it
_OWN = F_IMAGE_ARGUMENT | F_IS_IMAGE
_IMPS = (IMPLICATION, EQUIVALENCE)
_JUNCTIONS = (CONJUNCTION, DISJUNCTION)
_COMPOSED_OPS = ("-", "~", EXT_INTERSECTION, INT_INTERSECTION)
_IMAGE_OPS = (EXT_IMAGE1, EXT_IMAGE2, INT_IMAGE1, INT_IMAGE2)
#: what ``_make_compound`` records for a connector: a counter to bump (negative codes)
#: or the flag bit to set
_K_IMP = -1
_K_TEMP = -2
_K_JUNCTION = -3
_K_SET = -4  # nothing to record, but sets count more slots (see ``_make_compound``)
_OP_KINDS: dict[str, int] = {
    **dict.fromkeys(SETS, _K_SET),
    **dict.fromkeys(_IMPS, _K_IMP),
    TEMPORAL_IMPLICATION: _K_TEMP,
    **dict.fromkeys(_JUNCTIONS, _K_JUNCTION),
    **dict.fromkeys(_COMPOSED_OPS, F_COMPOSED),
    **dict.fromkeys(_IMAGE_OPS, F_IMAGE),
}

#: a compound's components, and variable bindings (aliases, so that the compiled engine
#: can declare them plain tuples and dicts in ``terms.pxd``)
Components = tuple[Term, ...]
Bindings = dict[Term, Term]
#: a term's key in the interning table: its connector (None for an atom) and its
#: components, or its name
Key = tuple[object, ...]

_TABLE: dict[tuple[object, ...], Term] = {}
#: the table is swept of terms nobody else holds when it grows past this size
_SWEEP_AT = [200_000]
#: its size after the last sweep (see ``sweep_early``)
_SWEPT_TO = [0]


def _sweep() -> None:
    """Drop interned terms referenced only by the table, in one pass.

    A term's components are interned before it, so the table's insertion order puts
    them first; visiting the newest first drops a dead term (and its key) before its
    components are looked at, so a whole dead subtree goes in the same pass.

    A term's variable forms (``forms``, see ``rules.variable_forms``) are interned after
    it, so the pass meets them while it still holds them: the forms of the terms it
    dropped, and the components only those forms held, are looked at again after it,
    so they too go in the same sweep rather than at the next one.

    How many references "held by the table alone" amounts to depends on how this code
    runs (interpreted, the call's argument is one more; compiled, it is not), so it is
    measured on a probe entry that only the table holds, visited first, and again on
    one for the second look.
    """
    table: dict = _TABLE
    table[_PROBE_KEY] = _probe()  # newest: the first one visited
    # the terms only: a dropped term's key is made again from the term, so the keys of
    # the terms that stay (most of a big table) are not touched at all
    terms: list = list(table.values())
    refs = sys.getrefcount
    later: list = []  # the forms of the dropped terms
    t = terms.pop()  # the probe
    alone = refs(t)
    del table[_PROBE_KEY]
    while terms:
        t = terms.pop()  # the previous term is released here
        n = refs(t)
        if n <= alone:
            del table[_key_of(t)]
            forms = t.forms
            if forms:
                for f in forms:
                    if type(f) is Term:  # (not the marker of a term that is its own form)
                        later.append(f)
    forms = f = None  # (the last dead term's forms, and its last form, held no longer)
    if later:
        # held by the table and this list alone, as the probe (looked at first) is
        table[_PROBE_KEY] = _probe()
        later.append(table[_PROBE_KEY])
        alone = -1
        while later:
            t = later.pop()  # the previous one, if dropped, is released here
            n = refs(t)
            if alone < 0:
                alone = n
                del table[_PROBE_KEY]
                continue
            if n <= alone:
                k = _key_of(t)
                if table.get(k) is t:
                    del table[k]
                    later.extend(t.args)  # looked at once this one is released
                k = None  # (it holds the components' tuple, which they are counted by)
    k = None
    t = None
    _SWEPT_TO[0] = len(table)
    _SWEEP_AT[0] = max(200_000, 2 * len(table))


def _key_of(t: Term) -> Key:
    """The interning table's key of ``t``, as ``atom`` and ``compound`` make it."""
    return (t.op, t.args) if t.op is not None else (None, t.name)


#: the probe's key in the table during a sweep (no term has this key)
_PROBE_KEY = ("sweep probe", ())


def _probe() -> Term:
    """A term for the sweep's probe entry: no connector, no components, no forms."""
    t: Term = Term.__new__(Term)
    t.op = None
    t.name = "sweep probe"
    t.args = ()
    t.forms = None
    t.anticipated = None
    t.keys = None
    return t


def sweep_early(share: float = 0.5) -> int:
    """Sweep the table now if it has grown ``share`` of the way from its size after the
    last sweep to the size at which interning would sweep it; returns how many terms
    went.

    Interning sweeps the table when a new term would pass the limit, which is in the
    middle of a reasoning step: a sweep of a few hundred thousand terms takes a tenth of
    a second, a decision's worth of time. A robot's loop calls this between its cycles
    (``NAR.tidy``), so the sweeps happen there and interning rarely needs one. (Measured
    from the last sweep's result, not from zero: a table mostly of live terms would
    otherwise be swept again at every call.)
    """
    before = len(_TABLE)
    last = _SWEPT_TO[0]
    if before < last + share * (_SWEEP_AT[0] - last):
        return 0
    _sweep()
    return before - len(_TABLE)


def interned_count() -> int:
    """How many terms are interned right now."""
    return len(_TABLE)


def atom(name: str) -> Term:
    """The interned atom ``name`` (names, ``^ops``, ``$1``/``#1``/``?1`` variables)."""
    key = (None, name)
    table: dict = _TABLE
    found = table.get(key)
    if found is not None:
        return found
    t: Term = Term.__new__(Term)
    t.op = None
    t.name = name
    t.args = ()
    t.complexity = 1
    t._str = name
    v = name[0] in _VAR_PREFIXES and len(name) > 1
    t.is_var = v
    t.has_var = v
    t.has_query_var = v and name[0] == "?"
    t.has_indep_var = v and name[0] == "$"
    t.has_dep_var = v and name[0] == "#"
    t.is_op = name[0] == "^"
    t.cache = None
    t.flags = 0
    t.n_imp = 0
    t.n_temp = 0
    t._names = None
    t.hol = None
    t.forms = None
    t.anticipated = None
    t.keys = None
    if len(table) >= _SWEEP_AT[0]:
        _sweep()
    table[key] = t
    return t


def compound(op: str, args: Components) -> Term:
    """The interned compound with connector ``op`` over ``args``."""
    key = (op, args)
    table: dict = _TABLE
    t = table.get(key)
    if t is not None:
        return t
    return _make_compound(key, op, args)


def _make_compound(key: Key, op: str, args: Components) -> Term:
    """Build and intern a new compound; every per-term property is computed once here."""
    t: Term = Term.__new__(Term)
    a: Term
    b: Term
    connectors: dict = CONNECTORS  # (typed: the compiled ``get`` is the dict's own)
    op = connectors.get(op, op)
    t.op = op
    t.name = None
    t.args = args
    t._str = None
    t.is_var = False
    kinds: dict = _OP_KINDS
    kind = kinds.get(op, 0)  # one look-up: most terms are ``-->`` or ``*``, of no kind
    if len(args) == 2:
        # the common case (statements, binary connectors), without loops
        a, b = args
        # ONA's binary-tree slot count: sets of n elements chain n-1 element nodes
        complexity = 1 + a.complexity + b.complexity
        if kind == _K_SET:
            complexity += 2
        flags = a.flags | b.flags
        if flags & F_IS_IMAGE:
            flags = (flags & ~_OWN) | F_IMAGE_ARGUMENT
        else:
            flags &= ~_OWN
        n_imp = a.n_imp + b.n_imp
        n_temp = a.n_temp + b.n_temp
        hv = a.has_var or b.has_var
        if hv:
            hq = a.has_query_var or b.has_query_var
            hi = a.has_indep_var or b.has_indep_var
            hd = a.has_dep_var or b.has_dep_var
        else:
            hq = hi = hd = False
        # an operation term: ``^op`` or ``<(args) --> ^op>``
        t.is_op = op is INHERITANCE and b.op is None and b.is_op
    else:
        # unary terms carry a terminator slot, sets of n elements chain n-1 element
        # nodes plus the terminator
        complexity = 1 + (1 if len(args) == 1 else 0)
        if kind == _K_SET and len(args) > 1:
            complexity += len(args)
        flags = 0
        n_imp = n_temp = 0
        hv = hq = hi = hd = False
        for a in args:
            complexity += a.complexity
            flags |= a.flags
            n_imp += a.n_imp
            n_temp += a.n_temp
            hv = hv or a.has_var
            hq = hq or a.has_query_var
            hi = hi or a.has_indep_var
            hd = hd or a.has_dep_var
        flags &= ~_OWN
        t.is_op = False
    if kind != 0 and kind != _K_SET:
        if kind == _K_IMP:
            n_imp += 1
        elif kind == _K_TEMP:
            n_temp += 1
        elif kind == _K_JUNCTION:
            if args[-1].op in _JUNCTIONS:
                flags |= F_JUNCTION_RIGHT_NESTED
        elif kind == F_IMAGE:
            flags |= F_IMAGE | F_IS_IMAGE
        else:
            flags |= kind  # F_COMPOSED
    t.complexity = complexity
    t.flags = flags
    t.n_imp = n_imp  # ==> and <=> inside (conclusion filter: at most one)
    t.n_temp = n_temp  # =/> inside (at most two)
    t.has_var = hv
    t.has_query_var = hq
    t.has_indep_var = hi
    t.has_dep_var = hd
    t.cache = None  # per-term results of pure checks (conclusion filters)
    t._names = None
    t.hol = None
    t.forms = None  # what a variable-introducing rule derives from it (rules.variable_forms)
    t.anticipated = None  # anticipation's record of it as a precondition, during a call
    t.keys = None  # the spike groups its concept is in (sensorimotor._keys_of)
    table: dict = _TABLE
    if len(table) >= _SWEEP_AT[0]:
        _sweep()
    table[key] = t
    return t


def names_repeat(t: Term) -> bool:
    """True if some (non-variable) name occurs more than once in ``t``."""
    args = t.args
    if len(args) == 2:
        a, b = args
        if a.op is None and b.op is None:  # ``<a --> b>`` without a walk
            return a is b and not a.is_var
        # binary: a repeat inside either side, or a name shared by both (the sides'
        # distinct names are cached on the subterms, which are mostly old terms)
        na = a.index_names()
        nb = b.index_names()
        if na and nb:
            if len(nb) == 1:
                if nb[0] in na:
                    return True
            elif len(na) == 1:
                if na[0] in nb:
                    return True
            elif not set(na).isdisjoint(nb):
                return True
        return (a.op is not None and names_repeat(a)) or (b.op is not None and names_repeat(b))
    seen: set[int] = set()
    stack = [t]
    pop = stack.pop
    push = stack.extend
    while stack:
        x = pop()
        if x.op is None:
            if not x.is_var:
                i = id(x)
                if i in seen:
                    return True
                seen.add(i)
        else:
            push(x.args)
    return False


def statement(subject: Term, copula: str, predicate: Term) -> Term:
    """``<subject copula predicate>``."""
    return compound(copula, (subject, predicate))


def negation(t: Term) -> Term:
    """``(! t)``."""
    return compound(NEGATION, (t,))


def _render(t: Term) -> str:
    op = t.op
    if op is None:
        return t.name  # type: ignore[return-value]
    args = t.args
    if op in STATEMENT_COPULAS:
        return f"<{args[0]} {op} {args[1]}>"
    if op in SETS:
        o, c = SETS[op]
        return o + " ".join(str(a) for a in args) + c
    if len(args) == 1:
        return f"({op} {args[0]})"
    return "(" + f" {op} ".join(str(a) for a in args) + ")"


def substitute(t: Term, mapping: Bindings) -> Term:
    """``t`` with every subterm found in ``mapping`` replaced (no recursion into replacements)."""
    r = mapping.get(t)
    if r is not None:
        return r
    args = t.args
    if not args:
        return t
    if len(args) == 2:
        a, b = args
        # an unmapped atom is its own result: no call for the leaves
        na = mapping.get(a)
        if na is None:
            na = substitute(a, mapping) if a.args else a
        nb = mapping.get(b)
        if nb is None:
            nb = substitute(b, mapping) if b.args else b
        if na is a and nb is b:
            return t
        return compound(t.op, (na, nb))  # type: ignore[arg-type]
    new = tuple([substitute(a, mapping) for a in args])
    if new == args:
        return t
    return compound(t.op, new)  # type: ignore[arg-type]


def normalize_variables(t: Term) -> Term:
    """Rename variables ``$x #y ?z`` to ``$1.. #1.. ?1..`` by first occurrence in ONA's array order."""
    if not t.has_var:
        return t
    counters = {"$": 0, "#": 0, "?": 0}
    mapping: dict[Term, Term] = {}
    for a in t.level_order_atoms():
        if a.is_var and a not in mapping:
            k = a.name[0]  # type: ignore[index]
            counters[k] += 1
            mapping[a] = atom(f"{k}{counters[k]}")
    if all(k is v for k, v in mapping.items()):
        return t
    return substitute(t, mapping)


def is_operation(t: Term) -> bool:
    """``^op`` or ``<(args) --> ^op>``."""
    return t.is_op


def operation_name(t: Term) -> Term | None:
    """The ``^op`` atom of an operation term, else None."""
    if t.op is None:
        return t if t.is_op else None
    if t.is_op:
        return t.args[1]
    return None
