"""A wheeled mobile base for MuJoCo worlds: the body, its drive, and what it senses.

Field robots such as Hammer et al.'s garbage collector ("Non-Axiomatic Reasoning for an
Autonomous Mobile Robot") or a Q.bo in a room share one make-up: a differential drive,
wheel encoders that slip, an IMU, a 2D lidar or ultrasonic rangers, and a pose estimate
built from those alone. This module gives a world all of it so that its percepts never
come from the simulator's state:

* :class:`BaseSpec` and :func:`base_fragment`: the MJCF of a base (chassis, two driven
  wheels on hinges with velocity servos, two frictionless casters, an IMU site, a lidar
  site) with a hook for what rides on it (an arm, a camera); the world pastes the three
  strings into its ``<worldbody>``, ``<actuator>`` and ``<sensor>``.
* :class:`DiffDrive`: turns a body velocity (m/s, rad/s) into wheel speeds, within the
  spec's limits; :func:`steer` is a simple go-to-point law on an estimated pose.
* :func:`cast_rays`, :class:`Lidar` and :class:`RangeCone`: distances by MuJoCo's ray
  casting (``mj_multiRay``), over a full planar scan or a narrow cone (an ultrasonic
  ranger), each with a range limit; the robot's own geoms (group :data:`ROBOT_GROUP`)
  are never hit.
* :class:`WheelOdometry`: dead reckoning from the encoders (each increment off by a
  random slip) and the IMU's yaw rate (with a bias), so it drifts as a real one does.
* :class:`Localiser`: the odometry's motion, corrected by matching each lidar scan to
  the known walls (point-to-line least squares, a few Gauss-Newton steps, outliers
  gated); where the lidar sees no wall the estimate runs on odometry alone.
* :class:`MobileBase`: the above bundled for one base in one model.

The API is kept backward compatible: new parameters come with defaults.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from robocog.worlds.physics.gl import choose_gl

choose_gl()

import mujoco  # noqa: E402

#: geom group of the robot's own parts; rays of this module never hit it
ROBOT_GROUP = 3
#: contact bits of the robot's geoms: they touch the world but not each other (an arm
#: folding over its own chassis, a mast it swings past)
ROBOT_CONTACT = 'contype="2" conaffinity="1"'
#: geom groups a ray sees (MuJoCo has six): all but the robot's
SEEN_GROUPS = np.array([1 if g != ROBOT_GROUP else 0 for g in range(6)], dtype=np.uint8)

Wall = tuple[tuple[float, float], tuple[float, float]]


def wrap(angle: float) -> float:
    """An angle in (-pi, pi]."""
    return math.atan2(math.sin(angle), math.cos(angle))


@dataclass(frozen=True)
class BaseSpec:
    """Dimensions and limits of a differential-drive base (metres, kilograms, seconds).

    The defaults are a field robot of about the garbage collector's size, driving at
    the 2D field's 0.35 m/s and turning at 45 degrees a second.
    """

    name: str = "base"
    length: float = 0.6
    width: float = 0.4
    height: float = 0.18
    clearance: float = 0.06  # chassis bottom over the ground
    mass: float = 20.0
    wheel_radius: float = 0.1
    wheel_width: float = 0.05
    track: float = 0.46  # distance between the wheels' contact lines
    caster_radius: float = 0.04
    max_speed: float = 0.35
    max_turn_rate: float = math.radians(45.0)
    wheel_gain: float = 20.0  # velocity servo gain (N m per rad/s)
    wheel_torque: float = 12.0  # servo torque limit (N m)
    wheel_friction: float = 1.2
    lidar_at: tuple[float, float, float] = (0.2, 0.0, 0.32)  # on the chassis
    rgba: tuple[float, float, float, float] = (0.25, 0.3, 0.35, 1.0)

    def joint(self, side: str) -> str:
        """Name of the left or right wheel's hinge (``side`` is ``left`` or ``right``)."""
        return f"{self.name}_{side}_wheel"

    @property
    def imu_site(self) -> str:
        return f"{self.name}_imu"

    @property
    def lidar_site(self) -> str:
        return f"{self.name}_lidar"

    @property
    def gyro(self) -> str:
        return f"{self.name}_gyro"

    @property
    def accelerometer(self) -> str:
        return f"{self.name}_accel"


