"""The garbage field of Hammer et al., Section V, as an embedded, seeded simulator.

A 22 x 22 m square of a football field, fenced. Checkpoints lie on a circular route near
the boundary (the robot navigates to them by name), and bottles and cups stand upright
at the checkpoints. The robot is a tracked base with a camera, a 2 m lidar sector
reading, a localisation estimate once a second and a gripper that drops what it holds
into a trailer. The rules are those the paper reports, so that a mind's success rate
comes out of the same causes the paper names:

- the camera recognises an object in the current light with the paper's rate (Table I:
  sunny 83%, cloudy 70%, evening 61%); a recognised object is seen in most frames when
  near and less often far away, a tipped one less often than an upright one;
- a pick on a well-detected upright object succeeds about 85% of the time (less in
  evening light, whose shadows spoil the bounding boxes); when it fails the object may
  lean over, and a tipped object is still seen but can no longer be picked;
- the mission runs on one battery charge (``mission_time``): time spent on futile picks
  is time missing at the end of the route;
- trash accumulates at some checkpoints more often than at others, so a mind that
  keeps evidence can learn where it is seen. Each round is one run of the paper's test
  procedure (Section V.C): the robot starts again from the start corner on a fresh
  battery, the operator clears away what the last round left, and fresh objects are
  placed with the hotspot weights. The field counts, per checkpoint, the arrivals and
  those with trash in view, which is what a mind's evidence can be checked against.

Time is simulated: every ``percepts()`` call is one camera frame (4 per second, as on
the paper's Jetson Nano) and each command takes the time it would take the robot, so a
mission of several minutes runs in a fraction of a second. All randomness comes from
one ``random.Random`` seeded at construction.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

from robocog.robot.commands import Command, Drop, Forward, GoTo, Outcome, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose

Light = Literal["sunny", "cloudy", "evening"]

#: Detection rate of bottles and cups by light (Hammer et al., Table I).
DETECTION_RATE: dict[str, float] = {"sunny": 0.83, "cloudy": 0.70, "evening": 0.61}
#: Grasp success on a well-detected upright object by light (Section V.C: 85%; the
#: paper notes worse manipulation in the strong shadows of the evening sun).
PICK_SUCCESS: dict[str, float] = {"sunny": 0.85, "cloudy": 0.85, "evening": 0.75}
LIGHTS: tuple[str, ...] = tuple(DETECTION_RATE)
LABELS: tuple[str, ...] = ("bottle", "cup")


@dataclass(frozen=True)
class GarbageConfig:
    """Every rule of the field as a number, so an experiment can state what it ran."""

    light: Light = "sunny"
    size: float = 22.0
    checkpoints: int = 8
    route_radius: float = 8.5
    objects: int = 10
    #: relative accumulation weight per checkpoint index (missing indices weigh 1)
    hotspots: dict[int, float] = field(default_factory=lambda: {2: 4.0, 5: 4.0})
    max_per_checkpoint: int = 3
    #: objects stand this far (m) ahead of the checkpoint, along the route
    place_distance: tuple[float, float] = (0.8, 1.8)
    place_spread: float = 0.45  # radians either side of the route direction
    camera_fov: float = math.radians(60.0)
    camera_range: float = 5.0
    frame_near: float = 0.97  # per-frame detection of a recognised upright object, near
    frame_far: float = 0.5  # the same at camera_range (linear from near_range)
    near_range: float = 2.0
    tipped_visibility: float = 0.75  # a lying object is seen this much less often
    lidar_range: float = 2.0
    frame_seconds: float = 0.25
    localisation_period: float = 1.0
    place_radius: float = 1.0
    speed: float = 0.35  # m/s on the tracks
    turn_rate: float = math.radians(45.0)  # rad/s
    pick_reach: float = 2.5  # beyond this the arm cannot reach, even after approach
    pick_seconds: float = 12.0  # lowering the arm, the proportional approach, grasping
    recover_seconds: float = 6.0  # the backing-off after a failed grasp
    drop_seconds: float = 4.0
    tip_on_failure: float = 0.6
    mission_time: float = 420.0  # one battery charge, seconds
    #: a new round starts from a cleared field (the test procedure places the objects
    #: anew); False leaves what the last round left, tipped bottles included
    clear_between_rounds: bool = True
    #: the detector's recognition rate, in place of the light's (Table I) when given:
    #: lets a sweep ask how the minds fare as detection worsens, which the paper's three
    #: lights sample at only three points
    detection: float | None = None
    #: grasp success on a well-detected upright object, in place of the light's
    grasp: float | None = None

    def __post_init__(self) -> None:
        if self.light not in DETECTION_RATE:
            raise ValueError(f"light must be one of {', '.join(LIGHTS)}, not {self.light!r}")
        if self.checkpoints < 2 or self.objects < 0:
            raise ValueError("need at least two checkpoints and a non-negative object count")
        for name in ("detection", "grasp"):
            value = getattr(self, name)
            if value is not None and not 0.0 <= value <= 1.0:
                raise ValueError(f"{name} must be a probability in [0, 1], not {value!r}")

    @property
    def detection_rate(self) -> float:
        """Share of objects the detector recognises (Table I's rate for the light unless
        ``detection`` overrides it)."""
        return DETECTION_RATE[self.light] if self.detection is None else self.detection

    @property
    def pick_success(self) -> float:
        """Grasp success on a well-detected upright object (the light's unless ``grasp``
        overrides it)."""
        return PICK_SUCCESS[self.light] if self.grasp is None else self.grasp


@dataclass
class Trash:
    """One bottle or cup on the field, and what happened to it."""

    instance: str
    label: str
    x: float
    y: float
    checkpoint: str
    round: int
    recognisable: bool
    upright: bool = True
    held: bool = False
    collected: bool = False
    cleared: bool = False  # taken away by the operator at the end of its round
    times_seen: int = 0
    pick_attempts: int = 0
    picks_while_tipped: int = 0
    tipped_at: float | None = None

    @property
    def on_field(self) -> bool:
        """Still lying or standing on the ground."""
        return not (self.held or self.collected or self.cleared)


@dataclass(frozen=True)
class Event:
    """A line of the run's log: when, what, about which object."""

    time: float
    kind: str
    detail: str = ""


