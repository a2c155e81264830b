"""The garbage field of Hammer et al. as MJCF: grass, fence, checkpoints, trash and robot.

The field is the 2D field's (:mod:`robocog.worlds.garbage`, docs/garbage.md): a fenced
square of grass, ``size`` metres a side, eight checkpoints on a circle (flat markers
that nothing collides with), and the round's bottles and cups as free bodies, each
upright, leaning against a stone, or lying on its side. The robot is the shared
differential base (:mod:`robocog.worlds.physics.mobile_base`) carrying a camera on a
mast, a lidar, a tray behind, and a three-joint arm in front whose parallel gripper
closes two sliding fingers (position servos with a force limit, so an object is held by
the friction of the pads).

The lights are the day's: a sun (a directional light with shadows) whose height,
colour and strength change with :data:`LIGHTING`, and the sky's light, which reaches a
surface by how much of the sky it faces (see :func:`sky_light`). The same model is
relit by :func:`set_light`, so one scene can be seen under every light.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, replace

import mujoco
import numpy as np

from robocog.worlds.physics.mobile_base import (
    ROBOT_CONTACT,
    ROBOT_GROUP,
    BaseSpec,
    base_fragment,
    yaw_quat,
)

#: bottle: body radius, body height, neck radius, neck height (metres)
BOTTLE = (0.034, 0.17, 0.014, 0.06)
#: cup: radius, height
CUP = (0.04, 0.10)
OBJECT_MASS = {"bottle": 0.06, "cup": 0.04}

#: the arm in the base's frame (x forward, z up): shoulder, link lengths
SHOULDER = (0.2, 0.0, 0.27)
UPPER = 0.32
FORE = 0.30
PALM_TO_GRASP = 0.07  # from the wrist axis to the point between the finger pads
FINGER_OPEN = 0.065  # each finger's travel from the middle
FINGER_CLOSED = 0.0
#: camera on a mast: position in the base's frame and downward pitch (radians)
CAMERA_AT = (-0.05, -0.17, 0.85)
CAMERA_PITCH = math.radians(22.0)
CAMERA_FOVY = 2 * math.degrees(math.atan(math.tan(math.radians(30.0)) * 480 / 640))
TRAY = (-0.2, 0.0, 0.24)  # centre of the tray's floor
#: the grass's two colours (its reflectance per channel: the light it sends back up)
GRASS = ((0.27, 0.46, 0.18), (0.31, 0.5, 0.2))


@dataclass(frozen=True)
class Lighting:
    """A time of day: the sun's elevation and azimuth (degrees), its colour and strength,
    the sky's ambient light, and whether the sun casts shadows."""

    elevation: float
    azimuth: float
    colour: tuple[float, float, float]
    strength: float
    ambient: float
    sky: tuple[float, float, float]
    shadows: bool = True
    #: the air's haze: from ``haze[0]`` metres objects fade into the sky's colour,
    #: wholly at ``haze[1]`` (a clear day's is far beyond the camera's range)
    haze: tuple[float, float] = (200.0, 1000.0)
    #: the sky's light on an upright surface over its light on the ground (the sky's
    #: part only): 0.5 for a sky of even brightness, as a clear sky away from the sun
    #: roughly is; 0.396 for the CIE standard overcast sky (Moon and Spencer's), three
    #: times brighter at the zenith than at the horizon, whose light comes mostly from
    #: overhead
    sky_vertical: float = 0.5


#: the three lights of the paper's test days: a high bright sun; an overcast sky (no
#: sun, flat bluish light); a low warm sun whose long shadows fall across the field
LIGHTING: dict[str, Lighting] = {
    "sunny": Lighting(58.0, 200.0, (1.0, 0.98, 0.92), 0.75, 0.35, (0.95, 0.97, 1.0)),
    "cloudy": Lighting(
        70.0, 180.0, (0.85, 0.88, 0.95), 0.08, 0.17, (0.8, 0.83, 0.9), False, (1.0, 14.0), 0.396
    ),
    "evening": Lighting(
        9.0, 250.0, (1.0, 0.55, 0.28), 0.75, 0.175, (0.55, 0.45, 0.45), True, (4.0, 40.0)
    ),
}


@dataclass(frozen=True)
class Placed:
    """One object as the scene places it: kind, position, yaw and pose."""

    name: str
    label: str
    x: float
    y: float
    yaw: float
    pose: str  # "upright", "leaning" or "lying"


