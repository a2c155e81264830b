"""The tabletop of Thiella (2021) in physics: a MuJoCo arm, two cameras and AprilTags.

:class:`MujocoTabletop` is a ``Body`` like :class:`~robocog.worlds.tabletop.TabletopWorld`
and takes the same commands, but every one of them is a motion of a simulated arm:

* ``PickUp(x)`` / ``Unstack(x, y)``: open, travel above ``x`` at a safe height, descend,
  close the fingers on it, lift. The grasp holds by the pads' friction; whether it held
  is read from the fingers (a closed hand has nothing between its pads).
* ``PutDown(x, on)`` / ``Stack(x, on)``: travel above ``on`` (a free place on a fixed
  object, or the top of a cube), descend, open, rise; then look whether ``x`` stayed.

Where a cube is comes only from the cameras: each look renders the overhead and the
front camera, detects the tags (:mod:`robocog.worlds.physics.perception`) and keeps the
cubes' poses; the arm aims at those. The percepts are the tags seen, what each cube is
seen resting on (:class:`~robocog.robot.percepts.Resting`), and the gripper. A look
happens when the mind asks for percepts, once per simulated instant (rendering is the
costly part, so the physics runs unrendered in between).

Faults come from the physics, or on purpose: ``slip_rate`` opens the fingers just
after a lift (the cube drops where it falls), and :meth:`perturb` moves a cube as a
person would. Both are seen at the next look.

Needs the ``physics`` extra; :func:`robocog.worlds.physics.gl.choose_gl` picks EGL or
OSMesa so it renders without a display.
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterable, Mapping
from dataclasses import replace

import numpy as np

from robocog.robot.commands import Command, Outcome, PickUp, PutDown, Stack, Unstack
from robocog.robot.percepts import Gripper, Percept, Resting, Tag
from robocog.worlds.physics.gl import choose_gl
from robocog.worlds.tabletop import BLOCK_C_BINS, FIXED_OBJECTS, INITIAL_BINS, Executed

choose_gl()  # before mujoco is imported (importing robocog.worlds.physics did it too)

import mujoco  # noqa: E402

from robocog.worlds.physics.arm import Arm, IKError, down_rotation  # noqa: E402
from robocog.worlds.physics.perception import CubeView, Eyes, cube_views, resting  # noqa: E402
from robocog.worlds.physics.scene import (  # noqa: E402
    CUBE,
    FINGER_OPEN,
    OFFSTAGE,
    Layout,
    scene_xml,
)

#: every cube the assembly may bring in, in the order their tags are numbered
ALL_CUBES: tuple[str, ...] = (
    *INITIAL_BINS,
    *BLOCK_C_BINS,
    "BlockA",
    "BlockB",
)

#: the tool centre point's height over the highest cube top when travelling
CLEARANCE = 0.07
#: where the arm waits while the cameras look: above the gap between table and workbench
READY = (0.0, -0.16, 0.30)


def _segment_distance(
    p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]
) -> float:
    """Distance in the plane from ``p`` to the segment ``a``-``b``."""
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    length = dx * dx + dy * dy
    t = 0.0 if length == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)


class MujocoTabletop:
    """The physical tabletop and arm; implements ``Body``."""

    def __init__(
        self,
        seed: int = 0,
        parts: Mapping[str, str] | None = None,
        slip_rate: float = 0.0,
        layout: Layout | None = None,
        record: bool = False,
        frame_every: float = 0.25,
        camera_size: tuple[int, int] = (1280, 960),
    ) -> None:
        if not 0.0 <= slip_rate < 1.0:
            raise ValueError("slip_rate must be in [0, 1)")
        self.rng = random.Random(seed)
        self.layout = layout or Layout()
        self.fixed: list[str] = list(FIXED_OBJECTS)
        names = [*self.fixed, *ALL_CUBES]
        self.tag_names: dict[int, str] = {i + 1: n for i, n in enumerate(names)}
        self.tag_ids = {n: i for i, n in self.tag_names.items()}
        xml, assets = scene_xml(
            {c: self.tag_ids[c] for c in ALL_CUBES},
            {f: self.tag_ids[f] for f in self.fixed},
            self.layout,
        )
        self.model = mujoco.MjModel.from_xml_string(xml, assets)
        self.data = mujoco.MjData(self.model)
        self.arm = Arm(self.model, self.data, self._step)
        self.eyes = Eyes(self.model, *camera_size)
        self.slip_rate = slip_rate
        self.record = record
        self.frame_every = frame_every
        self.frames: list[np.ndarray] = []
        self._video: mujoco.Renderer | None = None
        self._next_frame = 0.0
        self.held: str | None = None
        self.present: set[str] = set()
        self.views: dict[str, CubeView] = {}
        self.rests: dict[str, str] = {}
        self.seen_fixed: list[str] = []
        self.seen_now: set[str] = set()
        self._looked_at = -1.0
        self.log: list[Executed] = []
        self.grasps = 0
        self.slips = 0
        self.physics_steps = 0
        self.looks = 0
        self._joint = {
            c: self.model.jnt_qposadr[
                mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, f"cube_{c}")
            ]
            for c in ALL_CUBES
        }
        self._dof = {
            c: self.model.jnt_dofadr[
                mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, f"cube_{c}")
            ]
            for c in ALL_CUBES
        }
        mujoco.mj_forward(self.model, self.data)
        # the yaw the tool has, relative to its bearing from the base, with the flange at 0
        reach = np.array([0.0, 0.3, 1.6, 1.2, 0.0, 0.0])
        pos, rot = self.arm.tcp(reach)
        bx, by = self.layout.base
        bearing = math.atan2(pos[1] - by, pos[0] - bx)
        self._yaw_offset = math.atan2(rot[1, 0], rot[0, 0]) - bearing
        self.ready_q = self.arm.solve(np.array(READY), self._down(READY[0], READY[1]), reach)
        self.arm.reset(self.ready_q)
        self.add_parts(INITIAL_BINS if parts is None else parts)

    # -- the scene, by hand --------------------------------------------------------

    def _set_cube(self, name: str, pos: Iterable[float], yaw: float = 0.0) -> None:
        adr, dof = self._joint[name], self._dof[name]
        self.data.qpos[adr : adr + 3] = list(pos)
        self.data.qpos[adr + 3 : adr + 7] = [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]
        self.data.qvel[dof : dof + 6] = 0.0

    def add_parts(self, parts: Mapping[str, str]) -> None:
        """Put cubes into the scene by hand; ``parts`` maps each to what it rests on.

        A part on a fixed object goes to a free place on it; one on another part is set
        on its top. Small seeded offsets in place and yaw make each seed's scene its own.
        """
        pending = dict(parts)
        placed: dict[str, tuple[float, float, float, float]] = {}
        for _ in range(len(pending) + 1):
            for name, support in list(pending.items()):
                if name not in self._joint:
                    raise ValueError(f"no cube for {name}")
                jitter = (self.rng.uniform(-0.008, 0.008), self.rng.uniform(-0.008, 0.008))
                yaw = self.rng.uniform(-0.25, 0.25)
                if support in self.fixed:
                    region = self.layout.region(support)
                    x, y = self._free_slot(support, placed, by_hand=True)
                    pos = (x + jitter[0], y + jitter[1], region.top + CUBE / 2 + 0.001)
                elif support in placed:
                    bx, by, bz, byaw = placed[support]
                    pos, yaw = (bx, by, bz + CUBE + 0.001), byaw + self.rng.uniform(-0.1, 0.1)
                else:
                    continue
                self._set_cube(name, pos, yaw)
                placed[name] = (*pos, yaw)
                self.present.add(name)
                del pending[name]
        if pending:
            raise ValueError(f"cannot place {sorted(pending)}: unknown supports")
        mujoco.mj_forward(self.model, self.data)
        self._run(0.5)

    def remove(self, names: Iterable[str]) -> None:
        """Take cubes off the table by hand (they wait out of view)."""
        for i, name in enumerate(names):
            j = ALL_CUBES.index(name)
            self._set_cube(
                name, (OFFSTAGE[0] + 0.1 * j, OFFSTAGE[1] + 0.1 * i, OFFSTAGE[2] + CUBE / 2)
            )
            self.present.discard(name)
        mujoco.mj_forward(self.model, self.data)

    def replace_with_block(self, parts: Iterable[str], block: str) -> None:
        """Replace a finished stack by one cube ``block`` where its bottom stood (by hand)."""
        parts = list(parts)
        if self.held in parts:
            raise ValueError(f"the {self.held} is still in the hand")
        bottom = min(parts, key=lambda p: self.cube_pose(p)[0][2])
        (x, y, z), yaw = self.cube_pose(bottom)
        self.remove(parts)
        self._set_cube(block, (x, y, z + 0.001), yaw)
        self.present.add(block)
        mujoco.mj_forward(self.model, self.data)
        self._run(0.4)

    def perturb(self, among: Iterable[str] = ()) -> str | None:
        """Move one cube as a person would: a clear one, onto the table or onto another.

        The cube is drawn from ``among`` when one of those is clear (an experiment names
        the parts its request is about), else from every clear cube. Returns a sentence
        saying what moved, or None when no cube could be moved.
        """
        truth = self.ground_truth()
        clear = [c for c in sorted(self.present) if c != self.held and c not in truth.values()]
        wanted = [c for c in clear if c in set(among)]
        if not clear:
            return None
        name = self.rng.choice(wanted or clear)
        targets = [c for c in clear if c != name and truth.get(c) is not None]
        if targets and self.rng.random() < 0.5:
            other = self.rng.choice(targets)
            self.move_by_hand(name, other)
            return f"the {name} was moved onto the {other}"
        self.move_by_hand(name, "table")
        return f"the {name} was moved to the table"

    def move_by_hand(self, name: str, onto: str) -> None:
        """Set a cube on a free place of a fixed object, or on top of another cube."""
        if name not in self.present or name == self.held:
            raise ValueError(f"the {name} is not on the table to be moved")
        if onto in self.fixed:
            x, y = self._free_slot(onto, {}, by_hand=True)
            top = self.layout.region(onto).top
            self._set_cube(name, (x, y, top + CUBE / 2 + 0.002), self.rng.uniform(-0.4, 0.4))
        else:
            (x, y, z), yaw = self.cube_pose(onto)
            self._set_cube(name, (x, y, z + CUBE + 0.002), yaw)
        mujoco.mj_forward(self.model, self.data)
        self._run(0.5)
        self._looked_at = -1.0

    # -- ground truth, for judging a run (the mind never sees it) --------------------

    def cube_pose(self, name: str) -> tuple[tuple[float, float, float], float]:
        """The simulator's centre and yaw of a cube (for the experiment's checks only)."""
        adr = self._joint[name]
        x, y, z = (float(v) for v in self.data.qpos[adr : adr + 3])
        w, qx, qy, qz = (float(v) for v in self.data.qpos[adr + 3 : adr + 7])
        yaw = math.atan2(2 * (w * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
        return (x, y, z), yaw

    def ground_truth(self) -> dict[str, str]:
        """What each cube rests on in the simulator (for judging, never for the mind)."""
        poses = {c: self.cube_pose(c)[0] for c in self.present}
        out: dict[str, str] = {}
        for name, (x, y, z) in poses.items():
            for other, (ox, oy, oz) in poses.items():
                if (
                    other != name
                    and abs(z - oz - CUBE) < 0.012
                    and math.hypot(x - ox, y - oy) < 0.02
                ):
                    out[name] = other
            if name not in out:
                for region in self.layout.regions:
                    if region.contains(x, y) and abs(z - CUBE / 2 - region.top) < 0.01:
                        out[name] = region.name
        return out

    def holds(self, fact: tuple[str, ...]) -> bool:
        """Whether an ``on``, ``clear`` or ``in-hand`` fact is true in the simulator."""
        truth = self.ground_truth()
        if fact[0] == "on" and len(fact) == 3:
            return truth.get(fact[1]) == fact[2]
        if fact[0] == "clear" and len(fact) == 2:
            return fact[1] not in truth.values() and self.held != fact[1]
        if fact[0] == "in-hand" and len(fact) == 2:
            return self.held == fact[1]
        raise ValueError(f"unknown fact {fact}")

    # -- physics and video -----------------------------------------------------------

    def _step(self, n: int) -> None:
        if not self.record:
            mujoco.mj_step(self.model, self.data, nstep=n)
            self.physics_steps += n
            return
        for _ in range(n):
            mujoco.mj_step(self.model, self.data)
            self.physics_steps += 1
            if self.data.time >= self._next_frame:
                self._grab_frame()
                self._next_frame = self.data.time + self.frame_every

    def _grab_frame(self) -> None:
        if self._video is None:
            self._video = mujoco.Renderer(self.model, 360, 480)
        self._video.update_scene(self.data, camera="view")
        self.frames.append(self._video.render().copy())

    def snapshot(self, camera: str = "view", size: tuple[int, int] = (960, 720)) -> np.ndarray:
        """A picture of the scene now (for reports)."""
        renderer = mujoco.Renderer(self.model, size[1], size[0])
        try:
            renderer.update_scene(self.data, camera=camera)
            return renderer.render().copy()
        finally:
            renderer.close()

    def _run(self, seconds: float) -> None:
        self._step(max(1, int(seconds / self.model.opt.timestep)))

    # -- perception ------------------------------------------------------------------

    def look(self) -> None:
        """Render both cameras and update what is seen, once per simulated instant."""
        if self._looked_at == self.data.time:
            return
        mujoco.mj_forward(self.model, self.data)
        sightings = self.eyes.look(self.data)
        cubes = {i: n for i, n in self.tag_names.items() if n not in self.fixed}
        views = cube_views(sightings, cubes)
        self.seen_now = set(views)
        # a cube no camera sees now stays where it was if a cube now stands on its top
        # (covered, as the lower cubes of a stack are); otherwise it is forgotten
        for name, old in sorted(self.views.items(), key=lambda kv: -kv[1].centre[2]):
            if name in views or name == self.held or name not in self.present:
                continue
            if any(
                abs(v.centre[2] - old.centre[2] - CUBE) < 0.35 * CUBE
                and math.hypot(v.centre[0] - old.centre[0], v.centre[1] - old.centre[1])
                < 0.5 * CUBE
                for v in views.values()
            ):
                views[name] = replace(old, seen_from="memory")
        self.views = views
        self.rests = resting(self.views, self.layout)
        seen_ids = {s.id for s in sightings}
        self.seen_fixed = [n for n in self.fixed if self.tag_ids[n] in seen_ids]
        self._looked_at = self.data.time
        self.looks += 1

    def time(self) -> float:
        """Simulated seconds."""
        return float(self.data.time)

    def percepts(self) -> list[Percept]:
        """The tags seen, what each cube rests on (covered ones too), and the gripper."""
        self.look()
        out: list[Percept] = []
        for name in self.seen_fixed:
            out.append(Tag(self.tag_ids[name], name))
        for name in sorted(self.seen_now, key=lambda n: self.tag_ids[n]):
            out.append(Tag(self.tag_ids[name], name))
        for name, on in self.rests.items():
            out.append(Resting(name, on))
        out.append(Gripper(self.held))
        return out

    # -- commands ----------------------------------------------------------------------

    def execute(self, command: Command) -> Outcome:
        """Carry out one of the four manipulator actions with the arm."""
        try:
            outcome = self._execute(command)
        except IKError as exc:
            self._home()
            outcome = Outcome.failure(f"out of reach: {exc}")
        self.log.append(Executed(self.time(), command, outcome))
        return outcome

    def _execute(self, command: Command) -> Outcome:
        if isinstance(command, PickUp):
            return self._grasp(command.obj, None)
        if isinstance(command, Unstack):
            return self._grasp(command.obj, command.frm)
        if isinstance(command, PutDown | Stack):
            return self._place(command.obj, command.on)
        return Outcome.failure(f"the arm cannot {type(command).__name__}")

    def _down(self, x: float, y: float, yaw: float | None = None) -> np.ndarray:
        return down_rotation(self._grip_yaw(x, y, yaw))

    def _grip_yaw(self, x: float, y: float, yaw: float | None) -> float:
        """The gripper yaw that matches a cube's faces and keeps the flange near its middle."""
        bx, by = self.layout.base
        natural = math.atan2(y - by, x - bx) + self._yaw_offset
        if yaw is None:
            return natural
        best = yaw
        for k in range(4):
            cand = yaw + k * math.pi / 2
            diff = (cand - natural + math.pi) % (2 * math.pi) - math.pi
            if abs(diff) <= math.pi / 4 + 1e-9:
                best = natural + diff
        return best

    def _safe_z(self, path: list[tuple[float, float]]) -> float:
        """A travel height clearing every seen cube near the path (a held cube hangs below)."""
        tops = [0.0]
        for name, v in self.views.items():
            if name == self.held:
                continue
            if any(
                _segment_distance((v.centre[0], v.centre[1]), a, b) < 0.12
                for a, b in zip(path, path[1:] or path, strict=False)
            ):
                tops.append(v.centre[2] + CUBE / 2)
        return max(0.2, max(tops) + CLEARANCE + CUBE / 2)

    def _travel(self, x: float, y: float, yaw: float | None) -> None:
        """Rise to a safe height, cross over (around the base), and stop above (x, y)."""
        pos, _ = self.arm.tcp(self.arm.target)
        bx, by = self.layout.base
        a0 = math.atan2(pos[1] - by, pos[0] - bx)
        a1 = math.atan2(y - by, x - bx)
        turn = (a1 - a0 + math.pi) % (2 * math.pi) - math.pi
        path = [(float(pos[0]), float(pos[1]))]
        if abs(turn) > 0.6:  # a straight line would pass over the base: go round at 0.42 m
            mid = a0 + turn / 2
            path.append((bx + 0.42 * math.cos(mid), by + 0.42 * math.sin(mid)))
        path.append((x, y))
        z = max(self._safe_z(path), float(pos[2]))
        self.arm.move(np.array([pos[0], pos[1], z]), self._tool_yaw(0.0))
        for px, py in path[1:-1]:
            self.arm.move(np.array([px, py, z]), self._grip_yaw(px, py, None))
        self.arm.move(np.array([x, y, z]), self._grip_yaw(x, y, yaw))

    def _tool_yaw(self, fallback: float) -> float:
        _, rot = self.arm.tcp(self.arm.target)
        yaw = math.atan2(rot[1, 0], rot[0, 0])
        return yaw if math.isfinite(yaw) else fallback

    def _home(self) -> None:
        """Back to the ready pose, where the arm hides little from the cameras."""
        pos, _ = self.arm.tcp(self.arm.target)
        z = max(float(pos[2]), self._safe_z([(float(pos[0]), float(pos[1]))]))
        try:
            self.arm.move(np.array([pos[0], pos[1], z]), self._tool_yaw(0.0))
        except IKError:
            pass
        self.arm.go_joints(self.ready_q, 1.2)

    def _below(self, name: str) -> list[str]:
        return [n for n, on in self.rests.items() if on == name]

    def _grasp(self, obj: str, frm: str | None) -> Outcome:
        self.look()
        if self.held is not None:
            return Outcome.failure(f"the hand already holds the {self.held}")
        if obj in self.fixed:
            return Outcome.failure(f"the {obj} is fixed")
        view = self.views.get(obj)
        if view is None:
            return Outcome.failure(f"no {obj} in view")
        if not view.upright:
            return Outcome.failure(f"the {obj} lies tilted")
        if self._below(obj):
            return Outcome.failure(f"the {obj} is not clear")
        if frm is not None and self.rests.get(obj) != frm:
            return Outcome.failure(f"the {obj} is not on the {frm}")
        x, y, z = view.centre
        self.arm.open()
        self._travel(x, y, view.yaw)
        yaw = self._grip_yaw(x, y, view.yaw)
        self.arm.move(np.array([x, y, z + 0.05]), yaw)
        self.arm.move(np.array([x, y, z - 0.002]), yaw, speed=0.12)
        self.arm.close()
        self.grasps += 1
        self.arm.move(np.array([x, y, z + 0.06]), yaw, speed=0.12)
        if self.arm.finger_gap() < CUBE * 0.7:
            self.arm.open()
            self._home()
            return Outcome.failure(f"grasp failed: the {obj} slipped")
        self.held = obj
        if self.slip_rate > 0.0 and self.rng.random() < self.slip_rate:
            self.arm.open()
            self.held = None
            self.slips += 1
            self._run(0.8)
            self._home()
            return Outcome.failure(f"grasp failed: the {obj} slipped from the fingers")
        self._home()
        if self.arm.finger_gap() < CUBE * 0.7:
            self.held = None
            return Outcome.failure(f"the {obj} fell from the hand")
        return Outcome.success()

    def _free_slot(
        self,
        fixed: str,
        extra: Mapping[str, tuple[float, float, float, float]],
        by_hand: bool = False,
    ) -> tuple[float, float]:
        """A place on ``fixed`` with no cube near it: as the cameras saw it for the arm,
        as it is for a placement by hand (``by_hand``, with ``extra`` just placed)."""
        region = self.layout.region(fixed)
        taken = [(p[0], p[1]) for p in extra.values()]
        if by_hand:
            taken += [
                self.cube_pose(c)[0][:2] for c in self.present if c not in extra and c != self.held
            ]
        else:
            taken += [(v.centre[0], v.centre[1]) for n, v in self.views.items() if n != self.held]
        for slot in region.slots:
            if all(math.hypot(slot[0] - tx, slot[1] - ty) > CUBE * 1.3 for tx, ty in taken):
                return slot
        return region.slots[0]

    def _place(self, obj: str, on: str) -> Outcome:
        self.look()
        if self.held != obj:
            return Outcome.failure(f"the {obj} is not in the hand")
        if on == obj:
            return Outcome.failure(f"the {on} is not clear")
        if on in self.fixed:
            region = self.layout.region(on)
            x, y = self._free_slot(on, {})
            # square to the table (the cube sits square in the fingers), so that the
            # front camera sees a face of it straight on once others cover its top
            z, yaw = region.top + CUBE / 2 + 0.003, 0.0
        else:
            view = self.views.get(on)
            if view is None:
                return Outcome.failure(f"no {on} in view")
            if not view.upright or self._below(on):
                return Outcome.failure(f"the {on} is not clear")
            x, y = view.centre[0], view.centre[1]
            z, yaw = view.centre[2] + CUBE + 0.003, view.yaw
        self._travel(x, y, yaw)
        grip_yaw = self._grip_yaw(x, y, yaw)
        self.arm.move(np.array([x, y, z + 0.04]), grip_yaw)
        self.arm.move(np.array([x, y, z]), grip_yaw, speed=0.1)
        self.arm.grip(FINGER_OPEN, 0.4)
        self.held = None
        self.arm.move(np.array([x, y, z + 0.06]), grip_yaw, speed=0.15)
        self._home()
        self.look()
        if self.rests.get(obj) != on:
            seen = self.rests.get(obj)
            where = f"on the {seen}" if seen else "somewhere else"
            return Outcome.failure(f"the {obj} did not stay on the {on}: it is {where}")
        return Outcome.success()

    @property
    def failed_grasps(self) -> int:
        """Grasps that did not end with the cube in the hand."""
        return sum(
            1
            for e in self.log
            if isinstance(e.command, PickUp | Unstack)
            and not e.outcome.ok
            and ("grasp failed" in e.outcome.reason or "fell" in e.outcome.reason)
        )

    def close(self) -> None:
        """Free the renderers (their GL contexts are best freed while this one is alive)."""
        self.eyes.close()
        if self._video is not None:
            self._video.close()
            self._video = None
