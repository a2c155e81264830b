"""The four actions as Atomese rules, and the pattern matching that runs them.

The rules live in ``data/actions.scm`` as QueryLinks (Section 3.2 of the thesis): a
variable declaration, a pattern of PresentLink, AbsentLink and NotLink/EqualLink
clauses, and a rewrite whose plain atoms are added and whose DeleteLinks are removed.
They are the single source of the action semantics:

* ``Rule.groundings(facts)`` is the rule without arguments: every binding of its
  variables that the state satisfies (the objects the action can be done on);
* ``Rule.given(...)`` is the rule with arguments: the same query with EqualLinks that
  pin its variables to the given objects, and ``Rule.apply`` performs the rewrite;
* ``ground_rules`` compiles the rules once per task into bit-mask operators
  (``task.Operator``) so that the search does not re-match patterns at every node. The
  test suite checks on random states that both give the same successors.

A state here is a set of facts: ``(InheritanceLink X (ConceptNode "object"))`` is the
fact ``("object", "X")`` and ``(EvaluationLink (PredicateNode "on") (ListLink X Y))`` is
``("on", "X", "Y")``.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from importlib import resources
from itertools import product

from robocog.planning.sexpr import SexprError, SList, String, parse
from robocog.planning.task import PLACE, TAKE, Fact, Operator, intern_bit


@dataclass(frozen=True)
class Var:
    """A pattern variable (``VariableNode "?ob"``)."""

    name: str


Term = Var | str
Pattern = tuple[Term, ...]  # predicate name first, then terms


class RuleError(ValueError):
    """A rule file that does not say a rule the planner can run (line and column given)."""


@dataclass(frozen=True)
class Rule:
    """One action rule: what must be present and absent, what is added and deleted."""

    name: str
    variables: tuple[Var, ...]
    present: tuple[Pattern, ...]
    absent: tuple[Pattern, ...] = ()
    different: tuple[tuple[Term, Term], ...] = ()
    equal: tuple[tuple[Term, Term], ...] = ()
    add: tuple[Pattern, ...] = ()
    delete: tuple[Pattern, ...] = ()
    text: str = field(default="", compare=False)

    @property
    def kind(self) -> str | None:
        """TAKE if the rule puts something in the hand, PLACE if it empties the hand."""
        if any(p[0] == HAND for p in self.add):
            return TAKE
        if any(p[0] == HAND for p in self.delete):
            return PLACE
        return None

    def given(self, *objects: str) -> Rule:
        """The rule with arguments: its variables, in order, equal to *objects*."""
        if len(objects) > len(self.variables):
            raise ValueError(f"{self.name} takes at most {len(self.variables)} objects")
        pins = tuple((v, o) for v, o in zip(self.variables, objects, strict=False))
        return replace(self, equal=self.equal + pins)

    def groundings(self, facts: Iterable[Fact] | FactIndex) -> list[dict[Var, str]]:
        """Every binding of the rule's variables that satisfies its pattern in *facts*."""
        index = facts if isinstance(facts, FactIndex) else FactIndex(facts)
        seed: dict[Var, str] = {}
        for a, b in self.equal:
            if isinstance(a, Var) and isinstance(b, str):
                seed[a] = b
        found = []
        for binding in _match(self.present, index, seed):
            if self._constraints_hold(binding) and not any(
                _ground(p, binding) in index.facts for p in self.absent
            ):
                found.append(binding)
        return found

    def _constraints_hold(self, binding: Mapping[Var, str]) -> bool:
        def value(t: Term) -> str | None:
            return binding.get(t) if isinstance(t, Var) else t

        for a, b in self.different:
            if value(a) == value(b):
                return False
        for a, b in self.equal:
            if value(a) != value(b):
                return False
        return True

    def apply(self, facts: frozenset[Fact], binding: Mapping[Var, str]) -> frozenset[Fact]:
        """The rewrite for one binding: deleted facts removed, added facts created."""
        gone = {_ground(p, binding) for p in self.delete}
        new = {_ground(p, binding) for p in self.add}
        return (facts - gone) | new

    def label(self, binding: Mapping[Var, str]) -> tuple[str, tuple[str, ...]]:
        """The action name and its arguments, in the order the variables are declared."""
        return self.name, tuple(binding[v] for v in self.variables)


HAND = "in-hand"


class FactIndex:
    """Facts indexed by predicate, for the matcher."""

    def __init__(self, facts: Iterable[Fact]) -> None:
        self.facts = frozenset(facts)
        self.by_pred: dict[tuple[str, int], list[Fact]] = {}
        for fact in sorted(self.facts):  # sorted: the same order in every process
            self.by_pred.setdefault((fact[0], len(fact)), []).append(fact)


