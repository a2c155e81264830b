"""A manipulator's tabletop: a table, a workbench, five bins and tagged cubes (Thiella 2021, Ch. 4).

Every object carries an AprilTag; the tag's name is the part the cube stands for
(``BettClamp``, ``SnapRing1``...), so the camera "sees" an induction hardened rod where
there is only a yellow cube. The perception phase reads the tags (:class:`Tag` percepts)
and nothing else: which object stands on which is not perceived, as in the thesis,
where it is told in sentences.

The arm executes the four actions of the thesis as robot Commands:

* ``PickUp(x)``: take a clear cube resting on a fixed object (table, workbench, a bin);
* ``PutDown(x, on)``: put the held cube on a fixed object;
* ``Stack(x, on)``: put the held cube on a clear cube or on a fixed object;
* ``Unstack(x, frm)``: take a clear cube from the top of ``frm``.

A command whose preconditions do not hold fails with the reason, and the world is
unchanged. A grasp (``PickUp``, ``Unstack``) can also fail for no reason the planner
could know: with probability ``grasp_failure``, or at chosen grasps (``fail_grasps``),
the cube slips and stays where it was. Fixed objects are never "full".

Between assembly stages the thesis replaced finished stacks by hand with one cube
(BlockA, BlockB, BlockC); :meth:`TabletopWorld.replace_with_block` does that.
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from robocog.robot.commands import Command, Outcome, PickUp, PutDown, Stack, Unstack
from robocog.robot.percepts import Gripper, Percept, Tag

FIXED_OBJECTS = ("table", "workbench", "PurpleBin", "GreenBin", "RedBin", "BlueBin", "YellowBin")

#: where each part of the torque reaction arm waits at the start (Fig. 5.6); a part
#: named as the support of another stands under it
INITIAL_BINS: dict[str, str] = {
    "BettClamp": "BlueBin",
    "InductionHardenedRod": "YellowBin",
    "SnapRing2": "PurpleBin",
    "SnapRing1": "SnapRing2",
    "BearingSleeve2": "GreenBin",
    "BearingSleeve1": "BearingSleeve2",
    "RecirculatingBallSleeve": "RedBin",
}

#: the parts of BlockC, brought in when its stage begins (they have no coloured cube in
#: the thesis's figures); BlockC itself names the base the bracket is mounted on
BLOCK_C_BINS: dict[str, str] = {
    "BlockC": "workbench",
    "UpperBearingBracket": "PurpleBin",
    "Bearing": "GreenBin",
    "RotatingBalancerSupport": "RedBin",
    "TCEIScrew": "YellowBin",
}

#: seconds the arm takes for each action (for the simulated clock)
ACTION_SECONDS = {"PickUp": 6.0, "Unstack": 6.0, "PutDown": 5.0, "Stack": 5.0}


@dataclass(frozen=True, slots=True)
class Executed:
    """One command the arm was given, when, and how it ended."""

    t: float
    command: Command
    outcome: Outcome


class TabletopWorld:
    """The tabletop scene and the arm; implements ``Body``."""

    def __init__(
        self,
        seed: int = 0,
        parts: Mapping[str, str] | None = None,
        fixed: Iterable[str] = FIXED_OBJECTS,
        grasp_failure: float = 0.0,
        fail_grasps: Iterable[int] = (),
    ) -> None:
        if not 0.0 <= grasp_failure < 1.0:
            raise ValueError("grasp_failure must be in [0, 1)")
        self.rng = random.Random(seed)
        self.fixed: list[str] = list(fixed)
        self.on: dict[str, str] = {}
        self.held: str | None = None
        self.tags: dict[int, str] = {}
        self._next_tag = 0
        self.grasp_failure = grasp_failure
        self.fail_grasps = set(fail_grasps)
        self.grasps = 0
        self.failed_grasps = 0
        self.clock = 0.0
        self.log: list[Executed] = []
        for name in self.fixed:
            self._tag(name)
        self.add_parts(INITIAL_BINS if parts is None else parts)

    # -- the scene ----------------------------------------------------------------

    def _tag(self, name: str) -> None:
        """Give ``name`` the next unused tag id (ids are never reused)."""
        if not self._known(name):
            self._next_tag += 1
            self.tags[self._next_tag] = name

    def _known(self, name: str) -> bool:
        return name in self.tags.values()

    @property
    def cubes(self) -> list[str]:
        """The movable objects, in the order their tags were assigned."""
        return [n for n in self.tags.values() if n not in self.fixed]

    def add_parts(self, parts: Mapping[str, str]) -> None:
        """Bring cubes into the scene; ``parts`` maps each to what it rests on."""
        pending = dict(parts)
        for _ in range(len(pending) + 1):
            for name, support in list(pending.items()):
                if support in self.fixed or support in self.on or support == self.held:
                    if self._known(name):
                        raise ValueError(f"the {name} is already in the scene")
                    if support not in self.fixed and not self.clear(support):
                        raise ValueError(f"the {support} already has something on it")
                    self._tag(name)
                    self.on[name] = support
                    del pending[name]
        if pending:
            raise ValueError(f"cannot place {sorted(pending)}: unknown supports")

    def clear(self, name: str) -> bool:
        """True when nothing stands on ``name`` (fixed objects always have room)."""
        return name in self.fixed or name not in self.on.values()

    def below(self, name: str) -> list[str]:
        """What ``name`` stands on, down to the fixed object (nearest first)."""
        chain = []
        cur = name
        while cur in self.on:
            cur = self.on[cur]
            chain.append(cur)
        return chain

    def replace_with_block(self, parts: Iterable[str], block: str) -> None:
        """Replace a finished stack by one cube named ``block`` where its bottom stood.

        ``parts`` must form one stack, bottom to top in any order, with nothing else on it.
        """
        parts = list(parts)
        if self.held in parts:
            raise ValueError(f"the {self.held} is still in the hand")
        bottom = [p for p in parts if self.on.get(p) not in parts]
        if len(bottom) != 1 or any(p not in self.on for p in parts):
            raise ValueError(f"{parts} is not one stack")
        support = self.on[bottom[0]]
        top = [p for p in parts if self.clear(p)]
        if len(top) != 1:
            raise ValueError(f"something else stands on the stack {parts}")
        for p in parts:
            del self.on[p]
        self.tags = {i: n for i, n in self.tags.items() if n not in parts}
        self._tag(block)
        self.on[block] = support

    def holds(self, fact: tuple[str, ...]) -> bool:
        """Whether an ``on``, ``clear`` or ``in-hand`` fact is true of the scene."""
        kind = fact[0]
        if kind == "on" and len(fact) == 3:
            return self.on.get(fact[1]) == fact[2]
        if kind == "clear" and len(fact) == 2:
            return self.clear(fact[1]) and self.held != fact[1]
        if kind == "in-hand" and len(fact) == 2:
            return self.held == fact[1]
        raise ValueError(f"unknown fact {fact}")

    # -- Body ---------------------------------------------------------------------

    def time(self) -> float:
        """Simulated seconds the arm has worked."""
        return self.clock

    def percepts(self) -> list[Percept]:
        """Every tag in view, and the gripper."""
        out: list[Percept] = [Tag(i, name) for i, name in self.tags.items()]
        out.append(Gripper(self.held))
        return out

    def execute(self, command: Command) -> Outcome:
        """Carry out one of the four manipulator actions."""
        outcome = self._execute(command)
        self.clock += ACTION_SECONDS.get(type(command).__name__, 0.0)
        self.log.append(Executed(self.clock, command, outcome))
        return outcome

    def _execute(self, command: Command) -> Outcome:
        if isinstance(command, PickUp):
            return self._grasp(command.obj, None)
        if isinstance(command, Unstack):
            return self._grasp(command.obj, command.frm)
        if isinstance(command, PutDown):
            return self._place(command.obj, command.on, fixed_only=True)
        if isinstance(command, Stack):
            return self._place(command.obj, command.on, fixed_only=False)
        return Outcome.failure(f"the arm cannot {type(command).__name__}")

    def _grasp(self, obj: str, frm: str | None) -> Outcome:
        if not self._known(obj):
            return Outcome.failure(f"no {obj} in view")
        if obj in self.fixed:
            return Outcome.failure(f"the {obj} is fixed")
        if self.held is not None:
            return Outcome.failure(f"the hand already holds the {self.held}")
        if not self.clear(obj):
            return Outcome.failure(f"the {obj} is not clear")
        support = self.on.get(obj)
        if frm is None and support not in self.fixed:
            return Outcome.failure(f"the {obj} is on the {support}: unstack it")
        if frm is not None and support != frm:
            return Outcome.failure(f"the {obj} is not on the {frm}")
        self.grasps += 1
        if self.grasps in self.fail_grasps or (
            self.grasp_failure > 0.0 and self.rng.random() < self.grasp_failure
        ):
            self.failed_grasps += 1
            return Outcome.failure(f"grasp failed: the {obj} slipped")
        del self.on[obj]
        self.held = obj
        return Outcome.success()

    def _place(self, obj: str, on: str, fixed_only: bool) -> Outcome:
        if self.held != obj:
            return Outcome.failure(f"the {obj} is not in the hand")
        if not self._known(on):
            return Outcome.failure(f"no {on} in view")
        if fixed_only and on not in self.fixed:
            return Outcome.failure(f"the {on} is not a fixed object: stack on it instead")
        if on == obj or not self.clear(on):
            return Outcome.failure(f"the {on} is not clear")
        self.on[obj] = on
        self.held = None
        return Outcome.success()
