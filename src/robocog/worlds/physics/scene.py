"""The tabletop of Thiella (2021, Fig. 3.1) written as MJCF: what stands where, and the arm.

As in the thesis's Gazebo world, a white table is on the left, a grey workbench on the
right with the arm fixed on it, and five coloured bins behind them. Every object wears
a tag36h11 AprilTag: the cubes on all six faces (whichever face ends up on top shows
its tag to the camera), the fixed objects on a flat plate beside them. The cubes are
equal, 5 cm, coloured as in Table 5.1 (the parts of BlockC have no colour there and are
white here).

The arm is robocog's own: six revolute joints (waist, shoulder, elbow, wrist pitch,
wrist roll, flange) and a parallel gripper of two sliding fingers driven by position
servos whose force is limited, so a cube is held by the friction of the finger pads.
Gravity is compensated on the arm's links, as a real controller would.

Positions are in metres, the table top at ``z = 0``; the world ``x`` points right and
``y`` away from the arm. The layout is plain data (``Layout``) that the body's
perception also reads as its map of the fixed objects.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from robocog.worlds.physics.tags import BLACK_CELLS, TOTAL_CELLS, png_bytes, tag_image

CUBE = 0.05
"""Edge of every cube (metres)."""

TAG_FACE = 0.999
"""Share of a cube's face the tag covers: all of it (a smaller tag is placed less
surely in depth by the detector, two and a half centimetres off at 0.9 of the face)."""

TAG_SIZE = CUBE * TAG_FACE * BLACK_CELLS / TOTAL_CELLS
"""Edge of a tag's black square (4 cm), what the detector calls the tag size."""

BIN_INNER = 0.13
BIN_WALL = 0.008
BIN_HEIGHT = 0.022
BIN_FLOOR = 0.008

#: Table 5.1's cube colours; the blocks and BlockC's parts are coloured here
CUBE_COLOURS: dict[str, tuple[float, float, float]] = {
    "BearingSleeve1": (0.15, 0.65, 0.2),
    "BearingSleeve2": (0.95, 0.55, 0.1),
    "BettClamp": (0.15, 0.3, 0.85),
    "SnapRing1": (0.55, 0.55, 0.55),
    "SnapRing2": (0.85, 0.7, 0.2),
    "RecirculatingBallSleeve": (0.85, 0.15, 0.15),
    "InductionHardenedRod": (0.95, 0.9, 0.15),
    "BlockA": (0.3, 0.2, 0.6),
    "BlockB": (0.2, 0.55, 0.6),
    "BlockC": (0.6, 0.35, 0.25),
    "UpperBearingBracket": (0.9, 0.9, 0.9),
    "Bearing": (0.9, 0.9, 0.9),
    "RotatingBalancerSupport": (0.9, 0.9, 0.9),
    "TCEIScrew": (0.9, 0.9, 0.9),
}

BIN_COLOURS: dict[str, tuple[float, float, float]] = {
    "PurpleBin": (0.5, 0.2, 0.6),
    "GreenBin": (0.2, 0.6, 0.25),
    "RedBin": (0.8, 0.15, 0.15),
    "BlueBin": (0.15, 0.3, 0.8),
    "YellowBin": (0.9, 0.8, 0.15),
}


@dataclass(frozen=True)
class Region:
    """A fixed object's top surface: a rectangle at height ``top``, and where cubes go."""

    name: str
    centre: tuple[float, float]
    half: tuple[float, float]
    top: float
    slots: tuple[tuple[float, float], ...]
    tag_at: tuple[float, float]

    def contains(self, x: float, y: float, margin: float = 0.0) -> bool:
        """Whether (x, y) lies over this surface (grown by ``margin``)."""
        return (
            abs(x - self.centre[0]) <= self.half[0] + margin
            and abs(y - self.centre[1]) <= self.half[1] + margin
        )


def _bin(name: str, x: float, y: float) -> Region:
    half = BIN_INNER / 2
    return Region(name, (x, y), (half, half), BIN_FLOOR, ((x, y),), (x, y + half + 0.06))


