"""The robot contract shared by every mind and every body: percept and command types,
the Body and Mind protocols, and the sense-decide-act loop. Knows no engine.
"""

from robocog.robot.commands import (
    Cancel,
    Command,
    Drop,
    Forward,
    GoTo,
    Look,
    Outcome,
    Pick,
    PickUp,
    PutDown,
    Stack,
    Status,
    Turn,
    Unstack,
)
from robocog.robot.percepts import (
    Detection,
    Gripper,
    Obstacle,
    Percept,
    Pose,
    Range,
    Resting,
    Tag,
)
from robocog.robot.protocols import Body, Mind

__all__ = [
    "Body",
    "Cancel",
    "Command",
    "Detection",
    "Drop",
    "Forward",
    "GoTo",
    "Gripper",
    "Look",
    "Mind",
    "Obstacle",
    "Outcome",
    "Percept",
    "Pick",
    "PickUp",
    "Pose",
    "PutDown",
    "Range",
    "Resting",
    "Stack",
    "Status",
    "Tag",
    "Turn",
    "Unstack",
]
