"""The Q.bo's atomic actions of Fujita et al. on the robot contract, and the perceptions they return.

The paper's agent calls three environment actions (Section 2.4): ``looking_Qbo(Obj)``,
``forward_Qbo(Dir)`` and ``search_Qbo(Dir)``, the last two sent through
``tcp_write(...)``. On the Q.bo a Python program turned each into motor commands and
sensor reads and answered with perceptions. This module is that program, written over
``Look``, ``Forward`` and ``Turn`` so it drives any Body that offers them:

* :class:`QboActions` runs one atomic action to its end, one Command per cycle, reading
  the percepts between commands (``search_Qbo`` must see whether it still faces an
  obstacle before turning further).
* :class:`QboPerception` turns percepts into the beliefs the plans of Figs. 6-8 test:
  ``my_current_direction(D)``, ``found_obstacle``, ``found_target(Obj)``,
  ``target_direction(D)`` and ``front_of(Obj)``, the paper's stop conditions. Directions are whole degrees, counter-clockwise, in the frame
  of the robot's odometry, as the paper's ``Dir + 45`` arithmetic needs.
* :class:`ReachExitReference` is Figs. 6-8 transcribed into Python, step for step. It
  needs no engine and serves as the control against which the AgentSpeak run of the
  same plans is compared.
"""

from __future__ import annotations

import math
import re
from collections.abc import Generator, Sequence
from dataclasses import dataclass, field
from importlib import resources

from robocog.robot.commands import Command, Forward, Look, Outcome, Turn
from robocog.robot.percepts import Detection, Percept, Pose, Range

#: the constant length of one ``forward_Qbo`` move, metres
STEP_LENGTH = 0.5
#: an ultrasonic reading below this is ``found_obstacle``, metres
OBSTACLE_DISTANCE = 0.4
#: ``search_Qbo`` turns away from the base direction by this much at a time, degrees
SEARCH_STEP = 15
#: and gives up after this many turns (up to 90 degrees either side)
SEARCH_TRIES = 12

ACTIONS = ("looking_Qbo", "forward_Qbo", "search_Qbo")

#: the one copy of Figs. 6-8 in robocog, kept with the AgentSpeak interpreter's examples
PLANS = ("robocog.bdi", "examples/qbo_reach_exit.asl")


def reach_exit_program() -> str:
    """The .asl program: Figs. 6-8 as printed, the sub-goals the paper leaves out, and
    the initial goal ``!reach_exit``."""
    package, path = PLANS
    text = resources.files(package).joinpath(path).read_text(encoding="utf-8")
    return text + "\n!reach_exit.\n"


def degrees(angle: float) -> int:
    """Radians as whole degrees in (-180, 180], the unit of the paper's directions."""
    d = round(math.degrees(angle)) % 360
    return d - 360 if d > 180 else d


def turn_to(direction_deg: float, heading: float) -> float:
    """The signed turn, in radians, that brings ``heading`` to ``direction_deg``."""
    a = math.radians(direction_deg) - heading
    return math.atan2(math.sin(a), math.cos(a))


@dataclass
class Sense:
    """The few things the atomic actions read from the percepts."""

    heading: float = 0.0
    sonar: float = math.inf
    detections: list[Detection] = field(default_factory=list)

    @classmethod
    def of(cls, percepts: Sequence[Percept]) -> Sense:
        """Collect heading, nearest ultrasonic reading and detections."""
        sense = cls()
        for p in percepts:
            if isinstance(p, Pose):
                sense.heading = p.theta
            elif isinstance(p, Range):
                sense.sonar = min(sense.sonar, p.distance)
            elif isinstance(p, Detection):
                sense.detections.append(p)
        return sense

    @property
    def obstacle(self) -> bool:
        """``found_obstacle``: an ultrasonic sensor reads closer than the threshold."""
        return self.sonar < OBSTACLE_DISTANCE


Routine = Generator[Command, Sense, None]


def looking_qbo(target: str) -> Routine:
    """Three images, head left, ahead and right; the perception is read afterwards."""
    yield Look("around")


