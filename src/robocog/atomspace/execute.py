"""Executing and evaluating atoms: queries, rewrites and grounded functions.

``execute`` runs what OpenCog's ``cog-execute!`` runs, with OpenCog's 2021 results:

- GetLink: a SetLink of the groundings (the atom itself for one variable, a ListLink
  in declaration order for several, ``(SetLink (ListLink))`` for a satisfied pattern
  without variables);
- BindLink and QueryLink: the rewrite is instantiated for every grounding and the
  SetLink of the rewrites is returned;
- MeetLink: a QueueValue of the groundings;
- SatisfactionLink: ``(stv 1 1)`` if a grounding exists, else ``(stv 0 1)``;
- ExecutionOutputLink: the registered function is called with the space and the
  arguments (the members of the ListLink) and its result is added to the space.

Grounded names are ``py:NAME``; ``scm:NAME`` (the thesis's spelling) is read the same
way. Only functions registered from Python are ever called: an unregistered name is an
error, never an import or an eval. As ``cog-execute!`` does, ``execute`` adds a query's
result (the SetLink of a GetLink or a BindLink) to the space, so a later query can find
it; ``query()`` and ``space.groundings`` only answer and leave the space as it was.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import Atom, Link, Node, _raw_link, variables_of
from robocog.atomspace.fastpath import get_set
from robocog.atomspace.matcher import (
    PatternError,
    compile_pattern,
    drop_self_groundings,
    is_variable_decl,
    parse_variables,
    query,
    substitute,
)
from robocog.atomspace.matcher.variables import type_admits
from robocog.atomspace.values import FALSE_TV, TRUE_TV, FloatValue, QueueValue, TruthValue, Value

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace


class MissingValue(PatternError):
    """A ValueOfLink asked for a key the atom has no Value under."""


class GroundedError(RuntimeError):
    """A grounded name that is not registered, or malformed."""


_PREFIXES = ("py:", "scm:")


def function_name(grounded: str) -> str:
    """The registry name in ``"py:NAME"`` (or ``"scm: NAME"``)."""
    for p in _PREFIXES:
        if grounded.startswith(p):
            name = grounded[len(p) :].strip()
            if name:
                return name
    raise GroundedError(
        f"grounded name {grounded!r} must be 'py:NAME' naming a registered Python function"
    )


def call_grounded(space: AtomSpace, node: Atom, args: tuple[Atom, ...]) -> Any:
    """Call the function a GroundedSchemaNode/GroundedPredicateNode names."""
    name = function_name(node[1])
    try:
        fn = space.lookup_function(name)
    except KeyError:
        if node[1].startswith("scm:"):
            try:  # a Scheme interpreter over this space answers every scm: name
                scm = space.lookup_function("scm:*")
            except KeyError:
                pass
            else:
                return scm(space, name, args)
        raise GroundedError(f"no Python function is registered under {name!r}") from None
    return fn(space, *args)


def _arguments(args: Atom) -> tuple[Atom, ...]:
    return args[1] if args[0] == "ListLink" else (args,)


def _executable(atom: Atom) -> bool:
    return atom[0] == "ExecutionOutputLink" or atom[0] in _t.QUERY_TYPES


def execute(space: AtomSpace, atom: Atom) -> Any:
    """Execute ``atom`` in ``space`` as ``cog-execute!`` does (see the module doc for what
    each type returns); an atom it returns is in the space afterwards."""
    t = atom[0]
    if t == "GetLink" and len(atom[1]) == 1 and not _defines_or_variables(space):
        # the shapes a robot asks most, answered as atoms without a dict per grounding
        members = get_set(space, atom[1][0])
        if members is not None:
            return space.add(tuple.__new__(Link, ("SetLink", tuple(members))))
    result = _run(space, atom)
    if result.__class__ is Link and t in _t.QUERY_TYPES:
        return space.add(result)
    return result


def _defines_or_variables(space: AtomSpace) -> bool:
    """True when a query's body may need expanding (DefineLinks) or its groundings
    filtering (VariableNodes in the space may ground a variable to itself)."""
    return bool(space.count_type("DefineLink") or space.count_type("VariableNode"))


def _run(space: AtomSpace, atom: Atom) -> Any:
    """Execute ``atom``; a query's result is returned without being added (a query inside
    an ExecutionOutputLink's arguments or an EqualLink is an intermediate value)."""
    t = atom[0]
    if t in _t.QUERY_TYPES:
        return run_query(space, atom)
    if t == "ExecutionOutputLink":
        return _execution_output(space, atom)
    if t == "PutLink":
        return _put(space, atom)
    return instantiate(space, atom)