@dataclass(frozen=True)
class BaseFragment:
    """MJCF text of one base: ``body`` goes into ``<worldbody>``, ``actuator`` into
    ``<actuator>``, ``sensor`` into ``<sensor>``."""

    body: str
    actuator: str
    sensor: str


def _f(*values: float) -> str:
    return " ".join(f"{v:.6g}" for v in values)


def yaw_quat(yaw: float) -> str:
    """MJCF ``quat`` of a rotation by ``yaw`` radians about z (whatever the model's
    ``compiler angle`` setting, which ``euler`` depends on)."""
    return _f(math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))


def base_fragment(
    spec: BaseSpec,
    pos: tuple[float, float] = (0.0, 0.0),
    yaw: float = 0.0,
    children: str = "",
) -> BaseFragment:
    """The MJCF of a base standing at ``pos`` facing ``yaw`` (radians, from world x).

    ``children`` is MJCF placed inside the chassis body (its frame: x forward, y left,
    z up from the ground under the base's centre), for an arm, a camera or a bumper.
    Give the geoms of such parts ``group="3"`` (:data:`ROBOT_GROUP`) so the base's own
    rays pass through them, and :data:`ROBOT_CONTACT` so they do not collide with the
    base. The wheel hinges carry encoders (``jointpos`` sensors named
    after the joints), the IMU site a gyro and an accelerometer.
    """
    s = spec
    n = s.name
    r = s.wheel_radius
    chassis_z = s.clearance + s.height / 2
    half = (s.length / 2, s.width / 2, s.height / 2)
    caster_x = s.length / 2 - s.caster_radius - 0.02
    # the casters ride a little higher than the wheels, so the wheels bear the weight
    # (and grip) and the chassis tips onto one caster
    caster_z = s.caster_radius + 0.004
    wheel_mass = 1.0
    wheels = []
    for side, sign in (("left", 1.0), ("right", -1.0)):
        wheels.append(
            f'<body name="{n}_{side}_wheel_link" pos="{_f(0.0, sign * s.track / 2, r)}">'
            f'<joint name="{s.joint(side)}" type="hinge" axis="0 1 0" damping="0.05"/>'
            f'<geom type="cylinder" size="{_f(r, s.wheel_width / 2)}" quat="0.7071068 0.7071068 0 0"'
            f' mass="{wheel_mass}" friction="{_f(s.wheel_friction, 0.005, 0.0001)}"'
            f' group="{ROBOT_GROUP}" {ROBOT_CONTACT} rgba="0.1 0.1 0.1 1"/>'
            "</body>"
        )
    body = (
        f'<body name="{n}" pos="{_f(pos[0], pos[1], 0.0)}" quat="{yaw_quat(yaw)}">'
        f'<freejoint name="{n}_free"/>'
        f'<geom name="{n}_chassis" type="box" size="{_f(*half)}" pos="{_f(0, 0, chassis_z)}"'
        f' mass="{s.mass}" group="{ROBOT_GROUP}" {ROBOT_CONTACT} rgba="{_f(*s.rgba)}"/>'
        f'<geom name="{n}_caster_front" type="sphere" size="{s.caster_radius:.6g}"'
        f' pos="{_f(caster_x, 0, caster_z)}" condim="1" mass="0.2" group="{ROBOT_GROUP}" {ROBOT_CONTACT}'
        ' rgba="0.2 0.2 0.2 1"/>'
        f'<geom name="{n}_caster_back" type="sphere" size="{s.caster_radius:.6g}"'
        f' pos="{_f(-caster_x, 0, caster_z)}" condim="1" mass="0.2" group="{ROBOT_GROUP}" {ROBOT_CONTACT}'
        ' rgba="0.2 0.2 0.2 1"/>'
        f'<geom name="{n}_lidar_head" type="cylinder" size="0.04 0.025"'
        f' pos="{_f(*s.lidar_at)}" mass="0.3" group="{ROBOT_GROUP}" {ROBOT_CONTACT} rgba="0.05 0.05 0.05 1"/>'
        f'<site name="{s.imu_site}" pos="{_f(0, 0, chassis_z)}"/>'
        f'<site name="{s.lidar_site}" pos="{_f(s.lidar_at[0], s.lidar_at[1], s.lidar_at[2] + 0.03)}"/>'
        + "".join(wheels)
        + children
        + "</body>"
    )
    limit = (s.max_speed + s.max_turn_rate * s.track / 2) / r * 1.5
    actuator = "".join(
        f'<velocity name="{s.joint(side)}" joint="{s.joint(side)}" kv="{s.wheel_gain:.6g}"'
        f' ctrlrange="{_f(-limit, limit)}" forcerange="{_f(-s.wheel_torque, s.wheel_torque)}"/>'
        for side in ("left", "right")
    )
    sensor = (
        f'<jointpos name="{s.joint("left")}" joint="{s.joint("left")}"/>'
        f'<jointpos name="{s.joint("right")}" joint="{s.joint("right")}"/>'
        f'<gyro name="{s.gyro}" site="{s.imu_site}"/>'
        f'<accelerometer name="{s.accelerometer}" site="{s.imu_site}"/>'
    )
    return BaseFragment(body, actuator, sensor)