def fence(size: float) -> tuple[tuple[tuple[float, float], tuple[float, float]], ...]:
    """The fence's four segments (the localiser's map)."""
    s = size
    return (((0, 0), (s, 0)), ((s, 0), (s, s)), ((s, s), (0, s)), ((0, s), (0, 0)))


def _f(*v: float) -> str:
    return " ".join(f"{x:.5g}" for x in v)


def _quat(axis: tuple[float, float, float], angle: float) -> tuple[float, float, float, float]:
    s = math.sin(angle / 2)
    return (math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s)


def _qmul(a: tuple[float, ...], b: tuple[float, ...]) -> tuple[float, float, float, float]:
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    )


def _object_geoms(p: Placed) -> str:
    rgba_b = "0.72 0.86 0.9 1"
    band = "0.85 0.18 0.15 1"
    if p.label == "bottle":
        r, h, nr, nh = BOTTLE
        return (
            f'<geom type="cylinder" size="{_f(r, h / 2)}" pos="0 0 {h / 2:.5g}" rgba="{rgba_b}"'
            ' friction="0.9 0.005 0.0001" condim="4"/>'
            f'<geom type="cylinder" size="{_f(r + 0.0008, 0.03)}" pos="0 0 {h * 0.55:.5g}"'
            f' rgba="{band}" contype="0" conaffinity="0" mass="0"/>'
            f'<geom type="cylinder" size="{_f(nr, nh / 2)}" pos="0 0 {h + nh / 2:.5g}"'
            f' rgba="{rgba_b}" mass="0.005"/>'
            f'<geom type="cylinder" size="{_f(nr + 0.002, 0.008)}" pos="0 0 {h + nh:.5g}"'
            ' rgba="0.1 0.3 0.8 1" mass="0.002"/>'
        )
    r, h = CUP
    return (
        f'<geom type="cylinder" size="{_f(r, h / 2)}" pos="0 0 {h / 2:.5g}"'
        ' rgba="0.96 0.95 0.9 1" friction="0.9 0.005 0.0001" condim="4"/>'
        f'<geom type="cylinder" size="{_f(r + 0.0008, 0.012)}" pos="0 0 {h - 0.012:.5g}"'
        ' rgba="0.55 0.35 0.2 1" contype="0" conaffinity="0" mass="0"/>'
    )


def object_height(label: str) -> float:
    """Standing height of a bottle or cup."""
    return BOTTLE[1] + BOTTLE[3] if label == "bottle" else CUP[1]


def object_radius(label: str) -> float:
    """Body radius of a bottle or cup."""
    return BOTTLE[0] if label == "bottle" else CUP[0]


def _object_body(p: Placed) -> tuple[str, str]:
    """The object's body and, for a leaning one, the stone it leans on."""
    yaw = _quat((0, 0, 1), p.yaw)
    stone = ""
    r = object_radius(p.label)
    if p.pose == "upright":
        quat, z = yaw, 0.001
    elif p.pose == "lying":
        quat, z = _qmul(yaw, _quat((1, 0, 0), math.pi / 2)), r + 0.001
        # lying along the local y axis after the roll: centre the body on its spot
    else:  # leaning on a stone, tilted about 25 degrees towards +x of its yaw
        tilt = math.radians(25.0)
        quat, z = _qmul(yaw, _quat((0, 1, 0), tilt)), 0.002
        h = object_height(p.label)
        reach = 0.6 * h
        sx = p.x + math.cos(p.yaw) * (reach * math.sin(tilt) + r * math.cos(tilt) + 0.03)
        sy = p.y + math.sin(p.yaw) * (reach * math.sin(tilt) + r * math.cos(tilt) + 0.03)
        top = reach * math.cos(tilt) - r * math.sin(tilt) - 0.01
        stone = (
            f'<geom name="{p.name}_stone" type="box" size="{_f(0.035, 0.05, top / 2)}"'
            f' pos="{_f(sx, sy, top / 2)}" quat="{yaw_quat(p.yaw)}" rgba="0.45 0.42 0.38 1"/>'
        )
    body = (
        f'<body name="{p.name}" pos="{_f(p.x, p.y, z)}" quat="{_f(*quat)}">'
        f'<freejoint name="{p.name}"/>'
        f'<inertial pos="0 0 {object_height(p.label) * 0.4:.4g}" mass="{OBJECT_MASS[p.label]}"'
        f' diaginertia="{_f(2e-4, 2e-4, 6e-5)}"/>' + _object_geoms(p) + "</body>"
    )
    return body, stone