@dataclass(frozen=True)
class Layout:
    """Where the fixed objects are, and the arm's base: the robot's map of its workplace."""

    base: tuple[float, float] = (0.0, -0.36)
    regions: tuple[Region, ...] = field(
        default_factory=lambda: (
            Region(
                "table",
                (-0.36, -0.2),
                (0.24, 0.25),
                0.0,
                ((-0.27, -0.3), (-0.27, -0.15), (-0.42, -0.3), (-0.42, -0.15), (-0.27, -0.02)),
                (-0.54, -0.4),
            ),
            Region(
                "workbench",
                (0.36, -0.2),
                (0.24, 0.25),
                0.0,
                ((0.28, -0.28), (0.28, -0.12), (0.43, -0.28), (0.43, -0.12), (0.28, 0.0)),
                (0.54, -0.4),
            ),
            _bin("PurpleBin", -0.34, 0.12),
            _bin("GreenBin", -0.17, 0.14),
            _bin("RedBin", 0.0, 0.15),
            _bin("BlueBin", 0.17, 0.14),
            _bin("YellowBin", 0.34, 0.12),
        )
    )

    def region(self, name: str) -> Region:
        """The surface of a fixed object by name (KeyError if unknown)."""
        for r in self.regions:
            if r.name == name:
                return r
        raise KeyError(name)

    @property
    def fixed(self) -> tuple[str, ...]:
        """The fixed objects' names."""
        return tuple(r.name for r in self.regions)


#: where the overhead camera hangs and how wide it sees (vertical field of view, degrees)
CAMERA_POS = (0.0, -0.12, 1.25)
CAMERA_FOVY = 40.0
#: the front camera, behind the arm, looking down at the bins at about 40 degrees
FRONT_POS = (0.0, -0.8, 0.7)
FRONT_XYAXES = "1 0 0 0 0.655 0.756"
FRONT_FOVY = 50.0

#: cubes not yet in the scene wait out of view on the floor, this far away
OFFSTAGE = (2.0, 2.0, -0.75)

ARM_JOINTS = ("j1", "j2", "j3", "j4", "j5", "j6")
FINGER_JOINTS = ("finger_l", "finger_r")
FINGER_OPEN = 0.042
"""Each finger's travel when open: a 5 cm cube fits with 1.7 cm to spare each side."""


def _rgba(c: tuple[float, float, float], a: float = 1.0) -> str:
    return f"{c[0]:.3f} {c[1]:.3f} {c[2]:.3f} {a:g}"


def _tag_material(tag_id: int, colour: tuple[float, float, float] | None) -> tuple[str, str]:
    name = f"tag{tag_id}"
    asset = (
        f'<texture name="{name}" type="2d" file="{name}.png"/>'
        f'<material name="{name}" texture="{name}" rgba="1 1 1 1" specular="0" shininess="0"/>'
    )
    return name, asset


def arm_xml(base: tuple[float, float]) -> str:
    """The six-joint arm and its two-finger gripper, base on the workbench at ``base``."""
    grey, dark = "0.75 0.76 0.78 1", "0.25 0.25 0.28 1"
    return f"""
    <body name="arm_base" pos="{base[0]} {base[1]} 0" euler="0 0 1.5708">
      <geom type="cylinder" size="0.07 0.04" pos="0 0 0.04" rgba="{dark}"/>
      <body name="link1" pos="0 0 0.08" gravcomp="1">
        <joint name="j1" axis="0 0 1" range="-2.9 2.9"/>
        <geom type="cylinder" size="0.05 0.03" pos="0 0 0.03" rgba="{grey}" mass="2"/>
        <body name="link2" pos="0 0 0.06" gravcomp="1">
          <joint name="j2" axis="0 1 0" range="-2.0 2.0"/>
          <geom type="capsule" fromto="0 0 0 0 0 0.38" size="0.035" rgba="{grey}" mass="2"/>
          <body name="link3" pos="0 0 0.38" gravcomp="1">
            <joint name="j3" axis="0 1 0" range="-2.7 2.7"/>
            <geom type="capsule" fromto="0 0 0 0 0 0.34" size="0.03" rgba="{grey}" mass="1.5"/>
            <body name="link4" pos="0 0 0.34" gravcomp="1">
              <joint name="j4" axis="0 1 0" range="-2.2 2.2"/>
              <geom type="capsule" fromto="0 0 0 0 0 0.05" size="0.028" rgba="{dark}" mass="0.5"/>
              <body name="link5" pos="0 0 0.05" gravcomp="1">
                <joint name="j5" axis="1 0 0" range="-2.0 2.0"/>
                <geom type="cylinder" size="0.026 0.02" pos="0 0 0.02" rgba="{grey}" mass="0.4"/>
                <body name="link6" pos="0 0 0.04" gravcomp="1">
                  <joint name="j6" axis="0 0 1" range="-3.1 3.1"/>
                  <geom type="box" size="0.065 0.022 0.012" pos="0 0 0.012" rgba="{dark}"
                        mass="0.4"/>
                  <site name="tcp" pos="0 0 0.064" size="0.004" rgba="1 0 0 0"/>
                  <body name="finger_l" pos="-0.006 0 0.024" gravcomp="1">
                    <joint name="finger_l" type="slide" axis="-1 0 0" range="0 {FINGER_OPEN}"
                           damping="8" armature="0.01"/>
                    <geom name="pad_l" type="box" size="0.006 0.013 0.0275" pos="0 0 0.0275"
                          rgba="{grey}" mass="0.05" condim="4" friction="1.5 0.02 0.001"/>
                  </body>
                  <body name="finger_r" pos="0.006 0 0.024" gravcomp="1">
                    <joint name="finger_r" type="slide" axis="1 0 0" range="0 {FINGER_OPEN}"
                           damping="8" armature="0.01"/>
                    <geom name="pad_r" type="box" size="0.006 0.013 0.0275" pos="0 0 0.0275"
                          rgba="{grey}" mass="0.05" condim="4" friction="1.5 0.02 0.001"/>
                  </body>
                </body>
              </body>
            </body>
          </body>
        </body>
      </body>
    </body>"""