def _wrap(angle: float) -> float:
    """An angle in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))


class GarbageField:
    """The field as a Body: ``percepts()``, ``execute(command)``, ``time()``."""

    def __init__(self, config: GarbageConfig | None = None, seed: int = 0) -> None:
        self.config = config or GarbageConfig()
        self.seed = seed
        self.rng = random.Random(seed)
        c = self.config
        mid = c.size / 2.0
        # Checkpoints clockwise from the upper left, as the route of Fig. 6.
        self.checkpoints: dict[str, tuple[float, float]] = {}
        for i in range(c.checkpoints):
            angle = math.radians(135.0) - 2.0 * math.pi * i / c.checkpoints
            self.checkpoints[f"p{i}"] = (
                mid + c.route_radius * math.cos(angle),
                mid + c.route_radius * math.sin(angle),
            )
        self.route: list[str] = list(self.checkpoints)
        self.start: tuple[float, float] = (1.5, c.size - 1.5)  # upper-left corner
        self.start_heading = -math.pi / 4.0  # facing into the field
        self.x, self.y = self.start
        self.theta = self.start_heading
        self.clock = 0.0
        self.holding: Trash | None = None
        self.trash: list[Trash] = []
        self.rounds = 0
        self.visited: list[str] = []
        self.last_checkpoint: int = -1
        self.route_complete = False
        self.trajectory: list[tuple[float, float]] = [(self.x, self.y)]
        self.events: list[Event] = []
        self.futile_seconds = 0.0  # spent on picks at objects lying over
        self._last_pose_time = -math.inf
        #: per checkpoint: arrivals, and arrivals with an object the camera can show
        self.arrivals: dict[str, int] = dict.fromkeys(self.route, 0)
        self.arrivals_with_trash: dict[str, int] = dict.fromkeys(self.route, 0)
        self.new_round()

    # ---- setting up a round -------------------------------------------------------

    def _heading_at(self, index: int) -> float:
        """Direction of travel when arriving at checkpoint ``index`` along the route."""
        name = self.route[index]
        prev = self.checkpoints[self.route[index - 1]] if index > 0 else self.start
        cx, cy = self.checkpoints[name]
        return math.atan2(cy - prev[1], cx - prev[0])

    def new_round(self) -> list[Trash]:
        """Start a run of the test procedure: scatter a fresh set of objects over the
        checkpoints and restart the route from the start corner.

        Checkpoints with a hotspot weight receive objects more often, which is what a
        mind can learn over repeated rounds. With ``clear_between_rounds`` what the last
        round left on the ground is taken away first, so that what a later round shows
        at a checkpoint is that round's trash, not a bottle the robot tipped over before.
        An object the robot holds stays in its gripper.
        """
        c = self.config
        if self.rounds:
            if c.clear_between_rounds:
                for t in self.trash:
                    if t.on_field:
                        t.cleared = True
            self.x, self.y = self.start
            self.theta = self.start_heading
            self.trajectory.append((self.x, self.y))
        self.rounds += 1
        weights = [c.hotspots.get(i, 1.0) for i in range(len(self.route))]
        counts = [0] * len(self.route)
        placed: list[Trash] = []
        for n in range(c.objects):
            open_slots = [
                w if counts[i] < c.max_per_checkpoint else 0.0 for i, w in enumerate(weights)
            ]
            if not any(open_slots):
                break
            index = self.rng.choices(range(len(self.route)), weights=open_slots)[0]
            counts[index] += 1
            heading = self._heading_at(index)
            cx, cy = self.checkpoints[self.route[index]]
            for _attempt in range(20):
                d = self.rng.uniform(*c.place_distance)
                a = heading + self.rng.uniform(-c.place_spread, c.place_spread)
                x, y = cx + d * math.cos(a), cy + d * math.sin(a)
                if all(math.hypot(x - t.x, y - t.y) > 0.35 for t in self.trash + placed):
                    break
            label = self.rng.choice(LABELS)
            placed.append(
                Trash(
                    instance=f"{label}{len(self.trash) + n + 1}",
                    label=label,
                    x=min(max(x, 0.3), c.size - 0.3),
                    y=min(max(y, 0.3), c.size - 0.3),
                    checkpoint=self.route[index],
                    round=self.rounds,
                    recognisable=self.rng.random() < c.detection_rate,
                )
            )
        self.trash.extend(placed)
        self.visited = []
        self.last_checkpoint = -1
        self.route_complete = False
        self._log("round", f"{self.rounds}: {len(placed)} objects")
        return placed

    # ---- the Body protocol --------------------------------------------------------

    def time(self) -> float:
        """Simulated seconds since the mission started."""
        return self.clock

    @property
    def done(self) -> bool:
        """The route is complete or the battery is spent."""
        return self.route_complete or self.out_of_time

    @property
    def out_of_time(self) -> bool:
        """The mission's battery charge is spent."""
        return self.clock >= self.config.mission_time

    def percepts(self) -> list[Percept]:
        """One camera frame, the lidar sector, the gripper, and the pose once a second."""
        c = self.config
        self.clock += c.frame_seconds
        out: list[Percept] = []
        for t in self.trash:
            if not t.on_field:
                continue
            detection = self._sense(t)
            if detection is not None:
                t.times_seen += 1
                out.append(detection)
        out.append(self._lidar())
        out.append(Gripper(self.in_gripper()))
        if self.clock - self._last_pose_time >= c.localisation_period - 1e-9:
            self._last_pose_time = self.clock
            out.append(Pose(self.x, self.y, self.theta, self.place()))
        return out

    def in_gripper(self) -> str | None:
        """What the gripper reports it holds (the name its percepts give), or None."""
        return self.holding.instance if self.holding else None

    def execute(self, command: Command) -> Outcome:
        """Carry out one command, advancing the clock by the time it takes."""
        if self.out_of_time:
            return Outcome.failure("battery spent")
        if isinstance(command, Forward):
            return self._forward(command.distance)
        if isinstance(command, Turn):
            return self._turn(command.angle)
        if isinstance(command, GoTo):
            return self._goto(command.place)
        if isinstance(command, Pick):
            return self._pick(command.target)
        if isinstance(command, Drop):
            return self._drop()
        return Outcome.failure(f"{type(command).__name__} is not supported by this robot")

    # ---- sensing ------------------------------------------------------------------

    def _relative(self, x: float, y: float) -> tuple[float, float]:
        """Distance and bearing (positive to the left) of a point from the robot."""
        dx, dy = x - self.x, y - self.y
        return math.hypot(dx, dy), _wrap(math.atan2(dy, dx) - self.theta)

    def detection_probability(self, t: Trash) -> float:
        """Chance that this frame shows ``t``: recognition, field of view, distance, pose."""
        c = self.config
        if not t.on_field or not t.recognisable:
            return 0.0
        distance, bearing = self._relative(t.x, t.y)
        if distance > c.camera_range or abs(bearing) > c.camera_fov / 2.0:
            return 0.0
        if distance <= c.near_range:
            p = c.frame_near
        else:
            k = (distance - c.near_range) / (c.camera_range - c.near_range)
            p = c.frame_near + k * (c.frame_far - c.frame_near)
        return p * (1.0 if t.upright else c.tipped_visibility)

    def _sense(self, t: Trash) -> Detection | None:
        p = self.detection_probability(t)
        if p <= 0.0 or self.rng.random() >= p:
            return None
        distance, bearing = self._relative(t.x, t.y)
        confidence = min(0.99, max(0.3, self.rng.gauss(0.75 if t.upright else 0.5, 0.1)))
        return Detection(
            label=t.label,
            bearing=bearing + self.rng.gauss(0.0, 0.02),
            distance=max(0.05, distance + self.rng.gauss(0.0, 0.05)),
            confidence=round(confidence, 3),
            instance=t.instance,
        )

    def _lidar(self) -> Obstacle:
        """The nearest fence point within lidar range, by sector (front is +-30 deg)."""
        c = self.config
        best: tuple[float, float] | None = None
        # The fence: the nearest point on each side of the square.
        for px, py in ((0.0, self.y), (c.size, self.y), (self.x, 0.0), (self.x, c.size)):
            d, b = self._relative(px, py)
            if d <= c.lidar_range and (best is None or d < best[0]):
                best = (d, b)
        if best is None:
            return Obstacle("none", c.lidar_range)
        d, b = best
        sector = "front" if abs(b) <= math.radians(30) else ("left" if b > 0 else "right")
        return Obstacle(sector, round(d, 3))

    def place(self) -> str | None:
        """The checkpoint the robot is at, if any."""
        for name, (px, py) in self.checkpoints.items():
            if math.hypot(px - self.x, py - self.y) <= self.config.place_radius:
                return name
        return None

    # ---- acting -------------------------------------------------------------------

    def _advance(self, seconds: float) -> None:
        self.clock += seconds

    def _move_to(self, x: float, y: float, turn: bool = True) -> float:
        """Drive in a straight line (turning first unless backing); returns the metres."""
        c = self.config
        distance = math.hypot(x - self.x, y - self.y)
        if distance > 1e-6 and turn:
            heading = math.atan2(y - self.y, x - self.x)
            self._advance(abs(_wrap(heading - self.theta)) / c.turn_rate)
            self.theta = heading
        steps = max(1, int(distance / 0.5))
        for i in range(1, steps + 1):
            self.trajectory.append(
                (self.x + (x - self.x) * i / steps, self.y + (y - self.y) * i / steps)
            )
        self.x, self.y = x, y
        self._advance(distance / c.speed)
        return distance

    #: How close to the fence the robot may come (metres); a subclass with a larger
    #: body keeps further off.
    fence_margin = 0.3

    def _fenced_move(self, x: float, y: float, turn: bool = True) -> Outcome:
        """Drive to (x, y) held inside the fence; reaching the fence instead fails.

        Shared by ``_forward`` and ``drive_to`` here and in every subclass, so that the
        fence is one rule whatever moves the robot (a subclass overrides ``_move_to``).
        """
        m, size = self.fence_margin, self.config.size
        cx = min(max(x, m), size - m)
        cy = min(max(y, m), size - m)
        self._move_to(cx, cy, turn=turn)
        if (cx, cy) != (x, y):
            self._log("blocked", "fence")
            return Outcome.failure("blocked by the fence")
        return Outcome.success()

    def _face(self, heading: float) -> None:
        """Turn on the spot to ``heading``, spending the time the turn takes."""
        self._advance(abs(_wrap(heading - self.theta)) / self.config.turn_rate)
        self.theta = _wrap(heading)

    def _forward(self, distance: float) -> Outcome:
        x = self.x + distance * math.cos(self.theta)
        y = self.y + distance * math.sin(self.theta)
        return self._fenced_move(x, y, turn=distance >= 0)

    def drive_to(self, x: float, y: float, heading: float | None = None) -> Outcome:
        """Drive to a point of the field (a navigator's goal that is no checkpoint),
        then face ``heading`` if given; a point beyond the fence fails at the fence."""
        if self.out_of_time:
            return Outcome.failure("battery spent")
        outcome = self._fenced_move(x, y)
        if outcome.ok and heading is not None:
            self._face(heading)
        return outcome

    def _turn(self, angle: float) -> Outcome:
        self.theta = _wrap(self.theta + angle)
        self._advance(abs(angle) / self.config.turn_rate)
        return Outcome.success()

    def _resolve_place(self, place: str) -> int | None:
        if place in ("next", ""):
            return self.last_checkpoint + 1
        if place in self.checkpoints:
            return self.route.index(place)
        if place == "start":
            return len(self.route)
        return None

    def _goto(self, place: str) -> Outcome:
        index = self._resolve_place(place)
        if index is None:
            return Outcome.failure(f"unknown place {place!r}")
        if index >= len(self.route):
            self._move_to(*self.start)
            self.route_complete = True
            self._log("goto", "start: route complete")
            return Outcome.success()
        return self._reach_checkpoint(index)

    def _reach_checkpoint(self, index: int) -> Outcome:
        """Go to checkpoint ``index`` of the route and face along it (a subclass drives
        there its own way and books the arrival alike)."""
        self._move_to(*self.checkpoints[self.route[index]])
        self.theta = self._heading_at(index)
        self._book_arrival(index)
        return Outcome.success()

    def _book_arrival(self, index: int, note: str = "") -> None:
        """The report's bookkeeping of an arrival at checkpoint ``index``."""
        name = self.route[index]
        self.last_checkpoint = index
        if name not in self.visited:
            self.visited.append(name)
        self.arrivals[name] += 1
        if any(self.detection_probability(t) > 0.0 for t in self.trash):
            self.arrivals_with_trash[name] += 1
        self._log("goto", name + note)

    def _target(self, target: str) -> Trash | None:
        """The object the pick procedure aims at: the nearest one it can see that
        ``target`` names (an instance, a label, or ``trash`` for any).

        The procedure runs its own camera loop while it approaches, so it chooses among
        every object the camera can show now, not only those of the last frame.
        """
        candidates = [
            t
            for t in self.trash
            if t.on_field
            and target in ("", "trash", "any", t.label, t.instance)
            and self.detection_probability(t) > 0.0
        ]
        if not candidates:
            return None
        return min(candidates, key=lambda t: math.hypot(t.x - self.x, t.y - self.y))

    def _pick(self, target: str) -> Outcome:
        """The hand-made motor procedure: approach the object, grasp, come back.

        The robot backs off to where it started the pick and faces the way it faced
        then, so the other objects at the checkpoint stay in view.
        """
        c = self.config
        if self.holding is not None:
            return Outcome.failure("the gripper is already holding something")
        t = self._target(target)
        if t is None:
            self._advance(1.0)
            return Outcome.failure(f"no {target or 'object'} in view")
        t.pick_attempts += 1
        distance, _bearing = self._relative(t.x, t.y)
        if distance > c.pick_reach:
            self._advance(2.0)
            self._log("pick", f"{t.instance}: too far")
            return Outcome.failure("too far away to grab")
        home, facing, began = (self.x, self.y), self.theta, self.clock
        was_upright = t.upright
        stand_off = 0.3
        if distance > stand_off:
            k = (distance - stand_off) / distance
            self._move_to(self.x + (t.x - self.x) * k, self.y + (t.y - self.y) * k)
        self._advance(c.pick_seconds)
        if not t.upright:
            t.picks_while_tipped += 1
            outcome = Outcome.failure("slipped: the object is lying over")
            self._log("pick", f"{t.instance}: lying over, cannot be grasped")
        elif self.rng.random() < c.pick_success:
            t.held = True
            self.holding = t
            outcome = Outcome.success()
            self._log("pick", f"{t.instance}: held")
        else:
            if self.rng.random() < c.tip_on_failure:
                t.upright = False
                t.tipped_at = self.clock
                self._log("tip", t.instance)
            outcome = Outcome.failure("missed the grasp")
            self._log("pick", f"{t.instance}: missed")
        # Arm up, back off to where the pick began and face the same way again.
        self._move_to(*home, turn=False)
        self._advance(abs(_wrap(facing - self.theta)) / c.turn_rate)
        self.theta = facing
        if not outcome.ok:
            self._advance(c.recover_seconds)
        if not was_upright:
            self.futile_seconds += self.clock - began
        return outcome

    def _drop(self) -> Outcome:
        if self.holding is None:
            self._advance(1.0)
            return Outcome.failure("the gripper is empty")
        t = self.holding
        t.held = False
        t.collected = True
        self.holding = None
        self._advance(self.config.drop_seconds)
        self._log("drop", t.instance)
        return Outcome.success()

    def _log(self, kind: str, detail: str = "") -> None:
        self.events.append(Event(round(self.clock, 3), kind, detail))

    # ---- what the experiment reads afterwards --------------------------------------

    def objects(self, round_: int | None = None) -> list[Trash]:
        """The objects of one round (all rounds by default)."""
        return [t for t in self.trash if round_ is None or t.round == round_]

    def collected(self, round_: int | None = None) -> int:
        """How many objects of the round ended in the trailer."""
        return sum(t.collected for t in self.objects(round_))

    def failure_cause(self, t: Trash) -> str | None:
        """Why an object was not collected, in the paper's terms (None if it was).

        ``detection``: the robot was at its checkpoint but the camera never reported
        it; ``grasp``: it was picked at but the grasp failed (it may have been tipped
        over); ``decision``: it was seen and graspable but the mind never tried, carried
        it and never dropped it, or ended the route without going to its checkpoint;
        ``time``: the battery ran out before the robot reached its checkpoint.
        """
        if t.collected:
            return None
        if t.held:
            return "decision"
        if t.pick_attempts > 0:
            return "grasp"
        if t.times_seen > 0:
            return "decision"
        if t.checkpoint not in self.visited:
            return "time" if self.out_of_time else "decision"
        return "detection"

    def describe(self) -> dict[str, object]:
        """The field's layout, for plots and reports."""
        return {
            "size": self.config.size,
            "start": self.start,
            "checkpoints": dict(self.checkpoints),
            "hotspots": {
                self.route[i]: w for i, w in self.config.hotspots.items() if i < len(self.route)
            },
        }


def route_places(field_: GarbageField) -> Sequence[str]:
    """The checkpoint names in route order (what an operator tells a mind)."""
    return tuple(field_.route)