def _arm(spec: BaseSpec) -> str:
    """The arm and gripper, in the base's frame; every geom in the robot's group."""
    g = f'group="{ROBOT_GROUP}" {ROBOT_CONTACT}'
    sx, sy, sz = SHOULDER
    finger = (
        '<body name="finger_{side}" pos="{x:.4g} 0 0" gravcomp="1">'
        '<joint name="finger_{side}" type="slide" axis="0 {sign} 0" range="-0.005 0.07"'
        ' damping="2"/>'
        '<geom type="box" size="0.04 0.006 0.03" pos="0.04 {off} 0" rgba="0.2 0.2 0.22 1"'
        ' friction="1.6 0.01 0.001" condim="4" mass="0.05" ' + g + "/>"
        "</body>"
    )
    fingers = "".join(
        finger.format(side=side, sign=sign, x=PALM_TO_GRASP - 0.04, off=f"{-sign * 0.0:.3g}")
        for side, sign in (("left", 1), ("right", -1))
    )
    return (
        f'<body name="arm_base" pos="{_f(sx, sy, sz - 0.03)}">'
        f'<geom type="cylinder" size="0.05 0.03" rgba="0.3 0.3 0.32 1" mass="0.5" {g}/>'
        f'<body name="upper_arm" pos="0 0 0.03" gravcomp="1">'
        '<joint name="shoulder" type="hinge" axis="0 1 0" range="-3.5 1.7" damping="3"'
        ' armature="0.05"/>'
        f'<geom type="capsule" fromto="0 0 0 {UPPER} 0 0" size="0.025" rgba="0.9 0.55 0.1 1"'
        f' mass="0.6" {g}/>'
        f'<body name="forearm" pos="{UPPER} 0 0" gravcomp="1">'
        '<joint name="elbow" type="hinge" axis="0 1 0" range="-0.2 2.9" damping="2"'
        ' armature="0.03"/>'
        f'<geom type="capsule" fromto="0 0 0 {FORE} 0 0" size="0.02" rgba="0.9 0.55 0.1 1"'
        f' mass="0.4" {g}/>'
        f'<body name="hand" pos="{FORE} 0 0" gravcomp="1">'
        '<joint name="wrist" type="hinge" axis="0 1 0" range="-3.3 3.3" damping="1"'
        ' armature="0.02"/>'
        f'<geom type="box" size="0.02 0.09 0.03" pos="0.02 0 0" rgba="0.25 0.25 0.28 1"'
        f' mass="0.2" {g}/>'
        f'<site name="grasp" pos="{PALM_TO_GRASP} 0 0"/>' + fingers + "</body></body></body></body>"
    )


def _robot_children(spec: BaseSpec) -> str:
    g = f'group="{ROBOT_GROUP}" {ROBOT_CONTACT}'
    cx, cy, cz = CAMERA_AT
    p = CAMERA_PITCH
    tx, ty, tz = TRAY
    tray_walls = "".join(
        f'<geom type="box" size="{_f(*size)}" pos="{_f(tx + dx, ty + dy, tz + 0.06)}"'
        f' rgba="0.35 0.35 0.3 1" mass="0.1" {g}/>'
        for size, dx, dy in (
            ((0.005, 0.17, 0.06), 0.12, 0.0),
            ((0.005, 0.17, 0.06), -0.12, 0.0),
            ((0.12, 0.005, 0.06), 0.0, 0.17),
            ((0.12, 0.005, 0.06), 0.0, -0.17),
        )
    )
    return (
        f'<geom type="cylinder" size="0.015 {cz / 2 - 0.12:.4g}" pos="{_f(cx, cy, cz / 2 + 0.12)}"'
        f' rgba="0.2 0.2 0.2 1" mass="0.3" {g}/>'
        f'<camera name="camera" pos="{_f(cx, cy, cz)}" fovy="{CAMERA_FOVY:.5g}"'
        f' xyaxes="0 -1 0 {_f(math.sin(p), 0, math.cos(p))}"/>'
        f'<geom type="box" size="0.12 0.17 0.005" pos="{_f(tx, ty, tz)}" rgba="0.35 0.35 0.3 1"'
        f' mass="0.3" {g}/>' + tray_walls + _arm(spec)
    )


