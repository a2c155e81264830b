"""OpenCog's Scheme API of 2021 over robocog's AtomSpace: ``(use-modules (opencog))``.

Every atom type is a procedure that builds the atom and adds it to the current
AtomSpace (``(Concept "a" (stv 0.9 0.8))``, ``(List a b)``; lists of atoms among a link's
arguments are spliced in, as OpenCog's constructors do). The ``cog-`` procedures read and
change the AtomSpace as their OpenCog namesakes do, and ``scm:`` grounded predicates and
schemas call Scheme procedures. :func:`make_scheme` gives an interpreter with all of it.
"""

from __future__ import annotations

import io
import math
import random as _random
from dataclasses import dataclass
from typing import Any

from robocog.atomspace import schemelib
from robocog.atomspace import types as _t
from robocog.atomspace.atomese import MAX_ARITY, MAX_TEXT, MAX_UNFOLDED, dump, write_pretty
from robocog.atomspace.atoms import Atom, Link, Node, atom_text
from robocog.atomspace.scheme import (
    UNSPECIFIED,
    Primitive,
    Procedure,
    Scheme,
    SchemeError,
    Sym,
    shorten,
    sym,
    to_text,
)
from robocog.atomspace.schemedata import PRINTERS
from robocog.atomspace.space import TV_KEY, AtomSpace
from robocog.atomspace.values import (
    FloatValue,
    LinkValue,
    QueueValue,
    StringValue,
    TruthValue,
    Value,
    stv,
)

OPENCOG_MODULES = {
    "opencog",
    "opencog exec",
    "opencog query",
    "opencog logger",
    "opencog type-utils",
    "opencog atom-types",
    "opencog persist",
    "opencog python",
}

PRINTERS[Link] = atom_text
PRINTERS[Node] = atom_text
PRINTERS[Value] = lambda v: v.to_atomese()


def _bad(who: str, x: Any, expecting: str) -> SchemeError:
    return SchemeError(
        "wrong-type-arg",
        f"In procedure {who}: Wrong type argument (expecting {expecting}): "
        f"{shorten(to_text(x), 100)}",
    )


def _atom(x: Any, who: str) -> Atom:
    if not isinstance(x, Atom):
        raise _bad(who, x, "an atom")
    return x


def _type_name(x: Any, who: str) -> str:
    name = str.__str__(x) if isinstance(x, str) else None
    if isinstance(x, Atom) and x[0] == "TypeNode":
        name = x[1]
    full = _t.resolve(name) if name else None
    if full is None:
        raise _bad(who, x, "an atom type")
    return full


def _node_name(x: Any, who: str) -> str:
    if isinstance(x, bool):
        raise _bad(who, x, "a string")
    if isinstance(x, str):
        return str.__str__(x)
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        return repr(x) if not x.is_integer() else str(int(x))
    raise _bad(who, x, "a string")


#: what a key holds once ``(cog-set-value! atom key #f)`` removed its value
_REMOVED = LinkValue([])