def forward_qbo(direction: float, sense: Sense) -> Routine:
    """Turn to the base direction and move a constant length (the body stops at obstacles)."""
    sense = yield Turn(turn_to(direction, sense.heading))
    yield Forward(STEP_LENGTH)


def search_qbo(direction: float, sense: Sense) -> Routine:
    """Turn to the base direction, then little by little away from it until nothing is
    in front, and move on; if every direction within 90 degrees is blocked, stay."""
    sense = yield Turn(turn_to(direction, sense.heading))
    tries = 0
    while sense.obstacle and tries < SEARCH_TRIES:
        tries += 1
        offset = SEARCH_STEP * ((tries + 1) // 2) * (1 if tries % 2 else -1)
        sense = yield Turn(turn_to(direction + offset, sense.heading))
    if not sense.obstacle:
        yield Forward(STEP_LENGTH)


_TERM = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\((.*)\))?\s*$", re.S)


def parse_action(text: str) -> tuple[str, list[str]]:
    """``"tcp_write(forward_Qbo(45))"`` -> ``("forward_Qbo", ["45"])``.

    ``tcp_write`` is only the paper's transport to the Python side, so it is unwrapped.
    Raises ValueError for text that is not one of the Q.bo's actions.
    """
    m = _TERM.match(text)
    if not m:
        raise ValueError(f"not an action term: {text!r}")
    name, inner = m.group(1), m.group(2)
    if name == "tcp_write" and inner is not None:
        return parse_action(inner)
    if name not in ACTIONS:
        raise ValueError(f"unknown Q.bo action {name!r}")
    args = [a.strip() for a in inner.split(",")] if inner else []
    return name, args


def _number(value: object) -> float:
    try:
        return float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError) as exc:
        raise ValueError(f"a direction must be a number, got {value!r}") from exc


class QboPerception:
    """Percepts -> the beliefs of Figs. 6-8, keeping the last look's answer.

    ``looking_Qbo`` answers with ``found_target``/``target_direction``; those stay
    believed until the next look, as a Jason environment keeps a percept until it is
    replaced. The other two beliefs follow the sensors every cycle.
    """

    def __init__(self) -> None:
        self.looking_for: str | None = None
        self.awaiting_look = False
        self.target: tuple[str, int] | None = None
        self.heading = 0.0
        self.obstacle = False
        self.looks = 0

    def look_started(self, target: str) -> None:
        """A ``looking_Qbo(target)`` began; its images arrive with the next percepts."""
        self.looks += 1
        self.looking_for = target
        self.awaiting_look = True

    def update(self, percepts: Sequence[Percept]) -> list[str]:
        """Read this cycle's percepts; return the beliefs, as AgentSpeak literals."""
        sense = Sense.of(percepts)
        self.heading = sense.heading
        self.obstacle = sense.obstacle
        if self.awaiting_look:
            self.awaiting_look = False
            seen = [d for d in sense.detections if d.label == self.looking_for]
            if seen:
                best = max(seen, key=lambda d: d.confidence)
                self.target = (best.label, degrees(sense.heading + best.bearing))
            else:
                self.target = None
        return self.literals()

    def literals(self) -> list[str]:
        """The current beliefs, as AgentSpeak literals."""
        out = [f"my_current_direction({degrees(self.heading)})"]
        if self.obstacle:
            out.append("found_obstacle")
        if self.target is not None:
            out.append(f"found_target({self.target[0]})")
            out.append(f"target_direction({self.target[1]})")
            if self.obstacle:
                out.append(f"front_of({self.target[0]})")
        return out

    def front_of(self, target: str) -> bool:
        """The stop conditions of Section 3.1: the target recognised by the last look and
        the ultrasonic sensors meeting an obstacle. Perceived as ``front_of(Target)``."""
        return self.target is not None and self.target[0] == target and self.obstacle


