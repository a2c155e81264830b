"""The shared mobile base: drive, lidar, range cone, odometry and lidar localisation."""

from __future__ import annotations

import math

import pytest

from robocog.worlds.physics.gl import choose_gl

choose_gl()  # offscreen GL chosen before mujoco loads
pytest.importorskip("mujoco")

import mujoco  # noqa: E402
import numpy as np  # noqa: E402

from robocog.worlds.physics.mobile_base import (  # noqa: E402
    BaseSpec,
    Localiser,
    MobileBase,
    RangeCone,
    base_fragment,
    steer,
    walls_xml,
)

SIZE = 6.0
WALLS = (
    ((0, 0), (SIZE, 0)),
    ((SIZE, 0), (SIZE, SIZE)),
    ((SIZE, SIZE), (0, SIZE)),
    ((0, SIZE), (0, 0)),
)


def _world(start=(2.0, 3.0, 0.0), range_max=8.0):
    from robocog.worlds.physics.mobile_base import LidarSpec

    spec = BaseSpec()
    sonar = '<site name="sonar" pos="0.31 0 0.2"/>'
    frag = base_fragment(spec, start[:2], start[2], children=sonar)
    xml = (
        '<mujoco><option timestep="0.005" integrator="implicitfast"/><worldbody>'
        '<geom type="plane" size="10 10 0.1" friction="1 0.005 0.0001"/>'
        + walls_xml(WALLS)
        + frag.body
        + f"</worldbody><actuator>{frag.actuator}</actuator><sensor>{frag.sensor}</sensor></mujoco>"
    )
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    base = MobileBase(model, data, spec, start, WALLS, LidarSpec(range_max=range_max), seed=1)
    return model, data, base


def _run(model, data, base, seconds, v, w):
    for _ in range(int(seconds / model.opt.timestep)):
        base.drive(v, w)
        mujoco.mj_step(model, data)
        base.sense(model.opt.timestep)


def test_the_base_drives_at_its_speed_and_turns_at_its_rate():
    model, data, base = _world()
    _run(model, data, base, 0.5, 0.0, 0.0)  # settle on the wheels
    x0, y0, _ = base.true_pose()
    _run(model, data, base, 3.0, 0.35, 0.0)
    x1, y1, t1 = base.true_pose()
    assert 0.9 < x1 - x0 < 1.1 and abs(y1 - y0) < 0.05 and abs(t1) < 0.05
    _run(model, data, base, 2.0, 0.0, math.radians(45))
    assert 1.3 < base.true_pose()[2] < 1.75  # about 90 degrees
    # the odometry followed, with its slip: within a few centimetres here
    ex, ey, et = base.odometry.pose
    tx, ty, tt = base.true_pose()
    assert math.hypot(ex - tx, ey - ty) < 0.1 and abs(et - tt) < 0.1


def test_lidar_reads_the_walls_and_respects_its_range():
    model, data, base = _world(start=(2.0, 3.0, 0.0))
    scan = base.scan(correct=False)
    assert len(scan.ranges) == 360
    lidar_x = 2.0 + base.spec.lidar_at[0]
    ahead = scan.sector_min(-0.02, 0.02)
    behind = min(scan.ranges[0], scan.ranges[-1])
    assert abs(ahead - (SIZE - lidar_x)) < 0.03
    assert abs(behind - lidar_x) < 0.03
    # a short range lidar sees only the near wall
    model, data, base = _world(start=(2.0, 3.0, 0.0), range_max=2.5)
    scan = base.scan(correct=False)
    assert np.isinf(scan.sector_min(-0.02, 0.02))
    assert np.isfinite(behind)


def test_range_cone_reads_the_wall_ahead():
    model, data, base = _world(start=(4.0, 3.0, 0.0))
    cone = RangeCone(model, "sonar", range_max=3.0)
    reading = cone.read(data)
    assert abs(reading - (SIZE - 4.31)) < 0.03
    far = RangeCone(model, "sonar", range_max=1.0)
    assert math.isinf(far.read(data))


def test_localiser_corrects_a_wrong_estimate_against_the_walls():
    model, data, base = _world(start=(2.0, 2.5, 0.3))
    base.localiser.pose = (2.2, 2.35, 0.36)  # as if odometry had drifted
    for _ in range(3):
        base.scan()
    x, y, t = base.estimate
    assert math.hypot(x - 2.0, y - 2.5) < 0.05 and abs(t - 0.3) < 0.02
    assert base.localiser.corrections == 3
    # no wall points: the estimate stays
    lonely = Localiser(WALLS, pose=(1.0, 1.0, 0.0))
    assert not lonely.correct(np.zeros((3, 2)))
    assert lonely.pose == (1.0, 1.0, 0.0)


def test_steer_reaches_a_point_on_the_estimate():
    model, data, base = _world(start=(1.5, 1.5, 0.0))
    target = (3.0, 3.5)
    for step in range(int(20 / model.opt.timestep)):
        v, w, arrived = steer(base.estimate, target, base.spec)
        if arrived:
            break
        base.drive(v, w)
        mujoco.mj_step(model, data)
        base.sense(model.opt.timestep)
        if step % 20 == 0:
            base.scan(correct=True)
    x, y, _ = base.true_pose()
    assert arrived and math.hypot(x - target[0], y - target[1]) < 0.15
