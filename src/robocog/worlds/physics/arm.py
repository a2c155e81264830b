"""The arm's motion: inverse kinematics by damped least squares, and straight-line moves.

The gripper always works from above: its fingers point down and its finger axis turns
to the cube's yaw. A target pose is reached by damped least squares on MuJoCo's site
Jacobians (``mj_jacSite``), iterated on a scratch copy of the model's data so the real
arm never jumps; each iterate is clipped to the joint limits. A move runs the tool
centre point along a straight line, a waypoint every centimetre, each solved from the
one before, and the position servos follow the waypoints in time. The fingers are
position servos with limited force: closing on a cube squeezes it, and only the
friction of the pads holds it.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import mujoco
import numpy as np

from robocog.worlds.physics.scene import ARM_JOINTS, FINGER_JOINTS, FINGER_OPEN


class IKError(RuntimeError):
    """No joint configuration within limits reaches the pose."""


def down_rotation(yaw: float) -> np.ndarray:
    """The gripper's orientation pointing down, finger axis along ``yaw`` (world frame)."""
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, s, 0.0], [s, -c, 0.0], [0.0, 0.0, -1.0]])


class Arm:
    """Solves and runs the arm's moves on a MuJoCo model; ``step(n)`` advances the world."""

    def __init__(
        self, model: mujoco.MjModel, data: mujoco.MjData, step: Callable[[int], None]
    ) -> None:
        self.model, self.data, self.step = model, data, step
        self.scratch = mujoco.MjData(model)
        joint = mujoco.mjtObj.mjOBJ_JOINT
        ids = [mujoco.mj_name2id(model, joint, n) for n in ARM_JOINTS]
        self.qadr = np.array([model.jnt_qposadr[i] for i in ids])
        self.dadr = np.array([model.jnt_dofadr[i] for i in ids])
        self.lower = np.array([model.jnt_range[i][0] for i in ids])
        self.upper = np.array([model.jnt_range[i][1] for i in ids])
        fingers = [mujoco.mj_name2id(model, joint, n) for n in FINGER_JOINTS]
        self.fadr = np.array([model.jnt_qposadr[i] for i in fingers])
        act = mujoco.mjtObj.mjOBJ_ACTUATOR
        self.arm_act = np.array([mujoco.mj_name2id(model, act, f"a{i}") for i in range(1, 7)])
        self.grip_act = np.array([mujoco.mj_name2id(model, act, n) for n in ("grip_l", "grip_r")])
        self.site = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, "tcp")
        self.target = self.data.qpos[self.qadr].copy()
        self.speed = 0.35  # m/s of the tool centre point along a line
        self.ik_failures = 0

    # -- kinematics ---------------------------------------------------------------

    def tcp(self, q: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Position and rotation matrix of the tool centre point at joints ``q``."""
        d = self.scratch
        d.qpos[:] = self.data.qpos
        if q is not None:
            d.qpos[self.qadr] = q
        mujoco.mj_kinematics(self.model, d)
        return d.site_xpos[self.site].copy(), d.site_xmat[self.site].reshape(3, 3).copy()

    def solve(
        self, pos: np.ndarray, rot: np.ndarray, q0: np.ndarray, iterations: int = 200
    ) -> np.ndarray:
        """Joint angles putting the tool at ``pos`` with ``rot``, from ``q0`` (raises IKError)."""
        m, d = self.model, self.scratch
        q = q0.copy()
        d.qpos[:] = self.data.qpos
        jacp = np.zeros((3, m.nv))
        jacr = np.zeros((3, m.nv))
        damping = 0.03
        want = np.zeros(4)
        have = np.zeros(4)
        err_r = np.zeros(3)
        mujoco.mju_mat2Quat(want, rot.reshape(9))
        for _ in range(iterations):
            d.qpos[self.qadr] = q
            mujoco.mj_kinematics(m, d)
            mujoco.mj_comPos(m, d)
            x = d.site_xpos[self.site]
            r = d.site_xmat[self.site].reshape(3, 3)
            err_p = pos - x
            mujoco.mju_mat2Quat(have, d.site_xmat[self.site])
            mujoco.mju_subQuat(err_r, want, have)  # the rotation from here to the target
            err_r = (
                r @ err_r
            )  # mju_subQuat answers in the tool's frame; the Jacobian is in the world's
            err = np.concatenate([err_p, err_r])
            if np.linalg.norm(err_p) < 2e-4 and np.linalg.norm(err_r) < 2e-3:
                return q
            mujoco.mj_jacSite(m, d, jacp, jacr, self.site)
            jac = np.vstack([jacp[:, self.dadr], jacr[:, self.dadr]])
            dq = jac.T @ np.linalg.solve(jac @ jac.T + damping**2 * np.eye(6), err)
            norm = np.linalg.norm(dq)
            if norm > 0.3:
                dq *= 0.3 / norm
            q = np.clip(q + dq, self.lower, self.upper)
        raise IKError(f"no joint angles reach {np.round(pos, 3).tolist()}")

    # -- motion -------------------------------------------------------------------

    def grip(self, opening: float, seconds: float = 0.5) -> None:
        """Drive each finger to ``opening`` metres from the centre and wait."""
        self.data.ctrl[self.grip_act] = opening
        self.step(int(seconds / self.model.opt.timestep))

    def open(self) -> None:
        """Open the fingers fully."""
        self.grip(FINGER_OPEN, 0.4)

    def close(self) -> None:
        """Close the fingers; on a cube they stop at its faces and squeeze it."""
        self.grip(0.0, 0.6)

    def finger_gap(self) -> float:
        """The distance between the finger pads (metres)."""
        return float(self.data.qpos[self.fadr].sum())

    def move(self, pos: np.ndarray, yaw: float, speed: float | None = None) -> None:
        """Move the tool centre point in a straight line to ``pos``, pointing down at ``yaw``.

        The yaw turns evenly along the line. Raises IKError (before moving) if a
        waypoint cannot be reached.
        """
        speed = speed or self.speed
        start, start_rot = self.tcp(self.target)
        start_yaw = math.atan2(start_rot[1, 0], start_rot[0, 0])
        dyaw = (yaw - start_yaw + math.pi) % (2 * math.pi) - math.pi
        dist = float(np.linalg.norm(pos - start))
        n = max(2, int(math.ceil(max(dist / 0.01, abs(dyaw) / 0.05))))
        path = []
        q = self.target.copy()
        for i in range(1, n + 1):
            f = i / n
            q = self.solve(start + f * (pos - start), down_rotation(start_yaw + f * dyaw), q)
            path.append(q)
        seconds = max(dist / speed, abs(dyaw) / 1.5, 0.2)
        steps_each = max(1, int(seconds / n / self.model.opt.timestep))
        for q in path:
            self.data.ctrl[self.arm_act] = q
            self.step(steps_each)
        self.target = path[-1]
        self.settle()

    def settle(self, tolerance: float = 0.004, max_seconds: float = 1.0) -> None:
        """Let the servos catch up with the last waypoint."""
        dt = self.model.opt.timestep
        for _ in range(int(max_seconds / dt / 10)):
            if np.max(np.abs(self.data.qpos[self.qadr] - self.target)) < tolerance:
                return
            self.step(10)

    def go_joints(self, q: np.ndarray, seconds: float = 1.5) -> None:
        """Move in joint space to ``q`` (for the park pose, away from the camera)."""
        start = self.target.copy()
        n = max(2, int(seconds / 0.02))
        for i in range(1, n + 1):
            self.data.ctrl[self.arm_act] = start + (q - start) * i / n
            self.step(max(1, int(0.02 / self.model.opt.timestep)))
        self.target = q.copy()
        self.settle()

    def reset(self, q: np.ndarray) -> None:
        """Put the arm at ``q`` at once, servos holding it there (only before a run)."""
        self.data.qpos[self.qadr] = q
        self.data.qvel[self.dadr] = 0.0
        self.data.ctrl[self.arm_act] = q
        self.data.ctrl[self.grip_act] = FINGER_OPEN
        self.data.qpos[self.fadr] = FINGER_OPEN
        self.target = q.copy()
        mujoco.mj_forward(self.model, self.data)