def field_xml(
    size: float,
    checkpoints: dict[str, tuple[float, float]],
    objects: list[Placed],
    start: tuple[float, float, float],
    spec: BaseSpec | None = None,
    shadow_size: int = 1024,
) -> str:
    """The whole MJCF of one round's field."""
    spec = spec or BaseSpec(name="robot")
    base = base_fragment(spec, start[:2], start[2], children=_robot_children(spec))
    from robocog.worlds.physics.mobile_base import walls_xml

    fence_xml = walls_xml(fence(size), height=1.0, thickness=0.06, rgba="0.16 0.3 0.22 1")
    markers = "".join(
        f'<geom name="cp_{n}" type="cylinder" size="0.25 0.002" pos="{_f(x, y, 0.002)}"'
        ' rgba="0.85 0.85 0.3 1" contype="0" conaffinity="0" group="1"/>'
        for n, (x, y) in checkpoints.items()
    )
    bodies, stones = [], []
    for p in objects:
        b, s = _object_body(p)
        bodies.append(b)
        stones.append(s)
    gripper = "".join(
        f'<position name="finger_{side}" joint="finger_{side}" kp="60" ctrlrange="-0.005 0.07"'
        ' forcerange="-6 6"/>'
        for side in ("left", "right")
    )
    arm_act = "".join(
        f'<position name="{j}" joint="{j}" kp="{kp}" kv="{kv}" ctrlrange="-3.5 3.5"'
        f' forcerange="-{f} {f}"/>'
        for j, kp, kv, f in (
            ("shoulder", 120, 12, 60),
            ("elbow", 80, 8, 40),
            ("wrist", 30, 3, 15),
        )
    )
    joint_sensors = "".join(
        f'<jointpos name="{j}_pos" joint="{j}"/>'
        for j in ("shoulder", "elbow", "wrist", "finger_left", "finger_right")
    )
    mid = size / 2
    return f"""<mujoco model="garbage_field">
  <compiler angle="radian"/>
  <option timestep="0.005" integrator="implicitfast" cone="elliptic" impratio="4"/>
  <visual>
    <quality offsamples="0" shadowsize="{shadow_size}"/>
    <map znear="0.02" zfar="60" shadowclip="12"/>
    <headlight ambient="0.3 0.3 0.3" diffuse="0 0 0" specular="0 0 0"/>
    <global offwidth="640" offheight="480"/>
  </visual>
  <asset>
    <texture name="grass" type="2d" builtin="checker" rgb1="{_f(*GRASS[0])}" rgb2="{_f(*GRASS[1])}"
      width="256" height="256" mark="random" random="0.08" markrgb="0.4 0.55 0.25"/>
    <material name="grass" texture="grass" texrepeat="{size * 2:.4g} {size * 2:.4g}"
      specular="0" shininess="0" reflectance="0"/>
    <texture name="sky" type="skybox" builtin="gradient" rgb1="0.7 0.8 0.95" rgb2="0.95 0.95 1"
      width="64" height="64"/>
  </asset>
  <worldbody>
    <light name="sun" directional="true" castshadow="true" pos="{_f(mid, mid, 30)}"
      dir="0 0 -1" diffuse="0.8 0.8 0.8" specular="0.1 0.1 0.1"/>
    <light name="sky" directional="true" castshadow="false" pos="{_f(mid, mid, 30)}"
      dir="0 0 -1" diffuse="0 0 0" specular="0 0 0"/>
    <geom name="ground" type="plane" size="{_f(mid + 8, mid + 8, 0.1)}" pos="{_f(mid, mid, 0)}"
      material="grass" friction="1 0.005 0.0001"/>
    {fence_xml}
    {markers}
    {"".join(stones)}
    {"".join(bodies)}
    {base.body}
  </worldbody>
  <actuator>{base.actuator}{arm_act}{gripper}</actuator>
  <sensor>{base.sensor}{joint_sensors}</sensor>
</mujoco>"""