class QboActions:
    """Runs one atomic action at a time as a sequence of Commands, one per cycle."""

    def __init__(self, perception: QboPerception | None = None) -> None:
        self.perception = perception or QboPerception()
        self.routine: Routine | None = None
        self.action: tuple[str, list[str]] | None = None
        self.failures: list[str] = []
        self._first = True

    @property
    def busy(self) -> bool:
        """True while an atomic action has commands left to run."""
        return self.routine is not None

    def start(self, name: str, args: Sequence[object], percepts: Sequence[Percept]) -> None:
        """Begin ``name(args)``; raises ValueError for an unknown action or bad argument."""
        sense = Sense.of(percepts)
        if name == "looking_Qbo":
            if len(args) != 1:
                raise ValueError("looking_Qbo takes the target's name")
            target = str(args[0])
            self.perception.look_started(target)
            routine = looking_qbo(target)
        elif name in ("forward_Qbo", "search_Qbo"):
            if len(args) != 1:
                raise ValueError(f"{name} takes one base direction")
            direction = _number(args[0])
            routine = (forward_qbo if name == "forward_Qbo" else search_qbo)(direction, sense)
        else:
            raise ValueError(f"unknown Q.bo action {name!r}")
        self.routine = routine
        self.action = (name, [str(a) for a in args])
        self._first = True
        self.failures = []

    def next_command(self, percepts: Sequence[Percept]) -> Command | None:
        """The action's next command given what is sensed now; None once it has ended."""
        if self.routine is None:
            return None
        try:
            if self._first:
                self._first = False
                command = next(self.routine)
            else:
                command = self.routine.send(Sense.of(percepts))
        except StopIteration:
            self.routine = None
            return None
        return command

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Keep a failed command's reason; stopping at an obstacle is part of the action."""
        if not outcome.ok:
            self.failures.append(outcome.reason)


@dataclass
class _Frame:
    """Where the reference controller is in the plans: which object, which step."""

    target: str
    step: str = "check"


