"""The channels of Hammer et al., Section IV: percepts as Narsese events, operations as Commands.

Pure functions, so the encodings can be read and tested without a reasoner:

- vision: ``<bottle --> [left|center|right]>. :|:`` by thirds of the field of view,
  plus ``<bottle --> [see]>. :|:`` (the form the background knowledge's
  ``<trash --> [see]>`` generalises through ``<bottle --> trash>``) and, when the
  detector tracks instances, ``<{bottle3} --> [see]>. :|:`` (the instance whose pick
  hypothesis Section V.D says loses evidence);
- obstacles within the lidar's 2 m: ``<obstacle --> [left|front|right|free]>. :|:``;
- localisation: ``<({SELF} * {p3}) --> at>. :|:`` when the pose names a place;
- haptics: ``<gripper --> [hold|open]>. :|:``, with the other state denied
  (``<gripper --> [open]>. :|: {0.0 0.9}`` while holding, and the reverse).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence

from robocog.robot.commands import Command, Drop, Forward, GoTo, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose

#: the operations of Section IV, in the order they are registered
OPERATIONS: tuple[str, ...] = ("^forward", "^left", "^right", "^goto", "^pick", "^drop")
#: a field of view of 60 degrees, the camera of the paper's robot
DEFAULT_FOV = math.radians(60.0)
FORWARD_STEP = 0.5  # metres per ^forward
TURN_STEP = math.radians(30.0)  # radians per ^left / ^right

_ATOM = re.compile(r"[^A-Za-z0-9_]+")
_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def atom(name: str) -> str:
    """A name made safe as a Narsese atom (letters, digits, underscore)."""
    cleaned = _ATOM.sub("_", name.strip()) or "unnamed"
    return cleaned if not cleaned[0].isdigit() else "n" + cleaned


def direction(bearing: float, fov: float = DEFAULT_FOV) -> str:
    """Which third of the field of view a bearing falls in (positive bearing is left)."""
    third = fov / 6.0
    if bearing > third:
        return "left"
    if bearing < -third:
        return "right"
    return "center"


def detection_events(d: Detection, fov: float = DEFAULT_FOV, instances: bool = True) -> list[str]:
    """The events one detection becomes."""
    label = atom(d.label)
    out = [f"<{label} --> [{direction(d.bearing, fov)}]>. :|:", f"<{label} --> [see]>. :|:"]
    if instances and d.instance:
        out.append(f"<{{{atom(d.instance)}}} --> [see]>. :|:")
    return out


def obstacle_event(o: Obstacle) -> str:
    """The nearest obstacle within range, or ``free``."""
    sector = "free" if o.sector == "none" else o.sector
    return f"<obstacle --> [{sector}]>. :|:"


def place_event(p: Pose) -> str | None:
    """Where the robot is, when it is at a named place."""
    if not p.place:
        return None
    return f"<({{SELF}} * {{{atom(p.place)}}}) --> at>. :|:"


def gripper_event(g: Gripper | bool) -> str:
    """The haptic channel: holding something or open."""
    holding = g if isinstance(g, bool) else g.holding is not None
    return f"<gripper --> [{'hold' if holding else 'open'}]>. :|:"


def gripper_events(g: Gripper | bool) -> list[str]:
    """The haptic channel's Boolean as two events: the state, and the other state denied.

    Holding and open are two concepts to the reasoner; saying that the gripper is *not*
    holding (frequency 0) is what lets a pick's anticipated ``<gripper --> [hold]>``
    meet negative evidence at once, and what keeps an old ``hold`` from prompting a
    second ``^drop``.
    """
    holding = g if isinstance(g, bool) else g.holding is not None
    other = "open" if holding else "hold"
    return [gripper_event(holding), f"<gripper --> [{other}]>. :|: {{0.0 0.9}}"]


def encode(
    percepts: Iterable[Percept],
    fov: float = DEFAULT_FOV,
    instances: bool = True,
    max_detections: int = 3,
) -> list[str]:
    """All events of one frame: the place first, then the most confident detections,
    then the lidar and the gripper.

    The place comes first so that what is seen there follows it in time, which is what
    lets the reasoner form ``<<({SELF} * {p3}) --> at> =/> <trash --> [see]>>``. At most
    ``max_detections`` objects are reported per frame, as a detector keeps its best
    boxes, so a cluttered frame does not flood the reasoner.
    """
    detections: list[Detection] = []
    place: list[str] = []
    rest: list[str] = []
    for p in percepts:
        if isinstance(p, Detection):
            detections.append(p)
        elif isinstance(p, Obstacle):
            rest.append(obstacle_event(p))
        elif isinstance(p, Pose):
            e = place_event(p)
            if e:
                place.append(e)
        elif isinstance(p, Gripper):
            rest.extend(gripper_events(p))
    detections.sort(key=lambda d: (-d.confidence, d.distance))
    seen: list[str] = []
    for d in detections[:max_detections]:
        seen.extend(detection_events(d, fov, instances))
    return place + seen + rest


def recall_questions(percepts: Iterable[Percept], max_detections: int = 3) -> list[str]:
    """``<bottle --> ?1>?`` for each label reported this frame: what is ``bottle``?"""
    detections = sorted(
        (p for p in percepts if isinstance(p, Detection)), key=lambda d: (-d.confidence, d.distance)
    )
    labels = dict.fromkeys(atom(d.label) for d in detections[:max_detections])
    return [f"<{label} --> ?1>?" for label in labels]


_KIND = re.compile(r"^<([A-Za-z0-9_]+) --> ([A-Za-z0-9_]+)>$")


def seen_as(question: str, answer: str | None, f: float, c: float) -> str | None:
    """The sighting of a label reported under what the reasoner says the label is.

    Asked ``<bottle --> ?1>?`` and answering ``<bottle --> trash>`` with (f, c), the
    vision channel also reports ``<trash --> [see]>. :|:`` with frequency f and
    confidence f * c * 0.9 (the answer's weight on an input event). The category comes
    from the reasoner's own knowledge, not from the channel; only a plain atom counts
    (``<bottle --> [left]>`` or a compound is not a kind of thing).
    """
    if answer is None:
        return None
    m = _KIND.match(answer.strip())
    q = _KIND.match(question.replace(" ?1>?", " x>").strip())
    if not m or not q or m.group(1) != q.group(1) or m.group(2) == m.group(1):
        return None
    conf = round(max(0.0, min(0.99, f * c * 0.9)), 6)
    return f"<{m.group(2)} --> [see]>. :|: {{{f:.6f} {conf:.6f}}}"


def not_seen(kind: str) -> str:
    """A kind looked for and not in view this frame: ``<trash --> [see]>`` denied."""
    return f"<{atom(kind)} --> [see]>. :|: {{0.0 0.9}}"


def goal_at(place: str) -> str:
    """The goal of being at a place: ``<({SELF} * {p3}) --> at>! :|:``."""
    return f"<({{SELF}} * {{{atom(place)}}}) --> at>! :|:"


def command_for(op: str, args: str | None, places: Sequence[str] = ()) -> Command | None:
    """The Command an executed operation stands for, or None for an unknown one.

    ``args`` is the printed argument term, e.g. ``({SELF} * (next * p3))`` or
    ``({SELF} * {bottle3})``. For ``^goto`` a known place named in it is the target,
    otherwise the next checkpoint of the route; for ``^pick`` an instance in braces is
    the target, otherwise any trash in view.
    """
    words = [w for w in _WORD.findall(args or "") if w != "SELF"]
    if op == "^forward":
        return Forward(FORWARD_STEP)
    if op == "^left":
        return Turn(TURN_STEP)
    if op == "^right":
        return Turn(-TURN_STEP)
    if op == "^goto":
        known = {atom(p): p for p in places}
        for w in words:
            if w in known:
                return GoTo(known[w])
        return GoTo("next")
    if op == "^pick":
        braces = re.findall(r"\{([A-Za-z0-9_]+)\}", args or "")
        targets = [b for b in braces if b != "SELF"]
        return Pick(targets[0] if targets else "trash")
    if op == "^drop":
        return Drop()
    return None