def _put(space: AtomSpace, atom: Atom) -> Any:
    """Beta reduction, as OpenCog's PutLink does it: the body's variables (a LambdaLink's
    declared ones, else the free ones in order of appearance) replaced by the arguments
    (one value, a ListLink of values for several variables, or a SetLink of such for
    one reduction each), and the result made real in the space: a closed DeleteLink
    then removes what it names and leaves nothing."""
    out = atom[1]
    decl = None
    if len(out) == 3 and is_variable_decl(out[0]):
        decl, body, args = out  # (Put (TypedVariable ...) body args): a typed filter
    elif len(out) == 2:
        body, args = out
    else:
        raise PatternError(f"PutLink needs a body and arguments: {str(atom)[:300]}")
    if body[0] in ("DefinedSchemaNode", "DefinedPredicateNode"):
        for d in space.incoming(body, "DefineLink"):
            if d[1][0] == body:
                body = d[1][1]
                break
    if _executable(args):
        args = _run(space, args)  # (Put body (Get ...)): the query's groundings
        if not isinstance(args, Atom):
            raise PatternError(f"PutLink: its arguments gave {args!r}, not atoms")
    allowed: dict = {}
    if body[0] == "LambdaLink":
        parts = body[1]
        decl = parts[0] if len(parts) == 2 else None
        body = parts[-1]
        variables, allowed = parse_variables(decl, body)
    elif decl is not None:
        variables, allowed = parse_variables(decl, body)
    else:
        variables = variables_of(body)
    if not variables:
        return instantiate(space, body)

    def fits(values: Atom) -> bool:
        given = (values,) if len(variables) == 1 else _arguments(values)
        for v, x in zip(variables, given, strict=False):
            ok = allowed.get(v)
            if isinstance(ok, frozenset) and not type_admits(ok, x):
                return False
        return True

    def reduce(values: Atom) -> Any:
        given = (values,) if len(variables) == 1 else _arguments(values)
        if len(given) != len(variables):
            raise PatternError(f"PutLink: {len(variables)} variables, {len(given)} values")
        return instantiate(space, substitute(body, dict(zip(variables, given, strict=True))))

    if args[0] == "SetLink":
        results = [r for r in (reduce(a) for a in args[1] if fits(a)) if isinstance(r, Atom)]
        return space.add(Link("SetLink", *results))
    return reduce(args)


def _execution_output(space: AtomSpace, atom: Atom) -> Any:
    out = atom[1]
    if len(out) != 2 or out[0][0] != "GroundedSchemaNode":
        raise GroundedError(f"ExecutionOutputLink needs a GroundedSchemaNode and arguments: {atom}")
    args = tuple(_run(space, a) if _executable(a) else a for a in _arguments(out[1]))
    result = call_grounded(space, out[0], args)
    if isinstance(result, Atom):
        return space.add(result)
    if result is None or isinstance(result, Value):
        return result
    raise GroundedError(f"{out[0][1]} returned {result!r}, not an atom or a Value")


def instantiate(space: AtomSpace, atom: Atom) -> Any:
    """Add a (grounded) rewrite to the space, running ExecutionOutputLinks inside it."""
    if atom.__class__ is Node:
        return space.add(atom)
    if atom[0] == "ExecutionOutputLink":
        return _execution_output(space, atom)
    if atom[0] == "PutLink":
        return _put(space, atom)  # a rewrite that is a PutLink is reduced, as OpenCog does
    if atom[0] in _t.QUERY_TYPES:
        return space.add(atom)
    if atom[0] == "DeleteLink":
        # grounded, it removes what it holds and is not added; with variables left
        # (a rewrite that does not bind them all) it is an ordinary atom
        return space.add(atom)
    kids = []
    for a in atom[1]:
        r = instantiate(space, a)
        if r is None and a[0] == "DeleteLink":
            continue  # done: its atoms are gone, and it is no part of the result
        if not isinstance(r, Atom):
            raise GroundedError(f"a rewrite inside {atom[0]} produced {r!r}, not an atom")
        kids.append(r)
    return space.add(Link(atom[0], *kids))


