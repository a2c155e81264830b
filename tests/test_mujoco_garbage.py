"""The garbage field in physics: a leg and a pick, percepts from pixels and rays, and the
learned detector's accuracy on held-out renders."""

from __future__ import annotations

import math

import pytest

from robocog.worlds.physics.gl import choose_gl

choose_gl()  # offscreen GL chosen before mujoco loads
pytest.importorskip("mujoco")
pytest.importorskip("sklearn")

import mujoco  # noqa: E402

from robocog.robot.commands import Drop, GoTo, Pick  # noqa: E402
from robocog.robot.percepts import Detection, Gripper, Obstacle, Pose  # noqa: E402
from robocog.worlds.garbage import GarbageConfig  # noqa: E402
from robocog.worlds.physics import trash_detector as td  # noqa: E402


@pytest.fixture(scope="module")
def trained():
    """A small detector trained here (seeded), and its report on held-out renders."""
    return td.train(td.TrainingSettings(frames=24, held_out=9, seed=3))


def _field(detector, seed=0, **config):
    from robocog.worlds.mujoco_garbage import MujocoGarbageField

    return MujocoGarbageField(GarbageConfig(**config), seed=seed, detector=detector)


def _teleport(world, x, y, theta):
    """Put the robot's body somewhere (the simulator only: the estimate is not told)."""
    adr = world.model.joint("robot_free").qposadr[0]
    z = world.data.qpos[adr + 2]
    world.data.qpos[adr : adr + 7] = [x, y, z, math.cos(theta / 2), 0, 0, math.sin(theta / 2)]
    mujoco.mj_forward(world.model, world.data)


def _place_estimate(world, x, y, theta):
    world.base.localiser.reset((x, y, theta))


def test_the_detector_is_accurate_on_held_out_renders(trained):
    detector, report = trained
    assert report.frames == 9 and report.objects > 20
    # a model of 24 frames finds what the sun lights well; the dim flat overcast and
    # the low evening sun, where objects hardly stand out, are harder for it
    sunny_found, sunny_objects = report.per_light["sunny"]
    assert sunny_objects >= 10 and sunny_found >= 0.75 * sunny_objects
    assert report.recall >= 0.45
    assert report.label_accuracy >= 0.8
    assert report.false_positives <= report.found // 4
    # the model round-trips through its plain-array file
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "model.npz"
        detector.save(path)
        again = td.TrashDetector.load(path)
    frame = td.render_frames(1, 99)[0]
    assert again.detect(frame.image) == detector.detect(frame.image)


def test_one_leg_and_one_pick(trained):
    detector, _ = trained
    world = _field(detector, seed=5)
    try:
        assert world.execute(GoTo("next")).ok
        x, y, _ = world.base.true_pose()
        cx, cy = world.checkpoints["p0"]
        assert math.hypot(x - cx, y - cy) < 0.4
        pose = [p for p in world.percepts() if isinstance(p, Pose)]
        # put the robot before an upright object, 1.6 m away, facing it
        target = next(
            t for t, p in zip(world.trash, world.placed, strict=True) if p.pose == "upright"
        )
        yaw = 0.3
        x, y = target.x - 1.6 * math.cos(yaw), target.y - 1.6 * math.sin(yaw)
        _teleport(world, x, y, yaw)
        _place_estimate(world, x, y, yaw)
        seen = [p for p in world.percepts() if isinstance(p, Detection)]
        assert any(abs(d.bearing) < 0.1 and abs(d.distance - 1.6) < 0.2 for d in seen)
        assert world.execute(Pick("trash")).ok
        grip = [p for p in world.percepts() if isinstance(p, Gripper)]
        assert grip and grip[0].holding is not None
        assert world.joint_positions()["finger_left"] > 0.012  # the fingers rest on it
        assert world.execute(Drop()).ok
        assert world.collected() == 1
    finally:
        world.close()
    assert pose and pose[0].place == "p0"


def _put(world, name, x, y):
    """Stand an object upright at (x, y) (the simulator only)."""
    j = world.model.joint(name)
    world.data.qpos[j.qposadr[0] : j.qposadr[0] + 7] = [x, y, 0.001, 1, 0, 0, 0]
    world.data.qvel[j.dofadr[0] : j.dofadr[0] + 6] = 0.0
    mujoco.mj_forward(world.model, world.data)


def _seen(world):
    percepts = world.percepts()
    return {d.label: d for d in percepts if isinstance(d, Detection)}, percepts


