"""The physical tabletop: tags drawn by robocog, a stack built by the arm, tags found in pixels."""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocog.worlds.physics.tags import CODES, png_bytes, tag_cells

mujoco = pytest.importorskip("mujoco", reason="the physics extra (mujoco) is not installed")
apriltags = pytest.importorskip(
    "pupil_apriltags", reason="the physics extra (pupil-apriltags) is not installed"
)

from robocog.robot import Body, Gripper, PickUp, Resting, Stack, Tag  # noqa: E402
from robocog.worlds.mujoco_tabletop import MujocoTabletop  # noqa: E402
from robocog.worlds.physics.perception import shared_detector  # noqa: E402
from robocog.worlds.physics.scene import CUBE  # noqa: E402
from robocog.worlds.tabletop import FIXED_OBJECTS, INITIAL_BINS  # noqa: E402


@pytest.fixture(scope="module")
def world() -> MujocoTabletop:
    w = MujocoTabletop(seed=1)
    yield w
    w.close()


def test_every_tag_drawn_here_is_read_back_as_its_id() -> None:
    # the process's one detector: pupil-apriltags frees a detector's tag family before
    # the detector, whose own teardown then reads the freed family, so a second detector
    # made and dropped here could corrupt the heap of the process running the tests
    detector = shared_detector()
    for tag_id in range(len(CODES)):
        image = np.kron(tag_cells(tag_id) * 255, np.ones((6, 6), dtype=np.uint8)).astype(np.uint8)
        found = detector.detect(np.pad(image, 12, constant_values=255))
        assert [d.tag_id for d in found] == [tag_id]
    assert png_bytes(np.zeros((2, 3), dtype=np.uint8)).startswith(b"\x89PNG")


def _faces(world: MujocoTabletop, name: str) -> list[np.ndarray]:
    """The simulator's centres of a cube's six faces."""
    body = mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_BODY, f"cube_{name}")
    centre = world.data.xpos[body]
    rot = world.data.xmat[body].reshape(3, 3)
    return [centre + rot @ (s * CUBE / 2 * np.eye(3)[i]) for i in range(3) for s in (1, -1)]


def test_the_default_cameras_find_every_visible_tag_of_fig_5_6_within_a_centimetre(
    world: MujocoTabletop,
) -> None:
    assert isinstance(world, Body)
    mujoco.mj_forward(world.model, world.data)
    sightings = world.eyes.look(world.data)
    assert sightings
    covered = set(INITIAL_BINS.values())
    overhead = {s.id for s in sightings if s.camera == "overhead"}
    for name in INITIAL_BINS:
        tag = world.tag_ids[name]
        if name not in covered:  # its top face is in view of the overhead camera
            assert tag in overhead, f"the {name}'s top tag was not found"
        assert any(s.id == tag for s in sightings), f"no camera found the {name}"
    for name in FIXED_OBJECTS:
        assert world.tag_ids[name] in overhead, f"the {name}'s tag was not found"
    worst = 0.0
    for s in sightings:
        name = world.tag_names[s.id]  # an id the scene does not have would fail here
        if name in FIXED_OBJECTS:
            x, y = world.layout.region(name).tag_at
            truth = [np.array([x, y, 0.001])]
        else:
            truth = _faces(world, name)
        error = min(float(np.linalg.norm(np.array(s.position) - t)) for t in truth)
        worst = max(worst, error)
        assert error < 0.01, f"tag {s.id} ({name}) from the {s.camera} camera is {error:.4f} m off"
    assert worst > 0.0


def test_perception_says_what_rests_on_what_in_fig_5_6(world: MujocoTabletop) -> None:
    seen = world.percepts()
    rests = {(p.obj, p.on) for p in seen if isinstance(p, Resting)}
    assert rests == set(INITIAL_BINS.items())
    assert {p.name for p in seen if isinstance(p, Tag)} == set(FIXED_OBJECTS) | set(INITIAL_BINS)
    assert Gripper(None) in seen


@pytest.fixture
def fresh_world() -> MujocoTabletop:
    w = MujocoTabletop(seed=1)
    yield w
    w.close()


@pytest.mark.slow
def test_the_arm_stacks_one_cube_on_another_and_the_camera_sees_it_on_top(
    fresh_world: MujocoTabletop,
) -> None:
    world = fresh_world
    assert world.execute(PickUp("InductionHardenedRod")).ok
    assert Gripper("InductionHardenedRod") in world.percepts()
    outcome = world.execute(Stack("InductionHardenedRod", "BettClamp"))
    assert outcome.ok, outcome.reason
    # the simulator agrees: the rod's cube sits centred one cube above the clamp's
    (x, y, z), _ = world.cube_pose("InductionHardenedRod")
    (bx, by, bz), _ = world.cube_pose("BettClamp")
    assert abs(z - bz - CUBE) < 0.005 and math.hypot(x - bx, y - by) < 0.01
    assert world.held is None and world.arm.finger_gap() > CUBE
    seen = world.percepts()
    assert Resting("InductionHardenedRod", "BettClamp") in seen
    view = world.views["InductionHardenedRod"]
    assert view.upright and abs(view.centre[2] - z) < 0.01
    # the overhead camera reads the rod's tag on top of the stack, the clamp's no more
    image = world.eyes.last_images["overhead"]
    on_top = world.eyes.detect(image, world.data, "overhead")
    rod = [s for s in on_top if s.id == world.tag_ids["InductionHardenedRod"]]
    assert rod and rod[0].normal[2] > 0.8 and abs(rod[0].position[2] - (z + CUBE / 2)) < 0.01
    clamp = [s for s in on_top if s.id == world.tag_ids["BettClamp"] and s.normal[2] > 0.8]
    assert clamp == []


@pytest.mark.slow
def test_planner_mind_sees_a_cube_moved_onto_its_target_and_replans_physically() -> None:
    from robocog.experiments.assembly_thesis import experiment
    from robocog.minds.planner_mind import PlannerMind
    from robocog.robot.loop import Loop

    world = MujocoTabletop(seed=2)
    try:
        mind = PlannerMind(perceive_scene=True)
        loop = Loop(world, mind)
        record = mind.request(
            "The InductionHardenedRod is on the BettClamp.", facts=experiment("5.2").facts
        )
        loop.step()
        assert world.held == "InductionHardenedRod"
        world.move_by_hand("SnapRing1", "BettClamp")
        loop.run(20, until=lambda: not mind.busy)
        assert record.status == "reached", record.message
        assert record.failures[0] == "seen: the SnapRing1 is on the BettClamp, not on the SnapRing2"
        assert world.holds(("on", "InductionHardenedRod", "BettClamp"))
        assert not world.holds(("on", "SnapRing1", "BettClamp"))
    finally:
        world.close()