def set_light(model: mujoco.MjModel, light: str, jitter: random.Random | None = None) -> None:
    """Relight the scene as ``light`` (a key of :data:`LIGHTING`); with ``jitter`` the
    sun's height, bearing and strength vary a little (another hour of the same kind of
    day), as training frames need."""
    spec = LIGHTING[light]
    if jitter is not None:
        spec = replace(
            spec,
            elevation=max(3.0, spec.elevation + jitter.uniform(-4.0, 4.0)),
            azimuth=jitter.uniform(0.0, 360.0),
            strength=spec.strength * jitter.uniform(0.85, 1.15),
            ambient=spec.ambient * jitter.uniform(0.85, 1.15),
        )
    sun = model.light("sun").id
    el, az = math.radians(spec.elevation), math.radians(spec.azimuth)
    # the light shines from the sun towards the ground
    direction = -np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    model.light_dir[sun] = direction
    model.light_diffuse[sun] = np.array(spec.colour) * spec.strength
    model.light_specular[sun] = np.array(spec.colour) * 0.1 * spec.strength
    model.light_castshadow[sun] = 1 if spec.shadows else 0
    overhead, everywhere = sky_light(spec)
    model.light_diffuse[model.light("sky").id] = overhead
    model.vis.headlight.ambient[:] = everywhere
    # MuJoCo's fog distances are in units of the model's extent
    extent = float(model.stat.extent) or 1.0
    model.vis.map.fogstart = spec.haze[0] / extent
    model.vis.map.fogend = spec.haze[1] / extent
    model.vis.rgba.fog[:] = [*(np.array(spec.sky) * min(1.0, spec.ambient + spec.strength)), 1.0]


def sky_light(spec: Lighting) -> tuple[np.ndarray, np.ndarray]:
    """The sky's light as MuJoCo can draw it: (overhead, everywhere), RGB.

    ``spec.ambient`` is the sky's light on open ground. A surface receives the light of
    the part of the sky it faces: the ground all of it, an upright side (of a bottle, a
    cup) ``spec.sky_vertical`` of it, plus the light the grass throws back (half the
    ground's light times the grass's reflectance, so green). MuJoCo's ambient light
    falls on every surface alike, so the sky is drawn as that upright share plus the
    bounce (``everywhere``, the ambient) and the rest as a light from straight overhead
    without shadows (``overhead``), which a face receives by how much it faces up (the
    ground gets the bounce too, which an ambient light cannot keep off it). Lit by
    ambient alone, an overcast sky would light the sides of bottles and cups as
    brightly as the grass, and they would stand out brighter than on a sunny day.
    """
    sky = np.array(spec.sky) * spec.ambient
    sun_on_ground = (
        np.array(spec.colour) * spec.strength * max(0.0, math.sin(math.radians(spec.elevation)))
    )
    grass = np.mean(np.array(GRASS), axis=0)
    bounce = 0.5 * grass * (sky + sun_on_ground)
    everywhere = sky * spec.sky_vertical + bounce
    overhead = sky * (1.0 - spec.sky_vertical)
    return overhead, everywhere


def prepare_renderer(renderer: mujoco.Renderer) -> mujoco.Renderer:
    """Turn on the haze (fog) a light may bring, and shadows."""
    renderer.scene.flags[mujoco.mjtRndFlag.mjRND_FOG] = 1
    renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = 1
    return renderer


@dataclass(frozen=True)
class CameraModel:
    """The camera's sensor: auto-exposure and noise, as a small robot camera has them.

    The renderer gives the light that reaches each pixel. The sensor collects it as
    electrons (``full_well`` for a white pixel at unit gain) with shot noise (Poisson,
    here its Gaussian approximation) and ``read_noise``; auto-exposure raises the gain
    until the frame's mean brightness reaches ``target`` (up to ``max_gain``), so a dim
    scene comes out as bright as a sunny one but noisier, as on a real camera.
    """

    target: float = 110.0
    max_gain: float = 8.0
    full_well: float = 900.0
    read_noise: float = 6.0

    def expose(self, image: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """The frame the camera delivers for a rendered ``image`` (uint8 RGB)."""
        raw = image[..., :3].astype(np.float32)
        mean = float(raw.mean()) + 1e-3
        gain = min(self.max_gain, max(1.0, self.target / mean))
        electrons = raw * (self.full_well / 255.0)
        noisy = electrons + rng.standard_normal(raw.shape, dtype=np.float32) * np.sqrt(
            electrons + self.read_noise**2
        )
        out = noisy * gain * (255.0 / self.full_well)
        return np.clip(out, 0, 255).astype(np.uint8)