class CogAPI:
    """The ``cog-`` procedures of one interpreter: they share its current AtomSpace."""

    def __init__(self, scheme: Scheme, space: AtomSpace) -> None:
        self.scheme = scheme
        self.space = space
        self.stack: list[AtomSpace] = []
        #: id of a link built here -> (its unfolded size, the link: kept alive so the id
        #: stays its own)
        self.sizes: dict[int, tuple[int, Link]] = {}
        #: ids of the spaces marked read-only (their truth values cannot change)
        self.readonly: set[int] = set()

    # -- constructors
    def node(self, full: str) -> Any:
        def make(name: Any = None, *rest: Any) -> Atom:
            if name is None:
                raise SchemeError("wrong-number-of-args", f"{full} needs a name")
            if isinstance(name, TruthValue):
                name, rest = (rest[0] if rest else None), (name,)
            text = _node_name(name, full)
            tv = None
            for r in rest:
                if isinstance(r, TruthValue):
                    tv = r
                elif not isinstance(r, Value):
                    raise _bad(full, r, "a truth value")
            atom = Node(full, text)
            return self._add(atom, tv)

        return make

    def link(self, full: str) -> Any:
        def make(*args: Any) -> Any:
            out: list[Atom] = []
            tv = None
            for a in args:
                if isinstance(a, Atom):
                    out.append(a)
                elif isinstance(a, TruthValue):
                    tv = a
                elif isinstance(a, list):
                    for b in a:
                        out.append(_atom(b, full))
                elif a is UNSPECIFIED:
                    continue
                else:
                    raise _bad(full, a, "an atom")
            if len(out) > MAX_ARITY:
                raise SchemeError(
                    "wrong-number-of-args", f"{full}: more than {MAX_ARITY} atoms in one link"
                )
            size = 1 + sum(self._size(x) for x in out)
            if size > MAX_UNFOLDED:
                raise SchemeError(
                    "out-of-range",
                    f"{full}: an atom of more than {MAX_UNFOLDED} atoms with its shared parts "
                    "unfolded (atoms are hashed by content)",
                )
            made = self._add(Link(full, *out), tv)
            if size > 1 + len(out) and isinstance(made, Link):
                self.sizes[id(made)] = (size, made)
            return made

        return make

    def _size(self, x: Atom) -> int:
        """The atoms ``x`` holds with shared parts unfolded (known for links built here
        with nested links; a link of nodes counts its own arity)."""
        if x.__class__ is Node:
            return 1
        known = self.sizes.get(id(x))
        if known is not None and known[1] is x:
            return known[0]
        return 1 + sum(1 if y.__class__ is Node else self._size(y) for y in x[1])

    def _add(self, atom: Atom, tv: TruthValue | None) -> Any:
        try:
            found = self.space.add(atom)
        except ValueError as exc:  # a second definition of a name, a held DeleteLink
            raise SchemeError("misc-error", str(exc)) from None
        if found is None:
            return atom  # a closed DeleteLink: it removed what it held
        if tv is not None:
            self.space.set_tv(found, tv)
        return found

    # -- execution
    def execute(self, atom: Any) -> Any:
        from robocog.atomspace.flow import execute_any

        a = _atom(atom, "cog-execute!")
        return _result(execute_any(self.space, a))

    def evaluate(self, atom: Any) -> Any:
        from robocog.atomspace.flow import evaluate_any

        return evaluate_any(self.space, _atom(atom, "cog-evaluate!"))

    # -- inspection
    def incoming(self, atom: Any, *_as: Any) -> list:
        return sorted(self.space.incoming(_atom(atom, "cog-incoming-set")))

    def incoming_by_type(self, atom: Any, type: Any, *_as: Any) -> list:
        t = _type_name(type, "cog-incoming-by-type")
        a = _atom(atom, "cog-incoming-by-type")
        return sorted(x for x in self.space.incoming(a) if _t.is_a(x[0], t))

    def get_atoms(self, type: Any, subtypes: Any = False) -> list:
        t = _type_name(type, "cog-get-atoms")
        return sorted(self.space.get_by_type(t, subtypes=subtypes is not False))

    def prt_atomspace(self, *_a: Any) -> Any:
        self.scheme.out.write(dump(self.space))
        return UNSPECIFIED

    def node_lookup(self, type: Any, name: Any) -> Any:
        atom = Node(_type_name(type, "cog-node"), _node_name(name, "cog-node"))
        return atom if atom in self.space else []

    def link_lookup(self, type: Any, *out: Any) -> Any:
        flat: list[Atom] = []
        for o in out:
            flat.extend(o if isinstance(o, list) else [o])
        atom = Link(_type_name(type, "cog-link"), *[_atom(a, "cog-link") for a in flat])
        return atom if atom in self.space else []

    def delete(self, atom: Any, *_a: Any) -> bool:
        a = _atom(atom, "cog-delete!")
        if a not in self.space or self.space.incoming(a):
            return False
        return self.space.remove(a)

    def delete_recursive(self, atom: Any, *_a: Any) -> bool:
        a = _atom(atom, "cog-delete-recursive!")
        return self.space.remove(a, recursive=True) if a in self.space else False

    # -- truth values and values
    def tv(self, atom: Any) -> TruthValue:
        return self.space.get_tv(_atom(atom, "cog-tv"))

    def set_tv(self, atom: Any, tv: Any) -> Any:
        a = _atom(atom, "cog-set-tv!")
        if id(self.space) in self.readonly:
            raise SchemeError("misc-error", "TruthValue not changed; AtomSpace is readonly")
        if not isinstance(tv, TruthValue):
            raise _bad("cog-set-tv!", tv, "a truth value")
        return self.space.set_tv(a, tv)

    def value(self, atom: Any, key: Any) -> Any:
        v = self.space.get_value(_atom(atom, "cog-value"), _atom(key, "cog-value"))
        return False if v is None or v is _REMOVED else _result(v)

    def set_value(self, atom: Any, key: Any, value: Any) -> Any:
        a = _atom(atom, "cog-set-value!")
        k = _atom(key, "cog-set-value!")
        if isinstance(value, list):
            value = LinkValue(value)
        if value is False or value is None:
            # OpenCog removes the key; robocog stores Values only, so an empty LinkValue
            self.space.set_value(a, k, _REMOVED)
            return a
        if isinstance(value, Atom):
            value = LinkValue([value])
        if not isinstance(value, Value):
            raise _bad("cog-set-value!", value, "a Value")
        return self.space.set_value(a, k, value)

    def keys(self, atom: Any) -> list:
        a = _atom(atom, "cog-keys")
        keys = [k for k in self.space.keys(a) if self.space.get_value(a, k) is not _REMOVED]
        if self.space.get_tv_or_none(a) is not None and TV_KEY not in keys:
            keys.append(TV_KEY)
        return sorted(keys)

    # -- atomspaces
    def new_atomspace(self, parent: Any = None) -> AtomSpace:
        if isinstance(parent, AtomSpace):
            return parent.child()
        return AtomSpace()

    def set_atomspace(self, space: Any) -> AtomSpace:
        if not isinstance(space, AtomSpace):
            raise _bad("cog-set-atomspace!", space, "an AtomSpace")
        old = self.space
        self.space = space
        return old

    def push(self) -> Any:
        self.stack.append(self.space)
        self.space = self.space.child()
        return UNSPECIFIED

    def pop(self) -> Any:
        if not self.stack:
            raise SchemeError("misc-error", "cog-pop-atomspace: stack is empty")
        self.space = self.stack.pop()
        return UNSPECIFIED


