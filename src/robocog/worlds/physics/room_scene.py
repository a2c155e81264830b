"""The room of Fujita et al. (Fig. 3) written as MJCF, with a Q.bo-like robot in it.

The plan is the 2D room's (:class:`~robocog.worlds.room.RoomConfig`): a 6 x 4 m room, a
0.9 m doorway in its north wall framed by two jambs that stand a little proud of the
wall, a door leaf hinged at the doorway's right jamb and opened inward, a corridor
beyond and, across it, the closed door of the opposite room. Both leaves are the same
wood with the same horizontal slit under the knob (the feature the paper's robot
recognised doors by), so a camera cannot tell one door from the other.

The robot is the Q.bo's size and shape on the shared wheeled base
(:mod:`~robocog.worlds.physics.mobile_base`: two driven wheels whose servos' torque is
limited, two casters, encoders and an IMU): a round body 0.36 m across that collides
with walls, door leaves and jambs, so a body pressed against a jamb stalls where it
touches; a head on a pan joint carrying the camera 0.42 m above the floor; two
ultrasonic sensors low on the front, angled outward. The room's solid geoms are in
group 0, decoration (slits, knobs) in group 1, the floors in group 2, the robot's own
parts in the base's robot group (3), which the rays and the camera pass over.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocog.worlds.physics.mobile_base import ROBOT_GROUP, BaseSpec, base_fragment

#: wall thickness and height, metres
WALL = 0.08
WALL_HEIGHT = 2.2
#: the door leaves: thickness, height, and the slit and knob on both faces
LEAF = 0.04
LEAF_HEIGHT = 2.0
SLIT_Z = 0.8
KNOB_Z = 0.95
#: the jambs: how far they stand proud of the wall on each side, and their width
JAMB_PROUD = 0.05
JAMB_WIDTH = 0.06
#: the robot: body radius, camera height, sonar height and lateral offset
BODY_RADIUS = 0.18
CAMERA_Z = 0.42
SONAR_Z = 0.08
SONAR_OFFSET = 0.1
#: the ultrasonic sensors' axes, turned outward from straight ahead (degrees)
SONAR_ANGLE = 10.0
#: camera: horizontal field of view (degrees) and the image's aspect (3 x 2 square areas)
CAMERA_HFOV = 54.0
ASPECT = 1.5

COLOURS = {
    "floor": (0.52, 0.52, 0.5),
    "wall": (0.86, 0.84, 0.78),
    "jamb": (0.95, 0.95, 0.95),
    "leaf": (0.55, 0.34, 0.17),
    "slit": (0.05, 0.04, 0.03),
    "knob": (0.8, 0.78, 0.7),
    "corridor_floor": (0.3, 0.34, 0.42),
    "corridor_wall": (0.62, 0.7, 0.78),
    "body": (0.92, 0.92, 0.95),
    "head": (0.2, 0.2, 0.22),
}


@dataclass(frozen=True)
class RoomPlan:
    """Dimensions of the room, the corridor and the doors (metres), as in the 2D room."""

    width: float = 6.0
    depth: float = 4.0
    doorway_x: float = 4.2
    doorway_width: float = 0.9
    corridor_depth: float = 1.6
    opposite_door_x: float = 5.0
    corridor_left: float = -1.0
    corridor_right: float = 7.0

    @property
    def top(self) -> float:
        """The y of the corridor's far wall, where the opposite door is."""
        return self.depth + self.corridor_depth

    def wall_segments(self) -> list[tuple[float, float, float, float]]:
        """The walls as segments on their centre lines (the opposite door's gap left out)."""
        w, h, top = self.width, self.depth, self.top
        d0, d1 = self.doorway_x, self.doorway_x + self.doorway_width
        o0, o1 = self.opposite_door_x, self.opposite_door_x + self.doorway_width
        left, right = self.corridor_left, self.corridor_right
        return [
            (0.0, 0.0, w, 0.0),
            (w, 0.0, w, h),
            (0.0, 0.0, 0.0, h),
            (left, h, d0, h),
            (d1, h, right, h),
            (left, h, left, top),
            (right, h, right, top),
            (left, top, o0, top),
            (o1, top, right, top),
        ]