def _ground(pattern: Pattern, binding: Mapping[Var, str]) -> Fact:
    return tuple(binding[t] if isinstance(t, Var) else t for t in pattern)


def _match(
    patterns: tuple[Pattern, ...], index: FactIndex, binding: dict[Var, str]
) -> Iterator[dict[Var, str]]:
    """Backtracking conjunctive match, most bound pattern first."""
    if not patterns:
        yield dict(binding)
        return

    def unbound(p: Pattern) -> int:
        return sum(1 for t in p[1:] if isinstance(t, Var) and t not in binding)

    best = min(range(len(patterns)), key=lambda i: unbound(patterns[i]))
    pattern, rest = patterns[best], patterns[:best] + patterns[best + 1 :]
    for fact in index.by_pred.get((pattern[0], len(pattern)), ()):
        new = dict(binding)
        ok = True
        for term, value in zip(pattern[1:], fact[1:], strict=True):
            if isinstance(term, Var):
                if new.setdefault(term, value) != value:
                    ok = False
                    break
            elif term != value:
                ok = False
                break
        if ok:
            yield from _match(rest, index, new)


# ---------------------------------------------------------------------------- reading


def _fail(message: str, expr: object, source: str) -> RuleError:
    line = getattr(expr, "line", 0)
    column = getattr(expr, "column", 0)
    return RuleError(f"{source}:{line}:{column}: {message}")


def _term(expr: object, source: str) -> Term:
    if isinstance(expr, SList) and len(expr.items) == 2 and isinstance(expr.items[1], String):
        head = expr.head()
        if head in ("variablenode", "variable"):
            return Var(expr.items[1].value)
        if head in ("conceptnode", "concept"):
            return expr.items[1].value
    raise _fail("expected a VariableNode or ConceptNode", expr, source)


def atom_to_pattern(expr: object, source: str = "<rules>") -> Pattern:
    """An InheritanceLink or EvaluationLink as a fact pattern."""
    if not isinstance(expr, SList):
        raise _fail("expected a link", expr, source)
    head = expr.head()
    if head in ("inheritancelink", "inheritance") and len(expr.items) == 3:
        concept = _term(expr.items[2], source)
        if not isinstance(concept, str):
            raise _fail("the parent of an InheritanceLink must be a ConceptNode", expr, source)
        return (concept, _term(expr.items[1], source))
    if head in ("evaluationlink", "evaluation") and len(expr.items) == 3:
        pred = expr.items[1]
        if not (
            isinstance(pred, SList)
            and pred.head() in ("predicatenode", "predicate")
            and len(pred.items) == 2
            and isinstance(pred.items[1], String)
        ):
            raise _fail("expected a PredicateNode", pred, source)
        args = expr.items[2]
        if isinstance(args, SList) and args.head() in ("listlink", "list"):
            terms = tuple(_term(a, source) for a in args.items[1:])
        else:
            terms = (_term(args, source),)
        return (pred.items[1].value, *terms)
    raise _fail("expected an InheritanceLink or an EvaluationLink", expr, source)