def _result(v: Any) -> Any:
    """A value returned to Scheme (lists of atoms stay Python lists)."""
    return UNSPECIFIED if v is None else v


def _value_list(v: Any) -> list:
    if isinstance(v, TruthValue):
        return [v.strength, v.confidence]
    if isinstance(v, Value):
        return list(v.items)  # type: ignore[attr-defined]
    if isinstance(v, Atom):
        return list(v[1]) if isinstance(v, Link) else [v[1]]
    raise _bad("cog-value->list", v, "a Value")


def install(s: Scheme, space: AtomSpace | None = None, preload: bool = True) -> CogAPI:
    """Give ``s`` OpenCog's modules, constructors and ``cog-`` procedures over ``space``:
    bound at once (``preload``, as the REPL and ``robocog atomese`` have them), or only
    after ``(use-modules (opencog))``, as in a bare Guile."""
    before = set(s.globals.vars)
    api = _install(s, space)
    bindings = {k: v for k, v in s.globals.vars.items() if k not in before}
    for m in OPENCOG_MODULES:
        s.known_modules.setdefault(m, {})

    def no_bank(*_a: Any) -> Any:
        raise SchemeError("misc-error", "attention values need an AttentionBank (not modelled)")

    s.known_modules["opencog attentionbank"] = {
        sym(n): Primitive(no_bank, n) for n in ("cog-av", "cog-set-av!", "cog-new-av", "av")
    }
    s.known_modules["opencog exec"] = {
        k: bindings.pop(k) for k in (sym("cog-execute!"), sym("cog-evaluate!"))
    }
    s.known_modules["opencog"] = bindings
    if not preload:
        for m in ("opencog", "opencog exec"):
            for k in s.known_modules[m]:
                del s.globals.vars[k]
    return api