def test_percepts_follow_pixels_and_rays_not_the_simulator(trained):
    detector, _ = trained
    world = _field(detector, seed=5)
    try:
        bottle = next(t.instance for t in world.trash if t.label == "bottle")
        cup = next(t.instance for t in world.trash if t.label == "cup")
        # the robot in open ground, the bottle ahead-left and the cup ahead-right
        _teleport(world, 11.0, 11.0, 0.0)
        _place_estimate(world, 11.0, 11.0, 0.0)
        _put(world, bottle, 13.0, 11.6)
        _put(world, cup, 13.0, 10.4)
        seen, _ = _seen(world)
        assert seen["bottle"].bearing > 0.15 and seen["cup"].bearing < -0.15
        # swap them in the simulator: the next frame's boxes follow the pixels
        _put(world, bottle, 13.0, 10.4)
        _put(world, cup, 13.0, 11.6)
        swapped, _ = _seen(world)
        assert swapped["bottle"].bearing < -0.15 and swapped["cup"].bearing > 0.15
        assert abs(swapped["bottle"].bearing - seen["cup"].bearing) < 0.05
        # move the robot's body, not its estimate, 1.2 m from the fence: the lidar's
        # obstacle follows the rays, the pose stays the estimate's (too far to match)
        _teleport(world, 11.0, 1.2, 0.0)
        world.wait(1.0)  # the pose is told once a second
        _, percepts = _seen(world)
        obstacle = next(p for p in percepts if isinstance(p, Obstacle))
        pose = next(p for p in percepts if isinstance(p, Pose))
        assert obstacle.sector == "right" and abs(obstacle.distance - 1.2) < 0.1
        assert abs(pose.y - 11.0) < 0.5
        true = world.base.true_pose()
        assert abs(true[1] - 1.2) < 0.05
    finally:
        world.close()


def test_commands_refuse_bad_options_in_one_line(capsys):
    from robocog.cli import main

    for argv in (
        ["experiment", "garbage", "--world", "mujoco", "--detection-frames", "-1"],
        ["train", "detector", "--frames", "1"],
    ):
        with pytest.raises(SystemExit) as stop:
            main(argv)
        assert stop.value.code == 2
        err = capsys.readouterr().err
        assert argv[-2] in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert main(["train"]) == 2


def test_a_missing_onnx_model_is_refused(capsys, tmp_path):
    from robocog.cli import main

    with pytest.raises(SystemExit) as stop:
        main(["experiment", "garbage", "--world", "mujoco", "--detector", str(tmp_path / "x")])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and "--detector" in err and "no such file" in err


def test_the_report_puts_table_one_beside_the_paper():
    from robocog.experiments.garbage import ExperimentResult
    from robocog.experiments.report import markdown

    row = {"rate": 0.8, "in_view": 10, "frames": 3, "paper": 0.83}
    result = ExperimentResult(
        GarbageConfig(), 0, 0, {}, world="mujoco", extra={"detection": {"sunny": row}}
    )
    page = markdown(result, {})
    assert "| sunny | 80% | 10 | 3 | 83% |" in page
    assert "learned detector" in page and "grasp success 85%" not in page


def test_an_overcast_sky_lights_upright_sides_less_than_the_ground():
    """The sky lights a surface by how much of it the surface faces: the ground all of
    it, an upright side a share (less under an overcast sky, brightest overhead), plus
    the grass's green bounce. Lit alike, bottles and cups would stand out brighter under
    cloud than in sun."""
    import numpy as np

    from robocog.worlds.physics.field_scene import LIGHTING, sky_light

    share = {}
    for name in ("sunny", "cloudy"):
        spec = LIGHTING[name]
        overhead, everywhere = sky_light(spec)
        ground = overhead + everywhere
        sky = np.array(spec.sky) * spec.ambient
        assert np.all(ground >= sky - 1e-9)  # the ground gets the whole sky
        # the bounce off the grass is green: it adds most to an upright side's green
        bounce = everywhere - sky * spec.sky_vertical
        assert bounce[1] > bounce[0] > 0 and bounce[1] > bounce[2] > 0
        share[name] = float(everywhere.sum() / ground.sum())
    assert share["cloudy"] < 0.6 and share["cloudy"] < share["sunny"]


def test_the_2d_field_stays_the_default_world():
    from robocog.cli import build_parser

    args = build_parser(["experiment", "garbage"]).parse_args(["experiment", "garbage"])
    assert args.world == "2d"
    mujoco_args = build_parser(["experiment", "garbage"]).parse_args(
        ["experiment", "garbage", "--world", "mujoco"]
    )
    assert mujoco_args.world == "mujoco"
