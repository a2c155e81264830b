"""The action rules run by the AtomSpace's own pattern matcher, one AtomSpace per state.

This is the thesis's way of searching (Section 4.5.1.2): the state is an AtomSpace, the
rules without arguments are queried to find the objects each action applies to, and for
each such object the rule with arguments (the same QueryLink plus EqualLinks pinning its
variables) is run in a copy of the space to make the child state. It is slow by nature
and kept as the reference the compiled operators of ``rules.ground_rules`` are checked
against, and as a way to watch the thesis's procedure on small scenes.

The rule file's rewrite uses ``DeleteLink`` for the atoms an action removes.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from importlib import resources

from robocog.atomspace import AtomSpace, Link, Node, parse, query, substitute
from robocog.planning.rules import HAND
from robocog.planning.task import PLACE, TAKE, Fact
from robocog.planning.world import FIXED, OBJECT, Scene, scene_facts


def concept(name: str) -> Node:
    """``(ConceptNode name)``."""
    return Node("ConceptNode", name)


def fact_atom(fact: Fact) -> Link:
    """A planner fact as its Atomese atom (types as InheritanceLinks)."""
    if fact[0] in (OBJECT, FIXED) and len(fact) == 2:
        return Link("InheritanceLink", concept(fact[1]), concept(fact[0]))
    pred = Node("PredicateNode", fact[0])
    if len(fact) == 2:
        return Link("EvaluationLink", pred, concept(fact[1]))
    return Link("EvaluationLink", pred, Link("ListLink", *(concept(a) for a in fact[1:])))


def atom_fact(atom: Link) -> Fact:
    """The planner fact of an EvaluationLink or InheritanceLink atom."""
    if atom.type == "InheritanceLink":
        child, parent = atom.out
        return (parent.name, child.name)  # type: ignore[attr-defined]
    pred, args = atom.out
    if args.type == "ListLink":
        return (pred.name, *(a.name for a in args.out))  # type: ignore[attr-defined]
    return (pred.name, args.name)  # type: ignore[attr-defined]


@dataclass(frozen=True)
class AtomeseRule:
    """One DefineLink'd QueryLink of the rule file, split into its parts."""

    name: str
    decl: Link
    body: Link
    rewrite: Link
    kind: str | None

    def variables(self) -> list[Node]:
        """The declared variables in order."""
        out = []
        for d in self.decl.out if self.decl.type == "VariableList" else (self.decl,):
            out.append(d.out[0] if d.type == "TypedVariableLink" else d)
        return out

    def groundings(self, space: AtomSpace) -> list[dict]:
        """The rule without arguments: every binding the matcher finds in *space*."""
        return query(space, self.body, self.decl)

    def given(self, space: AtomSpace, *objects: str) -> list[dict]:
        """The rule with arguments: the same query with EqualLinks pinning variables."""
        pins = [
            Link("EqualLink", v, concept(o))
            for v, o in zip(self.variables(), objects, strict=False)
        ]
        clauses = self.body.out if self.body.type == "AndLink" else (self.body,)
        return query(space, Link("AndLink", *clauses, *pins), self.decl)

    def perform(self, space: AtomSpace, binding: dict) -> AtomSpace:
        """A copy of *space* with the rewrite done for *binding*."""
        child = space.copy()
        for effect in self.rewrite.out:
            if effect.type == "DeleteLink":
                for atom in effect.out:
                    child.remove(substitute(atom, binding), recursive=True)
        for effect in self.rewrite.out:
            if effect.type != "DeleteLink":
                child.add(substitute(effect, binding))
        return child

    def label(self, binding: dict) -> tuple[str, tuple[str, ...]]:
        """Action name and argument names."""
        return self.name, tuple(binding[v].name for v in self.variables())


def load_rules(text: str | None = None) -> list[AtomeseRule]:
    """Read the rule file (default: the packaged ``data/actions.scm``) with the AtomSpace reader."""
    if text is None:
        text = resources.files("robocog.planning").joinpath("data/actions.scm").read_text()
    rules = []
    for atom in parse(text, "actions.scm").atoms:
        schema, q = atom.out
        decl, body, rewrite = q.out
        adds = [e for e in rewrite.out if e.type != "DeleteLink"]
        dels = [a for e in rewrite.out if e.type == "DeleteLink" for a in e.out]
        kind = None
        if any(_pred(a) == HAND for a in adds):
            kind = TAKE
        elif any(_pred(a) == HAND for a in dels):
            kind = PLACE
        rules.append(AtomeseRule(schema.name, decl, body, rewrite, kind))
    return rules


def _pred(atom: Link) -> str:
    if atom.type == "EvaluationLink":
        return atom.out[0].name  # type: ignore[attr-defined]
    return ""


def scene_space(scene: Scene) -> AtomSpace:
    """The scene as an AtomSpace of Section 3.1 atoms."""
    space = AtomSpace(name="scene")
    for fact in sorted(scene_facts(scene)):
        space.add(fact_atom(fact))
    return space


def state_key(space: AtomSpace) -> frozenset:
    """The changing atoms of a state: equal keys, equal arrangements."""
    return frozenset(space.get_by_type("EvaluationLink"))


class AtomSpaceSearch:
    """A search space whose states are AtomSpaces, expanded with the matcher.

    ``init`` and the states handed to the search are keys (frozensets of atoms); the
    AtomSpace of each is kept alongside. Hand alternation: with an ``in-hand`` atom only
    rules that empty the hand run, otherwise only rules that fill it.
    """

    def __init__(
        self, scene: Scene, goal: list[Fact], rules: list[AtomeseRule] | None = None
    ) -> None:
        self.rules = rules if rules is not None else load_rules()
        root = scene_space(scene)
        self.init = state_key(root)
        self.spaces: dict[frozenset, AtomSpace] = {self.init: root}
        self.goal = [fact_atom(f) for f in goal]
        self.hand = Node("PredicateNode", HAND)

    def is_goal(self, state: frozenset) -> bool:
        """Every goal atom present."""
        return all(g in state for g in self.goal)

    def successors(
        self, state: frozenset
    ) -> Iterator[tuple[tuple[str, tuple[str, ...]], frozenset]]:
        """Thesis steps 4-5: query each rule, then run it per object in a copy."""
        space = self.spaces[state]
        busy = any(link.out[0] == self.hand for link in state)
        want = PLACE if busy else TAKE
        for rule in self.rules:
            if rule.kind not in (None, want):
                continue
            probe = space.copy()
            found = rule.groundings(probe)
            for binding in found:
                name, args = rule.label(binding)
                pinned = rule.given(space, *args)
                for b in pinned:
                    child = rule.perform(space, b)
                    key = state_key(child)
                    self.spaces.setdefault(key, child)
                    yield (name, args), key


def facts_of(state: frozenset) -> set[Fact]:
    """The facts of a state key."""
    return {atom_fact(a) for a in state}
