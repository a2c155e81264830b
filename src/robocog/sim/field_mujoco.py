"""``robocog sim garbage --world mujoco --ros2``: the physical garbage field as a ROS 2 robot.

The same robot as :class:`~robocog.sim.ros2.GarbageRobot` (the same topics, the same
``navigate_to_pose`` and ``/gripper/grasp`` actions, the same lock-step, the same
``/mission/state``), on :class:`~robocog.worlds.mujoco_garbage.MujocoGarbageField`,
with what the physical robot measures in place of the field's exact geometry:

* ``/camera/image_raw`` (sensor_msgs/Image, ``rgb8``, 640 x 480, best effort) and
  ``/camera/camera_info`` (sensor_msgs/CameraInfo, the rendered pinhole camera): the
  frame the detector saw, one a camera frame (4 a simulated second);
* ``/detections``: the learned detector's boxes in that frame, each with the object's
  place on the ground (from the box's foot and the camera's height and pitch) as its
  hypothesis position and its track as its id;
* ``/scan``: the ray-cast lidar's latest scan (360 rays, ``inf`` where nothing is in
  range), one a frame;
* ``/odom`` and ``/tf``: the wheel odometry (which slips) as odom -> base_link, the
  localiser's correction from the lidar as map -> odom, and the lidar and the camera
  (its optical frame) on the base; ``/amcl_pose`` the localiser's estimate;
* ``/imu/data_raw`` (sensor_msgs/Imu): the gyro and the accelerometer, no orientation
  (its covariance's first element -1, as REP 145 says of an IMU without one);
* ``/joint_states``: the arm's joint sensors (shoulder, elbow, wrist, both fingers).

The camera renders in a GL context that belongs to the thread that made it, so the
world is run from the thread of :meth:`GarbageRobot.run` only (goals and grasps are
handed to it), which is how the base class runs every world.
"""

from __future__ import annotations

import math
from typing import Any

from cyclonedds.pub import DataWriter

from robocog.bridges.perception import quaternion_of
from robocog.bridges.ros2 import messages as m
from robocog.bridges.ros2.link import SENSOR
from robocog.robot.percepts import Detection
from robocog.sim.ros2 import GarbageRobot, detection_2d
from robocog.worlds.mujoco_garbage import MujocoGarbageField
from robocog.worlds.physics import field_scene as fs

#: the camera's topics (those a ROS camera driver offers)
IMAGE_TOPIC = "/camera/image_raw"
CAMERA_INFO_TOPIC = "/camera/camera_info"
IMU_TOPIC = "/imu/data_raw"
#: an optical frame (x right, y down, z ahead) in a body frame (x ahead, y left, z up)
OPTICAL = (-0.5, 0.5, -0.5, 0.5)