def _install(s: Scheme, space: AtomSpace | None) -> CogAPI:  # noqa: C901 - a table
    api = CogAPI(s, space if space is not None else AtomSpace())
    d = s.define
    for full in _t.all_types():
        if full in ("Atom", "Node", "Link"):
            continue
        maker = api.node(full) if full in _t.NODE_TYPES else api.link(full)
        d(full, maker)
    for short in list(_t._ALIASES):  # noqa: SLF001 - the table of short names
        full = _t.resolve(short)
        if full is not None and sym(full) in s.globals.vars:
            d(short, s.globals.vars[sym(full)])

    # values
    def stv_(s_: Any, c: Any) -> TruthValue:
        try:
            return stv(s_, c)
        except (TypeError, ValueError) as exc:
            raise SchemeError("wrong-type-arg", f"In procedure stv: {exc}") from None

    def ctv(m: Any, c: Any, n: Any) -> CountTruthValue:
        try:
            return CountTruthValue(m, c, n)
        except ValueError as exc:
            raise SchemeError("wrong-type-arg", f"In procedure ctv: {exc}") from None

    d("ctv", ctv)
    d("CountTruthValue", ctv)
    d("cog-new-ctv", ctv)
    d("stv", stv_)
    d("cog-new-stv", stv_)
    d("SimpleTruthValue", stv_)
    d("TruthValue", stv_)
    d("FloatValue", lambda *a: FloatValue(_flatten(a)))
    d("StringValue", lambda *a: StringValue(_flatten(a)))
    d("LinkValue", lambda *a: LinkValue(_members(_flatten(a), "LinkValue")))
    d("QueueValue", lambda *a: QueueValue(_members(_flatten(a), "QueueValue")))
    d("cog-new-value", lambda t, *a: s.apply(s.lookup(str(t)), list(a)))

    d("cog-execute!", api.execute)
    d("cog-evaluate!", api.evaluate)
    d("cog-incoming-set", api.incoming)
    d("cog-incoming-by-type", api.incoming_by_type)
    d(
        "cog-outgoing-set",
        lambda a: list(_atom(a, "cog-outgoing-set")[1]) if isinstance(a, Link) else [],
    )
    d("cog-outgoing-atom", lambda a, i: _atom(a, "cog-outgoing-atom")[1][i])
    d(
        "cog-outgoing-by-type",
        lambda a, t: [x for x in a[1] if _t.is_a(x[0], _type_name(t, "cog-outgoing-by-type"))],
    )
    d("gar", lambda a: _atom(a, "gar")[1][0])
    d("gdr", lambda a: _atom(a, "gdr")[1][1])
    d("gadr", lambda a: _atom(a, "gadr")[1][1][1][0])
    d("gddr", lambda a: _atom(a, "gddr")[1][1][1][1])
    d("cog-node", api.node_lookup)
    d("cog-link", api.link_lookup)
    d("cog-atom", lambda a, *_: _atom(a, "cog-atom"))
    d("cog-name", lambda a: _atom(a, "cog-name")[1] if isinstance(a, Node) else "")
    d("cog-type", lambda a: sym(a[0]) if isinstance(a, Atom) else sym(_value_type(a)))
    d("cog-arity", lambda a: len(a[1]) if isinstance(_atom(a, "cog-arity"), Link) else 0)
    d("cog-atom?", lambda a: isinstance(a, Atom))
    d("cog-node?", lambda a: isinstance(a, Node))
    d("cog-link?", lambda a: isinstance(a, Link))
    d("cog-value?", lambda a: isinstance(a, Value))
    d("cog-tv?", lambda a: isinstance(a, TruthValue))
    d(
        "cog-subtype?",
        lambda a, b: _t.is_a(_type_name(b, "cog-subtype?"), _type_name(a, "cog-subtype?")),
    )
    d("cog-get-types", lambda: [sym(t) for t in _t.all_types()])
    d("cog-get-atoms", api.get_atoms)
    d("cog-get-all-roots", lambda: sorted(a for a in api.space if not api.space.incoming(a)))
    d("cog-map-type", lambda f, t: _map_type(s, api, f, t))
    d("cog-count-atoms", lambda t: len(api.space.get_by_type(_type_name(t, "cog-count-atoms"))))
    d("cog-chase-link", lambda lt, et, a: _chase(api, lt, et, a))
    d("cog-prt-atomspace", api.prt_atomspace)
    d("clear", lambda *a: api.space.clear() or True)

    def export_all(path: Any) -> bool:
        with _file(s, path, "export-all-atoms", "w") as f:
            f.write(dump(api.space))
        return True

    def load_file(path: Any, last: bool = True) -> Any:
        with _file(s, path, "load", "r") as f:
            text = f.read(MAX_TEXT + 1)
        if len(text) > MAX_TEXT:
            raise SchemeError("misc-error", f"load: {shorten(str(path))}: file too large")
        old = s.source
        try:
            value = s.eval_text(text, source=str(path))
        finally:
            s.source = old
        return value if last else UNSPECIFIED

    d("export-all-atoms", export_all)
    d("load", lambda path: load_file(path, last=False))
    d("primitive-load", load_file)
    d("cog-delete!", api.delete)
    d("cog-delete", api.delete)
    d("cog-extract!", api.delete)
    d("cog-extract", api.delete)
    d("cog-delete-recursive!", api.delete_recursive)
    d("cog-extract-recursive!", api.delete_recursive)
    d("cog-equal?", lambda a, b: a == b)
    d("cog-tv", api.tv)
    d("cog-set-tv!", api.set_tv)
    d("cog-mean", lambda a: api.tv(a).strength)
    d("cog-confidence", lambda a: api.tv(a).confidence)
    d("cog-tv-mean", lambda tv: _tv(tv, "cog-tv-mean").strength)
    d("cog-tv-confidence", lambda tv: _tv(tv, "cog-tv-confidence").confidence)
    d("cog-tv-count", lambda tv: 0.0)
    d("cog-tv->alist", lambda tv: [[sym("mean"), tv.strength], [sym("confidence"), tv.confidence]])
    d("cog-value", api.value)
    d("cog-set-value!", api.set_value)
    d("cog-keys", api.keys)
    d("cog-value->list", _value_list)
    d("cog-value-ref", lambda v, i: _value_list(v)[i])
    d("cog-value-type", lambda v: sym(_value_type(v)))
    d("cog-new-atomspace", api.new_atomspace)
    d("cog-set-atomspace!", api.set_atomspace)
    d("cog-atomspace", lambda *a: api.space)
    d("cog-atomspace?", lambda x: isinstance(x, AtomSpace))
    d("cog-atomspace-env", lambda *a: api.space.parent or False)
    d("cog-atomspace-clear", lambda *a: api.space.clear() or True)
    d("cog-push-atomspace", api.push)
    d("cog-pop-atomspace", api.pop)
    d("cog-atomspace-ro!", lambda *a: api.readonly.add(id(a[0] if a else api.space)) or True)
    d("cog-atomspace-rw!", lambda *a: api.readonly.discard(id(a[0] if a else api.space)) or True)
    d("cog-atomspace-cow!", lambda *a: True)
    d("cog-report-counts", lambda: [])
    for level in ("error", "warn", "info", "debug", "fine"):
        d(f"cog-logger-{level}", lambda *a: UNSPECIFIED)
    logger: dict[str, Any] = {
        "level": "INFO",
        "filename": "opencog.log",
        "stdout": True,
        "sync": True,
        "timestamp": True,
        "component": "",
    }

    def setter(what: str) -> Any:
        def set_(*a: Any) -> Any:
            old = logger[what]
            if a:
                v = a[-1]
                logger[what] = v.upper() if what == "level" and isinstance(v, str) else v
            return old if what in ("level", "filename", "component") else True

        return set_

    for what in list(logger):
        d(f"cog-logger-set-{what}!", setter(what))
        d(f"cog-logger-get-{what}", lambda what=what: logger[what])
    d("RandomStream", lambda n=1: RandomStream(n))

    # scm: grounded procedures call back into this interpreter
    def grounded(space: AtomSpace, name: str, args: tuple) -> Any:
        try:
            f = s.lookup(name)
        except SchemeError:
            raise SchemeError("unbound-variable", f"Unbound variable: {shorten(name)}") from None
        old = api.space
        api.space = space
        try:
            return s.apply(f, list(args))
        finally:
            api.space = old

    api.space.register("scm:*", grounded)
    s.cog = api  # type: ignore[attr-defined]
    return api


