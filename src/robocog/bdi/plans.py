"""Triggers, plan bodies and the plan library.

A plan body is compiled once into a chain of immutable cells ``(step, next)`` so that an
intended means only keeps a pointer into it: starting a plan costs nothing however long
its body, and ``if``/``while``/``for`` insert their blocks in front of the rest of the
chain without copying it.
"""

from __future__ import annotations

from collections.abc import Iterable

from robocog.bdi.logic import compile_cond, right_assoc
from robocog.bdi.terms import Literal, Term, Var, term_str

# trigger kinds
BELIEF = ""
ACHIEVE = "!"
TEST = "?"


class Trigger:
    """``+!g``, ``-!g``, ``+?g``, ``-?g``, ``+b`` or ``-b``."""

    __slots__ = ("op", "kind", "literal", "cands")

    def __init__(self, op: str, kind: str, literal: Term) -> None:
        self.op = op
        self.kind = kind
        self.literal = literal
        #: (plan library, its version, candidate plans), filled in by the library
        self.cands: tuple | None = None

    @property
    def is_goal(self) -> bool:
        """Achievement or test goal (as opposed to a belief change)."""
        return self.kind != BELIEF

    @property
    def is_addition(self) -> bool:
        """``+`` trigger."""
        return self.op == "+"

    def key(self) -> tuple | None:
        """Index key in the plan library; ``None`` when the literal is a variable."""
        lit = self.literal
        if lit.__class__ is Literal:
            return (self.op, self.kind, lit.functor, len(lit.args), lit.neg)
        return None

    def __repr__(self) -> str:
        return f"{self.op}{self.kind}{term_str(self.literal)}"


# body step kinds
ACTION = 1
INTERNAL = 2
ACHIEVE_STEP = 3
ACHIEVE_NF = 4
TEST_STEP = 5
ADD_BEL = 6
ADD_BEL_NF = 7
DEL_BEL = 8
DEL_BEL_NF = 9
DEL_ADD_BEL = 10
ADD_BEL_END = 11
CONSTRAINT = 12
IF = 13
WHILE = 14
FOR = 15
WHILE_AGAIN = 16
FOR_NEXT = 17
#: ``a |&| b`` and ``a ||| b``: the term is ``"and"`` or ``"or"``, each block a branch
FORK = 18
#: where a branch of a fork ends (added when the fork runs; ``state`` is the fork)
JOIN = 19

_PREFIX = {
    ACHIEVE_STEP: "!",
    ACHIEVE_NF: "!!",
    TEST_STEP: "?",
    ADD_BEL: "+",
    ADD_BEL_NF: "++",
    DEL_BEL: "-",
    DEL_BEL_NF: "--",
    DEL_ADD_BEL: "-+",
    ADD_BEL_END: "+>",
}


class Step:
    """One formula of a plan body.

    ``term`` is the literal or formula; ``blocks`` holds the compiled chains of
    ``if``/``while``/``for`` (and the conditions of ``elif``); ``line`` is where it was
    written, for failure annotations.
    """

    __slots__ = ("kind", "term", "blocks", "line", "state", "cache", "rel", "memo")

    def __init__(
        self, kind: int, term: Term, blocks: tuple = (), line: int = 0, state: object = None
    ) -> None:
        self.kind = kind
        self.term = term
        self.blocks = blocks
        self.line = line
        self.state = state
        #: what executing the step can compute once (a ready trigger, the term with its
        #: ``source(self)`` annotation); filled in by the agent at first use
        self.cache: object = None
        #: (plan library, version, {op: candidate plans}) for the events the step posts
        self.rel: tuple | None = None
        #: for a term with one variable: (variable, its last value, what was built
        #: from it), reused while the variable has that same (ground) value
        self.memo: tuple | None = None

    def __repr__(self) -> str:
        if self.kind in _PREFIX:
            return _PREFIX[self.kind] + term_str(self.term)
        if self.kind == IF:
            return f"if ({term_str(self.term)}) {{ ... }}"
        if self.kind in (WHILE, WHILE_AGAIN):
            return f"while ({term_str(self.term)}) {{ ... }}"
        if self.kind in (FOR, FOR_NEXT):
            return f"for ({term_str(self.term)}) {{ ... }}"
        if self.kind == FORK:
            op = " |&| " if self.term == "and" else " ||| "
            return op.join("; ".join(map(repr, chain_steps(b))) or "true" for b in self.blocks)
        if self.kind == JOIN:
            return ".join"
        return term_str(self.term)


Chain = tuple | None  # (Step, Chain)


def chain(steps: Iterable[Step], rest: Chain = None) -> Chain:
    """Link steps into a body chain ending in ``rest``."""
    out = rest
    for st in reversed(list(steps)):
        out = (st, out)
    return out


def prepend(block: Chain, rest: Chain) -> Chain:
    """The steps of ``block`` followed by ``rest`` (copies only ``block``'s cells)."""
    if rest is None:
        return block
    items = []
    while block is not None:
        items.append(block[0])
        block = block[1]
    out = rest
    for st in reversed(items):
        out = (st, out)
    return out


def chain_steps(c: Chain) -> list[Step]:
    """The steps of a chain, in order."""
    out = []
    while c is not None:
        out.append(c[0])
        c = c[1]
    return out