def _split(link: Atom) -> tuple[Atom | None, Atom, Atom | None]:
    """(declaration, body, rewrite) of a query link."""
    t, out = link[0], link[1]
    if t in ("BindLink", "QueryLink"):
        if len(out) == 2:
            return None, out[0], out[1]
        if len(out) == 3 and is_variable_decl(out[0]):
            return out[0], out[1], out[2]
    else:
        if len(out) == 1:
            return None, out[0], None
        if len(out) == 2 and is_variable_decl(out[0]):
            return out[0], out[1], None
    raise PatternError(
        f"malformed {t}: expected [variables] body{' rewrite' if t in ('BindLink', 'QueryLink') else ''}"
    )


def grounding_atom(variables: list[Atom], b: dict[Atom, Atom]) -> Atom:
    """One grounding as OpenCog returns it: the atom, or a ListLink for several."""
    if len(variables) == 1:
        return b[variables[0]]
    return _raw_link("ListLink", tuple([b[v] for v in variables]))


#: how deep DefinedPredicateNodes may be expanded inside one another
_DEFINE_DEPTH = 32


def _expand_defined(space: AtomSpace, atom: Atom, depth: int = 0) -> Atom:
    """A pattern body with each DefinedPredicateNode that stands as a clause replaced
    by what its DefineLink says (a LambdaLink's body), as OpenCog expands them before a
    search; in an EvaluationLink's predicate place it is a call, left as it is."""
    if atom.__class__ is Node:
        if atom[0] != "DefinedPredicateNode":
            return atom
        if depth >= _DEFINE_DEPTH:
            raise PatternError(f"{atom}: definitions nested more than {_DEFINE_DEPTH} deep")
        for d in space.incoming(atom, "DefineLink"):
            if d[1][0] == atom:
                body = d[1][1]
                if body[0] == "LambdaLink":
                    body = body[1][-1]
                return _expand_defined(space, body, depth + 1)
        return atom
    if atom[0] in _t.QUERY_TYPES or atom[0] in ("QuoteLink", "LambdaLink"):
        return atom
    out = atom[1]
    start = 1 if atom[0] == "EvaluationLink" else 0
    new = out[:start] + tuple(_expand_defined(space, a, depth) for a in out[start:])
    if all(x is y for x, y in zip(new, out, strict=True)):
        return atom
    return Link(atom[0], *new)


def _definition_variables(space: AtomSpace, body: Atom) -> list[Atom] | None:
    """OpenCog 2021 lists the variables of a GetLink whose clauses are defined
    predicates clause by clause, each definition's own (a variable shared by three
    definitions is listed three times); None when no definition stands as a clause."""
    clauses = body[1] if body[0] == "AndLink" else (body,)
    if not any(c[0] == "DefinedPredicateNode" for c in clauses):
        return None
    seq: list[Atom] = []
    for c in clauses:
        seq.extend(variables_of(_expand_defined(space, c)))
    return seq if len(seq) != len(set(seq)) else None


