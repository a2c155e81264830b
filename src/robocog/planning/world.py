"""The scene the planner reasons about and its AtomSpace facts.

A ``Scene`` is what the perception and learning phases establish: the objects seen
(movable ones and fixed ones such as the table, the workbench and the bins), which object
is on which, and what is in the hand. An object that is on nothing rests where it was
found (the thesis's "initial fixed object"): it is picked up with Pickup and put back
there with Putdown. ``scene_facts`` writes the scene as the atoms of Section 3.1, and
``build_task`` grounds the action rules over them.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from robocog.planning.rules import HAND, Rule, default_rules, ground_rules
from robocog.planning.task import Fact, Task, intern_bit

OBJECT = "object"
FIXED = "fixed-object"


class SceneError(ValueError):
    """A scene that cannot be: a loop of objects, two things in the hand, and so on."""


@dataclass
class Scene:
    """Objects and their arrangement; ``on`` maps an object to what it stands on."""

    objects: list[str] = field(default_factory=list)
    fixed: list[str] = field(default_factory=list)
    on: dict[str, str] = field(default_factory=dict)
    held: str | None = None

    def copy(self) -> Scene:
        """An independent copy (the planner never changes the caller's scene)."""
        return Scene(list(self.objects), list(self.fixed), dict(self.on), self.held)

    def names(self) -> list[str]:
        """Every object, movable ones first."""
        return list(self.objects) + list(self.fixed)

    def add_object(self, name: str, fixed: bool = False) -> None:
        """Make *name* known; a name declared fixed moves from the movable list."""
        if fixed:
            if name in self.objects:
                self.objects.remove(name)
            if name not in self.fixed:
                self.fixed.append(name)
        elif name not in self.objects and name not in self.fixed:
            self.objects.append(name)

    def check(self) -> None:
        """Raise SceneError if the arrangement is impossible."""
        names = set(self.names())
        for top, below in self.on.items():
            if top not in names or below not in names:
                raise SceneError(f"unknown object in 'the {top} is on the {below}'")
            if top in self.fixed:
                raise SceneError(f"the {top} is a fixed object and cannot be on anything")
            if top == below:
                raise SceneError(f"the {top} cannot be on itself")
        seen_under: dict[str, str] = {}
        for top, below in self.on.items():
            if below in self.objects:
                if below in seen_under:
                    raise SceneError(
                        f"the {top} and the {seen_under[below]} cannot both be on the {below}"
                    )
                seen_under[below] = top
        for start in self.on:
            seen = {start}
            cur = start
            while cur in self.on:
                cur = self.on[cur]
                if cur in seen:
                    raise SceneError(f"the objects on top of the {start} form a loop")
                seen.add(cur)
        if self.held is not None:
            if self.held not in self.objects:
                raise SceneError(f"the {self.held} cannot be in the hand")
            if self.held in self.on:
                raise SceneError(f"the {self.held} cannot be in the hand and on something")
            if self.held in self.on.values():
                raise SceneError(f"something is on the {self.held}, which is in the hand")

    @classmethod
    def from_facts(
        cls, facts: Iterable[Fact], objects: Sequence[str], fixed: Sequence[str]
    ) -> Scene:
        """Read the arrangement back from atoms (``on``, ``in-hand``)."""
        scene = cls(list(objects), list(fixed))
        for fact in facts:
            if fact[0] == "on" and len(fact) == 3:
                scene.on[fact[1]] = fact[2]
            elif fact[0] == HAND and len(fact) == 2:
                scene.held = fact[1]
        return scene


def scene_facts(scene: Scene) -> set[Fact]:
    """The atoms of Section 3.1 for *scene*: types, ``clear``, ``on``, ``stacked``, ``in-hand``."""
    facts: set[Fact] = set()
    covered = set(scene.on.values())
    for name in scene.objects:
        facts.add((OBJECT, name))
        if name not in covered and name != scene.held:
            facts.add(("clear", name))
    for name in scene.fixed:
        facts.add((FIXED, name))
        facts.add(("clear", name))
    for top, below in scene.on.items():
        facts.add(("on", top, below))
        facts.add(("stacked", top))
    if scene.held is not None:
        facts.add((HAND, scene.held))
    return facts


def build_task(
    scene: Scene,
    goal: Iterable[Fact],
    rules: Sequence[Rule] | None = None,
    goal_absent: Iterable[Fact] = (),
) -> Task:
    """Ground the action rules over *scene* and number its facts; the goal is a fact list."""
    scene.check()
    rules = list(rules) if rules is not None else default_rules()
    state = scene_facts(scene)
    static = {f for f in state if f[0] in (OBJECT, FIXED)}
    facts: list[Fact] = []
    intern: dict[Fact, int] = {}
    ops = ground_rules(rules, static, scene.names(), intern, facts)
    dynamic = sorted(f for f in state if f not in static)
    init = goal_mask = absent_mask = 0
    for fact in dynamic:
        init |= intern_bit(intern, facts, fact)
    for fact in goal:
        goal_mask |= intern_bit(intern, facts, fact)
    for fact in goal_absent:
        absent_mask |= intern_bit(intern, facts, fact)
    busy = sum(1 << i for i, f in enumerate(facts) if f[0] == HAND)
    task = Task(
        facts=facts,
        operators=ops,
        init=init,
        goal=goal_mask,
        goal_absent=absent_mask,
        busy=busy,
        objects=tuple(scene.objects),
        fixed=tuple(scene.fixed),
        index=intern,
    )
    return task