def walls_xml(
    walls: Sequence[Wall], height: float = 1.0, thickness: float = 0.05, rgba: str = "0.5 0.5 0.5 1"
) -> str:
    """Box geoms standing on the given segments (a fence, a room's walls).

    Give the segments counter-clockwise around the free space (the space on each
    segment's left): each box stands on the outer side, so the segment is the wall's
    face, which is what a ray hits and what :class:`Localiser` matches scans against.
    """
    out = []
    for (x1, y1), (x2, y2) in walls:
        length = math.hypot(x2 - x1, y2 - y1)
        angle = math.atan2(y2 - y1, x2 - x1)
        # outward normal: to the right of the direction of travel
        nx, ny = math.sin(angle), -math.cos(angle)
        cx = (x1 + x2) / 2 + nx * thickness / 2
        cy = (y1 + y2) / 2 + ny * thickness / 2
        out.append(
            f'<geom type="box" size="{_f(length / 2 + thickness, thickness / 2, height / 2)}"'
            f' pos="{_f(cx, cy, height / 2)}" quat="{yaw_quat(angle)}" rgba="{rgba}"/>'
        )
    return "".join(out)


class DiffDrive:
    """The wheels' velocity servos of one base: ``drive(v, w)`` sets them for a forward
    speed ``v`` (m/s) and a turn rate ``w`` (rad/s, positive to the left), clipped to the
    spec's limits."""

    def __init__(self, model: mujoco.MjModel, spec: BaseSpec) -> None:
        self.spec = spec
        self.left = model.actuator(spec.joint("left")).id
        self.right = model.actuator(spec.joint("right")).id

    def drive(self, data: mujoco.MjData, v: float, w: float) -> tuple[float, float]:
        """Set the wheel speeds; returns the (clipped) ``(v, w)`` commanded."""
        s = self.spec
        v = max(-s.max_speed, min(s.max_speed, v))
        w = max(-s.max_turn_rate, min(s.max_turn_rate, w))
        data.ctrl[self.left] = (v - w * s.track / 2) / s.wheel_radius
        data.ctrl[self.right] = (v + w * s.track / 2) / s.wheel_radius
        return v, w

    def stop(self, data: mujoco.MjData) -> None:
        """Hold the wheels still."""
        self.drive(data, 0.0, 0.0)


def steer(
    pose: tuple[float, float, float],
    target: tuple[float, float],
    spec: BaseSpec,
    tolerance: float = 0.05,
    turn_first: float = math.radians(20.0),
) -> tuple[float, float, bool]:
    """A go-to-point law on an estimated pose: ``(v, w, arrived)``.

    Turns on the spot while the target is more than ``turn_first`` off the heading,
    then drives with a proportional correction of the heading, slowing on arrival.
    """
    x, y, theta = pose
    dx, dy = target[0] - x, target[1] - y
    distance = math.hypot(dx, dy)
    if distance <= tolerance:
        return 0.0, 0.0, True
    error = wrap(math.atan2(dy, dx) - theta)
    w = max(-spec.max_turn_rate, min(spec.max_turn_rate, 2.5 * error))
    if abs(error) > turn_first:
        return 0.0, w, False
    v = min(spec.max_speed, 1.2 * distance + 0.03) * math.cos(error)
    return v, w, False