def run_query(space: AtomSpace, link: Atom) -> Any:
    """Run a GetLink, BindLink, QueryLink, MeetLink or SatisfactionLink."""
    decl, body, rewrite = _split(link)
    per_definition: list[Atom] | None = None
    if space.count_type("DefineLink"):
        if decl is None and link[0] == "GetLink":
            per_definition = _definition_variables(space, body)
        body = _expand_defined(space, body)
    t = link[0]
    if decl is None and body[0] == "AbsentLink" and t in ("BindLink", "QueryLink"):
        # nothing to ground, only an absence to check: the rewrite once, or nothing
        if any(query(space, a, limit=1) for a in body[1]):
            return Link("SetLink")
        _d, _b, rewrite = _split(link)
        r = instantiate(space, rewrite) if rewrite is not None else None
        return Link("SetLink", *([r] if isinstance(r, Atom) else []))
    if _split_or(body):
        return _boolean_query(space, link, decl, body)
    if decl is None and t != "SatisfactionLink":
        # no declaration: every variable of the body, in order, free; query() takes the
        # fast path for the plain relation queries, which need no compiled pattern
        found = query(space, body)
        # one variable bound in every grounding: the pattern's only one (no walk over it)
        vs = list(found[0]) if found and len(found[0]) == 1 else variables_of(body)
        if found and vs and space.count_type("VariableNode"):
            found = drop_self_groundings(found, vs)
    else:
        pattern = compile_pattern(body, decl)
        if t == "SatisfactionLink":
            return TRUE_TV if pattern.groundings(space, limit=1) else FALSE_TV
        found = pattern.groundings(space)
        vs = pattern.variables
    if t == "GetLink" and per_definition is not None:
        return _raw_link("SetLink", tuple(grounding_atom(per_definition, b) for b in found))
    if t == "GetLink":
        # grounding_atom, inlined for one and two variables (a ListLink is ordered)
        if len(vs) == 1:
            v = vs[0]
            return _raw_link("SetLink", tuple([b[v] for b in found]))
        if len(vs) == 2:
            v, w = vs
            new = tuple.__new__
            return _raw_link(
                "SetLink", tuple([new(Link, ("ListLink", (b[v], b[w]))) for b in found])
            )
        return _raw_link("SetLink", tuple([grounding_atom(vs, b) for b in found]))
    if t == "MeetLink":
        return QueueValue(grounding_atom(vs, b) for b in found)
    results: list[Atom] = []
    seen: set[Atom] = set()
    assert rewrite is not None
    for b in found:
        r = instantiate(space, substitute(rewrite, b))
        if isinstance(r, Atom) and r not in seen:
            seen.add(r)
            results.append(r)
    return Link("SetLink", *results)


_BOOL = frozenset({"AndLink", "OrLink", "NotLink"})


def _split_or(body: Atom) -> bool:
    """Is ``body`` a classical boolean pattern with an OrLink whose branches mention
    different variables (the groundings of one branch leave the others' unbound)?"""
    stack = [body]
    while stack:
        a = stack.pop()
        if a.__class__ is not Link or a[0] not in _BOOL:
            continue
        if a[0] == "OrLink":
            sets = {frozenset(variables_of(b)) for b in a[1]}
            if len(sets) > 1:
                return True
        stack.extend(a[1])
    return False


def _boolean_clauses(atom: Atom, negated: bool, present: list, absent: list) -> None:
    """Sort the Present/Absent clauses of an And/Or/Not tree: present ones (not under a
    NotLink) must be found, absent ones (AbsentLink, or PresentLink under a NotLink)
    must not be, whichever branch of an OrLink they stand in."""
    t = atom[0]
    if t in ("AndLink", "OrLink"):
        for a in atom[1]:
            _boolean_clauses(a, negated, present, absent)
    elif t == "NotLink":
        for a in atom[1]:
            _boolean_clauses(a, not negated, present, absent)
    elif t == "PresentLink":
        (absent if negated else present).extend(atom[1])
    elif t == "AbsentLink":
        (present if negated else absent).extend(atom[1])
    elif not negated and atom.__class__ is Link and t not in _t.QUERY_TYPES:
        present.append(atom)


def _boolean_query(space: AtomSpace, link: Atom, decl: Atom | None, body: Atom) -> Any:
    """OpenCog 2021's answer to a pattern that is an And/Or/Not of Present and Absent
    clauses whose OrLink branches mention different variables: every present clause
    is grounded (wherever it stands), no absent clause may be found, every variable
    must be ground, and the whole body must then evaluate true."""
    present: list[Atom] = []
    absent: list[Atom] = []
    _boolean_clauses(body, False, present, absent)
    variables, _allowed = parse_variables(decl, body)
    found: list[dict[Atom, Atom]] = []
    if present:
        pattern = compile_pattern(Link("AndLink", *present), decl)
        found = [b for b in pattern.groundings(space) if all(v in b for v in variables)]
    kept = []
    for b in found:
        if any(substitute(a, b) in space for a in absent):
            continue
        if evaluate(space, substitute(body, b)).is_true():
            kept.append(b)
    t = link[0]
    if t == "SatisfactionLink":
        return TRUE_TV if kept else FALSE_TV
    if t == "GetLink":
        return _raw_link("SetLink", tuple(grounding_atom(variables, b) for b in kept))
    if t == "MeetLink":
        return QueueValue(grounding_atom(variables, b) for b in kept)
    _d, _b, rewrite = _split(link)
    assert rewrite is not None
    results = [instantiate(space, substitute(rewrite, b)) for b in kept]
    return Link("SetLink", *[r for r in results if isinstance(r, Atom)])