def _rgba(name: str) -> str:
    r, g, b = COLOURS[name]
    return f"{r} {g} {b} 1"


def _box(
    name: str,
    a: tuple[float, float],
    b: tuple[float, float],
    thick: float,
    colour: str,
    height: float = WALL_HEIGHT,
) -> str:
    """A box geom standing on the floor along the segment a-b."""
    cx, cy = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    yaw = math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))
    return (
        f'<geom name="{name}" type="box" pos="{cx:.4f} {cy:.4f} {height / 2:.4f}" '
        f'euler="0 0 {yaw:.3f}" size="{length / 2 + thick / 2:.4f} {thick / 2:.4f} '
        f'{height / 2:.4f}" rgba="{_rgba(colour)}"/>'
    )


def _leaf_geoms(prefix: str, width: float, sides: tuple[float, ...]) -> str:
    """A leaf along its body's -x from the hinge, with a slit and a knob on each side."""
    parts = [
        f'<geom name="{prefix}_leaf" type="box" pos="{-width / 2:.4f} 0 {LEAF_HEIGHT / 2 + 0.01:.4f}" '
        f'size="{width / 2:.4f} {LEAF / 2:.4f} {LEAF_HEIGHT / 2:.4f}" rgba="{_rgba("leaf")}"/>'
    ]
    for i, side in enumerate(sides):
        y = side * (LEAF / 2 + 0.002)
        parts.append(
            f'<geom name="{prefix}_slit{i}" type="box" group="1" contype="0" conaffinity="0" '
            f'pos="{-0.55 * width:.4f} {y:.4f} {SLIT_Z}" size="0.2 0.003 0.02" '
            f'rgba="{_rgba("slit")}"/>'
        )
        parts.append(
            f'<geom name="{prefix}_knob{i}" type="sphere" group="1" contype="0" conaffinity="0" '
            f'pos="{-0.85 * width:.4f} {side * (LEAF / 2 + 0.03):.4f} {KNOB_Z}" size="0.03" '
            f'rgba="{_rgba("knob")}"/>'
        )
    return "\n      ".join(parts)


def camera_fovy(hfov_degrees: float = CAMERA_HFOV, aspect: float = ASPECT) -> float:
    """MuJoCo's vertical field of view (degrees) for a horizontal one and an aspect."""
    half = math.radians(hfov_degrees) / 2
    return math.degrees(2 * math.atan(math.tan(half) / aspect))


#: the Q.bo's base on the shared mobile base: small wheels, a narrow track, slow
QBO_BASE = BaseSpec(
    name="qbo",
    length=0.26,
    width=0.24,
    height=0.12,
    clearance=0.04,
    mass=6.0,
    wheel_radius=0.05,
    wheel_width=0.03,
    track=0.26,
    caster_radius=0.025,
    max_speed=0.2,
    max_turn_rate=math.radians(45.0),
    wheel_gain=2.0,
    wheel_torque=1.2,
    wheel_friction=1.2,
    lidar_at=(0.0, 0.0, 0.12),
    rgba=(0.3, 0.3, 0.32, 1.0),
)


def robot_children() -> str:
    """What rides on the base: the round body that collides, the ultrasonic sensors'
    sites (x axis along the beam), and the pan head with the camera. The robot's own
    geoms are in the base's robot group, so neither its rays nor its camera see them."""
    r = BODY_RADIUS
    g = ROBOT_GROUP
    return f"""
      <geom name="body" type="cylinder" pos="0 0 0.19" size="{r} 0.13" mass="1"
            group="{g}" rgba="{_rgba("body")}" friction="1.0 0.01 0.001"/>
      <site name="sonar_left" pos="{r} {SONAR_OFFSET} {SONAR_Z}" size="0.01"
            euler="0 0 {SONAR_ANGLE}"/>
      <site name="sonar_right" pos="{r} {-SONAR_OFFSET} {SONAR_Z}" size="0.01"
            euler="0 0 {-SONAR_ANGLE}"/>
      <body name="head" pos="0.02 0 0.33">
        <joint name="head_pan" type="hinge" axis="0 0 1" range="-100 100" damping="0.2"
               armature="0.01"/>
        <geom name="head" type="sphere" size="0.1" pos="0 0 0.08" mass="0.5" group="{g}"
              contype="0" conaffinity="0" rgba="{_rgba("head")}"/>
        <camera name="eye" pos="0.1 0 {CAMERA_Z - 0.33:.3f}" xyaxes="0 -1 0 0 0 1"
                fovy="{camera_fovy():.3f}"/>
      </body>"""


