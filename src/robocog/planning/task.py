"""A grounded planning task: facts numbered once, states as bit sets, operators as masks.

The action rules (Atomese or PDDL) say what each action needs and does; grounding them
once over the task's objects turns every action into four bit masks (facts that must be
present, facts that must be absent, facts added, facts deleted). A search node is then a
single Python integer, so copying, comparing and hashing a state costs one machine word
per 60 facts instead of a copied AtomSpace per node.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field

#: a ground fact: predicate name followed by its arguments, e.g. ("on", "A", "B")
Fact = tuple[str, ...]

TAKE = "take"  #: an action that fills the hand (pickup, unstack)
PLACE = "place"  #: an action that empties the hand (putdown, stack)


@dataclass(frozen=True)
class Operator:
    """One ground action: its name and arguments and its four fact masks."""

    name: str
    args: tuple[str, ...]
    pre: int
    absent: int
    add: int
    delete: int
    kind: str | None = None

    def applicable(self, state: int) -> bool:
        """True when every required fact is in *state* and no forbidden one is."""
        return state & self.pre == self.pre and not state & self.absent

    def apply(self, state: int) -> int:
        """The state after this action (deletes first, then adds, as in STRIPS)."""
        return (state & ~self.delete) | self.add


@dataclass
class Task:
    """Facts, operators, the initial state and the goal of one planning problem.

    ``busy`` is the mask of the facts that say the hand holds something; when it is set
    the search only tries ``PLACE`` actions, otherwise only ``TAKE`` actions, the
    alternation of Section 4.5.1 of the thesis. Operators without a kind are always tried.
    """

    facts: list[Fact]
    operators: list[Operator]
    init: int
    goal: int
    goal_absent: int = 0
    busy: int = 0
    objects: tuple[str, ...] = ()
    fixed: tuple[str, ...] = ()
    index: dict[Fact, int] = field(default_factory=dict)
    _triggers: dict[int, list[Operator]] = field(default_factory=dict, repr=False)
    _trigger_mask: int = 0
    _free_ops: list[Operator] = field(default_factory=list, repr=False)

    def __post_init__(self) -> None:
        if not self.index:
            self.index = {fact: i for i, fact in enumerate(self.facts)}
        self._build_triggers()

    def _build_triggers(self) -> None:
        """Index each operator under one of its required facts, the rarest at the start.

        A node then looks only at the operators whose trigger fact it holds, instead of
        testing every ground action.
        """
        counts: dict[str, int] = {}
        for i, fact in enumerate(self.facts):
            if self.init >> i & 1:
                counts[fact[0]] = counts.get(fact[0], 0) + 1
        self._triggers = {}
        self._trigger_mask = 0
        self._free_ops = []
        for op in self.operators:
            required = list(bits(op.pre))
            if not required:
                self._free_ops.append(op)
                continue
            best = min(
                required, key=lambda b: (counts.get(self.facts[b][0], 0), -len(self.facts[b]), b)
            )
            self._triggers.setdefault(best, []).append(op)
            self._trigger_mask |= 1 << best

    def fact_bit(self, fact: Fact) -> int:
        """The mask of one fact (0 if the task never mentions it)."""
        i = self.index.get(fact)
        return 0 if i is None else 1 << i

    def mask(self, facts: Iterable[Fact]) -> int:
        """The mask of several facts; unknown facts raise KeyError naming the fact."""
        m = 0
        for fact in facts:
            if fact not in self.index:
                raise KeyError(f"unknown fact {fact_text(fact)}")
            m |= 1 << self.index[fact]
        return m

    def state_facts(self, state: int) -> list[Fact]:
        """The facts true in *state*, in task order."""
        return [self.facts[i] for i in bits(state)]

    def is_goal(self, state: int) -> bool:
        """True when *state* holds every goal fact and none of the forbidden ones."""
        return state & self.goal == self.goal and not state & self.goal_absent

    def applicable(self, state: int, kinds: bool = True) -> Iterator[Operator]:
        """The operators applicable in *state*, alternating hand-free/hand-busy actions."""
        want = None
        if kinds and self.busy:
            want = PLACE if state & self.busy else TAKE
        for op in self._free_ops:
            if (want is None or op.kind in (None, want)) and op.applicable(state):
                yield op
        for bit in bits(state & self._trigger_mask):
            for op in self._triggers[bit]:
                if (want is None or op.kind in (None, want)) and op.applicable(state):
                    yield op

    def successors(self, state: int) -> Iterator[tuple[Operator, int]]:
        """Each applicable operator with the state it leads to."""
        for op in self.applicable(state):
            yield op, op.apply(state)

    def restricted(self, names: set[str]) -> Task:
        """The same task keeping only actions that involve at least one of *names*.

        This is the thesis's quick search: fewer branches, but no promise of a plan.
        """
        ops = [op for op in self.operators if names.intersection(op.args)]
        return Task(
            facts=self.facts,
            operators=ops,
            init=self.init,
            goal=self.goal,
            goal_absent=self.goal_absent,
            busy=self.busy,
            objects=self.objects,
            fixed=self.fixed,
            index=self.index,
        )

    def with_state(
        self, init: int, goal: int | None = None, goal_absent: int | None = None
    ) -> Task:
        """A copy of this task starting elsewhere or aiming elsewhere (operators shared)."""
        task = Task.__new__(Task)
        task.__dict__.update(self.__dict__)
        task.init = init
        if goal is not None:
            task.goal = goal
        if goal_absent is not None:
            task.goal_absent = goal_absent
        return task

    def validate(self, plan: Sequence[Operator]) -> bool:
        """Replay *plan* from the initial state: every step applicable, goal reached."""
        state = self.init
        for op in plan:
            if not op.applicable(state):
                return False
            state = op.apply(state)
        return self.is_goal(state)


def bits(m: int) -> Iterator[int]:
    """The positions of the set bits of *m*, lowest first.

    States and masks are integers; this walks only the set bits, so its cost follows the
    facts that hold rather than the facts the task knows.
    """
    while m:
        low = m & -m
        yield low.bit_length() - 1
        m ^= low


def intern_bit(index: dict[Fact, int], facts: list[Fact], fact: Fact) -> int:
    """The mask of *fact*, numbering it (appended to *facts*) the first time it is met.

    Grounding meets facts one action at a time; numbering them as they come gives the
    operators, the initial state and the goal one shared numbering.
    """
    i = index.get(fact)
    if i is None:
        i = index[fact] = len(facts)
        facts.append(fact)
    return 1 << i


def fact_text(fact: Fact) -> str:
    """A fact as PDDL-like text: ``(on A B)``."""
    return "(" + " ".join(fact) + ")"