class Plan:
    """``@label trigger : context <- body.``"""

    __slots__ = (
        "label",
        "trigger",
        "context",
        "subplans",
        "scope",
        "goal_cond",
        "cond",
        "test",
        "bind",
        "body",
        "source",
        "line",
        "code_line",
        "order",
        "params",
    )

    def __init__(
        self,
        trigger: Trigger,
        context: Term | None,
        body: Chain,
        label: Literal | None = None,
        source: str = "",
        line: int = 0,
    ) -> None:
        self.label = label
        self.trigger = trigger
        self.context = context
        #: the context as it is evaluated (conjunctions grouped to the right)
        self.cond = right_assoc(context) if context is not None else None
        #: ``test(agent, s, trail)``: whether the context holds (as ``holds``)
        self.test = compile_cond(self.cond) if context is not None else None
        self.body = body
        self.source = source
        self.line = line
        #: the line Jason gives the plan (``code_line`` of ``.intention``'s labels)
        self.code_line = line
        self.order = 0
        #: JasonER: the plan's sub-plans (a PlanLibrary, relevant only while the plan
        #: is intended), the plan whose sub-plan this is, and its goal condition
        self.subplans: PlanLibrary | None = None
        self.scope: Plan | None = None
        self.goal_cond: Term | None = None
        #: the trigger's arguments when they are distinct variables and there are no
        #: annotations: relevance is then a matter of binding them
        self.params = _simple_params(trigger)
        #: how the trigger binds: -1 by unification, else the number of parameters
        self.bind = -1 if self.params is None else min(len(self.params), 2)
        lit = trigger.literal if trigger is not None else None
        if self.bind == -1 and lit.__class__ is Literal and lit.ground and not lit.annots:
            self.bind = -2  # e.g. +!count(0): relevant to a ground event with these args

    def __repr__(self) -> str:
        lab = f"@{term_str(self.label)} " if self.label is not None else ""
        ctx = f" : {term_str(self.context)}" if self.context is not None else ""
        body = "; ".join(repr(s) for s in chain_steps(self.body)) or "true"
        return f"{lab}{self.trigger!r}{ctx} <- {body}."


def _simple_params(trigger: Trigger | None) -> tuple | None:
    lit = trigger.literal if trigger is not None else None
    if lit.__class__ is not Literal or lit.annots:
        return None
    args = lit.args
    if all(a.__class__ is Var for a in args) and len({id(a) for a in args}) == len(args):
        if any(a.name == "_" for a in args):
            return None
        return args
    return None


class PlanLibrary:
    """Plans indexed by trigger (operator, kind, functor, arity), kept in program order."""

    def __init__(self) -> None:
        self._plans: list[Plan] = []
        self._index: dict[tuple, list[Plan]] = {}
        self._var_plans: list[Plan] = []
        self._counter = 0
        self._labels: dict[str, Plan] = {}
        #: changes with every addition or removal (invalidates cached candidates)
        self.version = 0

    def add(self, plan: Plan, at_end: bool = True) -> None:
        """Add a plan (at the end of program order, or at the beginning)."""
        self._counter += 1
        self.version += 1
        plan.order = self._counter if at_end else -self._counter
        if plan.label is not None:
            name = plan.label.functor
            if name in self._labels:
                self.remove(name)
            self._labels[name] = plan
        key = plan.trigger.key()
        target = self._var_plans if key is None else self._index.setdefault(key, [])
        if at_end:
            target.append(plan)
            self._plans.append(plan)
        else:
            target.insert(0, plan)
            self._plans.insert(0, plan)

    def remove(self, label: str) -> bool:
        """Remove the plan with this label."""
        plan = self._labels.pop(label, None)
        if plan is None:
            return False
        self._plans.remove(plan)
        self.version += 1
        key = plan.trigger.key()
        (self._var_plans if key is None else self._index[key]).remove(plan)
        return True

    def get(self, label: str) -> Plan | None:
        """The plan with this label, if any."""
        return self._labels.get(label)

    def candidates(self, trigger: Trigger) -> list[Plan]:
        """Plans whose trigger may be relevant for ``trigger``, in program order."""
        got = trigger.cands
        if got is not None and got[0] is self and got[1] == self.version:
            return got[2]
        lit = trigger.literal
        if lit.__class__ is Literal:
            found = self._index.get(
                (trigger.op, trigger.kind, lit.functor, len(lit.args), lit.neg), ()
            )
        else:
            found = ()
        if self._var_plans:
            extra = [p for p in self._var_plans if p.trigger.op == trigger.op]
            extra = [p for p in extra if p.trigger.kind == trigger.kind]
            found = sorted([*found, *extra], key=lambda p: p.order)
        trigger.cands = (self, self.version, found)
        return found  # type: ignore[return-value]

    def has_candidate(self, trigger: Trigger) -> bool:
        """True if some plan may handle ``trigger`` (without touching the trigger's
        remembered candidates: a trigger shared by several agents would lose them)."""
        lit = trigger.literal
        if not self._var_plans and lit.__class__ is Literal:
            key = (trigger.op, trigger.kind, lit.functor, len(lit.args), lit.neg)
            return bool(self._index.get(key))
        return bool(self.candidates(trigger))

    def __iter__(self):  # noqa: ANN204 - iterator of plans
        return iter(self._plans)

    def __len__(self) -> int:
        return len(self._plans)


def is_var_trigger(t: Trigger) -> bool:
    """True for a trigger such as ``+!G``."""
    return t.literal.__class__ is Var
