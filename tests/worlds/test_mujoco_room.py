"""The physical Q.bo room: a look finds the door in the right image area, and the
ultrasonic sensors stop the base before a wall."""

from __future__ import annotations

import math

import pytest

import robocog.worlds.physics  # noqa: F401  (chooses the offscreen GL before mujoco loads)

mujoco = pytest.importorskip("mujoco", reason="the physics extra (mujoco) is not installed")
pytest.importorskip("sklearn", reason="the physics extra (scikit-learn) is not installed")

from robocog.minds.qbo import QboPerception  # noqa: E402
from robocog.robot.commands import Forward, Look  # noqa: E402
from robocog.worlds.mujoco_room import MujocoRoom  # noqa: E402
from robocog.worlds.physics import room_vision  # noqa: E402


@pytest.fixture(scope="module")
def classifier(tmp_path_factory: pytest.TempPathFactory) -> room_vision.AreaClassifier:
    """A classifier trained on fewer renders than the default, cached in a temporary folder."""
    return room_vision.trained(
        seed=3, images=240, test_images=60, directory=tmp_path_factory.mktemp("svm")
    )


def test_the_svm_scores_well_on_held_out_renders(
    classifier: room_vision.AreaClassifier,
) -> None:
    assert [s.target for s in classifier.scores] == ["door", "entry"]
    for score in classifier.scores:
        assert score.accuracy >= 0.9, score.line()
        (tn, fp), (fn, tp) = score.confusion
        assert tn + fp + fn + tp == score.support
        assert tp > 0 and tn > 0  # both classes occur in the held-out areas


def _leaf_centre(world: MujocoRoom) -> tuple[float, float]:
    return world.door.face.point(0.5)


@pytest.mark.parametrize(("offset", "image"), [(0.0, "front"), (-55.0, "left")])
def test_looking_finds_the_door_in_the_area_it_stands_in(
    classifier: room_vision.AreaClassifier, offset: float, image: str
) -> None:
    x, y = 3.0, 2.5
    probe = MujocoRoom(0, classifier=classifier, start=(x, y, 0.0), door_open_degrees=80.0)
    cx, cy = _leaf_centre(probe)
    probe.close()
    towards = math.atan2(cy - y, cx - x)
    world = MujocoRoom(
        0,
        classifier=classifier,
        start=(x, y, towards + math.radians(offset)),
        door_open_degrees=80.0,
    )
    try:
        perception = QboPerception()
        perception.look_started("door")
        assert world.execute(Look("around")).ok
        literals = perception.update(world.percepts())
        doors = [d for d in world.percepts() if getattr(d, "label", None) == "door"]
        best = max(doors, key=lambda d: d.confidence)
        # the middle column of the image whose centre points at the leaf
        assert best.instance is not None and best.instance.startswith(f"{image}:")
        assert best.instance.endswith(":1")
        assert world.last_seen["door"].source == "door"
        assert "found_target(door)" in literals
        said = math.radians(perception.target[1]) if perception.target else math.inf
        assert abs(math.degrees(said - towards)) < 12.0, (said, towards)
    finally:
        world.close()


def test_the_ultrasonic_sensors_stop_the_base_before_a_wall(
    classifier: room_vision.AreaClassifier,
) -> None:
    world = MujocoRoom(1, classifier=classifier, start=(3.0, 1.2, -math.pi / 2))
    try:
        outcome = world.execute(Forward(3.0))
        assert not outcome.ok and outcome.reason == "obstacle ahead"
        left, right = world.sonars(noise=False)
        assert min(left, right) < world.config.stop_distance + 0.05
        # stopped short of the wall (its face is 4 cm north of y = 0), not against it
        assert 0.04 + 0.18 + 0.1 < world.y < 0.75
        assert abs(world.x - 3.0) < 0.05
        assert world.time() > 4.0  # it drove there at 0.15 m/s
    finally:
        world.close()


def test_the_inspector_draws_the_physical_room_as_the_2d_one(
    classifier: room_vision.AreaClassifier,
) -> None:
    from robocog.inspector.views import world_viewer

    world = MujocoRoom(2, classifier=classifier, door_open_degrees=80.0)
    try:
        view = world_viewer(world)(world, world.percepts())
        assert view["kind"] == "room"
        leaf = view["targets"][0]["face"]
        # the leaf stands 80 degrees into the room from its hinge at the right jamb
        assert math.degrees(math.atan2(leaf[1] - leaf[3], leaf[0] - leaf[2])) == pytest.approx(
            80.0, abs=1.0
        )
        assert view["robot"]["x"] == pytest.approx(world.x, abs=0.01)
    finally:
        world.close()
