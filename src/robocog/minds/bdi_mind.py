"""BdiMind: an AgentSpeak (Jason) agent behind the robot contract.

The percepts of each frame replace the agent's percepts, which its reasoning cycle
turns into beliefs annotated ``source(percept)`` as Jason does (``bdi_encoding`` gives
the literals). Environment actions (``goto pick drop forward left right``) become
Commands; each returns an ``ActionHandle`` that the Outcome completes, so the
intention that acted waits for the robot exactly as a Jason agent waits for its
environment. The default program is the background knowledge of Hammer et al. translated to
AgentSpeak (``knowledge/garbage.asl``), the paper's BDI baseline.
"""

from __future__ import annotations

import importlib.resources
from collections import deque
from collections.abc import Sequence

from robocog.bdi.actions import ActionHandle
from robocog.bdi.agent import Agent
from robocog.minds.bdi_encoding import command_for_action, percept_beliefs
from robocog.minds.channels import DEFAULT_FOV
from robocog.robot.commands import Command, Outcome, Pick
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose

#: the robot's environment actions, as the program calls them
ACTIONS: tuple[str, ...] = ("goto", "pick", "drop", "forward", "left", "right")


def program(name: str = "garbage.asl") -> str:
    """The text of an AgentSpeak program shipped with robocog."""
    return importlib.resources.files("robocog.minds").joinpath("knowledge", name).read_text()


class BdiMind:
    """A Mind whose decisions are the agent's environment actions."""

    name = "BDI"

    def __init__(
        self,
        source: str | None = None,
        agent_name: str = "collector",
        cycles_per_frame: int = 25,
        fov: float = DEFAULT_FOV,
        log: int = 200,
    ) -> None:
        self.output: deque[str] = deque(maxlen=max(1, log))
        self.agent = Agent(
            program() if source is None else source,
            agent_name,
            printer=lambda who, text: self.output.append(f"[{who}] {text}"),
            warn=lambda who, text: self.output.append(f"[{who}] warning: {text}"),
        )
        for action in ACTIONS:
            self.agent.register_action(action, self._environment_action(action))
        self.cycles_per_frame = cycles_per_frame
        self.fov = fov
        self._requested: list[tuple[Command, ActionHandle]] = []
        self._waiting: deque[tuple[Command, ActionHandle]] = deque()
        self.actions: list[str] = []

    def _environment_action(self, functor: str):  # noqa: ANN202 - the agent's callback type
        def act(*args: object) -> bool | ActionHandle:
            command = command_for_action(functor, args)
            self.actions.append(f"{functor}({', '.join(str(a) for a in args)})")
            if command is None:
                return False
            handle = ActionHandle()
            self._requested.append((command, handle))
            return handle

        return act

    # ---- the Mind protocol ----------------------------------------------------

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """What the sensors report now replaces what they reported before."""
        self.agent.set_percepts(percept_beliefs(percepts, self.fov))

    def decide(self) -> list[Command]:
        """Run reasoning cycles until the agent acts, is idle, or the frame's budget ends."""
        for _ in range(self.cycles_per_frame):
            if self.agent.is_idle():
                break
            self.agent.step()
            if self._requested:
                break
        requested, self._requested = self._requested, []
        self._waiting.extend(requested)
        return [command for command, _handle in requested]

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Complete the action that asked for ``command``."""
        for i, (cmd, handle) in enumerate(self._waiting):
            if cmd == command:
                del self._waiting[i]
                if outcome.ok:
                    handle.succeed()
                else:
                    handle.fail(outcome.reason or outcome.status.value)
                return

    def beliefs(self, functor: str | None = None) -> list[str]:
        """The agent's current beliefs as text (for reports and tests)."""
        return [str(b) for b in self.agent.beliefs(functor)]


def probe() -> str | None:
    """Why BdiMind cannot run yet, or None when the agent can drive the robot.

    Runs the program on one frame with a bottle in view and an open gripper: a working
    interpreter asks to pick the bottle.
    """
    try:
        mind = BdiMind()
    except Exception as exc:  # a broken program or installation may fail in any way
        return f"the AgentSpeak program does not load: {type(exc).__name__}: {exc}"
    frame: list[Percept] = [
        Detection("bottle", 0.0, 1.0, 0.9, "bottle1"),
        Obstacle("none", 2.0),
        Gripper(None),
        Pose(0.0, 0.0, 0.0, "p0"),
    ]
    try:
        for _ in range(5):
            mind.perceive(frame)
            for command in mind.decide():
                if command == Pick("bottle"):
                    return None
                mind.on_outcome(command, Outcome.success())
    except Exception as exc:
        return f"the agent fails while reasoning: {type(exc).__name__}: {exc}"
    return "the agent did not ask to pick a bottle it sees with an open gripper"