def scene_xml(plan: RoomPlan) -> str:
    """The MJCF of the room, the corridor, both doors and the robot (robot and door posed
    by their joints' qpos)."""
    walls = []
    for i, (ax, ay, bx, by) in enumerate(plan.wall_segments()):
        corridor = max(ay, by) > plan.depth
        colour = "corridor_wall" if corridor else "wall"
        walls.append(_box(f"wall{i}", (ax, ay), (bx, by), WALL, colour))
    d0, d1 = plan.doorway_x, plan.doorway_x + plan.doorway_width
    h = plan.depth
    jamb_half = (JAMB_WIDTH / 2, WALL / 2 + JAMB_PROUD, WALL_HEIGHT / 2)
    jambs = [
        f'<geom name="{name}" type="box" pos="{x:.4f} {h} {WALL_HEIGHT / 2}" '
        f'size="{jamb_half[0]} {jamb_half[1]} {jamb_half[2]}" rgba="{_rgba("jamb")}"/>'
        for name, x in (("jamb_left", d0 - JAMB_WIDTH / 2), ("jamb_right", d1 + JAMB_WIDTH / 2))
    ]
    width = plan.doorway_width - 0.03
    o0 = plan.opposite_door_x
    top = plan.top
    base = base_fragment(QBO_BASE, children=robot_children())
    corridor_cx = (plan.corridor_left + plan.corridor_right) / 2
    corridor_hx = (plan.corridor_right - plan.corridor_left) / 2
    return f"""<mujoco model="robocog_room">
  <compiler angle="degree" autolimits="true"/>
  <option timestep="0.005" integrator="implicitfast" gravity="0 0 -9.81"/>
  <visual>
    <global offwidth="640" offheight="480"/>
    <quality shadowsize="0"/>
    <headlight ambient="0.5 0.5 0.5" diffuse="0.35 0.35 0.35" specular="0 0 0"/>
  </visual>
  <default>
    <geom friction="0.9 0.01 0.001" solref="0.01 1"/>
  </default>
  <worldbody>
    <light pos="3 2 3" dir="0 0 -1" diffuse="0.35 0.35 0.35" castshadow="false"/>
    <light pos="3 4.8 2" dir="0 0 -1" diffuse="0.2 0.2 0.2" castshadow="false"/>
    <geom name="floor" type="box" group="2" friction="1.2 0.005 0.0001"
          pos="{plan.width / 2} {plan.depth / 2} -0.01" size="{plan.width / 2} {plan.depth / 2} 0.01"
          rgba="{_rgba("floor")}"/>
    <geom name="corridor_floor" type="box" group="2" friction="1.2 0.005 0.0001"
          pos="{corridor_cx} {(plan.depth + top) / 2} -0.01"
          size="{corridor_hx} {plan.corridor_depth / 2} 0.01" rgba="{_rgba("corridor_floor")}"/>
    {chr(10).join("    " + w for w in walls)}
    {chr(10).join("    " + j for j in jambs)}
    <body name="door" pos="{d1 - 0.01} {h} 0">
      <joint name="door_hinge" type="hinge" axis="0 0 1" range="0 100" damping="40"
             frictionloss="6" ref="0"/>
      <inertial pos="{-width / 2} 0 1" mass="15" diaginertia="5 5 1"/>
      {_leaf_geoms("door", width, (1.0, -1.0))}
    </body>
    <body name="opposite_door" pos="{o0 + plan.doorway_width - 0.015} {top} 0">
      {_leaf_geoms("opposite", width, (-1.0,))}
    </body>
    {base.body}
  </worldbody>
  <actuator>
    {base.actuator}
    <position name="pan" joint="head_pan" kp="4" kv="0.4" forcerange="-2 2"/>
  </actuator>
  <sensor>
    {base.sensor}
  </sensor>
</mujoco>
"""