ARM_ACTUATORS = """
    <position name="a1" joint="j1" kp="900" forcerange="-150 150"/>
    <position name="a2" joint="j2" kp="1500" forcerange="-250 250"/>
    <position name="a3" joint="j3" kp="1100" forcerange="-200 200"/>
    <position name="a4" joint="j4" kp="500" forcerange="-80 80"/>
    <position name="a5" joint="j5" kp="400" forcerange="-60 60"/>
    <position name="a6" joint="j6" kp="300" forcerange="-40 40"/>
    <position name="grip_l" joint="finger_l" kp="400" forcerange="-12 12"/>
    <position name="grip_r" joint="finger_r" kp="400" forcerange="-12 12"/>"""


def scene_xml(
    cubes: dict[str, int], fixed_tags: dict[str, int], layout: Layout
) -> tuple[str, dict[str, bytes]]:
    """The MJCF of the tabletop and its assets (tag textures as PNG bytes).

    ``cubes`` maps every cube that may ever appear to its tag id, ``fixed_tags`` every
    fixed object to its tag id. Cubes start off stage; the body places them.
    """
    assets: dict[str, bytes] = {}
    materials: list[str] = []
    for tag_id in sorted(set(cubes.values()) | set(fixed_tags.values())):
        assets[f"tag{tag_id}.png"] = png_bytes(tag_image(tag_id, 8))
        materials.append(_tag_material(tag_id, None)[1])

    bodies: list[str] = []
    for region in layout.regions:
        tag_id = fixed_tags[region.name]
        tx, ty = region.tag_at
        bodies.append(
            f'<geom name="tagplate_{region.name}" type="box" '
            f'size="{CUBE * TAG_FACE / 2} {CUBE * TAG_FACE / 2} 0.0005" '
            f'pos="{tx} {ty} 0.0005" material="tag{tag_id}" contype="0" conaffinity="0"/>'
        )
        if region.name in BIN_COLOURS:
            colour = _rgba(BIN_COLOURS[region.name])
            cx, cy = region.centre
            h = BIN_INNER / 2
            outer = h + BIN_WALL
            wall_z = BIN_HEIGHT / 2
            walls = [
                (0.0, h + BIN_WALL / 2, outer, BIN_WALL / 2),
                (0.0, -h - BIN_WALL / 2, outer, BIN_WALL / 2),
                (h + BIN_WALL / 2, 0.0, BIN_WALL / 2, h),
                (-h - BIN_WALL / 2, 0.0, BIN_WALL / 2, h),
            ]
            parts = [
                f'<geom type="box" size="{outer} {outer} {BIN_FLOOR / 2}" pos="0 0 {BIN_FLOOR / 2}" '
                f'rgba="{colour}"/>'
            ]
            for dx, dy, sx, sy in walls:
                parts.append(
                    f'<geom type="box" size="{sx} {sy} {wall_z}" pos="{dx} {dy} {wall_z}" '
                    f'rgba="{colour}"/>'
                )
            bodies.append(f'<body name="{region.name}" pos="{cx} {cy} 0">{"".join(parts)}</body>')

    for i, (name, tag_id) in enumerate(sorted(cubes.items(), key=lambda kv: kv[1])):
        colour = _rgba(CUBE_COLOURS.get(name, (0.8, 0.8, 0.8)))
        x, y, z = OFFSTAGE[0] + 0.1 * i, OFFSTAGE[1], OFFSTAGE[2] + CUBE / 2
        h = CUBE / 2
        t = h * TAG_FACE
        # the cube's body is its colour; a thin tagged skin on each face shows the tag
        skins = "".join(
            f'<geom type="box" size="{sx} {sy} {sz}" pos="{px} {py} {pz}" material="tag{tag_id}" '
            f'contype="0" conaffinity="0" mass="0"/>'
            for (sx, sy, sz, px, py, pz) in (
                (t, t, 0.0003, 0, 0, h),
                (t, t, 0.0003, 0, 0, -h),
                (t, 0.0003, t, 0, h, 0),
                (t, 0.0003, t, 0, -h, 0),
                (0.0003, t, t, h, 0, 0),
                (0.0003, t, t, -h, 0, 0),
            )
        )
        bodies.append(
            f'<body name="cube_{name}" pos="{x} {y} {z}"><freejoint name="cube_{name}"/>'
            f'<geom name="cube_{name}" type="box" size="{h * 0.995} {h * 0.995} {h * 0.995}" '
            f'mass="0.06" rgba="{colour}" condim="4" friction="1.2 0.02 0.001"/>{skins}</body>'
        )

    table = layout.region("table")
    bench = layout.region("workbench")
    xml = f"""<mujoco model="robocog_tabletop">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"
          noslip_iterations="2"/>
  <visual>
    <global offwidth="1280" offheight="960"/>
    <quality shadowsize="2048"/>
    <headlight ambient="0.45 0.45 0.45" diffuse="0.45 0.45 0.45" specular="0 0 0"/>
  </visual>
  <default>
    <geom solref="0.004 1" solimp="0.95 0.99 0.001"/>
    <joint damping="6" armature="0.05"/>
  </default>
  <asset>
    {"".join(materials)}
  </asset>
  <worldbody>
    <light pos="0 -0.2 2.2" dir="0 0 -1" diffuse="0.5 0.5 0.5" castshadow="false"/>
    <geom name="floor" type="plane" size="4 4 0.1" pos="0 0 -0.75" rgba="0.35 0.33 0.3 1"/>
    <geom name="table" type="box" size="{table.half[0]} {table.half[1]} 0.02"
          pos="{table.centre[0]} {table.centre[1]} -0.02" rgba="0.95 0.95 0.93 1"/>
    <geom name="workbench" type="box" size="{bench.half[0]} {bench.half[1]} 0.02"
          pos="{bench.centre[0]} {bench.centre[1]} -0.02" rgba="0.55 0.56 0.58 1"/>
    <geom name="bench_middle" type="box" size="0.12 0.25 0.02" pos="0 -0.2 -0.02"
          rgba="0.55 0.56 0.58 1"/>
    <geom name="shelf" type="box" size="0.6 0.13 0.02" pos="0 0.18 -0.02" rgba="0.4 0.4 0.42 1"/>
    <camera name="overhead" pos="{CAMERA_POS[0]} {CAMERA_POS[1]} {CAMERA_POS[2]}"
            xyaxes="1 0 0 0 1 0" fovy="{CAMERA_FOVY}"/>
    <camera name="front" pos="{FRONT_POS[0]} {FRONT_POS[1]} {FRONT_POS[2]}"
            xyaxes="{FRONT_XYAXES}" fovy="{FRONT_FOVY}"/>
    <camera name="view" pos="0.95 -1.05 0.85" xyaxes="0.74 0.67 0 -0.3 0.33 0.9" fovy="45"/>
    {"".join(bodies)}
    {arm_xml(layout.base)}
  </worldbody>
  <contact>
    <exclude body1="link6" body2="finger_l"/>
    <exclude body1="link6" body2="finger_r"/>
  </contact>
  <actuator>{ARM_ACTUATORS}
  </actuator>
</mujoco>"""
    return xml, assets