def _product(
    a: tuple[float, float, float, float], b: tuple[float, float, float, float]
) -> tuple[float, float, float, float]:
    """The quaternion product ``a b`` (x, y, z, w): rotation ``b``, then ``a``."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def _transform(x: float, y: float, yaw: float, z: float = 0.0) -> m.Transform:
    qx, qy, qz, qw = quaternion_of(yaw)
    return m.Transform(m.Vector3(x, y, z), m.Quaternion(qx, qy, qz, qw))


class MujocoGarbageRobot(GarbageRobot):
    """A ``MujocoGarbageField`` behind the garbage robot's topics and actions, with its
    camera images, its lidar's scans, its odometry and its arm's joints."""

    world: MujocoGarbageField

    def __init__(self, world: MujocoGarbageField, domain_id: int, **options: Any) -> None:
        super().__init__(world, domain_id, **options)
        self.w_image = self._writer(IMAGE_TOPIC, m.Image, SENSOR)
        self.w_camera_info = self._writer(CAMERA_INFO_TOPIC, m.CameraInfo)
        self.w_imu = self._writer(IMU_TOPIC, m.Imu, SENSOR)
        pc = world.physical
        self.focal = (pc.height / 2) / math.tan(math.radians(fs.CAMERA_FOVY) / 2)
        cx, cy, cz = fs.CAMERA_AT
        pitch = fs.CAMERA_PITCH  # down: a positive turn about the base's y axis
        tilt = (0.0, math.sin(pitch / 2), 0.0, math.cos(pitch / 2))
        qx, qy, qz, qw = _product(tilt, OPTICAL)
        self._camera_at = m.Transform(m.Vector3(cx, cy, cz), m.Quaternion(qx, qy, qz, qw))
        lx, ly, lz = world.spec.lidar_at
        self._lidar_at = m.Transform(m.Vector3(lx, ly, lz))
        #: camera images sent (a frame with no one to see it, and no recorder, sends none)
        self.images = 0

    def _motion(self, now: m.Time) -> list[tuple[DataWriter, Any]]:
        """The odometry's pose as odom -> base_link, the localiser's correction of it as
        map -> odom, the sensors on the base; the IMU's reading."""
        w = self.world
        ox, oy, ot = w.base.odometry.pose
        ex, ey, et = w.base.estimate
        # map -> odom: the turn and shift that carry the odometry's pose onto the estimate
        dt = et - ot
        mx = ex - (ox * math.cos(dt) - oy * math.sin(dt))
        my = ey - (ox * math.sin(dt) + oy * math.cos(dt))
        tf = m.TFMessage(
            [
                m.TransformStamped(m.Header(now, "map"), "odom", _transform(mx, my, dt)),
                m.TransformStamped(m.Header(now, "odom"), "base_link", _transform(ox, oy, ot)),
                m.TransformStamped(m.Header(now, "base_link"), "base_scan", self._lidar_at),
                m.TransformStamped(m.Header(now, "base_link"), "camera", self._camera_at),
            ]
        )
        qx, qy, qz, qw = quaternion_of(ot)
        pose = m.Pose(m.Point(ox, oy, 0.0), m.Quaternion(qx, qy, qz, qw))
        gyro, accel = w.base.imu()
        imu = m.Imu(
            m.Header(now, "base_link"),  # the IMU sits on the base's axes
            orientation_covariance=[-1.0] + [0.0] * 8,
            angular_velocity=m.Vector3(*map(float, gyro)),
            linear_acceleration=m.Vector3(*map(float, accel)),
        )
        return [(self.w_tf, tf), (self.w_odom, self._odometry(now, pose)), (self.w_imu, imu)]

    def _joints(self, now: m.Time, holding: str) -> m.JointState:
        """The arm's joint sensors (radians; the fingers in metres from the middle)."""
        joints = self.world.joint_positions()
        return m.JointState(m.Header(now, "base_link"), list(joints), list(joints.values()))

    def _camera(self, now: m.Time) -> list[tuple[DataWriter, Any]]:
        """The frame the detector saw, and the camera's calibration; none when no one
        subscribes and nothing records (an image costs tens of milliseconds to send)."""
        frame = self.world.last_frame
        if frame is None or (
            self.on_message is None and not self.w_image.get_matched_subscriptions()
        ):
            return []
        self.images += 1
        header = m.Header(now, "camera")
        height, width = int(frame.shape[0]), int(frame.shape[1])
        return [
            (self.w_camera_info, m.pinhole(header, width, height, self.focal)),
            (self.w_image, m.rgb8(header, frame)),
        ]

    def _scan(self, now: m.Time) -> m.LaserScan:
        """The lidar's latest scan, as it read it (``inf``: no return within range)."""
        scan = self.world.lidar_scan()
        spec = self.world.base.lidar.spec
        step = float(scan.angles[1] - scan.angles[0]) if len(scan.angles) > 1 else 0.0
        return m.LaserScan(
            m.Header(now, "base_scan"),
            angle_min=float(scan.angles[0]),
            angle_max=float(scan.angles[-1]),
            angle_increment=step,
            scan_time=1.0 / spec.rate,
            range_min=spec.range_min,
            range_max=scan.range_max,
            ranges=[float(r) for r in scan.ranges],
        )

    def _box(self, d: Detection, now: m.Time) -> m.Detection2D:
        """The detector's own box of the detection, in the image's pixels."""
        for seen, b in self.world.last_detections:
            if seen is d:
                box = m.BoundingBox2D(
                    m.Pose2D(m.Point2D((b.u0 + b.u1) / 2.0, (b.v0 + b.v1) / 2.0)),
                    float(b.u1 - b.u0),
                    float(b.v1 - b.v0),
                )
                return detection_2d(d, now, box)
        return super()._box(d, now)