@dataclass(frozen=True, slots=True, repr=False)
class CountTruthValue(TruthValue):
    """``(ctv mean confidence count)``: kept and printed as given (OpenCog does not check
    its range either); the matcher reads its mean as any truth value's."""

    count: float = 0.0

    def __post_init__(self) -> None:
        for x in (self.strength, self.confidence, self.count):
            if isinstance(x, bool) or not isinstance(x, int | float) or not math.isfinite(x):
                raise ValueError(f"CountTruthValue takes three finite numbers, not {x!r}")

    def to_atomese(self) -> str:
        """``(ctv mean confidence count)``."""
        return f"(ctv {to_text(float(self.strength))} {to_text(float(self.confidence))} " + (
            f"{to_text(float(self.count))})"
        )


class RandomStream(FloatValue):
    """``(RandomStream n)``: each read gives ``n`` new random numbers in [0, 1)."""

    __slots__ = ("_n",)
    _name = "RandomStream"

    def __init__(self, n: Any = 1) -> None:
        if isinstance(n, bool) or not isinstance(n, int) or not 0 < n <= 1_000_000:
            raise _bad("RandomStream", n, "a count from 1 to 10^6")
        object.__setattr__(self, "_n", n)

    @property
    def items(self) -> tuple[float, ...]:  # type: ignore[override]
        """Fresh samples at each read."""
        return tuple(_random.random() for _ in range(self._n))

    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)


