"""Percepts as AgentSpeak beliefs and environment actions as Commands, for BdiMind.

Pure functions, so they can be read and tested without an interpreter: the beliefs are
written as text, which the agent reads as its percepts (through a cached reader), and an
action's arguments come as the Python values the agent hands over. The beliefs carry
the same information as NARS's channels (Hammer et al., Section IV):

- ``see(bottle)`` and ``position(bottle, left|center|right)`` per detected label;
- ``obstacle(left|front|right|free)``;
- ``at(p3)`` when the pose names a place;
- ``gripper(hold|open)``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence

from robocog.minds.channels import DEFAULT_FOV, FORWARD_STEP, TURN_STEP, direction
from robocog.robot.commands import Command, Drop, Forward, GoTo, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose

_NAME = re.compile(r"[^a-z0-9_]+")


def name(text: str) -> str:
    """A text made safe as an AgentSpeak atom (lower case, letters, digits, underscore)."""
    cleaned = _NAME.sub("_", text.strip().lower()) or "unnamed"
    return cleaned if cleaned[0].isalpha() else "n" + cleaned


def percept_beliefs(percepts: Iterable[Percept], fov: float = DEFAULT_FOV) -> list[str]:
    """The beliefs of one frame, without duplicates, in a stable order."""
    out: list[str] = []
    for p in percepts:
        if isinstance(p, Detection):
            label = name(p.label)
            out += [f"see({label})", f"position({label},{direction(p.bearing, fov)})"]
        elif isinstance(p, Obstacle):
            out.append(f"obstacle({'free' if p.sector == 'none' else p.sector})")
        elif isinstance(p, Pose) and p.place:
            out.append(f"at({name(p.place)})")
        elif isinstance(p, Gripper):
            out.append(f"gripper({'hold' if p.holding else 'open'})")
    return list(dict.fromkeys(out))


def command_for_action(functor: str, args: Sequence[object]) -> Command | None:
    """The Command an environment action stands for, or None if the robot has none.

    ``args`` are the action's arguments as the agent hands them (numbers as numbers,
    atoms and strings as text), so a distance or an angle is never printed and read back.
    """
    if functor == "goto":
        return GoTo(str(args[0]) if args else "next")
    if functor == "pick":
        return Pick(str(args[0]) if args else "trash")
    if functor == "drop":
        return Drop()
    if functor == "forward":
        metres = _number(args[0]) if args else None
        return Forward(FORWARD_STEP if metres is None else metres)
    if functor in ("left", "right"):
        degrees = _number(args[0]) if args else None
        angle = TURN_STEP if degrees is None else math.radians(degrees)
        return Turn(angle if functor == "left" else -angle)
    return None


def _number(value: object) -> float | None:
    """A number argument as a float, else None."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    return None