def _read_rule(expr: SList, source: str) -> Rule:
    if expr.head() not in ("definelink",) or len(expr.items) != 3:
        raise _fail("expected (DefineLink (DefinedSchemaNode NAME) (QueryLink ...))", expr, source)
    name_node, query = expr.items[1], expr.items[2]
    if not (isinstance(name_node, SList) and len(name_node.items) == 2):
        raise _fail("expected (DefinedSchemaNode NAME)", name_node, source)
    name = name_node.items[1]
    if not isinstance(name, String):
        raise _fail("the schema name must be a string", name_node, source)
    if not (isinstance(query, SList) and query.head() in ("querylink", "bindlink")):
        raise _fail("expected a QueryLink", query, source)
    if len(query.items) != 4:
        raise _fail("a QueryLink needs variables, a pattern and a rewrite", query, source)
    decl, body, rewrite = query.items[1], query.items[2], query.items[3]
    variables: list[Var] = []
    if not isinstance(decl, SList):
        raise _fail("expected a VariableList", decl, source)
    decls = decl.items[1:] if decl.head() == "variablelist" else (decl,)
    for d in decls:
        if isinstance(d, SList) and d.head() == "typedvariablelink":
            d = d.items[1]
        v = _term(d, source)
        if not isinstance(v, Var):
            raise _fail("expected a VariableNode", d, source)
        variables.append(v)
    present: list[Pattern] = []
    absent: list[Pattern] = []
    different: list[tuple[Term, Term]] = []
    equal: list[tuple[Term, Term]] = []
    clauses = body.items[1:] if isinstance(body, SList) and body.head() == "andlink" else (body,)
    for clause in clauses:
        if not isinstance(clause, SList):
            raise _fail("expected a clause", clause, source)
        head = clause.head()
        if head == "presentlink":
            present.extend(atom_to_pattern(a, source) for a in clause.items[1:])
        elif head == "absentlink":
            absent.extend(atom_to_pattern(a, source) for a in clause.items[1:])
        elif head == "notlink" and len(clause.items) == 2:
            inner = clause.items[1]
            if not (isinstance(inner, SList) and inner.head() == "equallink"):
                raise _fail("only (NotLink (EqualLink a b)) is supported", clause, source)
            different.append((_term(inner.items[1], source), _term(inner.items[2], source)))
        elif head == "equallink" and len(clause.items) == 3:
            equal.append((_term(clause.items[1], source), _term(clause.items[2], source)))
        elif head in ("inheritancelink", "evaluationlink"):
            present.append(atom_to_pattern(clause, source))
        else:
            raise _fail(f"unsupported clause {head or '?'}", clause, source)
    add: list[Pattern] = []
    delete: list[Pattern] = []
    effects = (
        rewrite.items[1:]
        if isinstance(rewrite, SList) and rewrite.head() == "listlink"
        else (rewrite,)
    )
    for effect in effects:
        if isinstance(effect, SList) and effect.head() == "deletelink":
            delete.extend(atom_to_pattern(a, source) for a in effect.items[1:])
        else:
            add.append(atom_to_pattern(effect, source))
    bound = {t for p in present for t in p[1:] if isinstance(t, Var)}
    for v in variables:
        if v not in bound:
            raise _fail(f"variable {v.name} is not bound by a PresentLink", query, source)
    return Rule(
        name=name.value,
        variables=tuple(variables),
        present=tuple(present),
        absent=tuple(absent),
        different=tuple(different),
        equal=tuple(equal),
        add=tuple(add),
        delete=tuple(delete),
    )


def read_rules(text: str, source: str = "<rules>") -> list[Rule]:
    """Read every DefineLink of an Atomese rule file; RuleError names line and column."""
    try:
        exprs = parse(text, source)
    except SexprError as exc:
        raise RuleError(str(exc)) from exc
    rules = []
    for expr in exprs:
        if not isinstance(expr, SList):
            raise _fail("expected a DefineLink", expr, source)
        rules.append(_read_rule(expr, source))
    return rules


_DEFAULT: list[Rule] | None = None


def default_rules() -> list[Rule]:
    """The four actions of the thesis, read from the packaged ``data/actions.scm``."""
    global _DEFAULT
    if _DEFAULT is None:
        text = resources.files("robocog.planning").joinpath("data/actions.scm").read_text()
        _DEFAULT = read_rules(text, "actions.scm")
    return list(_DEFAULT)


# ---------------------------------------------------------------------------- grounding


def dynamic_predicates(rules: Iterable[Rule]) -> set[str]:
    """Predicates some rule adds or deletes; the others never change (types)."""
    out: set[str] = set()
    for rule in rules:
        out.update(p[0] for p in rule.add)
        out.update(p[0] for p in rule.delete)
    return out


def ground_rules(
    rules: Iterable[Rule],
    static: Iterable[Fact],
    objects: Iterable[str],
    intern: dict[Fact, int],
    facts: list[Fact],
) -> list[Operator]:
    """Compile every grounding of *rules* into bit-mask operators.

    Static clauses (types such as ``object``) are matched once against *static*; the
    remaining clauses become the operator's masks over the facts numbered in *intern*
    (new facts are appended to *facts*). Variables bound only by changing facts range
    over *objects*.
    """
    rules = list(rules)
    dyn = dynamic_predicates(rules)
    index = FactIndex(static)
    objects = list(objects)
    ops: list[Operator] = []

    def bit(fact: Fact) -> int:
        return intern_bit(intern, facts, fact)

    for rule in rules:
        static_pats = tuple(p for p in rule.present if p[0] not in dyn)
        dyn_pats = tuple(p for p in rule.present if p[0] in dyn)
        for binding in _match(static_pats, index, {}):
            free = [v for v in rule.variables if v not in binding]
            for values in product(objects, repeat=len(free)):
                full = dict(binding)
                full.update(zip(free, values, strict=True))
                if not rule._constraints_hold(full):
                    continue
                pre = absent = add = delete = 0
                for p in dyn_pats:
                    pre |= bit(_ground(p, full))
                for p in rule.absent:
                    absent |= bit(_ground(p, full))
                for p in rule.add:
                    add |= bit(_ground(p, full))
                for p in rule.delete:
                    delete |= bit(_ground(p, full))
                name, args = rule.label(full)
                ops.append(Operator(name, args, pre, absent, add, delete & ~add, rule.kind))
    return ops
