"""The channels of Hammer et al., Section IV: percepts as Narsese events, operations as Commands.

Pure functions, so the encodings can be read and tested without a reasoner. The events
are built as the engine's own sentences (interned terms, truth values), never as text
to be parsed again, and an executed operation's arguments are read off the term the
engine hands to it:

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

import re
from collections.abc import Iterable, Sequence

from robocog.minds.channels import DEFAULT_FOV, FORWARD_STEP, TURN_STEP, direction
from robocog.nars import terms
from robocog.nars.narsese import Sentence
from robocog.nars.terms import EXT_SET, INHERITANCE, INT_SET, PRODUCT, Term
from robocog.nars.truth import Truth
from robocog.robot.commands import Command, Drop, Forward, GoTo, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose

__all__ = [
    "DEFAULT_FOV",
    "FORWARD_STEP",
    "OPERATIONS",
    "TURN_STEP",
    "atom",
    "command_for",
    "detection_events",
    "direction",
    "encode",
    "frame_events",
    "goal_at",
    "gripper_event",
    "gripper_events",
    "not_seen",
    "obstacle_event",
    "place_event",
    "recall_questions",
    "seen_as",
]

#: the operations of Section IV, in the order they are registered
OPERATIONS: tuple[str, ...] = ("^forward", "^left", "^right", "^goto", "^pick", "^drop")
#: the task goal the background knowledge leads to: ``G! :|:``
TASK_GOAL = Sentence(terms.atom("G"), "!", ":|:")
#: a state reported as not holding: frequency 0, the confidence of an input event
DENIED = Truth(0.0, 0.9)

_ATOM = re.compile(r"[^A-Za-z0-9_]+")
_SELF = terms.compound(EXT_SET, (terms.atom("SELF"),))
_AT = terms.atom("at")
_SEE = terms.compound(INT_SET, (terms.atom("see"),))
_QUERY = terms.atom("?1")


def atom(name: str) -> str:
    """A name made safe as a Narsese atom (letters, digits, underscore)."""
    cleaned = _ATOM.sub("_", name.strip()) or "unnamed"
    return cleaned if not cleaned[0].isdigit() else "n" + cleaned


def _name(name: str) -> Term:
    return terms.atom(atom(name))


def _is(subject: Term, predicate: Term) -> Term:
    return terms.statement(subject, INHERITANCE, predicate)


def _property(name: str) -> Term:
    """``[name]``."""
    return terms.compound(INT_SET, (terms.atom(name),))


def _instance(name: str) -> Term:
    """``{name}``."""
    return terms.compound(EXT_SET, (_name(name),))


def _event(term: Term, truth: Truth | None = None) -> Sentence:
    return Sentence(term, ".", ":|:", truth)


def _at(place: str) -> Term:
    """``<({SELF} * {place}) --> at>``."""
    return _is(terms.compound(PRODUCT, (_SELF, _instance(place))), _AT)


def detection_events(
    d: Detection, fov: float = DEFAULT_FOV, instances: bool = True
) -> list[Sentence]:
    """The events one detection becomes."""
    label = _name(d.label)
    out = [_event(_is(label, _property(direction(d.bearing, fov)))), _event(_is(label, _SEE))]
    if instances and d.instance:
        out.append(_event(_is(_instance(d.instance), _SEE)))
    return out


def obstacle_event(o: Obstacle) -> Sentence:
    """The nearest obstacle within range, or ``free``."""
    sector = "free" if o.sector == "none" else o.sector
    return _event(_is(terms.atom("obstacle"), _property(sector)))


def place_event(p: Pose) -> Sentence | None:
    """Where the robot is, when it is at a named place."""
    if not p.place:
        return None
    return _event(_at(p.place))


def gripper_event(g: Gripper | bool, truth: Truth | None = None) -> Sentence:
    """The haptic channel: holding something or open."""
    holding = g if isinstance(g, bool) else g.holding is not None
    return _event(_is(terms.atom("gripper"), _property("hold" if holding else "open")), truth)


def gripper_events(g: Gripper | bool) -> list[Sentence]:
    """The haptic channel's Boolean as two events: the state, and the other state denied.

    Holding and open are two concepts to the reasoner; saying that the gripper is *not*
    holding (frequency 0) is what lets a pick's anticipated ``<gripper --> [hold]>``
    meet negative evidence at once, and what keeps an old ``hold`` from prompting a
    second ``^drop``.
    """
    holding = g if isinstance(g, bool) else g.holding is not None
    return [gripper_event(holding), gripper_event(not holding, DENIED)]


def frame_events(
    percepts: Iterable[Percept],
    fov: float = DEFAULT_FOV,
    instances: bool = True,
    max_detections: int = 3,
) -> tuple[list[Sentence], list[Sentence]]:
    """The events of one frame in two parts: where the robot is, and the rest (the most
    confident detections, then the lidar and the gripper).

    The place comes first so that what is seen there follows it in time, which is what
    lets the reasoner form ``<<({SELF} * {p3}) --> at> =/> <trash --> [see]>>``. At most
    ``max_detections`` objects are reported per frame, as a detector keeps its best
    boxes, so a cluttered frame does not flood the reasoner.
    """
    detections: list[Detection] = []
    place: list[Sentence] = []
    rest: list[Sentence] = []
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
    seen: list[Sentence] = []
    for d in detections[:max_detections]:
        seen.extend(detection_events(d, fov, instances))
    return place, seen + rest


def encode(
    percepts: Iterable[Percept],
    fov: float = DEFAULT_FOV,
    instances: bool = True,
    max_detections: int = 3,
) -> list[Sentence]:
    """All events of one frame, the place first (see :func:`frame_events`)."""
    place, rest = frame_events(percepts, fov, instances, max_detections)
    return place + rest


def recall_questions(percepts: Iterable[Percept], max_detections: int = 3) -> list[Term]:
    """``<bottle --> ?1>`` for each label reported this frame: what is ``bottle``?"""
    detections = sorted(
        (p for p in percepts if isinstance(p, Detection)), key=lambda d: (-d.confidence, d.distance)
    )
    labels = dict.fromkeys(_name(d.label) for d in detections[:max_detections])
    return [_is(label, _QUERY) for label in labels]


def _plain(t: Term) -> bool:
    """A name that is a kind of thing: not a compound, a variable or an operation."""
    return t.is_atom and not t.is_var and not t.is_op


def seen_as(question: Term, answer: Term | None, f: float, c: float) -> Sentence | None:
    """The sighting of a label reported under what the reasoner says the label is.

    Asked ``<bottle --> ?1>`` and answering ``<bottle --> trash>`` with (f, c), the
    vision channel also reports ``<trash --> [see]>. :|:`` with frequency f and
    confidence f * c * 0.9 (the answer's weight on an input event), both to six decimal
    places. The category comes from the reasoner's own knowledge, not from the channel;
    only a plain name counts (``<bottle --> [left]>`` or a compound is not a kind of thing).
    """
    if answer is None or answer.op != INHERITANCE or question.op != INHERITANCE:
        return None
    label, kind = answer.args
    if not (_plain(label) and _plain(kind)) or label is not question.subject or kind is label:
        return None
    conf = round(max(0.0, min(0.99, f * c * 0.9)), 6)
    return _event(_is(kind, _SEE), Truth(round(f, 6), conf))


def seen_kind(event: Sentence) -> Term:
    """The kind a sighting reports: ``trash`` of ``<trash --> [see]>``."""
    return event.term.subject


def not_seen(kind: Term) -> Sentence:
    """A kind looked for and not in view this frame: ``<trash --> [see]>`` denied."""
    return _event(_is(kind, _SEE), DENIED)


def goal_at(place: str) -> Sentence:
    """The goal of being at a place: ``<({SELF} * {p3}) --> at>! :|:``."""
    return Sentence(_at(place), "!", ":|:")


def arrived_at(place: str) -> Sentence:
    """The robot has arrived at a place: ``<({SELF} * {p3}) --> at>. :|:``."""
    return _event(_at(place))


def _names(args: Term | None) -> list[str]:
    """The names in an operation's argument, left to right, but ``SELF``."""
    if args is None:
        return []
    return [t.name for t in args.walk() if _plain(t) and t.name != "SELF"]  # type: ignore[misc]


def _instances(args: Term | None) -> list[str]:
    """The names in braces (``{bottle3}``) in an operation's argument, left to right."""
    if args is None:
        return []
    return [
        t.args[0].name  # type: ignore[misc]
        for t in args.walk()
        if t.op == EXT_SET and len(t.args) == 1 and _plain(t.args[0]) and t is not _SELF
    ]


def command_for(op: str, args: Term | None, places: Sequence[str] = ()) -> Command | None:
    """The Command an executed operation stands for, or None for an unknown one.

    ``args`` is the argument term the reasoner hands to the operation, e.g.
    ``({SELF} * (next * p3))`` or ``({SELF} * {bottle3})``. For ``^goto`` a known place
    named in it is the target, otherwise the next checkpoint of the route; for ``^pick``
    an instance in braces is the target, otherwise any trash in view.
    """
    if op == "^forward":
        return Forward(FORWARD_STEP)
    if op == "^left":
        return Turn(TURN_STEP)
    if op == "^right":
        return Turn(-TURN_STEP)
    if op == "^goto":
        known = {atom(p): p for p in places}
        for w in _names(args):
            if w in known:
                return GoTo(known[w])
        return GoTo("next")
    if op == "^pick":
        targets = _instances(args)
        return Pick(targets[0] if targets else "trash")
    if op == "^drop":
        return Drop()
    return None
