"""What the garbage minds share of Hammer et al.'s sensor channels (Section IV): the
camera's field of view split in thirds, and the length of one step and one turn.

Kept apart from the encodings so that either mind reads the same numbers without
loading the other's engine.
"""

from __future__ import annotations

import math

#: a field of view of 60 degrees, the camera of the paper's robot
DEFAULT_FOV = math.radians(60.0)
FORWARD_STEP = 0.5  # metres per ^forward
TURN_STEP = math.radians(30.0)  # radians per ^left / ^right


def direction(bearing: float, fov: float = DEFAULT_FOV) -> str:
    """Which third of the field of view a bearing falls in (positive bearing is left)."""
    third = fov / 6.0
    if bearing > third:
        return "left"
    if bearing < -third:
        return "right"
    return "center"
