"""Percepts as AgentSpeak beliefs and environment actions as Commands, for BdiMind.

Pure functions over text, so they can be read and tested without an interpreter. The
beliefs carry the same information as NARS's channels (Hammer et al., Section IV):

- ``see(bottle)`` and ``position(bottle, left|center|right)`` per detected label;
- ``obstacle(left|front|right|free)``;
- ``at(p3)`` when the pose names a place;
- ``gripper(hold|open)``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable

from robocog.minds.nars_encoding import DEFAULT_FOV, FORWARD_STEP, TURN_STEP, direction
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


def command_for_action(functor: str, args: list[str]) -> Command | None:
    """The Command an environment action stands for, or None if the robot has none."""
    if functor == "goto":
        return GoTo(args[0] if args else "next")
    if functor == "pick":
        return Pick(args[0] if args else "trash")
    if functor == "drop":
        return Drop()
    if functor == "forward":
        return Forward(float(args[0]) if args and _number(args[0]) else FORWARD_STEP)
    if functor in ("left", "right"):
        angle = math.radians(float(args[0])) if args and _number(args[0]) else TURN_STEP
        return Turn(angle if functor == "left" else -angle)
    return None


def _number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True