def turn_law(theta: float, heading: float, spec: BaseSpec, tolerance: float = 0.02) -> float:
    """Turn rate that brings ``theta`` to ``heading`` (0 once within ``tolerance``)."""
    error = wrap(heading - theta)
    if abs(error) <= tolerance:
        return 0.0
    w = 2.5 * error
    w = math.copysign(max(abs(w), 0.1), w)
    return max(-spec.max_turn_rate, min(spec.max_turn_rate, w))


def cast_rays(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    origin: np.ndarray,
    directions: np.ndarray,
    range_max: float,
    exclude_body: int = -1,
    groups: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Distances along unit ``directions`` (N x 3) from ``origin`` to the first geom hit.

    Returns ``(distances, geom_ids)``; a ray that hits nothing within ``range_max``
    reads ``inf`` with geom id -1. The robot's own geoms (group :data:`ROBOT_GROUP`) and
    ``exclude_body`` are never hit. Needs the current ``mj_forward``/``mj_step`` state.
    """
    directions = np.ascontiguousarray(directions, dtype=np.float64)
    count = len(directions)
    dist = np.empty(count, dtype=np.float64)
    geom = np.empty(count, dtype=np.int32)
    mujoco.mj_multiRay(
        model,
        data,
        np.asarray(origin, dtype=np.float64),
        directions.reshape(-1),
        SEEN_GROUPS if groups is None else groups,
        1,
        exclude_body,
        geom,
        dist,
        None,
        count,
        range_max,
    )
    miss = (geom < 0) | (dist < 0) | (dist > range_max)
    dist[miss] = np.inf
    geom[miss] = -1
    return dist, geom


@dataclass(frozen=True)
class LidarSpec:
    """A planar scanning lidar: ``rays`` evenly over ``fov`` (centred ahead), read up to
    ``range_max`` metres, each range off by Gaussian ``noise`` (metres)."""

    rays: int = 360
    range_max: float = 8.0
    range_min: float = 0.05
    fov: float = 2.0 * math.pi
    noise: float = 0.01
    rate: float = 10.0  # scans a second


@dataclass(frozen=True)
class Scan:
    """One lidar scan: ``angles`` (radians from the sensor's forward axis, positive to
    the left) and ``ranges`` (metres; ``inf`` where nothing was within range)."""

    angles: np.ndarray
    ranges: np.ndarray
    range_max: float
    stamp: float = 0.0

    def sector_min(self, low: float, high: float) -> float:
        """The nearest range between two angles (``inf`` if none)."""
        mask = (self.angles >= low) & (self.angles <= high)
        return float(np.min(self.ranges[mask])) if mask.any() else math.inf

    def points(self, offset: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
        """The hits as (x, y) in the base's frame, the sensor at ``offset``."""
        ok = np.isfinite(self.ranges)
        r, a = self.ranges[ok], self.angles[ok]
        return np.column_stack((offset[0] + r * np.cos(a), offset[1] + r * np.sin(a)))


class Lidar:
    """A planar lidar at a site of the model, scanning by ray casting."""

    def __init__(
        self,
        model: mujoco.MjModel,
        site: str,
        spec: LidarSpec | None = None,
        rng: random.Random | None = None,
    ) -> None:
        self.model = model
        self.spec = spec or LidarSpec()
        self.site = model.site(site).id
        self.body = int(model.site_bodyid[self.site])
        self.rng = np.random.default_rng((rng or random.Random(0)).getrandbits(32))
        n = self.spec.rays
        if self.spec.fov >= 2 * math.pi - 1e-9:
            self.angles = -math.pi + 2 * math.pi * np.arange(n) / n
        else:
            self.angles = np.linspace(-self.spec.fov / 2, self.spec.fov / 2, n)
        self._local = np.column_stack((np.cos(self.angles), np.sin(self.angles), np.zeros(n)))

    def scan(self, data: mujoco.MjData, stamp: float = 0.0) -> Scan:
        """Cast every ray from the site, in the site's horizontal plane."""
        xmat = data.site_xmat[self.site].reshape(3, 3)
        directions = self._local @ xmat.T
        dist, _geom = cast_rays(
            self.model, data, data.site_xpos[self.site], directions, self.spec.range_max, self.body
        )
        if self.spec.noise > 0:
            dist = dist + self.rng.normal(0.0, self.spec.noise, len(dist))
        dist[dist < self.spec.range_min] = np.inf
        dist[dist > self.spec.range_max] = np.inf
        return Scan(self.angles, dist, self.spec.range_max, stamp)


class RangeCone:
    """An ultrasonic or infrared ranger: the nearest hit within a cone of ``half_angle``
    around a site's x axis, sampled by ``rays`` rays (a centre ray and rings around it),
    up to ``range_max``; ``inf`` when nothing is in range. Hits lower than ``floor``
    (metres above ``z = 0``) are the ground's echo and ignored, as a ranger's driver
    would filter them.
    """

    def __init__(
        self,
        model: mujoco.MjModel,
        site: str,
        half_angle: float = math.radians(15.0),
        range_max: float = 2.0,
        rays: int = 13,
        noise: float = 0.0,
        rng: random.Random | None = None,
        floor: float = 0.01,
    ) -> None:
        self.model = model
        self.floor = floor
        self.site = model.site(site).id
        self.body = int(model.site_bodyid[self.site])
        self.range_max = range_max
        self.noise = noise
        self.rng = rng or random.Random(0)
        directions = [(1.0, 0.0, 0.0)]
        rings = max(1, (rays - 1) // 6)
        per_ring = max(1, (rays - 1) // rings)
        for ring in range(1, rings + 1):
            tilt = half_angle * ring / rings
            for k in range(per_ring):
                phi = 2 * math.pi * k / per_ring
                directions.append(
                    (
                        math.cos(tilt),
                        math.sin(tilt) * math.cos(phi),
                        math.sin(tilt) * math.sin(phi),
                    )
                )
        self._local = np.array(directions)

    def read(self, data: mujoco.MjData) -> float:
        """The nearest distance in the cone (``inf`` if nothing within range)."""
        xmat = data.site_xmat[self.site].reshape(3, 3)
        directions = self._local @ xmat.T
        origin = data.site_xpos[self.site]
        dist, _ = cast_rays(self.model, data, origin, directions, self.range_max, self.body)
        with np.errstate(invalid="ignore"):
            dist[origin[2] + dist * directions[:, 2] < self.floor] = np.inf
        nearest = float(np.min(dist))
        if math.isfinite(nearest) and self.noise > 0:
            nearest = max(0.0, nearest + self.rng.gauss(0.0, self.noise))
        return nearest


class WheelOdometry:
    """Dead reckoning from the wheel encoders and the IMU's yaw rate.

    Each encoder increment is scaled by ``1 + N(0, slip)`` (wheels slip and skid on
    grass); the heading integrates the gyro, which carries a constant ``gyro_bias``
    (rad/s) and white noise. The distance is the wheels' mean travel. The pose is in
    the frame the odometry started in (its start pose given).
    """

    def __init__(
        self,
        spec: BaseSpec,
        start: tuple[float, float, float] = (0.0, 0.0, 0.0),
        slip: float = 0.03,
        gyro_bias: float = 0.002,
        gyro_noise: float = 0.005,
        rng: random.Random | None = None,
    ) -> None:
        self.spec = spec
        self.x, self.y, self.theta = start
        self.slip = slip
        self.gyro_bias = gyro_bias
        self.gyro_noise = gyro_noise
        self.rng = rng or random.Random(0)
        self._wheels: tuple[float, float] | None = None
        self.travelled = 0.0

    @property
    def pose(self) -> tuple[float, float, float]:
        return self.x, self.y, self.theta

    def update(self, left: float, right: float, yaw_rate: float, dt: float) -> None:
        """Take the encoders' angles (radians) and the gyro's yaw rate over ``dt``."""
        if self._wheels is None:
            self._wheels = (left, right)
            return
        dl = (left - self._wheels[0]) * self.spec.wheel_radius
        dr = (right - self._wheels[1]) * self.spec.wheel_radius
        self._wheels = (left, right)
        if self.slip > 0:
            dl *= 1.0 + self.rng.gauss(0.0, self.slip)
            dr *= 1.0 + self.rng.gauss(0.0, self.slip)
        distance = (dl + dr) / 2
        dtheta = (yaw_rate + self.gyro_bias + self.rng.gauss(0.0, self.gyro_noise)) * dt
        mid = self.theta + dtheta / 2
        self.x += distance * math.cos(mid)
        self.y += distance * math.sin(mid)
        self.theta = wrap(self.theta + dtheta)
        self.travelled += abs(distance)


def _segments(walls: Sequence[Wall]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    a = np.array([w[0] for w in walls], dtype=float)
    b = np.array([w[1] for w in walls], dtype=float)
    d = b - a
    length = np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-9)
    return a, d, length, np.column_stack((-d[:, 1], d[:, 0])) / length[:, None]


@dataclass
class Localiser:
    """A pose estimate: the odometry's motion, corrected by the lidar against known walls.

    ``predict`` applies the odometry's increment (taken in the odometry's own frame and
    carried over in the body frame, so a corrected estimate stays corrected).
    ``correct`` matches a scan's points to the nearest wall (within ``gate`` metres),
    and solves a few damped point-to-line least squares steps for ``(x, y, theta)``;
    a scan that sees fewer than ``min_points`` wall points leaves the estimate alone
    (a robot far from every wall, as on a large field with a short-range lidar, runs on
    odometry until it nears one). ``damping`` keeps a single wall (which fixes only the
    distance to it and the heading) from moving the estimate along the wall.
    """

    walls: Sequence[Wall]
    pose: tuple[float, float, float] = (0.0, 0.0, 0.0)
    gate: float = 0.35
    min_points: int = 15
    damping: float = 5.0
    iterations: int = 4
    corrections: int = 0
    last_inliers: int = 0
    _odom: tuple[float, float, float] | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        self._a, self._d, self._len, self._n = _segments(self.walls)

    def reset(self, pose: tuple[float, float, float]) -> None:
        """Set the estimate (a known start, an operator's placement); the next odometry
        reading becomes the reference its motion is counted from."""
        self.pose = pose
        self._odom = None

    def predict(self, odometry: tuple[float, float, float]) -> None:
        """Move by the odometry's change since the last call."""
        if self._odom is None:
            self._odom = odometry
            return
        ox, oy, ot = self._odom
        dx, dy = odometry[0] - ox, odometry[1] - oy
        forward = dx * math.cos(ot) + dy * math.sin(ot)
        lateral = -dx * math.sin(ot) + dy * math.cos(ot)
        dtheta = wrap(odometry[2] - ot)
        x, y, t = self.pose
        self.pose = (
            x + forward * math.cos(t) - lateral * math.sin(t),
            y + forward * math.sin(t) + lateral * math.cos(t),
            wrap(t + dtheta),
        )
        self._odom = odometry

    def _match(self, world: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Per point: the signed distance to and normal of its nearest wall."""
        rel = world[:, None, :] - self._a[None, :, :]
        t = np.clip((rel * self._d[None]).sum(-1) / self._len[None] ** 2, 0.0, 1.0)
        closest = self._a[None] + t[..., None] * self._d[None]
        gap = np.hypot(*(world[:, None, :] - closest).transpose(2, 0, 1))
        nearest = np.argmin(gap, axis=1)
        normal = self._n[nearest]
        signed = ((world - self._a[nearest]) * normal).sum(-1)
        return signed, normal

    def correct(self, points: np.ndarray) -> bool:
        """Correct the pose from scan ``points`` (N x 2, the base's frame); True if it did."""
        if len(points) < self.min_points or not len(self.walls):
            self.last_inliers = 0
            return False
        x, y, t = self.pose
        inliers = 0
        for _ in range(self.iterations):
            c, s = math.cos(t), math.sin(t)
            world = np.column_stack(
                (x + c * points[:, 0] - s * points[:, 1], y + s * points[:, 0] + c * points[:, 1])
            )
            residual, normal = self._match(world)
            keep = np.abs(residual) < self.gate
            inliers = int(keep.sum())
            if inliers < self.min_points:
                self.last_inliers = inliers
                return False
            r, n, p = residual[keep], normal[keep], points[keep]
            dtheta_x = -s * p[:, 0] - c * p[:, 1]
            dtheta_y = c * p[:, 0] - s * p[:, 1]
            jac = np.column_stack((n[:, 0], n[:, 1], n[:, 0] * dtheta_x + n[:, 1] * dtheta_y))
            lhs = jac.T @ jac + self.damping * np.eye(3)
            step = np.linalg.solve(lhs, -jac.T @ r)
            x, y, t = x + step[0], y + step[1], wrap(t + step[2])
            if np.abs(step).max() < 1e-4:
                break
        self.pose = (float(x), float(y), float(t))
        self.corrections += 1
        self.last_inliers = inliers
        return True


class MobileBase:
    """One base in a compiled model: drive, encoders, IMU, lidar, odometry and estimate.

    Call :meth:`sense` after every physics step (or every few, with the time they took)
    to run the odometry, and :meth:`scan` at the lidar's rate, which also corrects the
    estimate against ``walls``. :attr:`estimate` is what a world may report as the
    robot's pose; :meth:`true_pose` reads the simulator and is for reports and tests.
    """

    def __init__(
        self,
        model: mujoco.MjModel,
        data: mujoco.MjData,
        spec: BaseSpec,
        start: tuple[float, float, float],
        walls: Sequence[Wall] = (),
        lidar: LidarSpec | None = None,
        slip: float = 0.03,
        seed: int = 0,
    ) -> None:
        self.model = model
        self.data = data
        self.spec = spec
        rng = random.Random(seed)
        self.drive_ = DiffDrive(model, spec)
        self.lidar = Lidar(model, spec.lidar_site, lidar, rng)
        self.odometry = WheelOdometry(spec, start, slip=slip, rng=rng)
        self.localiser = Localiser(walls, pose=start)
        self.body = model.body(spec.name).id
        self._left = model.sensor(spec.joint("left")).adr[0]
        self._right = model.sensor(spec.joint("right")).adr[0]
        self._gyro = model.sensor(spec.gyro).adr[0]
        self._accel = model.sensor(spec.accelerometer).adr[0]
        self.last_scan: Scan | None = None
        self.sense(0.0)

    def drive(self, v: float, w: float) -> tuple[float, float]:
        """Command a forward speed and turn rate (clipped to the spec's limits)."""
        return self.drive_.drive(self.data, v, w)

    def stop(self) -> None:
        self.drive_.stop(self.data)

    def encoders(self) -> tuple[float, float]:
        """The wheel angles (radians): left, right."""
        return float(self.data.sensordata[self._left]), float(self.data.sensordata[self._right])

    def imu(self) -> tuple[np.ndarray, np.ndarray]:
        """The gyro's angular velocity and the accelerometer's reading (the IMU's frame)."""
        gyro = self.data.sensordata[self._gyro : self._gyro + 3].copy()
        accel = self.data.sensordata[self._accel : self._accel + 3].copy()
        return gyro, accel

    def sense(self, dt: float) -> None:
        """Read the encoders and gyro over the last ``dt`` seconds into the odometry."""
        left, right = self.encoders()
        yaw_rate = float(self.data.sensordata[self._gyro + 2])
        self.odometry.update(left, right, yaw_rate, dt)
        self.localiser.predict(self.odometry.pose)

    def scan(self, stamp: float = 0.0, correct: bool = True) -> Scan:
        """A lidar scan; with ``correct`` the estimate is matched to the walls."""
        scan = self.lidar.scan(self.data, stamp)
        self.last_scan = scan
        if correct:
            offset = (self.spec.lidar_at[0], self.spec.lidar_at[1])
            self.localiser.correct(scan.points(offset))
        return scan

    @property
    def estimate(self) -> tuple[float, float, float]:
        """The pose estimate ``(x, y, theta)``: odometry and IMU, corrected by the lidar."""
        return self.localiser.pose

    def true_pose(self) -> tuple[float, float, float]:
        """The simulator's pose of the base (ground truth; never a percept)."""
        x, y = self.data.xpos[self.body][:2]
        xmat = self.data.xmat[self.body].reshape(3, 3)
        return float(x), float(y), math.atan2(xmat[1, 0], xmat[0, 0])