class ReachExitReference:
    """Figs. 6-8 of Fujita et al. transcribed into Python, for comparison with the .asl run.

    ``@re`` reaches the door then the entry; ``@ro`` sets the expected direction
    (``@s_td1``: 0, ``@s_td2``: current direction + 45) and searches; ``@so1`` looks
    around and decides while ``front_of(Object)`` is not believed, ``@so2`` stops. The
    stop conditions are the paper's: the target recognised and the ultrasonic sensors
    meeting an obstacle. ``@da1``-``@da4`` choose the action.
    """

    def __init__(self) -> None:
        self.perception = QboPerception()
        self.actions = QboActions(self.perception)
        self.goals = ["door", "entry"]
        self.frame: _Frame | None = None
        self.expected: int = 0
        self.percepts: list[Percept] = []
        self.log: list[str] = []
        self.done = False

    @property
    def phase(self) -> str:
        """The object currently reached for (``door``, ``entry``) or ``done``."""
        return "done" if self.done else (self.frame.target if self.frame else self.goals[0])

    def front_of(self, target: str) -> bool:
        """The stop conditions of plan ``re``: target recognised and obstacle met."""
        return self.perception.front_of(target)

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """Update the beliefs from the sensors."""
        self.percepts = list(percepts)
        self.perception.update(percepts)

    def decide(self) -> list[Command]:
        """The next command of the running action, or the plans' next action."""
        for _ in range(8):
            if self.actions.busy:
                command = self.actions.next_command(self.percepts)
                if command is not None:
                    return [command]
                continue
            if not self._advance():
                return []
        return []

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Pass the outcome to the running action."""
        self.actions.on_outcome(command, outcome)

    def _advance(self) -> bool:
        """Run the plans until an atomic action starts; False when nothing is left."""
        if self.done:
            return False
        if self.frame is None:
            if not self.goals:
                self.done = True
                return False
            target = self.goals.pop(0)
            self.frame = _Frame(target)
            if target == "door":
                self.expected = 0  # @s_td1
            else:
                self.expected = degrees(self.perception.heading) + 45  # @s_td2
            self.log.append(f"reach_object({target}) expected {self.expected}")
        frame = self.frame
        if frame.step == "check":
            if self.front_of(frame.target):  # @so2
                self.log.append(f"front_of({frame.target})")
                self.frame = None
                return self._advance()
            frame.step = "decide"  # @so1: around_search
            self.actions.start("looking_Qbo", [frame.target], self.percepts)
            return True
        frame.step = "check"  # @so1: decide_action, then recurse
        p = self.perception
        name = "search_Qbo" if p.obstacle else "forward_Qbo"
        if p.target is not None:
            direction = p.target[1]  # @da1 / @da2: toward the target seen
        else:
            direction = self.expected  # @da3 / @da4: the expected direction
        self.log.append(f"{name}({direction})")
        self.actions.start(name, [direction], self.percepts)
        return True


class QboBdiMind:
    """The AgentSpeak interpreter running the paper's plans on the Q.bo's actions.

    The program's environment actions are the paper's: ``looking_Qbo(Obj)`` and
    ``tcp_write(forward_Qbo(Dir))`` / ``tcp_write(search_Qbo(Dir))``. Each returns a
    pending handle to the agent; the action's Commands then run one per cycle, and the
    handle succeeds when the last one has ended, so the intention waits for its robot
    as Jason's does. Beliefs come from :class:`QboPerception` as ``source(percept)``.
    """

    #: reasoning cycles allowed in one ``decide`` before yielding to the loop
    MAX_CYCLES = 500

    def __init__(self, program: str, name: str = "qbo") -> None:
        from robocog.bdi.agent import Agent

        self.perception = QboPerception()
        self.actions = QboActions(self.perception)
        self.output: list[str] = []
        self.agent = Agent(program, name, printer=lambda who, text: self.output.append(text))
        self.agent.register_action("tcp_write", self._tcp_write, raw=True)
        self.agent.register_action("looking_Qbo", self._looking, raw=True)
        self.percepts: list[Percept] = []
        self._request: tuple[str, list[object]] | None = None
        self._handle: object | None = None
        self.log: list[str] = []

    def _pending(self, name: str, args: list[object]) -> object:
        from robocog.bdi.actions import ActionHandle

        handle = ActionHandle()
        self._request = (name, args)
        self._handle = handle
        self.log.append(f"{name}({', '.join(str(a) for a in args)})")
        return handle

    def _tcp_write(self, term: object) -> object:
        from robocog.bdi.actions import to_python

        name = getattr(term, "functor", None)
        if name not in ("forward_Qbo", "search_Qbo"):
            raise ValueError(f"tcp_write of an unknown action: {term}")
        return self._pending(name, [to_python(a) for a in term.args])  # type: ignore[attr-defined]

    def _looking(self, term: object) -> object:
        from robocog.bdi.actions import to_python

        return self._pending("looking_Qbo", [to_python(term)])

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """Sensors -> the beliefs of Figs. 6-8, replacing last cycle's percepts."""
        self.percepts = list(percepts)
        self.agent.set_percepts(self.perception.update(percepts))

    def decide(self) -> list[Command]:
        """Run the agent until its running action needs the robot, or it has nothing to do."""
        for _ in range(self.MAX_CYCLES):
            if self.actions.busy:
                command = self.actions.next_command(self.percepts)
                if command is not None:
                    return [command]
                self._finish()
                continue
            if self._request is not None:
                name, args = self._request
                self._request = None
                try:
                    self.actions.start(name, args, self.percepts)
                except ValueError as exc:
                    self._handle.fail(str(exc))  # type: ignore[attr-defined]
                    self._handle = None
                continue
            if self.agent.is_idle():
                return []
            self.agent.step()
        return []

    def _finish(self) -> None:
        if self._handle is not None:
            self._handle.succeed()  # type: ignore[attr-defined]
            self._handle = None

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Hand the outcome to the running action."""
        self.actions.on_outcome(command, outcome)

    @property
    def done(self) -> bool:
        """True when the agent has no goal left."""
        return self._handle is None and not self.actions.busy and self.agent.is_idle()