def _members(items: list, who: str) -> list:
    for x in items:
        if not isinstance(x, Atom | Value):
            raise _bad(who, x, "atoms or Values")
    return items


def _file(s: Scheme, path: Any, who: str, mode: str) -> Any:
    """Open a file the program names (when the interpreter allows files)."""
    if not getattr(s, "files", False):
        raise SchemeError("misc-error", f"{who}: files are not available to this program")
    if not isinstance(path, str):
        raise _bad(who, path, "a file name")
    try:
        return open(path, mode, encoding="utf-8")  # noqa: SIM115 - the caller's with
    except OSError as exc:
        raise SchemeError("system-error", f"{who}: {shorten(str(exc), 200)}") from None


def _tv(x: Any, who: str) -> TruthValue:
    if not isinstance(x, TruthValue):
        raise _bad(who, x, "a truth value")
    return x


def _value_type(v: Any) -> str:
    if isinstance(v, TruthValue):
        return "SimpleTruthValue"
    if isinstance(v, Value):
        return type(v).__name__
    if isinstance(v, Atom):
        return v[0]
    raise _bad("cog-value-type", v, "a Value")


def _flatten(args: tuple) -> list:
    out: list = []
    for a in args:
        if isinstance(a, list):
            out.extend(a)
        else:
            out.append(a)
    return out


def _map_type(s: Scheme, api: CogAPI, f: Any, t: Any) -> Any:
    for a in sorted(api.space.get_by_type(_type_name(t, "cog-map-type"))):
        if s.apply(f, [a]) is not False:
            return True
    return False


def _chase(api: CogAPI, link_type: Any, end_type: Any, anchor: Any) -> list:
    lt = _type_name(link_type, "cog-chase-link")
    et = _type_name(end_type, "cog-chase-link")
    a = _atom(anchor, "cog-chase-link")
    out = []
    for link in api.space.incoming(a):
        if not _t.is_a(link[0], lt):
            continue
        for x in link[1]:
            if x != a and _t.is_a(x[0], et):
                out.append(x)
    return sorted(set(out))


def make_scheme(space: AtomSpace | None = None, out: Any = None, preload: bool = True) -> Scheme:
    """A Scheme interpreter with OpenCog's modules over ``space`` (a new one if None);
    without ``preload``, OpenCog's procedures come with ``(use-modules (opencog))``."""
    s = Scheme()
    schemelib.install(s)
    if out is not None:
        s.out = out
    install(s, space, preload=preload)
    return s


def run_text(
    text: str,
    space: AtomSpace | None = None,
    source: str = "<string>",
    max_steps: int | None = None,
) -> str:
    """Run a Scheme text with OpenCog's modules and return what it printed.

    Every failure is a :class:`~robocog.atomspace.scheme.SchemeError` (an
    :class:`~robocog.atomspace.atomese.AtomeseError`) with file, line and column;
    ``max_steps`` bounds the evaluation steps (for text from an untrusted source)."""
    buf = io.StringIO()
    s = make_scheme(space, out=buf)
    s.budget = max_steps
    s.files = False  # text from elsewhere reads and writes no files
    s.eval_text(text, source=source)
    return buf.getvalue()


def pretty(x: Any) -> str:
    """A value as the REPL prints it (atoms indented as OpenCog prints them)."""
    if isinstance(x, Atom | Value):
        return write_pretty(x)
    if isinstance(x, AtomSpace):
        return f"#<atomspace {id(x):x}>"
    return to_text(x)


PRINTERS[AtomSpace] = lambda sp: f"#<atomspace {id(sp):x}>"

__all__ = ["CogAPI", "install", "make_scheme", "pretty", "run_text"]

_ = (Primitive, Procedure, Sym)