#: executes the atoms this module does not (arithmetic, value flows); installed by
#: :mod:`robocog.atomspace.flow`
_FLOW: list[Callable[[AtomSpace, Atom], Any]] = []


def set_flow(fn: Callable[[AtomSpace, Atom], Any]) -> None:
    """Let ``fn`` compute the operands of comparisons that are arithmetic or value links."""
    _FLOW[:] = [fn]


def _operand(space: AtomSpace, a: Atom) -> Any:
    if _executable(a):
        return _run(space, a)
    if _FLOW and a.__class__ is Link and a[0] not in _t.QUERY_TYPES and not variables_of(a):
        return _FLOW[0](space, a)
    return a


def _number(atom: Any) -> float:
    if isinstance(atom, FloatValue) and atom.items:
        return atom.items[0]
    if isinstance(atom, TruthValue):
        return atom.strength
    if atom[0] != "NumberNode":
        raise PatternError(f"not a number: {atom}")
    try:
        return float(atom[1].split()[0])
    except (ValueError, IndexError):
        raise PatternError(f"not a number: {atom}") from None


def evaluate(space: AtomSpace, atom: Atom) -> TruthValue:
    """The truth value of an evaluatable atom (crisp for the logical connectives)."""
    t = atom[0]
    out = atom[1]
    if t in ("EqualLink", "IdenticalLink"):
        vals = [_run(space, a) if t == "EqualLink" and _executable(a) else a for a in out]
        return TRUE_TV if all(v == vals[0] for v in vals[1:]) else FALSE_TV
    if t == "NotLink":
        if len(out) != 1:
            raise PatternError("NotLink takes one atom")
        return FALSE_TV if evaluate(space, out[0]).is_true() else TRUE_TV
    if t == "AndLink":
        return TRUE_TV if all(evaluate(space, a).is_true() for a in out) else FALSE_TV
    if t == "OrLink":
        return TRUE_TV if any(evaluate(space, a).is_true() for a in out) else FALSE_TV
    if t == "PresentLink":
        return TRUE_TV if all(a in space for a in out) else FALSE_TV
    if t == "AbsentLink":
        return FALSE_TV if any(a in space for a in out) else TRUE_TV
    if t == "GreaterThanLink":
        if len(out) != 2:
            raise PatternError("GreaterThanLink takes two numbers")
        try:
            x, y = (_operand(space, a) for a in out)
        except MissingValue:
            return FALSE_TV  # a value that is not there compares as false
        return TRUE_TV if _number(x) > _number(y) else FALSE_TV
    if t == "SatisfactionLink":
        return run_query(space, atom)
    if t == "EvaluationLink" and out and out[0][0] == "GroundedPredicateNode":
        args = _arguments(out[1]) if len(out) > 1 else ()
        r = call_grounded(space, out[0], args)
        if isinstance(r, TruthValue):
            return r
        if isinstance(r, bool):
            return TRUE_TV if r else FALSE_TV
        raise GroundedError(f"{out[0][1]} returned {r!r}, not a truth value")
    if t == "EvaluationLink" and out and out[0][0] == "DefinedPredicateNode":
        for d in space.incoming(out[0], "DefineLink"):
            if d[1][0] == out[0]:
                return evaluate(space, d[1][1])
        raise PatternError(f"{out[0]} is not defined")
    if atom[0] == "DefinedPredicateNode":
        for d in space.incoming(atom, "DefineLink"):
            if d[1][0] == atom:
                return evaluate(space, d[1][1])
        raise PatternError(f"{atom} is not defined")
    if atom in space:
        return space.get_tv(atom)
    return FALSE_TV
